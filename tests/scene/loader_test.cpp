// parseScene / loadScene in-process: defaults, derived values, overrides and
// the exact form of the messages.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cli_support.h"
#include "particles/scenefile.h"

namespace particles {
namespace {

SceneDef parse(const std::string& text) {
  return parseScene(text, "test.json");
}

std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Loader, DefaultsApplied) {
  const SceneDef s = parse(R"({"balls": [{"position": [1, 2], "radius": 0.5, "mass": 3}]})");
  EXPECT_EQ(s.name, "");
  EXPECT_EQ(s.gravity, Vec2(0, 0));
  EXPECT_EQ(s.contact.restitution, 1.0);
  EXPECT_EQ(s.contact.friction, 0.0);
  EXPECT_TRUE(s.walls.empty());
  EXPECT_TRUE(s.forces.empty());
  EXPECT_EQ(s.dt, 0.001);
  EXPECT_EQ(s.duration, 1.0);
  EXPECT_EQ(s.stepCount(), 1000);
  const SolverSettings defaults;
  EXPECT_EQ(s.solver.contactPasses, defaults.contactPasses);
  EXPECT_EQ(s.solver.correctionPasses, defaults.correctionPasses);
  EXPECT_EQ(s.solver.gridThreshold, defaults.gridThreshold);
  ASSERT_EQ(s.balls.size(), 1u);
  const BallDef& b = s.balls[0];
  EXPECT_EQ(b.position, Vec2(1, 2));
  EXPECT_EQ(b.velocity, Vec2(0, 0));
  EXPECT_EQ(b.angle, 0.0);
  EXPECT_EQ(b.angularVelocity, 0.0);
  EXPECT_EQ(b.radius, 0.5);
  EXPECT_EQ(b.mass, 3.0);
  EXPECT_FALSE(b.inertia.has_value());
  EXPECT_EQ(b.resolvedInertia(), 0.5 * 3.0 * 0.25);  // uniform disk, m r^2 / 2
  EXPECT_FALSE(b.restitution.has_value());
  EXPECT_FALSE(b.friction.has_value());
}

TEST(Loader, EveryTopLevelKeyRead) {
  const SceneDef s = parse(R"({
    "name": "all", "gravity": [0.5, -9.81], "contact": {"restitution": 0.25, "friction": 0.75},
    "walls": [{"a": [-5, -1], "b": [5, -1]}],
    "balls": [{"position": [0, 0], "velocity": [1, -2], "angle": 0.5, "angular_velocity": -3,
               "radius": 0.5, "mass": 2}],
    "forces": [{"type": "pull", "ball": 0, "target": [3, 2], "stiffness": 10}],
    "dt": 0.002, "duration": 0.5,
    "solver": {"contact_passes": 7, "correction_passes": 3, "grid_threshold": 0,
               "swept_walls": true, "swept_balls": true, "sequential_impacts": true,
               "velocity_shock": false}})");
  EXPECT_EQ(s.name, "all");
  EXPECT_EQ(s.gravity, Vec2(0.5, -9.81));
  EXPECT_EQ(s.contact.restitution, 0.25);
  EXPECT_EQ(s.contact.friction, 0.75);
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].a, Vec2(-5, -1));
  EXPECT_EQ(s.walls[0].b, Vec2(5, -1));
  EXPECT_EQ(s.balls[0].velocity, Vec2(1, -2));
  EXPECT_EQ(s.balls[0].angle, 0.5);
  EXPECT_EQ(s.balls[0].angularVelocity, -3.0);
  EXPECT_EQ(s.dt, 0.002);
  EXPECT_EQ(s.duration, 0.5);
  EXPECT_EQ(s.stepCount(), 250);
  EXPECT_EQ(s.solver.contactPasses, 7);
  EXPECT_EQ(s.solver.correctionPasses, 3);
  EXPECT_EQ(s.solver.gridThreshold, 0);
  EXPECT_TRUE(s.solver.sweptWalls);
  EXPECT_TRUE(s.solver.sweptBalls);
  EXPECT_TRUE(s.solver.scaleSequentialImpacts);
  EXPECT_FALSE(s.solver.scaleVelocityShock);
}

TEST(Loader, SoftStepKeys) {
  const SceneDef s = parse(R"({"balls": [{"position": [0, 0], "radius": 0.5, "mass": 1}],
    "dt": 0.01, "solver": {"soft_substeps": 4, "soft_contact_hertz": 100,
                           "soft_contact_damping_ratio": 0, "soft_contact_push_speed": 0.5}})");
  EXPECT_EQ(s.solver.scaleSubsteps, 4);
  EXPECT_EQ(s.solver.scaleContactHertz, 100.0);  // exactly the bound: a quarter of 400 Hz
  EXPECT_EQ(s.solver.scaleContactDampingRatio, 0.0);
  EXPECT_EQ(s.solver.scaleContactPushSpeed, 0.5);
}

TEST(Loader, SoftStepOffByDefault) {
  const SceneDef s = parse(R"({"balls": [{"position": [0, 0], "radius": 0.5, "mass": 1}],
    "solver": {"soft_substeps": 2}})");
  const SolverSettings defaults;
  EXPECT_EQ(defaults.scaleSubsteps, 0);
  EXPECT_EQ(s.solver.scaleSubsteps, 2);
  EXPECT_EQ(s.solver.scaleContactHertz, defaults.scaleContactHertz);
  EXPECT_EQ(s.solver.scaleContactDampingRatio, defaults.scaleContactDampingRatio);
  EXPECT_EQ(s.solver.scaleContactPushSpeed, defaults.scaleContactPushSpeed);
}

TEST(Loader, DensityGivesMass) {
  const SceneDef s = parse(R"({"balls": [{"position": [0, 0], "radius": 0.5, "density": 2}]})");
  EXPECT_DOUBLE_EQ(s.balls[0].mass, 2.0 * std::numbers::pi * 0.25);
  EXPECT_DOUBLE_EQ(s.balls[0].resolvedInertia(), 0.5 * s.balls[0].mass * 0.25);
}

TEST(Loader, ExplicitInertiaKept) {
  const SceneDef s =
      parse(R"({"balls": [{"position": [0, 0], "radius": 0.5, "mass": 2, "inertia": 0.5}]})");
  ASSERT_TRUE(s.balls[0].inertia.has_value());
  EXPECT_EQ(*s.balls[0].inertia, 0.5);
  EXPECT_EQ(s.balls[0].resolvedInertia(), 0.5);
}

TEST(Loader, InfiniteFrictionIsNoSlip) {
  const SceneDef s = parse(R"({"contact": {"friction": "infinite"},
    "walls": [{"a": [-5, -1], "b": [5, -1], "friction": "infinite"}],
    "balls": [{"position": [0, 0], "radius": 0.5, "mass": 1, "friction": "infinite"}]})");
  EXPECT_EQ(s.contact.friction, kNoSlip);
  EXPECT_EQ(*s.walls[0].friction, kNoSlip);
  EXPECT_EQ(*s.balls[0].friction, kNoSlip);
  EXPECT_TRUE(std::isinf(s.contact.friction));
}

TEST(Loader, PerBallAndPerWallOverrides) {
  const SceneDef s = parse(R"({"contact": {"restitution": 0.5, "friction": 0.3},
    "walls": [{"a": [-5, -1], "b": [5, -1], "restitution": 0.1, "friction": 0},
              {"a": [-5, 5], "b": [5, 5]}],
    "balls": [{"position": [0, 0], "radius": 0.5, "mass": 1, "restitution": 0.9, "friction": 2},
              {"position": [2, 0], "radius": 0.5, "mass": 1}]})");
  EXPECT_EQ(*s.walls[0].restitution, 0.1);
  EXPECT_EQ(*s.walls[0].friction, 0.0);
  EXPECT_FALSE(s.walls[1].restitution.has_value());
  EXPECT_FALSE(s.walls[1].friction.has_value());
  EXPECT_EQ(*s.balls[0].restitution, 0.9);
  EXPECT_EQ(*s.balls[0].friction, 2.0);
  EXPECT_FALSE(s.balls[1].restitution.has_value());
  EXPECT_FALSE(s.balls[1].friction.has_value());
}

TEST(Loader, BoxAppendsFourWallsAfterTheOthers) {
  const SceneDef s = parse(R"({"walls": [{"a": [-9, -9], "b": [-8, -9]}],
    "box": {"min": [-2, -1], "max": [3, 4], "restitution": 0.7, "friction": "infinite"},
    "balls": [{"position": [0, 0], "radius": 0.5, "mass": 1}]})");
  ASSERT_EQ(s.walls.size(), 5u);
  EXPECT_EQ(s.walls[0].a, Vec2(-9, -9));
  EXPECT_FALSE(s.walls[0].restitution.has_value());
  const std::vector<WallDef> box = boxWalls(Vec2(-2, -1), Vec2(3, 4));
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(s.walls[k + 1].a, box[k].a);
    EXPECT_EQ(s.walls[k + 1].b, box[k].b);
    EXPECT_EQ(*s.walls[k + 1].restitution, 0.7);
    EXPECT_EQ(*s.walls[k + 1].friction, kNoSlip);
    EXPECT_TRUE(s.walls[k + 1].oneSided);  // a box's walls face in
  }
}

TEST(Loader, WallsAreTwoSidedUnlessOneSidedIsSet) {
  const SceneDef s = parse(R"({"walls": [{"a": [-5, -1], "b": [5, -1]},
              {"a": [5, 5], "b": [-5, 5], "one_sided": true},
              {"a": [-5, 6], "b": [5, 6], "one_sided": false}],
    "balls": [{"position": [0, 0], "radius": 0.5, "mass": 1}]})");
  ASSERT_EQ(s.walls.size(), 3u);
  EXPECT_FALSE(s.walls[0].oneSided);
  EXPECT_TRUE(s.walls[1].oneSided);
  EXPECT_FALSE(s.walls[2].oneSided);
}

TEST(Loader, ForceDefaults) {
  const SceneDef s = parse(R"({"balls": [{"position": [0, 0], "radius": 0.5, "mass": 1},
                                         {"position": [3, 0], "radius": 0.5, "mass": 1}],
    "forces": [{"type": "pull", "ball": 1, "target": [3, 2], "stiffness": 10},
               {"type": "constant", "ball": 0},
               {"type": "constant", "ball": 1.0, "force": [1, 2], "torque": -3, "start": 0.5,
                "end": 0.5}]})");
  ASSERT_EQ(s.forces.size(), 3u);
  EXPECT_EQ(s.forces[0].type, ForceType::Pull);
  EXPECT_EQ(s.forces[0].ball, 1);
  EXPECT_EQ(s.forces[0].target, Vec2(3, 2));
  EXPECT_EQ(s.forces[0].stiffness, 10.0);
  EXPECT_EQ(s.forces[0].start, 0.0);
  EXPECT_TRUE(std::isinf(s.forces[0].end));
  EXPECT_EQ(s.forces[1].type, ForceType::Constant);
  EXPECT_EQ(s.forces[1].force, Vec2(0, 0));
  EXPECT_EQ(s.forces[1].torque, 0.0);
  EXPECT_EQ(s.forces[2].ball, 1);  // 1.0 is an integer
  EXPECT_EQ(s.forces[2].force, Vec2(1, 2));
  EXPECT_EQ(s.forces[2].torque, -3.0);
  EXPECT_EQ(s.forces[2].start, 0.5);  // start == end: legal, never active
  EXPECT_EQ(s.forces[2].end, 0.5);
}

TEST(Loader, ExactlyTouchingIsAllowed) {
  EXPECT_NO_THROW(parse(R"({"walls": [{"a": [-5, -0.5], "b": [5, -0.5]}],
    "balls": [{"position": [0, 0], "radius": 0.5, "mass": 1},
              {"position": [1, 0], "radius": 0.5, "mass": 1}]})"));
}

TEST(Loader, OverlapWithinToleranceIsAllowed) {
  // Overlap 1e-10 of the radii sum: rounding, not penetration.
  EXPECT_NO_THROW(parse(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1},
                                      {"position": [1.9999999998, 0], "radius": 1, "mass": 1}]})"));
}

TEST(Loader, MessageFormatOfTheSpec) {
  try {
    parseScene(R"({"balls": [{"position": [0, 0], "radius": 0.5, "mass": 1},
                             {"position": [2, 0], "radius": 0.5, "mass": 1},
                             {"position": [4, 0], "radius": 0.5, "mass": 1},
                             {"position": [6, 0], "radius": -1, "mass": 1}]})",
               "scenes/bad.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "scenes/bad.json: balls[3].radius: must be > 0, got -1");
  }
}

TEST(Loader, SceneErrorIsARuntimeError) {
  EXPECT_THROW(parse("[]"), std::runtime_error);
}

TEST(Loader, NotJsonGivesLineAndColumn) {
  const std::string message = errorOf("{\n\"balls\": [\n}");
  EXPECT_TRUE(message.starts_with("test.json: not valid JSON: parse error at line 3, column 1"))
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(Loader, DuplicateKeyDeepInside) {
  EXPECT_EQ(errorOf(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1},
                                  {"position": [3, 0], "radius": 1, "mass": 1,
                                   "velocity": [1, 0], "velocity": [2, 0]}]})"),
            "test.json: balls[1]: duplicate key 'velocity'");
}

TEST(Loader, OverflowingNumberNamesItsPath) {
  EXPECT_EQ(errorOf(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1}],
                        "gravity": [0, -1e400]})"),
            "test.json: gravity[1]: must be a finite number, got -1e400 (too large for a double)");
}

TEST(Loader, LoadSceneMissingFile) {
  try {
    loadScene("/nonexistent/dir/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/dir/scene.json: cannot open");
  }
}

TEST(Loader, LoadSceneReadsAFile) {
  const test::TempDir dir;
  const std::string file = dir.write(
      "one.json", R"({"name": "one", "balls": [{"position": [0, 0], "radius": 1, "mass": 1}]})");
  EXPECT_EQ(loadScene(file).name, "one");
}

// Many touching balls: the overlap check must not be quadratic, and must
// still find the one overlapping pair at the end.
TEST(Loader, LargeSceneOverlapCheck) {
  constexpr int kSide = 150;  // 22,500 balls in touching rows and columns
  std::string text = R"({"balls": [)";
  for (int i = 0; i < kSide * kSide; ++i) {
    text += i ? ", " : "";
    text += R"({"position": [)" + std::to_string(i % kSide) + ", " + std::to_string(i / kSide) +
            R"(], "radius": 0.5, "mass": 1})";
  }
  EXPECT_EQ(parse(text + "]}").balls.size(), static_cast<std::size_t>(kSide * kSide));
  const std::string overlapping =
      text + R"(, {"position": [148.5, 149], "radius": 0.5, "mass": 1}]})";
  EXPECT_EQ(errorOf(overlapping),
            "test.json: balls[22500]: overlaps balls[22498] by 0.5 m at t = 0 (tolerance 1e-9 of "
            "the radii sum)");
}

TEST(Timing, ChecksShared) {
  EXPECT_NO_THROW(checkTimeStep(1e-3, "--dt"));
  EXPECT_THROW(checkTimeStep(0.0, "--dt"), SceneError);
  EXPECT_THROW(checkTimeStep(std::nan(""), "--dt"), SceneError);
  EXPECT_NO_THROW(checkDuration(0.0, "--duration"));
  EXPECT_THROW(checkDuration(-1e-9, "--duration"), SceneError);
  EXPECT_THROW(checkDuration(INFINITY, "--duration"), SceneError);
  EXPECT_NO_THROW(checkStepCount(1e6, 1e-9, "x"));
  EXPECT_THROW(checkStepCount(1e10, 1e-10, "x"), SceneError);
  try {
    checkTimeStep(-2, "--dt");
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "--dt: must be > 0, got -2");
  }
}

}  // namespace
}  // namespace particles
