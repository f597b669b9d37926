#include "parallel.h"

#include "threads.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define EULERMAP_PAUSE() _mm_pause()
#else
#define EULERMAP_PAUSE() std::this_thread::yield()
#endif

namespace eulermap {

namespace {

// Pieces per thread of the team: more pieces share a busy machine's cores better, each costs
// one atomic increment.
constexpr long kPiecesPerThread = 4;

// How long a thread spins for the next loop, or the caller for the last pieces, before it
// sleeps: on a quiet machine the core's loops follow each other within this, and a sleeping
// thread takes tens of microseconds to wake.
constexpr std::chrono::microseconds kSpin(200);

thread_local bool tInLoop = false;  // a pool thread, or a caller inside its loop

// Spins until done() or kSpin has passed; whether done().
template <class Done> bool SpinUntil(Done &&done) {
  const auto end = std::chrono::steady_clock::now() + kSpin;
  for (int n = 1;; ++n) {
    if (done()) return true;
    EULERMAP_PAUSE();
    if (n % 64 == 0 && std::chrono::steady_clock::now() > end) return false;
  }
}

// The most threads a loop runs on.
constexpr int kMaxTeam = 64;

// One loop. Seat s of the team (the caller's is 0) has the share [s n / team, (s + 1) n /
// team) of the range, and claims its pieces first, in order: a loop run again and again
// (the multigrid's sweeps) finds each share's nodes in the cache of the core that worked on
// them before. Then it claims the pieces left in the other shares.
struct Loop {
  struct alignas(64) Share {
    std::atomic<long> next;
    long end;
  };
  const void *body;
  detail::PieceFn fn;
  int team;
  long piece;
  Share share[kMaxTeam];
  std::mutex errorMutex;
  std::exception_ptr error;

  Loop(long n, int threads, const void *b, detail::PieceFn f) : body(b), fn(f), team(threads) {
    piece = (n + team * kPiecesPerThread - 1) / (team * kPiecesPerThread);
    for (int s = 0; s < team; ++s) share[s].next = n * s / team, share[s].end = n * (s + 1) / team;
  }

  void ClaimPieces(int seat) {
    for (int k = 0; k < team; ++k) {
      Share &s = share[(seat + k) % team];
      for (long begin; (begin = s.next.fetch_add(piece, std::memory_order_relaxed)) < s.end;) {
        try {
          fn(body, begin, std::min(s.end, begin + piece));
        } catch (...) {
          const std::lock_guard<std::mutex> lock(errorMutex);
          if (!error) error = std::current_exception();
          for (int t = 0; t < team; ++t) share[t].next.store(share[t].end, std::memory_order_relaxed);  // no more pieces
        }
      }
    }
  }
};

// The pool's threads sit waiting for a loop, take a seat at it (one of the team less the
// caller) and claim its pieces.
class Pool {
 public:
  static Pool &Instance() {
    static Pool pool;
    return pool;
  }

  ~Pool() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      posted_.fetch_add(1);
    }
    wake_.notify_all();
    for (std::thread &t : threads_) t.join();
  }

  // Runs the loop on the caller and up to team - 1 pool threads, the caller asking
  // whileWaiting (when given) while it waits for theirs; false when another thread's loop
  // holds the pool.
  bool Run(Loop &loop, const Interrupt *whileWaiting) {
    const int helpers = loop.team - 1;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (loop_) return false;
      const unsigned long seen = posted_.load(std::memory_order_relaxed);  // a new thread sees this loop
      while (int(threads_.size()) < helpers) threads_.emplace_back([this, seen] { Serve(seen); });
      loop_ = &loop;
      seats_ = helpers;
      posted_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    tInLoop = true;
    loop.ClaimPieces(0);
    tInLoop = false;
    SpinUntil([&] { return working_.load(std::memory_order_acquire) == 0; });
    std::unique_lock<std::mutex> lock(mutex_);
    loop_ = nullptr;  // no thread sits down any more
    seats_ = 0;
    const auto done = [&] { return working_.load(std::memory_order_relaxed) == 0; };
    if (!whileWaiting) {
      done_.wait(lock, done);
      return true;
    }
    while (!done_.wait_for(lock, kWaitBetweenPolls, done)) {
      lock.unlock();
      whileWaiting->Stop();
      lock.lock();
    }
    return true;
  }

 private:
  Pool() = default;

  void Serve(unsigned long seen) {
    tInLoop = true;
    for (;;) {
      SpinUntil([&] { return posted_.load(std::memory_order_acquire) != seen; });
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return posted_.load(std::memory_order_relaxed) != seen; });
      seen = posted_.load(std::memory_order_relaxed);
      if (stopping_) return;
      if (!loop_ || seats_ == 0) continue;
      const int seat = loop_->team - seats_--;
      working_.fetch_add(1, std::memory_order_relaxed);
      Loop *loop = loop_;
      lock.unlock();
      loop->ClaimPieces(seat);
      lock.lock();
      if (working_.fetch_sub(1, std::memory_order_release) == 1) done_.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::atomic<unsigned long> posted_{0};  // loops posted: a change wakes the threads
  std::atomic<int> working_{0};           // threads at the loop
  Loop *loop_ = nullptr;
  int seats_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

} // namespace

namespace detail {

void RunPieces(long n, bool parallel, const void *body, PieceFn fn, const Interrupt *whileWaiting) {
  if (n <= 0) return;
  const int team = parallel && !tInLoop ? std::clamp(Threads(), 1, kMaxTeam) : 1;
  if (team == 1 || n == 1) return fn(body, 0, n);  // alone
  Loop loop(n, team, body, fn);
  if (!Pool::Instance().Run(loop, whileWaiting)) loop.ClaimPieces(0);  // alone: another thread's loop holds the pool
  if (loop.error) std::rethrow_exception(loop.error);
}

} // namespace detail

} // namespace eulermap
