#include "multigrid.h"

#include "parallel.h"

#include <algorithm>
#include <numeric>

namespace eulermap {

namespace {
constexpr std::size_t kCoarsestNodes = 1000;
constexpr int kCoarsestSweeps = 20;
constexpr int kCoarseSweeps = 1;  // red-black sweep pairs each way on the levels between (the finest: 1)

// Full weighting (R = P^T / 8) of the values from, on the fine layout, onto the coarse one:
// coarse node (I, J, K) takes w(di) w(dj) w(dk) / 8 of fine node (2I + di, 2J + dj, 2K + dk),
// w(0) = 1, w(+-1) = 1/2 (kRedOnly: only the 13 red ones, those of even di + dj + dk; from is
// 0 at black nodes). A tap has colour di + dj + dk (mod 2) and lies at the centre's position
// plus (di == 1) + dj P_x/2 + dk P_x P_y/2 (red_black.h: the centre's s_x = 2I + 1 is odd),
// and the centre of I lies at that of I = 0 plus I: each tap is a contiguous run along the
// coarse row (vectorised, taps unrolled). Ghosts hold 0, so nodes past the box count for nothing.
template <bool kRedOnly, int N>
void FullWeighting(const RedBlackLayout &fine, const RedBlackArrays<N> &from, const RedBlackLayout &coarse, RedBlackArrays<N> &to) {
  constexpr int kTaps = kRedOnly ? 13 : 27, kChunk = kRedOnly ? 13 : 9;  // taps summed in registers per pass
  int colour[kTaps], taps = 0;
  long offset[kTaps];
  float weight[kTaps];
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if (kRedOnly && ((di + dj + dk) & 1)) continue;
        colour[taps] = (di + dj + dk) & 1;
        offset[taps] = (di == 1) + dj * fine.RowStride() + dk * fine.PlaneStride();
        weight[taps++] = (di ? 0.5f : 1.0f) * (dj ? 0.5f : 1.0f) * (dk ? 0.5f : 1.0f) / 8.0f;
      }
  const int nc = coarse.dims[0];
  ParallelPieces(coarse.dims[2], [&](long begin, long end) {
    std::vector<float> row(nc);
    for (int K = int(begin); K < end; ++K)
      for (int J = 0; J < coarse.dims[1]; ++J) {
        const std::size_t centre = fine.Position(0, 2 * J, 2 * K), first = coarse.Position(0, J, K);
        for (int e = 0; e < N; ++e) {
          const float *tap[kTaps];
          for (int t = 0; t < kTaps; ++t) tap[t] = from.c[colour[t]][e].data() + centre + offset[t];
          for (int t0 = 0; t0 < kTaps; t0 += kChunk)
#pragma omp simd
            for (int I = 0; I < nc; ++I) {
              float sum = t0 ? row[I] : 0.0f;
              for (int t = t0; t < t0 + kChunk; ++t) sum += weight[t] * tap[t][I];
              row[I] = sum;
            }
          // Coarse node (I, J, K): colour I + J + K (mod 2), position that of I = 0 plus (I + 1) / 2.
          float *even = to.c[(J + K) & 1][e].data() + first, *odd = to.c[(J + K + 1) & 1][e].data() + first;
          for (int I = 0; I < nc; I += 2) even[I / 2] = row[I];
          for (int I = 1; I < nc; I += 2) odd[(I + 1) / 2] = row[I];
        }
      }
  }, fine.Nodes() >= kParallelNodes);
}

// D_i = g_i g_i^T + beta_i I (beta null: 0) at every fine node, full weighting onto the coarse
// layout (as FullWeighting<false, 6> of D, without storing the fine D): tap by tap, the six
// products accumulated along the coarse row.
void RestrictBlocks(const RedBlackLayout &fine, const RedBlackArrays<3> &g, const RedBlackArrays<1> *beta,
                    const RedBlackLayout &coarse, RedBlackArrays<6> &to) {
  int colour[27], taps = 0;
  long offset[27];
  float weight[27];
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        colour[taps] = (di + dj + dk) & 1;
        offset[taps] = (di == 1) + dj * fine.RowStride() + dk * fine.PlaneStride();
        weight[taps++] = (di ? 0.5f : 1.0f) * (dj ? 0.5f : 1.0f) * (dk ? 0.5f : 1.0f) / 8.0f;
      }
  const int nc = coarse.dims[0];
  ParallelPieces(coarse.dims[2], [&](long begin, long end) {
    std::vector<float> rows[6];
    for (std::vector<float> &r : rows) r.resize(nc);
    for (int K = int(begin); K < end; ++K)
      for (int J = 0; J < coarse.dims[1]; ++J) {
        const std::size_t centre = fine.Position(0, 2 * J, 2 * K), first = coarse.Position(0, J, K);
        float *r0 = rows[0].data(), *r1 = rows[1].data(), *r2 = rows[2].data(), *r3 = rows[3].data(), *r4 = rows[4].data(),
              *r5 = rows[5].data();
        for (std::vector<float> &r : rows) std::fill(r.begin(), r.end(), 0.0f);
        for (int t = 0; t < taps; ++t) {
          const std::size_t at = centre + offset[t];
          const float *x = g.c[colour[t]][0].data() + at, *y = g.c[colour[t]][1].data() + at, *z = g.c[colour[t]][2].data() + at;
          const float w = weight[t];
#pragma omp simd
          for (int I = 0; I < nc; ++I) {
            const float a = x[I], b = y[I], c = z[I];
            r0[I] += w * (a * a), r1[I] += w * (a * b), r2[I] += w * (a * c);
            r3[I] += w * (b * b), r4[I] += w * (b * c), r5[I] += w * (c * c);
          }
          if (beta) {
            const float *s = beta->c[colour[t]][0].data() + at;
#pragma omp simd
            for (int I = 0; I < nc; ++I) r0[I] += w * s[I], r3[I] += w * s[I], r5[I] += w * s[I];
          }
        }
        // Coarse node (I, J, K): colour I + J + K (mod 2), position that of I = 0 plus (I + 1) / 2.
        for (int e = 0; e < 6; ++e) {
          float *even = to.c[(J + K) & 1][e].data() + first, *odd = to.c[(J + K + 1) & 1][e].data() + first;
          for (int I = 0; I < nc; I += 2) even[I / 2] = rows[e][I];
          for (int I = 1; I < nc; I += 2) odd[(I + 1) / 2] = rows[e][I];
        }
      }
  }, fine.Nodes() >= kParallelNodes);
}
} // namespace

BlockMultigrid::BlockMultigrid(const Grid &grid, double alpha, const Interrupt &interrupt) {
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
    const bool finest = &l == &levels_.front();
    l.layout = RedBlackLayout(l.dims);
    l.r.Resize(l.layout, 1, interrupt);
    if (finest) continue;  // its blocks, x and b come from the solver (Update, Precondition)
    l.data.Resize(l.layout, 2, interrupt);
    l.shift.Resize(l.layout, 2, interrupt);
    ForEachRun(l.layout, 0, 1, [&](int j, int k, int c, const RedBlackLayout::Run &run, std::size_t) {
      for (int n = 0; n < run.count; ++n) l.shift.c[c][0][run.first + n] = float(l.alpha * l.layout.NeighbourCount(run.firstI + 2 * n, j, k));
    });
    l.inverse.Resize(l.layout, 2, interrupt);
    l.diagonal.Resize(l.layout, 1, interrupt);
    l.ownX.Resize(l.layout, 2, interrupt), l.x = &l.ownX;
    l.ownB.Resize(l.layout, 2, interrupt), l.b = &l.ownB;
    for (std::vector<float> &g : l.gathered) AssignPolling(g, l.Count(), 0.0f, interrupt);
  }
}

void BlockMultigrid::Update(const RedBlackArrays<3> &g, const RedBlackArrays<1> &shift, const RedBlackArrays<1> *beta) {
  g_ = &g, shift_ = &shift;
  for (std::size_t n = 1; n < levels_.size(); ++n)  // coarse D = R D (lumped)
    if (n == 1)
      RestrictBlocks(levels_[0].layout, g, beta, levels_[1].layout, levels_[1].data);
    else
      FullWeighting<false>(levels_[n - 1].layout, levels_[n - 1].data, levels_[n].layout, levels_[n].data);
  for (std::size_t n = 1; n < levels_.size(); ++n) {
    Level &l = levels_[n];
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
}

void BlockMultigrid::ProlongAdd(Level &coarse, Level &fine) {
  // The coarse x in Grid::Index order first, so that its rows can be read whole.
  const vcg::Point3i &cd = coarse.dims;
  ForEachRun(coarse.layout, 0, 1, [&](int, int, int c, const RedBlackLayout::Run &run, std::size_t row) {
    for (int a = 0; a < 3; ++a) {
      const float *x = coarse.x->c[c][a].data() + run.first;
      float *to = coarse.gathered[a].data() + row + run.firstI;
      for (int n = 0; n < run.count; ++n) to[2 * n] = x[n];
    }
  });
  const int nc = cd[0];
  ParallelPieces(fine.dims[2], [&](long begin, long end) {
    std::vector<float> sum(nc);
    for (int k = int(begin); k < end; ++k)
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
          float *x = fine.x->c[0][a].data() + run.first;
          if (run.firstI == 0)
            for (int n = 0; n < run.count; ++n) x[n] += 0.25f * sum[n];
          else
            for (int n = 0; n < run.count; ++n) x[n] += 0.125f * (sum[n] + sum[n + 1]);
        }
      }
  }, fine.layout.Nodes() >= kParallelNodes);
}

void BlockMultigrid::Sweep(Level &l, int c, bool fromZero, std::vector<double> *plane) {
  const long hy = l.layout.RowStride(), hz = l.layout.PlaneStride();
  const float alpha = float(l.alpha);
  const bool finest = &l == &levels_.front();
  ForEachRun(l.layout, c, c, [&](int, int k, int, const RedBlackLayout::Run &run, std::size_t) {
    const long w = run.west;
    const float *b[3], *o[3];
    float *x[3];
    for (int a = 0; a < 3; ++a)
      b[a] = l.b->c[c][a].data() + run.first, o[a] = l.x->c[1 - c][a].data() + run.first, x[a] = l.x->c[c][a].data() + run.first;
    auto addDot = [&] {  // a second pass while the run is in cache (as velocity.cpp's Apply)
      if (!plane) return;
      double dot = 0;
#pragma omp simd reduction(+ : dot)
      for (long m = 0; m < run.count; ++m) dot += double(b[0][m]) * x[0][m] + double(b[1][m]) * x[1][m] + double(b[2][m]) * x[2][m];
      (*plane)[k] += dot;
    };
    // x = D^-1 (b + alpha sum_j x_j) at each node of the run, D^-1 applied by `solve`.
    auto sweep = [&](auto &&solve) {
      if (fromZero) {
#pragma omp simd
        for (long m = 0; m < run.count; ++m) solve(m, b[0][m], b[1][m], b[2][m]);
      } else {
#pragma omp simd
        for (long m = 0; m < run.count; ++m)
          solve(m, b[0][m] + alpha * NeighbourSum(o[0], m, w, hy, hz), b[1][m] + alpha * NeighbourSum(o[1], m, w, hy, hz),
                b[2][m] + alpha * NeighbourSum(o[2], m, w, hy, hz));
      }
    };
    if (finest) {
      // (g g^T + s I)^-1 t = (t - g (g . t) / (s + |g|^2)) / s (Sherman-Morrison), s = alpha n_i + beta_i.
      const float *g[3], *shift = shift_->c[c][0].data() + run.first;
      for (int a = 0; a < 3; ++a) g[a] = g_->c[c][a].data() + run.first;
      sweep([&](long m, float t0, float t1, float t2) {
        const float gg = g[0][m] * g[0][m] + g[1][m] * g[1][m] + g[2][m] * g[2][m];
        const float k = (g[0][m] * t0 + g[1][m] * t1 + g[2][m] * t2) / (shift[m] + gg), inv = 1.0f / shift[m];
        x[0][m] = (t0 - g[0][m] * k) * inv;
        x[1][m] = (t1 - g[1][m] * k) * inv;
        x[2][m] = (t2 - g[2][m] * k) * inv;
      });
      return addDot();
    }
    const float *inv[6];
    for (int e = 0; e < 6; ++e) inv[e] = l.inverse.c[c][e].data() + run.first;
    sweep([&](long m, float s0, float s1, float s2) {
      x[0][m] = inv[0][m] * s0 + inv[1][m] * s1 + inv[2][m] * s2;
      x[1][m] = inv[1][m] * s0 + inv[3][m] * s1 + inv[4][m] * s2;
      x[2][m] = inv[2][m] * s0 + inv[4][m] * s1 + inv[5][m] * s2;
    });
    addDot();
  });
}

void BlockMultigrid::Residual(Level &l) {
  const long hy = l.layout.RowStride(), hz = l.layout.PlaneStride();
  const float alpha = float(l.alpha);
  const bool finest = &l == &levels_.front();
  ForEachRun(l.layout, 0, 0, [&](int, int, int, const RedBlackLayout::Run &run, std::size_t) {
    const long w = run.west;
    const float *b[3], *o[3], *x[3];
    float *r[3];
    for (int a = 0; a < 3; ++a)
      b[a] = l.b->c[0][a].data() + run.first, o[a] = l.x->c[1][a].data() + run.first, x[a] = l.x->c[0][a].data() + run.first,
      r[a] = l.r.c[0][a].data() + run.first;
    if (finest) {  // the block times x: g (g . x) + s x
      const float *g[3], *shift = shift_->c[0][0].data() + run.first;
      for (int a = 0; a < 3; ++a) g[a] = g_->c[0][a].data() + run.first;
#pragma omp simd
      for (long m = 0; m < run.count; ++m) {
        const float x0 = x[0][m], x1 = x[1][m], x2 = x[2][m], gx = g[0][m] * x0 + g[1][m] * x1 + g[2][m] * x2;
        r[0][m] = b[0][m] + alpha * NeighbourSum(o[0], m, w, hy, hz) - (g[0][m] * gx + shift[m] * x0);
        r[1][m] = b[1][m] + alpha * NeighbourSum(o[1], m, w, hy, hz) - (g[1][m] * gx + shift[m] * x1);
        r[2][m] = b[2][m] + alpha * NeighbourSum(o[2], m, w, hy, hz) - (g[2][m] * gx + shift[m] * x2);
      }
      return;
    }
    const float *d[6];
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

void BlockMultigrid::Cycle(std::size_t n, std::vector<double> *plane, const Interrupt *interrupt) {
  auto poll = [interrupt] {
    if (interrupt) interrupt->Stop();
  };
  Level &l = levels_[n];
  if (n + 1 == levels_.size()) {  // coarsest
    for (int s = 0; s < kCoarsestSweeps; ++s) Sweep(l, 0, s == 0), Sweep(l, 1, false);
    for (int s = 0; s < kCoarsestSweeps; ++s) {
      const bool last = s + 1 == kCoarsestSweeps;
      Sweep(l, 1, false, last ? plane : nullptr), Sweep(l, 0, false, last ? plane : nullptr);
    }
    return;
  }
  const int sweeps = n == 0 ? 1 : kCoarseSweeps;
  // A poll after each colour of the finest level: each is a pass over half its nodes, and
  // no piece of work between two polls should be longer than one pass (the operator's, the
  // restriction's); the longest gaps at 384^3 were elsewhere (docs/NOTES.md, session 30).
  for (int s = 0; s < sweeps; ++s) Sweep(l, 0, s == 0), poll(), Sweep(l, 1, false);
  poll();
  Residual(l);
  Level &c = levels_[n + 1];
  FullWeighting<true>(l.layout, l.r, c.layout, c.ownB);  // the residual is 0 at black nodes
  poll();
  Cycle(n + 1);
  poll();
  ProlongAdd(c, l);
  for (int s = 0; s < sweeps; ++s) {
    const bool last = s + 1 == sweeps;  // each colour's last sweep
    Sweep(l, 1, false, last ? plane : nullptr), poll(), Sweep(l, 0, false, last ? plane : nullptr);
  }
}

double BlockMultigrid::Precondition(const RedBlackArrays<3> &r, RedBlackArrays<3> &z, const Interrupt &interrupt) {
  interrupt.Stop();
  Level &fine = levels_.front();
  fine.b = &r, fine.x = &z;  // read and written in place
  std::vector<double> plane(fine.dims[2], 0.0);  // r . z by plane, summed in order (as velocity.cpp's Apply)
  Cycle(0, &plane, &interrupt);
  return std::accumulate(plane.begin(), plane.end(), 0.0);
}

} // namespace eulermap
