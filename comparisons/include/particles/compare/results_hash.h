// One hash of everything a suite run computed per case, so that two runs
// (threads, shards, builds, machines) can be compared by one value:
// report.json's "results_hash" (docs/report-format.md, docs/determinism.md).
#pragma once

#include <cstdint>

#include "particles/compare/suite.h"

namespace particles::compare {

// FNV-1a 64 (particles::StateHasher) over the cases in suite order
// (`index` order, whatever order `cases` holds them in): per case its index
// as a u64, then for each of engine, Box2D and closed form a tag byte
// ('E', 'B', 'T'; 'N' instead of 'T' when there is no closed form) followed
// by every ball's vx, vy, omega as canonical doubles, then one byte for
// `pass` (0 or 1).
std::uint64_t resultsHash(const SuiteResult& result);

}  // namespace particles::compare
