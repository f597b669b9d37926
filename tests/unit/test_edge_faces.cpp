// The faces around each edge (edge_faces.h): two around every edge of a closed sphere, one
// along the rim where faces were deleted (deleted faces are left out), the same list for
// (a, b) and (b, a), none for a pair that is no edge, every face of a non-manifold edge in the
// order added, edges kept as the table grows and none after Clear, and one key per unordered
// pair.
#include "core/edge_faces.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <set>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

std::vector<int> List(const EdgeFaces::Faces &faces) { return std::vector<int>(faces.begin(), faces.end()); }

TEST(EdgeFaces, EveryEdgeOfAClosedSphereHasTwoFacesEitherWayRound) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 2);
  const EdgeFaces edges(sphere);
  for (std::size_t n = 0; n < sphere.face.size(); ++n)
    for (int e = 0; e < 3; ++e) {
      const int a = int(vcg::tri::Index(sphere, sphere.face[n].V(e))), b = int(vcg::tri::Index(sphere, sphere.face[n].V((e + 1) % 3)));
      const std::vector<int> around = List(edges.Around(a, b));
      ASSERT_EQ(around.size(), 2u);
      EXPECT_TRUE(around[0] == int(n) || around[1] == int(n));
      EXPECT_EQ(List(edges.Around(b, a)), around);
    }
  EXPECT_EQ(edges.Around(0, 0).size(), 0u);
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

TEST(EdgeFaces, ANonManifoldEdgeKeepsEveryFaceInOrderAsTheTableGrows) {
  EdgeFaces edges;  // room for 16 edges: the 3000 below grow it
  for (int f = 0; f < 5; ++f) edges.Add(7, 3, 100 + f);
  for (int n = 0; n < 3000; ++n) edges.Add(n, n + 1, n);
  EXPECT_EQ(List(edges.Around(3, 7)), std::vector<int>({100, 101, 102, 103, 104}));
  for (int n = 0; n < 3000; ++n) {
    ASSERT_EQ(List(edges.Around(n + 1, n)), std::vector<int>({n})) << n;
    ASSERT_EQ(edges.Around(n, n + 2).size(), 0u) << n;
  }
  edges.Clear();
  EXPECT_EQ(edges.Around(3, 7).size(), 0u);
  EXPECT_EQ(edges.Around(10, 11).size(), 0u);
  edges.Add(3, 7, 9);
  EXPECT_EQ(List(edges.Around(7, 3)), std::vector<int>({9}));
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
