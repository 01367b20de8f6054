// What the two halves of the large-scene path (scale_rows.cpp builds the
// rows, scale_solver.cpp solves them) share.
#pragma once

#include <cstddef>
#include <utility>

namespace particles::scale {

// Upper bound on the strips of the parallel solve (even: a fixed number, so
// that no result depends on the thread count).
constexpr int kMaxStrips = 32;

// Items [begin, end) of part t of T: a split by index only, never by timing.
inline std::pair<std::size_t, std::size_t> part(std::size_t n, int t, int threads) {
  const std::size_t tt = static_cast<std::size_t>(t), tn = static_cast<std::size_t>(threads);
  return {n * tt / tn, n * (tt + 1) / tn};
}

}  // namespace particles::scale
