// eulermap::InflateShrink — a morph from f0 to f1 through a shape that holds the target:
// the source's inside X0 inflates until it holds the target's inside X1, then the linear
// blend shrinks it onto X1 (issue 12 item 3; DESIGN.md: births). The third morph the
// pipeline tries where the linear blend grows parts from nothing (pipeline.cpp, MapPlaced).
//
// Why: grow_shrink.h grows X0 into a target part through the place where they touch, so a
// patch of a few faces is stretched over the whole part (sphere -> two tori in a row at 128
// cells: 32.8% of the area flipped as tracked, 37 400 points added). Inflated, the source's
// surface moves along its normals, as a whole, and the shrink is the set-up under which the
// linear blend has no births: the source made to enclose the target.
//
// With L0 = max f0 over X1 and the box term b(p) = (1.5 - the node's index distance to the
// grid's faces) h (the inflated source kept one cell inside the grid):
//   B:       fB = max(f0 - L0, b), whose inside X0 (+) L0, within the grid, holds X1;
//   inflate, t <= t*, s = t / t*:            f = (1 - s) f0 + s fB   (= f0 - s L0 inside the box)
//   shrink,  t >= t*, s = (t - t*) / (1 - t*): f = s f1 - (1 - s) c
// with c the way out of B: -fB, lengthened where X1 blocks the straight way by what the path
// around X1 adds (c = -fB + max(0, w - (1 + kChamferError) (-fB) - 2h), w grow_shrink.h's
// CarveDistance of B onto X1, measured in the 26-neighbour metric), L1 = max f1 over B's
// inside and t* = L0 / (L0 + L1), so that the surface moves at one speed. Where nothing
// blocks the way, c = -fB and the shrink is the linear blend (1 - s) fB + s f1, the set-up
// under which the linear blend has no births: the source made to enclose the target. No part
// is born: outside B, f1 >= dist(., B) >= fB (X1 lies in B, and fB is at most the distance
// to B), so the shrink only grows there; inside B every new component would be a piece left
// by a split. And no cavity is born where the target is hollow: with the straight distance
// to B's surface a cup's floor and a cage's centre left before the nodes between them and
// the outside (sphere -> a cup at 64 cells: 84.5% covered, the cup's inside missing).
// Inflation closes the source's own handles and merges its parts (events the shrink
// undoes), so this morph comes after grow_shrink.h's.
//
// Inputs:  f0, f1 on one grid, signed distances in world units (not copied: they must
//          outlive the InflateShrink)
// Outputs: Frame(t): f(., t) at every node
#pragma once

#include "field.h"

#include <vector>

namespace eulermap {

class InflateShrink {
 public:
  InflateShrink(const ScalarField &f0, const ScalarField &f1);

  void Frame(double t, ScalarField &out) const;
  double Switch() const { return switch_; }         // t*
  double InflateLength() const { return l0_; }      // L0, world units
  double ShrinkLength() const { return l1_; }       // L1

 private:
  const ScalarField &f0_, &f1_;
  std::vector<double> fb_;  // fB per node
  std::vector<double> wayOut_;  // per node, c above
  double l0_ = 0, l1_ = 0, switch_ = 0;
};

} // namespace eulermap
