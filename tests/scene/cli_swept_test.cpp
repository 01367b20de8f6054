// Scene files carry the continuous-collision switches (solver.swept_walls,
// solver.swept_balls), and `particles stress --swept-walls` writes them into
// its broken scenes, so `particles run` replays what stress ran.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "cli_support.h"

namespace particles::test {
namespace {

using nlohmann::json;

// A ball of radius 0.5 at x = 0 at 2500 m/s (5 radii per 1 ms step) toward a
// wall at x = 2, e = 1, for 3 steps. Swept, it bounces at t = 0.6 ms and ends
// at x = 1.5 - 2500 (3 ms - 0.6 ms) = -4.5; discrete, it is through the wall.
std::string fastBallAtWall(const char* swept) {
  return std::string(R"({"walls": [{"a": [2, -5], "b": [2, 5]}],
    "balls": [{"position": [0, 0], "velocity": [2500, 0], "radius": 0.5, "mass": 1}],
    "dt": 0.001, "duration": 0.003, "solver": {"swept_walls": )") +
         swept + "}}";
}

double finalX(const CliResult& r) {
  return json::parse(r.out)["balls"][0]["position"][0].get<double>();
}

// `particles run` on the scene with its switch on and off: ball 0's final x
// of each run.
struct OnAndOff {
  double on = 0.0, off = 0.0;
};
OnAndOff finalXOnAndOff(std::string (*scene)(const char* swept)) {
  TempDir dir;
  const CliResult on = runCli("run " + shellQuote(dir.write("on.json", scene("true"))));
  const CliResult off = runCli("run " + shellQuote(dir.write("off.json", scene("false"))));
  EXPECT_EQ(on.status, 0) << on.err;
  EXPECT_EQ(off.status, 0) << off.err;
  if (on.status != 0 || off.status != 0) return {NAN, NAN};
  return {finalX(on), finalX(off)};
}

TEST(CliSwept, SweptWallsFromTheSceneFile) {
  const OnAndOff x = finalXOnAndOff(fastBallAtWall);
  EXPECT_NEAR(x.on, -4.5, 1e-9);
  EXPECT_GT(x.off, 2.0);
}

// Two equal balls closing at 2500 m/s (5 radii per step), e = 1, 3 steps:
// swept, they meet at t = 0.4 ms and exchange velocities (ball 0 ends at
// 2000 * 0.4e-3 - 500 * 2.6e-3 = -0.5 m); discrete, they pass through.
std::string fastBalls(const char* swept) {
  return std::string(R"({"balls": [
      {"position": [0, 0], "velocity": [2000, 0], "radius": 0.5, "mass": 1},
      {"position": [2, 0], "velocity": [-500, 0], "radius": 0.5, "mass": 1}],
    "dt": 0.001, "duration": 0.003, "solver": {"swept_balls": )") +
         swept + "}}";
}

TEST(CliSwept, SweptBallsFromTheSceneFile) {
  const OnAndOff x = finalXOnAndOff(fastBalls);
  EXPECT_NEAR(x.on, -0.5, 1e-9);
  EXPECT_GT(x.off, 2.0);
}

// The wall case that tunnels in the discrete engine is stable with
// --swept-walls; its scene is still written (Box2D tunnels), records the
// switch, and replays the bounce.
TEST(CliSwept, StressWritesTheSwitchIntoTheBrokenScenes) {
  TempDir dir;
  const std::string out = dir.file("out").string();
  const CliResult r = runCli("stress --swept-walls --out " + shellQuote(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string scene = out + "/broken/speed__wall__5_r_step.json";
  const json j = json::parse(readFile(scene));
  EXPECT_EQ(j["solver"]["swept_walls"], true);
  const CliResult replay = runCli("run " + shellQuote(scene));
  ASSERT_EQ(replay.status, 0) << replay.err;
  EXPECT_LT(finalX(replay), 2.0) << "the replay bounced, as stress saw";
}

}  // namespace
}  // namespace particles::test
