// Untangling (untangle.h): a mapped sphere with a fold, made by hand, comes out unfolded,
// on the target, with the vertices it moved near where they were.
#include "core/quality.h"
#include "core/untangle.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// A unit sphere as target and a copy as its map. Folded: the copy with one vertex pulled
// across a neighbour along the sphere (reflected through it), so that the faces around it
// turn over: a fold as the map leaves one where a thin feature's two sides land on each other.
struct Spheres {
  Mesh target, mapped;
  Spheres() {
    MakeSphere(target, Point3(0, 0, 0), 1, 4);
    MakeSphere(mapped, Point3(0, 0, 0), 1, 4);
  }
};
struct Folded : Spheres {
  Folded() {
    const Face &f = mapped.face[0];
    const Point3 v = f.cP(0), w = f.cP(1);
    mapped.face[0].V(0)->P() = (w * 2 - v).Normalize();
  }
};

double LargestMove(const Mesh &before, const Mesh &after) {
  double largest = 0;
  for (std::size_t n = 0; n < before.vert.size(); ++n)
    largest = std::max(largest, vcg::Distance(before.vert[n].cP(), after.vert[n].cP()));
  return largest;
}

TEST(Untangle, TheHandMadeFoldIsFolded) {
  Folded m;
  const ClosestPoint target(m.target);
  EXPECT_GT(FlippedAreaShare(m.mapped, target), 0);
}

TEST(Untangle, AFoldComesOutUnfolded) {
  Folded m;
  const ClosestPoint target(m.target);
  EXPECT_GT(Untangle(m.mapped, target), 0);
  EXPECT_EQ(FlippedAreaShare(m.mapped, target), 0);
}

TEST(Untangle, MovedVerticesStayOnTheTargetAndNearby) {
  Folded m;
  Mesh before;
  MakeSphere(before, Point3(0, 0, 0), 1, 4);
  const ClosestPoint target(m.target);
  Untangle(m.mapped, target);
  const double edge = LongestEdge(before);
  for (const Vertex &v : m.mapped.vert) EXPECT_LT(target.Query(v.cP()).distance, 1e-9);
  // The folded vertex goes back among its neighbours: within two edges of where it was on
  // the sphere; the others move less than an edge.
  EXPECT_LT(vcg::Distance(m.mapped.vert[vcg::tri::Index(m.mapped, m.mapped.face[0].cV(0))].cP(),
                          before.vert[vcg::tri::Index(before, before.face[0].cV(0))].cP()),
            2 * edge);
  m.mapped.face[0].V(0)->P() = before.face[0].cP(0);
  EXPECT_LT(LargestMove(before, m.mapped), edge);
}

TEST(Untangle, AnUnfoldedMapIsLeftAlone) {
  Spheres m;
  const ClosestPoint target(m.target);
  EXPECT_EQ(Untangle(m.mapped, target), 0);
}

} // namespace
