// eulermap::Interrupt — how the core's long loops keep the host's progress bar moving and
// hear Cancel on big grids (OpenVDB's interrupter): between bounded pieces of work they
// ask Stop(), and stop when it says so.
//
// The pieces: a conjugate-gradient iteration of the velocity solve (its operator on its own,
// and each pass of its start), and its multigrid V-cycle's smoothing (each colour on the
// finest level), restriction and coarse levels (velocity.h, multigrid.h), and
// kNodesBetweenPolls nodes of a distance-transform sweep (distance_transform.h), of each
// pass that finds an inside set (sdf.h), of a warped morph frame (morph.h), of a velocity
// system's assembly, of the labelling of the morph's first inside set and of each step's
// sign flips (zero_set_topology.h); a Lanczos step of a Laplace-Beltrami basis and a
// refinement of ZoomOut (functional_map.h); kBytesBetweenPolls of a large array while it is filled
// (AssignPolling, FillPolling); and once a system is assembled. The pipeline reports its
// stages between them (pipeline.h).
//
// Stop() never throws, so it may be asked inside a parallel region: on the thread that
// made the Interrupt (the host's, whose callback may touch its GUI) it asks the callback;
// on any other thread it only reads whether an earlier answer was "cancel". A loop that
// stops returns what it has; its caller then throws Error("cancelled") (Cancelled()).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

namespace eulermap {

// Nodes of a distance-transform sweep between two polls.
constexpr std::size_t kNodesBetweenPolls = std::size_t(1) << 18;

// Bytes of a large array filled between two polls (AssignPolling).
constexpr std::size_t kBytesBetweenPolls = std::size_t(32) << 20;

class Interrupt {
 public:
  using Callback = std::function<bool()>;  // false: cancel

  Interrupt() = default;  // never stops
  explicit Interrupt(Callback callback) : callback_(std::move(callback)), owner_(std::this_thread::get_id()) {}

  // Whether to stop: on the thread that made this object, the callback's answer (once it
  // said cancel, always); elsewhere, whether it has said cancel.
  bool Stop() const {
    if (callback_ && !cancelled_ && std::this_thread::get_id() == owner_ && !callback_()) cancelled_ = true;
    return cancelled_;
  }
  bool Cancelled() const { return cancelled_; }

 private:
  Callback callback_;
  std::thread::id owner_;
  mutable std::atomic<bool> cancelled_{false};
};

// An Interrupt over a poll that may throw to cancel (the pipeline's progress callback does),
// for work that asks Stop(), which must not throw: the first throw is held, Stop() says stop
// from then on, and Rethrow() throws it once the work has returned.
class HeldThrow {
 public:
  explicit HeldThrow(std::function<void()> poll)
      : poll_(std::move(poll)), interrupt_([this] {
          try {
            if (poll_) poll_();
            return true;
          } catch (...) {
            thrown_ = std::current_exception();
            return false;
          }
        }) {}
  HeldThrow(const HeldThrow &) = delete;
  HeldThrow &operator=(const HeldThrow &) = delete;

  const Interrupt &interrupt() const { return interrupt_; }
  void Rethrow() const {
    if (thrown_) std::rethrow_exception(thrown_);
  }

 private:
  std::function<void()> poll_;
  std::exception_ptr thrown_;
  Interrupt interrupt_;
};

// v = n copies of value, kBytesBetweenPolls at a time with a poll after each: the kernel
// clears a fresh page at its first touch, which took up to 20 s for a 1.4 GB array (the
// velocity solver's at 384^3, on a virtual machine; docs/NOTES.md).
template <class T> void AssignPolling(std::vector<T> &v, std::size_t n, const T &value, const Interrupt &interrupt) {
  v.clear();
  v.reserve(n);
  const std::size_t piece = std::max<std::size_t>(1, kBytesBetweenPolls / sizeof(T));
  while (v.size() < n) {
    v.resize(std::min(n, v.size() + piece), value);
    interrupt.Stop();
  }
}

// v = at(0), ..., at(n - 1), filled as AssignPolling fills.
template <class T, class At> void FillPolling(std::vector<T> &v, std::size_t n, At &&at, const Interrupt &interrupt) {
  v.clear();
  v.reserve(n);
  const std::size_t piece = std::max<std::size_t>(1, kBytesBetweenPolls / sizeof(T));
  while (v.size() < n) {
    for (const std::size_t end = std::min(n, v.size() + piece); v.size() < end;) v.push_back(at(v.size()));
    interrupt.Stop();
  }
}

} // namespace eulermap
