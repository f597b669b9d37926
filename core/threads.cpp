#include "threads.h"

#include <omp.h>

namespace eulermap {

namespace {
thread_local int tThreads = 0;  // 0: OpenMP's default
} // namespace

int Threads() { return tThreads > 0 ? tThreads : omp_get_max_threads(); }

ThreadCount::ThreadCount(int threads) : saved_(tThreads) {
  if (threads > 0) tThreads = threads;
}

ThreadCount::~ThreadCount() { tThreads = saved_; }

} // namespace eulermap
