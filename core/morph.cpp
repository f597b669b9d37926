// eulermap::Morph — the anchor-guided morph f(p,t) of Eq. 1 (morph.h, DESIGN.md: morph.h).
//
//   f(p,t) = (1-t) f0(W_t->0(p)) + t f1(W_t->1(p))                           (Eq. 1)
//
// With 4 or more non-coplanar anchors the anchors move along q_i(t), found by
// as-rigid-as-possible interpolation (Alexa, Cohen-Or, Levin 2000) of the tetrahedra
// spanned by 4-subsets of the anchors, and the warps W_t->0, W_t->1 are 3-D thin-plate
// RBF interpolants (phi(r) = r plus an affine part) through q_i(t) -> a_i and
// q_i(t) -> b_i. Otherwise both warps are the identity (a plain linear blend).
#include "morph.h"

#include "eigen_point.h"
#include "grow_shrink.h"
#include "inflate_shrink.h"
#include "parallel.h"
#include "union_find.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

namespace eulermap {

namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Tuning constants (see Describe() and the report of the morph).
constexpr double kCoplanarSource = 1e-2;  // a: smallest / largest singular value of the centred anchors
constexpr double kCoplanarTarget = 1e-6;  // b: only truly flat target anchors break the TPS system
constexpr double kMinTetQuality = 1e-2;   // tetrahedron kept when sqrt(2)|det E| / Lmax^3 >= this (regular = 1)
constexpr double kMinFallbackQuality = 1e-4;  // best tetrahedron accepted for an anchor no kept one covers
constexpr std::size_t kMaxTetrahedra = 30000;  // more 4-subsets than this: deterministic sample

// Ratio smallest / largest singular value of the centred points (0 for < 2 distinct points).
//   pts:     the points
//   returns  sigma_3 / sigma_1, a scale-free flatness measure in [0,1]
double Flatness(const std::vector<Point3> &pts) {
  if (pts.size() < 2) return 0;
  Eigen::MatrixX3d x(pts.size(), 3);
  for (std::size_t i = 0; i < pts.size(); ++i) x.row(i) = ToEigen(pts[i]).transpose();
  x.rowwise() -= x.colwise().mean();
  // The singular values are the square roots of the eigenvalues of x^T x (3 x 3; ascending).
  const Vec3 s = Eigen::SelfAdjointEigenSolver<Mat3>(x.transpose() * x).eigenvalues().cwiseMax(0).cwiseSqrt();
  return s(2) > 0 ? s(0) / s(2) : 0;
}

// Shape quality of a tetrahedron: 6 sqrt(2) |volume| / (longest edge)^3, 1 for a regular
// one, 0 for a flat one. Near-degenerate tetrahedra make the affine map A ill-conditioned.
//   p:       the four corners
double TetQuality(const std::array<Vec3, 4> &p) {
  Mat3 e;
  for (int c = 0; c < 3; ++c) e.col(c) = p[c + 1] - p[0];
  double longest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (p[i] - p[j]).norm());
  if (longest <= 0) return 0;
  return std::sqrt(2.0) * std::abs(e.determinant()) / (longest * longest * longest);
}

// Binomial coefficient C(n, 4) in floating point (no overflow for any anchor count).
double Choose4(std::size_t n) { return n < 4 ? 0 : double(n) * (n - 1) * (n - 2) * (n - 3) / 24; }

} // namespace

// The two thin-plate warps of one time t. Both interpolate through the same nodes
// q_i(t), so they share one (n+4) x (n+4) system and one distance evaluation per point.
struct WarpPair {
  double t = 0;
  bool identity[2] = {false, false};  // W_t->0 (resp. W_t->1) is exactly the identity
  Vec3 centre;                        // coordinates are normalised: y = (p - centre) / unit
  double unit = 1;
  Eigen::Matrix<double, Eigen::Dynamic, 3> nodes;    // q_i(t), normalised
  Eigen::Matrix<double, Eigen::Dynamic, 6> weights;  // RBF weights, [to a | to b]
  Eigen::Matrix<double, 4, 6> affine;                // rows: 1, y_x, y_y, y_z

  // Evaluates the warps at a row of points p_m = start + (m step, 0, 0), m < count (a row
  // of grid nodes), vectorised over the points: per node q_i the distances
  // r_m = |y_m - q_i| = sqrt((y_m.x - q_i.x)^2 + c_i), c_i the part of the squared
  // distance that is the same along the row, then each warp coordinate W(y_m) = affine
  // part + sum_i phi(r_m) w_i, phi(r) = r, as whole rows (less than half the instructions
  // of a point at a time: docs/NOTES.md).
  //   want:      which to evaluate, [W_t->0, W_t->1]; one not wanted is not written
  //   toSource:  out, W_t->0(p_m) for m < count, when want[0]
  //   toTarget:  out, W_t->1(p_m), when want[1]
  //   scratch:   work space (resized here), so that rows allocate nothing
  void EvaluateRow(const Point3 &start, double step, int count, const bool want[2], Point3 *toSource, Point3 *toTarget,
                   std::vector<double> &scratch) const {
    const Vec3 y0 = (ToEigen(start) - centre) / unit;
    const double dy = step / unit;
    const bool evaluate[2] = {want[0] && !identity[0], want[1] && !identity[1]};
    // Columns [first, first + columns) of the 6 (3 per warp): column c at acc + (c - first) count.
    const int first = evaluate[0] ? 0 : 3, columns = 3 * (evaluate[0] + evaluate[1]);
    scratch.resize(std::size_t(7) * count);
    double *x = scratch.data(), *acc = x + count;
    for (int m = 0; m < count; ++m) x[m] = y0.x() + m * dy;
    for (int c = first; c < first + columns; ++c) {
      const double base = affine(0, c) + y0.y() * affine(2, c) + y0.z() * affine(3, c), slope = affine(1, c);
      for (int m = 0; m < count; ++m) acc[(c - first) * count + m] = base + x[m] * slope;
    }
    AccumulateColumns(columns, first, x, y0, count, acc);
    Point3 *out[2] = {toSource, toTarget};
    for (int w = 0; w < 2; ++w) {
      if (!want[w]) continue;
      const double *a = acc + std::size_t(std::max(3 * w - first, 0)) * count;  // unread unless evaluate[w]
      for (int m = 0; m < count; ++m)
        out[w][m] = evaluate[w] ? Point3(centre.x() + unit * a[m], centre.y() + unit * a[count + m], centre.z() + unit * a[2 * count + m])
                                : start + Point3(m * step, 0, 0);
    }
  }

  // Accumulate for 6 or 3 columns, compiled for AVX2 too and chosen by the processor at load time
  // (the same IEEE operations in the same order, so the same values, with four points a vector).
  __attribute__((target_clones("avx2", "default"), flatten)) void AccumulateColumns(int columns, int first, const double *x,
                                                                                   const Vec3 &y0, int count,
                                                                                   double *acc) const {
    if (columns == 6) Accumulate<6>(first, x, y0, count, acc);
    else if (columns == 3) Accumulate<3>(first, x, y0, count, acc);
  }

  // acc[c count + m] += sum_i phi(|y_m - q_i|) w_i(first + c), c < kColumns, y_m =
  // (x[m], y0.y, y0.z): one pass over the row per kGroup nodes q_i (fewer loads and stores of
  // acc per node than one pass each), then one per node left over.
  template <int kColumns> void Accumulate(int first, const double *x, const Vec3 &y0, int count, double *acc) const {
    constexpr int kGroup = 5;
    Eigen::Index i = 0;
    for (; i + kGroup <= nodes.rows(); i += kGroup) AccumulateGroup<kColumns, kGroup>(i, first, x, y0, count, acc);
    for (; i < nodes.rows(); ++i) AccumulateGroup<kColumns, 1>(i, first, x, y0, count, acc);
  }

  // The nodes q_i .. q_i+kNodes-1 of Accumulate, in one pass over the row.
  template <int kColumns, int kNodes>
  void AccumulateGroup(Eigen::Index i, int first, const double *x, const Vec3 &y0, int count, double *acc) const {
    double qx[kNodes], c2[kNodes], w[kNodes][kColumns];
    for (int n = 0; n < kNodes; ++n) {
      const double cy = y0.y() - nodes(i + n, 1), cz = y0.z() - nodes(i + n, 2);
      qx[n] = nodes(i + n, 0), c2[n] = cy * cy + cz * cz;
      for (int c = 0; c < kColumns; ++c) w[n][c] = weights(i + n, first + c);
    }
#pragma omp simd
    for (int m = 0; m < count; ++m) {
      double r[kNodes];
      for (int n = 0; n < kNodes; ++n) r[n] = std::sqrt((x[m] - qx[n]) * (x[m] - qx[n]) + c2[n]);
      for (int c = 0; c < kColumns; ++c) {
        double sum = acc[c * count + m];
        for (int n = 0; n < kNodes; ++n) sum += r[n] * w[n][c];
        acc[c * count + m] = sum;
      }
    }
  }

  // Both warps at one point p: W_t->0(p) into toSource, W_t->1(p) into toTarget.
  void Evaluate(const Point3 &p, Point3 &toSource, Point3 &toTarget) const {
    const bool both[2] = {true, true};
    std::vector<double> scratch;
    EvaluateRow(p, 0, 1, both, &toSource, &toTarget, scratch);
  }
};

struct Morph::Impl {
  const ScalarField *f0 = nullptr, *f1 = nullptr;  // not owned; must outlive the Morph
  std::vector<Point3> a, b;
  Mode mode = Mode::LinearBlend;
  std::string reason;  // why the linear blend was chosen
  std::unique_ptr<GrowShrink> growShrink;  // Mode::GrowShrink
  std::unique_ptr<InflateShrink> inflateShrink;  // Mode::InflateShrink

  // ARAP data, all from the source tetrahedra (Alexa et al. 2000).
  struct Tet {
    std::array<int, 4> v;
    Eigen::Quaterniond rotation;  // R of the polar decomposition A = R S (proper)
    Mat3 stretch;                 // S (symmetric)
    Eigen::Matrix<double, 3, 4> arm;  // 4 (a_v - centroid of the tet), the per-vertex normal-equation term
  };
  std::vector<Tet> tets;
  double subsets = 0;             // C(n,4)
  bool sampled = false;           // tets drawn from the subsets rather than all of them
  std::size_t skipped = 0;        // near-degenerate subsets left out (full enumeration only)
  std::size_t rescued = 0;        // below-threshold tetrahedra kept to cover an anchor
  Eigen::LDLT<Eigen::MatrixXd> normal;  // L + c 1 1^T / n, factored once
  double centroidWeight = 0;      // c
  Vec3 centroidA, centroidB;
  Vec3 centre;                    // TPS normalisation
  double unit = 1;

  mutable std::mutex cacheMutex;
  mutable std::shared_ptr<const WarpPair> cache;  // the warps of the last t asked for

  void Setup();
  bool BuildTetrahedra();
  std::vector<Point3> RawAnchors(double t) const;
  std::shared_ptr<const WarpPair> Warps(double t) const;
  std::shared_ptr<const WarpPair> SolveWarps(double t) const;
  std::shared_ptr<const WarpPair> SolvePair(double t, const std::vector<Point3> &q, const std::vector<Point3> &to0,
                                            const std::vector<Point3> &to1) const;
};

// Chooses the mode and, for ARAP+TPS, builds the tetrahedra, their polar decompositions
// and the factored normal matrix. Throws std::invalid_argument for coincident anchors.
void Morph::Impl::Setup() {
  const std::size_t n = a.size();
  if (n < 4) {
    reason = n == 0 ? "no anchors" : std::to_string(n) + (n == 1 ? " anchor" : " anchors") + ", fewer than 4";
    return;
  }
  if (Flatness(a) < kCoplanarSource) {
    reason = std::to_string(n) + " anchors, coplanar on the source";
    return;
  }
  if (Flatness(b) < kCoplanarTarget) {
    reason = std::to_string(n) + " anchors, coplanar on the target";
    return;
  }
  if (n >= 65536) throw std::invalid_argument("Morph: too many anchors (" + std::to_string(n) + ")");

  // Normalisation of the TPS coordinates: centre and extent of all anchors.
  centroidA = centroidB = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    centroidA += ToEigen(a[i]);
    centroidB += ToEigen(b[i]);
  }
  centroidA /= double(n);
  centroidB /= double(n);
  centre = 0.5 * (centroidA + centroidB);
  unit = 0;
  for (std::size_t i = 0; i < n; ++i)
    unit = std::max({unit, (ToEigen(a[i]) - centre).norm(), (ToEigen(b[i]) - centre).norm()});

  // Coincident anchors make the TPS system singular (and contradict each other if their
  // partners differ): a clear error.
  for (const auto *side : {&a, &b})
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (vcg::Distance((*side)[i], (*side)[j]) <= 1e-9 * unit)
          throw std::invalid_argument("Morph: anchors " + std::to_string(i) + " and " + std::to_string(j) +
                                      " coincide on the " + (side == &a ? "source" : "target"));

  if (!BuildTetrahedra()) return;  // reason set
  mode = Mode::ArapTps;

  // The endpoints must come out of the least-squares fit by themselves (q(0) = a,
  // q(1) = b up to round-off); Anchors() then returns them exactly.
  for (double t : {0.0, 1.0}) {
    const std::vector<Point3> q = RawAnchors(t);
    const std::vector<Point3> &want = t == 0 ? a : b;
    double err = 0;
    for (std::size_t i = 0; i < n; ++i) err = std::max(err, vcg::Distance(q[i], want[i]));
    if (err > 1e-8 * unit)
      throw std::logic_error("Morph: ARAP interpolation misses its endpoint at t=" + std::to_string(t) +
                             " by " + std::to_string(err));
  }
}

// Tetrahedra of the ARAP interpolation (Alexa et al. 2000): every 4-subset of the anchors
// whose source tetrahedron is not near-degenerate (TetQuality >= kMinTetQuality); when
// C(n,4) > kMaxTetrahedra, kMaxTetrahedra distinct subsets drawn by a fixed-seed
// generator. An anchor that no kept tetrahedron contains gets its best one (if its
// quality is at least kMinFallbackQuality). Then per tetrahedron the polar decomposition
// of A, and the normal matrix of the least-squares fit.
//   returns false (with `reason` set) when no usable set of tetrahedra exists
bool Morph::Impl::BuildTetrahedra() {
  const int n = int(a.size());
  auto corners = [&](const std::array<int, 4> &v) {
    std::array<Vec3, 4> p;
    for (int c = 0; c < 4; ++c) p[c] = ToEigen(a[v[c]]);
    return p;
  };
  auto key = [](std::array<int, 4> v) {
    std::sort(v.begin(), v.end());
    return (std::uint64_t(v[0]) << 48) | (std::uint64_t(v[1]) << 32) | (std::uint64_t(v[2]) << 16) | std::uint64_t(v[3]);
  };

  std::vector<std::array<int, 4>> chosen;
  std::unordered_set<std::uint64_t> seen;
  subsets = Choose4(n);
  std::mt19937_64 random(0x65756c65726d6170ull);  // fixed seed: the same anchors give the same morph
  if (subsets <= double(kMaxTetrahedra)) {
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        for (int k = j + 1; k < n; ++k)
          for (int l = k + 1; l < n; ++l) {
            const std::array<int, 4> v = {i, j, k, l};
            if (TetQuality(corners(v)) >= kMinTetQuality) {
              chosen.push_back(v);
              seen.insert(key(v));
            } else {
              ++skipped;
            }
          }
  } else {
    sampled = true;
    for (std::size_t attempt = 0; chosen.size() < kMaxTetrahedra && attempt < 20 * kMaxTetrahedra; ++attempt) {
      std::array<int, 4> v;
      for (int c = 0; c < 4; ++c) {
        bool repeated;
        do {
          v[c] = int(random() % std::uint64_t(n));
          repeated = std::find(v.begin(), v.begin() + c, v[c]) != v.begin() + c;
        } while (repeated);
      }
      std::sort(v.begin(), v.end());
      if (seen.count(key(v))) continue;
      seen.insert(key(v));
      if (TetQuality(corners(v)) >= kMinTetQuality) chosen.push_back(v);
    }
  }

  // Coverage: every anchor must be in some tetrahedron, else its q_i(t) is undetermined.
  std::vector<int> count(n, 0);
  for (const auto &v : chosen)
    for (int c : v) ++count[c];
  for (int i = 0; i < n; ++i) {
    if (count[i]) continue;
    std::array<int, 4> best{};
    double bestQuality = -1;
    auto consider = [&](int j, int k, int l) {
      const std::array<int, 4> v = {i, j, k, l};
      const double q = TetQuality(corners(v));
      if (q > bestQuality) bestQuality = q, best = v;
    };
    if (Choose4(n) <= 4.0 * kMaxTetrahedra) {  // C(n-1,3) <= C(n,4): search them all
      for (int j = 0; j < n; ++j)
        for (int k = j + 1; k < n; ++k)
          for (int l = k + 1; l < n; ++l)
            if (j != i && k != i && l != i) consider(j, k, l);
    } else {
      for (std::size_t attempt = 0; attempt < kMaxTetrahedra; ++attempt) {
        int j = int(random() % n), k = int(random() % n), l = int(random() % n);
        if (j != i && k != i && l != i && j != k && k != l && j != l) consider(j, k, l);
      }
    }
    if (bestQuality < kMinFallbackQuality) {
      reason = std::to_string(n) + " anchors, anchor " + std::to_string(i) + " spans no usable tetrahedron";
      return false;
    }
    chosen.push_back(best);
    ++rescued;
    for (int c : best) ++count[c];
  }
  UnionFind components(n);  // anchors joined by the chosen tetrahedra
  for (const auto &v : chosen)
    for (int c = 1; c < 4; ++c) components.Merge(v[0], v[c]);
  for (int i = 1; i < n; ++i)
    if (components.Find(i) != components.Find(0)) {
      reason = std::to_string(n) + " anchors, tetrahedra fall apart into separate groups";
      return false;
    }

  // Per tetrahedron: A maps the source edge vectors onto the target's, A = R S.
  Eigen::MatrixXd laplacian = Eigen::MatrixXd::Zero(n, n);
  tets.reserve(chosen.size());
  for (const auto &v : chosen) {
    Tet tet;
    tet.v = v;
    Mat3 ea, eb;
    for (int c = 0; c < 3; ++c) {
      ea.col(c) = ToEigen(a[v[c + 1]]) - ToEigen(a[v[0]]);
      eb.col(c) = ToEigen(b[v[c + 1]]) - ToEigen(b[v[0]]);
    }
    const Mat3 affine = eb * ea.inverse();
    Eigen::JacobiSVD<Mat3> svd(affine, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat3 u = svd.matrixU();
    const Mat3 w = svd.matrixV();
    Vec3 sigma = svd.singularValues();
    if ((u * w.transpose()).determinant() < 0) {  // keep R proper; S takes the reflection
      u.col(2) = -u.col(2);
      sigma(2) = -sigma(2);
    }
    tet.rotation = Eigen::Quaterniond(Mat3(u * w.transpose())).normalized();
    tet.stretch = w * sigma.asDiagonal() * w.transpose();
    Vec3 centroid = Vec3::Zero();
    for (int c = 0; c < 4; ++c) centroid += ToEigen(a[v[c]]) / 4;
    for (int c = 0; c < 4; ++c) tet.arm.col(c) = 4 * (ToEigen(a[v[c]]) - centroid);
    tets.push_back(tet);
    // Laplacian of the tetrahedron's 6 edges (K4): 3 on the diagonal, -1 off it.
    for (int c = 0; c < 4; ++c)
      for (int d = 0; d < 4; ++d) laplacian(v[c], v[d]) += c == d ? 3 : -1;
  }
  // The fit fixes positions up to a translation; the centroid term pins that down.
  centroidWeight = laplacian.diagonal().mean();
  laplacian.array() += centroidWeight / n;
  normal.compute(laplacian);
  if (normal.info() != Eigen::Success || (normal.vectorD().array() <= 0).any()) {
    reason = std::to_string(n) + " anchors, singular ARAP system";
    tets.clear();
    return false;
  }
  return true;
}

// q(t) by the ARAP least-squares fit, without the exact-endpoint shortcut (Alexa 2000):
//   minimise  sum_tets sum_edges(j,k) | (x_k - x_j) - A(t) (a_k - a_j) |^2
//   subject to  mean(x) = (1-t) mean(a) + t mean(b),
//   A(t) = R(t) ((1-t) I + t S),  R(t) = slerp(I, R, t).
// Over all 6 edges of a tetrahedron the normal-equation term of vertex v is
// A(t) * 4 (a_v - centroid); the centroid constraint enters as c 1 1^T / n (see Setup).
//   t:       time (0 and 1 give a and b up to round-off)
//   returns  the n positions q_i(t)
std::vector<Point3> Morph::Impl::RawAnchors(double t) const {
  const int n = int(a.size());
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  for (const Tet &tet : tets) {
    const Mat3 at = identity.slerp(t, tet.rotation).toRotationMatrix() * ((1 - t) * Mat3::Identity() + t * tet.stretch);
    const Eigen::Matrix<double, 3, 4> moved = at * tet.arm;
    for (int c = 0; c < 4; ++c) rhs.row(tet.v[c]) += moved.col(c).transpose();
  }
  const Vec3 centroid = (1 - t) * centroidA + t * centroidB;
  rhs.rowwise() += centroidWeight * centroid.transpose();
  const Eigen::MatrixX3d x = normal.solve(rhs);
  std::vector<Point3> q(n);
  for (int i = 0; i < n; ++i) q[i] = ToPoint(x.row(i).transpose());
  return q;
}

// Thin-plate warps of time t: SolvePair(t, q(t), a, b).
std::shared_ptr<const WarpPair> Morph::Impl::SolveWarps(double t) const {
  std::vector<Point3> q;
  if (t == 0) q = a;
  else if (t == 1) q = b;
  else q = RawAnchors(t);
  return SolvePair(t, q, a, b);
}

// Two thin-plate warps through the nodes q: solves [K P; P^T 0] [w; c] = [d; 0] once for
// both value sets d = to0 and d = to1, with K_ij = |y_i - y_j| (phi(r) = r), P_i = (1, y_i),
// y_i the normalised q_i.
//   t:         time recorded in the pair (for the cache)
//   returns    the solved pair; a warp whose nodes equal its values is flagged identity
std::shared_ptr<const WarpPair> Morph::Impl::SolvePair(double t, const std::vector<Point3> &q,
                                                        const std::vector<Point3> &to0,
                                                        const std::vector<Point3> &to1) const {
  const int n = int(q.size());
  auto pair = std::make_shared<WarpPair>();
  pair->t = t;
  pair->centre = centre;
  pair->unit = unit;
  pair->identity[0] = q == to0;
  pair->identity[1] = q == to1;
  pair->nodes.resize(n, 3);
  for (int i = 0; i < n; ++i) pair->nodes.row(i) = ((ToEigen(q[i]) - centre) / unit).transpose();

  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 4, n + 4);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n + 4, 6);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) m(i, j) = (pair->nodes.row(i) - pair->nodes.row(j)).norm();
    m(i, n) = m(n, i) = 1;
    for (int c = 0; c < 3; ++c) m(i, n + 1 + c) = m(n + 1 + c, i) = pair->nodes(i, c);
    rhs.block<1, 3>(i, 0) = ((ToEigen(to0[i]) - centre) / unit).transpose();
    rhs.block<1, 3>(i, 3) = ((ToEigen(to1[i]) - centre) / unit).transpose();
  }
  Eigen::MatrixXd solution = m.partialPivLu().solve(rhs);
  if ((m * solution - rhs).norm() > 1e-10 * (1 + rhs.norm()))  // nodes (nearly) flat or colliding mid-morph
    solution = m.completeOrthogonalDecomposition().solve(rhs);
  pair->weights = solution.topRows(n);
  pair->affine = solution.bottomRows(4);
  return pair;
}

// The warps of time t, reusing the last solve when t repeats. Thread-safe.
std::shared_ptr<const WarpPair> Morph::Impl::Warps(double t) const {
  {
    std::lock_guard<std::mutex> lock(cacheMutex);
    if (cache && cache->t == t) return cache;
  }
  std::shared_ptr<const WarpPair> solved = SolveWarps(t);
  std::lock_guard<std::mutex> lock(cacheMutex);
  cache = solved;
  return solved;
}

// Builds the morph between f0 and f1.
//   f0, f1:  source and (placed) target fields on the same grid; not copied, they must
//            outlive the Morph
//   a, b:    matched anchors, a[i] on the source and b[i] on the placed target
// Throws std::invalid_argument on grids that differ, anchor lists of different lengths,
// or coincident anchors (with 4 or more non-coplanar ones).
Morph::Morph(const ScalarField &f0, const ScalarField &f1, std::vector<Point3> a, std::vector<Point3> b, Blend blend)
    : impl_(std::make_unique<Impl>()) {
  if (f0.grid.dims != f1.grid.dims || f0.grid.origin != f1.grid.origin || f0.grid.h != f1.grid.h ||
      f0.values.size() != f0.grid.NodeCount() || f1.values.size() != f1.grid.NodeCount())
    throw std::invalid_argument("Morph: f0 and f1 must be filled fields on the same grid");
  if (a.size() != b.size())
    throw std::invalid_argument("Morph: " + std::to_string(a.size()) + " source anchors but " +
                                std::to_string(b.size()) + " target anchors");
  impl_->f0 = &f0;
  impl_->f1 = &f1;
  impl_->a = std::move(a);
  impl_->b = std::move(b);
  impl_->Setup();
  if (impl_->mode == Mode::LinearBlend && blend == Blend::GrowShrink) {
    impl_->growShrink = std::make_unique<GrowShrink>(f0, f1);
    impl_->mode = Mode::GrowShrink;
  }
  if (impl_->mode == Mode::LinearBlend && blend == Blend::InflateShrink) {
    impl_->inflateShrink = std::make_unique<InflateShrink>(f0, f1);
    impl_->mode = Mode::InflateShrink;
  }
}

Morph::~Morph() = default;

Morph::Mode Morph::mode() const { return impl_->mode; }

// One line for the report: the mode and what it was built from.
std::string Morph::Describe() const {
  const Impl &m = *impl_;
  if (m.mode == Mode::LinearBlend) return "linear blend (" + m.reason + ")";
  if (m.mode == Mode::GrowShrink) {
    std::ostringstream s;
    s << "grow then withdraw (" << m.reason << "; the linear blend grows parts from nothing): the source grows "
      << m.growShrink->GrowLength() << " into the target, then withdraws " << m.growShrink->WithdrawLength()
      << ", switching at t = " << m.growShrink->Switch();
    return s.str();
  }
  if (m.mode == Mode::InflateShrink) {
    std::ostringstream s;
    s << "inflate then shrink (" << m.reason << "; the linear blend grows parts from nothing): the source inflates "
      << m.inflateShrink->InflateLength() << " until it holds the target, then shrinks up to "
      << m.inflateShrink->ShrinkLength() << " onto it, switching at t = " << m.inflateShrink->Switch();
    return s.str();
  }
  std::ostringstream s;
  s << "ARAP+TPS, " << m.a.size() << " anchors, " << m.tets.size() << " tetrahedra";
  if (m.sampled)
    s << " (deterministic sample of " << std::llround(m.subsets) << " 4-subsets, near-degenerate ones left out)";
  else if (m.skipped)
    s << " (" << m.skipped << " near-degenerate of " << std::llround(m.subsets) << " 4-subsets left out)";
  if (m.rescued) s << ", " << m.rescued << " below-threshold kept to cover anchors";
  return s.str();
}

// f(., t) at every node of the grid (Eq. 1):
//   out(node) = (1-t) f0(W_t->0(node)) + t f1(W_t->1(node)).
//   t:    time, normally in [0,1]; t = 0 gives f0 and t = 1 gives f1 exactly
//   out:  resized to the grid and overwritten
// The two thin-plate systems are solved once, then nodes are evaluated in parallel.
void Morph::Frame(double t, ScalarField &out, const Interrupt &interrupt) const {
  const ScalarField &f0 = *impl_->f0, &f1 = *impl_->f1;
  const Grid &g = f0.grid;
  out.grid = g;
  if (out.values.size() != g.NodeCount()) AssignPolling(out.values, g.NodeCount(), 0.0, interrupt);
  const long long count = (long long)g.NodeCount();

  if (impl_->mode == Mode::GrowShrink) return impl_->growShrink->Frame(t, out);
  if (impl_->mode == Mode::InflateShrink) return impl_->inflateShrink->Frame(t, out);
  if (impl_->mode == Mode::LinearBlend) {  // W = identity
    ParallelFor(count, [&](long i) {
      double v = 0;
      if (t != 1) v += (1 - t) * f0.values[i];
      if (t != 0) v += t * f1.values[i];
      out.values[i] = v;
    });
    return;
  }

  const std::shared_ptr<const WarpPair> warps = impl_->Warps(t);
  const WarpPair &w = *warps;
  const bool use0 = t != 1, use1 = t != 0;  // a zero weight drops its term
  const bool want[2] = {use0 && !w.identity[0], use1 && !w.identity[1]};
  const int nx = g.dims.X();
  const long long rows = (long long)g.dims.Y() * g.dims.Z();
  const long long rowsBetweenPolls = std::max(1LL, (long long)kNodesBetweenPolls / nx);
  ParallelPieces(rows, [&](long begin, long end) {
    std::vector<Point3> p0(nx), p1(nx);
    std::vector<double> scratch;
    for (long long r = begin; r < end; ++r) {
      if (r % rowsBetweenPolls == 0 ? interrupt.Stop() : interrupt.Cancelled()) continue;
      const int j = int(r % g.dims.Y()), k = int(r / g.dims.Y());
      w.EvaluateRow(g.Node(0, j, k), g.h, nx, want, p0.data(), p1.data(), scratch);
      for (int i = 0; i < nx; ++i) {
        const std::size_t idx = g.Index(i, j, k);
        double v = 0;
        if (use0) v += (1 - t) * (want[0] ? f0.Value(p0[i]) : f0.values[idx]);
        if (use1) v += t * (want[1] ? f1.Value(p1[i]) : f1.values[idx]);
        out.values[idx] = v;
      }
    }
  });
}

// q_i(t): a_i at t = 0 and b_i at t = 1 exactly; in between the ARAP interpolation
// (Alexa 2000), or the straight line (1-t) a_i + t b_i in linear-blend mode.
std::vector<Point3> Morph::Anchors(double t) const {
  const Impl &m = *impl_;
  if (t == 0) return m.a;
  if (t == 1) return m.b;
  if (m.mode == Mode::ArapTps) return m.RawAnchors(t);
  std::vector<Point3> q(m.a.size());
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = m.a[i] * (1 - t) + m.b[i] * t;
  return q;
}

// W_t->0(p): the thin-plate warp with W_t->0(q_i(t)) = a_i (identity in linear-blend
// mode and at t = 0). Thread-safe; solves (or reuses the last solve of) time t.
Point3 Morph::WarpToSource(double t, const Point3 &p) const {
  if (impl_->mode != Mode::ArapTps) return p;
  Point3 p0, p1;
  impl_->Warps(t)->Evaluate(p, p0, p1);
  return p0;
}

// W_t->1(p): the thin-plate warp with W_t->1(q_i(t)) = b_i (identity in linear-blend
// mode and at t = 1). Thread-safe, as WarpToSource.
Point3 Morph::WarpToTarget(double t, const Point3 &p) const {
  if (impl_->mode != Mode::ArapTps) return p;
  Point3 p0, p1;
  impl_->Warps(t)->Evaluate(p, p0, p1);
  return p1;
}

// Anchor motion between t0 and t1: the thin-plate warp taking q_i(t0) to q_i(t1),
// as a velocity (W(p) - p) / (t1 - t0) at every grid node, with each node's closeness
// to the anchors. Empty (no nodes) in linear-blend mode, where anchors do not move space.
void Morph::AnchorMotion(double t0, double t1, double radius, VectorField &out, ScalarField &closeness,
                         const Interrupt &interrupt) const {
  if (impl_->mode != Mode::ArapTps) {
    out = VectorField();
    closeness = ScalarField();
    return;
  }
  const Grid &g = impl_->f0->grid;
  const std::vector<Point3> q0 = Anchors(t0), q1 = Anchors(t1);
  const std::shared_ptr<const WarpPair> w = impl_->SolvePair(t0, q0, q1, q1);
  if (out.values.size() != g.NodeCount()) out = VectorField(g, Point3(0, 0, 0));
  if (closeness.values.size() != g.NodeCount()) closeness = ScalarField(g, 0.0);
  const double dt = t1 - t0;
  const int nx = g.dims.X();
  const long long rows = (long long)g.dims.Y() * g.dims.Z();
  const bool want[2] = {true, false};  // W: q(t0) -> q(t1)
  const long long rowsBetweenPolls = std::max(1LL, (long long)kNodesBetweenPolls / nx);
  ParallelPieces(rows, [&](long begin, long end) {
    std::vector<Point3> moved(nx);
    std::vector<double> scratch, x(nx), nearest2(nx);
    for (long long r = begin; r < end; ++r) {
      if (r % rowsBetweenPolls == 0 ? interrupt.Stop() : interrupt.Cancelled()) continue;
      const int j = int(r % g.dims.Y()), k = int(r / g.dims.Y());
      const Point3 start = g.Node(0, j, k);
      w->EvaluateRow(start, g.h, nx, want, moved.data(), nullptr, scratch);
      // Squared distance to the nearest q_i: (x - q_i.x)^2 + the part across the row.
      for (int i = 0; i < nx; ++i) x[i] = g.Node(i, j, k).X(), nearest2[i] = std::numeric_limits<double>::max();
      for (const Point3 &q : q0) {
        const double across = (start.Y() - q.Y()) * (start.Y() - q.Y()) + (start.Z() - q.Z()) * (start.Z() - q.Z());
        for (int i = 0; i < nx; ++i) nearest2[i] = std::min(nearest2[i], (x[i] - q.X()) * (x[i] - q.X()) + across);
      }
      for (int i = 0; i < nx; ++i) {
        const std::size_t n = g.Index(i, j, k);
        out.values[n] = (moved[i] - g.Node(i, j, k)) / dt;
        closeness.values[n] = std::exp(-nearest2[i] / (radius * radius));
      }
    }
  });
}

} // namespace eulermap
