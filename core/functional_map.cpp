#include "functional_map.h"

#include "parallel.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace eulermap {

namespace {

// Cotangent weights are clamped to this: a sliver's cotangent (scans hold some) would make
// the stiffness matrix as ill-conditioned as it is thin.
constexpr double kMaxCotangent = 1e3;
// Lanczos' shift: (L - sigma M) is positive definite for a negative sigma (L is positive
// semidefinite, 0 once per closed component), and the eigenvalues nearest sigma, the
// smallest, become the largest of the inverse, where Lanczos finds them first.
constexpr double kShift = -1e-2;
// A Ritz pair counts as converged when its residual is below this share of its Ritz value.
constexpr double kTolerance = 1e-8;

// The cotangent stiffness matrix L (L_ij = -(cot alpha_ij + cot beta_ij) / 2, rows summing to
// 0) and the lumped mass (a third of each adjacent triangle's area), the mesh scaled to unit
// area (L does not change with scale; the masses are divided by the area).
void Discretise(const Mesh &mesh, Eigen::SparseMatrix<double> &stiffness, Eigen::VectorXd &mass) {
  const Eigen::Index n = Eigen::Index(mesh.vert.size());
  std::vector<Eigen::Triplet<double>> entries;
  mass = Eigen::VectorXd::Zero(n);
  double area = 0;
  for (const Face &f : mesh.face) {
    if (f.IsD()) continue;
    Eigen::Index v[3];
    Point3 p[3];
    for (int c = 0; c < 3; ++c) v[c] = Eigen::Index(vcg::tri::Index(mesh, f.cV(c))), p[c] = f.cP(c);
    const double twiceArea = ((p[1] - p[0]) ^ (p[2] - p[0])).Norm();
    area += twiceArea / 2;
    for (int c = 0; c < 3; ++c) {
      mass[v[c]] += twiceArea / 6;
      const int i = (c + 1) % 3, j = (c + 2) % 3;  // the edge opposite corner c
      const Point3 e1 = p[i] - p[c], e2 = p[j] - p[c];
      const double cotangent = std::clamp((e1 * e2) / std::max((e1 ^ e2).Norm(), std::numeric_limits<double>::min()),
                                          -kMaxCotangent, kMaxCotangent);
      const double w = cotangent / 2;
      entries.emplace_back(v[i], v[j], -w), entries.emplace_back(v[j], v[i], -w);
      entries.emplace_back(v[i], v[i], w), entries.emplace_back(v[j], v[j], w);
    }
  }
  stiffness.resize(n, n);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  const double floor = 1e-12;  // unreferenced vertices: no mass, which M^-1/2 could not take
  mass = (mass / std::max(area, std::numeric_limits<double>::min())).cwiseMax(floor);
}

// The row of `to` nearest to each row of `from`: |x - y|^2 = |y|^2 - 2 x.y + |x|^2, the cross
// terms by one single-precision matrix product per block of rows, the blocks in parallel.
std::vector<std::size_t> NearestRows(const Eigen::MatrixXd &from, const Eigen::MatrixXd &to) {
  const Eigen::MatrixXf x = from.cast<float>(), y = to.cast<float>();
  const Eigen::RowVectorXf norms = y.rowwise().squaredNorm().transpose();
  std::vector<std::size_t> nearest(std::size_t(x.rows()));
  constexpr Eigen::Index kBlock = 256;
  ParallelFor(long((x.rows() + kBlock - 1) / kBlock), [&](long block) {
    const Eigen::Index r = Eigen::Index(block) * kBlock, rows = std::min(kBlock, x.rows() - r);
    const Eigen::MatrixXf cross = x.middleRows(r, rows) * y.transpose();
    for (Eigen::Index i = 0; i < rows; ++i) {
      Eigen::Index best = 0;
      (norms - 2 * cross.row(i)).minCoeff(&best);
      nearest[std::size_t(r + i)] = std::size_t(best);
    }
  });
  return nearest;
}

// The `wanted` largest eigenpairs (theta, y) of the symmetric operator `op` on R^n restricted
// to the complement of the orthonormal columns `locked`, by Lanczos: every new vector
// orthogonalised against `locked` and all vectors before it, twice (full reorthogonalisation:
// no ghost copies of converged pairs). Every 10 steps past `wanted` it checks the largest
// Ritz values theta of the tridiagonal T: the residual of the pair of T's eigenvector s is
// |beta_m s_m|. Fewer pairs where the complement is smaller; none where `interrupt` stops it
// (it asks before each step).
template <class Operator>
void Lanczos(const Operator &op, Eigen::Index n, const Eigen::MatrixXd &locked, Eigen::Index wanted, std::mt19937 &random,
             const Interrupt &interrupt, Eigen::MatrixXd &vectors, Eigen::VectorXd &values) {
  const Eigen::Index room = n - locked.cols();
  wanted = std::min(wanted, room);
  if (wanted <= 0) {
    vectors.resize(n, 0), values.resize(0);
    return;
  }
  std::normal_distribution<double> normal;
  Eigen::MatrixXd q(n, std::min<Eigen::Index>(room, 2 * wanted + 20));
  std::vector<double> alpha, beta;  // T's diagonal and subdiagonal
  auto orthogonalise = [&](Eigen::VectorXd &v, Eigen::Index j) {
    for (int pass = 0; pass < 2; ++pass) {
      v -= locked * (locked.transpose() * v).eval();
      v -= q.leftCols(j) * (q.leftCols(j).transpose() * v).eval();
    }
  };
  // A new start: the first, and after an invariant subspace.
  auto fresh = [&](Eigen::Index j) {
    Eigen::VectorXd v = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(random); });
    orthogonalise(v, j);
    q.col(j) = v.normalized();
  };
  fresh(0);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz;
  for (Eigen::Index j = 0;; ++j) {
    if (interrupt.Stop()) {
      vectors.resize(n, 0), values.resize(0);
      return;
    }
    Eigen::VectorXd w = op(q.col(j));
    alpha.push_back(q.col(j).dot(w));
    orthogonalise(w, j + 1);
    beta.push_back(w.norm());
    const Eigen::Index m = j + 1;
    const bool last = m == room;
    if (last || (m >= wanted + 10 && (m - wanted) % 10 == 0)) {
      const Eigen::VectorXd diagonal = Eigen::Map<const Eigen::VectorXd>(alpha.data(), m);
      const Eigen::VectorXd subdiagonal = Eigen::Map<const Eigen::VectorXd>(beta.data(), m - 1);
      ritz.computeFromTridiagonal(diagonal, subdiagonal, Eigen::ComputeEigenvectors);
      bool converged = true;
      for (Eigen::Index i = m - wanted; i < m && converged; ++i)
        converged = std::abs(beta.back() * ritz.eigenvectors()(m - 1, i)) <= kTolerance * std::abs(ritz.eigenvalues()[i]);
      if (last || converged) {
        vectors = q.leftCols(m) * ritz.eigenvectors().rightCols(wanted);
        values = ritz.eigenvalues().tail(wanted);
        return;
      }
    }
    if (q.cols() == m) q.conservativeResize(Eigen::NoChange, std::min<Eigen::Index>(room, m + m / 2 + 10));
    if (beta.back() <= 1e-10 * std::abs(alpha.back())) {  // an invariant subspace: T splits here
      beta.back() = 0;
      fresh(m);
    } else {
      q.col(m) = w / beta.back();
    }
  }
}

}  // namespace

// L phi = lambda M phi with M diagonal is the symmetric B y = lambda y, B = M^-1/2 L M^-1/2,
// y = M^1/2 phi. Lanczos runs on (B - sigma I)^-1 = M^1/2 (L - sigma M)^-1 M^1/2 (one sparse
// LDL^T factorisation, one solve a step); lambda = sigma + 1 / theta. A Krylov space holds
// one direction of each eigenspace: the further copies of a multiple eigenvalue (a sphere's
// 2l + 1) come only from rounding, and may come after the pairs wanted converged (a sphere
// at 16 pairs: the 7th of l = 3 missed). So Lanczos runs again orthogonal to the pairs found,
// and what it finds above the k-th theta joins them, until it finds nothing there.
LaplaceBasis ComputeLaplaceBasis(const Mesh &mesh, int k, const Interrupt &interrupt) {
  constexpr Eigen::Index kDeflated = 8;  // pairs each further run looks for
  LaplaceBasis basis;
  Eigen::SparseMatrix<double> stiffness;
  Eigen::VectorXd mass;
  Discretise(mesh, stiffness, mass);
  basis.mass = mass;
  const Eigen::Index n = stiffness.rows();
  k = int(std::min<Eigen::Index>(k, n));
  if (k <= 0) return basis;
  const Eigen::SparseMatrix<double> shifted = stiffness - kShift * Eigen::SparseMatrix<double>(mass.asDiagonal());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(shifted);
  if (factor.info() != Eigen::Success) return basis;
  const Eigen::VectorXd root = mass.cwiseSqrt();
  auto op = [&](const Eigen::VectorXd &y) -> Eigen::VectorXd {
    return root.cwiseProduct(factor.solve(root.cwiseProduct(y)));
  };
  std::mt19937 random(1);
  Eigen::MatrixXd y;
  Eigen::VectorXd theta;
  Lanczos(op, n, Eigen::MatrixXd(n, 0), k, random, interrupt, y, theta);
  for (;;) {
    if (interrupt.Cancelled()) return basis;
    Eigen::MatrixXd more;
    Eigen::VectorXd moreTheta;
    Lanczos(op, n, y, kDeflated, random, interrupt, more, moreTheta);
    if (interrupt.Cancelled()) return basis;
    const double kth = theta.minCoeff();
    std::vector<Eigen::Index> order;  // the pairs found so far and the new ones above the k-th, by theta
    Eigen::MatrixXd all(n, y.cols() + more.cols());
    all << y, more;
    Eigen::VectorXd allTheta(theta.size() + moreTheta.size());
    allTheta << theta, moreTheta;
    for (Eigen::Index i = 0; i < allTheta.size(); ++i)
      if (i < theta.size() || allTheta[i] > kth * (1 + kTolerance)) order.push_back(i);
    if (Eigen::Index(order.size()) == theta.size()) break;
    std::sort(order.begin(), order.end(), [&](Eigen::Index i, Eigen::Index j) { return allTheta[i] > allTheta[j]; });
    order.resize(std::size_t(k));
    y.resize(n, k), theta.resize(k);
    for (Eigen::Index i = 0; i < k; ++i) y.col(i) = all.col(order[std::size_t(i)]), theta[i] = allTheta[order[std::size_t(i)]];
  }
  // Ascending in lambda: descending in theta.
  std::vector<Eigen::Index> order(std::size_t(theta.size()));
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = Eigen::Index(i);
  std::sort(order.begin(), order.end(), [&](Eigen::Index i, Eigen::Index j) { return theta[i] > theta[j]; });
  basis.phi.resize(n, k), basis.lambda.resize(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    basis.phi.col(i) = y.col(order[std::size_t(i)]).cwiseQuotient(root);
    basis.lambda[i] = kShift + 1 / theta[order[std::size_t(i)]];
  }
  return basis;
}

std::vector<std::size_t> ZoomOut(const LaplaceBasis &source, const LaplaceBasis &target,
                                 const std::vector<std::size_t> &samples, const Eigen::VectorXd &weights,
                                 const std::vector<std::size_t> &candidates, std::vector<std::size_t> map, int from,
                                 int to, int step, const std::vector<std::size_t> &query, const Interrupt &interrupt) {
  const Eigen::VectorXd root = weights.cwiseSqrt();
  auto rows = [](const LaplaceBasis &basis, const std::vector<std::size_t> &vertices, int k) {
    Eigen::MatrixXd r(Eigen::Index(vertices.size()), k);
    for (std::size_t v = 0; v < vertices.size(); ++v) r.row(Eigen::Index(v)) = basis.phi.row(Eigen::Index(vertices[v])).head(k);
    return r;
  };
  const Eigen::MatrixXd a = rows(source, samples, to);
  const Eigen::MatrixXd b = rows(target, candidates, to);
  for (int k = std::min(from, to);; k = std::min(k + step, to)) {
    if (interrupt.Stop()) return {};
    const Eigen::MatrixXd c = (root.asDiagonal() * a.leftCols(k)).colPivHouseholderQr().solve(root.asDiagonal() * rows(target, map, k));
    if (k == to) return NearestRows(rows(source, query, k), target.phi.leftCols(k) * c.transpose());
    const std::vector<std::size_t> nearest = NearestRows(a.leftCols(k), b.leftCols(k) * c.transpose());
    for (std::size_t s = 0; s < map.size(); ++s) map[s] = candidates[nearest[s]];
  }
}

}  // namespace eulermap
