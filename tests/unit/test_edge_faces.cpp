// The faces around each edge (edge_faces.h): two around every edge of a closed sphere, one
// along the rim where faces were deleted (deleted faces are left out), the same list for
// (a, b) and (b, a), none for a pair that is no edge, and one key per unordered pair.
#include "core/edge_faces.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <set>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

TEST(EdgeFaces, EveryEdgeOfAClosedSphereHasTwoFacesEitherWayRound) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 2);
  const EdgeFaces edges(sphere);
  for (std::size_t n = 0; n < sphere.face.size(); ++n)
    for (int e = 0; e < 3; ++e) {
      const int a = int(vcg::tri::Index(sphere, sphere.face[n].V(e))), b = int(vcg::tri::Index(sphere, sphere.face[n].V((e + 1) % 3)));
      const std::vector<int> &around = edges.Around(a, b);
      ASSERT_EQ(around.size(), 2u);
      EXPECT_TRUE(around[0] == int(n) || around[1] == int(n));
      EXPECT_EQ(edges.Around(b, a), around);
    }
  EXPECT_TRUE(edges.Around(0, 0).empty());
}

TEST(EdgeFaces, DeletedFacesAreLeftOut) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 2);
  vcg::tri::Allocator<Mesh>::DeleteFace(sphere, sphere.face[0]);
  const EdgeFaces edges(sphere);
  for (int e = 0; e < 3; ++e) {
    const int a = int(vcg::tri::Index(sphere, sphere.face[0].V(e))), b = int(vcg::tri::Index(sphere, sphere.face[0].V((e + 1) % 3)));
    ASSERT_EQ(edges.Around(a, b).size(), 1u);
    EXPECT_NE(edges.Around(a, b)[0], 0);
  }
}

TEST(EdgeFaces, OneKeyPerUnorderedPair) {
  std::set<std::uint64_t> keys;
  for (int a = 0; a < 40; ++a)
    for (int b = a; b < 40; ++b) {
      EXPECT_EQ(EdgeFaces::Key(a, b), EdgeFaces::Key(b, a));
      keys.insert(EdgeFaces::Key(a, b));
    }
  EXPECT_EQ(keys.size(), 40u * 41 / 2);
  EXPECT_NE(EdgeFaces::Key(1, 1 << 20), EdgeFaces::Key(1 << 20, 2));
}

} // namespace
