// eulermap::ParallelPieces, eulermap::ParallelFor — the core's parallel loops, on a pool of
// threads of its own.
//
// An OpenMP region ends at a barrier: on a busy machine the scheduler takes a member of the
// team off its core and the others wait for it there (libgomp's threads spin, a policy read
// once from the environment, which a library cannot choose for the process). Here a loop's
// range is cut into pieces that the calling thread and the pool's threads claim one at a
// time. The caller claims pieces too, so a thread that has not got a core yet leaves its
// share to the others, and at the end the caller waits only for the pieces being worked on,
// asleep after a short spin. Measured: docs/NOTES.md.
//
// A loop started inside a loop runs on its own thread alone (as nested OpenMP regions do);
// so does one started while another thread's loop holds the pool. A piece that throws ends
// the loop once the pieces claimed are done, and the caller rethrows it.
#pragma once

#include "interrupt.h"

#include <chrono>
#include <type_traits>

namespace eulermap {

// How often a caller waiting for the other threads' pieces asks the interrupt it was given
// (ParallelPieces below): the host's progress bar moves and hears Cancel that often.
constexpr std::chrono::milliseconds kWaitBetweenPolls(100);

namespace detail {
using PieceFn = void (*)(const void *body, long begin, long end);
void RunPieces(long n, bool parallel, const void *body, PieceFn fn, const Interrupt *whileWaiting);
} // namespace detail

// Calls body(begin, end) once for each piece of [0, n) (consecutive ranges that cover it),
// on up to Threads() threads (threads.h), the calling one among them; on the calling thread
// alone, with one piece, when !parallel. Which thread works on a piece, and how large the
// pieces are, must not change the result. whileWaiting (when given), for a few long pieces
// of work: the calling thread, its own pieces done, asks whileWaiting->Stop() every
// kWaitBetweenPolls until the others' are (their work asks Stop() too, which off the calling
// thread only reads an earlier cancel).
template <class Body>
void ParallelPieces(long n, Body &&body, bool parallel = true, const Interrupt *whileWaiting = nullptr) {
  using B = std::remove_reference_t<Body>;
  detail::RunPieces(
      n, parallel, &body, [](const void *b, long begin, long end) { (*static_cast<B *>(const_cast<void *>(b)))(begin, end); },
      whileWaiting);
}

// Calls fn(i) for every i in [0, n), as ParallelPieces.
template <class Fn> void ParallelFor(long n, Fn &&fn, bool parallel = true, const Interrupt *whileWaiting = nullptr) {
  ParallelPieces(
      n,
      [&fn](long begin, long end) {
        for (long i = begin; i < end; ++i) fn(i);
      },
      parallel, whileWaiting);
}

} // namespace eulermap
