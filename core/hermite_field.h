// eulermap::HermiteField — a signed distance field read with sub-cell accuracy: its values
// and its gradients on the grid nodes, interpolated in each cell by the tricubic Hermite
// polynomial (the gradient-augmented level set of [NRS10]).
//
// [NRS10] J.-C. Nave, R. R. Rosales, B. Seibold, "A gradient-augmented level set method
//         with an optimally local, coherent advection scheme", J. Comput. Phys. 229(10), 2010.
//
// Per axis, with w in [0,1] the local coordinate in the cell and h the cell size, the cubic
// Hermite basis takes values and slopes at the cell's two ends:
//   H0 = 1 - 3w^2 + 2w^3,  H1 = 3w^2 - 2w^3,  G0 = h (w - 2w^2 + w^3),  G1 = h (w^3 - w^2).
// In 3D, f(p) = sum over the 8 corners c of
//   f H H H + f_x G H H + f_y H G H + f_z H H G + f_xy G G H + f_xz G H G + f_yz H G G
//   + f_xyz G G G,
// each product's factors per axis x, y, z taking that corner's end (H0/G0 or H1/G1). The
// first derivatives are the exact gradients of the distance (distance_transform.h); the
// mixed ones are central differences of those gradients, as in [NRS10].
//
// Why: the map ends on the zero level set of the target's field, and trilinear
// interpolation bends that set off the surface by a fraction of a cell where the surface
// curves. At the paper's grids 0.5% of the target's diagonal is only 0.16-0.2 cells, and
// target vertices pulled onto the zero set are within it at 87.1% (bunny, 30x40x30) and
// 92.6% (camelhead, 40x30x40) with trilinear interpolation, 96.6% / 96.2% with Catmull-Rom
// tricubic interpolation of the values alone, and 99.5% / 99.5% with this field.
// Used at the two ends of the map only: the levels of samples off the source (f0) and every
// tracked point's last pull-back onto f1 (tracker.h). Reading each frame in between this way
// would replace the pull-back's 8 node reads by 8 corners of 8 derivatives each (4 of them
// differenced from neighbours' gradients), and would need each frame's node gradients
// through the warps' Jacobians (morph.h).
#pragma once

#include "field.h"

namespace eulermap {

class HermiteField {
 public:
  // f and its node gradients (SignedDistance's), on the same grid; not copied: they must
  // outlive this object.
  HermiteField(const ScalarField &f, const VectorField &gradient);
  HermiteField(const ScalarField &f, const GradientField &gradient);  // single precision

  // f(p) from the Hermite polynomial of p's cell, and its gradient there when `gradient` is
  // given (one evaluation for both); outside the grid's box both are extended as
  // ScalarField::Value / Gradient do.
  double Value(const Point3 &p, Point3 *gradient = nullptr) const;
  const Grid &grid() const { return f_.grid; }

 private:
  // Mixed derivatives f_xy, f_xz, f_yz, f_xyz at node (i, j, k).
  void Mixed(int i, int j, int k, double out[4]) const;

  // The node gradient at (i, j, k), from whichever field was given.
  Point3 NodeGradient(int i, int j, int k) const {
    if (gradient_) return (*gradient_)(i, j, k);
    const vcg::Point3f &g = (*gradientFloat_)(i, j, k);
    return Point3(g[0], g[1], g[2]);
  }

  const ScalarField &f_;
  const VectorField *gradient_ = nullptr;
  const GradientField *gradientFloat_ = nullptr;
};

} // namespace eulermap
