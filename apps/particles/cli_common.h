// Helpers shared by the subcommands: the one-line error and warning format,
// argument validators whose messages read like the scene loader's, and the
// Box2D iteration options of `run`, `compare` and `suite`.
#pragma once

#include <string>
#include <vector>

#include "particles/reference/box2d_range.h"

namespace CLI {
class App;
class Option;
class Validator;
}  // namespace CLI

namespace particles::cli {

// "particles: error: MESSAGE" and "particles: warning: MESSAGE", one line on stderr.
void printError(const std::string& message);
void printWarning(const std::string& message);

// The range issues of a scene (reference::checkBox2DRange) as warnings,
// "outside Box2D's range: ...": the first kRangeWarningsShown of each kind,
// then one line counting the rest of that kind. A 460-grain hourglass raised
// one identical-looking warning per grain.
inline constexpr std::size_t kRangeWarningsShown = 3;
void printRangeWarnings(const std::vector<reference::RangeIssue>& issues);

// An integer in [min, max], checked on the text before CLI11
// converts it, so that "-1" is "--cases: must be an integer >= 0, got -1"
// rather than a wrapped or saturated value. The option's name is prefixed by
// CLI11; a failure is a CLI::ValidationError, exit status 2.
CLI::Validator integerInRange(long long min, long long max);
// A decimal unsigned 64-bit integer (no sign, no wrap-around).
CLI::Validator unsigned64();
// A finite number in [min, max] (NaN and infinities are refused, which
// CLI::Range lets through: every comparison with NaN is false).
CLI::Validator finiteInRange(double min, double max);

// Box2D's per-step solver iterations (Box2DSettings), with the defaults
// Box2D recommends.
struct Box2DIterations {
  int velocity = 8;
  int position = 3;
};

struct Box2DIterationOptions {
  CLI::Option* velocity = nullptr;
  CLI::Option* position = nullptr;
};

// Registers --velocity-iterations N and --position-iterations N on `cmd`.
// `scope` ends the help text, e.g. " (with --engine box2d only)".
Box2DIterationOptions addBox2DIterationOptions(CLI::App& cmd, Box2DIterations& iterations,
                                               const std::string& scope = "");

}  // namespace particles::cli
