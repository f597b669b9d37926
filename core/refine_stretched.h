// eulermap::RefineStretched, RefineAtSeams and OpenTears — the mapped source refined where the
// map stretches an edge along the target or crosses a seam of its texture, and opened where it
// tears across a gap beside a cut (ours, not the paper's).
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
// An edge is split only where its chord follows the target: it does not cross a gap
// (AcrossGap), and it does not run through a thin part (its ends on the two sides, its
// midpoint nearest one of them, or deep inside). A convex corner is split (its chord runs
// inside), so is a chord round a thin part's rim (its ends on the two sides, its midpoint
// just inside the rim: a picture frame's edge, ladder -> frame at 64 cells, 6.3% of the
// target's diagonal unsplit when ends facing opposite ways were refused, 5.0% split); a
// chord across a gap (the ends mapped onto two sides of an opening: a tear in
// the map) is left as it is, so the longest-edge figure still shows it.
//   in/out: cut (vertex positions on the source, per-vertex attribute "TargetPosition"
//           = the images, on the target's own frame; no deleted elements)
//   in:     target (the mesh the images lie on), limit (mapped length above which an edge
//           is split, target units)
//   returns the number of vertices added (at most one per vertex of cut)
#pragma once

#include "closest.h"

#include <vector>

namespace eulermap {

// An edge longer than this many grid cells on the target is split (or than the share of the
// target's diagonal that the pipeline counts as stretched, where that is shorter).
constexpr double kSplitCells = 2;
// A chord whose midpoint lies outside, this far from the target per unit of its length,
// crosses a gap: across a gap between its lips the midpoint lies half the chord's length
// away; across a right-angled concave corner (the rim of the hole between a chair's slats
// where a slat meets the rail) at most 1 / (2 sqrt 2) = 0.354, and that chord follows the
// target round the corner.
constexpr double kGapSag = 0.4;
// A chord between two lips that face each other (the target's normals at its ends opposed,
// each pointing at the other end: a hole's two sides) crosses the gap wherever its midpoint
// lies outside, farther than this per unit of its length. Such a chord can run obliquely,
// from low on one lip to high on the other, and sag less than kGapSag: sphere -> cup at 96
// cells, fans of faces from the cup's wall across the handle's hole to the handle, their
// chords sagging 0.35 to 0.44 of their length, under 0.4 next to the rim, so the faces over
// it did not reach the rim and stayed (OpenTears; longest mapped edge 10.6% of the target's
// diagonal).
// A concave corner's two sides do not face each other (their normals are at right angles),
// nor do a thin part's two sides (their normals point away from each other).
constexpr double kLipSag = 0.1;

int RefineStretched(Mesh &cut, const ClosestPoint &target, double limit);

// The cut refined along the target's texture seams (charts.h), before its texture coordinates
// are pulled (transfer.h): a face whose images lie in two charts takes one chart's
// coordinates over its whole extent, continued past the chart's border into whatever the
// texture holds there, so along a seam the texture shows a saw-tooth as large as the cut's
// faces. Each pass splits, as RefineStretched does, every edge mapped longer than
// kSeamEdgeShare of the target's mean edge length whose chord follows the target and whose
// ends' images lie in different charts; each of the kSeamPasses passes halves the faces
// over a seam, down to that length.
//   in/out: cut (as for RefineStretched)
//   in:     target and its index, chart: per face of target its chart (Charts)
//   returns the number of vertices added (at most one per vertex of cut)
constexpr int kSeamPasses = 4;
constexpr double kSeamEdgeShare = 0.5;
int RefineAtSeams(Mesh &cut, const Mesh &target, const ClosestPoint &index, const std::vector<int> &chart);

// Whether the chord between images a and b crosses a gap: its midpoint lies outside the
// target (on the side its nearest face's normal points to), more than kGapSag of the
// chord's length away, or more than kLipSag where its ends lie on lips facing each other.
bool AcrossGap(const Point3 &a, const Point3 &b, const ClosestPoint &target);

// A tear: a face with an edge mapped longer than the limit across a gap (AcrossGap). Where the
// faces of a tear reach a rim of the cut, the hole cut there opened wider along the morph
// than the faces surgery removed (a hole that opens late: sphere -> ring3 at 64 cells, the
// middle hole at step 34 of 40, 34 faces left across it, longest mapped edge 14% of the
// target's diagonal): those faces are removed, each connected piece of them only if the
// cut's components, boundary loops and Euler characteristic stay as they were (the hole
// grows; no new hole, no piece cut off). An island (surgery.h, kIslandShare) that such a
// piece would cut off from the rest goes with it, as surgery's cleaning removes islands:
// sphere -> cup at 48 cells, inflate then shrink, the handle's hole opened wider than its
// disc pair, and the tear across it cut off one face (longest edge 10.8% of the target's
// diagonal left; 3.4% with the face gone). Tears away from every rim stay (the longest-edge
// figure shows them).
//   in/out: cut (as for RefineStretched), compacted when faces go
//   in:     target, limit (as for RefineStretched)
//   returns the number of faces removed
int OpenTears(Mesh &cut, const ClosestPoint &target, double limit);

} // namespace eulermap
