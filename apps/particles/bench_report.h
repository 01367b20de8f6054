// The HTML report of `particles bench --report DIR`: DIR/index.html.
#pragma once

#include <string>

#include "bench_results.h"

namespace particles::cli {

// Throws std::runtime_error if DIR/index.html cannot be written.
void writeBenchReport(const std::string& dir, const BenchResults& results);

}  // namespace particles::cli
