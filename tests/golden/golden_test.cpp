// Golden state hashes (docs/determinism.md): the final state of every
// example scene and the results of a small suite run, pinned as FNV-1a 64
// hashes in tests/golden/state_hashes.json. Both CI builds (Release -O3 and
// the sanitizer build at -O1) check the same file, so passing in both shows
// that the optimisation level changes no result.
//
// After an intended change of the physics, rewrite the file with
//   PARTICLES_REGENERATE_GOLDEN=1 ctest --test-dir build -R Golden
// and review its diff like code.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "particles/compare/results_hash.h"
#include "particles/compare/suite.h"
#include "particles/scenefile.h"
#include "particles/state_hash.h"

namespace particles::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The suite run whose results hash is pinned: small, but every family and
// the catalogue, through the engine, Box2D and the closed form.
constexpr int kSuiteCases = 50;
constexpr const char* kSuiteKey = "--cases 50 --seed 1";

bool regenerating() {
  const char* v = std::getenv("PARTICLES_REGENERATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

json readGolden() {
  std::ifstream in(PARTICLES_GOLDEN_FILE);
  if (!in) return json::object();
  return json::parse(in);
}

// What `particles run SCENE` ends with, hashed.
std::string sceneHash(const fs::path& file) {
  const SceneDef scene = loadScene(file);
  World world(scene);
  world.run(scene.stepCount());
  return hashHex(stateHash(world));
}

std::string suiteHash(int jobs) {
  compare::SuiteSettings s;
  s.casesPerFamily = kSuiteCases;
  s.jobs = jobs;
  s.mutants = false;  // not part of the results hash
  return hashHex(compare::resultsHash(compare::runSuite(s)));
}

std::vector<fs::path> exampleScenes() {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(PARTICLES_SCENES_DIR))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The one test that computes every golden value, and the only one that
// rewrites the file, so that parallel tests never race on it.
TEST(Golden, StateHashes) {
  json computed = {{"about",
                    "FNV-1a 64 hashes of final states and suite results (docs/determinism.md). "
                    "Regenerate: PARTICLES_REGENERATE_GOLDEN=1 ctest --test-dir build -R Golden"},
                   {"scenes", json::object()},
                   {"suite", json::object()}};
  for (const fs::path& file : exampleScenes())
    computed["scenes"][file.filename().string()] = sceneHash(file);
  computed["suite"][kSuiteKey] = suiteHash(2);

  if (regenerating()) {
    std::ofstream(PARTICLES_GOLDEN_FILE) << computed.dump(1) << "\n";
    std::printf("rewrote %s\n", PARTICLES_GOLDEN_FILE);
    return;
  }
  const json golden = readGolden();
  ASSERT_TRUE(golden.contains("scenes")) << PARTICLES_GOLDEN_FILE << " has no \"scenes\"";
  for (const auto& [name, hash] : computed["scenes"].items()) {
    ASSERT_TRUE(golden["scenes"].contains(name))
        << name << " has no golden hash: regenerate (see the top of this file)";
    EXPECT_EQ(hash, golden["scenes"][name]) << name;
  }
  EXPECT_EQ(golden["scenes"].size(), computed["scenes"].size())
      << "the golden file lists scenes that no longer exist";
  EXPECT_EQ(computed["suite"][kSuiteKey], golden["suite"][kSuiteKey]) << kSuiteKey;
}

// The suite's threads write per-case slots: one thread or two, same results.
TEST(Golden, SuiteResultsHashIndependentOfThreads) {
  EXPECT_EQ(suiteHash(1), suiteHash(2));
}

// `particles run --hash` prints the same hash as the library.
TEST(Golden, RunHashFlagPrintsTheGoldenHash) {
  if (regenerating()) GTEST_SKIP() << "the golden file is being rewritten";
  const json golden = readGolden();
  for (const char* name : {"ball_in_box.json", "gears.json", "newtons_cradle.json"}) {
    const fs::path scene = fs::path(PARTICLES_SCENES_DIR) / name;
    const std::string command =
        std::string("'") + PARTICLES_CLI + "' run --hash '" + scene.string() + "' 2>&1 >/dev/null";
    FILE* pipe = ::popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string err;
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe) != nullptr) err += buf;
    EXPECT_EQ(::pclose(pipe), 0) << err;
    EXPECT_EQ(err, "state-hash: " + golden["scenes"][name].get<std::string>() + "\n") << name;
  }
}

}  // namespace
}  // namespace particles::test
