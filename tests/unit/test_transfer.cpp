// Texture and attribute transfer: coordinates pulled from the target (the
// inverse method), one chart per face, the source's own texture on the mapped layer (the
// forward method), colour and quality through the map, and how much of the target the
// transfer reaches compared with closest-point transfer.
#include "core/charts.h"
#include "core/placement.h"
#include "core/quality.h"
#include "core/transfer.h"
#include "tests/support/meshes.h"

#include <vcg/complex/algorithms/point_sampling.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

// Bound on a UV edge of the cut source (a quarter of the texture): its faces span at most
// about 3 grid cells on the torus, 0.07 in u or v; a face over a seam with coordinates
// from both sides would span close to 1.
constexpr double kUVEdgeBound = 0.25;

// (u, v) of a point on the torus of MakeTorus (centre 0, ring radius R): its ring and
// tube angles / 2 pi, in [0, 1).
vcg::Point2d TorusAngles(const Point3 &p, double R) {
  const double ring = std::atan2(p.Y(), p.X()), rho = std::hypot(p.X(), p.Y());
  const double tube = std::atan2(p.Z(), rho - R);
  auto unit = [](double angle) { return std::fmod(angle / (2 * M_PI) + 1, 1.0); };
  return {unit(ring), unit(tube)};
}

// Distance between two coordinates on the circle [0, 1).
double Circular(double a, double b) {
  const double d = std::fabs(a - b);
  return std::min(d, 1 - d);
}

double LongestUVEdge(const Mesh &m) {
  double longest = 0;
  for (const Face &f : m.face)
    if (!f.IsD())
      for (int c = 0; c < 3; ++c) longest = std::max(longest, vcg::Distance(f.cWT(c).P(), f.cWT((c + 1) % 3).P()));
  return longest;
}

Point3 TargetPosition(Mesh &cut, const Vertex *v) {
  auto position = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(cut, "TargetPosition");
  return position[vcg::tri::Index(cut, v)];
}

// The map of source onto target where they are (no placement), at `cells` cells.
void MapInPlace(Mesh &source, Mesh &target, int cells, Result &result, bool colourAndQuality = false) {
  Options options;
  options.gridResolution = cells;
  options.align = Align::None;
  options.transferColour = options.transferQuality = colourAndQuality;
  ComputeMap(source, target, {}, options, result);
}

// The analytic torus, with both kinds of texture coordinates the target may carry.
class PulledTorusTexCoords : public ::testing::TestWithParam<TexCoordKind> {};

// Fig. 5 with the texture: sphere -> torus whose coordinates are its angles.
TEST_P(PulledTorusTexCoords, EqualTheAnglesOfTheImagesAndNoFaceSpansTwoCharts) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  const double R = 1.0;
  MakeTorus(target, Point3(0, 0, 0), R, 0.4, 64, 32, GetParam());
  ASSERT_EQ(DetectTexCoords(target), GetParam());
  Result result;
  MapInPlace(source, target, 48, result);
  const Report &rep = result.report;
  std::printf("%s", rep.ToText().c_str());
  ASSERT_TRUE(rep.texCoordsPulled);
  EXPECT_EQ(rep.cutBoundaryLoops, 2);  // the map went through surgery: the cut is an annulus

  // Each corner's coordinates against the angles of its vertex's image: away from the
  // seams (both angles farther than 0.1 from 0: no face there reaches over a seam, its UV
  // edges are below 0.06), and everywhere modulo 1, where a corner past a seam continues
  // its face's chart linearly.
  Mesh &cut = result.cut;
  double awayError = 0, anyError = 0;
  int away = 0;
  for (const Face &f : cut.face)
    for (int c = 0; c < 3; ++c) {
      const vcg::Point2d uv = TorusAngles(TargetPosition(cut, f.cV(c)), R), pulled = f.cWT(c).P();
      const double error = std::max(Circular(uv[0], pulled[0]), Circular(uv[1], pulled[1]));
      anyError = std::max(anyError, error);
      if (std::min({uv[0], 1 - uv[0], uv[1], 1 - uv[1]}) > 0.1) {
        awayError = std::max({awayError, std::fabs(uv[0] - pulled[0]), std::fabs(uv[1] - pulled[1])});
        ++away;
      }
    }
  const double longest = LongestUVEdge(cut);
  std::printf("corners away from the seams: %d, largest error %.2e; largest error modulo 1 anywhere %.2e; "
              "longest UV edge %.4f (bound %.2f)\n",
              away, awayError, anyError, longest, kUVEdgeBound);
  EXPECT_GT(away, 3 * cut.fn / 2);
  EXPECT_LE(awayError, 1e-3);
  EXPECT_LE(anyError, 1e-2);
  EXPECT_LE(longest, kUVEdgeBound);
  EXPECT_EQ(rep.texture.find("; 0 faces over"), std::string::npos);  // the chart rule was needed
  EXPECT_EQ(cut.textures, target.textures);
}

INSTANTIATE_TEST_SUITE_P(Transfer, PulledTorusTexCoords,
                         ::testing::Values(TexCoordKind::PerWedge, TexCoordKind::PerVertex),
                         [](const ::testing::TestParamInfo<TexCoordKind> &info) {
                           return info.param == TexCoordKind::PerWedge ? "PerWedge" : "PerVertex";
                         });

// A coordinate that is a linear function of the position on the source.
vcg::Point2d SourceUV(const Point3 &p) { return {0.5 + 0.3 * p.X() - 0.1 * p.Z(), 0.5 + 0.3 * p.Y()}; }

void PaintSourceTexCoords(Mesh &m, const std::string &texture) {
  for (Face &f : m.face)
    for (int c = 0; c < 3; ++c) f.WT(c).P() = SourceUV(f.cP(c));
  m.textures = {texture};
}

// The forward method: the mapped layer carries the source's texture on the target's shape;
// the cut carries the target's.
TEST(Transfer, MappedKeepsTheSourceTextureAndCutTakesTheTargets) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  PaintSourceTexCoords(source, "source.png");
  MakeTorus(target, Point3(0, 0, 0), 1.0, 0.4);
  target.textures = {"torus.png"};
  Result result;
  MapInPlace(source, target, 48, result);
  ASSERT_TRUE(result.report.texCoordsPulled);
  EXPECT_EQ(result.mapped.textures, std::vector<std::string>({"source.png"}));
  EXPECT_EQ(result.cut.textures, std::vector<std::string>({"torus.png"}));
  ASSERT_EQ(result.mapped.fn, result.cut.fn);
  double error = 0;  // mapped face n is cut face n, whose corners lie where they were on the source
  for (std::size_t n = 0; n < result.cut.face.size(); ++n)
    for (int c = 0; c < 3; ++c)
      error = std::max(error, vcg::Distance(result.mapped.face[n].cWT(c).P(), SourceUV(result.cut.face[n].cP(c))));
  EXPECT_LE(error, 1e-9);  // points added by surgery included: midpoints of a linear function
}

// A target without coordinates: nothing pulled, the cut keeps the source's own, a note.
TEST(Transfer, TargetWithoutTexCoordsLeavesTheSourcesOwn) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  PaintSourceTexCoords(source, "source.png");
  MakeEllipsoid(target, Point3(0.2, 0, 0), Point3(1.5, 0.7, 0.9), 4);
  ASSERT_EQ(DetectTexCoords(target), TexCoordKind::None);
  Result result;
  MapInPlace(source, target, 32, result);
  EXPECT_FALSE(result.report.texCoordsPulled);
  EXPECT_NE(result.report.ToText().find("texture: none pulled (the target has no texture coordinates)"),
            std::string::npos);
  EXPECT_EQ(result.cut.textures, std::vector<std::string>({"source.png"}));
  ASSERT_EQ(result.cut.fn, source.fn);  // same topology: no surgery, the same faces
  double error = 0;
  for (std::size_t n = 0; n < source.face.size(); ++n)
    for (int c = 0; c < 3; ++c)
      error = std::max(error, vcg::Distance(result.cut.face[n].cWT(c).P(), source.face[n].cWT(c).P()));
  EXPECT_EQ(error, 0);
}

// Colour and quality of the target, linear in the position, read back at the images.
TEST(Transfer, ColourAndQualityFollowTheMap) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1.0, 4);
  MakeTorus(target, Point3(0, 0, 0), 1.0, 0.4);
  auto red = [](const Point3 &p) { return 127.5 + 90 * p.X(); };
  auto quality = [](const Point3 &p) { return 3 * p.X() + 2 * p.Y() - p.Z(); };
  for (Vertex &v : target.vert) {
    v.C() = vcg::Color4b((unsigned char)std::lround(red(v.cP())), 50, 200, 255);
    v.Q() = quality(v.cP());
  }
  Result result;
  MapInPlace(source, target, 48, result, true);
  Mesh &cut = result.cut;
  double colourError = 0, qualityError = 0;
  for (const Vertex &v : cut.vert) {
    const Point3 p = TargetPosition(cut, &v);
    colourError = std::max({colourError, std::fabs(v.cC()[0] - red(p)), std::fabs(v.cC()[1] - 50.0)});
    qualityError = std::max(qualityError, std::fabs(v.cQ() - quality(p)));
  }
  std::printf("largest colour error %.2f levels, quality error %.2e\n", colourError, qualityError);
  EXPECT_LE(colourError, 1.0);  // rounding of the target's and the cut's 8-bit channels
  EXPECT_LE(qualityError, 1e-9);
}

// Reach of a transfer: the share of the target's area whose colour some source vertex
// takes, i.e. of uniform target samples within 2% of the target's diagonal of a point
// the source's vertices read their colour from.
double Reach(Mesh &target, const std::vector<Point3> &readPoints) {
  std::vector<Point3> samples;
  vcg::tri::TrivialSampler<Mesh> sampler(samples);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>::SamplingRandomGenerator().initialize(6);
  vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>::Montecarlo(target, sampler, 20000);
  const double r2 = std::pow(0.02 * target.bbox.Diag(), 2);
  long reached = 0;
#pragma omp parallel for reduction(+ : reached)
  for (long n = 0; n < long(samples.size()); ++n)
    for (const Point3 &p : readPoints)
      if ((p - samples[n]).SquaredNorm() <= r2) {
        ++reached;
        break;
      }
  return double(reached) / samples.size();
}

// Eulerian transfer against closest-point transfer (MeshLab's Vertex Attribute Transfer:
// each source vertex takes the colour of the nearest target point, the target placed as
// the map places it), on two non-isometric pairs.
struct ReachCase {
  const char *name;
  std::function<void(Mesh &, Mesh &, std::vector<AnchorPair> &)> make;
  double margin;  // how much more of the target the map must reach
};

class ColourReach : public ::testing::TestWithParam<ReachCase> {};

TEST_P(ColourReach, MapReachesMoreOfTheTargetThanClosestPoint) {
  Mesh source, target;
  std::vector<AnchorPair> anchors;
  GetParam().make(source, target, anchors);
  Result result;
  ComputeMap(source, target, anchors, Options(), result);

  std::vector<Point3> a, b, mapped, closest;
  for (const AnchorPair &p : anchors) a.push_back(p.source), b.push_back(p.target);
  const Similarity back = FitPlacement(source, target, b, a, Align::CentreAndScale).Inverse();
  const ClosestPoint index(target);
  for (const Vertex &v : result.mapped.vert) mapped.push_back(v.cP());
  for (const Vertex &v : source.vert) closest.push_back(index.Query(back.Apply(v.cP())).point);
  const double ours = Reach(target, mapped), theirs = Reach(target, closest);
  std::printf("%s: the map's colours come from %.1f%% of the target, closest point's from %.1f%%\n",
              GetParam().name, 100 * ours, 100 * theirs);
  EXPECT_GE(ours, theirs + GetParam().margin);
  EXPECT_GE(ours, 0.9);
}

// Cow -> spot with the samples' anchors at the sample script's grid (samples/cow_to_spot.mlx):
// spot's texture has seams between its charts, and a cut face whose images lie in two charts
// shows one chart's texture continued past its border (the saw-tooth along the cow's neck in
// the README's picture). The faces over a seam, by the share of the mapped area they cover:
// 14.4% before the cut was refined along the seams, 2.8% after (RefineAtSeams).
TEST(Transfer, CowToSpotIsRefinedAlongSpotsSeams) {
  Mesh cow, spot;
  LoadMesh(SampleFile("cow.off"), cow);
  LoadMesh(SampleFile("spot.ply"), spot);
  Options options;
  options.gridResolution = 80;
  Result result;
  ComputeMap(cow, spot, ReadAnchorPairs(SampleFile("cow.pp"), SampleFile("spot.pp")), options, result);
  const std::vector<int> chart = Charts(FindSeams(spot, DetectTexCoords(spot)));
  const ClosestPoint onSpot(spot);
  const Mesh &mapped = result.mapped;  // the cut's faces, vertices at their images
  double over = 0, all = 0;
  for (const Face &f : mapped.face) {
    int charts[3];
    for (int c = 0; c < 3; ++c) charts[c] = chart[onSpot.Query(f.cP(c)).face - &spot.face[0]];
    const double area = vcg::DoubleArea(f) / 2;
    all += area;
    if (charts[0] != charts[1] || charts[1] != charts[2]) over += area;
  }
  std::printf("cow -> spot: %d vertices added along the seams; faces over a seam cover %.2f%% of the mapped area\n",
              result.report.seamSplit, 100 * over / all);
  EXPECT_GT(result.report.seamSplit, 0);
  EXPECT_LT(over / all, 0.04);
  EXPECT_LE(result.report.quality.flippedAreaShare, 0.005);
  EXPECT_EQ(result.report.cutVertices, cow.vn - 1 + result.report.seamSplit) << "one vertex welded, none cut";
}

INSTANTIATE_TEST_SUITE_P(
    Transfer, ColourReach,
    ::testing::Values(
        ReachCase{"sphere -> torus",
                  [](Mesh &s, Mesh &t, std::vector<AnchorPair> &) {
                    MakeSphere(s, Point3(0, 0, 0), 1.0, 5);
                    MakeTorus(t, Point3(0, 0, 0), 1.0, 0.4);
                  },
                  0.1},
        ReachCase{"spot -> cow",
                  [](Mesh &s, Mesh &t, std::vector<AnchorPair> &anchors) {
                    LoadMesh(SampleFile("spot.ply"), s);
                    LoadMesh(SampleFile("cow.off"), t);
                    anchors = ReadAnchorPairs(SampleFile("spot.pp"), SampleFile("cow.pp"));
                  },
                  0.1}),
    [](const ::testing::TestParamInfo<ReachCase> &info) { return info.index == 0 ? "SphereToTorus" : "SpotToCow"; });

} // namespace
