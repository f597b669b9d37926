#include "cut_axis.h"

#include "eigen_point.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace eulermap {

CutShape ShapeOf(TopologyEventKind kind) {
  switch (kind) {
    case TopologyEventKind::HandleGained:
    case TopologyEventKind::PartsMerged: return CutShape::Discs;
    case TopologyEventKind::HandleLost:
    case TopologyEventKind::PartSplit: return CutShape::Band;
    default: return CutShape::None;
  }
}

namespace {

// The Hessian of f at node (i, j, k), central differences one cell wide (clamped at the
// grid's border), in units of f per cell^2.
Eigen::Matrix3d NodeHessian(const ScalarField &f, const vcg::Point3i &node) {
  auto at = [&](int di, int dj, int dk) {
    const vcg::Point3i &d = f.grid.dims;
    const int i = std::clamp(node[0] + di, 0, d[0] - 1), j = std::clamp(node[1] + dj, 0, d[1] - 1),
              k = std::clamp(node[2] + dk, 0, d[2] - 1);
    return f(i, j, k);
  };
  auto offset = [](int axis, int s) {
    int o[3] = {0, 0, 0};
    o[axis] = s;
    return vcg::Point3i(o[0], o[1], o[2]);
  };
  Eigen::Matrix3d H;
  const double centre = at(0, 0, 0);
  for (int a = 0; a < 3; ++a) {
    const vcg::Point3i p = offset(a, 1);
    H(a, a) = at(p[0], p[1], p[2]) - 2 * centre + at(-p[0], -p[1], -p[2]);
    for (int b = a + 1; b < 3; ++b) {
      const vcg::Point3i q = offset(b, 1), pp = p + q, pm = p - q;
      H(a, b) = H(b, a) = (at(pp[0], pp[1], pp[2]) - at(pm[0], pm[1], pm[2]) - at(-pm[0], -pm[1], -pm[2]) +
                           at(-pp[0], -pp[1], -pp[2])) / 4;
    }
  }
  return H;
}

} // namespace

CutDirection CutAxis(const TopologyEvent &event, const ScalarField &f, const std::vector<Saddle> &saddles) {
  const int kind = ShapeOf(event.kind) == CutShape::Discs ? 2 : 1;
  const Saddle *nearest = nullptr;
  double best = kSaddleCells * f.grid.h;
  for (const Saddle &s : saddles)
    if (s.expandingDirections == kind && vcg::Distance(s.position, event.position) <= best)
      best = vcg::Distance(s.position, event.position), nearest = &s;
  if (nearest) return {nearest->stable, true};
  // The odd-signed principal curvature: with eigenvalues l0 <= l1 <= l2, one negative
  // (l1 >= 0) makes l0's the odd one, two negative make l2's.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(NodeHessian(f, event.node));
  const Eigen::Vector3d v = eigen.eigenvectors().col(eigen.eigenvalues()(1) >= 0 ? 0 : 2);
  return {ToPoint(v).Normalize(), false};
}

std::vector<Point3> BandPlanes(const TopologyEvent &event, const ScalarField &f) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(NodeHessian(f, event.node));
  std::vector<Point3> normals;
  for (int c = 0; c < 3; ++c) normals.push_back(ToPoint(Eigen::Vector3d(eigen.eigenvectors().col(c))).Normalize());
  for (int x = 0; x <= 1; ++x)  // one of each pair of opposite neighbours of a node among its 26
    for (int y = x ? -1 : 0; y <= 1; ++y)
      for (int z = x || y ? -1 : 1; z <= 1; ++z) normals.push_back(Point3(x, y, z).Normalize());
  return normals;
}

} // namespace eulermap
