// Every kind of bad scene file, through the real binary: exit status 2,
// nothing on stdout, and one stderr line "particles: error: FILE: PATH: ..."
// that names the file, the JSON path and the problem.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_support.h"

namespace particles::test {
namespace {

// A ball that is fine on its own, and a scene made of it plus `extra` keys.
constexpr const char* kBall = R"({"position": [0, 0], "radius": 1, "mass": 1})";
std::string withBall(const std::string& extra) {
  return std::string(R"({"balls": [)") + kBall + "]" + (extra.empty() ? "" : ", " + extra) + "}";
}

class Rejection : public ::testing::Test {
 protected:
  // `path` is the JSON path expected after the file name ("" when the message
  // is about the file as a whole); `problem` must appear in the message.
  void expectRejected(const std::string& json, const std::string& path,
                      const std::string& problem) {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    expectRejectedFile(dir_.write(name + ".json", json), path, problem);
  }

  void expectRejectedFile(const std::string& file, const std::string& path,
                          const std::string& problem) {
    const CliResult r = runCli("run " + shellQuote(file));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    const std::string prefix =
        "particles: error: " + file + ": " + (path.empty() ? "" : path + ": ");
    EXPECT_TRUE(r.err.starts_with(prefix)) << "expected prefix: " << prefix << "\ngot: " << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos)
        << "expected: " << problem << "\ngot: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }

  TempDir dir_;
};

TEST_F(Rejection, MissingFile) {
  expectRejectedFile(dir_.file("no_such_scene.json").string(), "", "cannot open");
}

TEST_F(Rejection, NotJson) {
  expectRejected("{\"balls\": [\n  {\"position\": [0, 0],, \"radius\": 1}]}", "",
                 "not valid JSON: parse error at line 2, column 23");
}

TEST_F(Rejection, EmptyFile) {
  expectRejected("", "", "not valid JSON");
}

TEST_F(Rejection, TrailingGarbage) {
  expectRejected(withBall("") + " x", "", "not valid JSON");
}

TEST_F(Rejection, TopLevelNotObject) {
  expectRejected("[1, 2]", "top level", "must be a JSON object {...}, got an array");
}

TEST_F(Rejection, UnknownKeySuggestsClosest) {
  expectRejected(R"({"balls": [{"position": [0, 0], "raduis": 1, "mass": 1}]})", "balls[0]",
                 "unknown key 'raduis'; did you mean 'radius'?");
}

TEST_F(Rejection, UnknownKeyListsKnownKeys) {
  expectRejected(withBall(R"("colour": "red")"), "top level",
                 "unknown key 'colour' (known keys: 'name', 'gravity'");
}

TEST_F(Rejection, UnknownKeyInNestedObject) {
  expectRejected(withBall(R"("contact": {"frcition": 0.3})"), "contact",
                 "unknown key 'frcition'; did you mean 'friction'?");
}

TEST_F(Rejection, UnknownKeyInSolver) {
  expectRejected(withBall(R"("solver": {"contact_pases": 3})"), "solver",
                 "did you mean 'contact_passes'?");
}

TEST_F(Rejection, DuplicateKey) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "radius": 2, "mass": 1}]})",
                 "balls[0]", "duplicate key 'radius'");
}

TEST_F(Rejection, MissingBalls) {
  expectRejected(R"({"name": "empty"})", "top level", "missing required key 'balls'");
}

TEST_F(Rejection, EmptyBalls) {
  expectRejected(R"({"balls": []})", "balls", "must list at least one ball");
}

TEST_F(Rejection, BallsNotArray) {
  expectRejected(R"({"balls": {"position": [0, 0]}})", "balls", "must be an array");
}

TEST_F(Rejection, MissingPosition) {
  expectRejected(R"({"balls": [{"radius": 1, "mass": 1}]})", "balls[0]",
                 "missing required key 'position'");
}

TEST_F(Rejection, MissingRadius) {
  expectRejected(R"({"balls": [{"position": [0, 0], "mass": 1}]})", "balls[0]",
                 "missing required key 'radius'");
}

TEST_F(Rejection, MissingMassAndDensity) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1}]})", "balls[0]",
                 "missing required key 'mass' (or 'density')");
}

TEST_F(Rejection, BothMassAndDensity) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1, "density": 2}]})",
                 "balls[0]", "give either 'mass' or 'density', not both");
}

TEST_F(Rejection, MissingWallEnd) {
  expectRejected(withBall(R"("walls": [{"a": [-5, -2]}])"), "walls[0]", "missing required key 'b'");
}

TEST_F(Rejection, StringWhereNumberExpected) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": "1", "mass": 1}]})",
                 "balls[0].radius", "must be a number, got string \"1\"");
}

TEST_F(Rejection, WrongTypeForTimeStep) {
  expectRejected(withBall(R"("dt": "0.001")"), "dt", "must be a number, got string");
}

TEST_F(Rejection, WrongTypeForName) {
  expectRejected(withBall(R"("name": 3)"), "name", "must be a string, got 3");
}

TEST_F(Rejection, WrongTypeInVector) {
  expectRejected(withBall(R"("gravity": [0, true])"), "gravity[1]", "must be a number, got true");
}

TEST_F(Rejection, VectorWithThreeNumbers) {
  expectRejected(R"({"balls": [{"position": [0, 0, 0], "radius": 1, "mass": 1}]})",
                 "balls[0].position", "must be an array of 2 numbers [x, y], got an array of 3");
}

TEST_F(Rejection, InfiniteNumber) {
  expectRejected(R"({"balls": [{"position": [0, 1e999], "radius": 1, "mass": 1}]})",
                 "balls[0].position[1]", "must be a finite number, got 1e999");
}

TEST_F(Rejection, NegativeInfiniteNumber) {
  expectRejected(withBall(R"("duration": -1e999)"), "duration", "must be a finite number");
}

TEST_F(Rejection, RadiusZero) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 0, "mass": 1}]})", "balls[0].radius",
                 "must be > 0, got 0");
}

TEST_F(Rejection, RadiusNegative) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": -1, "mass": 1}]})", "balls[0].radius",
                 "must be > 0, got -1");
}

TEST_F(Rejection, MassNonPositive) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": -2.5}]})", "balls[0].mass",
                 "must be > 0, got -2.5");
}

TEST_F(Rejection, DensityNonPositive) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "density": 0}]})",
                 "balls[0].density", "must be > 0, got 0");
}

TEST_F(Rejection, InertiaNonPositive) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1, "inertia": 0}]})",
                 "balls[0].inertia", "must be > 0, got 0");
}

TEST_F(Rejection, RestitutionAboveOne) {
  expectRejected(withBall(R"("contact": {"restitution": 1.5})"), "contact.restitution",
                 "must be in [0, 1], got 1.5");
}

TEST_F(Rejection, RestitutionNegativeOnBall) {
  expectRejected(
      R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1, "restitution": -0.1}]})",
      "balls[0].restitution", "must be in [0, 1], got -0.1");
}

TEST_F(Rejection, FrictionNegative) {
  expectRejected(withBall(R"("walls": [{"a": [-5, -2], "b": [5, -2], "friction": -0.2}])"),
                 "walls[0].friction", "must be >= 0, got -0.2");
}

TEST_F(Rejection, FrictionUnknownWord) {
  expectRejected(withBall(R"("contact": {"friction": "inf"})"), "contact.friction",
                 "must be a number >= 0 or \"infinite\", got string \"inf\"");
}

TEST_F(Rejection, TimeStepZero) {
  expectRejected(withBall(R"("dt": 0)"), "dt", "must be > 0, got 0");
}

TEST_F(Rejection, TimeStepNegative) {
  expectRejected(withBall(R"("dt": -0.001)"), "dt", "must be > 0, got -0.001");
}

TEST_F(Rejection, DurationNegative) {
  expectRejected(withBall(R"("duration": -1)"), "duration", "must be >= 0, got -1");
}

TEST_F(Rejection, StepCountDoesNotFit) {
  expectRejected(withBall(R"("dt": 1e-300, "duration": 1e10)"), "duration",
                 "does not fit in the 64-bit step counter");
}

TEST_F(Rejection, ForceNamesMissingBall) {
  expectRejected(withBall(R"("forces": [{"type": "constant", "ball": 1, "force": [1, 0]}])"),
                 "forces[0].ball", "ball 1 does not exist (the scene has 1 ball, index 0)");
}

TEST_F(Rejection, ForceNamesNegativeBall) {
  expectRejected(withBall(R"("forces": [{"type": "constant", "ball": -1}])"), "forces[0].ball",
                 "ball -1 does not exist");
}

TEST_F(Rejection, ForceBallNotInteger) {
  expectRejected(withBall(R"("forces": [{"type": "constant", "ball": 0.5}])"), "forces[0].ball",
                 "must be an integer ball index, got 0.5");
}

TEST_F(Rejection, ForceBallNotNumber) {
  expectRejected(withBall(R"("forces": [{"type": "constant", "ball": "0"}])"), "forces[0].ball",
                 "must be an integer ball index, got string \"0\"");
}

TEST_F(Rejection, UnknownForceType) {
  expectRejected(withBall(R"("forces": [{"type": "spring", "ball": 0}])"), "forces[0].type",
                 "unknown force type 'spring' (known types: 'pull', 'constant')");
}

TEST_F(Rejection, MisspeltForceType) {
  expectRejected(withBall(R"("forces": [{"type": "pul", "ball": 0}])"), "forces[0].type",
                 "did you mean 'pull'?");
}

TEST_F(Rejection, ForceWithoutType) {
  expectRejected(withBall(R"("forces": [{"ball": 0}])"), "forces[0]",
                 "missing required key 'type'");
}

TEST_F(Rejection, KeyOfOtherForceType) {
  expectRejected(withBall(R"("forces": [{"type": "constant", "ball": 0, "stiffness": 3}])"),
                 "forces[0]", "unknown key 'stiffness'");
}

TEST_F(Rejection, PullWithoutTarget) {
  expectRejected(withBall(R"("forces": [{"type": "pull", "ball": 0, "stiffness": 3}])"),
                 "forces[0]", "missing required key 'target'");
}

TEST_F(Rejection, NegativeStiffness) {
  expectRejected(
      withBall(R"("forces": [{"type": "pull", "ball": 0, "target": [1, 1], "stiffness": -3}])"),
      "forces[0].stiffness", "must be >= 0, got -3");
}

TEST_F(Rejection, ForceEndsBeforeItStarts) {
  expectRejected(withBall(R"("forces": [{"type": "constant", "ball": 0, "start": 2, "end": 1}])"),
                 "forces[0].end", "must be >= start (2), got 1");
}

TEST_F(Rejection, BallsOverlap) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1},
                               {"position": [5, 0], "radius": 1, "mass": 1},
                               {"position": [1.9, 0], "radius": 1, "mass": 1}]})",
                 "balls[2]",
                 "overlaps balls[0] by 0.1 m at t = 0 (tolerance 1e-9 of the radii sum)");
}

TEST_F(Rejection, BallsOverlapJustAboveTolerance) {
  // 1e-8 of the radii sum: ten times the tolerance.
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1, "mass": 1},
                               {"position": [1.99999998, 0], "radius": 1, "mass": 1}]})",
                 "balls[1]", "overlaps balls[0] by 2e-08 m");
}

TEST_F(Rejection, BallOverlapsWall) {
  expectRejected(withBall(R"("walls": [{"a": [-5, -0.75], "b": [5, -0.75]}])"), "balls[0]",
                 "overlaps walls[0] by 0.25 m at t = 0");
}

TEST_F(Rejection, BallOverlapsWallEnd) {
  // The closest point of the segment is its end point (0.5, 0.5).
  expectRejected(withBall(R"("walls": [{"a": [0.5, 0.5], "b": [5, 5]}])"), "balls[0]",
                 "overlaps walls[0] by 0.292893");
}

TEST_F(Rejection, BallOverlapsBoxWall) {
  expectRejected(withBall(R"("box": {"min": [-0.5, -3], "max": [3, 3]})"), "balls[0]",
                 "overlaps box left wall by 0.5 m");
}

TEST_F(Rejection, BoxMinNotBelowMax) {
  expectRejected(withBall(R"("box": {"min": [-3, -3], "max": [3, -3]})"), "box.max",
                 "must be greater than min in both x and y, got min [-3, -3], max [3, -3]");
}

TEST_F(Rejection, SolverPassesZero) {
  expectRejected(withBall(R"("solver": {"contact_passes": 0})"), "solver.contact_passes",
                 "must be an integer in [1, 10000], got 0");
}

// Finding 1 of docs/fuzzing.md: 2147483647 passes made a resting stack hang.
TEST_F(Rejection, SolverPassesBeyondTheBound) {
  expectRejected(withBall(R"("solver": {"correction_passes": 10001})"), "solver.correction_passes",
                 "must be an integer in [1, 10000], got 10001");
}

TEST_F(Rejection, SolverPassesNotInteger) {
  expectRejected(withBall(R"("solver": {"correction_passes": 2.5})"), "solver.correction_passes",
                 "must be an integer, got 2.5");
}

TEST_F(Rejection, GridThresholdNegative) {
  expectRejected(withBall(R"("solver": {"grid_threshold": -1})"), "solver.grid_threshold",
                 "must be an integer in [0, 2147483647], got -1");
}

TEST_F(Rejection, SweptWallsNotBoolean) {
  expectRejected(withBall(R"("solver": {"swept_walls": 1})"), "solver.swept_walls",
                 "must be true or false, got 1");
}

TEST_F(Rejection, SweptWallsAsString) {
  expectRejected(withBall(R"("solver": {"swept_walls": "true"})"), "solver.swept_walls",
                 "must be true or false, got string \"true\"");
}

TEST_F(Rejection, OneSidedNotBoolean) {
  expectRejected(withBall(R"("walls": [{"a": [-5, -2], "b": [5, -2], "one_sided": "yes"}])"),
                 "walls[0].one_sided", "must be true or false, got string \"yes\"");
}

TEST_F(Rejection, SweptBallsNotBoolean) {
  expectRejected(withBall(R"("solver": {"swept_balls": null})"), "solver.swept_balls",
                 "must be true or false, got null");
}

TEST_F(Rejection, VelocityShockNotBoolean) {
  expectRejected(withBall(R"("solver": {"velocity_shock": "off"})"), "solver.velocity_shock",
                 "must be true or false, got");
}

TEST_F(Rejection, SequentialImpactsNotBoolean) {
  expectRejected(withBall(R"("solver": {"sequential_impacts": 1})"), "solver.sequential_impacts",
                 "must be true or false, got");
}

TEST_F(Rejection, SoftSubstepsOutOfRange) {
  expectRejected(withBall(R"("solver": {"soft_substeps": 1001})"), "solver.soft_substeps",
                 "must be an integer in [0, 1000], got 1001");
  expectRejected(withBall(R"("solver": {"soft_substeps": -1})"), "solver.soft_substeps",
                 "must be an integer in [0, 1000], got -1");
}

// Without substeps the rigid step runs: a spring key would do nothing.
TEST_F(Rejection, SoftSpringWithoutSubsteps) {
  expectRejected(withBall(R"("solver": {"soft_contact_hertz": 30})"), "solver.soft_contact_hertz",
                 "needs \"soft_substeps\" >= 1");
  expectRejected(withBall(R"("solver": {"soft_substeps": 0, "soft_contact_push_speed": 1})"),
                 "solver.soft_contact_push_speed", "needs \"soft_substeps\" >= 1");
}

// 4 substeps of 0.01 s: a substep rate of 400 Hz, a spring of at most 100 Hz.
TEST_F(Rejection, SoftSpringAboveAQuarterOfTheSubstepRate) {
  expectRejected(
      withBall(R"("dt": 0.01, "solver": {"soft_substeps": 4, "soft_contact_hertz": 150})"),
      "solver.soft_contact_hertz",
      "must be at most a quarter of the substep rate, 100 Hz with 4 substeps of dt 0.01 s, got "
      "150");
}

TEST_F(Rejection, SoftSpringValues) {
  expectRejected(withBall(R"("solver": {"soft_substeps": 4, "soft_contact_hertz": 0})"),
                 "solver.soft_contact_hertz", "must be > 0, got 0");
  expectRejected(withBall(R"("solver": {"soft_substeps": 4, "soft_contact_damping_ratio": -1})"),
                 "solver.soft_contact_damping_ratio", "must be >= 0, got -1");
  expectRejected(withBall(R"("solver": {"soft_substeps": 4, "soft_contact_push_speed": 0})"),
                 "solver.soft_contact_push_speed", "must be > 0, got 0");
}

TEST_F(Rejection, DensityGivesInfiniteMass) {
  expectRejected(R"({"balls": [{"position": [0, 0], "radius": 1e200, "density": 1e200}]})",
                 "balls[0].density", "gives mass = density * pi * r^2 = inf");
}

}  // namespace
}  // namespace particles::test
