// The scene fuzzer's properties (fuzz/scene_check.h), checked in the normal
// build without libFuzzer: on the fuzzer's seed corpus (fuzz/corpus/) and on
// every input it ever failed on (tests/fuzz_regressions/inputs/). A file's
// name says what the loader must do with it: "invalid-*" is rejected,
// "valid-*" and the example scenes are accepted and stay finite; "extreme-*"
// and crashers ("crash-*", "timeout-*", ...) only have to keep the
// properties.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene_check.h"

namespace particles::test {
namespace {

namespace fs = std::filesystem;
using fuzz::Outcome;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void checkDirectory(const fs::path& dir, std::size_t atLeast) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && !e.path().filename().string().starts_with("."))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  EXPECT_GE(files.size(), atLeast) << dir;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::string name = file.filename().string();
    const auto t0 = std::chrono::steady_clock::now();
    const fuzz::Check check = fuzz::checkSceneInput(readFile(file));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(check.violation, "");
    EXPECT_LT(seconds, 10.0) << "the fuzzer's -timeout";
    const bool anyOutcome = name.starts_with("extreme-") || name.starts_with("crash-") ||
                            name.starts_with("timeout-") || name.starts_with("oom-") ||
                            name.starts_with("slow-unit-") || name.starts_with("leak-");
    if (name.starts_with("invalid-")) {
      EXPECT_EQ(check.outcome, Outcome::Rejected) << fuzz::outcomeName(check.outcome);
    } else if (!anyOutcome) {
      EXPECT_EQ(check.outcome, Outcome::Finite) << fuzz::outcomeName(check.outcome);
    }
  }
}

TEST(FuzzRegressions, SeedCorpus) {
  checkDirectory(PARTICLES_FUZZ_CORPUS_DIR, 20);
}

TEST(FuzzRegressions, PastFindings) {
  checkDirectory(PARTICLES_FUZZ_REGRESSIONS_DIR, 1);
}

}  // namespace
}  // namespace particles::test
