// The core's parallel loops (parallel.h) and their team (threads.h): every index once for
// any team, a ThreadCount that sets the team of this thread's loops only, nested loops and
// loops of two host threads at once that run alone, and a piece's exception rethrown.
#include "core/parallel.h"
#include "core/pipeline.h"
#include "core/threads.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace eulermap;
using namespace eulermap::testing;

namespace {

TEST(Parallel, EveryIndexOnceForAnyTeam) {
  for (const int team : {1, 2, 3, 5, 8})
    for (const long n : {0L, 1L, 2L, 7L, 100L, 10007L}) {
      const ThreadCount count(team);
      std::vector<std::atomic<int>> seen(n);
      std::atomic<long> pieces{0};
      ParallelPieces(n, [&](long begin, long end) {
        EXPECT_LT(begin, end);
        ++pieces;
        for (long i = begin; i < end; ++i) ++seen[i];
      });
      for (long i = 0; i < n; ++i) ASSERT_EQ(seen[i], 1) << "team " << team << ", n " << n << ", index " << i;
      EXPECT_LE(pieces, n);
      std::vector<std::atomic<int>> alone(n);
      ParallelFor(n, [&](long i) { ++alone[i]; }, false);
      for (long i = 0; i < n; ++i) ASSERT_EQ(alone[i], 1);
    }
}

// The threads that work on a loop of `team` pieces, each of which waits (up to 10 s) until
// `team` threads are at the loop: a team of that many, once its threads have cores.
std::set<std::thread::id> ThreadsAtALoop(int team) {
  std::mutex m;
  std::set<std::thread::id> ids;
  ParallelFor(team, [&](long) {
    {
      const std::lock_guard<std::mutex> lock(m);
      ids.insert(std::this_thread::get_id());
    }
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < end) {
      {
        const std::lock_guard<std::mutex> lock(m);
        if (int(ids.size()) == team) return;
      }
      std::this_thread::yield();
    }
  });
  return ids;
}

TEST(Parallel, ACountSetsTheTeamOfThisThreadsLoopsWhileItLives) {
  const int all = omp_get_max_threads();
  {
    const ThreadCount three(3);
    EXPECT_EQ(Threads(), 3);
    EXPECT_EQ(ThreadsAtALoop(3).size(), 3u);
    const ThreadCount one(1);
    EXPECT_EQ(ThreadsAtALoop(1), std::set<std::thread::id>{std::this_thread::get_id()});
  }
  EXPECT_EQ(Threads(), all) << "without a count: OpenMP's default";
  std::thread other([&] { EXPECT_EQ(Threads(), all) << "another thread's loops keep theirs"; });
  const ThreadCount two(2);
  other.join();
}

TEST(Parallel, ALoopInsideALoopRunsOnItsThreadAlone) {
  const ThreadCount two(2);
  std::atomic<int> elsewhere{0};
  ParallelFor(8, [&](long) {
    const std::thread::id outer = std::this_thread::get_id();
    ParallelFor(1000, [&](long) { elsewhere += std::this_thread::get_id() != outer; });
  });
  EXPECT_EQ(elsewhere, 0);
}

TEST(Parallel, ALoopWhileAnotherThreadsLoopHoldsThePoolRunsAlone) {
  const ThreadCount two(2);
  std::atomic<bool> holding{false}, released{false};
  std::thread host([&] {
    const ThreadCount mine(2);
    ParallelFor(2, [&](long) {
      holding = true;
      const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (!released && std::chrono::steady_clock::now() < end) std::this_thread::yield();
    });
  });
  while (!holding) std::this_thread::yield();
  std::vector<std::atomic<int>> seen(1000);
  std::atomic<int> elsewhere{0};
  const std::thread::id me = std::this_thread::get_id();
  ParallelFor(1000, [&](long i) {
    ++seen[i];
    elsewhere += std::this_thread::get_id() != me;
  });
  const bool beforeRelease = !released;
  released = true;
  host.join();
  EXPECT_TRUE(beforeRelease) << "the loop did not wait for the other thread's";
  EXPECT_EQ(elsewhere, 0);
  for (std::atomic<int> &s : seen) ASSERT_EQ(s, 1);
}

TEST(Parallel, APieceThatThrowsIsRethrownByTheCallerAndThePoolGoesOn) {
  const ThreadCount two(2);
  EXPECT_THROW(ParallelFor(1000, [&](long i) {
                 if (i == 700) throw std::runtime_error("piece");
               }),
               std::runtime_error);
  std::vector<std::atomic<int>> seen(1000);
  ParallelFor(1000, [&](long i) { ++seen[i]; });
  for (std::atomic<int> &s : seen) ASSERT_EQ(s, 1);
}

// The two signed distance fields are made so (pipeline.cpp): the caller, its own field done,
// keeps the host's progress bar moving while the other thread finishes, and a cancel it hears
// there reaches the other thread's work.
TEST(Parallel, ACallerWaitingForTheOthersAsksItsInterruptOnItsThread) {
  const ThreadCount two(2);
  const std::thread::id caller = std::this_thread::get_id();
  for (const bool cancel : {false, true}) {
    std::atomic<bool> otherStarted{false}, otherSawCancel{false};
    std::atomic<int> calls{0}, callsElsewhere{0};
    const Interrupt interrupt([&] {
      ++calls;
      if (std::this_thread::get_id() != caller) ++callsElsewhere;
      return !cancel;
    });
    ParallelFor(
        2,
        [&](long) {
          const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
          if (std::this_thread::get_id() == caller) {  // its piece ends once the other's has begun
            while (!otherStarted && std::chrono::steady_clock::now() < end) std::this_thread::yield();
            return;
          }
          otherStarted = true;
          for (int polls = 0; polls < 45 && std::chrono::steady_clock::now() < end; ++polls) {  // 450 ms of work
            if (interrupt.Stop()) {
              otherSawCancel = true;
              return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
          }
        },
        true, &interrupt);
    ASSERT_TRUE(otherStarted) << "the pool's thread never took the second piece";
    EXPECT_EQ(callsElsewhere, 0);
    if (cancel) {
      EXPECT_EQ(calls, 1);
      EXPECT_TRUE(otherSawCancel);
    } else {
      EXPECT_GE(calls, 2) << "450 ms of the other's work, polls every " << kWaitBetweenPolls.count() << " ms";
      EXPECT_FALSE(otherSawCancel);
    }
  }
}

TEST(Parallel, AMapLeavesTheProcesssThreadCountAsItFoundIt) {
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
  EXPECT_EQ(Threads(), before);
  EXPECT_EQ(omp_get_max_threads(), before);
}

} // namespace
