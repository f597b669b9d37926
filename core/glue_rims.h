// eulermap::GlueRims — the two rims of a disc pair brought onto one curve of the target
// (ours, not the paper's).
//
// A handle gained or two parts merging is cut as one disc from each of the two sheets that
// meet (surgery.h); a continuous map onto the target glues the two rims left: both map onto
// the one curve round the neck the event opens (topology.h, NeededCut). The tracked sheets
// lag the level set near the event (V vanishes at a critical point of f), so at the cut
// each sheet is a cell or two short of the event's place, and its rim ends on the neck
// where it was: a band of the neck between the two rims stays uncovered (two fronts growing
// round an outer torus of sphere -> ring3 meet on its far side at 48 cells, 2.4% of the
// target uncovered there). Here the image of each rim vertex moves to the target's point
// nearest the midpoint of it and the nearest point of the other rim's image; the faces beside
// the rims then stretch over the band, and refine_stretched.h splits them.
//   in/out: cut (per-vertex attribute "TargetPosition" = the images, target frame)
//   in:     target (the mesh the images lie on), places: where each disc pair was cut
//           (target frame), reach (target units): a disc pair's rims are the two boundary
//           loops whose images come nearest its place, both within reach; a loop is glued
//           once
//   returns the number of pairs glued
#pragma once

#include "closest.h"

#include <vector>

namespace eulermap {

int GlueRims(Mesh &cut, const ClosestPoint &target, const std::vector<Point3> &places, double reach);

} // namespace eulermap
