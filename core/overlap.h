// eulermap::FitOverlap — the placement of the target, without anchors, that overlaps the
// two insides most (ours, not the paper's; issue 12 item 3: a placement that avoids births).
//
// Why: the morph carries the source's inside onto the target's (Eq. 1); where the two do
// not overlap, parts of the target grow from nothing and the morph passes through shapes
// neither mesh has. Chair -> table at the centre-and-scale placement (the table scaled
// 1.27 so that the diagonals match, its top halfway up the chair's back) passes through
// genus 0 -> 2 -> 3 -> 0 at 64 cells: seat and top are two plates joined by the legs. The
// map was cut into 3 parts with 9 loops and covered 72% of the table. With the top on the
// seat and the legs on the legs, no event at all: one part, no loop, 100% covered.
//
// The measure: the intersection over union of the insides, each a soft occupancy
// o = clamp(1/2 - f / (2 w), 0, 1) of the mesh's signed distance f (sdf.h) on a coarse grid of
// its own, w one cell of it (a part a cell thick still
// counts, and the measure changes smoothly as the target slides):
//   IoU(P) = I / (V0 + s^3 V1 - I),  I = integral of o0(x) o1(P^-1 x),  V = integral of o.
// The search: P(p) = s R p + t with the start's rotation R (the identity, or a quarter turn
// where the pipeline turned the target: the search itself turns nothing), from the start
// (s_c, t_c): s = s_c 2^(i/8) for i = -4..4, t on a lattice of
// the source's cells within kOverlapReach of its bounding-box diagonal of t_c, on grids of
// kOverlapCoarseCells; then from the best, on grids of kOverlapCells, to the best of the 81
// neighbours (steps of one cell and a scale of 2^(1/16)) while one is better, then the same
// with half and quarter steps.
//
// Inputs:  source, target (their own frames), start: the centre-and-scale placement, turned or not
// Output:  the placement found, and the IoU at the start and at the end
#pragma once

#include "mesh.h"
#include "placement.h"

namespace eulermap {

constexpr int kOverlapCoarseCells = 16;  // the lattice's grids: cells on each mesh's longest side
constexpr int kOverlapCells = 40;        // the refinement's grids
constexpr double kOverlapReach = 0.25;   // translations searched, as a share of the source's diagonal
constexpr int kOverlapMoves = 16;        // steps of the refinement at each step length, at most

struct Overlap {
  Similarity placement;
  double startIoU = 0, bestIoU = 0;
};

Overlap FitOverlap(const Mesh &source, const Mesh &target, const Similarity &start);

} // namespace eulermap
