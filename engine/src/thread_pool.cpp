#include "particles/thread_pool.h"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace particles {
namespace {

// How long a wait polls before it goes to sleep. A sleeping thread takes
// tens of microseconds to wake on this project's 2-core VM, and the pile's
// threads wait for each other at every barrier (a few per step, each after
// ~0.1 ms of work): with 2,000 pauses (20-60 us, depending on the processor)
// the faster thread fell asleep and the slower one then waited for it to wake
// (0.16-0.23 s of 600 steps at N = 10,000; measured in docs/scale.md). A
// thread that has to wait longer (a whole step, or threads > cores) sleeps.
constexpr std::chrono::microseconds kSpinTime{200};

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
void waitWhileEqual(const std::atomic<T>& value, T old) {
  const auto until = std::chrono::steady_clock::now() + kSpinTime;
  for (unsigned i = 1;; ++i) {
    if (value.load(std::memory_order_acquire) != old) return;
    relax();
    // The clock is read every 64 pauses (a pause is 10-140 cycles).
    if (i % 64 == 0 && std::chrono::steady_clock::now() > until) break;
  }
  while (value.load(std::memory_order_acquire) == old) value.wait(old, std::memory_order_acquire);
}

}  // namespace

ThreadPool::ThreadPool(int threads) : size_(threads < 1 ? 1 : threads) {
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
    waitWhileEqual(running_, left);
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
  waitWhileEqual(phase_, phase);
}

void ThreadPool::work(int index) {
  long long seen = 0;
  for (;;) {
    waitWhileEqual(generation_, seen);
    seen = generation_.load(std::memory_order_acquire);
    if (stop_.load(std::memory_order_relaxed)) return;
    (*job_)(index);
    if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) running_.notify_all();
  }
}

}  // namespace particles
