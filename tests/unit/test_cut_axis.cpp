// The shape and axis of a cut (cut_axis.h): the shape from the event's kind alone; the axis
// the odd-signed principal direction of f's Hessian (one negative curvature: two parts
// meeting or a neck; two: a membrane tearing or a hole closing), or the stable manifold of
// a saddle of V of the matching kind within kSaddleCells.
#include "core/cut_axis.h"
#include "tests/support/fields.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

const double kSaddleField[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
const vcg::Point3i kNode(7, 7, 7);

TEST(CutAxis, ShapeFollowsTheEventsKind) {
  EXPECT_EQ(ShapeOf(TopologyEventKind::HandleGained), CutShape::Discs);
  EXPECT_EQ(ShapeOf(TopologyEventKind::PartsMerged), CutShape::Discs);
  EXPECT_EQ(ShapeOf(TopologyEventKind::HandleLost), CutShape::Band);
  EXPECT_EQ(ShapeOf(TopologyEventKind::PartSplit), CutShape::Band);
  EXPECT_EQ(ShapeOf(TopologyEventKind::ComponentBorn), CutShape::None);
}

// Two parts merging: f has one negative curvature (along y here), the axis follows it.
TEST(CutAxis, OneNegativeCurvatureGivesItsDirection) {
  const Grid g = LinearField(kSaddleField, Point3(0, 0, 0)).grid;
  const TopologyEvent merge = EventAt(g, kNode, TopologyEventKind::PartsMerged);
  EXPECT_NEAR(std::abs(CutAxis(merge, Quadric(g, merge.position, Point3(1, -2, 1)), {}).axis.Y()), 1, 1e-9);
}

// A hole closing: two negative curvatures, the axis is the positive one (z here).
TEST(CutAxis, OnePositiveCurvatureGivesItsDirection) {
  const Grid g = LinearField(kSaddleField, Point3(0, 0, 0)).grid;
  const TopologyEvent closing = EventAt(g, kNode, TopologyEventKind::HandleLost);
  const CutDirection d = CutAxis(closing, Quadric(g, closing.position, Point3(-1, -1, 3)), {});
  EXPECT_NEAR(std::abs(d.axis.Z()), 1, 1e-9);
  EXPECT_FALSE(d.fromSaddle);
}

// Of a saddle of the wrong kind, one too far and one of the right kind a cell away, only the
// last orients the cut (its stable direction, x), over the Hessian's z.
TEST(CutAxis, ANearbySaddleOfTheMatchingKindGivesTheAxis) {
  const Grid g = LinearField(kSaddleField, Point3(0, 0, 0)).grid;
  const TopologyEvent closing = EventAt(g, kNode, TopologyEventKind::HandleLost);
  const Point3 x = closing.position;
  const Saddle near{x + Point3(g.h, 0, 0), 1, Point3(1, 0, 0)}, wrongKind{x, 2, Point3(0, 1, 0)},
      far{x + Point3(3 * g.h, 0, 0), 1, Point3(0, 1, 0)};
  const CutDirection s = CutAxis(closing, Quadric(g, x, Point3(-1, -1, 3)), {wrongKind, far, near});
  EXPECT_TRUE(s.fromSaddle);
  EXPECT_NEAR(s.axis.X(), 1, 1e-9);
}

} // namespace
