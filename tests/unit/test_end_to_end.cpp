// End to end, same topology: the whole pipeline on real and analytic meshes,
// checked by the map's measured quality (report.h, MapQuality).
#include "core/quality.h"
#include "tests/support/meshes.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/append.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// Issue 2's thresholds: on-surface >= 99%, coverage >= 97%, flipped area <= 1%, anchor
// error <= 1 cell. `coverage` and `flipped` may be given lower/higher where a case says why.
void ExpectGoodMap(const Report &r, bool withAnchors, double coverage = 0.97, double flipped = 0.01) {
  std::printf("%s", r.ToText().c_str());
  EXPECT_GE(r.quality.onSurfaceRate, 0.99);
  EXPECT_GE(r.quality.coverage, coverage);
  EXPECT_LE(r.quality.flippedAreaShare, flipped);
  if (withAnchors) EXPECT_LE(r.quality.anchorErrorCells, 1.0);
  // Same topology: nothing is cut.
  EXPECT_EQ(r.cutComponents, 1);
  EXPECT_EQ(r.cutBoundaryLoops, 0);
  EXPECT_EQ(r.cutEulerCharacteristic, 2);
}

} // namespace

TEST(EndToEnd, SphereToEllipsoid) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  MakeEllipsoid(target, Point3(0.2, 0, 0), Point3(1.5, 0.7, 0.9), 5);
  Result result;
  Options options;
  options.align = Align::None;
  ComputeMap(source, target, {}, options, result);
  ExpectGoodMap(result.report, false);
}

TEST(EndToEnd, SphereToCube) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  MakeBox(target, Box3(Point3(-0.8, -0.8, -0.8), Point3(0.8, 0.8, 0.8)), 16);
  Result result;
  Options options;
  options.align = Align::None;
  ComputeMap(source, target, {}, options, result);
  ExpectGoodMap(result.report, false);
}

TEST(EndToEnd, BunnyToSphere) {
  Mesh source, target;
  LoadMesh(DataMesh("bunny.off"), source);
  MakeSphere(target, Point3(3, 1, 0), 0.5, 5);  // elsewhere and larger: centre-and-scale places it
  Result result;
  ComputeMap(source, target, {}, Options(), result);
  ExpectGoodMap(result.report, false);
}

TEST(EndToEnd, SpotToCowWithAnchors) {
  Mesh source, target;
  LoadMesh(DataMesh("spot.obj"), source);
  LoadMesh(DataMesh("cow.off"), target);
  const std::vector<AnchorPair> anchors = ReadAnchorPairs(SampleFile("spot.pp"), SampleFile("cow.pp"));
  ASSERT_GE(anchors.size(), 6u);
  Result result;
  ComputeMap(source, target, anchors, Options(), result);
  // The "tail" pair joins spot's tail to the cow's tail tuft. With the pair at the tail's
  // root instead (96.75% coverage, 1.50% flipped), the morph grows the tuft as a part of its
  // own (a separate component of f(., t) < 0 from t = 0.8 to 0.9) that no source point
  // reaches, even on a 128-cell grid (98.3% coverage, 304 of the 350 uncovered samples on
  // the tail); the report names it as the largest uncovered part (1.35% of the cow).
  ExpectGoodMap(result.report, true);
  // Per anchor: its own figures, the largest of which is the report's anchor error.
  const std::vector<AnchorFigure> &figures = result.report.quality.anchorFigures;
  ASSERT_EQ(figures.size(), anchors.size());
  double worst = 0;
  for (std::size_t n = 0; n < figures.size(); ++n) {
    EXPECT_EQ(figures[n].name, anchors[n].name);
    EXPECT_LT(std::abs(figures[n].targetLevel), 0.5) << figures[n].name;  // spot's and the cow's points lie on the grid's surfaces
    worst = std::max(worst, figures[n].error);
  }
  EXPECT_EQ(worst, result.report.quality.anchorErrorCells);
}

// The coverage samples that the mapped surface leaves are reported as parts: a target of
// two spheres, mapped onto by the first alone, misses the second, as one part at its place.
TEST(EndToEnd, CoverageNamesUncoveredParts) {
  Mesh target, second, mapped;
  MakeSphere(target, Point3(0, 0, 0), 1.0, 4);
  MakeSphere(second, Point3(5, 0, 0), 0.5, 4);
  vcg::tri::Append<Mesh, Mesh>::Mesh(target, second);
  vcg::tri::UpdateBounding<Mesh>::Box(target);
  MakeSphere(mapped, Point3(0, 0, 0), 1.0, 4);
  std::vector<UncoveredPart> parts;
  const double coverage = Coverage(target, mapped, 0.02 * target.bbox.Diag(), &parts);
  EXPECT_NEAR(coverage, 0.8, 0.02);  // the second sphere has 1/5 of the area
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_NEAR(parts[0].share, 0.2, 0.02);
  EXPECT_LE(vcg::Distance(parts[0].centre, Point3(5, 0, 0)), 0.05);
  EXPECT_NEAR(parts[0].radius, 0.5, 0.05);
}

// Anchors on tips the grid cuts short (report.h, AnchorFigure): camelhead onto its bend (the
// benchmark's target) on Table 1 row 4's coarse grid, with 21 farthest-point anchors. Every
// anchor more than a cell off lies on such a tip, the others end within a cell, and the
// report names the far ones. The map fails only its longest edge (about four cells of this
// grid), which anchors read from it do not mend: it is not made again through them
// (pipeline.cpp, ReadingCanMend; two such rounds folded 1.20% of it).
TEST(EndToEnd, AnchorsFarOffLieOnTipsTheGridCutsShort) {
  Mesh source, target;
  LoadMesh(DataMesh("camelhead.off"), source);
  LoadMesh(DataMesh("camelhead.off"), target);
  for (Vertex &v : target.vert) v.P() = Bend(v.P(), source.bbox, 1);
  const std::vector<AnchorPair> anchors = FarthestPointAnchors(source, target, 21);
  Options options;
  options.gridNodes = vcg::Point3i(40, 30, 40);
  Result result;
  ComputeMap(source, target, anchors, options, result);
  const Report &r = result.report;
  const std::string text = r.ToText();
  std::printf("%s", text.c_str());
  EXPECT_GE(r.quality.onSurfaceRate, 0.99);
  EXPECT_GE(r.quality.coverage, 0.97);
  EXPECT_LE(r.quality.flippedAreaShare, 0.01);
  EXPECT_EQ(r.morphsTried.find("read from the map before"), std::string::npos) << r.morphsTried;
  EXPECT_LE(r.quality.ResolvedAnchorErrorCells(), 1.0);
  int far = 0, resolved = 0;
  std::string named;  // the far anchors, as the note lists them
  for (const AnchorFigure &a : r.quality.anchorFigures) {
    resolved += a.Resolved();
    if (a.error <= 1) continue;
    named += (far++ ? ", " : "") + a.name;
    EXPECT_FALSE(a.Resolved()) << a.name << ": " << a.error << " cells off, levels " << a.sourceLevel << ", " << a.targetLevel;
  }
  EXPECT_GE(resolved, 10);  // the check above is about most anchors, not a few
  if (far > 0) EXPECT_NE(text.find((far == 1 ? "note: anchor " : "note: anchors ") + named), std::string::npos);
  std::printf("%d of %zu anchors more than a cell off (%s), %d resolved\n", far, anchors.size(), named.c_str(), resolved);
}

// The same map with 1 and 2 threads: spot -> cow with anchors at 32 cells, and
// sphere -> torus (surgery) at 32 cells. Every image agrees within 1e-6 of the target's
// diagonal, the cut has the same faces, and every figure of the report but the times and
// the peak memory has the same bits (`eulermap map` and map_meshes compare them exactly).
TEST(EndToEnd, OneAndTwoThreadsAgree) {
  for (int pair = 0; pair < 2; ++pair) {
    Mesh source, target;
    std::vector<AnchorPair> anchors;
    if (pair == 0) {
      LoadMesh(SampleFile("spot.ply"), source);
      LoadMesh(SampleFile("cow.off"), target);
      anchors = ReadAnchorPairs(SampleFile("spot.pp"), SampleFile("cow.pp"));
    } else {
      MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
      MakeTorus(target, Point3(0, 0, 0), 1.0, 0.4);
    }
    Result one, two;
    Options options;
    options.gridResolution = 32;
    options.threads = 1;
    ComputeMap(source, target, anchors, options, one);
    options.threads = 2;
    ComputeMap(source, target, anchors, options, two);
    ASSERT_EQ(one.mapped.vn, two.mapped.vn);
    ASSERT_EQ(one.cut.fn, two.cut.fn);
    double worst = 0;
    for (int v = 0; v < one.mapped.vn; ++v)
      worst = std::max(worst, vcg::Distance(one.mapped.vert[v].cP(), two.mapped.vert[v].cP()));
    std::printf("[ figures  ] %s: 1 vs 2 threads, largest image difference %.2e of diagonal %.3g\n",
                pair == 0 ? "spot -> cow" : "sphere -> torus", worst, target.bbox.Diag());
    EXPECT_LE(worst, 1e-6 * target.bbox.Diag());
    for (const Figure &figure : FigureTable())
      if (figure.unit != FigureUnit::Seconds && std::string(figure.name) != "peak_memory_mib")
        EXPECT_EQ(figure.value(one.report), figure.value(two.report)) << figure.name;
  }
}
