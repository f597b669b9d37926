// Progress and Cancel on big grids (interrupt.h, pipeline.h): the progress callback comes
// between bounded pieces of work (a conjugate-gradient iteration with its V-cycle, a slab
// of a distance sweep), and a callback that says cancel ends the map at the next of them.
// Counted in work, not in seconds: how often the callback comes per iteration and per node.
#include "core/interrupt.h"
#include "core/pipeline.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>
#include <vcg/complex/append.h>

#include <map>
#include <string>
#include <thread>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

constexpr int kNodes = 64;  // per axis: 8 sweeps of 64^3 nodes are 8 times kNodesBetweenPolls

struct Case {
  Mesh source, target;
  Options options;
  Case() {
    MakeSphere(source, Point3(0, 0, 0), 1, 3);
    MakeSphere(target, Point3(0, 0, 0), 1.25, 3);
    options.gridNodes = vcg::Point3i(kNodes, kNodes, kNodes);
    options.steps = 4;
    options.align = Align::None;
  }
};

bool IsStep(const std::string &stage) { return stage.rfind("step ", 0) == 0; }
// Step 2 (step 1 also allocates the solver's arrays, with a call after each).
bool IsSecondStep(const std::string &stage) { return stage.rfind("step 2 ", 0) == 0; }

TEST(Interrupt, ProgressComesBeforeEachSolverIterationAndEverySlabOfASweep) {
  Case c;
  std::map<std::string, int> calls;  // per stage
  Result result;
  ComputeMap(c.source, c.target, {}, c.options, result, [&](double, const std::string &stage) {
    ++calls[stage];
    return true;
  });
  ASSERT_TRUE(result.report.morphsTried.empty()) << "one morph: its steps are the only ones";
  int stepCalls = 0;
  for (const auto &[stage, n] : calls) stepCalls += IsStep(stage) ? n : 0;
  EXPECT_GE(stepCalls, c.options.steps + result.report.solverFigures.totalIterations)
      << "one call at each step and one before each of its iterations";
  // The thread that called ComputeMap sweeps one of the two fields: 8 sweeps of every node,
  // a call after at most kNodesBetweenPolls nodes and one plane.
  const std::size_t nodes = std::size_t(kNodes) * kNodes * kNodes, plane = std::size_t(kNodes) * kNodes;
  EXPECT_GE(std::size_t(calls["signed distance fields"]), 1 + 8 * nodes / (kNodesBetweenPolls + plane));
}

// Cancels at the n-th call of the first stage that `at` accepts; the map must throw Error
// "cancelled" and make no call after that one.
void ExpectCancelledAt(bool (*at)(const std::string &), int n, const Case &c = Case(),
                       const std::vector<AnchorPair> &anchors = {}) {
  int seen = 0, after = 0;
  bool said = false;
  Result result;
  try {
    ComputeMap(c.source, c.target, anchors, c.options, result, [&](double, const std::string &stage) {
      if (said) return ++after, false;
      if (at(stage) && ++seen == n) said = true;
      return !said;
    });
    ADD_FAILURE() << "the map ran to the end";
  } catch (const Error &e) {
    EXPECT_STREQ(e.what(), "cancelled");
  }
  EXPECT_TRUE(said);
  EXPECT_EQ(after, 0) << "calls after the one that said cancel";
}

TEST(Interrupt, CancelInsideAVelocitySolveEndsTheMap) {
  ExpectCancelledAt(IsSecondStep, 5);  // the stage, the assembly, the system, the first V-cycle, the first iteration
}

// A step of a big grid spends seconds before its first iteration (the first step allocates
// and zeroes the solver's arrays, every step assembles its system): calls during the first
// step's allocation, every kNodesBetweenPolls nodes of the assembly (here one plane group: one
// call) and one once the system is assembled.
TEST(Interrupt, ProgressComesWhileAStepAllocatesAndAssembles) {
  Case c;
  int stepCalls = 0;
  Result result;
  ComputeMap(c.source, c.target, {}, c.options, result, [&](double, const std::string &stage) {
    stepCalls += IsStep(stage);
    return true;
  });
  EXPECT_GE(stepCalls, 3 * c.options.steps + 1 + result.report.solverFigures.totalIterations)
      << "per step: the stage, the assembly, the assembled system, each iteration; the allocation once";
}

TEST(Interrupt, CancelWhileAVelocitySystemIsAssembledEndsTheMap) {
  ExpectCancelledAt(IsSecondStep, 2);  // the stage, then the assembly's poll
}

TEST(Interrupt, CancelWhileTheSolverAllocatesEndsTheMap) {
  ExpectCancelledAt(IsStep, 3);  // step 1: the stage, V, then the first of the solver's arrays
}

TEST(Interrupt, CancelInsideTheDistanceSweepsEndsTheMap) {
  // The stage, the distance arrays, the four seeding phases, then the first sweep's poll.
  ExpectCancelledAt([](const std::string &stage) { return stage == "signed distance fields"; }, 7);
}

// A warped map that fails its own figures is made again through anchors read from it
// (pipeline.cpp, AddAnchorsFromMap), whose Laplace-Beltrami bases ask before each Lanczos
// step (functional_map.h). The target has a second part, a small sphere apart from the big
// one, which the warp grows from nothing and no source point reaches: the first map covers
// too little of the target, so the anchors are read (the stage, then the bases' polls).
TEST(Interrupt, CancelWhileAnchorsAreReadEndsTheMap) {
  Case c;
  Mesh apart;
  MakeSphere(apart, Point3(2, 0, 0), 0.4, 3);
  vcg::tri::Append<Mesh, Mesh>::Mesh(c.target, apart);
  std::vector<AnchorPair> anchors;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      Point3 p(0, 0, 0);
      p[axis] = side;
      anchors.push_back({p, p * 1.25, "a" + std::to_string(anchors.size())});
    }
  ExpectCancelledAt([](const std::string &stage) { return stage.find("anchors read from the map before") != std::string::npos; },
                    20, c, anchors);
}

TEST(Interrupt, OnlyTheThreadThatMadeItAsksTheCallbackOthersReadTheAnswer) {
  int asked = 0;
  const Interrupt interrupt([&] { return ++asked < 2; });  // the second answer: cancel
  auto elsewhere = [&] {
    bool stop = false;
    std::thread([&] { stop = interrupt.Stop(); }).join();
    return stop;
  };
  EXPECT_FALSE(elsewhere());
  EXPECT_EQ(asked, 0);
  EXPECT_FALSE(interrupt.Stop());
  EXPECT_TRUE(interrupt.Stop());
  EXPECT_EQ(asked, 2);
  EXPECT_TRUE(elsewhere());
  EXPECT_TRUE(interrupt.Stop()) << "once cancel, always, without asking again";
  EXPECT_EQ(asked, 2);
}

} // namespace
