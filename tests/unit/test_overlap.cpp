// Unit tests of overlap.h: the placement that overlaps the two insides most finds the
// table's top on the chair's seat (centre-and-scale puts it halfway up the back), keeps a
// placement that already overlaps fully, and recovers a shift and a scale that
// centre-and-scale gets wrong.
#include "core/eigen_point.h"
#include "core/overlap.h"
#include "tests/support/meshes.h"
#include "tests/support/points.h"
#include "tests/support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace eulermap {
namespace {

using testing::MakeSphere;

// chair -> table (tests/support/shapes.cpp): the seat is the box z 0.45-0.55, the top 0.65-0.75
// on legs at the same places; the chair's back makes its bounding box taller.
TEST(Overlap, PutsTheTablesTopOnTheChairsSeat) {
  Mesh chair, table;
  testing::MakeShape("chair", chair, 64);
  testing::MakeShape("table", table, 64);
  const Similarity start = FitPlacement(chair, table, {}, {}, Align::CentreAndScale);
  EXPECT_GT(start.scale, 1.2);  // the diagonals: 1.72 / 1.36
  const Overlap o = FitOverlap(chair, table, start);
  EXPECT_LT(o.startIoU, 0.1);
  EXPECT_GT(o.bestIoU, 0.3);
  EXPECT_NEAR(o.placement.scale, 1, 0.05);
  // The top's middle (0, 0, 0.7) lands on the seat's (0, 0, 0.5), the legs' feet on the floor.
  const Point3 top = o.placement.Apply(Point3(0, 0, 0.7)), leg = o.placement.Apply(Point3(-0.35, -0.35, 0.3));
  const double cell = 1.5 / kOverlapCells;
  EXPECT_NEAR(top.Z(), 0.5, cell);
  EXPECT_NEAR(top.X(), 0, cell);
  EXPECT_NEAR(top.Y(), 0, cell);
  EXPECT_NEAR(leg.X(), -0.35, cell);
  EXPECT_NEAR(leg.Y(), -0.35, cell);
}

TEST(Overlap, KeepsAPlacementThatOverlapsFully) {
  Mesh a, b;
  MakeSphere(a, Point3(0, 0, 0), 0.7);
  MakeSphere(b, Point3(3, 1, -2), 1.4);  // the same ball, elsewhere and twice as big
  const Similarity start = FitPlacement(a, b, {}, {}, Align::CentreAndScale);
  const Overlap o = FitOverlap(a, b, start);
  EXPECT_GT(o.startIoU, 0.85);  // soft occupancies: the same ball overlaps itself 0.89
  EXPECT_NEAR(o.bestIoU, o.startIoU, 0.02);
  EXPECT_NEAR(o.placement.scale, 0.5, 0.02);
  EXPECT_POINT_NEAR(o.placement.Apply(Point3(3, 1, -2)), Point3(0, 0, 0), 0.03);
}

// A sphere with a thin spike: centre-and-scale matches the spiked box's diagonal and centroid,
// so it shrinks and shifts the ball; overlap puts the ball back on the ball.
TEST(Overlap, RecoversTheShiftAndScaleCentreAndScaleMisses) {
  using testing::MakeImplicit;
  Mesh ball, spiked;
  MakeSphere(ball, Point3(0, 0, 0), 0.5);
  MakeImplicit(
      spiked,
      [](const Point3 &p) {
        const double sphere = p.Norm() - 0.5;
        const double spike = std::max(std::hypot(p.X(), p.Y()) - 0.06, std::abs(p.Z() - 0.8) - 0.8);
        return std::min(sphere, spike);
      },
      Box3(Point3(-0.7, -0.7, -0.7), Point3(0.7, 0.7, 1.8)), 64);
  const Similarity start = FitPlacement(ball, spiked, {}, {}, Align::CentreAndScale);
  const Overlap o = FitOverlap(ball, spiked, start);
  EXPECT_GT(o.bestIoU, 0.75);
  EXPECT_GT(o.bestIoU, o.startIoU + 0.1);
  EXPECT_NEAR(o.placement.scale, 1, 0.05);
  EXPECT_POINT_NEAR(o.placement.Apply(Point3(0, 0, 0)), Point3(0, 0, 0), 0.04);
}

} // namespace
} // namespace eulermap
