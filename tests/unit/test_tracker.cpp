// The tracker (tracker.h, Eq. 7): points advected through known velocity fields land where
// the formula says, and stay on their own level sets.
#include "core/tracker.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace eulermap;

namespace {

constexpr double kRadius = 1;

// The signed distance to the sphere of radius kRadius around `centre`, on a grid of
// `cells` cells over [-2, 2]^3.
ScalarField Sphere(const Grid &grid, const Point3 &centre) {
  ScalarField f(grid, 0);
  grid.ForEachNode([&](int i, int j, int k, std::size_t n) { f.values[n] = vcg::Distance(grid.Node(i, j, k), centre) - kRadius; });
  return f;
}

Grid Box(int cells) { return Grid::Enclosing(Box3(Point3(-2, -2, -2), Point3(2, 2, 2)), cells, 0); }

// Points on the unit sphere, away from the rotation axis z.
std::vector<Point3> Ring(int count, double radius) {
  std::vector<Point3> points;
  for (int n = 0; n < count; ++n) {
    const double a = 2 * M_PI * n / count;
    points.push_back(Point3(std::cos(a) * 0.8, std::sin(a) * 0.8, 0.6) * radius);
  }
  return points;
}

TEST(Tracker, ATranslationCarriesPointsByVelocityTimesTime) {
  const Grid grid = Box(40);
  const Point3 velocity(0.4, -0.2, 0.1);
  const int steps = 10;
  const double dt = 1.0 / steps;
  const VectorField V(grid, velocity);
  const std::vector<Point3> start = Ring(12, kRadius);
  Tracker tracker(start, std::vector<double>(start.size(), 0));
  for (int k = 1; k <= steps; ++k) tracker.Advance(V, Sphere(grid, velocity * (k * dt)), dt);
  for (std::size_t n = 0; n < start.size(); ++n)
    EXPECT_LT(vcg::Distance(tracker.Points()[n], start[n] + velocity), 0.1 * grid.h) << "point " << n;
}

// A rotation about z at angular speed w: V(p) = w (-y, x, 0), linear, so trilinear
// interpolation reads it exactly; the sphere around the origin does not move.
VectorField Rotation(const Grid &grid, double w) {
  VectorField V(grid, Point3(0, 0, 0));
  grid.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 p = grid.Node(i, j, k);
    V.values[n] = Point3(-p.Y(), p.X(), 0) * w;
  });
  return V;
}

TEST(Tracker, ARotationTurnsPointsByItsAngle) {
  const Grid grid = Box(40);
  const double w = M_PI / 2;  // a quarter turn over t in [0, 1]
  const int steps = 20;
  const ScalarField f = Sphere(grid, Point3(0, 0, 0));
  const VectorField V = Rotation(grid, w);
  const std::vector<Point3> start = Ring(12, kRadius);
  Tracker tracker(start, std::vector<double>(start.size(), 0));
  for (int k = 0; k < steps; ++k) tracker.Advance(V, f, 1.0 / steps);
  for (std::size_t n = 0; n < start.size(); ++n) {
    const Point3 &p = start[n], turned(-p.Y(), p.X(), p.Z());  // p rotated by pi/2 about z
    EXPECT_LT(vcg::Distance(tracker.Points()[n], turned), 0.1 * grid.h) << "point " << n;
  }
}

TEST(Tracker, APointOffTheSurfaceFollowsItsOwnLevel) {
  const Grid grid = Box(40);
  const ScalarField f = Sphere(grid, Point3(0, 0, 0));
  const VectorField V = Rotation(grid, M_PI / 2);
  const double level = 0.3;  // 0.3 outside the sphere
  const std::vector<Point3> start = Ring(8, kRadius + level);
  Tracker tracker(start, std::vector<double>(start.size(), level));
  for (int k = 0; k < 20; ++k) tracker.Advance(V, f, 0.05);
  for (const Point3 &p : tracker.Points()) EXPECT_NEAR(p.Norm(), kRadius + level, 0.05 * grid.h);
}

TEST(Tracker, PullBackLandsOnTheLevelSet) {
  const Grid grid = Box(40);
  const ScalarField f = Sphere(grid, Point3(0, 0, 0));
  for (const Point3 &p : {Point3(1.3, 0.2, -0.1), Point3(0.1, 0.5, 0.4), Point3(-0.9, -0.9, 0.2)})
    EXPECT_NEAR(f.Value(PullBack(f, p, 0)), 0, 1e-4 * grid.h);
}

TEST(Tracker, AddedPointsAreTrackedFromThenOn) {
  Tracker tracker({Point3(1, 0, 0)}, {0});
  EXPECT_EQ(tracker.Add({Point3(0, 1, 0), Point3(0, 0, 1)}, 0.5), 1u);
  ASSERT_EQ(tracker.Points().size(), 3u);
  EXPECT_EQ(tracker.Levels()[2], 0.5);
}

} // namespace
