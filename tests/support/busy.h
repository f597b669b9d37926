// Test support: CPU-bound processes beside the one measured (the load mode of the benchmark,
// the idle-core tests of threads.h).
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vector>

namespace eulermap::testing {

// `count` children that spin at nice level `nice` until the object dies.
class BusyProcesses {
 public:
  explicit BusyProcesses(int count, int nice = 0) {
    for (int n = 0; n < count; ++n) {
      const pid_t pid = fork();
      if (pid == 0) {
        if (setpriority(PRIO_PROCESS, 0, nice) != 0) _exit(1);
        volatile unsigned long spin = 0;
        for (;;) spin = spin + 1;
      }
      if (pid > 0) pids_.push_back(pid);
    }
  }
  ~BusyProcesses() {
    for (pid_t pid : pids_) kill(pid, SIGKILL), waitpid(pid, nullptr, 0);
  }
  BusyProcesses(const BusyProcesses &) = delete;
  BusyProcesses &operator=(const BusyProcesses &) = delete;

 private:
  std::vector<pid_t> pids_;
};

} // namespace eulermap::testing
