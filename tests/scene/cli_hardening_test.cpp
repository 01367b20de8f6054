// Issue 7 on the command line: `run --hash` and `--max-steps`, and
// `suite --shard K/N` + `merge` giving the report of one run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.h"

namespace particles::test {
namespace {

using nlohmann::json;

TEST(CliHash, PrintsTheStateHashOnStderrOnly) {
  const std::string scene = shellQuote(sceneFile("free_flight.json"));
  const CliResult plain = runCli("run " + scene);
  const CliResult hashed = runCli("run --hash " + scene);
  ASSERT_EQ(hashed.status, 0) << hashed.err;
  EXPECT_EQ(hashed.out, plain.out) << "stdout stays exactly as documented";
  EXPECT_TRUE(std::regex_match(hashed.err, std::regex("state-hash: [0-9a-f]{16}\n"))) << hashed.err;
  EXPECT_EQ(runCli("run --hash " + scene).err, hashed.err);

  const CliResult box2d = runCli("run --hash --engine box2d " + scene);
  ASSERT_EQ(box2d.status, 0) << box2d.err;
  EXPECT_NE(box2d.err.find("state-hash: "), std::string::npos) << box2d.err;
  EXPECT_NE(box2d.err, hashed.err) << "float Box2D differs from the double engine";
}

TEST(CliMaxSteps, RefusesRunsLongerThanTheGuard) {
  const TempDir dir;
  // 1e12 steps: legal (fits the step counter) but days of work.
  const std::string scene = dir.write(
      "long.json",
      R"({"balls": [{"position": [0, 0], "radius": 0.5, "mass": 1}], "dt": 1e-3, "duration": 1e9})");
  const CliResult r = runCli("run " + shellQuote(scene));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "particles: error: " + scene +
                       ": duration / dt = 1000000000000 steps, more than --max-steps 100000000; "
                       "raise --max-steps, or 0 for no limit\n");

  const std::string s1000 = shellQuote(sceneFile("free_flight.json"));  // 2000 steps
  EXPECT_EQ(runCli("run --max-steps 1999 " + s1000).status, 2);
  EXPECT_EQ(runCli("run --max-steps 2000 " + s1000).status, 0);
  EXPECT_EQ(runCli("run --max-steps 0 --duration 1e-3 " + s1000).status, 0);
  EXPECT_EQ(runCli("run --max-steps -1 " + s1000).status, 2);
}

// A legal scene (a ball of mass 1e-312, whose inverse overflows) that
// diverges inside a step of a grid-sized scene: the broad phase once cast
// the NaN positions to cell indices and wrote out of bounds (segfault).
TEST(CliDivergence, NanPositionsInTheGridAreADivergenceNotACrash) {
  for (const char* name :
       {"crash-denormal-mass-nan-in-grid-1.json", "crash-denormal-mass-nan-in-grid-2.json"}) {
    const std::string file =
        std::string(PARTICLES_SCENES_DIR) + "/../tests/fuzz_regressions/inputs/" + name;
    const CliResult r = runCli("run " + shellQuote(file));
    EXPECT_EQ(r.status, 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find("the simulation diverged (non-finite state) at step 1"), std::string::npos)
        << r.err;
  }
}

// report.json without its "timing" object, as text: the rest must match
// byte for byte.
std::string withoutTiming(const std::string& text) {
  const std::size_t start = text.find("\n \"timing\": {");
  const std::size_t end = text.find("\n }", start + 1);
  if (start == std::string::npos || end == std::string::npos) return text;
  return text.substr(0, start) + text.substr(end + 3);
}

// report.md without its speed line.
std::string withoutSpeed(const std::string& text) {
  return std::regex_replace(text, std::regex("\nSpeed, [^\n]*\n"), "\n");
}

TEST(CliShards, ThreeShardsMergeIntoTheSingleRunReport) {
  const TempDir dir;
  const std::string cases = "--cases 50 --jobs 2";
  const CliResult single = runCli("suite " + cases + " --report " + shellQuote(dir.file("single")));
  ASSERT_EQ(single.status, 0) << single.out << single.err;
  std::vector<std::string> shards;
  for (int k = 1; k <= 3; ++k) {
    const std::string out = dir.file("shard-" + std::to_string(k));
    const CliResult r = runCli("suite " + cases + " --shard " + std::to_string(k) + "/3 --report " +
                               shellQuote(out));
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    const json j = json::parse(readFile(out + "/report.json"));
    EXPECT_EQ(j["shard"], json({{"index", k}, {"count", 3}}));
    EXPECT_EQ(j["case_records"], "all");
    EXPECT_EQ(j["mutants"].empty(), k != 1) << "the mutation check runs in shard 1 only";
    shards.push_back(shellQuote(out));
  }
  // In any order.
  const CliResult merged = runCli("merge " + shards[1] + ' ' + shards[2] + ' ' + shards[0] +
                                  " --report " + shellQuote(dir.file("merged")));
  ASSERT_EQ(merged.status, 0) << merged.out << merged.err;
  EXPECT_NE(merged.out.find("Merged 3 shard reports."), std::string::npos) << merged.out;

  const std::string a = readFile(dir.file("single") / "report.json");
  const std::string b = readFile(dir.file("merged") / "report.json");
  ASSERT_TRUE(withoutTiming(a) != a) << "no timing block found";
  EXPECT_TRUE(withoutTiming(a) == withoutTiming(b)) << "report.json differs beyond \"timing\"";
  EXPECT_EQ(json::parse(b)["timing"]["shards"], 3);
  EXPECT_EQ(json::parse(b)["timing"]["cases"], json::parse(a)["timing"]["cases"]);
  const std::string mdA = readFile(dir.file("single") / "report.md");
  const std::string mdB = readFile(dir.file("merged") / "report.md");
  EXPECT_TRUE(withoutSpeed(mdA) != mdA) << "no speed line found";
  EXPECT_TRUE(withoutSpeed(mdA) == withoutSpeed(mdB)) << "report.md differs beyond the speed line";
  // index.html holds no timing at all: identical.
  const std::string htmlA = readFile(dir.file("single") / "index.html");
  EXPECT_NE(htmlA.find("<table>"), std::string::npos);
  EXPECT_TRUE(htmlA == readFile(dir.file("merged") / "index.html")) << "index.html differs";
}

class CliMergeRefuses : public ::testing::Test {
 protected:
  // A small shard run; returns its report directory.
  std::string shard(const std::string& name, const std::string& args) {
    const std::string out = dir_.file(name);
    const CliResult r =
        runCli("suite --cases 5 --no-mutants --jobs 1 " + args + " --report " + shellQuote(out));
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    return shellQuote(out);
  }
  CliResult merge(const std::string& inputs) {
    return runCli("merge " + inputs + " --report " + shellQuote(dir_.file("merged")));
  }
  void expectRefusal(const std::string& inputs, const std::string& why) {
    const CliResult r = merge(inputs);
    EXPECT_EQ(r.status, 2) << r.out << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(r.err.starts_with("particles: error: ")) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  }
  TempDir dir_;
};

TEST_F(CliMergeRefuses, NotableRecords) {
  expectRefusal(shard("a", "--shard 1/2 --records notable") + " " + shard("b", "--shard 2/2"),
                "notable");
}

TEST_F(CliMergeRefuses, MissingAndDuplicateShards) {
  const std::string one = shard("one", "--shard 1/3"), two = shard("two", "--shard 2/3");
  expectRefusal(one + " " + two, "missing shard(s) 3 of 3");
  expectRefusal(one + " " + one, "a shard given twice");
  expectRefusal(one + " " + shard("x", "--shard 2/2"), "shards of different runs");
}

TEST_F(CliMergeRefuses, DifferentSettings) {
  expectRefusal(shard("a", "--shard 1/2 --seed 1") + " " + shard("b", "--shard 2/2 --seed 2"),
                "other settings than");
  expectRefusal(shard("c", "--shard 1/2") + " " + shard("d", "--shard 2/2 --velocity-iterations 9"),
                "settings.box2d_velocity_iterations = 9 vs 8");
}

TEST_F(CliMergeRefuses, EditedOrBrokenReports) {
  const std::string a = shard("a", "--shard 1/2"), b = shard("b", "--shard 2/2");
  EXPECT_EQ(merge(a + " " + b).status, 0);
  // A record whose verdict was edited no longer gives the file's summary.
  const std::filesystem::path file = dir_.file("b") / "report.json";
  json j = json::parse(readFile(file));
  j["cases"][0]["pass"] = false;
  writeFile(file, j.dump(1));
  expectRefusal(a + " " + b, "does not follow from the report's own case records");
  // A truncated file.
  writeFile(file, readFile(file).substr(0, 100));
  expectRefusal(a + " " + b, "not valid JSON");
  expectRefusal(a + " " + shellQuote(dir_.file("nowhere")), "cannot open");
}

TEST(CliShards, BadShardArguments) {
  for (const char* bad : {"0/3", "4/3", "1/0", "a/b", "1", "1/3/4", "1/2000000"}) {
    const CliResult r =
        runCli(std::string("suite --cases 1 --shard ") + bad + " --report /nonexistent");
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--shard: must be K/N with integers 1 <= K <= N"), std::string::npos)
        << r.err;
  }
}

}  // namespace
}  // namespace particles::test
