#include "threads.h"

#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <string>

namespace eulermap {

namespace {

thread_local int tThreads = 0;  // 0: IdleCores()

constexpr double kWindowSeconds = 0.25;  // the busy time is averaged over at least this

double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// CPU seconds this process has used, all its threads.
double OwnSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// CPU seconds the machine has spent busy at this process's priority or above (/proc/stat's
// "cpu" line: user, system and interrupts, and niced time only when this process is niced
// itself), -1 when unreadable. A niced process yields its core to a thread of ours (CFS
// weighs nice 10 at a tenth of nice 0), so it takes no core from the team (docs/NOTES.md).
double MachineBusySeconds() {
  std::ifstream in("/proc/stat");
  std::string cpu;
  unsigned long long user, nice, system, idle, iowait, irq, softirq;
  if (!(in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq) || cpu != "cpu") return -1;
  errno = 0;
  const bool niced = getpriority(PRIO_PROCESS, 0) > 0 && errno == 0;
  return double(user + (niced ? nice : 0) + system + irq + softirq) / double(sysconf(_SC_CLK_TCK));
}

// Tasks runnable now on the machine (/proc/loadavg's fourth field, "running/all"), -1 when unreadable.
int RunnableTasks() {
  std::ifstream in("/proc/loadavg");
  double load[3];
  int running = -1;
  char slash;
  if (!(in >> load[0] >> load[1] >> load[2] >> running >> slash)) return -1;
  return running;
}

// The last look of this thread: when, the machine's busy seconds and this process's, and
// the cores it found idle (0: none yet).
struct Look {
  double wall = 0, busy = 0, own = 0;
  int idle = 0;
};
thread_local Look tLast;

} // namespace

int IdleCores() {
  const int all = omp_get_max_threads();
  const double wall = Now();
  if (tLast.idle > 0 && wall - tLast.wall < kWindowSeconds) return tLast.idle;
  const double busy = MachineBusySeconds(), own = OwnSeconds();
  double others;  // cores the other processes kept busy
  if (busy < 0)
    others = 0;
  else if (tLast.idle > 0)
    others = std::max(0.0, (busy - tLast.busy) - (own - tLast.own)) / (wall - tLast.wall);
  else
    others = std::max(0, RunnableTasks() - 1);
  tLast = {wall, busy, own, std::clamp(int(std::lround(all - others)), 1, all)};
  return tLast.idle;
}

int Threads() { return tThreads > 0 ? tThreads : IdleCores(); }

ThreadCount::ThreadCount(int threads) : saved_(tThreads) {
  if (threads > 0) tThreads = threads;
}

ThreadCount::~ThreadCount() { tThreads = saved_; }

} // namespace eulermap
