// The bench's own timing harness: the median wall time of repeated runs
// (not a timed test: nothing here passes or fails on a time).
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace particles::cli {

// Median over `repeats` calls of `once()`'s wall time in seconds, each call
// timed on its own with the steady clock. `once` builds what it needs before
// calling `timed()` with the part to time, so construction is not counted.
template <typename Once>
double medianSeconds(int repeats, Once once) {
  std::vector<double> samples;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    double seconds = 0.0;
    once([&](auto&& part) {
      const auto t0 = std::chrono::steady_clock::now();
      part();
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    });
    samples.push_back(seconds);
  }
  std::sort(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  return n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}

}  // namespace particles::cli
