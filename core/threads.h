// eulermap::Threads — how many threads each of the core's parallel regions uses.
//
// A library must not change OpenMP's thread count for the process (inside MeshLab that
// would change it for every plugin after this one): ComputeMap holds a ThreadCount for
// the thread that calls it, and every parallel region of the core asks for its team in
// its own clause, `#pragma omp parallel ... num_threads(Threads())`.
#pragma once

namespace eulermap {

// The team size of a parallel region started by this thread: the innermost ThreadCount's,
// else OpenMP's own default (every core).
int Threads();

// Sets Threads() for this thread while it lives (threads > 0; 0 leaves OpenMP's default).
class ThreadCount {
 public:
  explicit ThreadCount(int threads);
  ~ThreadCount();
  ThreadCount(const ThreadCount &) = delete;
  ThreadCount &operator=(const ThreadCount &) = delete;

 private:
  int saved_;
};

} // namespace eulermap
