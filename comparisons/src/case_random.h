// A small, fully specified random source: the standard distributions are
// implementation-defined, and cases must be the same on every machine.
#pragma once

#include <cmath>
#include <cstdint>

namespace particles::compare::detail {

inline std::uint64_t splitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class CaseRandom {
 public:
  CaseRandom(std::uint64_t seed, std::uint64_t stream, std::uint64_t index)
      : state_(seed ^ (stream * 0xD1B54A32D192ED03ull) ^ (index * 0x8CB92BA72F3D8DD7ull)) {
    splitMix64(state_);
  }
  double uniform() { return static_cast<double>(splitMix64(state_) >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int below(int n) { return static_cast<int>(uniform() * n); }
  double sign() { return uniform() < 0.5 ? -1.0 : 1.0; }

 private:
  std::uint64_t state_;
};

}  // namespace particles::compare::detail
