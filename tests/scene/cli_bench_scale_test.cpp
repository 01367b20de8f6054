// particles bench --scale through the real binary: bad arguments are exit 2
// with nothing run; a tiny run prints its table and writes one CSV row per
// engine run.
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.h"

namespace particles::test {
namespace {

void expectBadInput(const std::string& args, const std::string& problem) {
  const CliResult r = runCli(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_EQ(r.out, "") << args;
  EXPECT_NE(r.err.find(problem), std::string::npos) << args << "\ngot: " << r.err;
}

TEST(CliBenchScale, BadArgumentsAreExitTwo) {
  expectBadInput("bench --scale --n 0 --csv ''", "--n");
  expectBadInput("bench --scale --n ten --csv ''", "--n");
  expectBadInput("bench --scale --threads 0 --csv ''", "--threads");
  expectBadInput("bench --scale --steps -1 --csv ''", "--steps");
  expectBadInput("bench --scale --frob", "frob");
  // CLI::Range would let NaN through (every comparison with it is false).
  expectBadInput("bench --scale --shock nan --csv ''", "--shock");
  expectBadInput("bench --scale --shock 1.5 --csv ''", "--shock");
  expectBadInput("bench --scale --shock inf --csv ''", "--shock");
  expectBadInput("bench --scale --seeds 0 --csv ''", "--seeds");
  expectBadInput("bench --scale --seeds two --csv ''", "--seeds");
  expectBadInput("bench --scale --substeps 0 --csv ''", "--substeps");
  expectBadInput("bench --scale --substeps 65 --csv ''", "--substeps");
  expectBadInput("bench --scale --contact-hertz nan --csv ''", "--contact-hertz");
  expectBadInput("bench --scale --contact-hertz 0 --csv ''", "--contact-hertz");
  // The soft step has substeps, not iterations.
  expectBadInput("bench --scale --substeps 4 --iterations 8 --csv ''", "--iterations");
  expectBadInput("bench --scale --repeats 0 --csv ''", "--repeats");
  expectBadInput("bench --scale --repeats 1001 --csv ''", "--repeats");
}

// Without --scale, bench is the catalogue benchmark: an option of the pile's
// must not silently run that instead, nor the catalogue's run the pile.
TEST(CliBenchScale, OptionsOfTheOtherBenchmarkAreExitTwo) {
  expectBadInput("bench --n 10", "--n needs --scale");
  expectBadInput("bench --threads 2", "--threads needs --scale");
  expectBadInput("bench --shock 0.5", "--shock needs --scale");
  expectBadInput("bench --seeds 3", "--seeds needs --scale");
  expectBadInput("bench --no-velocity-shock", "--no-velocity-shock needs --scale");
  expectBadInput("bench --no-settle-iteration", "--no-settle-iteration needs --scale");
  expectBadInput("bench --sequential-impacts", "--sequential-impacts needs --scale");
  expectBadInput("bench --band-rows 2", "--band-rows needs --scale");
  expectBadInput("bench --fast-pair-cells 1", "--fast-pair-cells needs --scale");
  expectBadInput("bench --no-wavefront", "--no-wavefront needs --scale");
  expectBadInput("bench --substeps 4", "--substeps needs --scale");
  expectBadInput("bench --contact-hertz 60", "--contact-hertz needs --scale");
  expectBadInput("bench --scale --n 10 --full", "--full is an option of the catalogue benchmark");
}

TEST(CliBenchScale, UnwritableCsvIsExitTwo) {
  expectBadInput("bench --scale --n 10 --steps 1 --csv /nonexistent-dir/pile.csv", "--csv");
}

// The fields of a CSV line (0-based).
std::vector<std::string> fieldsOf(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream fields(line);
  std::string field;
  while (std::getline(fields, field, ',')) out.push_back(field);
  return out;
}

TEST(CliBenchScale, TinyRunWritesTableAndCsv) {
  TempDir dir;
  const std::string csv = dir.file("pile.csv").string();
  const CliResult r =
      runCli("bench --scale --n 60 --threads 1 2 --steps 4 --csv " + shellQuote(csv));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("engine"), std::string::npos);
  EXPECT_NE(r.out.find("box2d"), std::string::npos);
  const std::string text = readFile(csv);
  EXPECT_TRUE(text.starts_with("engine,n,polydisperse,threads,velocity_iterations,steps,")) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;  // header, T=1, T=2, box2d
  EXPECT_NE(text.find("\nengine,60,0,2,8,4,"), std::string::npos) << text;
  EXPECT_NE(text.find("\nbox2d,60,0,1,8,4,"), std::string::npos) << text;
}

// The soft step's run is a row of its own: engine "soft", K its substeps,
// with its ratios to the Box2D run.
TEST(CliBenchScale, SoftStepRunIsASoftRow) {
  TempDir dir;
  const std::string csv = dir.file("pile.csv").string();
  const CliResult r =
      runCli("bench --scale --n 60 --steps 4 --substeps 4 --csv " + shellQuote(csv));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nsoft "), std::string::npos) << r.out;
  const std::string text = readFile(csv);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;  // header, soft, box2d
  const std::size_t at = text.find("\nsoft,60,0,1,4,4,");
  ASSERT_NE(at, std::string::npos) << text;
  const std::string line = text.substr(at + 1, text.find('\n', at + 1) - at - 1);
  // speed_ratio_engine_over_box2d (field 18) is filled in.
  const std::vector<std::string> fields = fieldsOf(line);
  ASSERT_GT(fields.size(), 18u) << line;
  EXPECT_FALSE(fields[18].empty()) << line;
}

// A CSV line without the fields of the ranges `drop` ([first, last], 0-based);
// each field kept ends with a comma.
std::string withoutFields(const std::string& line,
                          std::initializer_list<std::pair<int, int>> drop) {
  const std::vector<std::string> fields = fieldsOf(line);
  std::string kept;
  for (int i = 0; i < static_cast<int>(fields.size()); ++i)
    if (std::none_of(drop.begin(), drop.end(),
                     [i](const auto& range) { return range.first <= i && i <= range.second; }))
      kept += fields[static_cast<std::size_t>(i)] + ",";
  return kept;
}

// The CSV's fields (0-based) that hold timings: ms 0-299, ms 300+ and
// disk-steps/s (6 to 8); the slowest and fastest run's disk-steps/s (23, 24).
constexpr int kTimingFirst = 6, kTimingLast = 8, kSpreadFirst = 23, kSpreadLast = 24;

// Every CSV line of `engine` with its timing fields left out: they differ
// from run to run, nothing else may. The fields kept end with a comma each.
std::vector<std::string> figuresBySeed(const std::string& csv, const std::string& engine) {
  std::vector<std::string> lines;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // the header, whose first column is named "engine" too
  while (std::getline(in, line)) {
    if (!line.starts_with(engine + ",")) continue;
    lines.push_back(
        withoutFields(line, {{kTimingFirst, kTimingLast}, {kSpreadFirst, kSpreadLast}}));
  }
  return lines;
}

// --seeds 2 runs the seeds S and S + 1: the same figures, bit for bit, as two
// runs with --seed S and --seed S + 1, and a summary over both.
TEST(CliBenchScale, SeedsRunsConsecutiveSeedsAndSummarises) {
  TempDir dir;
  const std::string both = dir.file("both.csv").string(), second = dir.file("second.csv").string();
  const std::string common = "bench --scale --n 60 --threads 1 --steps 20 --no-box2d --csv ";
  const CliResult r = runCli(common + shellQuote(both) + " --seed 7 --seeds 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("over 2 seeds:"), std::string::npos) << r.out;
  ASSERT_EQ(runCli(common + shellQuote(second) + " --seed 8").status, 0);
  const std::vector<std::string> two = figuresBySeed(readFile(both), "engine");
  const std::vector<std::string> one = figuresBySeed(readFile(second), "engine");
  ASSERT_EQ(two.size(), 2u);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NE(two[0].find(",7,1,"), std::string::npos) << two[0];  // seed 7, one run
  EXPECT_EQ(two[1], one[0]);
  EXPECT_NE(two[0], two[1]);  // another seed, another pile
}

// --iterations K... runs the engine once per value (and thread count)
// against one Box2D run: each run is the run with that single value, bit for
// bit (its figures; the timings differ from run to run).
TEST(CliBenchScale, IterationsRunsOneEngineRunPerValue) {
  TempDir dir;
  const std::string both = dir.file("both.csv").string(), one = dir.file("one.csv").string();
  const std::string common = "bench --scale --n 60 --threads 1 --steps 30 --csv ";
  const CliResult r = runCli(common + shellQuote(both) + " --iterations 2 8");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(runCli(common + shellQuote(one) + " --iterations 8 --no-box2d").status, 0);
  const std::vector<std::string> runs = figuresBySeed(readFile(both), "engine");
  const std::vector<std::string> single = figuresBySeed(readFile(one), "engine");
  ASSERT_EQ(runs.size(), 2u);
  ASSERT_EQ(single.size(), 1u);
  EXPECT_TRUE(runs[0].starts_with("engine,60,0,1,2,30,")) << runs[0];
  EXPECT_TRUE(runs[1].starts_with("engine,60,0,1,8,30,")) << runs[1];
  // Without Box2D the two ratio columns (15 and 16 once the timings are left
  // out) are empty; the rest is the same.
  EXPECT_EQ(withoutFields(runs[1], {{15, 16}}), withoutFields(single[0], {{15, 16}}));
  EXPECT_NE(runs[0], runs[1]);
  const std::string text = readFile(both);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;  // header, K=2, K=8, box2d
  expectBadInput("bench --scale --iterations 0 --csv ''", "--iterations");
}

// --repeats R runs each engine configuration R times: the timings are the
// medians, with the slowest and fastest run's disk-steps/s beside them, and
// every other figure is that of one run, bit for bit: the runs, and the runs
// with 1 and 2 threads, end in the same state (the hash column).
TEST(CliBenchScale, RepeatsGiveMediansAndOneState) {
  TempDir dir;
  const std::string three = dir.file("three.csv").string(), once = dir.file("once.csv").string();
  // From SolverSettings::scaleParallelFrom (5,000 disks) on, so that T = 2
  // runs two threads.
  const std::string common = "bench --scale --n 5000 --threads 1 2 --steps 12 --no-box2d --csv ";
  const CliResult r = runCli(common + shellQuote(three) + " --repeats 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("state hash"), std::string::npos) << r.out;
  ASSERT_EQ(runCli(common + shellQuote(once)).status, 0);
  const std::string text = readFile(three);
  EXPECT_NE(text.find(",repeats,disk_steps_per_s_min,disk_steps_per_s_max,state_hash\n"),
            std::string::npos)
      << text;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> runs;
  while (std::getline(in, line)) runs.push_back(fieldsOf(line));
  ASSERT_EQ(runs.size(), 2u) << text;
  for (const std::vector<std::string>& f : runs) {
    ASSERT_EQ(f.size(), 26u) << text;
    EXPECT_EQ(f[22], "3");
    const double median = std::stod(f[8]), slowest = std::stod(f[23]), fastest = std::stod(f[24]);
    EXPECT_GT(slowest, 0.0);
    EXPECT_LE(slowest, median);
    EXPECT_LE(median, fastest);
    EXPECT_EQ(f[25].size(), 16u);
  }
  EXPECT_EQ(runs[0][3], "1");
  EXPECT_EQ(runs[1][3], "2");
  EXPECT_EQ(runs[0][25], runs[1][25]);  // 1 and 2 threads: one state
  // One run each: the same figures but the count of runs.
  const std::vector<std::string> repeated = figuresBySeed(text, "engine");
  const std::vector<std::string> single = figuresBySeed(readFile(once), "engine");
  ASSERT_EQ(single.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    // Field 22 (repeats) is field 19 once the timings 6-8 are left out.
    EXPECT_EQ(withoutFields(repeated[i], {{19, 19}}), withoutFields(single[i], {{19, 19}}));
    EXPECT_NE(repeated[i], single[i]);
  }
}

// --sequential-impacts reaches the engine: the pile of 1,000 disks landing
// (its first impacts in mid-air meet in groups the setting replays) ends in
// another state than with the passes alone, and the same one on two threads.
TEST(CliBenchScale, SequentialImpactsReachTheEngine) {
  TempDir dir;
  const auto hashes = [&](const std::string& extra) {
    const std::string csv = dir.file("pile.csv").string();
    const CliResult r = runCli("bench --scale --n 1000 --threads 1 2 --steps 120 --no-box2d" +
                               extra + " --csv " + shellQuote(csv));
    EXPECT_EQ(r.status, 0) << r.err;
    std::istringstream in(readFile(csv));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> out;
    while (std::getline(in, line)) {
      const std::vector<std::string> f = fieldsOf(line);
      if (f.size() == 26u) out.push_back(f[25]);
    }
    return out;
  };
  const std::vector<std::string> passes = hashes(""), sequence = hashes(" --sequential-impacts");
  ASSERT_EQ(passes.size(), 2u);
  ASSERT_EQ(sequence.size(), 2u);
  EXPECT_EQ(sequence[0], sequence[1]);
  EXPECT_NE(sequence[0], passes[0]);
}

}  // namespace
}  // namespace particles::test
