// Time integration of a free ball (no walls, no other balls), against the
// documented scheme, semi-implicit (symplectic) Euler: v += a dt, then
// x += v dt.
//
// Discrete closed form, by hand, for a constant acceleration a:
//   v_n = v_0 + a n dt,
//   x_n = x_0 + dt sum_{k=1..n} v_k = x_0 + v_0 n dt + a dt^2 n(n+1)/2.
// With t = n dt: x_n = x_0 + v_0 t + a t^2/2 + a t dt/2, i.e. the continuous
// answer plus a first-order error a t dt / 2. For free fall a = -g:
//   y_n = y_0 + v_0 t - g t^2/2 - g t dt/2.
// Rotation uses the same scheme with the angular acceleration tau/J.
//
// Rounding tolerance: after n steps each running sum has picked up at most
// ~n ulps of its largest magnitude per operation (two operations per update),
// and a velocity error feeds the position through dt for the remaining
// steps, at most n dt = t times it. So |error| <= 4 n eps (X + t V), with X and
// V the largest |position| and |velocity| of the run.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;

constexpr double kG = 9.81;

double roundingBound(long long n, double X, double t, double V) {
  return 4.0 * static_cast<double>(n) * kEps * (X + t * V);
}

particles::SceneDef freeBall(double dt, Vec2 x0, Vec2 v0, Vec2 gravity) {
  particles::SceneDef scene;
  scene.gravity = gravity;
  scene.dt = dt;
  particles::BallDef ball;
  ball.position = x0;
  ball.velocity = v0;
  scene.balls.push_back(ball);
  return scene;
}

const double kStepSizes[] = {1e-2, 1e-3, 1e-4};

TEST(Integration, FreeFallFollowsTheDiscreteSemiImplicitEulerClosedForm) {
  const double y0 = 10.0, v0 = 2.0;
  for (double dt : kStepSizes) {
    particles::World world(freeBall(dt, Vec2(0.0, y0), Vec2(0.0, v0), Vec2(0.0, -kG)));
    const long long steps = std::llround(1.0 / dt);
    const double tol = roundingBound(steps, y0 + 2.0, 1.0, v0 + kG);
    double worst = 0.0;
    for (long long n = 1; n <= steps; ++n) {
      world.step();
      const double N = static_cast<double>(n);
      const double y = y0 + v0 * N * dt - kG * dt * dt * N * (N + 1.0) / 2.0;
      const double v = v0 - kG * N * dt;
      const particles::BallState s = world.ball(0);
      worst = std::max(worst, std::abs(s.position.y() - y));
      ASSERT_NEAR(s.position.y(), y, tol) << "dt = " << dt << ", step " << n;
      ASSERT_NEAR(s.velocity.y(), v, tol) << "dt = " << dt << ", step " << n;
      ASSERT_EQ(s.position.x(), 0.0);
      ASSERT_EQ(s.velocity.x(), 0.0);
    }
    std::printf("[ measured ] free fall dt = %g: max |y - discrete form| = %.3e (bound %.1e)\n", dt,
                worst, tol);
  }
}

// Error against the continuous y0 + v0 t - g t^2/2 is exactly -g t dt/2 (to
// rounding), so it shrinks tenfold with dt: first order.
TEST(Integration, FreeFallConvergesAtFirstOrderWithErrorGTDtOverTwo) {
  const double y0 = 10.0, v0 = 2.0, t = 1.0;
  double previous = 0.0;
  for (double dt : kStepSizes) {
    particles::World world(freeBall(dt, Vec2(0.0, y0), Vec2(0.0, v0), Vec2(0.0, -kG)));
    const long long steps = std::llround(t / dt);
    world.run(steps);
    ASSERT_DOUBLE_EQ(world.time(), t);
    const double continuous = y0 + v0 * t - 0.5 * kG * t * t;
    const double error = world.ball(0).position.y() - continuous;
    const double tol = roundingBound(steps, y0 + 2.0, t, v0 + kG);
    EXPECT_NEAR(error, -0.5 * kG * t * dt, tol) << "dt = " << dt;
    std::printf("[ measured ] free fall dt = %g: error at t = 1 s = %.6e (g t dt/2 = %.6e)\n", dt,
                error, 0.5 * kG * t * dt);
    if (previous != 0.0) {
      EXPECT_NEAR(previous / error, 10.0, 1e-6) << "dt = " << dt;
    }
    previous = error;
  }
}

TEST(Integration, ProjectileFollowsTheDiscreteAndContinuousClosedForms) {
  const Vec2 x0(-1.0, 2.0), v0(3.0, 4.0);
  const double t = 0.8;
  for (double dt : kStepSizes) {
    particles::World world(freeBall(dt, x0, v0, Vec2(0.0, -kG)));
    const long long steps = std::llround(t / dt);
    const double tol = roundingBound(steps, 5.0, t, 10.0);
    for (long long n = 1; n <= steps; ++n) {
      world.step();
      const double N = static_cast<double>(n);
      const particles::BallState s = world.ball(0);
      // Horizontal: no acceleration, x_n = x0 + vx n dt.
      ASSERT_NEAR(s.position.x(), x0.x() + v0.x() * N * dt, tol) << "dt = " << dt;
      ASSERT_NEAR(s.velocity.x(), v0.x(), tol) << "dt = " << dt;
      ASSERT_NEAR(s.position.y(), x0.y() + v0.y() * N * dt - kG * dt * dt * N * (N + 1.0) / 2.0,
                  tol)
          << "dt = " << dt << ", step " << n;
    }
    // Continuous parabola plus the first-order term.
    const particles::BallState s = world.ball(0);
    EXPECT_NEAR(s.position.x(), x0.x() + v0.x() * t, tol);
    EXPECT_NEAR(s.position.y(), x0.y() + v0.y() * t - 0.5 * kG * t * t - 0.5 * kG * t * dt, tol);
  }
}

// ForceType::Constant: a force F at the centre and a torque tau give
// a = F/m and alpha = tau/J, integrated by the same scheme:
//   w_n = w0 + (tau/J) t_n,  theta_n = theta0 + w0 t_n + (tau/J) dt^2 n(n+1)/2
//   = theta0 + w0 t + tau t^2/(2J) + tau t dt/(2J).
particles::SceneDef drivenBall(double dt) {
  particles::SceneDef scene = freeBall(dt, Vec2(1.0, -1.0), Vec2(0.5, 0.0), Vec2(0.0, 0.0));
  scene.balls[0].mass = 2.0;
  scene.balls[0].radius = 0.3;  // J = m r^2 / 2 = 0.09
  scene.balls[0].angle = 0.25;
  scene.balls[0].angularVelocity = -1.0;
  particles::ForceDef f;
  f.type = particles::ForceType::Constant;
  f.force = Vec2(1.0, -3.0);
  f.torque = 0.18;  // alpha = 0.18 / 0.09 = 2 rad/s^2
  scene.forces.push_back(f);
  return scene;
}

TEST(Integration, ConstantTorqueSpinsUpAsTauTOverJWithTheSameScheme) {
  const double J = 0.5 * 2.0 * 0.3 * 0.3, alpha = 0.18 / J, w0 = -1.0, th0 = 0.25, t = 1.0;
  for (double dt : kStepSizes) {
    particles::World world(drivenBall(dt));
    EXPECT_TRUE(world.plan().torques);
    const long long steps = std::llround(t / dt);
    const double tol = roundingBound(steps, 3.0, t, 3.0);
    for (long long n = 1; n <= steps; ++n) {
      world.step();
      const double N = static_cast<double>(n);
      const particles::BallState s = world.ball(0);
      ASSERT_NEAR(s.angularVelocity, w0 + alpha * N * dt, tol) << "dt = " << dt;
      ASSERT_NEAR(s.angle, th0 + w0 * N * dt + alpha * dt * dt * N * (N + 1.0) / 2.0, tol)
          << "dt = " << dt << ", step " << n;
    }
    const particles::BallState s = world.ball(0);
    EXPECT_NEAR(s.angle, th0 + w0 * t + 0.5 * alpha * t * t + 0.5 * alpha * t * dt, tol);
  }
}

TEST(Integration, ConstantForceAcceleratesAtFOverM) {
  const Vec2 x0(1.0, -1.0), v0(0.5, 0.0), a = Vec2(1.0, -3.0) / 2.0;
  const double t = 1.0;
  for (double dt : kStepSizes) {
    particles::World world(drivenBall(dt));
    const long long steps = std::llround(t / dt);
    world.run(steps);
    const double tol = roundingBound(steps, 3.0, t, 3.0);
    const double N = static_cast<double>(steps);
    const particles::BallState s = world.ball(0);
    const Vec2 v = v0 + a * N * dt;
    const Vec2 x = x0 + v0 * N * dt + a * dt * dt * N * (N + 1.0) / 2.0;
    EXPECT_NEAR(s.velocity.x(), v.x(), tol);
    EXPECT_NEAR(s.velocity.y(), v.y(), tol);
    EXPECT_NEAR(s.position.x(), x.x(), tol);
    EXPECT_NEAR(s.position.y(), x.y(), tol);
  }
}

}  // namespace
