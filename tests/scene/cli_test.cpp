// The command line of `particles run`: help, argument errors, overrides,
// output formats, the warning and the divergence error.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "cli_support.h"

namespace particles::test {
namespace {

std::size_t lineCount(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

void expectArgumentError(const CliResult& r, const std::string& problem) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(r.err.starts_with("particles: error: ")) << r.err;
  EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
  EXPECT_EQ(lineCount(r.err), 1u) << r.err;
}

TEST(Cli, HelpMentionsRun) {
  const CliResult r = runCli("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("run"), std::string::npos);
  EXPECT_NE(r.out.find("Exit status"), std::string::npos);
}

TEST(Cli, RunHelpExplainsOptionsAndExitCodes) {
  const CliResult r = runCli("run --help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"--dt", "--duration", "--csv", "--csv-every", "SCENE.json", "0 ", "1 ",
                           "2 ", "t,id,x,y,angle,vx,vy,omega"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST(Cli, NoSubcommand) {
  expectArgumentError(runCli(""), "a subcommand is required");
}

TEST(Cli, UnknownSubcommand) {
  expectArgumentError(runCli("frobnicate"), "frobnicate");
}

TEST(Cli, UnknownOption) {
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --bogus"),
                      "--bogus");
}

TEST(Cli, MissingSceneArgument) {
  expectArgumentError(runCli("run"), "scene");
}

TEST(Cli, TimeStepNotANumber) {
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --dt abc"),
                      "--dt");
}

TEST(Cli, TimeStepOverrideValidated) {
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --dt=0"),
                      "--dt: must be > 0, got 0");
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --dt nan"),
                      "--dt: must be a finite number");
}

TEST(Cli, DurationOverrideValidated) {
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --duration=-1"),
                      "--duration: must be >= 0, got -1");
  expectArgumentError(
      runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --duration 1e300"),
      "does not fit in the 64-bit step counter");
}

TEST(Cli, CsvEveryValidated) {
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --csv-every 0"),
                      "--csv-every: must be an integer >= 1, got 0");
}

TEST(Cli, CsvFileNotWritable) {
  expectArgumentError(runCli("run " + shellQuote(sceneFile("free_flight.json")) +
                             " --csv /nonexistent/dir/out.csv"),
                      "--csv: cannot open '/nonexistent/dir/out.csv' for writing");
}

TEST(Cli, OverridesReplaceTheFilesTiming) {
  // free_flight.json: dt 0.001, duration 2. With dt 0.01 and duration 0.5: 50 steps.
  const CliResult r =
      runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --dt 0.01 --duration 0.5");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json state = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(state["time"].get<double>(), 0.5);
  EXPECT_NEAR(state["balls"][0]["position"][0].get<double>(), 1.0 + 3.0 * 0.5, 1e-12);
}

TEST(Cli, ZeroDurationPrintsTheInitialState) {
  const CliResult r = runCli("run " + shellQuote(sceneFile("free_flight.json")) + " --duration 0");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            R"({"time":0.0,"balls":[{"position":[1.0,2.0],"velocity":[3.0,-1.5],"angle":0.5,)"
            R"("angular_velocity":2.0}]})"
            "\n");
}

TEST(Cli, FinalStateIsOneLineOfJson) {
  const CliResult r = runCli("run " + shellQuote(sceneFile("head_on_spinning.json")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(lineCount(r.out), 1u);
  EXPECT_EQ(r.out.back(), '\n');
  const nlohmann::json state = nlohmann::json::parse(r.out);
  ASSERT_EQ(state.size(), 2u);
  ASSERT_EQ(state["balls"].size(), 2u);
  for (const auto& ball : state["balls"]) {
    EXPECT_EQ(ball.size(), 4u);
    EXPECT_EQ(ball["position"].size(), 2u);
    EXPECT_EQ(ball["velocity"].size(), 2u);
    EXPECT_TRUE(ball["angle"].is_number());
    EXPECT_TRUE(ball["angular_velocity"].is_number());
  }
}

TEST(Cli, CsvTrajectory) {
  const TempDir dir;
  const std::string csv = dir.file("out.csv").string();
  // newtons_cradle.json: 1000 steps, 5 balls; rows at t = 0 and every 300 steps.
  const CliResult r = runCli("run " + shellQuote(sceneFile("newtons_cradle.json")) + " --csv " +
                             shellQuote(csv) + " --csv-every 300");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = readFile(csv);
  EXPECT_TRUE(text.starts_with("t,id,x,y,angle,vx,vy,omega\n0,0,0,0,0,2,0,0\n0,1,1,0,0,0,0,0\n"))
      << text.substr(0, 200);
  EXPECT_EQ(lineCount(text), 1u + 5u * 4u);  // header + 5 balls at steps 0, 300, 600, 900
  // Ball 4 at x = 4 + 2 * 0.9, to rounding.
  EXPECT_NE(text.find("\n0.9,4,5.7999999999998"), std::string::npos) << text;
}

TEST(Cli, PassLimitWarning) {
  // A cradle hit from the right: the impulse travels against the contact
  // order, so one pass per step cannot settle it.
  const TempDir dir;
  const std::string scene = dir.write("reverse_cradle.json", R"({
    "solver": {"contact_passes": 1},
    "balls": [{"position": [0, 0], "radius": 0.5, "mass": 1},
              {"position": [1, 0], "radius": 0.5, "mass": 1},
              {"position": [2, 0], "radius": 0.5, "mass": 1},
              {"position": [3, 0], "velocity": [-1, 0], "radius": 0.5, "mass": 1}],
    "duration": 0.01})");
  const CliResult r = runCli("run " + shellQuote(scene));
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(lineCount(r.out), 1u);
  EXPECT_TRUE(r.err.starts_with("particles: warning: the contact-pass bound (1) was reached in "))
      << r.err;
  EXPECT_NE(r.err.find(" steps; velocities may still approach there\n"), std::string::npos);
}

TEST(Cli, DivergenceIsReportedNotPrinted) {
  // The first step's force overflows the velocity to infinity.
  const TempDir dir;
  const std::string scene = dir.write("diverge.json", R"({
    "balls": [{"position": [0, 0], "velocity": [1e308, 0], "radius": 1, "mass": 1e-300}],
    "forces": [{"type": "constant", "ball": 0, "force": [1e308, 0]}],
    "duration": 5})");
  const CliResult r = runCli("run " + shellQuote(scene));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "particles: error: " + scene +
                       ": the simulation diverged (non-finite state) at step 1 (t = 0.001 s)\n");
}

}  // namespace
}  // namespace particles::test
