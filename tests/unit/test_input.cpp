// What comes in: input.h's checks and repairs and Options::Validate, each asserted on
// what the pipeline then does: a clean Error naming the problem, or a map measured as
// sound (the memory budget: test_memory).
#include "core/input.h"
#include "core/pipeline.h"
#include "core/topology.h"
#include "tests/support/meshes.h"
#include "tests/support/shapes.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/append.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// Runs the map and returns the Error's message ("" when it succeeds).
std::string MapError(const Mesh &source, const Mesh &target, const Options &options = Options(),
                     const std::vector<AnchorPair> &anchors = {}, Result *out = nullptr) {
  Result result;
  try {
    ComputeMap(source, target, anchors, options, out ? *out : result);
  } catch (const Error &e) {
    return e.what();
  }
  return "";
}

Options Small() {
  Options o;
  o.gridResolution = 32;
  o.steps = 12;
  return o;
}

// Every face its own three vertices, as an STL file stores a mesh.
void MakeSoup(const Mesh &from, Mesh &soup) {
  for (const Face &f : from.face) {
    auto v = vcg::tri::Allocator<Mesh>::AddVertices(soup, 3);
    for (int c = 0; c < 3; ++c) v[c].P() = f.cP(c);
    vcg::tri::Allocator<Mesh>::AddFace(soup, &*v, &*v + 1, &*v + 2);
  }
}

double SignedVolume(const Mesh &m) {
  double v = 0;
  for (const Face &f : m.face) v += f.cP(0).dot(f.cP(1) ^ f.cP(2)) / 6;
  return v;
}

bool Says(const std::vector<std::string> &notes, const std::string &part) {
  for (const std::string &n : notes)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

// A closed sphere whose face (a, b, c) is split at m on its edge a b into (a, m, c) and
// (m, b, c), with the face (a, b, m) of zero area closing it: a corner on the opposite edge
// where m lies inside a b, corners at one place where m lies at a.
void AddFlatFace(Mesh &m, double along) {
  std::size_t corner[3];
  for (int c = 0; c < 3; ++c) corner[c] = vcg::tri::Index(m, m.face[0].cV(c));
  vcg::tri::Allocator<Mesh>::DeleteFace(m, m.face[0]);
  vcg::tri::Allocator<Mesh>::AddVertices(m, 1);  // may move the vertices: pointers taken after it
  Vertex *a = &m.vert[corner[0]], *b = &m.vert[corner[1]], *c = &m.vert[corner[2]], *mid = &m.vert.back();
  mid->P() = a->cP() + (b->cP() - a->cP()) * along;
  vcg::tri::Allocator<Mesh>::AddFace(m, a, mid, c);
  vcg::tri::Allocator<Mesh>::AddFace(m, mid, b, c);
  vcg::tri::Allocator<Mesh>::AddFace(m, a, b, mid);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
}

} // namespace

TEST(Input, CleanMeshIsLeftAsItIs) {
  Mesh m, copy;
  MakeSphere(m, Point3(0, 0, 0), 1, 3);
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, m);
  std::vector<std::string> notes;
  PrepareMesh(copy, "source", notes);
  EXPECT_TRUE(notes.empty());
  ASSERT_EQ(copy.vert.size(), m.vert.size());
  for (std::size_t n = 0; n < m.vert.size(); ++n) EXPECT_EQ(copy.vert[n].cP(), m.vert[n].cP());
}

TEST(Input, RepeatedIndexAndZeroAreaFacesAreRemoved) {
  Mesh m;
  MakeSphere(m, Point3(0, 0, 0), 1, 3);
  const int faces = m.fn;
  Vertex *v0 = &m.vert[0], *v1 = &m.vert[1];
  auto repeated = vcg::tri::Allocator<Mesh>::AddFaces(m, 1);  // "3 0 0 1" (AddFace asserts distinct vertices)
  repeated->V(0) = v0, repeated->V(1) = v0, repeated->V(2) = v1;
  const Point3 middle = (v0->cP() + v1->cP()) / 2;
  auto extra = vcg::tri::Allocator<Mesh>::AddVertices(m, 1);  // on the segment v0 v1: a needle
  extra->P() = middle;
  vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[0], &m.vert[1], &*extra);
  std::vector<std::string> notes;
  PrepareMesh(m, "source", notes);
  EXPECT_EQ(m.fn, faces);
  EXPECT_TRUE(Says(notes, "1 faces that repeat a vertex removed")) << notes.size();
  EXPECT_TRUE(Says(notes, "1 faces of zero area removed (with 1 vertices only they used)"));
  // The map of such a mesh is the map of the clean one.
  Mesh target;
  MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.3, 0.8, 0.9), 4);
  Result result;
  EXPECT_EQ(MapError(m, target, Small(), {}, &result), "");
  EXPECT_GE(result.report.quality.coverage, 0.97);
  Mesh clean;
  MakeSphere(clean, Point3(0, 0, 0), 1, 3);
  Result cleanResult;
  EXPECT_EQ(MapError(clean, target, Small(), {}, &cleanResult), "");
  EXPECT_EQ(result.report.cutFaces, cleanResult.report.cutFaces);
  EXPECT_EQ(result.report.morphMode, cleanResult.report.morphMode);
}

TEST(Input, ZeroAreaFacesInAClosedSurfaceAreMendedNotRemoved) {
  // Removing the face of zero area would leave a hole (a boundary loop): the map would then
  // need a cut with one loop more, and the surface would not be the one the user gave.
  for (const double along : {0.37, 1e-9}) {
    Mesh m;
    MakeSphere(m, Point3(0, 0, 0), 1, 3);
    AddFlatFace(m, along);
    Mesh soup;
    MakeSoup(m, soup);
    for (Mesh *mesh : {&m, &soup}) {
      std::vector<std::string> notes;
      PrepareMesh(*mesh, "source", notes);
      const Topology t = MeasureTopology(*mesh);
      EXPECT_EQ(t.components, 1) << along;
      EXPECT_EQ(t.boundaryLoops, 0) << along;
      EXPECT_EQ(t.eulerCharacteristic, 2) << along;
      EXPECT_TRUE(Says(notes, along > 0.1 ? "1 faces of zero area mended where the surface closes round them (0 by welding "
                                                "corners at one place, 1 by flipping the edge a corner lies on)"
                                          : "by welding corners at one place, 0 by flipping"))
          << (notes.empty() ? "" : notes.back());
      EXPECT_FALSE(Says(notes, "faces of zero area removed"));
      for (const Face &f : mesh->face) EXPECT_GT(((f.cP(1) - f.cP(0)) ^ (f.cP(2) - f.cP(0))).Norm(), 1e-4);
    }
  }
}

// Marching cubes makes faces of zero area where the surface passes through a grid node: caps
// (a corner on the opposite edge) and needles (two corners at nearly one place; stool3 at 128
// cells has two sharing their short edge, 1.4e-6 long). Every one is mended, none removed.
// One test a grid, so that ctest runs them side by side (minutes under the sanitizers).
class EveryShape : public ::testing::TestWithParam<int> {};

TEST_P(EveryShape, MarchingCubesSurfaceStaysClosed) {
  const int cells = GetParam();
  for (const Shape &shape : Shapes()) {
    Mesh m;
    MakeShape(shape.name, m, cells);
    std::vector<std::string> notes;
    PrepareMesh(m, "source", notes);
    const Topology t = MeasureTopology(m);
    EXPECT_EQ(t.boundaryLoops, 0) << shape.name << " at " << cells;
    EXPECT_EQ(t.components, shape.components) << shape.name << " at " << cells;
    EXPECT_FALSE(Says(notes, "faces of zero area removed")) << shape.name << " at " << cells;
  }
}

INSTANTIATE_TEST_SUITE_P(Input, EveryShape, ::testing::Values(48, 64, 96, 128));

TEST(Input, NonFiniteCoordinatesAreRefusedUnlessNoFaceUsesThem) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 3);
  MakeSphere(target, Point3(0, 0, 0), 1.2, 3);
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mesh m;
    vcg::tri::Append<Mesh, Mesh>::MeshCopy(m, source);
    m.vert[5].P().Y() = bad;
    EXPECT_NE(MapError(m, target, Small()).find("vertices with a NaN or infinite coordinate (the first is vertex 5)"),
              std::string::npos);
    EXPECT_NE(MapError(target, m, Small()).find("the target mesh has 1 vertices with a NaN"), std::string::npos);
  }
  // A stray vertex no face uses (NaN, or 1e6 away) is dropped: it neither stops nor stretches the grid.
  for (double stray : {std::numeric_limits<double>::quiet_NaN(), 1e6}) {
    Mesh m;
    vcg::tri::Append<Mesh, Mesh>::MeshCopy(m, source);
    vcg::tri::Allocator<Mesh>::AddVertices(m, 1)->P() = Point3(stray, 0, 0);
    Result result;
    EXPECT_EQ(MapError(m, target, Small(), {}, &result), "");
    EXPECT_TRUE(Says(result.report.repairs, "source: 1 vertices that no face uses removed"));
    EXPECT_GE(result.report.quality.coverage, 0.97);
    EXPECT_LT(result.report.cellSize, 0.1);
  }
}

TEST(Input, MeshesWithoutSurfaceOrInsideAreRefused) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 3);
  Mesh points;  // vertices only
  for (auto v = vcg::tri::Allocator<Mesh>::AddVertices(points, 3); v != points.vert.end(); ++v) v->P() = Point3(0, 0, 0);
  EXPECT_NE(MapError(points, sphere).find("the source mesh has no faces (3 vertices)"), std::string::npos);
  Mesh collinear;  // every face on a line
  auto v = vcg::tri::Allocator<Mesh>::AddVertices(collinear, 4);
  for (int n = 0; n < 4; ++n) v[n].P() = Point3(n, 2 * n, 0);
  vcg::tri::Allocator<Mesh>::AddFace(collinear, &collinear.vert[0], &collinear.vert[1], &collinear.vert[2]);
  vcg::tri::Allocator<Mesh>::AddFace(collinear, &collinear.vert[1], &collinear.vert[2], &collinear.vert[3]);
  EXPECT_NE(MapError(sphere, collinear).find("every face of the target mesh has zero area"), std::string::npos);
  Mesh point;  // no extent
  auto p = vcg::tri::Allocator<Mesh>::AddVertices(point, 3);
  for (int n = 0; n < 3; ++n) p[n].P() = Point3(1, 2, 3);
  vcg::tri::Allocator<Mesh>::AddFace(point, &*p, &*p + 1, &*p + 2);
  EXPECT_NE(MapError(point, sphere).find("the source mesh has no extent"), std::string::npos);
  Mesh triangle;  // a single open triangle bounds no inside
  auto t = vcg::tri::Allocator<Mesh>::AddVertices(triangle, 3);
  t[0].P() = Point3(0, 0, 0), t[1].P() = Point3(1, 0, 0), t[2].P() = Point3(0, 1, 0);
  vcg::tri::Allocator<Mesh>::AddFace(triangle, &*t, &*t + 1, &*t + 2);
  EXPECT_NE(MapError(triangle, sphere, Small()).find("the source mesh encloses no volume at this grid"),
            std::string::npos);
}

TEST(Input, TriangleSoupIsWeldedAndMapsAsTheWeldedMesh) {
  Mesh source, soup, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 3);
  MakeSoup(source, soup);
  MakeTorus(target, Point3(0, 0, 0), 1.0, 0.4);
  std::vector<std::string> notes;
  Mesh welded;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(welded, soup);
  PrepareMesh(welded, "source", notes);
  EXPECT_EQ(welded.vn, source.vn);
  EXPECT_EQ(welded.fn, source.fn);
  Result fromSoup, fromMesh;
  ASSERT_EQ(MapError(soup, target, Small(), {}, &fromSoup), "");
  ASSERT_EQ(MapError(source, target, Small(), {}, &fromMesh), "");
  const Report &a = fromSoup.report, &b = fromMesh.report;
  EXPECT_EQ(a.cutComponents, b.cutComponents);
  EXPECT_EQ(a.cutBoundaryLoops, b.cutBoundaryLoops);
  EXPECT_EQ(a.cutEulerCharacteristic, b.cutEulerCharacteristic);
  EXPECT_NEAR(a.quality.coverage, b.quality.coverage, 0.01);
}

TEST(Input, InsideOutMeshIsTurned) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 3);
  MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.4, 0.8, 0.9), 4);
  vcg::tri::Clean<Mesh>::FlipMesh(target);
  EXPECT_LT(SignedVolume(target), 0);
  Mesh turned;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(turned, target);
  std::vector<std::string> notes;
  PrepareMesh(turned, "target", notes);
  EXPECT_GT(SignedVolume(turned), 0);
  EXPECT_TRUE(Says(notes, "faces of parts that pointed inward turned outward"));
  Result result;
  ASSERT_EQ(MapError(source, target, Small(), {}, &result), "");
  EXPECT_GE(result.report.quality.coverage, 0.97);
  EXPECT_TRUE(result.report.warnings.empty());
}

TEST(Input, ParametersOutOfRangeAreRefusedByName) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 2);
  MakeSphere(target, Point3(0, 0, 0), 1.2, 2);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  struct Case { void (*set)(Options &, double); double value; const char *says; };
  const Case cases[] = {
      {[](Options &o, double x) { o.steps = int(x); }, 100000, "steps 100000 is out of range"},
      {[](Options &o, double x) { o.steps = int(x); }, 0, "steps 0 is out of range"},
      {[](Options &o, double x) { o.gridResolution = int(x); }, 2, "grid_resolution 2 is out of range"},
      {[](Options &o, double x) { o.alpha = x; }, inf, "alpha inf is out of range"},
      {[](Options &o, double x) { o.alpha = x; }, nan, "alpha nan is out of range"},
      {[](Options &o, double x) { o.alpha = x; }, -1, "alpha -1 is out of range"},
      {[](Options &o, double x) { o.holeRadius = x; }, 1e9, "hole_radius 1e+09 is out of range"},
      {[](Options &o, double x) { o.holeRadius = x; }, inf, "hole_radius inf is out of range"},
  };
  for (const Case &c : cases) {
    Options o;
    c.set(o, c.value);
    EXPECT_NE(MapError(source, target, o).find(c.says), std::string::npos) << c.says;
  }
}

TEST(Input, AnchorsThatCannotBeInterpolatedAreRefused) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 3);
  MakeSphere(target, Point3(0, 0, 0), 1, 3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<AnchorPair> anchors = {{Point3(1, 0, 0), Point3(1, 0, 0), "east"},
                                     {Point3(0, 1, 0), Point3(nan, 1, 0), "north"}};
  EXPECT_NE(MapError(source, target, Small(), anchors).find("anchor 'north' has a NaN or infinite coordinate on the "
                                                           "target"),
            std::string::npos);
  anchors[1] = {Point3(1, 0, 0), Point3(0, 1, 0), "twin"};
  EXPECT_NE(MapError(source, target, Small(), anchors).find("anchors 'east' and 'twin' lie at the same point of the "
                                                           "source"),
            std::string::npos);
}

TEST(Input, MirroredAnchorsEndWithAWarning) {
  Mesh source, target;
  MakeEllipsoid(source, Point3(0, 0, 0), Point3(1.5, 0.8, 0.5), 4);
  MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.5, 0.8, 0.5), 4);
  // Points on the ellipsoid that span space; the target's with x negated: left and right swapped.
  const Point3 dirs[] = {Point3(1, 0.2, 0.1), Point3(-0.3, 1, 0.2), Point3(0.2, -0.4, 1), Point3(0.5, 0.5, -0.7),
                         Point3(-0.8, -0.3, -0.4)};
  std::vector<AnchorPair> anchors;
  for (const Point3 &d : dirs) {
    const Point3 p(d.X() * 1.5, d.Y() * 0.8, d.Z() * 0.5);
    const Point3 on = p / std::sqrt(vcg::SquaredNorm(Point3(p.X() / 1.5, p.Y() / 0.8, p.Z() / 0.5)));
    anchors.push_back({on, Point3(-on.X(), on.Y(), on.Z()), "a" + std::to_string(anchors.size())});
  }
  Result result;
  ASSERT_EQ(MapError(source, target, Small(), anchors, &result), "");
  bool mirrored = false;
  for (const std::string &w : result.report.warnings) mirrored |= w.find("the anchors mirror each other") == 0;
  EXPECT_TRUE(mirrored) << result.report.ToText();
  // The same anchors, not swapped: no such warning.
  for (AnchorPair &a : anchors) a.target = a.source;
  ASSERT_EQ(MapError(source, target, Small(), anchors, &result), "");
  EXPECT_TRUE(result.report.warnings.empty()) << result.report.ToText();
}

TEST(Input, FacesThatDisagreeWithTheirNeighboursAreTurned) {
  Mesh sphere, mixed;
  MakeSphere(sphere, Point3(0, 0, 0), 1, 3);
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(mixed, sphere);
  for (std::size_t n = 0; n < mixed.face.size(); n += 2) std::swap(mixed.face[n].V(1), mixed.face[n].V(2));
  EXPECT_LT(std::abs(SignedVolume(mixed)), 0.5 * SignedVolume(sphere));
  std::vector<std::string> notes;
  PrepareMesh(mixed, "source", notes);
  EXPECT_NEAR(SignedVolume(mixed), SignedVolume(sphere), 1e-9);
  EXPECT_TRUE(Says(notes, "faces turned to agree with their neighbours"));
  Mesh target;
  MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.3, 0.8, 0.9), 4);
  Mesh mixedAgain;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(mixedAgain, sphere);
  for (std::size_t n = 0; n < mixedAgain.face.size(); n += 2)
    std::swap(mixedAgain.face[n].V(1), mixedAgain.face[n].V(2));
  Result result;
  ASSERT_EQ(MapError(mixedAgain, target, Small(), {}, &result), "");
  EXPECT_GE(result.report.quality.coverage, 0.97);
}
