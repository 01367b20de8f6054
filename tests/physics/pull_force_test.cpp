// The handout's mouse drag: F = k (M - O) at the ball's centre O, toward the
// target M. A free ball of mass m released at rest at O0 is a harmonic
// oscillator about M with w0 = sqrt(k/m):
//   x(t) = M - (M - O0) cos(w0 t)        (continuous).
//
// The step (v += dt F/m, then x += dt v) makes it a discrete oscillator, solved
// by hand here. With u = x - M and h = w0 dt:
//   v_{n+1} = v_n - w0^2 dt u_n,  u_{n+1} = u_n + dt v_{n+1}
//   => u_{n+1} - 2 u_n + u_{n-1} = -h^2 u_n,
// whose solutions are C cos(n theta) + D sin(n theta) with
// cos theta = 1 - h^2/2, i.e. theta = 2 asin(h/2). From u_0 = A = O0 - M and
// u_1 = A (1 - h^2): C = A, D = -A h^2 / (2 sin theta) = -A h / (2 cos(theta/2)).
//   u_n = A [cos(n theta) - h / (2 cos(theta/2)) sin(n theta)]   (discrete, exact)
// Against the continuous answer:
//   |u_n - A cos(w0 t_n)| <= |A| (n |theta - h| + h / (2 cos(theta/2)))
// where the second term, ~|A| w0 dt / 2, is the first-order error of the scheme
// and the first, ~|A| t w0^3 dt^2 / 24, the second-order phase drift.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;

constexpr double kMass = 2.0, kStiffness = 50.0;  // w0 = 5 rad/s
const Vec2 kStart(1.0, -2.0), kTarget(3.0, 1.0);

particles::SceneDef pulledBall(double dt, Vec2 start, Vec2 target) {
  particles::SceneDef scene;
  scene.dt = dt;
  particles::BallDef ball;
  ball.position = start;
  ball.mass = kMass;
  scene.balls.push_back(ball);
  particles::ForceDef pull;
  pull.type = particles::ForceType::Pull;
  pull.ball = 0;
  pull.target = target;
  pull.stiffness = kStiffness;
  scene.forces.push_back(pull);
  return scene;
}

// Runs `steps` steps and checks every position against both closed forms.
void checkOscillation(particles::World& world, long long steps, Vec2 start, Vec2 target,
                      long long stepOffset) {
  const double dt = world.dt(), w0 = std::sqrt(kStiffness / kMass), h = w0 * dt;
  const double theta = 2.0 * std::asin(h / 2.0);
  const Vec2 A = start - target;
  const Vec2 along = A.normalized();
  // Rounding: ~n ulps per operation of the largest magnitudes (positions up
  // to |M| + |A|, velocity errors turned into position by 1/w0, |v|/w0 <= |A|).
  const double roundTol =
      8.0 * static_cast<double>(steps) * kEps * (target.norm() + 2.0 * A.norm());
  double worstDiscrete = 0.0, worstContinuous = 0.0;
  for (long long n = 1; n <= steps; ++n) {
    world.step();
    const double N = static_cast<double>(n);
    const Vec2 u = world.ball(0).position - target;
    const double discrete =
        A.norm() * (std::cos(N * theta) - h / (2.0 * std::cos(theta / 2.0)) * std::sin(N * theta));
    const double continuous = A.norm() * std::cos(w0 * N * dt);
    const double firstOrderTol =
        A.norm() * (N * std::abs(theta - h) + h / (2.0 * std::cos(theta / 2.0))) + roundTol;
    worstDiscrete = std::max(worstDiscrete, std::abs(u.dot(along) - discrete));
    worstContinuous = std::max(worstContinuous, std::abs(u.dot(along) - continuous));
    ASSERT_NEAR(u.dot(along), discrete, roundTol) << "step " << n + stepOffset;
    ASSERT_NEAR(u.dot(along), continuous, firstOrderTol) << "step " << n + stepOffset;
    // It moves on the line through M and O0.
    ASSERT_NEAR(crossZ(along, u), 0.0, roundTol) << "step " << n + stepOffset;
  }
  std::printf(
      "[ measured ] pull dt = %g: max |x - discrete form| = %.3e (bound %.1e), "
      "max |x - continuous| = %.3e (first-order amplitude |A| w0 dt/2 = %.3e)\n",
      dt, worstDiscrete, roundTol, worstContinuous, A.norm() * h / 2.0);
}

TEST(PullForce, BallFromRestOscillatesAboutTheTarget) {
  const double dt = 1e-4;
  particles::World world(pulledBall(dt, kStart, kTarget));
  checkOscillation(world, 20000, kStart, kTarget, 0);  // 2 s, ~1.6 periods
}

// At a coarser step the first-order error is ten times larger, and still
// within the derived bound (which is what makes the bound meaningful).
TEST(PullForce, OscillationErrorIsFirstOrderInDt) {
  particles::World world(pulledBall(1e-3, kStart, kTarget));
  checkOscillation(world, 2000, kStart, kTarget, 0);
}

// Power-of-two dt so that start and end fall exactly on step times: the force
// acts in the steps that begin at t = start, ..., end - dt and in no other.
TEST(PullForce, InactiveOutsideItsTimeWindow) {
  const double dt = 0x1.0p-10;
  particles::SceneDef scene = pulledBall(dt, kStart, kTarget);
  scene.forces[0].start = 100 * dt;
  scene.forces[0].end = 200 * dt;
  particles::World world(scene);
  world.run(100);  // steps beginning at t = 0 .. 99 dt: inactive
  EXPECT_EQ(world.ball(0).position, kStart);
  EXPECT_EQ(world.ball(0).velocity, Vec2(0.0, 0.0));
  world.step();  // begins at t = start: active, v = dt k (M - O0) / m
  const Vec2 kick = dt * kStiffness / kMass * (kTarget - kStart);
  EXPECT_NEAR((world.ball(0).velocity - kick).norm(), 0.0, kRoundingRel * kick.norm());
  world.run(99);  // through the step beginning at end - dt
  const Vec2 v = world.ball(0).velocity;
  ASSERT_GT(v.norm(), 0.0);
  for (int i = 0; i < 100; ++i) {  // steps beginning at t >= end: inactive
    const Vec2 x = world.ball(0).position;
    world.step();
    ASSERT_EQ(world.ball(0).velocity, v) << "step " << world.stepIndex();
    ASSERT_NEAR((world.ball(0).position - (x + dt * v)).norm(), 0.0, 4.0 * kEps * 10.0);
  }
}

// The force acts at the centre: no torque. A non-spinning ball never turns;
// a spinning one keeps its spin exactly.
TEST(PullForce, ExertsNoTorque) {
  for (double w0 : {0.0, 1.5}) {
    particles::SceneDef scene = pulledBall(1e-3, kStart, kTarget);
    scene.balls[0].angularVelocity = w0;
    particles::World world(scene);
    for (int n = 1; n <= 2000; ++n) {
      world.step();
      ASSERT_EQ(world.ball(0).angularVelocity, w0);
      ASSERT_NEAR(world.ball(0).angle, w0 * n * 1e-3, 4.0 * n * kEps * (std::abs(w0) * 2.0));
    }
    EXPECT_GT((world.ball(0).position - kStart).norm(), 0.1) << "the pull did move the ball";
  }
}

// The viewer moves the target: a ball at rest on the old target (no force)
// then oscillates about the new one, starting from rest.
TEST(PullForce, MovingTheTargetMovesTheCentreOfOscillation) {
  const double dt = 1e-4;
  particles::World world(pulledBall(dt, kTarget, kTarget));
  world.run(100);
  EXPECT_EQ(world.ball(0).position, kTarget);
  EXPECT_EQ(world.ball(0).velocity, Vec2(0.0, 0.0));
  const Vec2 newTarget(-1.0, 0.5);
  world.setPullTarget(0, newTarget);
  checkOscillation(world, 10000, kTarget, newTarget, 100);
}

}  // namespace
