#include "multigrid.h"

#include <algorithm>

namespace eulermap {

namespace {
constexpr std::size_t kCoarsestNodes = 1000;
constexpr int kSmoothingSweeps = 1;
constexpr int kCoarsestSweeps = 20;

Sym3 operator+(const Sym3 &a, const Sym3 &b) {
  return {a.xx + b.xx, a.xy + b.xy, a.xz + b.xz, a.yy + b.yy, a.yz + b.yz, a.zz + b.zz};
}
Sym3 operator*(const Sym3 &a, float s) { return {a.xx * s, a.xy * s, a.xz * s, a.yy * s, a.yz * s, a.zz * s}; }

// Weight of fine coordinate f in the restriction to coarse coordinate c (f within one
// cell of 2c): 1 at 2c, 1/2 either side.
inline float Weight(int f, int c) { return f == 2 * c ? 1.0f : 0.5f; }

int Neighbours(const vcg::Point3i &d, int i, int j, int k) {
  return (i > 0) + (i + 1 < d[0]) + (j > 0) + (j + 1 < d[1]) + (k > 0) + (k + 1 < d[2]);
}
} // namespace

Sym3 Sym3::ShiftedInverse(double c) const {
  const double a = xx + c, b = xy, d = xz, e = yy + c, f = yz, g = zz + c;
  // Adjugate over determinant of [[a b d] [b e f] [d f g]].
  const double A = e * g - f * f, B = d * f - b * g, C = b * f - d * e;
  const double s = 1 / (a * A + b * B + d * C);
  return {float(A * s), float(B * s), float(C * s), float((a * g - d * d) * s), float((b * d - a * f) * s),
          float((a * e - b * b) * s)};
}

BlockMultigrid::BlockMultigrid(const Grid &grid, double alpha) {
  Level fine;
  fine.dims = grid.dims;
  fine.alpha = alpha;
  levels_.push_back(std::move(fine));
  for (;;) {
    const Level &l = levels_.back();
    if (l.Count() <= kCoarsestNodes || std::min({l.dims[0], l.dims[1], l.dims[2]}) <= 4) break;
    Level c;
    c.dims = vcg::Point3i(l.dims[0] / 2 + 1, l.dims[1] / 2 + 1, l.dims[2] / 2 + 1);
    c.alpha = l.alpha / 4;
    levels_.push_back(std::move(c));
  }
  for (std::size_t n = 0; n < levels_.size(); ++n) {
    Level &l = levels_[n];
    const std::size_t count = l.Count();
    l.data.resize(count);
    l.inverse.resize(count);
    l.x.resize(count), l.b.resize(count);
    l.r.resize(count);
  }
}

void BlockMultigrid::Update() {
  for (std::size_t n = 0; n < levels_.size(); ++n) {
    Level &l = levels_[n];
    if (n > 0) RestrictData(levels_[n - 1], l);
#pragma omp parallel for schedule(static)
    for (int k = 0; k < l.dims[2]; ++k)
      for (int j = 0; j < l.dims[1]; ++j)
        for (int i = 0; i < l.dims[0]; ++i) {
          const std::size_t idx = l.Index(i, j, k);
          l.inverse[idx] = l.data[idx].ShiftedInverse(l.alpha * Neighbours(l.dims, i, j, k));
        }
  }
}

void BlockMultigrid::RestrictData(const Level &fine, Level &coarse) {
  const vcg::Point3i &f = fine.dims;
#pragma omp parallel for schedule(static)
  for (int K = 0; K < coarse.dims[2]; ++K)
    for (int J = 0; J < coarse.dims[1]; ++J)
      for (int I = 0; I < coarse.dims[0]; ++I) {
        Sym3 sum;
        for (int k = std::max(2 * K - 1, 0); k <= std::min(2 * K + 1, f[2] - 1); ++k)
          for (int j = std::max(2 * J - 1, 0); j <= std::min(2 * J + 1, f[1] - 1); ++j)
            for (int i = std::max(2 * I - 1, 0); i <= std::min(2 * I + 1, f[0] - 1); ++i)
              sum = sum + fine.data[fine.Index(i, j, k)] * (Weight(i, I) * Weight(j, J) * Weight(k, K) / 8.0f);
        coarse.data[coarse.Index(I, J, K)] = sum;
      }
}

void BlockMultigrid::Restrict(const Level &fine, const std::vector<vcg::Point3f> &in, Level &coarse,
                              std::vector<vcg::Point3f> &out) {
  const vcg::Point3i &f = fine.dims;
#pragma omp parallel for schedule(static)
  for (int K = 0; K < coarse.dims[2]; ++K)
    for (int J = 0; J < coarse.dims[1]; ++J)
      for (int I = 0; I < coarse.dims[0]; ++I) {
        vcg::Point3f sum(0, 0, 0);
        for (int k = std::max(2 * K - 1, 0); k <= std::min(2 * K + 1, f[2] - 1); ++k)
          for (int j = std::max(2 * J - 1, 0); j <= std::min(2 * J + 1, f[1] - 1); ++j)
            for (int i = std::max(2 * I - 1, 0); i <= std::min(2 * I + 1, f[0] - 1); ++i)
              sum += in[fine.Index(i, j, k)] * (Weight(i, I) * Weight(j, J) * Weight(k, K) / 8.0f);
        out[coarse.Index(I, J, K)] = sum;
      }
}

void BlockMultigrid::ProlongAdd(const Level &coarse, Level &fine) {
  const vcg::Point3i &f = fine.dims;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < f[2]; ++k)
    for (int j = 0; j < f[1]; ++j)
      for (int i = 0; i < f[0]; ++i) {
        // The coarse nodes around fine node (i, j, k): (c0, c1) per axis, equal for an even index.
        const int i0 = i / 2, i1 = (i + 1) / 2, j0 = j / 2, j1 = (j + 1) / 2, k0 = k / 2, k1 = (k + 1) / 2;
        const vcg::Point3f v = (coarse.x[coarse.Index(i0, j0, k0)] + coarse.x[coarse.Index(i1, j0, k0)] +
                          coarse.x[coarse.Index(i0, j1, k0)] + coarse.x[coarse.Index(i1, j1, k0)] +
                          coarse.x[coarse.Index(i0, j0, k1)] + coarse.x[coarse.Index(i1, j0, k1)] +
                          coarse.x[coarse.Index(i0, j1, k1)] + coarse.x[coarse.Index(i1, j1, k1)]) *
                         0.125f;
        fine.x[fine.Index(i, j, k)] += v;
      }
}

void BlockMultigrid::Sweep(Level &l, int colour) {
  const vcg::Point3i &d = l.dims;
  const long sy = d[0], sz = long(d[0]) * d[1];
  std::vector<vcg::Point3f> &x = l.x;
  const float alpha = float(l.alpha);
#pragma omp parallel for schedule(static)
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = (j + k + colour) & 1; i < d[0]; i += 2) {
        const long idx = long(l.Index(i, j, k));
        vcg::Point3f sum(0, 0, 0);
        if (i > 0) sum += x[idx - 1];
        if (i + 1 < d[0]) sum += x[idx + 1];
        if (j > 0) sum += x[idx - sy];
        if (j + 1 < d[1]) sum += x[idx + sy];
        if (k > 0) sum += x[idx - sz];
        if (k + 1 < d[2]) sum += x[idx + sz];
        x[idx] = l.inverse[idx] * (sum * alpha + l.b[idx]);
      }
}

void BlockMultigrid::Residual(Level &l) {
  const vcg::Point3i &d = l.dims;
  const long sy = d[0], sz = long(d[0]) * d[1];
  const std::vector<vcg::Point3f> &x = l.x;
  const float alpha = float(l.alpha);
#pragma omp parallel for schedule(static)
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i) {
        const long idx = long(l.Index(i, j, k));
        vcg::Point3f lap(0, 0, 0);  // sum_j (x_i - x_j)
        if (i > 0) lap += x[idx] - x[idx - 1];
        if (i + 1 < d[0]) lap += x[idx] - x[idx + 1];
        if (j > 0) lap += x[idx] - x[idx - sy];
        if (j + 1 < d[1]) lap += x[idx] - x[idx + sy];
        if (k > 0) lap += x[idx] - x[idx - sz];
        if (k + 1 < d[2]) lap += x[idx] - x[idx + sz];
        l.r[idx] = l.b[idx] - (l.data[idx] * x[idx] + lap * alpha);
      }
}

void BlockMultigrid::Cycle(std::size_t n) {
  Level &l = levels_[n];
  std::fill(l.x.begin(), l.x.end(), vcg::Point3f(0, 0, 0));
  const bool coarsest = n + 1 == levels_.size();
  const int sweeps = coarsest ? kCoarsestSweeps : kSmoothingSweeps;
  for (int s = 0; s < sweeps; ++s) Sweep(l, 0), Sweep(l, 1);
  if (!coarsest) {
    Residual(l);
    Level &c = levels_[n + 1];
    Restrict(l, l.r, c, c.b);
    Cycle(n + 1);
    ProlongAdd(c, l);
  }
  for (int s = 0; s < sweeps; ++s) Sweep(l, 1), Sweep(l, 0);
}

void BlockMultigrid::Precondition(const std::vector<Point3> &r, std::vector<Point3> &z) {
  Level &fine = levels_.front();
  const long n = long(fine.Count());
#pragma omp parallel for schedule(static)
  for (long m = 0; m < n; ++m) fine.b[m] = vcg::Point3f::Construct(r[m]);
  Cycle(0);
#pragma omp parallel for schedule(static)
  for (long m = 0; m < n; ++m) z[m] = Point3::Construct(fine.x[m]);
}

} // namespace eulermap
