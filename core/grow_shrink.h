// eulermap::GrowShrink — a morph from f0 to f1 in which no part grows from nothing and none
// shrinks into nothing: the source's inside X0 first grows through the target's inside X1,
// then the part of it outside X1 withdraws into X1 (issue 12 item 3; DESIGN.md: births).
//
// Why: under the linear blend f = (1-t) f0 + t f1 (Eq. 1 without anchors) a part of the
// target that the source does not overlap appears as a new component of {f < 0} (a minimum
// of f crossing 0), which no tracked point reaches: sphere -> three tori in a row at the
// default placement covers 72% of the target. Here every node enters the inside set next
// to a node already inside, and leaves it next to one that stays, so the tracked surface
// itself grows into every part of the target it touches and withdraws from every part of
// the source the target does not hold.
//
// G = {min(f0, f1) < 0} = X0 u X1. d0, d1: distance within G (paths through G's nodes) from
// X0 and from X1; L0 = max d0 over X1, L1 = max d1 over X0. With t* = L0 / (L0 + L1), so
// that both fronts move at one speed (L0 + L1 per unit t):
//   grow,     t <= t*, s = t / t*:              f = min(f0, max(f1, d0 - s L0))
//   withdraw, t >= t*, s = (1 - t) / (1 - t*):  f = min(f1, max(f0, d1 - s L1))
// t = 0 gives f0's inside set, t* X0 u X1, 1 f1's; near the zero set f is f0, f1 or a front
// d - s L with |grad| = 1, and the two phases agree near the surface at t*. The velocity of
// a front (Eqs. 2-5) is (L0 + L1) grad d: the tracked surface is pushed along shortest
// paths within G.
// Where the target is hollow, withdrawing the farthest from X1 first would bear a cavity (a
// solid mug onto a cup: the cup's inside is born at its floor, farther from the cup than its
// mouth; 64.4% covered at 64 cells). Then the withdrawal comes in from the outside instead:
// f = min(f1, max(f0, u d1 - (1 - u) c)), u = 1 - s, c the way in from outside G through its
// nodes outside X1 (CarveDistance); nodes leave in the order of c / (c + d1), after those
// between them and the outside and before those between them and X1 (mug -> cup: 100%),
// that order closed where the way in narrows (a vase's neck: grow_shrink.cpp, CarveOrder;
// sphere -> vase: 62% -> 100%).
// Where the target fills a pocket of the source, joining the nodes nearest X0 first fills it
// from its walls inward: the walls' fronts meet along its middle and the tracked surface folds
// there (a cup onto a mug: 2.82% of the mapped area flipped at 64 cells). Then d0 gives way
// to an order that fills the pocket from its floor up, tau = d0 - c (c the way in from
// outside G through the nodes outside X0), closed so that the inside sets keep their
// topology (grow_shrink.cpp, PistonOrder; cup -> mug: 0.02%).
// Distances: Dijkstra over the 26 neighbours with steps h, sqrt 2 h, sqrt 3 h, a diagonal
// step taken only where a path of grid edges through G joins its ends within the cell: so
// every node of G has a 6-neighbour nearer to the seeds, and the inside sets keep the
// 6-connectivity of zero_set_topology.h (no node enters alone, none is left alone).
// A part of X1 that G does not join to X0 (a target part apart from everything the source
// touches) is not reached by growth; it appears at t* and its event says so.
//
// Inputs:  f0, f1 on one grid (not copied: they must outlive the GrowShrink)
// Outputs: Frame(t): f(., t) at every node
#pragma once

#include "field.h"

#include <vector>

namespace eulermap {

class GrowShrink {
 public:
  GrowShrink(const ScalarField &f0, const ScalarField &f1);

  void Frame(double t, ScalarField &out) const;
  double Switch() const { return switch_; }  // t*
  double GrowLength() const { return l0_; }  // L0, world units
  double WithdrawLength() const { return l1_; }  // L1

 private:
  const ScalarField &f0_, &f1_;
  std::vector<double> d0_, d1_;  // per node; +infinity outside G or where unreached (d0_: the piston's order where it fills a pocket)
  std::vector<double> carve_;    // per node, CarveDistance of G onto X1; empty where d1's order bears no cavity
                                 // (where not, carve_ and d1_ are tau L and (1 - tau) L, tau the carve's order)
  double l0_ = 0, l1_ = 0, switch_ = 0;
};

// in:  inside: per node of g, whether it belongs to G; seed: whether it is a seed (within G)
// out: per node, the distance within G from the seeds (above), +infinity where unreached
std::vector<double> DistanceWithin(const Grid &g, const std::vector<char> &inside, const std::vector<char> &seed);

// The most by which DistanceWithin's 26-neighbour paths exceed the straight distance in
// open space (direction (3, 1, 1): sqrt 3 + 2 against sqrt 11, 12.5%), with a margin.
constexpr double kChamferError = 0.15;

// in:  inside: per node, whether it belongs to the set that withdraws; kept: the nodes it
//      withdraws onto
// out: per node, the distance from the nodes outside `inside`, through nodes not kept
//      (0 outside, +infinity inside `kept` and where unreached)
std::vector<double> CarveDistance(const Grid &g, const std::vector<char> &inside, const std::vector<char> &kept);

} // namespace eulermap
