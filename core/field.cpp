#include "field.h"

#include <algorithm>

namespace eulermap {

double ScalarField::Value(const Point3 &p) const {
  int c[3];
  double w[3];
  Point3 outside;
  Locate(p, c, w, &outside);
  const double inside = Interpolate(c, w);
  return outside == Point3(0, 0, 0) ? inside : inside + outside.Norm() * grid.h;
}

Point3 ScalarField::Gradient(const Point3 &p) const {
  int c[3];
  double w[3];
  Point3 outside;
  Locate(p, c, w, &outside);
  if (outside != Point3(0, 0, 0)) return outside.Normalize();
  Point3 g(0, 0, 0);
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) {
        const double v = (*this)(c[0] + di, c[1] + dj, c[2] + dk);
        const double wx = di ? w[0] : 1 - w[0], wy = dj ? w[1] : 1 - w[1], wz = dk ? w[2] : 1 - w[2];
        g[0] += v * (di ? 1 : -1) * wy * wz;
        g[1] += v * wx * (dj ? 1 : -1) * wz;
        g[2] += v * wx * wy * (dk ? 1 : -1);
      }
  return g / grid.h;
}

Point3 ScalarField::NodeGradient(int i, int j, int k) const {
  const int c[3] = {i, j, k};
  const std::size_t idx = grid.Index(i, j, k), stride[3] = {1, std::size_t(grid.dims[0]), std::size_t(grid.dims[0]) * grid.dims[1]};
  const double whole = 1 / grid.h, half = 0.5 * whole;
  Point3 g;
  for (int a = 0; a < 3; ++a) {
    const int lo = c[a] > 0, hi = c[a] + 1 < grid.dims[a];  // one-sided at the box faces
    g[a] = (values[idx + hi * stride[a]] - values[idx - lo * stride[a]]) * (lo && hi ? half : whole);
  }
  return g;
}

} // namespace eulermap
