// The command line of `particles run --engine box2d` and `particles compare`:
// the Box2D twin's final state in the engine's format, range warnings, and
// the event-by-event comparison of both engines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli_support.h"

namespace particles::test {
namespace {

using nlohmann::json;

std::size_t lineCount(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

std::string quotedScene(const std::string& name) {
  return shellQuote(sceneFile(name));
}

// ---- particles run --engine box2d ------------------------------------------------

TEST(CliBox2D, InitialStateIsPrintedLikeTheEngines) {
  // free_flight.json's initial values are all exact floats, so Box2D's state
  // at t = 0 is the engine's, and the same format prints the same bytes.
  const std::string expected =
      R"({"time":0.0,"balls":[{"position":[1.0,2.0],"velocity":[3.0,-1.5],"angle":0.5,)"
      R"("angular_velocity":2.0}]})"
      "\n";
  const CliResult engine = runCli("run " + quotedScene("free_flight.json") + " --duration 0");
  const CliResult box2d =
      runCli("run " + quotedScene("free_flight.json") + " --duration 0 --engine box2d");
  ASSERT_EQ(engine.status, 0) << engine.err;
  ASSERT_EQ(box2d.status, 0) << box2d.err;
  EXPECT_EQ(engine.out, expected);
  EXPECT_EQ(box2d.out, expected);
  EXPECT_EQ(box2d.err, "");
}

TEST(CliBox2D, DefaultEngineIsTheImpulseSolver) {
  const CliResult byDefault = runCli("run " + quotedScene("head_on_spinning.json"));
  const CliResult named =
      runCli("run " + quotedScene("head_on_spinning.json") + " --engine engine");
  ASSERT_EQ(byDefault.status, 0) << byDefault.err;
  EXPECT_EQ(named.status, 0) << named.err;
  EXPECT_EQ(byDefault.out, named.out);
}

TEST(CliBox2D, SameKeysAndOrderAsTheEngine) {
  const CliResult engine = runCli("run " + quotedScene("oblique_floor_hit.json"));
  const CliResult box2d =
      runCli("run " + quotedScene("oblique_floor_hit.json") + " --engine box2d");
  ASSERT_EQ(engine.status, 0) << engine.err;
  ASSERT_EQ(box2d.status, 0) << box2d.err;
  EXPECT_EQ(box2d.err, "");
  EXPECT_EQ(lineCount(box2d.out), 1u);
  // With every number replaced by "#", the two lines are the same text.
  const std::regex number(R"(-?[0-9][0-9.eE+-]*)");
  EXPECT_EQ(std::regex_replace(engine.out, number, "#"),
            std::regex_replace(box2d.out, number, "#"));
  EXPECT_NE(engine.out, box2d.out);  // and the numbers really are Box2D's
}

TEST(CliBox2D, FreeFlightIsAStraightLineToFloatPrecision) {
  // free_flight.json: x0 = (1, 2), v = (3, -1.5), angle0 = 0.5, w = 2, no
  // forces; 2000 steps of dt = 0.001 to t = 2.
  const CliResult r = runCli("run " + quotedScene("free_flight.json") + " --engine box2d");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const json state = json::parse(r.out);
  const double t = state["time"].get<double>();
  EXPECT_EQ(t, 2.0);  // the twin's clock is step index * dt, in double
  const json& ball = state["balls"][0];

  // Box2D integrates c += h v in float (h = dt as a float). With no force the
  // velocity stays exactly (3, -1.5) (both are floats), but every step rounds
  // h v and the sum c + h v to float: each rounding is at most u = 2^-24
  // relative (unit roundoff), so after n steps the position is off by at most
  // n u (max |c| + |h v|), plus u |x0| for storing x0 and u |v| t for h != dt.
  // The factor 2 is a margin; the bound is ~8e-4 m here, far above the
  // engine's double error (~1e-13) and far below a wrong trajectory (|v| dt =
  // 3e-3 m per step).
  const double u = std::ldexp(1.0, -24);
  const double n = 2000.0, dt = 0.001;
  auto tolerance = [&](double x0, double v) {
    const double maxAbs = std::max(std::abs(x0), std::abs(x0 + v * t));
    return 2.0 * (n * u * (maxAbs + std::abs(v) * dt) + u * std::abs(x0) + u * std::abs(v) * t);
  };
  const double x = ball["position"][0].get<double>(), y = ball["position"][1].get<double>();
  const double a = ball["angle"].get<double>();
  EXPECT_NEAR(x, 1.0 + 3.0 * t, tolerance(1.0, 3.0));
  EXPECT_NEAR(y, 2.0 - 1.5 * t, tolerance(2.0, -1.5));
  EXPECT_NEAR(a, 0.5 + 2.0 * t, tolerance(0.5, 2.0));
  EXPECT_EQ(ball["velocity"][0].get<double>(), 3.0);
  EXPECT_EQ(ball["velocity"][1].get<double>(), -1.5);
  EXPECT_EQ(ball["angular_velocity"].get<double>(), 2.0);
}

TEST(CliBox2D, CsvTrajectory) {
  const TempDir dir;
  const std::string csv = dir.file("box2d.csv").string();
  const CliResult r = runCli("run " + quotedScene("free_flight.json") + " --engine box2d --csv " +
                             shellQuote(csv) + " --csv-every 500");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = readFile(csv);
  EXPECT_TRUE(text.starts_with("t,id,x,y,angle,vx,vy,omega\n0,0,1,2,0.5,3,-1.5,2\n0.5,0,")) << text;
  EXPECT_EQ(lineCount(text), 1u + 5u);  // header + steps 0, 500, 1000, 1500, 2000
}

// Ten balls of 5 cm, each below the 0.1 m Box2D is tuned for: the first
// three say so, one more line counts the other seven (a 460-grain hourglass
// printed 460 lines).
TEST(CliBox2D, ManyRangeIssuesOfOneKindAreCounted) {
  const TempDir dir;
  std::string balls;
  for (int i = 0; i < 10; ++i)
    balls += std::string(i ? ", " : "") + R"({"position": [)" + std::to_string(i) +
             R"(, 0], "radius": 0.05, "mass": 1})";
  const std::string scene =
      dir.write("tiny_many.json", R"({"balls": [)" + balls + R"(], "duration": 0.1})");
  const CliResult r = runCli("run " + shellQuote(scene) + " --engine box2d");
  ASSERT_EQ(r.status, 0) << r.err;
  std::size_t radiusLines = 0;
  std::size_t start = 0;
  for (std::size_t end; (end = r.err.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = r.err.substr(start, end - start);
    EXPECT_TRUE(line.starts_with("particles: warning: outside Box2D's range: ")) << line;
    if (line.find("has radius 0.05") != std::string::npos) ++radiusLines;
  }
  EXPECT_EQ(radiusLines, 3u) << r.err;
  EXPECT_NE(r.err.find("outside Box2D's range: 7 more of the same kind (RadiusRange)\n"),
            std::string::npos)
      << r.err;
}

TEST(CliBox2D, SceneOutsideBox2DsRangeIsAWarning) {
  // A 1 cm ball: below the 0.1 m Box2D is tuned for, and near its slop.
  const TempDir dir;
  const std::string scene = dir.write("tiny.json", R"({
    "balls": [{"position": [0, 0], "velocity": [1, 0], "radius": 0.01, "mass": 1}],
    "duration": 0.1})");
  const CliResult r = runCli("run " + shellQuote(scene) + " --engine box2d");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(lineCount(r.out), 1u);
  EXPECT_TRUE(json::parse(r.out).is_object());
  ASSERT_FALSE(r.err.empty());
  std::size_t start = 0;
  for (std::size_t end; (end = r.err.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = r.err.substr(start, end - start);
    EXPECT_TRUE(line.starts_with("particles: warning: outside Box2D's range: ")) << line;
  }
  EXPECT_EQ(start, r.err.size()) << "stderr ends with a newline";
  EXPECT_NE(r.err.find("radius 0.01"), std::string::npos) << r.err;

  // The same scene in the engine: no Box2D, no warning.
  const CliResult engine = runCli("run " + shellQuote(scene));
  EXPECT_EQ(engine.status, 0);
  EXPECT_EQ(engine.err, "");
}

TEST(CliBox2D, UnknownEngineIsAnArgumentError) {
  const CliResult r = runCli("run " + quotedScene("free_flight.json") + " --engine nonsense");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(r.err.starts_with("particles: error: --engine: ")) << r.err;
  EXPECT_NE(r.err.find("nonsense"), std::string::npos) << r.err;
  EXPECT_EQ(lineCount(r.err), 1u);
}

TEST(CliBox2D, IterationsAreCheckedAndOnlyForBox2D) {
  const std::string scene = quotedScene("free_flight.json");
  CliResult r = runCli("run " + scene + " --velocity-iterations 4");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--velocity-iterations: applies only to --engine box2d"), std::string::npos)
      << r.err;
  r = runCli("run " + scene + " --engine box2d --position-iterations -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--position-iterations: must be an integer >= 0"), std::string::npos)
      << r.err;
  r = runCli("run " + scene + " --engine box2d --velocity-iterations 20 --position-iterations 5");
  EXPECT_EQ(r.status, 0) << r.err;
  // One velocity iteration is legal but outside Box2D's range: a warning.
  r = runCli("run " + scene + " --engine box2d --velocity-iterations 1");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.starts_with("particles: warning: outside Box2D's range: ")) << r.err;
}

TEST(CliBox2D, BadSceneIsRejectedAsForTheEngine) {
  const TempDir dir;
  const std::string scene =
      dir.write("bad.json", R"({"balls": [{"position": [0, 0], "radius": -1, "mass": 1}]})");
  const CliResult r = runCli("run " + shellQuote(scene) + " --engine box2d");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "particles: error: " + scene + ": balls[0].radius: must be > 0, got -1\n");
}

TEST(CliBox2D, RunHelpExplainsTheEngines) {
  const CliResult r = runCli("run --help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"--engine", "box2d", "--velocity-iterations", "--position-iterations",
                           "outside Box2D's range"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// ---- particles compare ----------------------------------------------------------

// The first matched event of the pair (a, b, wall), or null.
const json* findMatched(const json& comparison, int a, int b, bool wall) {
  for (const json& m : comparison["matched"]) {
    const json& e = m["engine"];
    if (e["a"] == a && e["b"] == b && e["wall"] == wall) return &m;
  }
  return nullptr;
}

void expectVelocities(const json& body) {
  for (const char* when : {"before", "after"}) {
    ASSERT_TRUE(body.contains(when)) << body.dump();
    ASSERT_EQ(body[when]["velocity"].size(), 2u) << body.dump();
    EXPECT_TRUE(body[when]["velocity"][0].is_number());
    EXPECT_TRUE(body[when]["velocity"][1].is_number());
    EXPECT_TRUE(body[when]["angular_velocity"].is_number());
  }
}

TEST(CliCompare, CradleAndObliqueHit) {
  const TempDir dir;
  const std::string out = dir.file("compare.json").string();
  const CliResult r = runCli("compare " + quotedScene("newtons_cradle.json") + " " +
                             quotedScene("oblique_floor_hit.json") + " --json " + shellQuote(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(r.out.starts_with(sceneFile("newtons_cradle.json") + ": 1000 steps, ")) << r.out;
  EXPECT_NE(r.out.find("\n" + sceneFile("oblique_floor_hit.json") + ": 1000 steps, "),
            std::string::npos)
      << r.out;

  const json all = json::parse(readFile(out));
  ASSERT_TRUE(all.is_array());
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0]["scene"], sceneFile("newtons_cradle.json"));
  EXPECT_EQ(all[1]["scene"], sceneFile("oblique_floor_hit.json"));

  // Newton's cradle: the first pair collides in both engines at the start.
  const json* cradle = findMatched(all[0], 0, 1, false);
  ASSERT_NE(cradle, nullptr) << all[0].dump();
  for (const char* engine : {"engine", "box2d"}) {
    const json& bodies = (*cradle)[engine]["bodies"];
    ASSERT_EQ(bodies.size(), 2u);
    EXPECT_EQ(bodies[0]["ball"], 0);
    EXPECT_EQ(bodies[1]["ball"], 1);
    for (const json& body : bodies) expectVelocities(body);
    // Ball 0 arrives at 2 m/s, ball 1 is at rest.
    EXPECT_EQ(bodies[0]["before"]["velocity"][0].get<double>(), 2.0);
    EXPECT_EQ(bodies[1]["before"]["velocity"][0].get<double>(), 0.0);
  }
  EXPECT_EQ(all[0]["final"].size(), 5u);

  // The oblique floor hit: ball 0 against wall 0, once, in both engines.
  const json& floor = all[1];
  EXPECT_EQ(floor["matched"].size(), 1u) << floor.dump();
  EXPECT_TRUE(floor["engine_only"].empty());
  EXPECT_TRUE(floor["box2d_only"].empty());
  const json* hit = findMatched(floor, 0, 0, true);
  ASSERT_NE(hit, nullptr) << floor.dump();
  for (const char* engine : {"engine", "box2d"}) {
    const json& event = (*hit)[engine];
    EXPECT_EQ(event["a"], 0);
    EXPECT_EQ(event["b"], 0);
    EXPECT_TRUE(event["wall"].get<bool>());
    ASSERT_EQ(event["bodies"].size(), 1u);  // a wall has no velocities
    const json& ball = event["bodies"][0];
    expectVelocities(ball);
    // It comes down and goes up.
    EXPECT_LT(ball["before"]["velocity"][1].get<double>(), 0.0) << engine;
    EXPECT_GT(ball["after"]["velocity"][1].get<double>(), 0.0) << engine;
  }
  EXPECT_TRUE((*hit)["difference"]["velocity"].is_number());
  EXPECT_TRUE((*hit)["difference"]["spin"].is_number());
  EXPECT_TRUE((*hit)["difference"]["relative"].is_number());
  EXPECT_TRUE(floor["outside_box2d_range"].empty());
}

TEST(CliCompare, TextOnlyWithoutJson) {
  const CliResult r = runCli("compare " + quotedScene("oblique_floor_hit.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 matched collision events, 0 engine only, 0 Box2D only"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("balls[0]-walls[0]"), std::string::npos) << r.out;
}

TEST(CliCompare, BadSceneComparesNothing) {
  const TempDir dir;
  const std::string bad =
      dir.write("bad.json", R"({"balls": [{"position": [0, 0], "radius": 1, "mass": -2}]})");
  const std::string out = dir.file("compare.json").string();
  const CliResult r = runCli("compare " + quotedScene("oblique_floor_hit.json") + " " +
                             shellQuote(bad) + " --json " + shellQuote(out));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "particles: error: " + bad + ": balls[0].mass: must be > 0, got -2\n");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliCompare, ArgumentErrors) {
  CliResult r = runCli("compare");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.err.starts_with("particles: error: ")) << r.err;
  r = runCli("compare " + quotedScene("oblique_floor_hit.json") + " --window -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--window: must be an integer >= 0"), std::string::npos) << r.err;
  r = runCli("compare " + quotedScene("oblique_floor_hit.json") +
             " --json /nonexistent/dir/c.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("--json: cannot open '/nonexistent/dir/c.json' for writing"),
            std::string::npos)
      << r.err;
}

TEST(CliCompare, HelpExplainsOutputAndExitCodes) {
  const CliResult r = runCli("compare --help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"--json", "--window", "--velocity-iterations", "--position-iterations",
                           "matched", "Exit status", "m/s", "rad/s"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

}  // namespace
}  // namespace particles::test
