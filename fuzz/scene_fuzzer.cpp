// libFuzzer entry point: every input is a scene file's text. The properties
// are checked in scene_check.cpp; a violation aborts, so libFuzzer saves the
// input as a crasher. Outcome counts are printed at exit, to show that the
// inputs reach the solver and not only the JSON parser.
#include <array>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "scene_check.h"

namespace {

using particles::fuzz::Outcome;

std::array<std::atomic<long long>, 4> counts{};

void printCounts() {
  std::fprintf(stderr, "scene_fuzzer outcomes:");
  for (Outcome o : {Outcome::Rejected, Outcome::TooBig, Outcome::Finite, Outcome::Diverged})
    std::fprintf(stderr, " %s %lld;", particles::fuzz::outcomeName(o),
                 counts[static_cast<int>(o)].load());
  std::fprintf(stderr, "\n");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit(printCounts);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const particles::fuzz::Check check = particles::fuzz::checkSceneInput(text);
  ++counts[static_cast<int>(check.outcome)];
  if (!check.violation.empty()) {
    std::fprintf(stderr, "scene_fuzzer: property violated: %s\n", check.violation.c_str());
    std::abort();
  }
  return 0;
}
