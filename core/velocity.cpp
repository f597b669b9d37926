#include "velocity.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace eulermap {

namespace {
// a . b summed over fixed blocks, the blocks' sums added in order: the same bits for any
// number of threads (an OpenMP reduction adds in an order that depends on it), so maps
// made with 1 and 2 threads agree (test_end_to_end).
double Dot(const std::vector<Point3> &a, const std::vector<Point3> &b) {
  constexpr long kBlock = 4096;
  const long n = long(a.size()), blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(blocks);
#pragma omp parallel for schedule(static)
  for (long k = 0; k < blocks; ++k) {
    double s = 0;
    for (long m = k * kBlock; m < std::min(n, (k + 1) * kBlock); ++m) s += a[m] * b[m];
    partial[k] = s;
  }
  return std::accumulate(partial.begin(), partial.end(), 0.0);
}
} // namespace

int VelocitySolver::Neighbours(int i, int j, int k) const {
  const vcg::Point3i &d = grid_.dims;
  return (i > 0) + (i + 1 < d.X()) + (j > 0) + (j + 1 < d.Y()) + (k > 0) + (k + 1 < d.Z());
}

VelocitySolve VelocitySolver::Solve(const ScalarField &fk, const ScalarField &fk1, double dt, VectorField &V,
                                    const VectorField &prior, const ScalarField &priorWeight) {
  grid_ = fk.grid;
  const std::size_t n = grid_.NodeCount();
  if (V.values.size() != n || V.grid.dims != grid_.dims) V = VectorField(grid_, Point3(0, 0, 0));
  g_.resize(n);
  b_.resize(n);
  const bool withPrior = !prior.values.empty();
  beta_ = withPrior ? priorWeight.values : std::vector<double>();
  // g = grad of (f_k + f_k+1)/2, f_t = (f_k+1 - f_k)/dt, b = -g f_t + beta P (right-hand side of (*)).
  const vcg::Point3i d = grid_.dims;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < d.Z(); ++k)
    for (int j = 0; j < d.Y(); ++j)
      for (int i = 0; i < d.X(); ++i) {
        const std::size_t idx = grid_.Index(i, j, k);
        const Point3 g = (fk.NodeGradient(i, j, k) + fk1.NodeGradient(i, j, k)) * 0.5;
        g_[idx] = g;
        b_[idx] = g * -((fk1.values[idx] - fk.values[idx]) / dt);
        if (withPrior) b_[idx] += prior.values[idx] * beta_[idx];
      }
  const double bNorm = std::sqrt(Dot(b_, b_));
  VelocitySolve s;
  if (bNorm == 0)  // no motion: V = 0 solves (*) exactly
    std::fill(V.values.begin(), V.values.end(), Point3(0, 0, 0));
  else if (method_ == Method::GaussSeidel)
    s = SolveGaussSeidel(V, bNorm);
  else if (method_ == Method::ConjugateGradient)
    s = SolveConjugateGradient(V, bNorm, [this](const std::vector<Point3> &r, std::vector<Point3> &z) { BlockJacobi(r, z); });
  else {
    if (!multigrid_ || multigrid_->Dims() != grid_.dims) multigrid_ = std::make_unique<BlockMultigrid>(grid_, alpha_);
    std::vector<Sym3> &data = multigrid_->Data();  // D_i = g g^T + beta_i I
#pragma omp parallel for schedule(static)
    for (long m = 0; m < long(n); ++m) {
      const Point3 &g = g_[m];
      const double b = Beta(m);
      data[m] = {float(g[0] * g[0] + b), float(g[0] * g[1]), float(g[0] * g[2]), float(g[1] * g[1] + b),
                 float(g[1] * g[2]), float(g[2] * g[2] + b)};
    }
    multigrid_->Update();
    s = SolveConjugateGradient(V, bNorm, [&](const std::vector<Point3> &r, std::vector<Point3> &z) { multigrid_->Precondition(r, z); });
  }
  return s;
}

void VelocitySolver::Apply(const std::vector<Point3> &x, std::vector<Point3> &out) const {
  const vcg::Point3i d = grid_.dims;
  const long sx = 1, sy = d.X(), sz = long(d.X()) * d.Y();
#pragma omp parallel for schedule(static)
  for (int k = 0; k < d.Z(); ++k)
    for (int j = 0; j < d.Y(); ++j)
      for (int i = 0; i < d.X(); ++i) {
        const long idx = long(grid_.Index(i, j, k));
        Point3 lap(0, 0, 0);  // sum_j (V_i - V_j)
        if (i > 0) lap += x[idx] - x[idx - sx];
        if (i + 1 < d.X()) lap += x[idx] - x[idx + sx];
        if (j > 0) lap += x[idx] - x[idx - sy];
        if (j + 1 < d.Y()) lap += x[idx] - x[idx + sy];
        if (k > 0) lap += x[idx] - x[idx - sz];
        if (k + 1 < d.Z()) lap += x[idx] - x[idx + sz];
        const Point3 &g = g_[idx];
        out[idx] = g * (g * x[idx]) + lap * alpha_ + x[idx] * Beta(idx);
      }
}

double VelocitySolver::Residual(const VectorField &V, std::vector<Point3> &r) const {
  Apply(V.values, r);
#pragma omp parallel for schedule(static)
  for (long n = 0; n < long(r.size()); ++n) r[n] = b_[n] - r[n];
  return std::sqrt(Dot(r, r));
}

void VelocitySolver::BlockJacobi(const std::vector<Point3> &r, std::vector<Point3> &z) const {
  // (g g^T + c I)^-1 = (I - g g^T / (c + |g|^2)) / c (Sherman-Morrison).
  const vcg::Point3i d = grid_.dims;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < d.Z(); ++k)
    for (int j = 0; j < d.Y(); ++j)
      for (int i = 0; i < d.X(); ++i) {
        const std::size_t idx = grid_.Index(i, j, k);
        const double c = alpha_ * Neighbours(i, j, k) + Beta(idx);
        const Point3 &g = g_[idx];
        z[idx] = (r[idx] - g * ((g * r[idx]) / (c + g.SquaredNorm()))) / c;
      }
}

VelocitySolve VelocitySolver::SolveConjugateGradient(
    VectorField &V, double bNorm, const std::function<void(const std::vector<Point3> &, std::vector<Point3> &)> &precondition) {
  const std::size_t n = grid_.NodeCount();
  VelocitySolve s;
  r_.resize(n), z_.resize(n), p_.resize(n), q_.resize(n);
  std::vector<Point3> &r = r_, &z = z_, &p = p_, &q = q_;
  double rNorm = Residual(V, r);
  precondition(r, z);
  p = z;
  double rz = Dot(r, z);
  while (rNorm > tolerance_ * bNorm && s.iterations < maxIterations_) {
    Apply(p, q);
    const double step = rz / Dot(p, q);
#pragma omp parallel for schedule(static)
    for (long m = 0; m < long(n); ++m) {
      V.values[m] += p[m] * step;
      r[m] -= q[m] * step;
    }
    rNorm = std::sqrt(Dot(r, r));
    ++s.iterations;
    precondition(r, z);
    const double rzNext = Dot(r, z);
    const double beta = rzNext / rz;
    rz = rzNext;
#pragma omp parallel for schedule(static)
    for (long m = 0; m < long(n); ++m) p[m] = z[m] + p[m] * beta;
  }
  s.residual = rNorm / bNorm;
  return s;
}

VelocitySolve VelocitySolver::SolveGaussSeidel(VectorField &V, double bNorm) {
  const std::size_t n = grid_.NodeCount();
  VelocitySolve s;
  std::vector<Point3> r(n);
  const vcg::Point3i d = grid_.dims;
  const long sx = 1, sy = d.X(), sz = long(d.X()) * d.Y();
  std::vector<Point3> &x = V.values;
  double rNorm = Residual(V, r);
  // Residuals cost as much as a sweep: check every few sweeps.
  const int checkEvery = 10;
  while (rNorm > tolerance_ * bNorm && s.iterations < maxIterations_) {
    for (int sweep = 0; sweep < checkEvery && s.iterations < maxIterations_; ++sweep, ++s.iterations)
      for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(static)
        for (int k = 0; k < d.Z(); ++k)
          for (int j = 0; j < d.Y(); ++j)
            for (int i = (j + k + colour) & 1; i < d.X(); i += 2) {
              const long idx = long(grid_.Index(i, j, k));
              Point3 sum(0, 0, 0);
              int nb = 0;
              if (i > 0) sum += x[idx - sx], ++nb;
              if (i + 1 < d.X()) sum += x[idx + sx], ++nb;
              if (j > 0) sum += x[idx - sy], ++nb;
              if (j + 1 < d.Y()) sum += x[idx + sy], ++nb;
              if (k > 0) sum += x[idx - sz], ++nb;
              if (k + 1 < d.Z()) sum += x[idx + sz], ++nb;
              // Eq. 5 from (*): V = Vbar - g (g . Vbar + f_t) / (alpha n + |g|^2), with
              // b = -g f_t, written for a general b: solve (g g^T + c I) V = alpha sum + b.
              const double c = alpha_ * nb + Beta(idx);
              const Point3 rhs = sum * alpha_ + b_[idx];
              const Point3 &g = g_[idx];
              x[idx] = (rhs - g * ((g * rhs) / (c + g.SquaredNorm()))) / c;
            }
      }
    rNorm = Residual(V, r);
  }
  s.residual = rNorm / bNorm;
  return s;
}

} // namespace eulermap

