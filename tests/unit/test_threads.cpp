// Thread counts per parallel region (threads.h): a ThreadCount sets the team of this
// thread's regions only, a run leaves OpenMP's own setting as it found it, and without a
// count the team is the cores that processes at this one's priority leave idle.
#include "core/pipeline.h"
#include "core/threads.h"
#include "tests/support/busy.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

int TeamSize() {
  int team = 0;
#pragma omp parallel num_threads(Threads())
#pragma omp single
  team = omp_get_num_threads();
  return team;
}

TEST(Threads, ACountSetsTheTeamOfThisThreadsRegionsWhileItLives) {
  const int all = omp_get_max_threads();
  {
    const ThreadCount one(1);
    EXPECT_EQ(Threads(), 1);
    EXPECT_EQ(TeamSize(), 1);
    EXPECT_EQ(omp_get_max_threads(), all) << "OpenMP's own setting is not touched";
  }
  EXPECT_EQ(Threads(), IdleCores());
}

TEST(Threads, ZeroLeavesTheCoresOtherProcessesLeaveIdle) {
  const ThreadCount none(0);
  EXPECT_EQ(Threads(), IdleCores());
  EXPECT_GE(Threads(), 1);
  EXPECT_LE(Threads(), omp_get_max_threads());
}

// IdleCores() over a window of 0.4 s (longer than its own, 0.25 s) beside `count` busy processes.
int IdleBeside(int count, int nice) {
  const BusyProcesses busy(count, nice);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  IdleCores();  // the window starts here
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  return IdleCores();
}

// Processes at this one's priority take cores from the team; niced ones yield theirs to it
// (run alone: RUN_SERIAL in tests/CMakeLists.txt).
TEST(Threads, IdleCoresCountsOnlyProcessesAtThisPriority) {
  const int all = omp_get_max_threads(), busy = std::min(all, 2);
  EXPECT_EQ(IdleBeside(busy, 0), std::max(1, all - busy));
  EXPECT_EQ(IdleBeside(busy, 19), all);
}

TEST(Threads, AMapLeavesOpenMPsSettingAsItFoundIt) {
  Mesh source, target;
  MakeSphere(source, Point3(0, 0, 0), 1, 3);
  MakeEllipsoid(target, Point3(0, 0, 0), Point3(1.3, 0.9, 0.9), 3);
  Options options;
  options.gridResolution = 16;
  options.steps = 4;
  options.threads = 1;
  const int before = omp_get_max_threads();
  Result result;
  ComputeMap(source, target, {}, options, result);
  EXPECT_EQ(result.report.threads, 1);
  EXPECT_EQ(omp_get_max_threads(), before);
}

} // namespace
