#include "hermite_field.h"

#include <algorithm>

namespace eulermap {

HermiteField::HermiteField(const ScalarField &f, const VectorField &gradient) : f_(f), gradient_(&gradient) {}
HermiteField::HermiteField(const ScalarField &f, const GradientField &gradient) : f_(f), gradientFloat_(&gradient) {}

void HermiteField::Mixed(int i, int j, int k, double out[4]) const {
  const Grid &grid = f_.grid;
  const int c[3] = {i, j, k};
  // Central difference of gradient component `comp` along axis a, and along b too when
  // b >= 0 (one-sided at the box faces).
  auto difference = [&](int comp, int a, int b) {
    int lo[3] = {c[0], c[1], c[2]}, hi[3] = {c[0], c[1], c[2]};
    for (int axis : {a, b}) {
      if (axis < 0) continue;
      lo[axis] = std::max(c[axis] - 1, 0);
      hi[axis] = std::min(c[axis] + 1, grid.dims[axis] - 1);
    }
    auto at = [&](const int *x, const int *y) {  // component comp at lo/hi along a (x) and b (y)
      int n[3] = {c[0], c[1], c[2]};
      n[a] = x[a];
      if (b >= 0) n[b] = y[b];
      return NodeGradient(n[0], n[1], n[2])[comp];
    };
    double span = (hi[a] - lo[a]) * grid.h;
    if (b < 0) return (at(hi, hi) - at(lo, lo)) / span;
    span *= (hi[b] - lo[b]) * grid.h;
    return (at(hi, hi) - at(hi, lo) - at(lo, hi) + at(lo, lo)) / span;
  };
  out[0] = 0.5 * (difference(1, 0, -1) + difference(0, 1, -1));  // f_xy = (d/dx f_y + d/dy f_x) / 2
  out[1] = 0.5 * (difference(2, 0, -1) + difference(0, 2, -1));  // f_xz
  out[2] = 0.5 * (difference(2, 1, -1) + difference(1, 2, -1));  // f_yz
  out[3] = (difference(0, 1, 2) + difference(1, 0, 2) + difference(2, 0, 1)) / 3;  // f_xyz
}

double HermiteField::Value(const Point3 &p, Point3 *gradient) const {
  int c[3];
  double w[3];
  Point3 outside;
  f_.Locate(p, c, w, &outside);
  const double h = f_.grid.h;
  // basis[a][end][order]: the value (order 0: H) and slope (order 1: G) bases of the cell's
  // lower (end 0) and upper (end 1) node along axis a, at w[a]; slope: their derivatives in w.
  double basis[3][2][2], slope[3][2][2];
  for (int a = 0; a < 3; ++a) {
    const double t = w[a], t2 = t * t, t3 = t2 * t;
    basis[a][0][0] = 1 - 3 * t2 + 2 * t3, slope[a][0][0] = 6 * t2 - 6 * t;
    basis[a][1][0] = 3 * t2 - 2 * t3, slope[a][1][0] = 6 * t - 6 * t2;
    basis[a][0][1] = h * (t - 2 * t2 + t3), slope[a][0][1] = h * (1 - 4 * t + 3 * t2);
    basis[a][1][1] = h * (t3 - t2), slope[a][1][1] = h * (3 * t2 - 2 * t);
  }
  double value = 0;
  Point3 g(0, 0, 0);
  for (int corner = 0; corner < 8; ++corner) {
    const int end[3] = {corner & 1, corner >> 1 & 1, corner >> 2 & 1};
    const int i = c[0] + end[0], j = c[1] + end[1], k = c[2] + end[2];
    // Derivatives by order mask m (bit a: differentiated along axis a): f, f_x, f_y, f_xy,
    // f_z, f_xz, f_yz, f_xyz.
    double mixed[4];
    Mixed(i, j, k, mixed);
    const Point3 first = NodeGradient(i, j, k);
    const double d[8] = {f_(i, j, k), first.X(), first.Y(), mixed[0], first.Z(), mixed[1], mixed[2], mixed[3]};
    for (int m = 0; m < 8; ++m) {
      const double bx = basis[0][end[0]][m & 1], by = basis[1][end[1]][m >> 1 & 1], bz = basis[2][end[2]][m >> 2 & 1];
      value += d[m] * bx * by * bz;
      if (gradient) {
        g[0] += d[m] * slope[0][end[0]][m & 1] * by * bz;
        g[1] += d[m] * bx * slope[1][end[1]][m >> 1 & 1] * bz;
        g[2] += d[m] * bx * by * slope[2][end[2]][m >> 2 & 1];
      }
    }
  }
  const bool out = outside != Point3(0, 0, 0);
  if (gradient) *gradient = out ? Point3(outside).Normalize() : g / h;
  return out ? value + outside.Norm() * h : value;
}

} // namespace eulermap
