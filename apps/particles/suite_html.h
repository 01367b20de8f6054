// DIR/index.html of `particles suite --report DIR`: per-family tables and the
// distributions of the engine's and Box2D's relative discrepancies.
#pragma once

#include <filesystem>

#include "particles/compare/suite.h"

namespace particles::cli {

// Throws std::runtime_error if DIR/index.html cannot be written.
void writeSuiteHtml(const std::filesystem::path& dir, const compare::SuiteResult& result);

}  // namespace particles::cli
