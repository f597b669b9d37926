// The map's measures (quality.h) on hand-built meshes whose answers are known: points at
// known distances, a sphere with one half turned over, a sphere mapped onto a hemisphere,
// a box, a uniformly scaled copy.
#include "core/quality.h"
#include "tests/support/meshes.h"

#include <vcg/complex/algorithms/update/normal.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// Faces of `m` whose centroid lies above z = 0, and their share of the area.
double UpperAreaShare(const Mesh &m) {
  double upper = 0, total = 0;
  for (const Face &f : m.face) {
    const double area = vcg::DoubleArea(f) / 2;
    total += area;
    if (vcg::Barycenter(f).Z() > 0) upper += area;
  }
  return upper / total;
}

TEST(Quality, OnSurfaceRateCountsThePointsWithinTheTolerance) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 4);
  const ClosestPoint surface(sphere);
  // 30 points on radial lines at distance 0.01 (within 0.02) and 10 at distance 0.05.
  std::vector<Point3> points;
  for (int n = 0; n < 40; ++n) {
    const double angle = 2 * M_PI * n / 40;
    const Point3 direction(std::cos(angle) * 0.6, std::sin(angle) * 0.6, 0.8);
    points.push_back(direction * (n < 30 ? 1.01 : 1.05));
  }
  EXPECT_DOUBLE_EQ(OnSurfaceRate(points, surface, 0.02), 0.75);
}

TEST(Quality, FlippedAreaShareIsTheAreaOfTheFacesTurnedOver) {
  Mesh target, mapped;
  MakeSphere(target, Point3(0, 0, 0), 1, 4);
  MakeSphere(mapped, Point3(0, 0, 0), 1, 4);
  const ClosestPoint index(target);
  EXPECT_EQ(FlippedAreaShare(mapped, index), 0);
  for (Face &f : mapped.face)
    if (vcg::Barycenter(f).Z() > 0) std::swap(f.V(1), f.V(2));
  EXPECT_NEAR(FlippedAreaShare(mapped, index), UpperAreaShare(mapped), 1e-12);
}

TEST(Quality, CoverageOfAHemisphereIsHalfTheSphereAndABand) {
  Mesh target, hemisphere;
  MakeSphere(target, Point3(0, 0, 0), 1, 5);
  MakeSphere(hemisphere, Point3(0, 0, 0), 1, 5);
  for (Face &f : hemisphere.face)
    if (vcg::Barycenter(f).Z() < 0) vcg::tri::Allocator<Mesh>::DeleteFace(hemisphere, f);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(hemisphere);
  // Samples within t of the upper half: z > -t, an area share of (1 + t) / 2 of the sphere.
  const double t = 0.1;
  std::vector<UncoveredPart> uncovered;
  const double coverage = Coverage(target, hemisphere, t, &uncovered);
  EXPECT_NEAR(coverage, (1 + t) / 2, 0.015);  // 20000 samples: a standard error of 0.0035
  ASSERT_EQ(uncovered.size(), 1u) << "the lower cap is one part";
  EXPECT_NEAR(uncovered[0].share, 1 - coverage, 1e-12);
  // The centroid of the cap z < -t of the unit sphere: (0, 0, -(1 + t) / 2).
  EXPECT_NEAR(uncovered[0].centre.Z(), -(1 + t) / 2, 0.02);
  EXPECT_NEAR(std::hypot(uncovered[0].centre.X(), uncovered[0].centre.Y()), 0, 0.02);
}

TEST(Quality, CoverageOfTheTargetItselfIsWhole) {
  Mesh target, copy;
  MakeSphere(target, Point3(0, 0, 0), 1, 4);
  MakeSphere(copy, Point3(0, 0, 0), 1, 4);
  std::vector<UncoveredPart> uncovered;
  EXPECT_EQ(Coverage(target, copy, 0.01, &uncovered), 1);
  EXPECT_TRUE(uncovered.empty());
}

TEST(Quality, LongestEdgeOfABoxIsAFaceDiagonal) {
  Mesh box;
  MakeBox(box, Box3(Point3(0, 0, 0), Point3(1, 2, 3)));
  EXPECT_NEAR(LongestEdge(box), std::hypot(2.0, 3.0), 1e-12);
}

// A box mapped onto itself 3 times as large with the placement's scale 1/3 stretches
// nothing; one corner pulled out stretches the edges at it, and only those count.
TEST(Quality, OnlyEdgesMappedLongerThanTwiceTheirSourceLengthAreStretched) {
  Mesh cut, mapped;
  MakeBox(cut, Box3(Point3(0, 0, 0), Point3(1, 2, 3)));
  MakeBox(mapped, Box3(Point3(0, 0, 0), Point3(3, 6, 9)));
  Point3 at(-1, -1, -1);
  EXPECT_EQ(LongestStretchedEdge(cut, mapped, 1.0 / 3, &at), 0);  // as long as on the source, scaled
  EXPECT_GT(LongestStretchedEdge(cut, mapped, 1, &at), 0);      // 3 times as long, unscaled
  Vertex *corner = &mapped.vert[0];
  const Point3 was = corner->cP();
  corner->P() = was * 4 - Point3(1, 1, 1) * 20;  // far out
  const double stretched = LongestStretchedEdge(cut, mapped, 1.0 / 3, &at);
  EXPECT_NEAR(stretched, LongestEdge(mapped), 1e-12);
  bool atCorner = false;  // the midpoint reported is that of an edge from the corner
  for (const Vertex &v : mapped.vert)
    atCorner |= vcg::Distance((v.cP() + corner->cP()) / 2, at) < 1e-12;
  EXPECT_TRUE(atCorner);
}

TEST(Quality, DistortionOfAUniformlyScaledCopyIsZero) {
  Mesh cut, mapped;
  MakeSphere(cut, Point3(0, 0, 0), 1, 3);
  MakeSphere(mapped, Point3(0, 0, 0), 3, 3);
  EXPECT_NEAR(StoreDistortion(cut, mapped), 0, 1e-9);
  for (const Vertex &v : cut.vert) EXPECT_NEAR(v.cQ(), 0, 1e-9);
}

double Area(const Mesh &m) {
  double area = 0;
  for (const Face &f : m.face) area += vcg::DoubleArea(f) / 2;
  return area;
}

TEST(Quality, DistortionLiesWhereTheAreaChanged) {
  // One vertex pushed outward: the faces around it grow. A vertex none of whose faces moved
  // keeps its area, so its share changes only by the total's growth: its distortion is
  // |log2(total before / total after)| exactly; the pushed vertex's is larger.
  Mesh cut, mapped;
  MakeSphere(cut, Point3(0, 0, 0), 1, 3);
  MakeSphere(mapped, Point3(0, 0, 0), 1, 3);
  mapped.vert[0].P() *= 1.5;
  StoreDistortion(cut, mapped);
  const double far = std::abs(std::log2(Area(cut) / Area(mapped)));
  EXPECT_GT(cut.vert[0].cQ(), 10 * far);
  int count = 0;
  for (const Vertex &v : cut.vert)
    if (vcg::Distance(v.cP(), cut.vert[0].cP()) > 0.8) {
      EXPECT_NEAR(v.cQ(), far, 1e-9);
      ++count;
    }
  EXPECT_GT(count, 300);
}

} // namespace
