// eulermap placement: the similarity P that puts the target in the source's frame
// (placement.h). Umeyama's least-squares similarity for 3 or more anchors in general
// position; simpler closed forms for 0, 1, 2 and collinear anchors.
#include "placement.h"

#include "eigen_point.h"

#include <vcg/complex/algorithms/update/bounding.h>

#include <Eigen/Geometry>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace eulermap {

namespace {

// Points as the columns of a 3 x n matrix.
Eigen::Matrix3Xd Columns(const std::vector<Point3> &pts) {
  Eigen::Matrix3Xd m(3, pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) m.col(i) = ToEigen(pts[i]);
  return m;
}

// The diagonal of the box of the live vertices along the given axes (columns; the identity:
// the axis-aligned box, whether or not m.bbox is up to date).
double Diagonal(const Mesh &mesh, const Eigen::Matrix3d &axes) {
  Box3 box;
  for (const auto &v : mesh.vert)
    if (!v.IsD()) box.Add(ToPoint(axes.transpose() * ToEigen(v.cP())));
  return box.IsNull() ? 0 : box.Diag();
}

// Principal direction of the centred columns of `x` (3 x n) and its singular values, from
// the 3 x 3 eigenproblem of x x^T (whose eigenvalues are their squares): an SVD of the
// 3 x n matrix itself gives the same and took 45 s more to compile under the sanitizers.
//   x:      points as columns, already centred
//   sigma:  out, singular values (descending; 0 beyond the rank)
//   returns the unit direction of largest spread
Eigen::Vector3d PrincipalDirection(const Eigen::Matrix3Xd &x, Eigen::Vector3d &sigma) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(x * x.transpose());  // ascending
  sigma = eigen.eigenvalues().reverse().cwiseMax(0).cwiseSqrt();
  return eigen.eigenvectors().col(2);
}

// Similarity taking points on (or near) a line onto points on a line: the "2-anchor
// rule", also used when 3 or more anchors are (near) collinear, where Umeyama's
// rotation about the line would be undetermined.
//   from, to:  3 x n matrices of matched points (n >= 2)
//   returns    rotation = the minimal rotation taking the principal direction of `from`
//              onto that of `to` (sign chosen so the points keep their order along the
//              line); scale = the least-squares scale of the positions along the line;
//              translation takes the centroid of `from` onto that of `to`. With two
//              points this maps the segment onto the segment exactly.
Similarity LineRule(const Eigen::Matrix3Xd &from, const Eigen::Matrix3Xd &to) {
  Similarity s;
  const Eigen::Vector3d cf = from.rowwise().mean(), ct = to.rowwise().mean();
  const Eigen::Matrix3Xd xf = from.colwise() - cf, xt = to.colwise() - ct;
  Eigen::Vector3d sf, st;
  const Eigen::Vector3d df = PrincipalDirection(xf, sf);
  Eigen::Vector3d dt = PrincipalDirection(xt, st);
  const Eigen::VectorXd along_f = xf.transpose() * df;
  Eigen::VectorXd along_t = xt.transpose() * dt;
  if (along_f.dot(along_t) < 0) {  // keep the order of the points along the line
    dt = -dt;
    along_t = -along_t;
  }
  const double denom = along_f.squaredNorm();
  if (denom > 0 && along_t.squaredNorm() > 0) {
    s.scale = along_f.dot(along_t) / denom;
    s.rotation = Eigen::Quaterniond::FromTwoVectors(df, dt).toRotationMatrix();
  }
  s.translation = ct - s.scale * s.rotation * cf;
  return s;
}

} // namespace

Point3 Similarity::Apply(const Point3 &p) const { return ToPoint(scale * (rotation * ToEigen(p)) + translation); }

Similarity Similarity::Inverse() const {
  // p = s R x + t  =>  x = (1/s) R^T p - (1/s) R^T t
  Similarity inv;
  inv.rotation = rotation.transpose();
  inv.scale = 1 / scale;
  inv.translation = -inv.scale * (inv.rotation * translation);
  return inv;
}

// Area-weighted centroid of the live faces: sum_f area_f * centre_f / sum_f area_f.
//   mesh:    any triangle mesh (deleted faces are skipped)
//   returns  the centroid; with no faces (or zero total area) the mean of the live
//            vertices, and (0,0,0) for an empty mesh
Point3 SurfaceCentroid(const Mesh &mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0;
  for (const auto &f : mesh.face) {
    if (f.IsD()) continue;
    const Eigen::Vector3d p0 = ToEigen(f.cP(0)), p1 = ToEigen(f.cP(1)), p2 = ToEigen(f.cP(2));
    const double a = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    sum += a * (p0 + p1 + p2) / 3;
    area += a;
  }
  if (area > 0) return ToPoint(sum / area);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto &v : mesh.vert)
    if (!v.IsD()) {
      mean += ToEigen(v.cP());
      ++n;
    }
  return n ? ToPoint(mean / n) : Point3(0, 0, 0);
}

// The placement P of placement.h.
//   source, target: the meshes (used only without anchors, for Align::CentreAndScale and Overlap)
//   from:           target-side anchors b_i
//   to:             source-side anchors a_i, matched to `from` by index
//   align:          what to do without anchors
//   returns         P with P(b_i) ~ a_i (least squares); throws std::invalid_argument
//                   when the two anchor lists differ in length
Similarity FitPlacement(const Mesh &source, const Mesh &target, const std::vector<Point3> &from,
                        const std::vector<Point3> &to, Align align) {
  if (from.size() != to.size())
    throw std::invalid_argument("FitPlacement: " + std::to_string(from.size()) + " target anchors but " +
                                std::to_string(to.size()) + " source anchors");
  Similarity s;
  const std::size_t n = from.size();
  if (n == 0) {
    if (align == Align::None) return s;
    return CentreAndScale(source, target);
  }

  const Eigen::Matrix3Xd f = Columns(from), t = Columns(to);
  const Eigen::Vector3d cf = f.rowwise().mean(), ct = t.rowwise().mean();
  if (n == 1) {
    s.translation = ct - cf;
    return s;
  }

  // Spread of each side: coincident anchors give a translation only; (near) collinear
  // ones the line rule (relative threshold 1e-3 on the second singular value, where
  // a rotation about the line is set by noise rather than by the anchors).
  Eigen::Vector3d sf, st;
  PrincipalDirection(f.colwise() - cf, sf);
  PrincipalDirection(t.colwise() - ct, st);
  const double reach = std::max({1.0, f.cwiseAbs().maxCoeff(), t.cwiseAbs().maxCoeff()});
  if (sf(0) <= 1e-12 * reach || st(0) <= 1e-12 * reach) {
    s.translation = ct - cf;
    return s;
  }
  const double kCollinear = 1e-3;
  if (n == 2 || sf(1) <= kCollinear * sf(0) || st(1) <= kCollinear * st(0)) return LineRule(f, t);

  // Umeyama (1991): least-squares similarity, proper rotation.
  const Eigen::Matrix4d m = Eigen::umeyama(f, t, true);
  const Eigen::Matrix3d sr = m.topLeftCorner<3, 3>();
  s.scale = std::cbrt(sr.determinant());
  s.rotation = sr / s.scale;
  s.translation = m.topRightCorner<3, 1>();
  return s;
}

MirrorTest TestMirror(const std::vector<Point3> &from, const std::vector<Point3> &to) {
  MirrorTest test;
  if (from.size() < 4 || from.size() != to.size()) return test;
  const Eigen::Matrix3Xd f = Columns(from), t = Columns(to);
  Eigen::Vector3d sf, st;
  PrincipalDirection(f.colwise() - f.rowwise().mean(), sf);
  PrincipalDirection(t.colwise() - t.rowwise().mean(), st);
  const double kFlat = 0.05;  // third spread against the first: below it the anchors are about coplanar
  if (sf(2) <= kFlat * sf(0) || st(2) <= kFlat * st(0)) return test;
  auto rms = [&](const Eigen::Matrix3Xd &x) {
    const Eigen::Matrix4d m = Eigen::umeyama(x, t, true);
    return std::sqrt(((m.topLeftCorner<3, 3>() * x).colwise() + Eigen::Vector3d(m.topRightCorner<3, 1>()) - t)
                         .squaredNorm() / double(x.cols()));
  };
  Eigen::Matrix3Xd mirrored = f;
  mirrored.row(0) *= -1;
  test.residual = rms(f);
  test.mirroredResidual = rms(mirrored);
  return test;
}

namespace {

// The 24 proper rotations that permute the axes and flip their signs (identity included).
std::vector<Eigen::Matrix3d> SignedPermutations() {
  std::vector<Eigen::Matrix3d> out;
  const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto &o : order)
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
      for (int a = 0; a < 3; ++a) r(a, o[a]) = (signs >> a & 1) ? -1 : 1;
      if (r.determinant() > 0) out.push_back(r);
    }
  return out;
}

double Angle(const Eigen::Matrix3d &r) { return std::acos(std::clamp((r.trace() - 1) / 2, -1.0, 1.0)); }

// The rotations, the smallest angle first (stable: equal angles keep their order).
void ByAngle(std::vector<Eigen::Matrix3d> &turns) {
  std::stable_sort(turns.begin(), turns.end(),
                   [](const Eigen::Matrix3d &a, const Eigen::Matrix3d &b) { return Angle(a) < Angle(b) - 1e-9; });
}

} // namespace

std::vector<Eigen::Matrix3d> QuarterTurns() {
  std::vector<Eigen::Matrix3d> turns;
  for (const Eigen::Matrix3d &r : SignedPermutations())
    if (!r.isIdentity()) turns.push_back(r);
  ByAngle(turns);
  return turns;
}

std::vector<Eigen::Matrix3d> AxisPermutations() {
  std::vector<Eigen::Matrix3d> out;
  for (const Eigen::Matrix3d &r : SignedPermutations()) {
    auto same = std::find_if(out.begin(), out.end(), [&](const Eigen::Matrix3d &o) { return o.cwiseAbs() == r.cwiseAbs(); });
    if (same == out.end())
      out.push_back(r);
    else if (Angle(r) < Angle(*same) - 1e-9)
      *same = r;
  }
  ByAngle(out);
  return out;
}

Eigen::Matrix3d PrincipalAxes(const Mesh &mesh) {
  // Per face, the second moment of a uniform triangle about the centroid c:
  // area / 12 (sum_i v_i v_i^T + s s^T), v_i its corners less c, s = v_0 + v_1 + v_2.
  const Eigen::Vector3d c = ToEigen(SurfaceCentroid(mesh));
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (const auto &f : mesh.face) {
    if (f.IsD()) continue;
    const Eigen::Vector3d v0 = ToEigen(f.cP(0)) - c, v1 = ToEigen(f.cP(1)) - c, v2 = ToEigen(f.cP(2)) - c, s = v0 + v1 + v2;
    const double area = 0.5 * (v1 - v0).cross(v2 - v0).norm();
    moment += area / 12 * (v0 * v0.transpose() + v1 * v1.transpose() + v2 * v2.transpose() + s * s.transpose());
  }
  Eigen::Matrix3d axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moment).eigenvectors();
  if (axes.determinant() < 0) axes.col(2) *= -1;
  return axes;
}

std::vector<Eigen::Matrix3d> CandidateTurns(const Mesh &source, const Mesh &target) {
  std::vector<Eigen::Matrix3d> turns = QuarterTurns(), aligned;
  const Eigen::Matrix3d s = PrincipalAxes(source), t = PrincipalAxes(target);
  for (const Eigen::Matrix3d &q : SignedPermutations()) aligned.push_back(s * q * t.transpose());
  ByAngle(aligned);
  auto listed = [&](const Eigen::Matrix3d &r) {
    if (Angle(r) < 1e-6) return true;  // the target as it is
    for (const Eigen::Matrix3d &u : turns)
      if ((u - r).norm() < 1e-6) return true;
    return false;
  };
  for (const Eigen::Matrix3d &r : aligned)
    if (!listed(r)) turns.push_back(r);
  return turns;
}

Similarity CentreAndScale(const Mesh &source, const Mesh &target, const Eigen::Matrix3d &turn) {
  const bool turned = !turn.isIdentity();
  const double ds = Diagonal(source, turned ? PrincipalAxes(source) : Eigen::Matrix3d::Identity()),
               dt = Diagonal(target, turned ? PrincipalAxes(target) : Eigen::Matrix3d::Identity());
  Similarity s;
  s.rotation = turn;
  if (ds > 0 && dt > 0) s.scale = ds / dt;
  s.translation = ToEigen(SurfaceCentroid(source)) - s.scale * (turn * ToEigen(SurfaceCentroid(target)));
  return s;
}

std::string DescribeTurn(const Eigen::Matrix3d &r) {
  const Eigen::AngleAxisd turn(r);
  Eigen::Vector3d axis = turn.axis() / turn.axis().cwiseAbs().maxCoeff();
  if (std::abs(turn.angle() - M_PI) < 1e-6) {  // a half turn about -a is one about a: the first axis component positive
    const int first = std::abs(axis[0]) > 1e-6 ? 0 : std::abs(axis[1]) > 1e-6 ? 1 : 2;
    if (axis[first] < 0) axis = -axis;
  }
  const long degrees = std::lround(turn.angle() * 180 / M_PI);
  char text[120];
  for (int a = 0; a < 3; ++a)
    if (std::abs(axis[a]) > 1 - 1e-6 && axis.cwiseAbs().sum() < 1 + 1e-6) {
      std::snprintf(text, sizeof text, "turned %ld degrees about the %s%c axis", degrees, axis[a] < 0 ? "-" : "", "xyz"[a]);
      return text;
    }
  if ((axis - axis.array().round().matrix()).norm() < 1e-6) {  // a diagonal of the cube or of its faces
    std::snprintf(text, sizeof text, "turned %ld degrees about (%ld, %ld, %ld)", degrees, std::lround(axis[0]),
                  std::lround(axis[1]), std::lround(axis[2]));
    return text;
  }
  const Eigen::Vector3d unit = axis.normalized();
  auto hundredths = [](double x) { return std::round(100 * x) / 100 + 0.0; };  // + 0.0: no "-0.00"
  std::snprintf(text, sizeof text, "turned %ld degrees about (%.2f, %.2f, %.2f)", degrees, hundredths(unit[0]),
                hundredths(unit[1]), hundredths(unit[2]));
  return text;
}

// Applies s to m in place.
//   m:  mesh; live vertex positions become s(p), vertex and face normals are rotated
//       (their lengths are kept), and the bounding box is recomputed
//   s:  the similarity (a proper rotation, so orientation is kept)
void Transform(Mesh &m, const Similarity &s) {
  for (auto &v : m.vert) {
    if (v.IsD()) continue;
    v.P() = s.Apply(v.P());
    v.N() = ToPoint(s.rotation * ToEigen(v.N()));
  }
  for (auto &f : m.face)
    if (!f.IsD()) f.N() = ToPoint(s.rotation * ToEigen(f.N()));
  vcg::tri::UpdateBounding<Mesh>::Box(m);
}

} // namespace eulermap
