// Maps between real scans with topological noise (SHREC'16 TOPKIDS, kidXX -> kid00 with
// ground truth; ../shared/data/README.md), through the whole pipeline at the default grid,
// with K farthest-point anchors paired with their true partners (tests/bench/topkids runs
// the whole protocol against the peers). Each test asserts one measured property; the
// bounds are today's figures with a margin (issue 14 states the goals beyond them).
#include "core/pipeline.h"
#include "core/surgery.h"
#include "core/topology.h"
#include "tests/support/correspondence.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>

namespace eulermap {
namespace {

using namespace testing;

struct Map {
  Result result;
  double error = 0;  // mean over 400 sampled source vertices, edge-path distance on kid00 / sqrt(area)
  int sourceVertices = 0, sourceLoops = 0;
};

double Area(const Mesh &m) {
  double a = 0;
  for (const Face &f : m.face) a += 0.5 * ((f.cP(1) - f.cP(0)) ^ (f.cP(2) - f.cP(0))).Norm();
  return a;
}

// kidXX -> kid00 with K anchors, computed once per (kid, K) for all the tests.
const Map &Mapped(const std::string &kid, int anchors) {
  static std::map<std::pair<std::string, int>, Map> maps;
  const auto key = std::make_pair(kid, anchors);
  if (auto found = maps.find(key); found != maps.end()) return found->second;
  Mesh source, target;
  LoadMesh(TopkidsFile("kid" + kid + ".off"), source);
  LoadMesh(TopkidsFile("kid00.off"), target);
  const std::vector<int> truth = ReadTruth(TopkidsFile("kid" + kid + "_ref.txt"));
  std::vector<AnchorPair> pairs;
  for (int v : FarthestVertices(source, anchors))
    pairs.push_back({source.vert[v].cP(), target.vert[truth[v]].cP(), "a" + std::to_string(v)});
  Map &map = maps[key];
  ComputeMap(source, target, pairs, Options(), map.result);
  const std::vector<Point3> images = SourceImages(source, map.result);
  // The predicted vertex of kid00: the nearest to the image.
  std::vector<int> from, to;
  for (std::size_t v = 0; v < source.vert.size(); v += source.vert.size() / 400) {
    int nearest = 0;
    for (std::size_t w = 0; w < target.vert.size(); ++w)
      if (vcg::SquaredDistance(target.vert[w].cP(), images[v]) < vcg::SquaredDistance(target.vert[nearest].cP(), images[v]))
        nearest = int(w);
    from.push_back(truth[v]), to.push_back(nearest);
  }
  const std::vector<double> d = EdgePathLengths(target, from, to);
  map.error = std::accumulate(d.begin(), d.end(), 0.0) / d.size() / std::sqrt(Area(target));
  map.sourceVertices = int(source.vert.size());
  map.sourceLoops = MeasureTopology(source).boundaryLoops;
  return map;
}

// More anchors do not make the map worse: kid01 -> kid00, this test's own error (400
// samples, paths along kid00's edges) x 100 with 0 / 8 / 16 anchors 9.55 / 7.20 / 6.40 at
// c003140, and 8 / 16 6.379 / 6.380 once chords round a thin part's rim were split (3daa2b2;
// the eight-anchor map gained most). Eight anchors have gained nothing over none on this
// pair before (sessions 16-28: 9.585 against 9.552), and sixteen now tie with eight, so each
// is held within 1% of the one with fewer anchors (issue 14's goal, anchors never worse).
TEST(Topkids, MoreAnchorsLowerTheError) {
  const double none = Mapped("01", 0).error, eight = Mapped("01", 8).error, sixteen = Mapped("01", 16).error;
  EXPECT_LE(eight, 1.01 * none) << "x 100: " << 100 * eight << " against " << 100 * none;
  EXPECT_LE(sixteen, 1.01 * eight) << "x 100: " << 100 * sixteen << " against " << 100 * eight;
  EXPECT_LT(sixteen, 0.075) << "x 100: " << 100 * sixteen;
}

// Refinement in rounds (pipeline.cpp, AddAnchorsFromMap): kid05's map through 16 anchors is
// made again through those and 128 more read from it, their partners refined by ZoomOut
// (functional_map.h). The first map covers 91.5% (its hands and feet, thinner than two
// cells, are born in the morph), the one through the read anchors 98.1%. By the protocol
// (tests/bench/topkids) error x 100 2.50, coverage 0.979, flipped after untangling 0.33%. The
// report's anchor figures stay the user's 16.
TEST(Topkids, TheMapIsMadeAgainThroughAnchorsReadFromItByZoomOut) {
  const Map &map = Mapped("05", 16);
  const Report &r = map.result.report;
  EXPECT_NE(r.morphsTried.find("(128 of its anchors read from the map before), kept"), std::string::npos) << r.morphsTried;
  EXPECT_EQ(r.quality.anchorFigures.size(), 16u);
  EXPECT_GE(r.quality.coverage, 0.97);
  EXPECT_LE(r.quality.flippedAreaShare, 0.005);
  EXPECT_LT(map.error, 0.04) << "x 100: " << 100 * map.error;
}

class TopkidsPair : public ::testing::TestWithParam<const char *> {};

// Coverage of kid00 with 16 anchors: 93.3% (kid01), 93.2% (kid03).
TEST_P(TopkidsPair, CoverageWithSixteenAnchors) {
  EXPECT_GE(Mapped(GetParam(), 16).result.report.quality.coverage, 0.91);
}

// Flipped area after untangling with 16 anchors: 0.69% (kid01), 2.31% (kid03); as tracked
// 41% and 29% (the goal of 2% is far).
TEST_P(TopkidsPair, FewFlipsAfterUntangling) {
  EXPECT_LE(Mapped(GetParam(), 16).result.report.quality.flippedAreaShare, 0.03);
}

// Surgery does not perforate: each event cut opens at most two boundary loops (a disc on
// each sheet, or a band's two rims).
TEST_P(TopkidsPair, SurgeryOpensAtMostTwoLoopsAnEvent) {
  const Map &map = Mapped(GetParam(), 16);
  const Report &r = map.result.report;
  EXPECT_LE(r.cutBoundaryLoops, map.sourceLoops + 2 * r.HolesCut()) << r.HolesCut() << " events cut";
}

// The points added are counted and bounded: surgery's within its budget (surgery.h), those
// split where the untangled map stretched (refine_stretched.h, at most one a vertex and a
// round by design) under a sixth of the source's vertices. With 16 anchors, kid01: 26851 and
// 874 for 8608 vertices (surgery spends most of its budget where the scan's folds stretch the
// tracked surface).
TEST_P(TopkidsPair, AddedPointsAreCountedAndBounded) {
  const Map &map = Mapped(GetParam(), 16);
  const Report &r = map.result.report;
  EXPECT_LE(r.pointsAdded, kAddedPerVertex * map.sourceVertices);
  EXPECT_LE(r.stretchedSplit, map.sourceVertices / 6) << r.stretchedSplit;
  EXPECT_LE(r.cutVertices, map.sourceVertices + r.pointsAdded + r.stretchedSplit)
      << "surgery " << r.pointsAdded << ", stretched " << r.stretchedSplit << ", source " << map.sourceVertices;
}

INSTANTIATE_TEST_SUITE_P(Topkids, TopkidsPair, ::testing::Values("01", "03"));

} // namespace
} // namespace eulermap
