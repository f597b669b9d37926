// Signed distance fields f0, f1 on grid nodes (DESIGN.md: sdf.h).
//
// SignedDistance(mesh, grid)
//   in:  a triangle mesh (closed, or with small holes) and the grid
//   out: per node, the distance to the nearest surface point (UnsignedDistance,
//        distance_transform.h), negative inside. Inside means generalized winding number >= 1/2,
//        so a mesh with a hole (camelhead.off) still has a sensible inside. The winding number
//        is evaluated near the surface only; elsewhere it follows from the whole number that
//        mesh + a cone closing its holes has there, flooded across the grid (sdf.cpp: Inside).
// WindingNumber: the generalized winding number of Jacobson et al. 2013, evaluated
//   hierarchically (far triangle clusters as dipoles, Barill et al. 2018).
#pragma once

#include "field.h"
#include "interrupt.h"
#include "mesh.h"

#include <memory>
#include <vector>

namespace eulermap {

class WindingNumber {
 public:
  explicit WindingNumber(const Mesh &mesh);
  explicit WindingNumber(std::vector<Point3> corners);  // triangles, 3 corners each
  ~WindingNumber();
  // Winding number at p: about 1 inside a closed outward-oriented mesh, 0 outside.
  double operator()(const Point3 &p) const;
  // The same from a cheaper evaluation (error <= 6.2e-3 measured).
  double Estimate(const Point3 &p) const;
  // Whether operator()(p) >= 1/2, decided with a cheaper evaluation where it is clear:
  // given w, w(p) within 6.2e-3 (Estimate), w decides unless it lies near 1/2.
  bool Inside(const Point3 &p, double w) const;
  bool Inside(const Point3 &p) const { return Inside(p, Estimate(p)); }

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

// gradient (when given): per node, the gradient of the signed distance (the unsigned
// one's, distance_transform.h, turned round inside), for HermiteField (hermite_field.h).
// interrupt: asked by the distance transform's sweeps and once the inside is known; once
// it says stop, the unsigned distance as far as it got.
ScalarField SignedDistance(const Mesh &mesh, const Grid &grid, VectorField *gradient = nullptr,
                           const Interrupt &interrupt = Interrupt());
// The same with the gradient in single precision (what the pipeline keeps: hermite_field.h).
ScalarField SignedDistance(const Mesh &mesh, const Grid &grid, GradientField *gradient, const Interrupt &interrupt = Interrupt());

} // namespace eulermap
