// Unit tests of core/closest.h: the nearest point on a box's faces, edges and corners
// against the exact distance, search limits, deleted faces, concurrent queries and an
// exhaustive search on the bunny, the faces a query may be limited to, and barycentric
// coordinates.
#include "core/closest.h"
#include "tests/support/fields.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>
#include <omp.h>
#include <vcg/simplex/face/distance.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace eulermap {
namespace {

using namespace eulermap::testing;  // the meshes and the box's distance of tests/support

TEST(ClosestPoint, BoxFacesEdgesCornersAndBarycentric) {
  Mesh m;
  const Box3 box(Point3(-1, -1, -1), Point3(1, 1, 1));
  MakeBox(m, box, 2);
  ClosestPoint cp(m);
  const Point3 queries[] = {Point3(0.3, 0.2, 3), Point3(2, 2, 0.1), Point3(3, -3, 3), Point3(0.1, 0.2, 0.3), Point3(0, 0, 0.9)};
  for (const Point3 &p : queries) {
    const ClosestHit hit = cp.Query(p);
    ASSERT_NE(hit.face, nullptr);
    EXPECT_NEAR(hit.distance, std::abs(BoxSignedDistance(box, p)), 1e-12);
    EXPECT_NEAR((hit.point - p).Norm(), hit.distance, 1e-12);
    const Point3 b = hit.barycentric;
    EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-12);
    for (int v = 0; v < 3; ++v) EXPECT_GE(b[v], -1e-9);
    const Point3 back = hit.face->cP(0) * b[0] + hit.face->cP(1) * b[1] + hit.face->cP(2) * b[2];
    EXPECT_NEAR((back - hit.point).Norm(), 0, 1e-12);
  }
  // A search radius smaller than the distance finds nothing; a larger one finds the face.
  EXPECT_EQ(cp.Query(Point3(0, 0, 3), 1.5).face, nullptr);
  EXPECT_NEAR(cp.Query(Point3(0, 0, 3), 2.5).distance, 2, 1e-12);
  // Far away, without a limit.
  EXPECT_NEAR(cp.Query(Point3(0, 0, 100)).distance, 99, 1e-9);

  // Deleted faces are not found; an empty mesh finds nothing.
  const ClosestHit top = cp.Query(Point3(0.5, 0.5, 1.5));
  vcg::tri::Allocator<Mesh>::DeleteFace(m, *const_cast<Face *>(top.face));
  const ClosestPoint withoutFace(m);
  const ClosestHit other = withoutFace.Query(Point3(0.5, 0.5, 1.5));
  ASSERT_NE(other.face, nullptr);
  EXPECT_NE(other.face, top.face);
  Mesh empty;
  EXPECT_EQ(ClosestPoint(empty).Query(Point3(0, 0, 0)).face, nullptr);
}

TEST(ClosestPoint, ConcurrentQueriesMatchSequentialOnes) {
  Mesh m;
  LoadMesh(DataMesh("bunny.off"), m);
  ClosestPoint cp(m);
  std::mt19937 rng(7);
  const Box3 b = m.bbox;
  std::uniform_real_distribution<double> ux(b.min.X() - 0.2 * b.DimX(), b.max.X() + 0.2 * b.DimX());
  std::uniform_real_distribution<double> uy(b.min.Y() - 0.2 * b.DimY(), b.max.Y() + 0.2 * b.DimY());
  std::uniform_real_distribution<double> uz(b.min.Z() - 0.2 * b.DimZ(), b.max.Z() + 0.2 * b.DimZ());
  std::vector<Point3> pts(20000);
  for (auto &p : pts) p = Point3(ux(rng), uy(rng), uz(rng));
  std::uniform_int_distribution<int> uv(0, m.vn - 1);
  std::uniform_real_distribution<double> off(-0.01, 0.01);
  for (std::size_t i = 0; i < pts.size(); i += 2) {  // half of them close to the surface
    const Vertex &v = m.vert[uv(rng)];
    pts[i] = v.cP() + v.cN() * (off(rng) * b.Diag());
  }
  std::vector<ClosestHit> seq(pts.size()), par(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) seq[i] = cp.Query(pts[i]);
#pragma omp parallel for schedule(dynamic, 64)
  for (long i = 0; i < long(pts.size()); ++i) par[i] = cp.Query(pts[i]);
  int mismatches = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (seq[i].face != par[i].face || seq[i].distance != par[i].distance) ++mismatches;
  EXPECT_EQ(mismatches, 0);
  // Check against an exhaustive search over the faces.
  for (std::size_t i = 0; i < 2000; ++i) {
    double best = 1e300;
    for (const Face &f : m.face) {
      double d = 1e300;
      Point3 q;
      vcg::face::PointDistanceBase(f, pts[i], d, q);
      best = std::min(best, d);
    }
    EXPECT_NEAR(seq[i].distance, best, 1e-12);
  }
}

// A query limited to some faces finds the nearest of those: on a sphere, the faces of the
// lower half only, from a point above the north pole, give a point on the equator or below,
// no nearer than any lower face (exhaustive search).
TEST(ClosestPoint, AQueryAmongSomeFacesFindsTheNearestOfThose) {
  Mesh m;
  MakeSphere(m, Point3(0, 0, 0), 1, 3);
  const ClosestPoint cp(m);
  auto lower = [](const Face &f) { return f.cP(0).Z() + f.cP(1).Z() + f.cP(2).Z() < 0; };
  const Point3 p(0.1, 0.2, 1.5);
  const ClosestHit hit = cp.Query(p, lower);
  ASSERT_NE(hit.face, nullptr);
  EXPECT_TRUE(lower(*hit.face));
  EXPECT_LT(hit.point.Z(), 0.1);
  double best = 1e300;
  for (const Face &f : m.face) {
    if (!lower(f)) continue;
    double d = 1e300;
    Point3 q;
    vcg::face::PointDistanceBase(f, p, d, q);
    best = std::min(best, d);
  }
  EXPECT_NEAR(hit.distance, best, 1e-12);
  EXPECT_GT(hit.distance, cp.Query(p).distance + 1);  // farther than the north pole
}

// Barycentric: the weights of the projection onto the triangle's plane, summing to 1;
// outside the triangle one is negative; a degenerate triangle gives its nearest corner.
TEST(ClosestPoint, BarycentricCoordinatesOfTheProjection) {
  const Point3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  const Point3 inside = Barycentric(a, b, c, Point3(0.5, 0.5, 3));
  EXPECT_NEAR(inside[0], 0.5, 1e-12);
  EXPECT_NEAR(inside[1], 0.25, 1e-12);
  EXPECT_NEAR(inside[2], 0.25, 1e-12);
  const Point3 outside = Barycentric(a, b, c, Point3(3, 1, -1));
  EXPECT_NEAR(outside[0] + outside[1] + outside[2], 1, 1e-12);
  EXPECT_LT(outside[0], 0);
  const Point3 back = a * outside[0] + b * outside[1] + c * outside[2];
  EXPECT_LT(vcg::Distance(back, Point3(3, 1, 0)), 1e-12);
  const Point3 degenerate = Barycentric(a, b, Point3(1, 0, 0), Point3(1.9, 0.3, 0));  // on a line
  EXPECT_EQ(degenerate, Point3(0, 1, 0));
}

} // namespace
} // namespace eulermap
