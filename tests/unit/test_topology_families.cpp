// Topology change on families of shapes, made here (tests/support/shapes.h), at
// grids 48, 64, 96 and 128, with the default placement (no anchors: centre-and-scale, and
// where that map fails its own figures the placement that overlaps the insides most,
// overlap.h; the source is never made to enclose the target): genus up and down, parts merging and splitting,
// furniture with thin parts both ways. Every case asserts
//   - the cut source's components, boundary loops and Euler characteristic are what a
//     continuous map onto the target needs (topology.h, NeededCut; Report::CutAsNeeded),
//     and what the events surgery acted on predict (each disc pair or band adds 2 loops);
//   - coverage of the target >= 97%, flipped area <= 1% after untangling (and its figure
//     before untangling is reported), longest mapped edge <= 5% of the target's diagonal.
// Each case prints one `family |` line with its figures (the closing note's table). Every
// pair of kPairs runs at every grid (76 cases; the README gives the suite's time), kFurtherPairs at 64 (kFurtherFinePairs at 96), kTurnedPairs at 48 and 64,
// kTiltedPairs at 64; a chair mapped onto itself tilted, its images checked against the
// tilt it was made with; and the coffee mug and the doughnut, placed by their handles.
#include "core/topology.h"
#include "tests/support/meshes.h"
#include "tests/support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <tuple>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

struct Pair {
  const char *source, *target;
};

const Pair kPairs[] = {
    {"sphere", "ring1"},   {"sphere", "ring2"},      {"sphere", "ring3"},    {"sphere", "ring4"},
    {"ring1", "sphere"},   {"ring2", "sphere"},      {"ring3", "sphere"},    {"ring2", "ring1"},
    {"ring1", "ring2"},    {"spheres2", "blob2"},    {"spheres3", "blob3"},  {"blob2", "spheres2"},
    {"blob3", "spheres3"}, {"chair", "chair_rails"}, {"chair_rails", "chair"}, {"chair", "chair_slats"},
    {"chair_slats", "chair"}, {"table", "chair"},    {"chair", "table"},
};

// Shapes added later (a stool, a picture frame, a ladder, a dumbbell; then plates with holes,
// a thin ring, a cube with a tunnel, two balls apart and overlapping, an armchair; then an
// open cup, whose inside the morphs must reach through its mouth; then a table with an H of
// stretchers, whose handles' bands must each do what its event does; then a sphere onto a chair
// with a slatted back, whose windows' rims lie on lips facing each other), made to
// try the method on shapes its families were not fixed on, at 64 cells only (the suite's
// time; docs/NOTES.md has them at 48 and 96). The
// pairs among them that still fail are in docs/NOTES.md (`eulermap_bench shapes SOURCE
// TARGET` prints any pair's figures).
const Pair kFurtherPairs[] = {
    {"chair", "stool"},        {"sphere", "frame"},        {"sphere", "ladder"},     {"dumbbell", "ring2"},
    {"sphere", "plate3"},      {"plate3", "sphere"},       {"plate2", "ring1"},      {"ring2", "plate3"},
    {"sphere", "thin_ring"},   {"thin_ring", "sphere"},    {"sphere", "box_tunnel"}, {"box_tunnel", "sphere"},
    {"two_balls", "snowman"},  {"snowman", "two_balls"},   {"chair", "armchair"},    {"armchair", "chair"},
    {"sphere", "cup"},         {"mug", "cup"},             {"cup", "mug"},               {"table_h", "sphere"},
    {"sphere", "chair_slats"},
};

// Further pairs at 96 cells, where a finer grid showed what 64 did not: sphere -> cup tore
// across the handle's hole, a fan of faces from the cup's wall to the handle whose chords sag
// less than a gap's usually do (refine_stretched.h, kLipSag: longest mapped edge 10.6% of
// the target's diagonal before); chair -> armchair failed its longest edge too (6.1% before
// the same change).
const Pair kFurtherFinePairs[] = {{"sphere", "cup"}, {"chair", "armchair"}};

// One mesh turned a quarter about the x axis (shapes.h, `_turned`), as files made with
// another axis up come: the morph carries a handle only where the two meshes' handles
// overlap, so as they are the maps cut handles no target explains (ring1 -> ring1_turned:
// 4 loops where none are needed). Each passes with the target turned back (pipeline.cpp,
// BestPlacement), and the log says so.
const Pair kTurnedPairs[] = {
    {"ring1", "ring1_turned"}, {"ring1_turned", "ring2"}, {"ring2", "mug"}, {"frame_turned", "ring1"},
};

// Turned by other angles (40 degrees about x, then 25 about y): the target turned so that its
// principal axes lie along the source's (placement.h, CandidateTurns), at 64 cells.
const Pair kTiltedPairs[] = {{"ring1", "ring1_tilted"}, {"ring2", "ring2_tilted"}};

constexpr int kMeshCells = 64;  // the marching cubes' resolution of the shapes

class Family : public ::testing::TestWithParam<std::tuple<Pair, int>> {};

TEST_P(Family, CutAsNeededCoveredUnfoldedUnstretched) {
  const auto [pair, cells] = GetParam();
  Mesh source, target;
  MakeShape(pair.source, source, kMeshCells);
  MakeShape(pair.target, target, kMeshCells);
  Options options;  // default placement: centre-and-scale, no anchors
  options.gridResolution = cells;
  Result result;
  const auto start = std::chrono::steady_clock::now();
  ComputeMap(source, target, {}, options, result);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Report &rep = result.report;
  std::printf("%s", rep.ToText().c_str());
  const FamilyFigures f = Figures(pair.source, pair.target, cells, target, result, seconds);
  std::printf("%s", f.line.c_str());
  ASSERT_TRUE(rep.cutPredicted) << rep.cutNotChecked;
  EXPECT_TRUE(rep.CutAsNeeded());
  EXPECT_EQ(rep.cutBoundaryLoops, 2 * (f.discPairs + f.bands));  // as the events acted on predict
  EXPECT_GE(rep.quality.coverage, 0.97);
  EXPECT_LE(rep.quality.flippedAreaShare, 0.01);
  EXPECT_LE(f.longestShare, 0.05);
  const std::string names = std::string(pair.source) + pair.target;
  if (names.find("_turned") != std::string::npos || names.find("_tilted") != std::string::npos)
    EXPECT_NE(rep.placement.find("turned"), std::string::npos) << rep.placement;
}

// A chair, which no turn maps onto itself, onto the same chair tilted: the map must undo the
// tilt, not only land on the surface. Each source point's true partner is the tilt R of it
// (shapes.h, ShapeTurn); the images lie within 0.65% of the diagonal of it on average (1.2%
// at most, 64 cells). A ranking by cuts alone cannot tell up from down where no cut is
// needed: with the turns placed by the axis-aligned boxes the chair was kept turned 131
// degrees, passing the family's figures, its seat on its back.
TEST(Tilted, AChairIsMappedOntoItselfTiltedWithTheTiltUndone) {
  Mesh source, target;
  MakeShape("chair", source, kMeshCells);
  MakeShape("chair_tilted", target, kMeshCells);
  Options options;
  options.gridResolution = 64;
  Result result;
  ComputeMap(source, target, {}, options, result);
  const Report &rep = result.report;
  std::printf("%s", rep.ToText().c_str());
  EXPECT_TRUE(rep.CutAsNeeded());
  EXPECT_NE(rep.placement.find("turned"), std::string::npos) << rep.placement;
  const Eigen::Matrix3d tilt = ShapeTurn("chair_tilted");
  const double diag = target.bbox.Diag();
  double sum = 0, worst = 0;
  ASSERT_EQ(result.cut.vert.size(), result.mapped.vert.size());
  for (std::size_t n = 0; n < result.cut.vert.size(); ++n) {
    const Point3 &p = result.cut.vert[n].cP();
    const Eigen::Vector3d truth = tilt * Eigen::Vector3d(p.X(), p.Y(), p.Z());
    const double e = vcg::Distance(result.mapped.vert[n].cP(), Point3(truth.x(), truth.y(), truth.z())) / diag;
    sum += e, worst = std::max(worst, e);
  }
  const double mean = sum / result.cut.vert.size();
  std::printf("images against the tilt: mean %.2f%%, at most %.2f%% of the diagonal\n", 100 * mean, 100 * worst);
  EXPECT_LE(mean, 0.02);
  EXPECT_LE(worst, 0.05);
}

// The coffee mug and the doughnut, both ways: the textbook pair. At centre-and-scale the
// doughnut's hole lies inside the mug's body and no turn about the centroid moves it onto the
// handle (1/4/-2 where 1/0/0 is needed, at 48, 64 and 96 cells). The target is moved so that
// the hole it gains lies on the handle the source loses, its axes laid each way and scaled
// (pipeline.cpp, BestPlacement): then the morph has no event and nothing is cut. The map
// keeps the source's faces (nothing is cut, so none is split), and with the doughnut placed at
// half size each source edge is twice as long in the doughnut's units: mug -> ring1's longest
// edge is 5.4-5.7% of the diagonal at 48 to 96 cells, mapped 1.55 times its source length
// there (64 cells); what is asserted is that no edge is stretched (mapped more than twice
// its source length: quality.h, LongestStretchedEdge) beyond 5%.
class Moved : public ::testing::TestWithParam<Pair> {};

TEST_P(Moved, TheMugAndTheDoughnutMapWithoutACut) {
  const Pair pair = GetParam();
  Mesh source, target;
  MakeShape(pair.source, source, kMeshCells);
  MakeShape(pair.target, target, kMeshCells);
  Options options;
  options.gridResolution = 64;
  Result result;
  const auto start = std::chrono::steady_clock::now();
  ComputeMap(source, target, {}, options, result);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Report &rep = result.report;
  std::printf("%s%s", rep.ToText().c_str(), Figures(pair.source, pair.target, 64, target, result, seconds).line.c_str());
  EXPECT_EQ(rep.topologyEvents.size(), 0u) << pair.source;
  EXPECT_EQ(rep.cutComponents, 1);
  EXPECT_EQ(rep.cutBoundaryLoops, 0);
  EXPECT_EQ(rep.cutEulerCharacteristic, 0);
  EXPECT_GE(rep.quality.coverage, 0.97);
  EXPECT_LE(rep.quality.flippedAreaShare, 0.01);
  EXPECT_LE(rep.quality.stretchedEdgeShare, 0.05);
  EXPECT_NE(rep.placement.find("lies on the handle the source loses"), std::string::npos) << rep.placement;
}

// A pair's part of a test's name: "mug_to_ring1" (Name adds the grid: "sphere_to_ring2_96").
std::string PairName(const Pair &pair) { return std::string(pair.source) + "_to_" + pair.target; }

INSTANTIATE_TEST_SUITE_P(EitherWay, Moved, ::testing::Values(Pair{"mug", "ring1"}, Pair{"ring1", "mug"}),
                         [](const ::testing::TestParamInfo<Pair> &info) { return PairName(info.param); });

std::string Name(const ::testing::TestParamInfo<std::tuple<Pair, int>> &info) {
  const auto [pair, cells] = info.param;
  return PairName(pair) + "_" + std::to_string(cells);
}

INSTANTIATE_TEST_SUITE_P(Coarse, Family, ::testing::Combine(::testing::ValuesIn(kPairs), ::testing::Values(48, 64)), Name);
INSTANTIATE_TEST_SUITE_P(Fine, Family, ::testing::Combine(::testing::ValuesIn(kPairs), ::testing::Values(96, 128)), Name);
INSTANTIATE_TEST_SUITE_P(Further, Family, ::testing::Combine(::testing::ValuesIn(kFurtherPairs), ::testing::Values(64)), Name);
INSTANTIATE_TEST_SUITE_P(FurtherFine, Family, ::testing::Combine(::testing::ValuesIn(kFurtherFinePairs), ::testing::Values(96)), Name);
INSTANTIATE_TEST_SUITE_P(Turned, Family, ::testing::Combine(::testing::ValuesIn(kTurnedPairs), ::testing::Values(48, 64)), Name);
INSTANTIATE_TEST_SUITE_P(Tilted, Family, ::testing::Combine(::testing::ValuesIn(kTiltedPairs), ::testing::Values(64)), Name);

} // namespace
