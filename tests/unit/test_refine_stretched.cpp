// The mapped source refined where the map stretches an edge (refine_stretched.h): edges
// whose images run along the target are split onto it; a chord across a gap (a tear) is not,
// and a tear that reaches a rim is opened unless that changes the cut's topology.
#include "core/refine_stretched.h"
#include "core/topology.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

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

// A square of the target, its corners in the order that makes its normal face `normal`.
void AddSquare(Mesh &target, const std::array<Point3, 4> &corners, const Point3 &normal) {
  auto v = vcg::tri::Allocator<Mesh>::AddVertices(target, 4);
  for (int c = 0; c < 4; ++c) v[c].P() = corners[c];
  const bool turned = ((corners[1] - corners[0]) ^ (corners[2] - corners[0])) * normal < 0;
  vcg::tri::Allocator<Mesh>::AddFace(target, &v[0], &v[turned ? 2 : 1], &v[turned ? 1 : 2]);
  vcg::tri::Allocator<Mesh>::AddFace(target, &v[0], &v[turned ? 3 : 2], &v[turned ? 2 : 3]);
}

TEST(RefineStretched, AnObliqueChordBetweenFacingLipsIsAGapOneRoundAConcaveCornerIsNot) {
  // From (3, 0, 0) to (0, 0, 1): the midpoint lies 0.5 from the nearest square, 0.16 of the
  // chord's length (under kGapSag). Between a floor facing up and a ceiling facing down (a
  // hole's two sides: the cup's wall and its handle, sphere -> cup at 96 cells) the chord
  // crosses the gap; between a floor and a wall at right angles (a concave corner) it
  // follows the target round the corner.
  const Point3 a(3, 0, 0), b(0, 0, 1);
  Mesh slot, corner;
  AddSquare(slot, {Point3(-5, -5, 0), Point3(5, -5, 0), Point3(5, 5, 0), Point3(-5, 5, 0)}, Point3(0, 0, 1));
  AddSquare(slot, {Point3(-5, -5, 1), Point3(5, -5, 1), Point3(5, 5, 1), Point3(-5, 5, 1)}, Point3(0, 0, -1));
  AddSquare(corner, {Point3(0, -5, 0), Point3(5, -5, 0), Point3(5, 5, 0), Point3(0, 5, 0)}, Point3(0, 0, 1));
  AddSquare(corner, {Point3(0, -5, 0), Point3(0, 5, 0), Point3(0, 5, 5), Point3(0, -5, 5)}, Point3(1, 0, 0));
  const ClosestPoint acrossSlot(slot), roundCorner(corner);
  EXPECT_LT(acrossSlot.Query((a + b) / 2).distance, kGapSag * vcg::Distance(a, b));
  EXPECT_TRUE(AcrossGap(a, b, acrossSlot));
  EXPECT_TRUE(AcrossGap(b, a, acrossSlot));
  EXPECT_FALSE(AcrossGap(a, b, roundCorner));
  EXPECT_FALSE(AcrossGap(b, a, roundCorner));
}

TEST(RefineStretched, AnEdgeOverAConvexCornerIsSplit) {
  // One face mapped over the edge of a box (top face z = 4 to side face x = 4): its chords
  // run inside the box, 1 below its faces, and the target's normals there are at right angles.
  Mesh cut, target;
  MakeBox(target, Box3(Point3(0, 0, 0), Point3(4, 4, 4)), 4);
  vcg::tri::Allocator<Mesh>::AddVertices(cut, 3);
  cut.vert[0].P() = Point3(0, 0, 0), cut.vert[1].P() = Point3(1, 0, 0), cut.vert[2].P() = Point3(0, 0.2, 0);
  vcg::tri::Allocator<Mesh>::AddFace(cut, &cut.vert[0], &cut.vert[1], &cut.vert[2]);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  image[0] = Point3(2, 2, 4), image[1] = Point3(4, 2, 2), image[2] = Point3(2, 2.5, 4);
  ClosestPoint onTarget(target);
  EXPECT_FALSE(AcrossGap(image[0], image[1], onTarget));
  EXPECT_GT(RefineStretched(cut, onTarget, 2.0), 0);
  for (int n = 3; n < cut.vn; ++n) EXPECT_LT(onTarget.Query(image[n]).distance, 1e-9);
}

TEST(RefineStretched, AnEdgeRoundAThinPlatesRimIsSplitOneThroughItIsNot) {
  // A plate 0.4 thick. One face maps from its top to its bottom beside its rim x = 4: the
  // chord wraps the rim (its midpoint 0.05 inside it), though the target faces opposite
  // ways at its ends (a picture frame's edge, ladder -> frame at 64 cells: 6.3% of the
  // diagonal left unsplit). Another maps from top to bottom in the middle: that chord runs
  // through the plate (its midpoint nearest the top or the bottom, 0.2 inside), the two
  // sides of a thin part, and stays.
  for (const double x : {3.95, 2.0}) {
    Mesh cut, target;
    MakeBox(target, Box3(Point3(0, 0, 0), Point3(4, 4, 0.4)), 8);
    vcg::tri::Allocator<Mesh>::AddVertices(cut, 3);
    cut.vert[0].P() = Point3(0, 0, 0), cut.vert[1].P() = Point3(1, 0, 0), cut.vert[2].P() = Point3(0, 0.1, 0);
    vcg::tri::Allocator<Mesh>::AddFace(cut, &cut.vert[0], &cut.vert[1], &cut.vert[2]);
    Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
    image[0] = Point3(x, 2, 0.4), image[1] = Point3(x, 2, 0), image[2] = Point3(x, 2.05, 0.4);
    ClosestPoint onTarget(target);
    const int added = RefineStretched(cut, onTarget, 0.3);
    if (x > 3) {
      EXPECT_GT(added, 0);
      EXPECT_LT(LongestImage(cut, image), 0.3);
      for (int n = 3; n < cut.vn; ++n) EXPECT_NEAR(image[n].X(), 4, 1e-9);  // on the rim
    } else {
      EXPECT_EQ(added, 0);
    }
  }
}

// A flat grid of unit squares, (columns + 1) x (rows + 1) vertices, vertex (i, j) = i + j (columns + 1).
void MakeGrid(Mesh &m, int columns, int rows) {
  auto v = vcg::tri::Allocator<Mesh>::AddVertices(m, (columns + 1) * (rows + 1));
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) v[i + j * (columns + 1)].P() = Point3(i, j, 0);
  auto at = [&](int i, int j) { return &m.vert[i + j * (columns + 1)]; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      vcg::tri::Allocator<Mesh>::AddFace(m, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      vcg::tri::Allocator<Mesh>::AddFace(m, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

// The quad (a, b, c, d) as two faces facing (b - a) ^ (c - a).
void AddQuad(Mesh &m, const Point3 &a, const Point3 &b, const Point3 &c, const Point3 &d) {
  auto v = vcg::tri::Allocator<Mesh>::AddVertices(m, 4);
  v[0].P() = a, v[1].P() = b, v[2].P() = c, v[3].P() = d;
  vcg::tri::Allocator<Mesh>::AddFace(m, &v[0], &v[1], &v[2]);
  vcg::tri::Allocator<Mesh>::AddFace(m, &v[0], &v[2], &v[3]);
}

// Source: a `columns` x 2 grid (4 or more). Target: the ground z = 0 (facing up) with a
// trench 5 deep between x = 1 and x = 3, along y from 0 to `trench`; where the trench ends
// (trench 1), the ground bridges it. The grid's bottom row maps onto the ground with x -> 0,
// 0.5, 1, 3, 4, 5, ..., the rows above onto the bridge as they are (or, without one, like
// the bottom row): the faces over the trench are a tear.
struct GapCase {
  Mesh cut, target;
  explicit GapCase(double trench, int columns = 4) {
    MakeGrid(cut, columns, 2);
    Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
    const double gapX[3] = {0, 0.5, 1};
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= columns; ++i)
        image[i + (columns + 1) * j] = Point3(j >= trench || i > 2 ? i : gapX[i], j, 0);
    auto ground = [&](double x0, double y0, double x1, double y1, double z) {
      AddQuad(target, Point3(x0, y0, z), Point3(x1, y0, z), Point3(x1, y1, z), Point3(x0, y1, z));
    };
    ground(0, 0, 1, 2, 0), ground(3, 0, columns, 2, 0), ground(1, 0, 3, trench, -5);
    if (trench < 2) ground(1, trench, 3, 2, 0);
    AddQuad(target, Point3(1, 0, -5), Point3(1, trench, -5), Point3(1, trench, 0), Point3(1, 0, 0));  // facing +x
    AddQuad(target, Point3(3, 0, 0), Point3(3, trench, 0), Point3(3, trench, -5), Point3(3, 0, -5));  // facing -x
    if (trench < 2)  // the trench's end, facing -y
      AddQuad(target, Point3(1, trench, -5), Point3(3, trench, -5), Point3(3, trench, 0), Point3(1, trench, 0));
  }
};

TEST(OpenTears, ATearReachingARimIsOpened) {
  GapCase c(1);
  const Topology before = MeasureTopology(c.cut);
  ClosestPoint onTarget(c.target);
  // Only the bottom edge over the trench (2 long, its midpoint 1 above it) is a tear: the
  // face (2,0) (3,0) (3,1) goes; the hole (here the outer rim) grows, nothing else changes.
  EXPECT_EQ(OpenTears(c.cut, onTarget, 1.5), 1);
  EXPECT_EQ(c.cut.fn, 15);
  const Topology after = MeasureTopology(c.cut);
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.boundaryLoops, before.boundaryLoops);
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  Handle image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(c.cut, "TargetPosition");
  for (Face &f : c.cut.face)  // no tear is left
    for (int e = 0; e < 3; ++e) {
      const double length = vcg::Distance(image[f.V(e)], image[f.V1(e)]);
      EXPECT_TRUE(length <= 1.5 || !AcrossGap(image[f.V(e)], image[f.V1(e)], onTarget));
    }
}

TEST(OpenTears, ATearThatWouldCutOffAPieceStays) {
  GapCase c(2);  // the whole column over the trench tears, from the bottom rim to the top
  ClosestPoint onTarget(c.target);
  EXPECT_EQ(OpenTears(c.cut, onTarget, 1.5), 0);
  EXPECT_EQ(c.cut.fn, 16);
  EXPECT_EQ(MeasureTopology(c.cut).components, 1);
}

// Where the piece the tear would cut off is an island (under kIslandShare of the area: here
// the 2 x 2 squares left of the trench, of 2 x 204), it goes with the tear: the hole grows
// over both and the cut stays one disc with one rim.
TEST(OpenTears, AnIslandATearCutsOffGoesWithIt) {
  GapCase c(2, 204);
  const Topology before = MeasureTopology(c.cut);
  ClosestPoint onTarget(c.target);
  EXPECT_EQ(OpenTears(c.cut, onTarget, 1.5), 4 + 8);  // the column over the trench, the island
  EXPECT_EQ(c.cut.fn, 2 * 204 * 2 - 12);
  const Topology after = MeasureTopology(c.cut);
  EXPECT_EQ(after.components, before.components);
  EXPECT_EQ(after.boundaryLoops, before.boundaryLoops);
  EXPECT_EQ(after.eulerCharacteristic, before.eulerCharacteristic);
  for (const Vertex &v : c.cut.vert)
    if (!v.IsD()) EXPECT_GE(v.cP().X(), 3);  // nothing left of the trench
}

} // namespace
