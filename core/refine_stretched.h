// eulermap::RefineStretched — the mapped source refined where the map stretches an edge
// (ours, not the paper's).
//
// Surgery splits the tracked edges that stretch while the points move (surgery.h, step 4);
// untangling (untangle.h) then spreads folded places over the target once the points have
// stopped, and can stretch an edge beyond kSplitCells again (ring2 -> sphere at 64 cells:
// longest mapped edge 4.8% of the target's diagonal as tracked, 6.7% untangled, 3.4% once
// refined here and untangled again: the pipeline untangles, refines, untangles). Such an
// edge is split at its midpoint on the source (vcglib's RefineE: the source's wedge and
// vertex data interpolated), and the new vertex's image is the target's point nearest the
// midpoint of its ends' images: the map is linear along the edge at the scale it was
// tracked at, and the image lies on the target instead of on a chord across it.
// An edge is split only where its chord follows the target: the nearest target point to
// the chord's midpoint lies within kChordSag of the edge's mapped length, and the target
// faces the same way at both ends and there. A chord across a gap (the ends mapped onto
// two sheets that face each other: a tear in the map) is left as it is, so the longest-edge
// figure still shows it.
//   in/out: cut (vertex positions on the source, per-vertex attribute "TargetPosition"
//           = the images, on the target's own frame; no deleted elements)
//   in:     target (the mesh the images lie on), limit (mapped length above which an edge
//           is split, target units)
//   returns the number of vertices added (at most one per vertex of cut)
#pragma once

#include "closest.h"

namespace eulermap {

constexpr double kSplitCells = 2;  // an edge longer than this many grid cells on the target is split
constexpr double kChordSag = 0.25;  // a chord this far from the target (per unit of its length) crosses a gap

int RefineStretched(Mesh &cut, const ClosestPoint &target, double limit);

} // namespace eulermap
