// eulermap::Field — values on the nodes of a Grid, read anywhere by trilinear interpolation.
//
// ScalarField holds f0, f1 and the morph frames f(., t_k); VectorField holds V_k.
// Outside the grid a scalar field is extended by the distance to the grid's box
// (a signed-distance-like extension, so points that leave the box are pulled back).
#pragma once

#include "grid.h"

#include <vector>

namespace eulermap {

// Zero of a field's value type. vcg::Point3's default constructor leaves its coordinates
// uninitialised, so Point3() is not zero (a stack garbage value here made the tracker
// lose points inside MeshLab, where the stack is not fresh).
template <class Value> Value Zero() { return Value(0); }
template <> inline Point3 Zero<Point3>() { return Point3(0, 0, 0); }

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
    Value r = Zero<Value>();
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const double weight = (di ? w[0] : 1 - w[0]) * (dj ? w[1] : 1 - w[1]) * (dk ? w[2] : 1 - w[2]);
          r += (*this)(c[0] + di, c[1] + dj, c[2] + dk) * weight;
        }
    return r;
  }

  // Cell (lower corner) and local coordinates in [0,1]^3 of the clamped point p.
  void Locate(const Point3 &p, int cell[3], double local[3]) const {
    const Point3 g = grid.ToGrid(p);
    for (int a = 0; a < 3; ++a) {
      const double x = std::min(std::max(g[a], 0.0), double(grid.dims[a] - 1));
      cell[a] = std::min(int(x), grid.dims[a] - 2);
      local[a] = x - cell[a];
    }
  }
};

struct ScalarField : Field<double> {
  using Field<double>::Field;

  // f(p): trilinear inside the box; outside, the value at the nearest box point plus
  // the distance to the box.
  double Value(const Point3 &p) const;
  // Gradient of the trilinear interpolant at p (world units), the box-extension's outside.
  Point3 Gradient(const Point3 &p) const;
  // Central-difference gradient at node (i,j,k) (one-sided at the box faces), world units.
  Point3 NodeGradient(int i, int j, int k) const;
};

using VectorField = Field<Point3>;

} // namespace eulermap
