#include "particles/thread_pool.h"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace particles {
namespace {

// How long a wait polls before it goes to sleep (std::atomic::wait, a
// futex). Waking a sleeping thread takes tens of microseconds on this
// project's 2-core VM, and a notify that finds a sleeper costs a system call.
// Measured on the 10,000-ball pile with two threads (docs/scale.md):
// - at a barrier (sync; a step has a few dozen, each after ~0.1 ms of work)
//   2,000 pauses let the faster thread fall asleep, and the slower one then
//   waited for it to wake at the next barrier. 50 us by the clock keeps the
//   waits short; 200 us gained nothing more and made the test suite, which
//   runs two 2-thread tests on 2 cores, 4 s (17 %) slower;
// - a worker waiting for the next job (run) waits through the serial part
//   of a step (~0.2 ms at 10,000 balls): 1 ms of polling keeps it awake from
//   step to step (+9-13 % at 10,000 balls, two threads) and costs the test
//   suite nothing measurable.
// A thread that waits longer (no more steps, or threads > cores) sleeps.
constexpr std::chrono::microseconds kSyncSpin{50};
constexpr std::chrono::microseconds kJobSpin{1000};

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

// Waits until `value` is no longer `old`: polls, then sleeps in
// std::atomic::wait (a futex on Linux).
template <class T>
void waitWhileEqual(const std::atomic<T>& value, T old, std::chrono::microseconds spin) {
  const auto until = std::chrono::steady_clock::now() + spin;
  for (unsigned i = 1;; ++i) {
    if (value.load(std::memory_order_acquire) != old) return;
    relax();
    // The clock is read every 64 pauses (a pause is 10-140 cycles).
    if (i % 64 == 0 && std::chrono::steady_clock::now() > until) break;
  }
  while (value.load(std::memory_order_acquire) == old) value.wait(old, std::memory_order_acquire);
}

}  // namespace

ThreadPool::ThreadPool(int threads)
    : size_(threads < 1 ? 1 : threads),
      progress_(std::make_unique<Progress[]>(static_cast<std::size_t>(size_))) {
  for (int i = 1; i < size_; ++i) workers_.emplace_back([this, i] { work(i); });
}

ThreadPool::~ThreadPool() {
  stop_.store(true, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void ThreadPool::run(const std::function<void(int)>& job) {
  if (size_ == 1) {
    job(0);
    return;
  }
  job_ = &job;
  running_.store(size_ - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);  // publishes job_ and running_
  generation_.notify_all();
  job(0);
  for (int left = running_.load(std::memory_order_acquire); left != 0;
       left = running_.load(std::memory_order_acquire))
    waitWhileEqual(running_, left, kSyncSpin);
  job_ = nullptr;
}

// A barrier of all size() threads. The last to arrive resets the count, then
// opens the next phase; the others wait for the phase to change. A thread
// that leaves and arrives at the next barrier at once finds the count reset,
// because it read the new phase (acquire) after the reset was written.
void ThreadPool::sync() {
  if (size_ == 1) return;
  const unsigned phase = phase_.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == size_) {
    arrived_.store(0, std::memory_order_relaxed);
    phase_.store(phase + 1, std::memory_order_release);
    phase_.notify_all();
    return;
  }
  waitWhileEqual(phase_, phase, kSyncSpin);
}

void ThreadPool::resetProgress() {
  for (int t = 0; t < size_; ++t) progress_[static_cast<std::size_t>(t)].phase.store(0);
}

void ThreadPool::announce(int t, int phase) {
  std::atomic<int>& mine = progress_[static_cast<std::size_t>(t)].phase;
  mine.store(phase, std::memory_order_release);
  mine.notify_all();
}

// Polls, as at a barrier, then sleeps until the announced phase changes
// (phases only grow, so each change is a step towards `phase`).
void ThreadPool::waitFor(int other, int phase) {
  const std::atomic<int>& theirs = progress_[static_cast<std::size_t>(other)].phase;
  for (int seen = theirs.load(std::memory_order_acquire); seen < phase;
       seen = theirs.load(std::memory_order_acquire))
    waitWhileEqual(theirs, seen, kSyncSpin);
}

void ThreadPool::work(int index) {
  long long seen = 0;
  for (;;) {
    waitWhileEqual(generation_, seen, kJobSpin);
    seen = generation_.load(std::memory_order_acquire);
    if (stop_.load(std::memory_order_relaxed)) return;
    (*job_)(index);
    if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) running_.notify_all();
  }
}

}  // namespace particles
