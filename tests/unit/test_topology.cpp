// Topology of triangle meshes (topology.h): components, boundary loops, Euler characteristic
// and genus of known meshes (sphere, torus, disc, annulus, two spheres), a torus with seams
// measured as the surface it describes, and the cut a continuous map needs.
#include "core/topology.h"
#include "tests/support/meshes.h"

#include <vcg/complex/append.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

void ExpectTopology(const Topology &t, int components, int loops, int chi, int genus) {
  EXPECT_EQ(t.components, components);
  EXPECT_EQ(t.boundaryLoops, loops);
  EXPECT_EQ(t.eulerCharacteristic, chi);
  EXPECT_EQ(t.Genus(), genus);
}

// The faces of m whose centroid satisfies `cut` are deleted.
template <class Cut> void DeleteFaces(Mesh &m, Cut cut) {
  for (Face &f : m.face)
    if (!f.IsD() && cut((f.cP(0) + f.cP(1) + f.cP(2)) / 3)) vcg::tri::Allocator<Mesh>::DeleteFace(m, f);
}

TEST(Topology, ASphereIsOneClosedComponentOfGenusZero) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 3);
  ExpectTopology(MeasureTopology(sphere), 1, 0, 2, 0);
}

TEST(Topology, AClosedTorusHasGenusOne) {
  Mesh torus;
  MakeTorus(torus, Point3(0, 0, 0), 1, 0.3, 32, 16);
  ExpectTopology(MeasureTopology(torus), 1, 0, 0, 1);
}

TEST(Topology, ASphereWithoutItsCapIsADisc) {
  Mesh disc;
  MakeSphere(disc, Point3(0, 0, 0), 1, 3);
  DeleteFaces(disc, [](const Point3 &c) { return c.Z() > 0.5; });
  ExpectTopology(MeasureTopology(disc), 1, 1, 1, 0);
}

TEST(Topology, ASphereWithoutBothCapsIsAnAnnulus) {
  Mesh annulus;
  MakeSphere(annulus, Point3(0, 0, 0), 1, 3);
  DeleteFaces(annulus, [](const Point3 &c) { return std::abs(c.Z()) > 0.5; });
  ExpectTopology(MeasureTopology(annulus), 1, 2, 0, 0);
}

TEST(Topology, TwoSpheresAreTwoComponents) {
  Mesh two, other;
  MakeSphere(two, Point3(-2, 0, 0), 1, 2);
  MakeSphere(other, Point3(2, 0, 0), 1, 2);
  vcg::tri::Append<Mesh, Mesh>::Mesh(two, other);
  ExpectTopology(MeasureTopology(two), 2, 0, 4, 0);
}

// Vertices no face uses are not counted.
TEST(Topology, UnreferencedVerticesAreNotCounted) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 2);
  vcg::tri::Allocator<Mesh>::AddVertices(sphere, 5);
  ExpectTopology(MeasureTopology(sphere), 1, 0, 2, 0);
}

// Per-vertex texture seams double the seam vertices: the mesh is a square (one loop), the
// surface it describes still a torus.
TEST(Topology, ASeamedTorusIsStillATorusAsASurface) {
  Mesh torus;
  MakeTorus(torus, Point3(0, 0, 0), 1, 0.3, 32, 16, TexCoordKind::PerVertex);
  const Topology asMesh = MeasureTopology(torus);
  EXPECT_EQ(asMesh.boundaryLoops, 1);
  EXPECT_EQ(asMesh.eulerCharacteristic, 1);
  ExpectTopology(MeasureSurfaceTopology(torus), 1, 0, 0, 1);
}

// NeededCut (topology.h): two discs per handle gained, a band per handle lost, a disc on each
// of two parts merging, a band around a neck that splits.
TEST(Topology, TheNeededCutFollowsTheChangesOfTheInsideSet) {
  const Topology sphere{1, 0, 2}, torus{1, 0, 0}, twoSpheres{2, 0, 4};
  ExpectTopology(NeededCut(sphere, 0, 0), 1, 0, 2, 0);   // nothing changes
  ExpectTopology(NeededCut(sphere, 0, 1), 1, 2, 0, 0);   // sphere -> torus: an annulus
  ExpectTopology(NeededCut(sphere, 0, 3), 1, 6, -4, 0);  // sphere -> genus 3
  ExpectTopology(NeededCut(torus, 0, -1), 1, 2, 0, 0);   // torus -> sphere: an annulus
  ExpectTopology(NeededCut(twoSpheres, -1, 0), 2, 2, 2, 0);  // merge: two discs
  ExpectTopology(NeededCut(sphere, 1, 0), 2, 2, 2, 0);   // split: two discs
}

} // namespace
