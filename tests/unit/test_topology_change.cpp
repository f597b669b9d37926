// Topology change: the whole pipeline between surfaces of different genus or number of
// components, checked by the exact topology of the cut source (DESIGN.md: expected topology
// after surgery) and by the map's measured quality (report.h, MapQuality). Saddles, cut
// axes and surgery on their own: test_saddle, test_cut_axis, test_surgery.
#include "core/closest.h"
#include "core/cut_axis.h"
#include "core/pipeline.h"
#include "core/placement.h"
#include "core/topology.h"
#include "tests/support/meshes.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

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

// A torus onto the same torus standing up (turned a quarter about x, as a file made with
// another axis up comes). As placed, the morph closes the lying torus's hole and opens the
// standing one's: 2 cuts and 4 loops where a continuous map needs none. The pipeline turns
// the target back (pipeline.cpp, BestPlacement: the linear blend's cuts and births ranked over the
// candidate turns of placement.h) and maps it with no cut, and the log says so.
TEST(TopologyChange, ATorusStandingUpIsMappedWithTheTargetTurnedBack) {
  Mesh source, target;
  MakeTorus(source, Point3(0, 0, 0), 1.0, 0.4);
  MakeTorus(target, Point3(0, 0, 0), 1.0, 0.4);
  Similarity stand;
  stand.rotation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  Transform(target, stand);
  Figures f;
  MapBetween(source, target, 32, f, Align::CentreAndScale);
  const Result &result = f.result;
  const Report &r = result.report;
  EXPECT_NE(r.placement.find("turned 90 degrees about the"), std::string::npos) << r.placement;
  EXPECT_EQ(r.placementsTried.rfind("the target as it is (", 0), 0u) << r.placementsTried;
  bool warned = false;
  for (const std::string &w : r.warnings) warned = warned || w.rfind("the target was turned", 0) == 0;
  EXPECT_TRUE(warned);
  EXPECT_EQ(r.cutComponents, 1);  // nothing cut: the torus as it is
  EXPECT_EQ(r.cutBoundaryLoops, 0);
  EXPECT_EQ(r.cutEulerCharacteristic, 0);
  EXPECT_GE(r.quality.coverage, 0.97);
  EXPECT_LE(r.quality.flippedAreaShare, 0.01);
  // The images lie on the target as given (its own frame, standing in the xz plane): |z| spans the ring.
  double most = 0;
  for (const Vertex &v : result.mapped.vert) most = std::max(most, std::abs(v.cP().Z()));
  EXPECT_GT(most, 1.2);
}

} // namespace

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
// outer tori out of nothing, which no tracked point reaches (72.7% coverage, 16 births). Grown
// and withdrawn (grow_shrink.h) no part is born, but the patch that grows into each outer
// torus stretches (6.83% flipped after untangling, an edge of 8.3% of the diagonal); inflated
// and shrunk (inflate_shrink.h), tried next, 0.40% and 4.1%, kept. Each of the 3 handles
// gained is cut as two discs.
TEST(TopologyChange, PartsThatTheLinearBlendGrowsFromNothingAreReached) {
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
  EXPECT_EQ(r.morphsTried.rfind("first grow then withdraw", 0), 0u) << r.morphsTried;
  EXPECT_EQ(r.morphMode.rfind("inflate then shrink", 0), 0u) << r.morphMode;
  for (const TopologyEvent &e : r.topologyEvents) EXPECT_NE(e.kind, TopologyEventKind::ComponentBorn);
  EXPECT_LE(r.quality.flippedAreaShare, 0.01);
  EXPECT_LE(r.quality.longestEdgeShare, 0.05);
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
