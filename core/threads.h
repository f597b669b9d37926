// eulermap::Threads — how many threads each of the core's parallel loops (parallel.h) uses.
//
// A library must not change the thread count of the process (inside MeshLab that would
// change it for every plugin after this one): ComputeMap holds a ThreadCount for the thread
// that calls it, and every loop of the core asks Threads() for its team.
//
// Without a count set, the team is OpenMP's default (OMP_NUM_THREADS, else the cores this
// process may run on), on a busy machine too: a loop's pieces go to whichever of its threads
// has a core (parallel.h), and its end waits only for pieces already begun, so a team of the
// machine's cores gets more of a shared machine than a smaller one. Figures: docs/NOTES.md.
#pragma once

namespace eulermap {

// The team size of a loop started by this thread: the innermost ThreadCount's, else
// OpenMP's default.
int Threads();

// Sets Threads() for this thread while it lives (threads > 0; 0 leaves the default).
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
