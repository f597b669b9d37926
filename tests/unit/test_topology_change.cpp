// Topology change: saddle detection (saddle.h) on analytic fields, and the whole
// pipeline between surfaces of different genus or number of components, checked by the
// exact topology of the cut source (DESIGN.md: expected topology after surgery) and by
// the map's measured quality (report.h, MapQuality).
#include "core/closest.h"
#include "core/saddle.h"
#include "core/surgery.h"
#include "core/topology.h"
#include "tests/support/meshes.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// A 16^3-node grid over [-1, 1]^3 and V(x) = A (x - c) on its nodes (trilinear = exact).
VectorField LinearField(const double A[3][3], const Point3 &c) {
  Grid g;
  g.origin = Point3(-1, -1, -1);
  g.h = 2.0 / 15;
  g.dims = vcg::Point3i(16, 16, 16);
  VectorField V(g, Point3(0, 0, 0));
  g.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 d = g.Node(i, j, k) - c;
    for (int r = 0; r < 3; ++r) V.values[n][r] = A[r][0] * d[0] + A[r][1] * d[1] + A[r][2] * d[2];
  });
  return V;
}

// Two meshes as one (components side by side).
void Join(Mesh &m, Mesh &other) {
  vcg::tri::Append<Mesh, Mesh>::Mesh(m, other);
  vcg::tri::UpdateBounding<Mesh>::Box(m);
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFace(m);
}

// A closed surface of revolution around the x axis, radius rho(x) for x in [-L, L]
// (rho(+-L) = 0): rings denser near the poles, outward-oriented.
template <class Profile> void MakeRevolution(Mesh &m, double L, Profile rho, int rings = 96, int around = 48) {
  m.Clear();
  auto v = vcg::tri::Allocator<Mesh>::AddVertices(m, rings * around + 2);
  for (int i = 0; i < rings; ++i) {
    const double x = -L * std::cos(M_PI * (i + 1) / (rings + 1));
    for (int j = 0; j < around; ++j) {
      const double a = 2 * M_PI * j / around;
      m.vert[i * around + j].P() = Point3(x, rho(x) * std::cos(a), rho(x) * std::sin(a));
    }
  }
  const int south = rings * around, north = south + 1;
  m.vert[south].P() = Point3(-L, 0, 0);
  m.vert[north].P() = Point3(L, 0, 0);
  (void)v;
  auto tri = [&](int a, int b, int c) {
    auto f = vcg::tri::Allocator<Mesh>::AddFaces(m, 1);
    f->V(0) = &m.vert[a], f->V(1) = &m.vert[b], f->V(2) = &m.vert[c];
  };
  for (int j = 0; j < around; ++j) {
    const int j1 = (j + 1) % around;
    tri(south, j1, j);
    tri(north, (rings - 1) * around + j, (rings - 1) * around + j1);
    for (int i = 0; i + 1 < rings; ++i) {
      tri(i * around + j, i * around + j1, (i + 1) * around + j1);
      tri(i * around + j, (i + 1) * around + j1, (i + 1) * around + j);
    }
  }
  vcg::tri::UpdateBounding<Mesh>::Box(m);
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFace(m);
}

// Two balls of radius R centred at (+-c, 0, 0) joined by a neck of radius `neck`.
void MakeDumbbell(Mesh &m, double c, double R, double neck) {
  const double L = c + R;
  MakeRevolution(m, L, [=](double x) {
    const double d = std::abs(x) - c;
    const double ball = std::max(R * R - d * d, 0.0);
    const double bump = std::exp(-std::pow(x / (c - R + 0.3), 2) * 4);
    return std::sqrt(ball + neck * neck * bump * (std::abs(x) < L ? 1 : 0));
  });
}

struct Figures {
  Topology topology;
  Result result;
  // The shapes of the cuts made (cut_axis.h: Discs where sheets meet, Band where a neck pinches).
  std::vector<CutShape> CutKinds() const {
    std::vector<CutShape> kinds;
    for (const EventSurgery &s : result.report.surgery)
      if (s.outcome == EventCut::Cut) kinds.push_back(ShapeOf(result.report.topologyEvents[s.event].kind));
    return kinds;
  }
};

void MapBetween(Mesh &source, Mesh &target, int cells, Figures &out, Align align = Align::None) {
  Options options;
  options.align = align;
  options.gridResolution = cells;
  options.fillHoles = true;
  ComputeMap(source, target, {}, options, out.result);
  std::printf("%s", out.result.report.ToText().c_str());
  out.topology = MeasureTopology(out.result.cut);
  std::printf("cut source: genus %d, %d vertices (the source has %d)\n", out.topology.Genus(), out.result.cut.vn, source.vn);
  // The exact events of {f < 0} (zero_set_topology.h) take f(., 0) to f(., 1), and the cut is
  // the one a continuous map needs (topology.h, NeededCut), in every case of this file.
  const Report &r = out.result.report;
  ASSERT_FALSE(r.topologyAlongMorph.empty());
  TopologyChange net;
  for (const TopologyEvent &e : r.topologyEvents) {
    const TopologyChange c = Effect(e.kind);
    net.components += c.components, net.handles += c.handles, net.cavities += c.cavities;
  }
  EXPECT_EQ(net.components, r.topologyAlongMorph.back().components - r.topologyAlongMorph.front().components);
  EXPECT_EQ(net.handles, r.topologyAlongMorph.back().handles - r.topologyAlongMorph.front().handles);
  EXPECT_TRUE(r.cutPredicted);
  EXPECT_TRUE(r.CutAsNeeded()) << "needed " << r.neededComponents << " / " << r.neededBoundaryLoops << " / "
                               << r.neededEulerCharacteristic;
}

// Topology of each connected component of m, largest first.
std::vector<Topology> PerComponent(Mesh &m) {
  vcg::tri::UpdateTopology<Mesh>::FaceFace(m);
  std::vector<std::pair<int, Face *>> pieces;
  vcg::tri::Clean<Mesh>::ConnectedComponents(m, pieces);
  std::sort(pieces.begin(), pieces.end(), [](auto &a, auto &b) { return a.first > b.first; });
  std::vector<Topology> out;
  for (auto &piece : pieces) {
    vcg::tri::UpdateSelection<Mesh>::FaceClear(m);
    piece.second->SetS();
    vcg::tri::UpdateSelection<Mesh>::FaceConnectedFF(m);
    Mesh part;
    vcg::tri::Append<Mesh, Mesh>::Mesh(part, m, true);
    out.push_back(MeasureTopology(part));
  }
  vcg::tri::UpdateSelection<Mesh>::FaceClear(m);
  return out;
}

// Mapped positions (TargetPosition) of the cut source's boundary vertices.
std::vector<Point3> RimImages(Mesh &cut) {
  auto target = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  std::vector<char> seen(cut.vert.size(), 0);
  std::vector<Point3> rim;
  for (Face &f : cut.face)
    for (int e = 0; e < 3; ++e)
      if (!f.IsD() && vcg::face::IsBorder(f, e))
        for (int c : {e, (e + 1) % 3}) {
          const std::size_t v = vcg::tri::Index(cut, f.V(c));
          if (!seen[v]) seen[v] = 1, rim.push_back(target[v]);
        }
  return rim;
}

} // namespace

TEST(SaddleFinder, FindsTheSaddlesOfLinearFields) {
  const Point3 c(0.13, -0.21, 0.07);  // inside a cell, not on a node
  const double one[3][3] = {{1, 0.3, 0}, {0, -1, 0.2}, {0, 0, -0.5}};  // one expanding direction
  const double two[3][3] = {{1, 0, 0}, {0, 0.5, 0}, {0.3, 0, -2}};     // two
  for (auto *A : {one, two}) {
    const std::vector<Saddle> s = FindSaddles(LinearField(A, c));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_LT(vcg::Distance(s[0].position, c), 1e-9);
    EXPECT_EQ(s[0].expandingDirections, A == one ? 1 : 2);
  }
  // A sink, a source and a rotation about a sink are no saddles.
  const double sink[3][3] = {{-1, 0, 0}, {0, -2, 0}, {0, 0, -1}};
  const double source[3][3] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 1}};
  const double spiral[3][3] = {{-0.1, -1, 0}, {1, -0.1, 0}, {0, 0, -1}};
  for (auto *A : {sink, source, spiral}) EXPECT_TRUE(FindSaddles(LinearField(A, c)).empty());
  // Nearly degenerate (a rate 1% of the largest, as along a ring of zeros): no saddle.
  const double ring[3][3] = {{1, 0, 0}, {0, 0.01, 0}, {0, 0, -1}};
  EXPECT_TRUE(FindSaddles(LinearField(ring, c)).empty());
  // A saddle on a grid node (found from its 8 cells) is one saddle.
  const std::vector<Saddle> onNode = FindSaddles(LinearField(one, Point3(-1 + 7 * 2.0 / 15, -1 + 2.0 / 15, -1 + 9 * 2.0 / 15)));
  EXPECT_EQ(onNode.size(), 1u);
}

// f(p) = sum_a curvature[a] (p - c)_a^2 on V's grid: critical at c, f(c) = 0.
ScalarField Quadric(const Grid &g, const Point3 &c, const Point3 &curvature) {
  ScalarField f(g, 0.0);
  g.ForEachNode([&](int i, int j, int k, std::size_t n) {
    const Point3 d = g.Node(i, j, k) - c;
    f.values[n] = curvature[0] * d[0] * d[0] + curvature[1] * d[1] * d[1] + curvature[2] * d[2] * d[2];
  });
  return f;
}

TopologyEvent EventAt(const Grid &g, const vcg::Point3i &node, TopologyEventKind kind) {
  TopologyEvent e;
  e.node = node;
  e.position = g.Node(node[0], node[1], node[2]);
  e.kind = kind;
  return e;
}

// The axis of a cut: the odd-signed principal direction of f's Hessian (one negative
// curvature: two parts meeting or a neck; two: a membrane tearing or a hole closing), or
// the stable manifold of a saddle of V of the matching kind within two cells.
TEST(CutAxis, OddSignedCurvatureOrNearbySaddle) {
  const double A[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  const Grid g = LinearField(A, Point3(0, 0, 0)).grid;
  const vcg::Point3i node(7, 7, 7);
  const TopologyEvent merge = EventAt(g, node, TopologyEventKind::PartsMerged);
  const Point3 x = merge.position;
  EXPECT_NEAR(std::abs(CutAxis(merge, Quadric(g, x, Point3(1, -2, 1)), {}).axis.Y()), 1, 1e-9);
  const TopologyEvent closing = EventAt(g, node, TopologyEventKind::HandleLost);
  const CutDirection d = CutAxis(closing, Quadric(g, x, Point3(-1, -1, 3)), {});
  EXPECT_NEAR(std::abs(d.axis.Z()), 1, 1e-9);
  EXPECT_FALSE(d.fromSaddle);
  Saddle near{x + Point3(g.h, 0, 0), 1, Point3(1, 0, 0)}, wrongKind{x, 2, Point3(0, 1, 0)}, far{x + Point3(3 * g.h, 0, 0), 1, Point3(0, 1, 0)};
  const CutDirection s = CutAxis(closing, Quadric(g, x, Point3(-1, -1, 3)), {wrongKind, far, near});
  EXPECT_TRUE(s.fromSaddle);
  EXPECT_NEAR(s.axis.X(), 1, 1e-9);
  EXPECT_EQ(ShapeOf(TopologyEventKind::HandleGained), CutShape::Discs);
  EXPECT_EQ(ShapeOf(TopologyEventKind::PartSplit), CutShape::Band);
  EXPECT_EQ(ShapeOf(TopologyEventKind::ComponentBorn), CutShape::None);
}

// Events cut by their kind where the tracked surface takes part: two sheets meeting lose a
// disc each, whatever V's saddles say; an event far from every tracked triangle and a birth
// are reported, not cut.
TEST(Surgery, EventsCutByKindWhereTheSurfaceTakesPart) {
  const double A[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  const Grid g = LinearField(A, Point3(0, 0, 0)).grid;  // 16^3 nodes over [-1, 1]^3
  const double cell = g.h;
  Mesh sphere;
  MakeSphere(sphere, g.Node(7, 7, 7), 0.3, 3);  // 2.25 cells from its centre
  std::vector<Point3> points;
  for (const Vertex &v : sphere.vert) points.push_back(v.cP());
  Tracker tracker(points, std::vector<double>(points.size(), 0.0));
  const ScalarField f = Quadric(g, g.Node(7, 7, 7), Point3(-1, -1, 1));  // a membrane through the centre, normal z
  const std::vector<TopologyEvent> events = {EventAt(g, {14, 14, 14}, TopologyEventKind::HandleGained),  // 7 cells away
                                             EventAt(g, {7, 7, 7}, TopologyEventKind::ComponentBorn),
                                             EventAt(g, {7, 7, 7}, TopologyEventKind::HandleGained)};
  Surgery surgery(sphere, cell, cell, events, std::vector<EventCut>(events.size(), EventCut::Planned), false);
  EXPECT_TRUE(surgery.Acts(0));
  surgery.Step(0, {}, f, tracker);
  ASSERT_EQ(surgery.Outcomes().size(), 3u);
  EXPECT_EQ(surgery.Outcomes()[0].outcome, EventCut::AwayFromSurface);
  EXPECT_EQ(surgery.Outcomes()[1].outcome, EventCut::NotACutKind);
  EXPECT_EQ(surgery.Outcomes()[2].outcome, EventCut::Cut);
  EXPECT_FALSE(surgery.Outcomes()[2].axisFromSaddle);
  Mesh cut;
  std::vector<EventSurgery> outcomes;
  surgery.Build(sphere, tracker.Points(), cut, outcomes);
  EXPECT_GT(outcomes[2].facesRemoved, 0);
  EXPECT_GT(outcomes[2].rimLength, 0);
  const Topology t = MeasureTopology(cut);  // both poles along z go: an annulus (sphere -> torus)
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.boundaryLoops, 2);
  EXPECT_EQ(t.eulerCharacteristic, 0);
  for (const Vertex &v : cut.vert)  // the poles went, the equator stayed
    if (!v.IsD()) EXPECT_LT(std::abs(v.cP().Z() - g.Node(7, 7, 7).Z()), 0.29);
}

// A neck pinching: the band of faces crossing the plane normal to the neck goes.
TEST(Surgery, PinchingNeckLosesABand) {
  const double A[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  const Grid g = LinearField(A, Point3(0, 0, 0)).grid;
  Mesh torus;
  MakeTorus(torus, g.Node(7, 7, 7), 0.55, 0.2);
  std::vector<Point3> points;
  for (const Vertex &v : torus.vert) points.push_back(v.cP());
  Tracker tracker(points, std::vector<double>(points.size(), 0.0));
  const vcg::Point3i node(11, 7, 7);  // on the ring, 4 cells from the centre: the neck runs along y
  const ScalarField f = Quadric(g, g.Node(11, 7, 7), Point3(1, -1, 1));
  Surgery surgery(torus, g.h, g.h, {EventAt(g, node, TopologyEventKind::HandleLost)}, {EventCut::Planned}, false);
  surgery.Step(0, {}, f, tracker);
  ASSERT_EQ(surgery.Outcomes()[0].outcome, EventCut::Cut);
  Mesh cut;
  std::vector<EventSurgery> outcomes;
  surgery.Build(torus, tracker.Points(), cut, outcomes);
  const Topology t = MeasureTopology(cut);  // a cylinder
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.boundaryLoops, 2);
  EXPECT_EQ(t.eulerCharacteristic, 0);
}

// Stretched edges are split only where both ends still follow f = 0: a tracked point left
// off its level set (the part of the surface it followed vanished without a cut) is no place
// to refine, since every point put beside it is pulled back onto the far end.
TEST(Surgery, StretchedEdgesAreSplitOnlyWhereTheirEndsKeepTheirLevel) {
  const Grid g = Grid::Enclosing(Box3(Point3(-1, -1, -1), Point3(1, 1, 1)), 40);
  Mesh source;
  MakeSphere(source, Point3(0, 0, 0), 0.1, 2);
  std::vector<Point3> points;
  for (const Vertex &v : source.vert) points.push_back(v.cP() * 6.0);  // stretched 6 times, edges over 2 cells
  for (const double radius : {0.6, 0.75}) {  // f = 0 through the points; 3 cells beyond them
    ScalarField f(g, 0.0);
    for (int k = 0; k < g.dims.Z(); ++k)
      for (int j = 0; j < g.dims.Y(); ++j)
        for (int i = 0; i < g.dims.X(); ++i) f(i, j, k) = g.Node(i, j, k).Norm() - radius;
    Tracker tracker(points, std::vector<double>(points.size(), 0.0));
    Surgery surgery(source, g.h, g.h, {}, {}, true);  // splits stretched edges from the start
    surgery.Step(0, {}, f, tracker);
    Mesh cut;
    std::vector<EventSurgery> outcomes;
    surgery.Build(source, tracker.Points(), cut, outcomes);
    if (radius == 0.6)
      EXPECT_GT(surgery.PointsAdded(), int(source.vert.size()));
    else
      EXPECT_EQ(surgery.PointsAdded(), 0);
  }
}

// Fig. 5: a sphere becomes a torus; two discs go, one from each side of the axis.
TEST(TopologyChange, SphereToTorus) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  const double R = 1.0, r = 0.4;
  MakeTorus(target, Point3(0, 0, 0), R, r);
  Figures f;
  MapBetween(source, target, 48, f);
  const Report &rep = f.result.report;
  EXPECT_EQ(f.topology.components, 1);
  EXPECT_EQ(f.topology.Genus(), 0);
  EXPECT_EQ(f.topology.boundaryLoops, 2);
  EXPECT_EQ(f.topology.eulerCharacteristic, 0);
  EXPECT_EQ(f.CutKinds(), std::vector<CutShape>({CutShape::Discs}));  // two sheets meet on the axis
  for (const Point3 &p : RimImages(f.result.cut)) EXPECT_LT(std::hypot(p.X(), p.Y()), R);
  const Topology filled = MeasureTopology(f.result.filled);  // tri::Hole closes both loops: a sphere
  EXPECT_EQ(filled.boundaryLoops, 0);
  EXPECT_EQ(filled.eulerCharacteristic, 2);
  EXPECT_GE(rep.quality.onSurfaceRate, 0.99);
  EXPECT_GE(rep.quality.coverage, 0.95);
  EXPECT_LE(rep.quality.longestEdgeCells, 3.0);
}

// A torus becomes a sphere: a band around the handle goes, leaving an annulus.
TEST(TopologyChange, TorusToSphere) {
  Mesh source, target;
  MakeTorus(source, Point3(0, 0, 0), 1.0, 0.4);
  MakeSphere(target, Point3(0, 0, 0), 1.2, 4);
  Figures f;
  MapBetween(source, target, 48, f);
  EXPECT_EQ(f.CutKinds(), std::vector<CutShape>({CutShape::Band}));  // the hole closes: a neck pinches
  EXPECT_EQ(f.topology.components, 1);
  EXPECT_EQ(f.topology.Genus(), 0);
  EXPECT_EQ(f.topology.boundaryLoops, 2);
  EXPECT_EQ(f.topology.eulerCharacteristic, 0);
  EXPECT_GE(f.result.report.quality.onSurfaceRate, 0.99);
}

// Two spheres merge into one ellipsoid: each loses one disc.
TEST(TopologyChange, TwoSpheresMerge) {
  Mesh source, other, target;
  MakeSphere(source, Point3(-1, 0, 0), 0.8, 4);
  MakeSphere(other, Point3(1, 0, 0), 0.8, 4);
  Join(source, other);
  MakeEllipsoid(target, Point3(0, 0, 0), Point3(2, 1, 1), 5);
  Figures f;
  MapBetween(source, target, 48, f);
  EXPECT_EQ(f.CutKinds(), std::vector<CutShape>({CutShape::Discs}));
  EXPECT_EQ(f.topology.components, 2);
  EXPECT_EQ(f.topology.Genus(), 0);
  EXPECT_EQ(f.topology.boundaryLoops, 2);
  EXPECT_EQ(f.topology.eulerCharacteristic, 2);
  for (const Topology &part : PerComponent(f.result.cut)) {  // each a disc
    EXPECT_EQ(part.boundaryLoops, 1);
    EXPECT_EQ(part.eulerCharacteristic, 1);
  }
  EXPECT_GE(f.result.report.quality.onSurfaceRate, 0.99);
}

// A dumbbell splits into two spheres: its neck goes, one loop on each side.
TEST(TopologyChange, DumbbellSplits) {
  Mesh source, target, other;
  MakeDumbbell(source, 1.3, 1.0, 0.35);
  MakeSphere(target, Point3(-1.3, 0, 0), 0.95, 4);
  MakeSphere(other, Point3(1.3, 0, 0), 0.95, 4);
  Join(target, other);
  Figures f;
  MapBetween(source, target, 64, f);
  EXPECT_EQ(f.CutKinds(), std::vector<CutShape>({CutShape::Band}));
  EXPECT_EQ(f.topology.components, 2);
  EXPECT_EQ(f.topology.Genus(), 0);
  EXPECT_EQ(f.topology.boundaryLoops, 2);
  EXPECT_EQ(f.topology.eulerCharacteristic, 2);
  for (const Topology &part : PerComponent(f.result.cut)) {  // each a disc
    EXPECT_EQ(part.boundaryLoops, 1);
    EXPECT_EQ(part.eulerCharacteristic, 1);
  }
  EXPECT_GE(f.result.report.quality.onSurfaceRate, 0.99);
}

// rocker-arm.obj (genus 1) becomes a sphere: a band around its handle goes.
TEST(TopologyChange, RockerArmToSphere) {
  Mesh source, target;
  LoadMesh(DataMesh("rocker-arm.obj"), source);
  MakeSphere(target, Point3(0, 0, 0), 1.0, 5);
  Figures f;
  MapBetween(source, target, 64, f, Align::CentreAndScale);
  EXPECT_EQ(f.topology.components, 1);
  EXPECT_EQ(f.topology.Genus(), 0);
  EXPECT_EQ(f.topology.boundaryLoops, 2);
  EXPECT_EQ(f.topology.eulerCharacteristic, 0);
  EXPECT_GE(f.result.report.quality.onSurfaceRate, 0.98);
}

// A sphere around 3holes.off (genus 3) becomes it: two discs per handle.
TEST(TopologyChange, SphereToThreeHoles) {
  Mesh source, target;
  LoadMesh(DataMesh("3holes.off"), target);
  MakeSphere(source, target.bbox.Center(), 0.55 * target.bbox.Diag(), 5);
  Figures f;
  MapBetween(source, target, 64, f);
  EXPECT_EQ(f.topology.components, 1);
  EXPECT_EQ(f.topology.Genus(), 0);
  EXPECT_EQ(f.topology.boundaryLoops, 6);
  EXPECT_EQ(f.topology.eulerCharacteristic, -4);
  EXPECT_GE(f.result.report.quality.onSurfaceRate, 0.98);
}

// Fig. 7: a box of 8 vertices becomes a genus-1 and a genus-2 torus. The box's own
// vertices say little, so dense samples on its faces are mapped with the integral
// formula (Eq. 7, ComputeMap's samples): all must land on the target.
void BoxToTarget(const Box3 &box, Mesh &target, int cells, const char *name) {
  Mesh source;
  MakeBox(source, box, 1);
  ASSERT_EQ(source.vn, 8);
  std::vector<Point3> samples;  // 24 x 24 per face, inside the face
  const int n = 24;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
          Point3 p;
          p[axis] = side ? box.max[axis] : box.min[axis];
          const int a = (axis + 1) % 3, b = (axis + 2) % 3;
          p[a] = box.min[a] + (u + 0.5) / n * box.Dim()[a];
          p[b] = box.min[b] + (v + 0.5) / n * box.Dim()[b];
          samples.push_back(p);
        }
  Options options;
  options.align = Align::None;
  options.gridResolution = cells;
  Result result;
  ComputeMap(source, target, {}, options, result, {}, samples);
  std::printf("%s", result.report.ToText().c_str());
  const ClosestPoint closest(target);
  const double tolerance = 0.005 * target.bbox.Diag();
  double worst = 0;
  int off = 0;
  for (const Point3 &p : result.sampleImages) {
    const double d = closest.Query(p).distance;
    worst = std::max(worst, d);
    off += d > tolerance;
  }
  std::printf("box -> %s: %zu samples, %d farther than 0.5%% of the diagonal (%.4g), farthest %.4g (%.2f%%)\n", name,
              samples.size(), off, tolerance, worst, 100 * worst / target.bbox.Diag());
  EXPECT_EQ(off, 0);
}

TEST(TopologyChange, BoxToGenusOneAndTwo) {
  Mesh torus, doubleTorus;
  MakeTorus(torus, Point3(0, 0, 0), 1.0, 0.4);
  BoxToTarget(torus.bbox, torus, 48, "torus (genus 1)");
  MakeDoubleTorus(doubleTorus);
  ASSERT_EQ(MeasureTopology(doubleTorus).Genus(), 2);
  BoxToTarget(doubleTorus.bbox, doubleTorus, 64, "double torus (genus 2)");
}

// Parts that grow from nothing: a sphere onto three overlapping tori in a row, placed
// by centre-and-scale so the sphere covers only the middle one. The linear blend grows the
// outer tori out of nothing, which no tracked point reaches (72.7% coverage, 16 births). The
// morph grows and withdraws instead (grow_shrink.h): no part is born, the surface grows into
// the outer tori, and each of the 3 handles gained is cut as two discs.
TEST(TopologyChange, PartsThatTheLinearBlendGrowsFromNothingAreGrownInto) {
  Mesh source, target, torus;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  for (double x : {-2.6, 0.0, 2.6}) {
    MakeTorus(torus, Point3(x, 0, 0), 1.0, 0.35);
    Join(target, torus);
    torus.Clear();
  }
  Result result;
  Options options;
  options.gridResolution = 64;
  ComputeMap(source, target, {}, options, result);
  const Report &r = result.report;
  std::printf("%s", r.ToText().c_str());
  EXPECT_EQ(r.morphMode.rfind("grow then withdraw", 0), 0u) << r.morphMode;
  for (const TopologyEvent &e : r.topologyEvents) EXPECT_NE(e.kind, TopologyEventKind::ComponentBorn);
  EXPECT_EQ(r.topologyAlongMorph.back().components, 1);  // the tori overlap: one part of genus 3
  EXPECT_EQ(r.topologyAlongMorph.back().handles, 3);
  EXPECT_GE(r.quality.coverage, 0.97);
  EXPECT_EQ(r.cutComponents, 1);  // sphere -> genus 3: 6 discs
  EXPECT_EQ(r.cutBoundaryLoops, 6);
  EXPECT_EQ(r.cutEulerCharacteristic, -4);
  // The tori overlap (one mesh of 3 parts, one inside set of genus 3): the log says the cut is
  // not checked against the meshes and why.
  EXPECT_NE(r.cutNotChecked.find("is not the target mesh (3 parts of genus 3)"), std::string::npos);
}
