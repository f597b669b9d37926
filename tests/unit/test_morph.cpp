// Unit tests of morph.h: measured properties of the ARAP anchor interpolation (Alexa et
// al. 2000), the thin-plate warps and the morph frames of Eq. 1 (placement: test_placement).
#include "core/eigen_point.h"
#include "core/morph.h"
#include "tests/support/meshes.h"
#include "tests/support/points.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>

namespace eulermap {
namespace {

using testing::RandomPoints;

// A non-trivial target: rotated, scaled, translated, then bent.
Point3 Bend(const Point3 &p) {
  const Eigen::Vector3d q = 1.3 * (Eigen::AngleAxisd(0.8, Eigen::Vector3d(0, 1, 1).normalized()) * ToEigen(p)) +
                            Eigen::Vector3d(0.2, 0.1, -0.3);
  return Point3(q.x(), q.y() + 0.3 * q.x() * q.x(), q.z() + 0.2 * std::sin(2 * q.y()));
}

std::vector<Point3> Map(const std::vector<Point3> &pts, Point3 (*fn)(const Point3 &)) {
  std::vector<Point3> out;
  for (const auto &p : pts) out.push_back(fn(p));
  return out;
}

// f0: sphere of radius 1 at the origin; f1: a sphere of radius 1.2 off-centre (as
// signed distances), on a grid over [-3,3]^3.
struct Fields {
  ScalarField f0, f1;
  explicit Fields(int cells = 24, vcg::Point3i nodes = vcg::Point3i(0, 0, 0)) {
    const Box3 box(Point3(-3, -3, -3), Point3(3, 3, 3));
    const Grid g = nodes.X() ? Grid::WithNodes(box, nodes, 0) : Grid::Enclosing(box, cells, 0);
    f0 = ScalarField(g, 0.0);
    f1 = ScalarField(g, 0.0);
    g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
      const Point3 p = g.Node(i, j, k);
      f0.values[idx] = p.Norm() - 1;
      f1.values[idx] = vcg::Distance(p, Point3(0.4, -0.2, 0.3)) - 1.2 + 0.1 * p.X() * p.Y();
    });
  }
};

// ---------------------------------------------------------------- morph: linear blend

void ExpectLinearBlend(const Fields &f, const Morph &m, const std::vector<Point3> &a, const std::vector<Point3> &b) {
  EXPECT_EQ(m.mode(), Morph::Mode::LinearBlend);
  EXPECT_NE(m.Describe().find("linear blend"), std::string::npos) << m.Describe();
  ScalarField out;
  for (double t : {0.0, 0.3, 1.0}) {
    m.Frame(t, out);
    ASSERT_EQ(out.values.size(), f.f0.values.size());
    for (std::size_t i = 0; i < out.values.size(); i += 7)
      ASSERT_NEAR(out.values[i], (1 - t) * f.f0.values[i] + t * f.f1.values[i], 1e-12) << "t=" << t;
  }
  const Point3 p(0.3, -1.1, 2.2);
  EXPECT_EQ(m.WarpToSource(0.4, p), p);
  EXPECT_EQ(m.WarpToTarget(0.4, p), p);
  const std::vector<Point3> q = m.Anchors(0.25);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_POINT_NEAR(q[i], a[i] * 0.75 + b[i] * 0.25, 1e-12);
}

TEST(Morph, LinearBlendWithFewerThanFourAnchors) {
  const Fields f;
  for (int n = 0; n <= 3; ++n) {
    const std::vector<Point3> a = RandomPoints(n, 1), b = Map(a, Bend);
    const Morph m(f.f0, f.f1, a, b);
    ExpectLinearBlend(f, m, a, b);
  }
}

TEST(Morph, LinearBlendWithCoplanarAnchors) {
  const Fields f;
  std::vector<Point3> a = RandomPoints(6, 2);
  for (auto &p : a) p.Z() = 0.5 * p.X() - 0.25 * p.Y() + 0.1;  // all on one plane
  const std::vector<Point3> b = Map(a, Bend);
  const Morph m(f.f0, f.f1, a, b);
  ExpectLinearBlend(f, m, a, b);
  EXPECT_NE(m.Describe().find("coplanar"), std::string::npos) << m.Describe();
}

// ---------------------------------------------------------------- morph: ARAP + TPS

std::vector<Point3> SpreadAnchors() {  // 8 non-coplanar anchors, no 4 of them coplanar by accident
  return {Point3(-1, -1, -0.9), Point3(1.1, -0.9, -1), Point3(-0.8, 1, -1.1), Point3(1, 1.2, -0.8),
          Point3(-1, -1.1, 1), Point3(0.9, -1, 1.1), Point3(-1.2, 0.9, 0.8), Point3(0.2, 0.3, 1.3)};
}

TEST(Morph, ArapTpsWarpsInterpolateTheAnchors) {
  const Fields f;
  const std::vector<Point3> a = SpreadAnchors(), b = Map(a, Bend);
  const Morph m(f.f0, f.f1, a, b);
  ASSERT_EQ(m.mode(), Morph::Mode::ArapTps) << m.Describe();
  EXPECT_NE(m.Describe().find("ARAP+TPS, 8 anchors, "), std::string::npos) << m.Describe();

  const std::vector<Point3> q0 = m.Anchors(0), q1 = m.Anchors(1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_POINT_NEAR(q0[i], a[i], 1e-9);
    EXPECT_POINT_NEAR(q1[i], b[i], 1e-9);
  }
  double offLine = 0;  // the ARAP path is not the straight line (the target is rotated)
  for (double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const std::vector<Point3> q = m.Anchors(t);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_POINT_NEAR(m.WarpToSource(t, q[i]), q0[i], 1e-6) << "t=" << t << " anchor " << i;
      EXPECT_POINT_NEAR(m.WarpToTarget(t, q[i]), q1[i], 1e-6) << "t=" << t << " anchor " << i;
      offLine = std::max(offLine, vcg::Distance(q[i], a[i] * (1 - t) + b[i] * t));
    }
  }
  EXPECT_GT(offLine, 1e-2);
  // At the ends the warps are the identity.
  const Point3 p(0.4, 2.1, -1.7);
  EXPECT_POINT_NEAR(m.WarpToSource(0, p), p, 1e-9);
  EXPECT_POINT_NEAR(m.WarpToTarget(1, p), p, 1e-9);
}

TEST(Morph, ArapTpsFramesMatchTheFieldsAtTheEndsAndEq1Between) {
  const Fields f;
  const std::vector<Point3> a = SpreadAnchors(), b = Map(a, Bend);
  const Morph m(f.f0, f.f1, a, b);
  ASSERT_EQ(m.mode(), Morph::Mode::ArapTps);
  ScalarField out;
  m.Frame(0, out);
  for (std::size_t i = 0; i < out.values.size(); ++i) ASSERT_NEAR(out.values[i], f.f0.values[i], 1e-9);
  m.Frame(1, out);
  for (std::size_t i = 0; i < out.values.size(); ++i) ASSERT_NEAR(out.values[i], f.f1.values[i], 1e-9);

  // In between, the parallel frame equals Eq. 1 evaluated point by point.
  const double t = 0.4;
  m.Frame(t, out);
  const Grid &g = out.grid;
  int checked = 0;
  g.ForEachNode([&](int i, int j, int k, std::size_t idx) {
    if (idx % 97) return;
    const Point3 p = g.Node(i, j, k);
    const double expected = (1 - t) * f.f0.Value(m.WarpToSource(t, p)) + t * f.f1.Value(m.WarpToTarget(t, p));
    ASSERT_NEAR(out.values[idx], expected, 1e-9);
    ++checked;
  });
  EXPECT_GT(checked, 100);
  // The frame differs from the plain blend (the warps do something).
  double maxDiff = 0;
  for (std::size_t i = 0; i < out.values.size(); ++i)
    maxDiff = std::max(maxDiff, std::abs(out.values[i] - ((1 - t) * f.f0.values[i] + t * f.f1.values[i])));
  EXPECT_GT(maxDiff, 1e-2);
}

TEST(Morph, ArapInterpolatesAPureRotationRigidly) {
  const Fields f;
  std::vector<Point3> a = SpreadAnchors();
  Point3 c(0, 0, 0);
  for (const auto &p : a) c += p / double(a.size());
  for (auto &p : a) p -= c;  // rotate about the anchors' centroid
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  std::vector<Point3> b;
  for (const auto &p : a) b.push_back(ToPoint(Eigen::AngleAxisd(M_PI / 2, axis) * ToEigen(p)));
  const Morph m(f.f0, f.f1, a, b);
  ASSERT_EQ(m.mode(), Morph::Mode::ArapTps);
  for (double t : {0.25, 0.5, 0.75}) {
    const Eigen::AngleAxisd rt(t * M_PI / 2, axis);
    const std::vector<Point3> q = m.Anchors(t);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_POINT_NEAR(q[i], ToPoint(rt * ToEigen(a[i])), 1e-6) << "t=" << t;
    // A rigid motion is affine, so the thin-plate warps reproduce it everywhere.
    const Point3 p(1.7, -0.6, 2.4);
    EXPECT_POINT_NEAR(m.WarpToSource(t, p), ToPoint(rt.inverse() * ToEigen(p)), 1e-6);
    EXPECT_POINT_NEAR(m.WarpToTarget(t, p), ToPoint(Eigen::AngleAxisd((1 - t) * M_PI / 2, axis) * ToEigen(p)), 1e-6);
  }
  const std::vector<Point3> q = m.Anchors(0.5);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      EXPECT_NEAR(vcg::Distance(q[i], q[j]), vcg::Distance(a[i], a[j]), 1e-6);
}

TEST(Morph, NearDegenerateTetrahedraAreLeftOut) {
  const Fields f;
  // Corners of a box: 12 of its 70 4-subsets are coplanar (6 faces, 6 diagonal planes).
  std::vector<Point3> a;
  for (int i = 0; i < 8; ++i) a.push_back(Point3(i & 1 ? 1 : -1, i & 2 ? 1.5 : -1.5, i & 4 ? 0.8 : -0.8));
  const Morph m(f.f0, f.f1, a, Map(a, Bend));
  ASSERT_EQ(m.mode(), Morph::Mode::ArapTps);
  EXPECT_NE(m.Describe().find("58 tetrahedra (12 near-degenerate of 70"), std::string::npos) << m.Describe();
}

TEST(Morph, ManyAnchorsAreSampledDeterministically) {
  const Fields f(16);
  const std::vector<Point3> a = RandomPoints(40, 3, 1.5), b = Map(a, Bend);  // C(40,4) = 91390
  const Morph m(f.f0, f.f1, a, b), again(f.f0, f.f1, a, b);
  ASSERT_EQ(m.mode(), Morph::Mode::ArapTps);
  EXPECT_NE(m.Describe().find("30000 tetrahedra (deterministic sample of 91390"), std::string::npos) << m.Describe();
  const std::vector<Point3> q = m.Anchors(0.5), q2 = again.Anchors(0.5);
  EXPECT_EQ(q, q2);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_POINT_NEAR(m.WarpToSource(0.5, q[i]), a[i], 1e-6);
    EXPECT_POINT_NEAR(m.WarpToTarget(0.5, q[i]), b[i], 1e-6);
  }
}

TEST(Morph, WarpsAreThreadSafe) {
  const Fields f;
  const std::vector<Point3> a = SpreadAnchors(), b = Map(a, Bend);
  const Morph m(f.f0, f.f1, a, b);
  const std::vector<Point3> pts = RandomPoints(400, 5, 2);
  const double times[3] = {0.2, 0.55, 0.8};
  std::vector<Point3> serial(pts.size()), parallel(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) serial[i] = m.WarpToSource(times[i % 3], pts[i]) + m.WarpToTarget(times[(i + 1) % 3], pts[i]);
#pragma omp parallel for
  for (long i = 0; i < long(pts.size()); ++i) parallel[i] = m.WarpToSource(times[i % 3], pts[i]) + m.WarpToTarget(times[(i + 1) % 3], pts[i]);
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(serial[i], parallel[i]) << i;
}

TEST(Morph, RejectsBadInput) {
  const Fields f, coarse(12);
  std::vector<Point3> a = SpreadAnchors(), b = Map(a, Bend);
  EXPECT_THROW(Morph(f.f0, f.f1, a, std::vector<Point3>(b.begin(), b.end() - 1)), std::invalid_argument);
  EXPECT_THROW(Morph(f.f0, coarse.f1, a, b), std::invalid_argument);
  a[3] = a[5];
  EXPECT_THROW(Morph(f.f0, f.f1, a, b), std::invalid_argument);
}

// Not a pass/fail test: the time of one frame on a 64^3 grid with 30 anchors.
TEST(Morph, FrameTime64Cubed30Anchors) {
  const Fields f(0, vcg::Point3i(64, 64, 64));
  const std::vector<Point3> a = RandomPoints(30, 4, 2), b = Map(a, Bend);
  const auto t0 = std::chrono::steady_clock::now();
  const Morph m(f.f0, f.f1, a, b);
  const auto t1 = std::chrono::steady_clock::now();
  ASSERT_EQ(m.mode(), Morph::Mode::ArapTps) << m.Describe();
  ScalarField out;
  std::vector<double> frames;
  for (double t : {0.2, 0.4, 0.6, 0.8, 0.5}) {
    const auto s = std::chrono::steady_clock::now();
    m.Frame(t, out);
    frames.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count());
  }
  std::sort(frames.begin(), frames.end());
  const auto s = std::chrono::steady_clock::now();
  m.Anchors(0.3);
  const double anchors = std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count();
  std::cout << "[ timing   ] " << m.Describe() << "\n[ timing   ] setup " << std::chrono::duration<double>(t1 - t0).count()
            << " s, Anchors(t) " << anchors << " s, Frame(t) on " << out.values.size() << " nodes: median "
            << frames[frames.size() / 2] << " s (min " << frames.front() << ", max " << frames.back() << ")\n";
  RecordProperty("frame_seconds_median", std::to_string(frames[frames.size() / 2]));
}

} // namespace
} // namespace eulermap
