// The example scenes in scenes/: each loads and runs, and the ones with an
// answer that can be worked out by hand give that answer.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cli_support.h"
#include "particles/scenefile.h"
#include "particles/state_hash.h"
#include "particles/world.h"

namespace particles::test {
namespace {

std::vector<std::string> exampleScenes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(PARTICLES_SCENES_DIR))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool allNumbersFinite(const nlohmann::json& j) {
  if (j.is_number()) return std::isfinite(j.get<double>());
  if (j.is_null()) return false;  // nlohmann dumps NaN and infinity as null
  if (j.is_array() || j.is_object()) {
    for (const auto& element : j)
      if (!allNumbersFinite(element)) return false;
  }
  return true;
}

nlohmann::json runScene(const std::string& name, const std::string& options = "") {
  const CliResult r = runCli("run " + shellQuote(sceneFile(name)) + options);
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

Vec2 vec(const nlohmann::json& j) {
  return Vec2(j[0].get<double>(), j[1].get<double>());
}

class ExampleScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleScene, LoadsRunsAndPrintsFiniteNumbers) {
  const std::string file = sceneFile(GetParam() + ".json");
  const SceneDef scene = loadScene(file);
  EXPECT_FALSE(scene.name.empty()) << "every example scene has a name";
  const CliResult r = runCli("run " + shellQuote(file));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const nlohmann::json state = nlohmann::json::parse(r.out);
  EXPECT_TRUE(allNumbersFinite(state)) << r.out;
  EXPECT_EQ(r.out.find("null"), std::string::npos);
  EXPECT_EQ(state["balls"].size(), scene.balls.size());
  EXPECT_DOUBLE_EQ(state["time"].get<double>(), static_cast<double>(scene.stepCount()) * scene.dt);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ExampleScene, ::testing::ValuesIn(exampleScenes()),
                         [](const auto& info) { return info.param; });

TEST(ExampleScenes, TheListedOnesExist) {
  for (const char* name :
       {"oblique_floor_hit", "free_flight", "projectile", "head_on_spinning", "gears",
        "ball_in_box", "newtons_cradle", "pull_drag", "constant_force_torque", "rolling_disk",
        "density_and_inertia", "no_slip_walls", "small_pile", "small_pile_soft", "hourglass"})
    EXPECT_TRUE(std::filesystem::exists(sceneFile(std::string(name) + ".json"))) << name;
}

// No forces: x(T) = x0 + v T and angle(T) = angle0 + w T.
TEST(HandChecked, FreeFlight) {
  const SceneDef scene = loadScene(sceneFile("free_flight.json"));
  const BallDef& b = scene.balls.at(0);
  const nlohmann::json ball = runScene("free_flight.json")["balls"][0];
  const double t = static_cast<double>(scene.stepCount()) * scene.dt;
  const Vec2 x = b.position + b.velocity * t;
  const Vec2 got = vec(ball["position"]);
  EXPECT_NEAR(got.x(), x.x(), 1e-12 * std::abs(x.x()));
  EXPECT_NEAR(got.y(), x.y(), 1e-12 * std::abs(x.y()));
  EXPECT_EQ(vec(ball["velocity"]), b.velocity);
  const double angle = b.angle + b.angularVelocity * t;
  EXPECT_NEAR(ball["angle"].get<double>(), angle, 1e-12 * std::abs(angle));
  EXPECT_EQ(ball["angular_velocity"].get<double>(), b.angularVelocity);
}

// Semi-implicit Euler under gravity, n steps: v_n = v0 + g n dt and
// x_n = x0 + v0 n dt + g dt^2 n (n + 1) / 2 (each step moves by the new v).
TEST(HandChecked, Projectile) {
  const SceneDef scene = loadScene(sceneFile("projectile.json"));
  const BallDef& b = scene.balls.at(0);
  const double n = static_cast<double>(scene.stepCount());
  const double dt = scene.dt;
  const Vec2 g = scene.gravity;
  ASSERT_EQ(n, 800.0);
  const Vec2 v = b.velocity + g * n * dt;
  const Vec2 x = b.position + b.velocity * n * dt + g * dt * dt * n * (n + 1.0) / 2.0;
  // The by-hand figures: y = 1 + 4 * 0.8 - 9.81e-6 * 800 * 801 / 2 = 1.056876.
  EXPECT_NEAR(x.y(), 1.056876, 1e-12);
  EXPECT_NEAR(v.y(), -3.848, 1e-12);

  const nlohmann::json ball = runScene("projectile.json")["balls"][0];
  const double scale = b.position.norm() + b.velocity.norm() * n * dt + g.norm() * n * n * dt * dt;
  EXPECT_NEAR(vec(ball["position"]).x(), x.x(), 1e-12 * scale);
  EXPECT_NEAR(vec(ball["position"]).y(), x.y(), 1e-12 * scale);
  EXPECT_NEAR(vec(ball["velocity"]).x(), v.x(), 1e-12 * v.norm());
  EXPECT_NEAR(vec(ball["velocity"]).y(), v.y(), 1e-12 * v.norm());
}

// e = 1, mu = 0, equal masses: the first ball's velocity passes down the row
// in one step; the last ball leaves at 2 m/s, the others stay where they are.
TEST(HandChecked, NewtonsCradle) {
  const nlohmann::json balls = runScene("newtons_cradle.json")["balls"];
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(vec(balls[i]["velocity"]), Vec2(0, 0)) << i;
    EXPECT_EQ(vec(balls[i]["position"]), Vec2(i, 0)) << i;
  }
  EXPECT_EQ(vec(balls[4]["velocity"]), Vec2(2, 0));
  EXPECT_NEAR(vec(balls[4]["position"]).x(), 4.0 + 2.0 * 1.0, 1e-12);
}

// Equal balls r = 0.5, m = 1, J = 1/8, head-on at 1 m/s each, both spinning
// at +10 rad/s, e = 1, mu = 0.3. Normal: lambdaN = 2 reverses both. Tangent:
// slip 2 w r = 10 m/s, no-slip impulse 10 / (2 + 2 r^2 / J) = 5/3 > mu
// lambdaN = 0.6, so lambdaT = 0.6: sideways speeds -/+0.6 m/s and spins
// 10 - r lambdaT / J = 7.6 rad/s.
TEST(HandChecked, HeadOnSameSpin) {
  const nlohmann::json balls = runScene("head_on_spinning.json")["balls"];
  EXPECT_NEAR(vec(balls[0]["velocity"]).x(), -1.0, 1e-12);
  EXPECT_NEAR(vec(balls[0]["velocity"]).y(), -0.6, 1e-12);
  EXPECT_NEAR(vec(balls[1]["velocity"]).x(), 1.0, 1e-12);
  EXPECT_NEAR(vec(balls[1]["velocity"]).y(), 0.6, 1e-12);
  EXPECT_NEAR(balls[0]["angular_velocity"].get<double>(), 7.6, 1e-12);
  EXPECT_NEAR(balls[1]["angular_velocity"].get<double>(), 7.6, 1e-12);
}

// Opposite spins: the surfaces move together at the contact (like meshing
// gears), so there is no friction impulse; the balls just bounce.
TEST(HandChecked, GearsOppositeSpins) {
  const nlohmann::json balls = runScene("gears.json")["balls"];
  EXPECT_EQ(vec(balls[0]["velocity"]), Vec2(-1, 0));
  EXPECT_EQ(vec(balls[1]["velocity"]), Vec2(1, 0));
  EXPECT_EQ(balls[0]["angular_velocity"].get<double>(), 10.0);
  EXPECT_EQ(balls[1]["angular_velocity"].get<double>(), -10.0);
}

// Sliding disk, e = 0: friction keeps the angular momentum about the contact
// point, m v r + J (-w) = m v0 r, until it rolls (v = -w r): v = 2/3 v0 = 2
// m/s and w = -4 rad/s, reached at t = v0 / (3 mu g) = 0.34 s.
TEST(HandChecked, RollingDisk) {
  const nlohmann::json ball = runScene("rolling_disk.json")["balls"][0];
  EXPECT_NEAR(vec(ball["velocity"]).x(), 2.0, 1e-9);
  EXPECT_NEAR(vec(ball["velocity"]).y(), 0.0, 1e-9);
  EXPECT_NEAR(ball["angular_velocity"].get<double>(), -4.0, 1e-9);
  EXPECT_NEAR(vec(ball["position"]).y(), 0.5, 1e-9);
}

// F = (4, -2) N on m = 2 kg and tau = 0.25 N m on J = m r^2 / 2 = 0.25 kg m^2
// for the 500 steps with t < 0.5 s, then tau = -0.125 N m alone for 500.
TEST(HandChecked, ConstantForceAndTorque) {
  const nlohmann::json ball = runScene("constant_force_torque.json")["balls"][0];
  const double dt = 1e-3, n = 500;
  const double ax = 2.0;                               // m/s^2
  const double push = ax * dt * dt * n * (n + 1) / 2;  // x after the force: 0.2505 m
  EXPECT_NEAR(vec(ball["velocity"]).x(), ax * n * dt, 1e-12);
  EXPECT_NEAR(vec(ball["position"]).x(), push + ax * n * dt * n * dt, 1e-12);
  EXPECT_NEAR(vec(ball["position"]).y(), -(push + ax * n * dt * n * dt) / 2, 1e-12);
  const double w1 = 1.0 * n * dt;  // alpha = 1 rad/s^2 for 0.5 s
  EXPECT_NEAR(ball["angular_velocity"].get<double>(), w1 - 0.5 * n * dt, 1e-12);
  const double angle =
      1.0 * dt * dt * n * (n + 1) / 2 + w1 * n * dt - 0.5 * dt * dt * n * (n + 1) / 2;
  EXPECT_NEAR(ball["angle"].get<double>(), angle, 1e-12);  // 0.312625 rad
}

// 48 balls dropped into a box (on the large-scene path: 32 or more balls
// under gravity) end at rest, inside the box and without overlap: every
// point of every ball moves slower than 1 cm/s (the pile benchmark's rest
// speed, docs/scale.md), no ball crosses a wall, and no two overlap by more
// than 1e-6 of the smaller radius. The settling is chaotic, so the scene runs
// 12 s: of 24 copies with every position moved by up to 0.1 mm, 13 were at
// rest after 3 s and all 24 after 12 s (docs/scale.md, "Cell order").
TEST(HandChecked, SmallPileComesToRestInsideTheBox) {
  const SceneDef scene = loadScene(sceneFile("small_pile.json"));
  const nlohmann::json balls = runScene("small_pile.json")["balls"];
  ASSERT_EQ(balls.size(), scene.balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double r = scene.balls[i].radius;
    const Vec2 x = vec(balls[i]["position"]);
    EXPECT_LT(vec(balls[i]["velocity"]).norm(), 0.01) << i;
    EXPECT_LT(std::abs(balls[i]["angular_velocity"].get<double>()) * r, 0.01) << i;
    EXPECT_GE(x.x() - r, -1e-9 * r) << i;
    EXPECT_GE(x.y() - r, -1e-9 * r) << i;
    EXPECT_LE(x.x() + r, 5.6 + 1e-9 * r) << i;
    EXPECT_LE(x.y() + r, 6.0 + 1e-9 * r) << i;
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      const double rj = scene.balls[j].radius;
      const double gap = (vec(balls[j]["position"]) - x).norm() - (r + rj);
      EXPECT_GT(gap, -1e-6 * std::min(r, rj)) << i << " " << j;
    }
  }
}

// The soft step's scene is small_pile.json with "solver": {"soft_substeps":
// 8}: the key reaches the engine (the same bits as setting
// SolverSettings::scaleSubsteps), and it changes the run.
TEST(HandChecked, SoftPileIsTheSmallPileWithSubsteps) {
  SceneDef rigid = loadScene(sceneFile("small_pile.json"));
  const SceneDef soft = loadScene(sceneFile("small_pile_soft.json"));
  ASSERT_EQ(soft.solver.scaleSubsteps, 8);
  ASSERT_EQ(rigid.solver.scaleSubsteps, 0);
  constexpr long long kSteps = 300;
  World rigidWorld(rigid);
  rigidWorld.run(kSteps);
  rigid.solver.scaleSubsteps = 8;
  World asSoft(rigid), softWorld(soft);
  asSoft.run(kSteps);
  softWorld.run(kSteps);
  EXPECT_EQ(stateHash(softWorld), stateHash(asSoft));
  EXPECT_NE(stateHash(softWorld), stateHash(rigidWorld));
}

// On the soft step the pile ends at rest inside the box, and overlapping:
// its springs carry the weight. At rest a spring's force is k x with k =
// m_n w^2 (the damping acts on velocity only; docs/scale.md, "The soft
// step"), so no overlap exceeds the whole pile's weight on one spring of
// the lightest pair, M g / (m_n w^2), with w = 2 pi (a quarter of the
// substep rate) and m_n half the lightest mass (walls are twice as stiff
// for a whole mass: a quarter of that). And the springs do carry it: some
// pair overlaps by more than one ball's weight needs, m g / (m_n w^2) for
// the lightest (3.1e-6 m here; the bound above is 1.9e-4 m, and the deepest
// was 4.0e-5 m when this was written), where the rigid step's overlap
// removal leaves at most 1e-6 of the radius (2.3e-7 m).
TEST(HandChecked, SoftPileComesToRestOnItsSprings) {
  const SceneDef scene = loadScene(sceneFile("small_pile_soft.json"));
  const nlohmann::json balls = runScene("small_pile_soft.json")["balls"];
  ASSERT_EQ(balls.size(), scene.balls.size());
  double total = 0.0, lightest = INFINITY;
  for (const BallDef& b : scene.balls) {
    total += b.mass;
    lightest = std::min(lightest, b.mass);
  }
  const double g = scene.gravity.norm();
  const double w = 2.0 * std::numbers::pi * 0.25 * scene.solver.scaleSubsteps / scene.dt;
  const double mostSag = total * g / (0.5 * lightest * w * w);
  const double oneWeight = lightest * g / (0.5 * lightest * w * w);
  double deepest = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double r = scene.balls[i].radius;
    const Vec2 x = vec(balls[i]["position"]);
    EXPECT_LT(vec(balls[i]["velocity"]).norm(), 0.01) << i;
    EXPECT_LT(std::abs(balls[i]["angular_velocity"].get<double>()) * r, 0.01) << i;
    EXPECT_GE(x.x() - r, -mostSag) << i;
    EXPECT_GE(x.y() - r, -mostSag) << i;
    EXPECT_LE(x.x() + r, 5.6 + mostSag) << i;
    EXPECT_LE(x.y() + r, 6.0 + mostSag) << i;
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      const double overlap = scene.balls[j].radius + r - (vec(balls[j]["position"]) - x).norm();
      EXPECT_LE(overlap, mostSag) << i << " " << j;
      deepest = std::max(deepest, overlap);
    }
  }
  EXPECT_GT(deepest, oneWeight);
}

}  // namespace
}  // namespace particles::test
