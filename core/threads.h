// eulermap::Threads — how many threads each of the core's parallel regions uses.
//
// A library must not change OpenMP's thread count for the process (inside MeshLab that
// would change it for every plugin after this one): ComputeMap holds a ThreadCount for
// the thread that calls it, and every parallel region of the core asks for its team in
// its own clause, `#pragma omp parallel ... num_threads(Threads())`.
//
// Without a count set, the team is the cores that other processes at this one's priority
// leave idle (at least one): on a busy machine a team larger than that waits at every
// barrier for a member the scheduler has taken off its core, and libgomp's threads spin
// there (its wait policy is read once, when the library loads, from the environment).
// Niced processes yield their cores to the team and are not counted. Figures: docs/NOTES.md.
#pragma once

namespace eulermap {

// The team size of a parallel region started by this thread: the innermost ThreadCount's,
// else IdleCores().
int Threads();

// The cores that other processes at this one's priority leave idle, at least 1 and at most
// OpenMP's default: the machine's busy time (/proc/stat; niced time only when this process
// is niced too) less this process's own, over the last quarter second or more, looked at
// again once that much time has passed (a first look: the runnable tasks of /proc/loadavg,
// this thread aside, niced ones included). OpenMP's default where Linux's figures are missing.
int IdleCores();

// Sets Threads() for this thread while it lives (threads > 0; 0 leaves IdleCores()).
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
