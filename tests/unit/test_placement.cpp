// Unit tests of placement.h: the similarity and its inverse, the fit to 1, 2, collinear and
// 3 or more anchors (Umeyama), centre-and-scale (centroids and diagonals agree), the mirror
// test of the anchors, Transform, and the turns of the target (QuarterTurns, PrincipalAxes,
// AxisPermutations, CandidateTurns, CentreAndScale, DescribeTurn).
#include "core/eigen_point.h"
#include "core/placement.h"
#include "tests/support/meshes.h"
#include "tests/support/points.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace eulermap {
namespace {

using testing::RandomPoints;

Similarity KnownSimilarity() {
  Similarity s;
  s.rotation = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  s.scale = 1.7;
  s.translation = Eigen::Vector3d(0.3, -4, 2.5);
  return s;
}

TEST(Placement, ApplyAndInverse) {
  const Similarity s = KnownSimilarity();
  const Point3 p(0.7, -1.2, 3.3);
  const Eigen::Vector3d expected = 1.7 * (s.rotation * ToEigen(p)) + s.translation;
  EXPECT_POINT_NEAR(s.Apply(p), ToPoint(expected), 1e-12);
  EXPECT_POINT_NEAR(s.Inverse().Apply(s.Apply(p)), p, 1e-12);
  EXPECT_POINT_NEAR(s.Apply(s.Inverse().Apply(p)), p, 1e-12);
}

TEST(Placement, UmeyamaRecoversKnownSimilarity) {
  const Similarity truth = KnownSimilarity();
  const Mesh empty;
  for (int n : {3, 4, 9}) {
    const std::vector<Point3> from = RandomPoints(n, 10 + n, 2);
    std::vector<Point3> to;
    for (const auto &p : from) to.push_back(truth.Apply(p));
    const Similarity s = FitPlacement(empty, empty, from, to, Align::None);
    EXPECT_NEAR(s.scale, truth.scale, 1e-9) << n << " anchors";
    EXPECT_LE((s.rotation - truth.rotation).norm(), 1e-9) << n << " anchors";
    EXPECT_LE((s.translation - truth.translation).norm(), 1e-9) << n << " anchors";
    EXPECT_NEAR(s.rotation.determinant(), 1, 1e-12);
  }
}

TEST(Placement, OneAndTwoAnchors) {
  const Mesh empty;
  const Point3 b0(1, 2, 3), a0(-1, 0.5, 2);
  Similarity s = FitPlacement(empty, empty, {b0}, {a0}, Align::CentreAndScale);
  EXPECT_NEAR(s.scale, 1, 0);
  EXPECT_LE((s.rotation - Eigen::Matrix3d::Identity()).norm(), 0);
  EXPECT_POINT_NEAR(s.Apply(b0), a0, 1e-12);

  const Point3 b1(2, 2, 3), a1(-1, 2.5, 2);  // x-direction onto y-direction, length 1 -> 2
  s = FitPlacement(empty, empty, {b0, b1}, {a0, a1}, Align::None);
  EXPECT_NEAR(s.scale, 2, 1e-12);
  EXPECT_POINT_NEAR(s.Apply(b0), a0, 1e-12);
  EXPECT_POINT_NEAR(s.Apply(b1), a1, 1e-12);
  // Minimal rotation: about the axis perpendicular to both directions (z), 90 degrees.
  EXPECT_LE((s.rotation * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(s.rotation).angle(), M_PI / 2, 1e-12);
}

TEST(Placement, CollinearAnchorsUseTheLineRule) {
  const Similarity truth = KnownSimilarity();
  const Mesh empty;
  std::vector<Point3> from, to;
  for (double u : {-1.0, 0.2, 0.5, 2.0}) {
    from.push_back(Point3(1, 1, 1) + Point3(1, 2, -1) * u);
    to.push_back(truth.Apply(from.back()));
  }
  const Similarity s = FitPlacement(empty, empty, from, to, Align::None);
  EXPECT_NEAR(s.scale, truth.scale, 1e-9);
  for (std::size_t i = 0; i < from.size(); ++i) EXPECT_POINT_NEAR(s.Apply(from[i]), to[i], 1e-9);
  EXPECT_NEAR(s.rotation.determinant(), 1, 1e-12);
}

TEST(Placement, SurfaceCentroid) {
  Mesh box, sphere;
  testing::MakeBox(box, Box3(Point3(1, 2, 3), Point3(2, 5, 4)), 4);
  EXPECT_POINT_NEAR(SurfaceCentroid(box), Point3(1.5, 3.5, 3.5), 1e-12);
  testing::MakeSphere(sphere, Point3(-2, 0.5, 7), 3, 3);
  EXPECT_POINT_NEAR(SurfaceCentroid(sphere), Point3(-2, 0.5, 7), 1e-9);
}

TEST(Placement, CentreAndScaleAlignsCentroidsAndDiagonals) {
  Mesh source, target;
  testing::MakeSphere(source, Point3(1, 2, 3), 2, 3);
  testing::MakeEllipsoid(target, Point3(-5, 0, 1), Point3(1, 2, 0.5), 3);

  const Similarity none = FitPlacement(source, target, {}, {}, Align::None);
  EXPECT_EQ(none.scale, 1);
  EXPECT_EQ(none.translation, Eigen::Vector3d::Zero());

  const Similarity s = FitPlacement(source, target, {}, {}, Align::CentreAndScale);
  Mesh placed;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(placed, target);
  Transform(placed, s);
  EXPECT_POINT_NEAR(SurfaceCentroid(placed), SurfaceCentroid(source), 1e-9);
  EXPECT_NEAR(placed.bbox.Diag(), source.bbox.Diag(), 1e-9);
  EXPECT_LE((s.rotation - Eigen::Matrix3d::Identity()).norm(), 0);
}

TEST(Placement, TransformMovesPositionsAndRotatesNormals) {
  Mesh m;
  testing::MakeSphere(m, Point3(0, 0, 0), 1, 2);
  const Similarity s = KnownSimilarity();
  Mesh moved;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(moved, m);
  Transform(moved, s);
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    EXPECT_POINT_NEAR(moved.vert[i].P(), s.Apply(m.vert[i].P()), 1e-12);
    EXPECT_POINT_NEAR(moved.vert[i].N(), ToPoint(s.rotation * ToEigen(m.vert[i].N())), 1e-12);
  }
  EXPECT_POINT_NEAR(moved.bbox.Center(), ToPoint(s.translation), 1e-9 * 1.7 * 2);
}

// The anchors' own frame wins over align: with 3 or more anchors the fitted similarity
// takes each b_i onto its a_i, whatever align says.
TEST(Placement, AnchorsDecideOverAlign) {
  const Similarity truth = KnownSimilarity();
  Mesh source, target;
  testing::MakeSphere(source, Point3(1, 2, 3), 2, 2);
  testing::MakeSphere(target, Point3(-5, 0, 1), 0.5, 2);
  const std::vector<Point3> from = RandomPoints(5, 21, 1);
  std::vector<Point3> to;
  for (const Point3 &p : from) to.push_back(truth.Apply(p));
  for (Align align : {Align::None, Align::CentreAndScale}) {
    const Similarity s = FitPlacement(source, target, from, to, align);
    for (std::size_t i = 0; i < from.size(); ++i) EXPECT_POINT_NEAR(s.Apply(from[i]), to[i], 1e-9);
  }
}

// Anchors whose left and right are swapped (x negated before a similarity) fit their mirror
// image far better than themselves; anchors moved by a similarity do not; 3 anchors cannot
// tell (both residuals 0).
TEST(Placement, TheMirrorTestTellsSwappedSidesFromASimilarity) {
  const Similarity truth = KnownSimilarity();
  const std::vector<Point3> from = RandomPoints(6, 33, 1);
  std::vector<Point3> moved, mirrored;
  for (const Point3 &p : from) {
    moved.push_back(truth.Apply(p));
    mirrored.push_back(truth.Apply(Point3(-p.X(), p.Y(), p.Z())));
  }
  const MirrorTest same = TestMirror(from, moved), swapped = TestMirror(from, mirrored);
  EXPECT_FALSE(same.Mirrored());
  EXPECT_LT(same.residual, 1e-9);
  EXPECT_TRUE(swapped.Mirrored());
  EXPECT_LT(swapped.mirroredResidual, 1e-9);
  EXPECT_GT(swapped.residual, 0.1);
  const MirrorTest three = TestMirror({from[0], from[1], from[2]}, {mirrored[0], mirrored[1], mirrored[2]});
  EXPECT_EQ(three.residual, 0);
  EXPECT_EQ(three.mirroredResidual, 0);
  EXPECT_FALSE(three.Mirrored());
}

TEST(Placement, TheQuarterTurnsAreTheCubesOtherRotationsSmallestFirst) {
  const std::vector<Eigen::Matrix3d> turns = QuarterTurns();
  ASSERT_EQ(turns.size(), 23u);
  double last = 0;
  int quarter = 0, third = 0, half = 0;
  for (std::size_t n = 0; n < turns.size(); ++n) {
    const Eigen::Matrix3d &r = turns[n];
    EXPECT_TRUE((r * r.transpose()).isIdentity(1e-12));
    EXPECT_NEAR(r.determinant(), 1, 1e-12);
    EXPECT_FALSE(r.isIdentity());
    EXPECT_TRUE((r.array().abs() == 1).count() == 3);  // a signed permutation
    for (std::size_t m = 0; m < n; ++m) EXPECT_FALSE(r.isApprox(turns[m]));
    const double angle = Eigen::AngleAxisd(r).angle();
    EXPECT_GE(angle, last - 1e-9);
    last = angle;
    quarter += std::abs(angle - M_PI / 2) < 1e-9, third += std::abs(angle - 2 * M_PI / 3) < 1e-9,
        half += std::abs(angle - M_PI) < 1e-9;
  }
  EXPECT_EQ(quarter, 6);
  EXPECT_EQ(third, 8);
  EXPECT_EQ(half, 9);
}

TEST(Placement, TheAxisPermutationsLayTheZAxisOnEachAxisAndEachOrderOnce) {
  const std::vector<Eigen::Matrix3d> orders = AxisPermutations();
  ASSERT_EQ(orders.size(), 6u);
  EXPECT_TRUE(orders[0].isIdentity());
  int onAxis[3] = {0, 0, 0};
  for (std::size_t n = 0; n < orders.size(); ++n) {
    const Eigen::Matrix3d &r = orders[n];
    EXPECT_NEAR(r.determinant(), 1, 1e-12);
    EXPECT_TRUE((r.array().abs() == 1).count() == 3);
    for (std::size_t m = 0; m < n; ++m) EXPECT_FALSE(r.cwiseAbs() == orders[m].cwiseAbs());
    const double angle = Eigen::AngleAxisd(r).angle();
    EXPECT_TRUE(angle < 1e-9 || std::abs(angle - M_PI / 2) < 1e-9 || std::abs(angle - 2 * M_PI / 3) < 1e-9) << angle;
    Eigen::Index axis;
    (r * Eigen::Vector3d::UnitZ()).cwiseAbs().maxCoeff(&axis);
    ++onAxis[axis];
  }
  EXPECT_EQ(onAxis[0], 2);  // a hole's axis along z laid along x, y and z, twice each
  EXPECT_EQ(onAxis[1], 2);
  EXPECT_EQ(onAxis[2], 2);
}

TEST(Placement, CentreAndScaleTurnedMatchesTheTurnedTargetsBox) {
  // A box 2 x 1 x 0.4, and the same box tilted (its axis-aligned box then has a longer
  // diagonal): turned back, it is placed exactly as the upright one, the same scale too.
  Mesh source, upright, tilted;
  testing::MakeBox(source, Box3(Point3(1, 2, 3), Point3(4, 4, 4)));
  testing::MakeBox(upright, Box3(Point3(-1, -0.5, -0.2), Point3(1, 0.5, 0.2)));
  testing::MakeBox(tilted, Box3(Point3(-1, -0.5, -0.2), Point3(1, 0.5, 0.2)));
  Similarity tilt;
  tilt.rotation = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  tilt.translation = Eigen::Vector3d(0.3, -1, 2);
  Transform(tilted, tilt);
  const Similarity straight = CentreAndScale(source, upright);
  const Similarity back = CentreAndScale(source, tilted, tilt.rotation.transpose());
  EXPECT_LT(FitPlacement(source, tilted, {}, {}, Align::CentreAndScale).scale, 0.9 * straight.scale);  // as it is: smaller
  EXPECT_NEAR(back.scale, straight.scale, 1e-9);
  for (const Point3 &corner : {Point3(-1, -0.5, -0.2), Point3(1, 0.5, 0.2), Point3(1, -0.5, 0.2)})
    EXPECT_POINT_NEAR(back.Apply(tilt.Apply(corner)), straight.Apply(corner), 1e-9);
}

TEST(Placement, DescribeTurnNamesTheAngleAndTheAxis) {
  EXPECT_EQ(DescribeTurn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix()),
            "turned 90 degrees about the x axis");
  EXPECT_EQ(DescribeTurn(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix()),
            "turned 90 degrees about the -z axis");
  EXPECT_EQ(DescribeTurn(Eigen::AngleAxisd(2 * M_PI / 3, Eigen::Vector3d(1, -1, 1).normalized()).toRotationMatrix()),
            "turned 120 degrees about (1, -1, 1)");
  EXPECT_EQ(DescribeTurn(Eigen::AngleAxisd(M_PI, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix()),
            "turned 180 degrees about (0, 1, 1)");
  EXPECT_EQ(DescribeTurn(Eigen::AngleAxisd(0.82, Eigen::Vector3d(-0.84, -0.51, 0.19).normalized()).toRotationMatrix()),
            "turned 47 degrees about (-0.84, -0.51, 0.19)");
}

TEST(Placement, CandidateTurnsLayTheTargetsPrincipalAxesOnTheSources) {
  // A box 2 x 1 x 0.4 and the same box turned by an angle no quarter turn has.
  Mesh source, target;
  testing::MakeBox(source, Box3(Point3(-1, -0.5, -0.2), Point3(1, 0.5, 0.2)));
  testing::MakeBox(target, Box3(Point3(-1, -0.5, -0.2), Point3(1, 0.5, 0.2)));
  Similarity tilt;
  tilt.rotation = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  Transform(target, tilt);
  const Eigen::Matrix3d axes = PrincipalAxes(source);
  EXPECT_NEAR(axes.determinant(), 1, 1e-9);
  EXPECT_NEAR(std::abs(axes(2, 0)), 1, 1e-9);  // the smallest moment first: along z
  EXPECT_NEAR(std::abs(axes(0, 2)), 1, 1e-9);  // the largest last: along x
  const std::vector<Eigen::Matrix3d> turns = CandidateTurns(source, target);
  EXPECT_EQ(turns.size(), 23u + 24u);  // the quarter turns, then 24 that align the axes
  for (std::size_t n = 0; n < 23; ++n) EXPECT_TRUE(turns[n].isApprox(QuarterTurns()[n]));
  bool undone = false;  // one of them turns the target back
  for (const Eigen::Matrix3d &r : turns) undone = undone || (r * tilt.rotation).isIdentity(1e-6);
  EXPECT_TRUE(undone);
  EXPECT_EQ(CandidateTurns(source, source).size(), 23u);  // axes along the coordinate axes: nothing more
}

} // namespace
} // namespace eulermap
