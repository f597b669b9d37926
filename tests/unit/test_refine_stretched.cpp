// The mapped source refined where the map stretches an edge (refine_stretched.h): edges
// whose images run along the target are split onto it; a chord across a gap (a tear) is not.
#include "core/refine_stretched.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

using Handle = Mesh::PerVertexAttributeHandle<Point3>;

double LongestImage(Mesh &cut, Handle &image) {
  double longest = 0;
  for (Face &f : cut.face)
    for (int e = 0; e < 3; ++e) longest = std::max(longest, vcg::Distance(image[f.V(e)], image[f.V1(e)]));
  return longest;
}

TEST(RefineStretched, EdgesStretchedAlongTheTargetAreSplitOntoIt) {
  Mesh cut, target;
  MakeSphere(cut, Point3(0, 0, 0), 1.0, 3);
  MakeSphere(target, Point3(0, 0, 0), 2.0, 5);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  for (Vertex &v : cut.vert) image[v] = v.P() * 2.0;  // the map doubles the sphere
  const double before = LongestImage(cut, image), limit = 0.8 * before;
  const int vertices = cut.vn;
  ClosestPoint onTarget(target);
  const int added = RefineStretched(cut, onTarget, limit);
  EXPECT_GT(added, 0);
  EXPECT_EQ(cut.vn, vertices + added);
  EXPECT_LE(LongestImage(cut, image), limit);
  for (int n = vertices; n < cut.vn; ++n) {
    // the image on the target (the inscribed polyhedron's distance to the sphere: under 1%
    // of its radius), the source point a chord's midpoint, inside the unit sphere
    EXPECT_LT(onTarget.Query(image[n]).distance, 1e-9 + 0.01 * 2.0);
    EXPECT_LT(cut.vert[n].P().Norm(), 1.0);
    EXPECT_GT(cut.vert[n].P().Norm(), 0.95);
  }
}

TEST(RefineStretched, AChordAcrossAGapIsNotSplit) {
  // Source: one quad (a, b, c, d). Target: two squares 1 apart facing each other (the faces
  // of a gap). a and b map onto the lower square 3 apart (stretched along it), c and d onto
  // the upper one: the edges between the squares (b-c, c-a, d-a) are a tear.
  Mesh cut, target;
  vcg::tri::Allocator<Mesh>::AddVertices(cut, 4);
  cut.vert[0].P() = Point3(0, 0, 0), cut.vert[1].P() = Point3(1, 0, 0);
  cut.vert[2].P() = Point3(1, 1, 0), cut.vert[3].P() = Point3(0, 1, 0);
  vcg::tri::Allocator<Mesh>::AddFace(cut, &cut.vert[0], &cut.vert[1], &cut.vert[2]);
  vcg::tri::Allocator<Mesh>::AddFace(cut, &cut.vert[0], &cut.vert[2], &cut.vert[3]);
  for (double z : {0.0, 1.0}) {
    auto v = vcg::tri::Allocator<Mesh>::AddVertices(target, 4);
    v[0].P() = Point3(-5, -5, z), v[1].P() = Point3(5, -5, z), v[2].P() = Point3(5, 5, z), v[3].P() = Point3(-5, 5, z);
    const int up = z > 0 ? 1 : 0;  // the lower square faces up, the upper one down
    vcg::tri::Allocator<Mesh>::AddFace(target, &v[0], &v[1 + up], &v[2 - up]);
    vcg::tri::Allocator<Mesh>::AddFace(target, &v[0], &v[2 + up], &v[3 - up]);
  }
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  image[0] = Point3(0, 0, 0), image[1] = Point3(3, 0, 0), image[2] = Point3(3, 0.1, 1), image[3] = Point3(0, 0.1, 1);
  ClosestPoint onTarget(target);
  const int added = RefineStretched(cut, onTarget, 2.0);
  // a-b and c-d are split once (1.5 long after), each at a point of its own square
  EXPECT_EQ(added, 2);
  for (int n = 4; n < cut.vn; ++n) EXPECT_NEAR(std::abs(image[n].Z() - 0.5), 0.5, 1e-12);
  // the tear keeps its length: c-a, 3.2 long
  EXPECT_GT(LongestImage(cut, image), 3.1);
}

} // namespace
