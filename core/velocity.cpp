#include "velocity.h"

#include "block_sum.h"
#include "parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace eulermap {

namespace {
// The 6 arrays (colour c, component a at 3c + a) of system vectors, as pointers.
template <class Vectors> auto Arrays(Vectors &v) {
  std::array<decltype(v.c[0][0].data()), 6> p;
  for (int c = 0; c < 2; ++c)
    for (int a = 0; a < 3; ++a) p[3 * c + a] = v.c[c][a].data();
  return p;
}

double Dot(const RedBlackArrays<3> &a, const RedBlackArrays<3> &b) {
  const auto pa = Arrays(a), pb = Arrays(b);
  return BlockSum(long(a.c[0][0].size()), [&](long begin, long end) {
    double s = 0;
    for (int e = 0; e < 6; ++e) {
      const float *u = pa[e], *v = pb[e];
#pragma omp simd reduction(+ : s)
      for (long m = begin; m < end; ++m) s += double(u[m]) * v[m];
    }
    return s;
  });
}
} // namespace

VelocitySolve VelocitySolver::Solve(const ScalarField &fk, const ScalarField &fk1, double dt, VectorField &V,
                                    const VectorField &prior, const ScalarField &priorWeight, const Interrupt &interrupt) {
  grid_ = fk.grid;
  // The first step allocates (and zeroes: the pages are touched) every array: seconds on big
  // grids, so the interrupt is asked while each is filled.
  if (V.values.size() != grid_.NodeCount() || V.grid.dims != grid_.dims)
    V.grid = grid_, AssignPolling(V.values, grid_.NodeCount(), Point3(0, 0, 0), interrupt);
  if (layout_.dims != grid_.dims) {
    layout_ = RedBlackLayout(grid_.dims);
    for (Vectors *v : {&g_, &x_, &r_, &p_, &q_, &previous_}) v->Resize(layout_, 2, interrupt);
    shift_.Resize(layout_, 2, interrupt);
  }
  const bool withPrior = !prior.values.empty(), multigrid = method_ == Method::Multigrid;
  if (multigrid && (!multigrid_ || multigrid_->Dims() != grid_.dims))
    multigrid_ = std::make_unique<BlockMultigrid>(grid_, alpha_, interrupt);
  if (interrupt.Stop()) return VelocitySolve();
  // The prior's weights beta_i for the multigrid (its coarse blocks), in p's first arrays (free
  // until the solve).
  RedBlackArrays<1> beta;
  const bool lendBeta = multigrid && withPrior;
  auto borrow = [&] {
    for (int c = 0; c < 2; ++c) beta.c[c][0].swap(p_.c[c][0]);
  };
  if (lendBeta) borrow();
  // g = grad of (f_k + f_k+1)/2 (central differences, one-sided on the box's faces), f_t =
  // (f_k+1 - f_k)/dt, b = -g f_t + beta P (right-hand side of (*), into r), shift = alpha n_i
  // + beta_i; x = V.
  const vcg::Point3i d = grid_.dims;
  const double *f0 = fk.values.data(), *f1 = fk1.values.data();
  const Point3 *v = V.values.data(), *motion = withPrior ? prior.values.data() : nullptr;
  const double *weight = withPrior ? priorWeight.values.data() : nullptr;
  const std::size_t sy = std::size_t(d.X()), sz = sy * d.Y();
  const double whole = 0.5 / grid_.h, half = 0.5 * whole;  // 0.5: of the mean of the two frames
  const int planesBetweenPolls = std::max(1, int(kNodesBetweenPolls / (sy * d.Y())));
  const long nx = d.X();
  ParallelPieces(d.Z(), [&](long begin, long end) {
    // A real row at a time: its nodes in Grid::Index order first (contiguous: vectorised),
    // then split by colour into the layout's arrays.
    std::vector<float> G[3], B[3], X[3], S(nx), W(nx);
    for (int a = 0; a < 3; ++a) G[a].resize(nx), B[a].resize(nx), X[a].resize(nx);
    const std::vector<double> none(withPrior ? 0 : nx, 0.0);  // beta without a prior
    for (int k = int(begin); k < end; ++k)
      for (int j = 0; j < d.Y(); ++j) {
        if (j == 0 && k % planesBetweenPolls == 0) interrupt.Stop();  // asks the callback on the caller's thread
        const std::size_t row = sy * (j + std::size_t(d.Y()) * k);
        const int across = (j > 0) + (j + 1 < d.Y()) + (k > 0) + (k + 1 < d.Z());  // neighbours in y and z
        // Central differences (one-sided on the box's faces); in y and z the same offsets along the row.
        const long yLo = j > 0 ? long(sy) : 0, yHi = j + 1 < d.Y() ? long(sy) : 0, zLo = k > 0 ? long(sz) : 0,
                   zHi = k + 1 < d.Z() ? long(sz) : 0;
        const double yScale = yLo && yHi ? half : whole, zScale = zLo && zHi ? half : whole;
        const double *a0 = f0 + row, *a1 = f1 + row, *w = withPrior ? weight + row : none.data();
        const Point3 *vr = v + row;
        // Node i with x-neighbours lo, hi, the x-difference's scale and its neighbour count n.
        auto node = [&](long i, long lo, long hi, double xScale, int n) {
          const double gx = ((a0[hi] + a1[hi]) - (a0[lo] + a1[lo])) * xScale;
          const double gy = ((a0[i + yHi] + a1[i + yHi]) - (a0[i - yLo] + a1[i - yLo])) * yScale;
          const double gz = ((a0[i + zHi] + a1[i + zHi]) - (a0[i - zLo] + a1[i - zLo])) * zScale;
          const double beta = w[i], ft = (a1[i] - a0[i]) / dt;
          G[0][i] = float(gx), G[1][i] = float(gy), G[2][i] = float(gz);
          B[0][i] = float(-gx * ft), B[1][i] = float(-gy * ft), B[2][i] = float(-gz * ft);
          X[0][i] = float(vr[i][0]), X[1][i] = float(vr[i][1]), X[2][i] = float(vr[i][2]);
          S[i] = float(alpha_ * n + beta), W[i] = float(beta);
        };
        if (nx == 1) {
          node(0, 0, 0, whole, across);
        } else {
          node(0, 0, 1, whole, across + 1);
#pragma omp simd
          for (long i = 1; i < nx - 1; ++i) node(i, i - 1, i + 1, half, across + 2);
          node(nx - 1, nx - 2, nx - 1, whole, across + 1);
        }
        if (withPrior)
          for (long i = 0; i < nx; ++i)
            for (int a = 0; a < 3; ++a) B[a][i] = float(B[a][i] + motion[row + i][a] * weight[row + i]);
        for (int c = 0; c < 2; ++c) {
          const RedBlackLayout::Run run = layout_.RowRun(c, j, k);
          const std::size_t m0 = run.first;
          const int i0 = run.firstI;
          for (int a = 0; a < 3; ++a) {
            float *g = g_.c[c][a].data() + m0, *b = r_.c[c][a].data() + m0, *x = x_.c[c][a].data() + m0,
                  *last = previous_.c[c][a].data() + m0;
            const float *Ga = G[a].data() + i0, *Ba = B[a].data() + i0, *Xa = X[a].data() + i0;
            for (int t = 0; t < run.count; ++t) {
              g[t] = Ga[2 * t], b[t] = Ba[2 * t], x[t] = Xa[2 * t];
              last[t] = Xa[2 * t] - last[t];  // d = V_k-1 - V_k-2
            }
          }
          float *shift = shift_.c[c][0].data() + m0;
          for (int t = 0; t < run.count; ++t) shift[t] = S[i0 + 2 * t];
          if (lendBeta) {
            float *to = beta.c[c][0].data() + m0;
            for (int t = 0; t < run.count; ++t) to[t] = W[i0 + 2 * t];
          }
        }
      }
  }, layout_.Nodes() >= kParallelNodes);
  if (multigrid) multigrid_->Update(g_, shift_, lendBeta ? &beta : nullptr);
  if (lendBeta) borrow();  // p gets its arrays back
  const double bNorm = std::sqrt(Dot(r_, r_));
  VelocitySolve s;
  if (bNorm == 0) {  // no motion: V = 0 solves (*) exactly
    std::fill(V.values.begin(), V.values.end(), Point3(0, 0, 0));
    return s;
  }
  if (interrupt.Stop()) return s;  // the frame and the system's assembly were a piece of work too
  if (method_ == Method::GaussSeidel) {
    previous_ = x_;  // V_k-1 (Gauss-Seidel starts from it: the comparison of the paper's update)
    p_ = r_;  // b
    s = SolveGaussSeidel(x_, bNorm, interrupt);
  } else if (method_ == Method::ConjugateGradient) {
    s = SolveConjugateGradient(x_, bNorm, [this](const Vectors &r, Vectors &z) { return BlockJacobi(r, z); }, interrupt);
  } else {
    // A poll before each V-cycle too: an iteration is two halves of about equal work.
    s = SolveConjugateGradient(x_, bNorm, [&](const Vectors &r, Vectors &z) { return multigrid_->Precondition(r, z, interrupt); },
                               interrupt);
  }
  interrupt.Stop();  // the solve's last iteration
  Point3 *out = V.values.data();
  ForEachRun(layout_, 0, 1, [&](int, int, int c, const RedBlackLayout::Run &run, std::size_t row) {
    const float *x[3] = {x_.c[c][0].data() + run.first, x_.c[c][1].data() + run.first, x_.c[c][2].data() + run.first};
    for (int t = 0; t < run.count; ++t) out[row + run.firstI + 2 * t] = Point3(x[0][t], x[1][t], x[2][t]);
  });
  return s;
}

double VelocitySolver::Apply(const Vectors &x, Vectors &out) const {
  const long hy = layout_.RowStride(), hz = layout_.PlaneStride();
  const float alpha = float(alpha_);
  // x . out summed by plane (each plane's runs in order, by one thread), then the planes in
  // order: the same bits for any number of threads.
  std::vector<double> plane(layout_.dims[2], 0.0);
  ForEachRun(layout_, 0, 1, [&](int, int k, int c, const RedBlackLayout::Run &run, std::size_t) {
    const long w = run.west;
    const float *v[3], *o[3], *g[3], *shift = shift_.c[c][0].data() + run.first;
    float *y[3];
    for (int a = 0; a < 3; ++a)
      v[a] = x.c[c][a].data() + run.first, o[a] = x.c[1 - c][a].data() + run.first, g[a] = g_.c[c][a].data() + run.first,
      y[a] = out.c[c][a].data() + run.first;
    // (g g^T + (alpha n_i + beta_i) I) V_i - alpha sum_j V_j, the left-hand side of (*).
#pragma omp simd
    for (long m = 0; m < run.count; ++m) {
      const float gv = g[0][m] * v[0][m] + g[1][m] * v[1][m] + g[2][m] * v[2][m];
      y[0][m] = g[0][m] * gv + shift[m] * v[0][m] - alpha * NeighbourSum(o[0], m, w, hy, hz);
      y[1][m] = g[1][m] * gv + shift[m] * v[1][m] - alpha * NeighbourSum(o[1], m, w, hy, hz);
      y[2][m] = g[2][m] * gv + shift[m] * v[2][m] - alpha * NeighbourSum(o[2], m, w, hy, hz);
    }
    double dot = 0;  // a second pass while the run is in cache: a reduction in the loop above is not vectorised
#pragma omp simd reduction(+ : dot)
    for (long m = 0; m < run.count; ++m) dot += double(v[0][m]) * y[0][m] + double(v[1][m]) * y[1][m] + double(v[2][m]) * y[2][m];
    plane[k] += dot;
  });
  return std::accumulate(plane.begin(), plane.end(), 0.0);
}

double VelocitySolver::Residual(const Vectors &x, const Vectors &b, Vectors &r, Vectors &ax) const {
  Apply(x, ax);
  const auto pb = Arrays(b);
  const auto pa = Arrays(ax);
  const auto pr = Arrays(r);
  return std::sqrt(BlockSum(long(layout_.Positions()), [&](long begin, long end) {
    double s = 0;
    for (int e = 0; e < 6; ++e) {
      const float *u = pb[e], *w = pa[e];
      float *v = pr[e];
#pragma omp simd reduction(+ : s)
      for (long m = begin; m < end; ++m) {
        v[m] = u[m] - w[m];
        s += double(v[m]) * v[m];
      }
    }
    return s;
  }));
}

double VelocitySolver::BlockJacobi(const Vectors &r, Vectors &z) const {
  // (g g^T + c I)^-1 = (I - g g^T / (c + |g|^2)) / c (Sherman-Morrison), c = alpha n_i + beta_i.
  std::vector<double> plane(layout_.dims[2], 0.0);  // r . z by plane, in order (as Apply)
  ForEachRun(layout_, 0, 1, [&](int, int k, int c, const RedBlackLayout::Run &run, std::size_t) {
    const float *v[3], *g[3], *shift = shift_.c[c][0].data() + run.first;
    float *y[3];
    for (int a = 0; a < 3; ++a)
      v[a] = r.c[c][a].data() + run.first, g[a] = g_.c[c][a].data() + run.first, y[a] = z.c[c][a].data() + run.first;
#pragma omp simd
    for (long m = 0; m < run.count; ++m) {
      const float gg = g[0][m] * g[0][m] + g[1][m] * g[1][m] + g[2][m] * g[2][m];
      const float k = (g[0][m] * v[0][m] + g[1][m] * v[1][m] + g[2][m] * v[2][m]) / (shift[m] + gg);
      y[0][m] = (v[0][m] - g[0][m] * k) / shift[m];
      y[1][m] = (v[1][m] - g[1][m] * k) / shift[m];
      y[2][m] = (v[2][m] - g[2][m] * k) / shift[m];
    }
    double dot = 0;
#pragma omp simd reduction(+ : dot)
    for (long m = 0; m < run.count; ++m) dot += double(v[0][m]) * y[0][m] + double(v[1][m]) * y[1][m] + double(v[2][m]) * y[2][m];
    plane[k] += dot;
  });
  return std::accumulate(plane.begin(), plane.end(), 0.0);
}

VelocitySolve VelocitySolver::SolveConjugateGradient(Vectors &x, double bNorm,
                                                     const std::function<double(const Vectors &, Vectors &)> &precondition,
                                                     const Interrupt &interrupt) {
  VelocitySolve s;
  const long n = long(layout_.Positions());
  Vectors &r = r_, &z = q_, &p = p_, &q = q_;
  const auto px = Arrays(x), pr = Arrays(r), pz = Arrays(z), pp = Arrays(p), pq = Arrays(q);
  // The start: x = V_k-1 + theta d along d = V_k-1 - V_k-2 (in previous_), theta minimising the
  // error's energy along d: theta = r . d / d . A d with r = b - A V_k-1 (theta = 1: the linear
  // extrapolation in time; never a worse start than V_k-1). previous_ then holds V_k-1.
  const auto pd = Arrays(previous_);
  const double dAd = Apply(previous_, q);  // q = A d
  interrupt.Stop();                         // each pass over the grid's nodes a piece of work
  Residual(x, r, r, p);  // r held b; p: scratch
  interrupt.Stop();
  const double theta = dAd > 0 ? Dot(r, previous_) / dAd : 0;
  const float thetaf = float(theta);
  double rNorm = std::sqrt(BlockSum(n, [&](long begin, long end) {  // x += theta d, r -= theta A d, |r|^2
    double t = 0;
    for (int e = 0; e < 6; ++e) {
      float *u = px[e], *v = pr[e], *d = pd[e];
      const float *dq = pq[e];
#pragma omp simd reduction(+ : t)
      for (long m = begin; m < end; ++m) {
        const float start = u[m];
        u[m] = start + d[m] * thetaf;
        d[m] = start;
        v[m] -= dq[m] * thetaf;
        t += double(v[m]) * v[m];
      }
    }
    return t;
  }));
  auto done = [&] { return rNorm <= tolerance_ * bNorm || s.iterations >= maxIterations_; };
  double rz = done() ? 0 : precondition(r, z);
  if (!done()) p = z;
  // x += step p is put off to the next pass over p (p = z + beta p), or to the end.
  auto advance = [&](float step) {
    ParallelPieces(n, [&](long begin, long end) {
      for (int e = 0; e < 6; ++e) {
        float *u = px[e];
        const float *v = pp[e];
#pragma omp simd
        for (long m = begin; m < end; ++m) u[m] += v[m] * step;
      }
    });
  };
  while (!done() && !interrupt.Stop()) {
    const double step = rz / Apply(p, q);  // q = A p
    interrupt.Stop();                        // as long a piece of work as a colour's sweep
    const float stepf = float(step);
    rNorm = std::sqrt(BlockSum(n, [&](long begin, long end) {  // r -= step q, then |r|^2
      double t = 0;
      for (int e = 0; e < 6; ++e) {
        float *v = pr[e];
        const float *dq = pq[e];
#pragma omp simd reduction(+ : t)
        for (long m = begin; m < end; ++m) {
          v[m] -= dq[m] * stepf;
          t += double(v[m]) * v[m];
        }
      }
      return t;
    }));
    ++s.iterations;
    if (done()) {  // no preconditioning for a direction that is not taken
      advance(stepf);
      break;
    }
    const double rzNext = precondition(r, z);
    const float beta = float(rzNext / rz);
    rz = rzNext;
    ParallelPieces(n, [&](long begin, long end) {
      for (int e = 0; e < 6; ++e) {  // x += step p, then p = z + beta p
        float *u = pp[e], *w = px[e];
        const float *v = pz[e];
#pragma omp simd
        for (long m = begin; m < end; ++m) {
          w[m] += u[m] * stepf;
          u[m] = v[m] + u[m] * beta;
        }
      }
    });
  }
  s.residual = rNorm / bNorm;
  return s;
}

VelocitySolve VelocitySolver::SolveGaussSeidel(Vectors &x, double bNorm, const Interrupt &interrupt) {
  VelocitySolve s;
  const long hy = layout_.RowStride(), hz = layout_.PlaneStride();
  const float alpha = float(alpha_);
  const Vectors &rhs = p_;
  double rNorm = Residual(x, rhs, r_, r_);
  // Residuals cost as much as a sweep: check every few sweeps.
  const int checkEvery = 10;
  while (rNorm > tolerance_ * bNorm && s.iterations < maxIterations_ && !interrupt.Stop()) {
    for (int sweep = 0; sweep < checkEvery && s.iterations < maxIterations_; ++sweep, ++s.iterations)
      for (int colour = 0; colour < 2; ++colour)
        ForEachRun(layout_, colour, colour, [&](int, int, int c, const RedBlackLayout::Run &run, std::size_t) {
          const long w = run.west;
          const float *o[3], *b[3], *g[3], *shift = shift_.c[c][0].data() + run.first;
          float *v[3];
          for (int a = 0; a < 3; ++a)
            v[a] = x.c[c][a].data() + run.first, o[a] = x.c[1 - c][a].data() + run.first, b[a] = rhs.c[c][a].data() + run.first,
            g[a] = g_.c[c][a].data() + run.first;
          // Eq. 5 from (*): V = Vbar - g (g . Vbar + f_t) / (alpha n + |g|^2), with b = -g f_t,
          // written for a general b: solve (g g^T + c I) V = alpha sum + b, c = alpha n_i + beta_i.
#pragma omp simd
          for (long m = 0; m < run.count; ++m) {
            const float r0 = alpha * NeighbourSum(o[0], m, w, hy, hz) + b[0][m],
                         r1 = alpha * NeighbourSum(o[1], m, w, hy, hz) + b[1][m],
                         r2 = alpha * NeighbourSum(o[2], m, w, hy, hz) + b[2][m];
            const float gg = g[0][m] * g[0][m] + g[1][m] * g[1][m] + g[2][m] * g[2][m];
            const float k = (g[0][m] * r0 + g[1][m] * r1 + g[2][m] * r2) / (shift[m] + gg);
            v[0][m] = (r0 - g[0][m] * k) / shift[m];
            v[1][m] = (r1 - g[1][m] * k) / shift[m];
            v[2][m] = (r2 - g[2][m] * k) / shift[m];
          }
        });
    rNorm = Residual(x, rhs, r_, r_);
  }
  s.residual = rNorm / bNorm;
  return s;
}

} // namespace eulermap

