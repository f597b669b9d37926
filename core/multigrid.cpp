#include "multigrid.h"

#include <algorithm>

namespace eulermap {

namespace {
constexpr std::size_t kCoarsestNodes = 1000;
constexpr int kCoarsestSweeps = 20;
} // namespace

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
  for (Level &l : levels_) {
    l.layout = RedBlackLayout(l.dims);
    l.data.Resize(l.layout);
    l.shift.Resize(l.layout);
    ForEachRun(l.layout, 0, 1, [&](int j, int k, int c, const RedBlackLayout::Run &run, std::size_t) {
      for (int n = 0; n < run.count; ++n) l.shift.c[c][0][run.first + n] = float(l.alpha * l.layout.NeighbourCount(run.firstI + 2 * n, j, k));
    });
    l.inverse.Resize(l.layout);
    l.diagonal.Resize(l.layout, 1);
    l.x.Resize(l.layout);
    l.b.Resize(l.layout);
    l.r.Resize(l.layout, 1);
    if (&l != &levels_.front())
      for (std::vector<float> &g : l.gathered) g.resize(l.Count());
  }
}

void BlockMultigrid::Update() {
  for (std::size_t n = 1; n < levels_.size(); ++n) RestrictData(levels_[n - 1], levels_[n]);
  for (Level &l : levels_)
    ForEachRun(l.layout, 0, 1, [&](int, int, int c, const RedBlackLayout::Run &run, std::size_t) {
      const float *d[6], *shift = l.shift.c[c][0].data() + run.first;
      float *inv[6], *diag[6];
      for (int e = 0; e < 6; ++e)
        d[e] = l.data.c[c][e].data() + run.first, inv[e] = l.inverse.c[c][e].data() + run.first,
        diag[e] = c == 0 ? l.diagonal.c[0][e].data() + run.first : nullptr;
#pragma omp simd
      for (long m = 0; m < run.count; ++m) {
        // A = D + alpha n I = [[a b p] [b e f] [p f g]]; A^-1 = adjugate / determinant, in double.
        const double a = double(d[0][m]) + shift[m], b = d[1][m], p = d[2][m], e = double(d[3][m]) + shift[m], f = d[4][m],
                     g = double(d[5][m]) + shift[m];
        const double A = e * g - f * f, B = p * f - b * g, C = b * f - p * e, s = 1 / (a * A + b * B + p * C);
        inv[0][m] = float(A * s), inv[1][m] = float(B * s), inv[2][m] = float(C * s);
        inv[3][m] = float((a * g - p * p) * s), inv[4][m] = float((b * p - a * f) * s), inv[5][m] = float((a * e - b * b) * s);
      }
      if (c == 0)
        for (int e = 0; e < 6; ++e)
#pragma omp simd
          for (long m = 0; m < run.count; ++m) diag[e][m] = d[e][m] + (e == 0 || e == 3 || e == 5 ? shift[m] : 0.0f);
    });
}

void BlockMultigrid::RestrictData(const Level &fine, Level &coarse) {
  // Full weighting of all 27 fine nodes around fine (2I, 2J, 2K), weight w(di) w(dj) w(dk) / 8,
  // w(0) = 1, w(+-1) = 1/2: the node (2I + di, ...) has colour di + dj + dk (mod 2) and lies at
  // position m + (di == 1) + dj P_x/2 + dk P_x P_y/2, m that of the centre (red_black.h: its
  // s_x is odd). Ghosts hold 0, as nodes past the box count for nothing.
  const long hy = fine.layout.RowStride(), hz = fine.layout.PlaneStride();
#pragma omp parallel for schedule(static)
  for (int K = 0; K < coarse.dims[2]; ++K)
    for (int J = 0; J < coarse.dims[1]; ++J)
      for (int I = 0; I < coarse.dims[0]; ++I) {
        const std::size_t m = fine.layout.Position(2 * I, 2 * J, 2 * K), to = coarse.layout.Position(I, J, K);
        float sum[6] = {0, 0, 0, 0, 0, 0};
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int colour = (di + dj + dk) & 1;
              const float weight = (di ? 0.5f : 1.0f) * (dj ? 0.5f : 1.0f) * (dk ? 0.5f : 1.0f) / 8.0f;
              const std::size_t at = m + (di == 1) + dj * hy + dk * hz;
              for (int e = 0; e < 6; ++e) sum[e] += fine.data.c[colour][e][at] * weight;
            }
        const int c = RedBlackLayout::Colour(I, J, K);
        for (int e = 0; e < 6; ++e) coarse.data.c[c][e][to] = sum[e];
      }
}

void BlockMultigrid::Restrict(const Level &fine, Level &coarse) {
  // Full weighting, coarse node (I, J, K) at fine (2I, 2J, 2K): weight 1/8 there, 1/32 at
  // the 12 fine nodes two of whose coordinates differ by 1 (red); the 14 others are black,
  // where the residual is 0. Positions from the centre's m (red_black.h: s_x = 2I + 1 is
  // odd, so i - 1 lies at m and i + 1 at m + 1).
  const long hy = fine.layout.RowStride(), hz = fine.layout.PlaneStride();
#pragma omp parallel for schedule(static)
  for (int K = 0; K < coarse.dims[2]; ++K)
    for (int J = 0; J < coarse.dims[1]; ++J)
      for (int I = 0; I < coarse.dims[0]; ++I) {
        const std::size_t m = fine.layout.Position(2 * I, 2 * J, 2 * K), to = coarse.layout.Position(I, J, K);
        const int c = RedBlackLayout::Colour(I, J, K);
        for (int a = 0; a < 3; ++a) {
          const float *v = fine.r.c[0][a].data() + m;
          const float edges = v[-hy - hz] + v[hz - hy] + v[hy - hz] + v[hy + hz] + v[-hy] + v[1 - hy] + v[hy] + v[1 + hy] +
                              v[-hz] + v[1 - hz] + v[hz] + v[1 + hz];
          coarse.b.c[c][a][to] = v[0] * 0.125f + edges * 0.03125f;
        }
      }
}

void BlockMultigrid::ProlongAdd(Level &coarse, Level &fine) {
  // The coarse x in Grid::Index order first, so that its rows can be read whole.
  const vcg::Point3i &cd = coarse.dims;
  ForEachRun(coarse.layout, 0, 1, [&](int, int, int c, const RedBlackLayout::Run &run, std::size_t row) {
    for (int a = 0; a < 3; ++a)
      for (int n = 0; n < run.count; ++n) coarse.gathered[a][row + run.firstI + 2 * n] = coarse.x.c[c][a][run.first + n];
  });
  const int nc = cd[0];
#pragma omp parallel
  {
    std::vector<float> sum(nc);
#pragma omp for schedule(static)
    for (int k = 0; k < fine.dims[2]; ++k)
      for (int j = 0; j < fine.dims[1]; ++j) {
        // The coarse rows around fine row (j, k), (J0, J1) x (K0, K1) (equal for an even
        // index), summed: 4 times the trilinear interpolation in y and z. Then in x, onto
        // the red nodes: i = 2I takes coarse node I, i = 2I + 1 the mean of I and I + 1.
        const std::size_t J0 = j / 2, J1 = (j + 1) / 2, K0 = k / 2, K1 = (k + 1) / 2;
        const RedBlackLayout::Run run = fine.layout.RowRun(0, j, k);
        for (int a = 0; a < 3; ++a) {
          const float *g = coarse.gathered[a].data();
          const float *r00 = g + nc * (J0 + cd[1] * K0), *r10 = g + nc * (J1 + cd[1] * K0), *r01 = g + nc * (J0 + cd[1] * K1),
                      *r11 = g + nc * (J1 + cd[1] * K1);
          for (int I = 0; I < nc; ++I) sum[I] = (r00[I] + r10[I]) + (r01[I] + r11[I]);
          float *x = fine.x.c[0][a].data() + run.first;
          if (run.firstI == 0)
            for (int n = 0; n < run.count; ++n) x[n] += 0.25f * sum[n];
          else
            for (int n = 0; n < run.count; ++n) x[n] += 0.125f * (sum[n] + sum[n + 1]);
        }
      }
  }
}

void BlockMultigrid::Sweep(Level &l, int c, bool fromZero) {
  const long hy = l.layout.RowStride(), hz = l.layout.PlaneStride();
  const float alpha = float(l.alpha);
  ForEachRun(l.layout, c, c, [&](int, int, int, const RedBlackLayout::Run &run, std::size_t) {
    const long w = run.west;
    const float *b[3], *o[3], *inv[6];
    float *x[3];
    for (int a = 0; a < 3; ++a)
      b[a] = l.b.c[c][a].data() + run.first, o[a] = l.x.c[1 - c][a].data() + run.first, x[a] = l.x.c[c][a].data() + run.first;
    for (int e = 0; e < 6; ++e) inv[e] = l.inverse.c[c][e].data() + run.first;
    auto solve = [&](long m, float s0, float s1, float s2) {
      x[0][m] = inv[0][m] * s0 + inv[1][m] * s1 + inv[2][m] * s2;
      x[1][m] = inv[1][m] * s0 + inv[3][m] * s1 + inv[4][m] * s2;
      x[2][m] = inv[2][m] * s0 + inv[4][m] * s1 + inv[5][m] * s2;
    };
    if (fromZero) {
#pragma omp simd
      for (long m = 0; m < run.count; ++m) solve(m, b[0][m], b[1][m], b[2][m]);
    } else {
#pragma omp simd
      for (long m = 0; m < run.count; ++m)
        solve(m, b[0][m] + alpha * NeighbourSum(o[0], m, w, hy, hz), b[1][m] + alpha * NeighbourSum(o[1], m, w, hy, hz),
              b[2][m] + alpha * NeighbourSum(o[2], m, w, hy, hz));
    }
  });
}

void BlockMultigrid::Residual(Level &l) {
  const long hy = l.layout.RowStride(), hz = l.layout.PlaneStride();
  const float alpha = float(l.alpha);
  ForEachRun(l.layout, 0, 0, [&](int, int, int, const RedBlackLayout::Run &run, std::size_t) {
    const long w = run.west;
    const float *b[3], *o[3], *x[3], *d[6];
    float *r[3];
    for (int a = 0; a < 3; ++a)
      b[a] = l.b.c[0][a].data() + run.first, o[a] = l.x.c[1][a].data() + run.first, x[a] = l.x.c[0][a].data() + run.first,
      r[a] = l.r.c[0][a].data() + run.first;
    for (int e = 0; e < 6; ++e) d[e] = l.diagonal.c[0][e].data() + run.first;
#pragma omp simd
    for (long m = 0; m < run.count; ++m) {
      const float x0 = x[0][m], x1 = x[1][m], x2 = x[2][m];
      r[0][m] = b[0][m] + alpha * NeighbourSum(o[0], m, w, hy, hz) - (d[0][m] * x0 + d[1][m] * x1 + d[2][m] * x2);
      r[1][m] = b[1][m] + alpha * NeighbourSum(o[1], m, w, hy, hz) - (d[1][m] * x0 + d[3][m] * x1 + d[4][m] * x2);
      r[2][m] = b[2][m] + alpha * NeighbourSum(o[2], m, w, hy, hz) - (d[2][m] * x0 + d[4][m] * x1 + d[5][m] * x2);
    }
  });
}

void BlockMultigrid::Cycle(std::size_t n) {
  Level &l = levels_[n];
  if (n + 1 == levels_.size()) {  // coarsest
    for (int s = 0; s < kCoarsestSweeps; ++s) Sweep(l, 0, s == 0), Sweep(l, 1, false);
    for (int s = 0; s < kCoarsestSweeps; ++s) Sweep(l, 1, false), Sweep(l, 0, false);
    return;
  }
  Sweep(l, 0, true), Sweep(l, 1, false);
  Residual(l);
  Level &c = levels_[n + 1];
  Restrict(l, c);
  Cycle(n + 1);
  ProlongAdd(c, l);
  Sweep(l, 1, false), Sweep(l, 0, false);
}

void BlockMultigrid::Precondition(const RedBlackArrays<3, double> &r, RedBlackArrays<3, double> &z) {
  Level &fine = levels_.front();
  const long n = long(fine.layout.Positions());
  for (int c = 0; c < 2; ++c)
    for (int a = 0; a < 3; ++a) {
      const double *from = r.c[c][a].data();
      float *to = fine.b.c[c][a].data();
#pragma omp parallel for simd schedule(static)
      for (long m = 0; m < n; ++m) to[m] = float(from[m]);
    }
  Cycle(0);
  for (int c = 0; c < 2; ++c)
    for (int a = 0; a < 3; ++a) {
      const float *from = fine.x.c[c][a].data();
      double *to = z.c[c][a].data();
#pragma omp parallel for simd schedule(static)
      for (long m = 0; m < n; ++m) to[m] = from[m];
    }
}

} // namespace eulermap
