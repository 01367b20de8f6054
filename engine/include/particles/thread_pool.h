// A small pool of worker threads for the large-scene step (docs/scale.md).
// run(job) calls job(t) once on each of size() threads (t = 0 on the caller)
// and returns when all are done; inside a job, sync() is a barrier of all
// size() threads. Work is split by index ranges that do not depend on
// timing, so results never depend on how the threads were scheduled.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace particles {

class ThreadPool {
 public:
  explicit ThreadPool(int threads);  // threads >= 1; threads - 1 workers are started
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return size_; }
  void run(const std::function<void(int)>& job);
  void sync();

  // Ordering between two threads instead of all of them (the large-scene
  // path's bands, docs/scale.md): thread t announces that it has done all
  // of its work up to `phase` that another thread may wait for; a thread
  // waits until thread `other` has announced at least `phase`. Phases count
  // up within one run(); resetProgress(), called outside run(), sets every
  // thread's back to 0.
  void resetProgress();
  void announce(int t, int phase);
  void waitFor(int other, int phase);

 private:
  void work(int index);

  int size_;
  // Every wait below polls before it sleeps (50 us at a barrier, 1 ms for the
  // next job; thread_pool.cpp says why): a step of the 10,000-ball pile has
  // about 30 barriers, and waking a sleeping thread costs more than the work
  // between two of them (docs/scale.md, "Waits that spin" and the night
  // session).
  std::atomic<int> arrived_{0};           // threads at the current barrier
  std::atomic<unsigned> phase_{0};        // barriers completed
  std::atomic<long long> generation_{0};  // jobs started
  std::atomic<int> running_{0};           // workers still in the current job
  std::atomic<bool> stop_{false};
  const std::function<void(int)>* job_ = nullptr;
  // Each thread's announced phase, on a cache line of its own.
  struct alignas(64) Progress {
    std::atomic<int> phase{0};
  };
  std::unique_ptr<Progress[]> progress_;
  std::vector<std::thread> workers_;
};

// A pool owned by a copyable object: a copy starts without a pool and makes
// its own when first asked, so copies never share threads.
class PoolHandle {
 public:
  PoolHandle() = default;
  PoolHandle(const PoolHandle&) {}
  PoolHandle& operator=(const PoolHandle&) { return *this; }
  PoolHandle(PoolHandle&&) noexcept = default;
  PoolHandle& operator=(PoolHandle&&) noexcept = default;

  // The pool with `threads` threads, made (or remade) on demand.
  ThreadPool& get(int threads) {
    if (!pool_ || pool_->size() != threads) pool_ = std::make_unique<ThreadPool>(threads);
    return *pool_;
  }

 private:
  std::unique_ptr<ThreadPool> pool_;
};

}  // namespace particles
