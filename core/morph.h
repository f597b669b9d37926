// eulermap::Morph — the anchor-guided morph f(p,t) of Eq. 1 (DESIGN.md: morph.h):
//
//   f(p,t) = (1-t) f0(W_t->0(p)) + t f1(W_t->1(p))
//
// Anchors a_i on the source and b_i on the (placed) target.
//   - fewer than 4 anchors, or coplanar ones: W = identity (a plain linear blend; the
//     similarity fitted to 1-3 anchors is the placement, placement.h);
//   - 4 or more non-coplanar anchors: q_i(t) by as-rigid-as-possible interpolation of
//     the tetrahedra of every 4-subset of anchors (Alexa et al. 2000: per tetrahedron,
//     A = R S by polar decomposition, A(t) = R(t) ((1-t) I + t S) with R(t) the slerp of R;
//     q(t) the least-squares fit of all A(t), centroid interpolated linearly), and
//     thin-plate (phi(r) = r, plus affine part) warps W_t->0, W_t->1 with
//     W_t->0(q_i(t)) = a_i and W_t->1(q_i(t)) = b_i.
// Without a warp (fewer than 4 anchors), Blend::GrowShrink replaces the linear blend with
// grow_shrink.h's morph, and Blend::InflateShrink with inflate_shrink.h's, in which no part
// grows from nothing (the pipeline asks for them when the linear blend would grow one).
#pragma once

#include "field.h"
#include "interrupt.h"

#include <memory>
#include <string>
#include <vector>

namespace eulermap {

class Morph {
 public:
  enum class Mode { LinearBlend, ArapTps, GrowShrink, InflateShrink };
  enum class Blend { Linear, GrowShrink, InflateShrink };  // what to do where no warp is built

  // f0, f1 on the same grid; anchors as matched lists (a[i] <-> b[i]), b already placed.
  // f0 and f1 are not copied: they must outlive the Morph.
  Morph(const ScalarField &f0, const ScalarField &f1, std::vector<Point3> a, std::vector<Point3> b,
        Blend blend = Blend::Linear);
  ~Morph();

  Mode mode() const;
  std::string Describe() const;  // e.g. "ARAP+TPS, 6 anchors (15 tetrahedra)"

  // f(., t) at every grid node (Eq. 1), into `out` (resized to the grid). interrupt: asked
  // every kNodesBetweenPolls nodes of a warped frame (interrupt.h); once it says stop, `out`
  // means nothing.
  void Frame(double t, ScalarField &out, const Interrupt &interrupt = Interrupt()) const;

  std::vector<Point3> Anchors(double t) const;        // q_i(t); q_i(0) = a_i, q_i(1) = b_i
  // Velocity of space that the anchors impose between t0 and t1: the thin-plate warp
  // q_i(t0) -> q_i(t1) minus the identity, over (t1 - t0), at every grid node, and
  // each node's closeness exp(-(d / radius)^2) to the nearest anchor q_i(t0) (d and
  // radius in world units); empty fields in linear-blend mode. The velocity solve's
  // prior (velocity.h). interrupt: as Frame's.
  void AnchorMotion(double t0, double t1, double radius, VectorField &velocity, ScalarField &closeness,
                    const Interrupt &interrupt = Interrupt()) const;
  Point3 WarpToSource(double t, const Point3 &p) const;  // W_t->0
  Point3 WarpToTarget(double t, const Point3 &p) const;  // W_t->1

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace eulermap
