#include "cli_common.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <sstream>

namespace particles::cli {

void printError(const std::string& message) {
  std::cerr << "particles: error: " << message << '\n';
}

void printWarning(const std::string& message) {
  std::cerr << "particles: warning: " << message << '\n';
}

void printRangeWarnings(const std::vector<reference::RangeIssue>& issues) {
  // checkBox2DRange groups the issues by code.
  for (std::size_t i = 0; i < issues.size();) {
    std::size_t end = i;
    while (end < issues.size() && issues[end].code == issues[i].code) ++end;
    const std::size_t shown = std::min(end - i, kRangeWarningsShown);
    for (std::size_t k = i; k < i + shown; ++k)
      printWarning("outside Box2D's range: " + issues[k].message);
    if (end - i > shown)
      printWarning("outside Box2D's range: " + std::to_string(end - i - shown) +
                   " more of the same kind (" + reference::rangeCodeName(issues[i].code) + ")");
    i = end;
  }
}

CLI::Validator integerInRange(long long min, long long max) {
  const std::string want =
      "must be an integer >= " + std::to_string(min) + " and <= " + std::to_string(max) + ", got ";
  return CLI::Validator(
      [min, max, want](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec != std::errc() || ptr != end || value < min || value > max) return want + text;
        return "";
      },
      "");
}

CLI::Validator unsigned64() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec != std::errc() || ptr != end)
          return "must be an integer >= 0 and < 2^64, got " + text;
        return "";
      },
      "");
}

CLI::Validator finiteInRange(double min, double max) {
  std::ostringstream want;
  want << "must be a number >= " << min << " and <= " << max << ", got ";
  return CLI::Validator(
      [min, max, want = want.str()](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (ec != std::errc() || ptr != end || !std::isfinite(value) || value < min || value > max)
          return want + text;
        return "";
      },
      "");
}

Box2DIterationOptions addBox2DIterationOptions(CLI::App& cmd, Box2DIterations& iterations,
                                               const std::string& scope) {
  // Box2D's own loops accept any count; 0 disables a solver, which
  // checkBox2DRange reports as leaving Box2D's range. The upper bound only
  // keeps the count an int.
  constexpr long long kMax = 1000000;
  Box2DIterationOptions o;
  o.velocity = cmd.add_option("--velocity-iterations", iterations.velocity,
                              "Box2D velocity-solver iterations per step, integer 0 to 1000000 "
                              "(Box2D recommends 8; fewer than 2 leaves Box2D's range)" +
                                  scope)
                   ->type_name("N")
                   ->default_val(iterations.velocity)
                   ->check(integerInRange(0, kMax));
  o.position = cmd.add_option("--position-iterations", iterations.position,
                              "Box2D position-solver iterations per step, integer 0 to 1000000 "
                              "(Box2D recommends 3; 0 never corrects overlaps)" +
                                  scope)
                   ->type_name("N")
                   ->default_val(iterations.position)
                   ->check(integerInRange(0, kMax));
  return o;
}

}  // namespace particles::cli
