// The properties the scene fuzzer checks on one input, shared with the
// normal build's regression test (tests/fuzz_regressions/), which replays
// the seed corpus and every past crasher through the same code without
// libFuzzer. docs/fuzzing.md explains each property and why.
#pragma once

#include <string>
#include <string_view>

namespace particles::fuzz {

// Scenes above these sizes are accepted by the loader but not stepped, so
// that every input stays fast.
inline constexpr std::size_t kMaxBalls = 1000;
inline constexpr std::size_t kMaxWalls = 1000;
// At most this many steps of an accepted scene (fewer if the scene asks).
inline constexpr long long kMaxSteps = 10;
// Velocity and position passes per step are capped at this for stepping.
// The loader accepts up to 2^31 - 1, and a resting stack never stops
// "approaching" (docs/fuzzing.md, finding 1), so such a scene costs the full
// count every step: a known, reported slowness, not re-found every run.
inline constexpr int kMaxPasses = 1000;

// The file name every input is parsed under; messages must start with it.
inline constexpr std::string_view kFileName = "fuzz.json";

enum class Outcome {
  Rejected,  // SceneError with a well-formed message
  TooBig,    // accepted, more than kMaxBalls balls or kMaxWalls walls: not stepped
  Finite,    // accepted and stepped; every ball state finite
  Diverged,  // accepted, outside the physical range, non-finite after the steps:
             // what `particles run` reports as divergence (exit 1)
};

struct Check {
  Outcome outcome = Outcome::Rejected;
  std::string violation;  // empty when every property holds
};

// parseScene(text, kFileName), then up to kMaxSteps steps of the world.
// Exceptions other than SceneError are not caught: they are crashes.
Check checkSceneInput(std::string_view text);

const char* outcomeName(Outcome o);

}  // namespace particles::fuzz
