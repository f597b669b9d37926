#include "saddle.h"

#include "eigen_point.h"
#include "parallel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace eulermap {

namespace {

// The trilinear field of one cell: corner values c[n], n = di + 2 dj + 4 dk.
struct Cell {
  Point3 c[8];

  // V at local coordinates u in [0,1]^3 and its Jacobian dV/du (J[row][col] = dV_row/du_col).
  Point3 Value(const double u[3], double J[3][3]) const {
    Point3 v(0, 0, 0), d[3] = {Point3(0, 0, 0), Point3(0, 0, 0), Point3(0, 0, 0)};
    for (int n = 0; n < 8; ++n) {
      const int b[3] = {n & 1, (n >> 1) & 1, (n >> 2) & 1};
      double w[3], dw[3];
      for (int a = 0; a < 3; ++a) w[a] = b[a] ? u[a] : 1 - u[a], dw[a] = b[a] ? 1 : -1;
      v += c[n] * (w[0] * w[1] * w[2]);
      d[0] += c[n] * (dw[0] * w[1] * w[2]);
      d[1] += c[n] * (w[0] * dw[1] * w[2]);
      d[2] += c[n] * (w[0] * w[1] * dw[2]);
    }
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col) J[r][col] = d[col][r];
    return v;
  }
};

} // namespace

int ExpandingDirections(const double J[3][3]) {
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = J[r][c];
  if (!m.allFinite()) return -1;
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(m).singularValues();
  if (!(sv(0) > 0) || sv(2) < 1e-6 * sv(0)) return -1;  // singular
  const Eigen::Vector3cd ev = Eigen::EigenSolver<Eigen::Matrix3d>(m, false).eigenvalues();
  const double largest = ev.cwiseAbs().maxCoeff();
  int positive = 0;
  for (int a = 0; a < 3; ++a) {
    const double re = ev(a).real();
    if (std::abs(re) < kMinRate * largest) return -1;  // a nearly neutral direction: degenerate
    positive += re > 0;
  }
  return positive;
}

namespace {
// kind 2: the direction of the stable line (eigenvector of the one negative eigenvalue);
// kind 1: the normal of the stable plane (spanned by the eigenvectors, or the real and
// imaginary parts of the complex one, of the two eigenvalues with negative real part).
Point3 StableDirection(const double J[3][3], int expanding) {
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = J[r][c];
  const Eigen::EigenSolver<Eigen::Matrix3d> es(m);
  std::vector<Eigen::Vector3d> span;
  for (int a = 0; a < 3; ++a) {
    if (es.eigenvalues()(a).real() >= 0) continue;
    const Eigen::Vector3cd v = es.eigenvectors().col(a);
    span.push_back(v.real());
    if (std::abs(es.eigenvalues()(a).imag()) > 0) span.push_back(v.imag());
  }
  Eigen::Vector3d d = expanding == 2 || span.size() < 2 ? span.at(0) : span[0].cross(span[1]);
  d.normalize();
  return ToPoint(d);
}
} // namespace

std::vector<Saddle> FindSaddles(const VectorField &V) {
  const Grid &g = V.grid;
  const vcg::Point3i d = g.dims;
  // Per node, which signs its components take: bit a when V_a <= 0, bit 3 + a when
  // V_a >= 0. A trilinear component lies between its corner values, so a cell can hold a
  // zero only when its corners' bits together are all six.
  std::vector<unsigned char> signs(V.values.size());
  ParallelFor(long(signs.size()), [&](long n) {
    const Point3 &v = V.values[n];
    signs[n] = (v[0] <= 0) | (v[1] <= 0) << 1 | (v[2] <= 0) << 2 | (v[0] >= 0) << 3 | (v[1] >= 0) << 4 | (v[2] >= 0) << 5;
  });
  const std::size_t sy = d.X(), sz = sy * d.Y();
  std::vector<std::vector<Saddle>> byPlane(std::max(0, d.Z() - 1));
  ParallelFor(long(byPlane.size()), [&](long k) {
      for (int j = 0; j < d.Y() - 1; ++j)
        for (int i = 0; i < d.X() - 1; ++i) {
          const unsigned char *c = &signs[g.Index(i, j, k)];
          if ((c[0] | c[1] | c[sy] | c[sy + 1] | c[sz] | c[sz + 1] | c[sz + sy] | c[sz + sy + 1]) != 63) continue;
          Cell cell;
          double scale = 0;
          for (int n = 0; n < 8; ++n) {
            cell.c[n] = V(i + (n & 1), j + ((n >> 1) & 1), k + ((n >> 2) & 1));
            scale = std::max(scale, cell.c[n].Norm());
          }
          if (!(scale > 0)) continue;
          double u[3] = {0.5, 0.5, 0.5}, J[3][3];
          Point3 v = cell.Value(u, J);
          for (int it = 0; it < 5 && v.Norm() > 1e-12 * scale; ++it) {
            Eigen::Matrix3d m;
            for (int r = 0; r < 3; ++r)
              for (int c = 0; c < 3; ++c) m(r, c) = J[r][c];
            const Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
            if (!lu.isInvertible()) break;
            const Eigen::Vector3d step = lu.solve(Eigen::Vector3d(v[0], v[1], v[2]));
            for (int a = 0; a < 3; ++a) u[a] -= step(a);
            if (std::abs(u[0] - 0.5) > 2 || std::abs(u[1] - 0.5) > 2 || std::abs(u[2] - 0.5) > 2) break;
            v = cell.Value(u, J);
          }
          const double eps = 1e-6;
          if (v.Norm() > 1e-6 * scale) continue;
          if (u[0] < -eps || u[0] > 1 + eps || u[1] < -eps || u[1] > 1 + eps || u[2] < -eps || u[2] > 1 + eps) continue;
          const int expanding = ExpandingDirections(J);  // dV/du = h dV/dx: same eigenvalues' signs
          if (expanding != 1 && expanding != 2) continue;
          byPlane[k].push_back({g.Node(i, j, k) + Point3(u[0], u[1], u[2]) * g.h, expanding, StableDirection(J, expanding)});
        }
  });
  std::vector<Saddle> found;
  for (const std::vector<Saddle> &plane : byPlane) found.insert(found.end(), plane.begin(), plane.end());
  // One zero found from several cells (on a shared face, edge or node) is one saddle.
  std::sort(found.begin(), found.end(), [](const Saddle &a, const Saddle &b) {
    return a.position < b.position;
  });
  std::vector<Saddle> out;
  for (const Saddle &s : found) {
    bool same = false;
    for (const Saddle &o : out)
      if (o.expandingDirections == s.expandingDirections && vcg::Distance(o.position, s.position) < 0.25 * g.h) same = true;
    if (!same) out.push_back(s);
  }
  return out;
}

} // namespace eulermap
