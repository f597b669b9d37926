#include "field.h"

#include <algorithm>

namespace eulermap {

namespace {
// Nearest point of the grid's box to p.
Point3 ClampToBox(const Grid &g, const Point3 &p) {
  const Box3 b = g.Bounds();
  Point3 q;
  for (int a = 0; a < 3; ++a) q[a] = std::min(std::max(p[a], b.min[a]), b.max[a]);
  return q;
}
} // namespace

double ScalarField::Value(const Point3 &p) const {
  const Point3 q = ClampToBox(grid, p);
  return Sample(q) + vcg::Distance(p, q);
}

Point3 ScalarField::Gradient(const Point3 &p) const {
  const Point3 q = ClampToBox(grid, p);
  if (q != p) return (p - q).Normalize();
  int c[3];
  double w[3];
  Locate(p, c, w);
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
  const int idx[3] = {i, j, k};
  Point3 g;
  for (int a = 0; a < 3; ++a) {
    int lo[3] = {i, j, k}, hi[3] = {i, j, k};
    lo[a] = std::max(idx[a] - 1, 0);
    hi[a] = std::min(idx[a] + 1, grid.dims[a] - 1);
    g[a] = ((*this)(hi[0], hi[1], hi[2]) - (*this)(lo[0], lo[1], lo[2])) / ((hi[a] - lo[a]) * grid.h);
  }
  return g;
}

} // namespace eulermap
