// The pipeline (pipeline.h) at the level of its stages, through ComputeMap on one small map
// (a sphere onto an ellipsoid elsewhere and larger, grid 24, 8 steps, with samples): the
// stages are reported in order and the share never goes back; a cancel at any stage ends
// the map with "cancelled"; what is refused before any stage; the inputs are left as they
// were; the mapped mesh is the cut moved to its images, which lie on the real target; the
// samples get one image each; the filled copy is made only on request.
#include "core/closest.h"
#include "core/pipeline.h"
#include "tests/support/meshes.h"

#include <vcg/complex/append.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

struct Call {
  double share;
  std::string stage;
};

struct PipelineRun {
  Mesh source, target, sourceBefore, targetBefore;
  std::vector<Point3> samples;
  Result result;
  std::vector<Call> calls;

  Options Small() const {
    Options o;
    o.gridResolution = 24;
    o.steps = 8;
    return o;
  }
  PipelineRun() {
    MakeSphere(source, Point3(0, 0, 0), 1, 3);
    MakeEllipsoid(target, Point3(10, -3, 2), Point3(2.4, 1.6, 1.8), 3);  // centre-and-scale brings it over
    vcg::tri::Append<Mesh, Mesh>::MeshCopy(sourceBefore, source);
    vcg::tri::Append<Mesh, Mesh>::MeshCopy(targetBefore, target);
    for (int n = 0; n < 10; ++n) samples.push_back(Point3(std::cos(n), std::sin(n), 0));  // on the equator
    ComputeMap(source, target, {}, Small(), result, [&](double share, const std::string &stage) {
      calls.push_back({share, stage});
      return true;
    }, samples);
  }
};

PipelineRun &TheRun() {
  static PipelineRun run;
  return run;
}

// The index of the first call of `stage` (or whose name starts with it), -1 if none.
int First(const std::vector<Call> &calls, const std::string &stage) {
  for (std::size_t n = 0; n < calls.size(); ++n)
    if (calls[n].stage.rfind(stage, 0) == 0) return int(n);
  return -1;
}

TEST(Pipeline, TheStagesComeInOrderAndTheShareNeverGoesBack) {
  const std::vector<Call> &calls = TheRun().calls;
  ASSERT_FALSE(calls.empty());
  for (std::size_t n = 1; n < calls.size(); ++n) EXPECT_GE(calls[n].share, calls[n - 1].share) << calls[n].stage;
  EXPECT_EQ(calls.front().share, 0);
  EXPECT_EQ(calls.front().stage, "checking the meshes");
  EXPECT_EQ(calls.back().share, 1);
  EXPECT_EQ(calls.back().stage, "done");
  const std::vector<std::string> order = {"checking the meshes", "signed distance fields", "topology along the morph",
                                          "step 1 of 8", "step 8 of 8", "measuring the map", "done"};
  for (std::size_t n = 0; n < order.size(); ++n) {
    ASSERT_GE(First(calls, order[n]), 0) << order[n];
    if (n) EXPECT_GT(First(calls, order[n]), First(calls, order[n - 1])) << order[n];
  }
}

TEST(Pipeline, ACancelAtAnyStageEndsTheMapWithCancelled) {
  PipelineRun &run = TheRun();
  for (const std::string stage : {"checking the meshes", "signed distance fields", "topology along the morph",
                                  "step 4 of 8", "measuring the map"}) {
    Result result;
    std::string message;
    bool askedLater = false, cancelled = false;
    try {
      ComputeMap(run.source, run.target, {}, run.Small(), result, [&](double, const std::string &name) {
        askedLater |= cancelled;
        cancelled |= name == stage;
        return !cancelled;
      });
    } catch (const Error &e) {
      message = e.what();
    }
    EXPECT_EQ(message, "cancelled") << stage;
    EXPECT_TRUE(cancelled) << stage;
    EXPECT_FALSE(askedLater) << stage << ": the map went on after the cancel";
  }
}

TEST(Pipeline, TheSameMeshAsBothEndsAndNonFiniteSamplesAreRefusedFirst) {
  PipelineRun &run = TheRun();
  Result result;
  int calls = 0;
  const Progress count = [&](double, const std::string &) { return ++calls, true; };
  try {
    ComputeMap(run.source, run.source, {}, run.Small(), result, count);
    ADD_FAILURE() << "the source as its own target was mapped";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("the target mesh is the source mesh"), std::string::npos) << e.what();
  }
  try {
    ComputeMap(run.source, run.target, {}, run.Small(), result, count, {Point3(0, 0, 0), Point3(NAN, 0, 0)});
    ADD_FAILURE() << "a NaN sample was mapped";
  } catch (const Error &e) {
    EXPECT_EQ(std::string(e.what()), "sample point 1 has a NaN or infinite coordinate");
  }
  EXPECT_EQ(calls, 0) << "a stage began before the refusal";
}

TEST(Pipeline, TheInputsAreLeftAsTheyWere) {
  PipelineRun &run = TheRun();
  for (auto [now, before] : {std::pair<Mesh *, Mesh *>{&run.source, &run.sourceBefore}, {&run.target, &run.targetBefore}}) {
    ASSERT_EQ(now->vert.size(), before->vert.size());
    ASSERT_EQ(now->face.size(), before->face.size());
    for (std::size_t n = 0; n < now->vert.size(); ++n) EXPECT_EQ(now->vert[n].P(), before->vert[n].P());
  }
}

TEST(Pipeline, TheMappedMeshIsTheCutAtItsImages) {
  Result &r = TheRun().result;
  ASSERT_GT(r.cut.fn, 0);
  EXPECT_EQ(r.mapped.vn, r.cut.vn);
  EXPECT_EQ(r.mapped.fn, r.cut.fn);
  auto image = vcg::tri::Allocator<Mesh>::GetPerVertexAttribute<Point3>(r.cut, "TargetPosition");
  for (std::size_t n = 0; n < r.cut.vert.size(); ++n)
    if (!r.cut.vert[n].IsD()) EXPECT_EQ(r.mapped.vert[n].P(), image[n]) << n;
  for (std::size_t f = 0; f < r.cut.face.size(); ++f)
    if (!r.cut.face[f].IsD())
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(vcg::tri::Index(r.mapped, r.mapped.face[f].V(c)), vcg::tri::Index(r.cut, r.cut.face[f].V(c)));
}

// The cut lies on the source where it was (not on the placed target), and its images on the
// real target (not the placed one, which is about 10 away).
TEST(Pipeline, TheCutStaysOnTheSourceAndItsImagesLieOnTheRealTarget) {
  PipelineRun &run = TheRun();
  const ClosestPoint onSource(run.source), onTarget(run.target);
  const double diag = run.target.bbox.Diag();
  double worstCut = 0;
  int off = 0;
  for (const Vertex &v : run.result.cut.vert)
    if (!v.IsD()) worstCut = std::max(worstCut, onSource.Query(v.cP()).distance);
  for (const Vertex &v : run.result.mapped.vert)
    if (!v.IsD()) off += onTarget.Query(v.cP()).distance > 0.005 * diag;
  EXPECT_LT(worstCut, 1e-9 * diag);
  EXPECT_LE(off, run.result.mapped.vn / 100);
}

TEST(Pipeline, EachSampleGetsOneImageNearTheRealTarget) {
  PipelineRun &run = TheRun();
  ASSERT_EQ(run.result.sampleImages.size(), run.samples.size());
  const ClosestPoint onTarget(run.target);
  for (const Point3 &p : run.result.sampleImages) EXPECT_LT(onTarget.Query(p).distance, 0.01 * run.target.bbox.Diag());
}

TEST(Pipeline, TheFilledCopyIsMadeOnlyOnRequest) { EXPECT_EQ(TheRun().result.filled.fn, 0); }

} // namespace
