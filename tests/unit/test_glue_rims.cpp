// The two rims of a disc pair brought onto one curve of the target (glue_rims.h): a torus
// with a band of its tube removed (the two rims a disc pair leaves on a neck, 0.4 radians of
// the ring apart) has both rims moved onto the target halfway between them; a place with
// no rims within reach glues nothing.
#include "core/glue_rims.h"
#include "core/topology.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>
#include <vcg/complex/algorithms/clean.h>

#include <cmath>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

using Handle = Mesh::PerVertexAttributeHandle<Point3>;

// A torus (ring 1, tube 0.3) without the faces whose centroid lies within `gap` radians of
// the ring angle 0; images at the vertices' own positions.
void TorusWithBandRemoved(Mesh &cut, double gap) {
  MakeTorus(cut, Point3(0, 0, 0), 1.0, 0.3, 64, 16, TexCoordKind::None);
  for (Face &f : cut.face) {
    const Point3 c = vcg::Barycenter(f);
    if (std::abs(std::atan2(c.Y(), c.X())) < gap) vcg::tri::Allocator<Mesh>::DeleteFace(cut, f);
  }
  vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(cut);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(cut);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  for (Vertex &v : cut.vert) image[v] = v.P();
}

TEST(GlueRims, TheTwoRimsOfAPairMeetHalfwayOnTheTarget) {
  Mesh cut, target;
  TorusWithBandRemoved(cut, 0.2);
  ASSERT_EQ(MeasureTopology(cut).boundaryLoops, 2);
  MakeTorus(target, Point3(0, 0, 0), 1.0, 0.3, 256, 64, TexCoordKind::None);
  const ClosestPoint onTarget(target);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  EXPECT_EQ(GlueRims(cut, onTarget, {Point3(1, 0, 0)}, 0.8), 1);
  const Topology after = MeasureTopology(cut);  // (face-face adjacency for the rims)
  EXPECT_EQ(after.boundaryLoops, 2);  // images move; the cut stays
  int rim = 0;
  for (Face &f : cut.face)
    for (int e = 0; e < 3; ++e)
      if (vcg::face::IsBorder(f, e)) {
        const Point3 &p = image[f.V(e)];
        ++rim;
        EXPECT_LT(std::abs(std::atan2(p.Y(), p.X())), 0.03);  // the rims were 0.2-0.3 radians off 0
        EXPECT_LT(onTarget.Query(p).distance, 1e-9);           // on the target
      }
  EXPECT_GT(rim, 0);
}

TEST(GlueRims, RimsOutOfReachStay) {
  Mesh cut, target;
  TorusWithBandRemoved(cut, 0.2);
  MakeTorus(target, Point3(0, 0, 0), 1.0, 0.3, 256, 64, TexCoordKind::None);
  const ClosestPoint onTarget(target);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  EXPECT_EQ(GlueRims(cut, onTarget, {Point3(-1, 0, 0)}, 0.8), 0);
  for (Vertex &v : cut.vert) EXPECT_EQ(image[v], v.P());
}

} // namespace
