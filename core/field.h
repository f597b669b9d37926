// eulermap::Field — values on the nodes of a Grid, read anywhere by trilinear interpolation.
//
// ScalarField holds f0, f1 and the morph frames f(., t_k); VectorField holds V_k.
// Outside the grid a scalar field is extended by the distance to the grid's box
// (a signed-distance-like extension, so points that leave the box are pulled back).
#pragma once

#include "grid.h"

#include <vector>

namespace eulermap {

template <class Value> struct Field {
  Grid grid;
  std::vector<Value> values;  // one per node, in Grid::Index order

  Field() = default;
  Field(const Grid &g, const Value &init) : grid(g), values(g.NodeCount(), init) {}

  Value &operator()(int i, int j, int k) { return values[grid.Index(i, j, k)]; }
  const Value &operator()(int i, int j, int k) const { return values[grid.Index(i, j, k)]; }

  // Trilinear interpolation at world point p; p is clamped onto the grid's box.
  Value Sample(const Point3 &p) const {
    int c[3];
    double w[3];
    Locate(p, c, w);
    return Interpolate(c, w);
  }

  // Cell (lower corner) and local coordinates in [0,1]^3 of the point p clamped onto the
  // box; outside (when given): p minus that point, in grid units.
  void Locate(const Point3 &p, int cell[3], double local[3], Point3 *outside = nullptr) const {
    const Point3 g = grid.ToGrid(p);
    for (int a = 0; a < 3; ++a) {
      const double x = std::min(std::max(g[a], 0.0), double(grid.dims[a] - 1));
      cell[a] = std::min(int(x), grid.dims[a] - 2);
      local[a] = x - cell[a];
      if (outside) (*outside)[a] = g[a] - x;
    }
  }

  // The trilinear interpolant of cell `cell` at local coordinates w: the corners weighted
  // by products of (1 - w_a) and w_a, summed axis by axis. No Value is default-constructed:
  // vcg::Point3() leaves its coordinates unset, and inside MeshLab a garbage start makes
  // the tracker lose points (test_field).
  Value Interpolate(const int cell[3], const double w[3]) const {
    const std::size_t sy = grid.dims.X(), sz = sy * grid.dims.Y();
    const Value *v = &values[grid.Index(cell[0], cell[1], cell[2])];
    const double x0 = 1 - w[0], x1 = w[0];
    const Value y0 = (v[0] * x0 + v[1] * x1) * (1 - w[1]) + (v[sy] * x0 + v[sy + 1] * x1) * w[1];
    const Value y1 = (v[sz] * x0 + v[sz + 1] * x1) * (1 - w[1]) + (v[sz + sy] * x0 + v[sz + sy + 1] * x1) * w[1];
    return y0 * (1 - w[2]) + y1 * w[2];
  }
};

struct ScalarField : Field<double> {
  using Field<double>::Field;

  // f(p): trilinear inside the box; outside, the value at the nearest box point plus
  // the distance to the box.
  double Value(const Point3 &p) const;
  // Gradient of the trilinear interpolant at p (world units), the box-extension's outside.
  Point3 Gradient(const Point3 &p) const;
  // Central-difference gradient at node (i,j,k) (one-sided at the box faces), world units:
  // the g of the velocity system (velocity.h).
  Point3 NodeGradient(int i, int j, int k) const;
};

using VectorField = Field<Point3>;
// Unit gradients of a distance (distance_transform.h), read by HermiteField: single precision
// (1e-7 of a unit vector) halves their memory on big grids.
using GradientField = Field<vcg::Point3f>;

} // namespace eulermap
