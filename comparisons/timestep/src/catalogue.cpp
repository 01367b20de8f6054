// The scenes of the time-stepped catalogue and their answers. Why each
// expected value holds is in docs/bench.md ("The catalogue").
#include "particles/timestep/catalogue.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "ball_def.h"
#include "particles/timestep/floor_bounce.h"

namespace particles::timestep {
namespace {

constexpr double kG = 9.81;  // m/s^2

WallDef wall(Vec2 a, Vec2 b) {
  WallDef w;
  w.a = a;
  w.b = b;
  return w;
}

std::vector<double> masses(const SceneDef& s) {
  std::vector<double> m;
  for (const BallDef& b : s.balls) m.push_back(b.mass);
  return m;
}
std::vector<double> inertias(const SceneDef& s) {
  std::vector<double> j;
  for (const BallDef& b : s.balls) j.push_back(b.resolvedInertia());
  return j;
}

// SplitMix64: the same numbers on every standard library.
struct SplitMix {
  std::uint64_t state;
  double uniform() {  // [0, 1)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

TimestepScene bounce() {
  TimestepScene t;
  t.name = "bounce";
  t.description =
      "ball dropped from h0 = 1 m on a floor, e = 0.8: apexes h_k = e^(2k) h0, k = 1..3";
  const double r = 0.5, h0 = 1.0, e = 0.8;
  SceneDef& s = t.scene;
  s.name = t.name;
  s.gravity = {0.0, -kG};
  s.contact = {e, 0.0};
  s.walls = {wall({-5, 0}, {5, 0})};
  s.balls = {ball({0, r + h0}, r, 1.0)};
  s.dt = 1e-3;
  s.duration = 2.2;  // the third apex is at about 2.0 s
  t.metric = [=](const std::vector<double>&) { return apexHeights(0, 0.0, r, e, h0, 3); };
  return t;
}

TimestepScene slideRoll() {
  TimestepScene t;
  t.name = "slide_roll";
  t.description =
      "disk launched at v0 = 3 m/s without spin, mu = 0.3: rolls at 2/3 v0 from t = v0/(3 mu g)";
  const double r = 0.5, v0 = 3.0, mu = 0.3;
  SceneDef& s = t.scene;
  s.name = t.name;
  s.gravity = {0.0, -kG};
  s.contact = {0.0, mu};
  s.walls = {wall({-10, 0}, {20, 0})};
  s.balls = {ball({0, r}, r, 1.0, {v0, 0})};
  s.dt = 1e-3;
  s.duration = 0.6;  // t* = 0.34 s
  t.metric = [=](const std::vector<double>&) { return slideToRoll(0, v0, r, 0.5, mu, kG); };
  return t;
}

TimestepScene inclineRoll() {
  TimestepScene t;
  t.name = "incline_roll";
  t.description =
      "disk released on a 20 degree incline, mu = 0.3 (tan 20 < 3 mu): s = a t^2/2, a = 2/3 g sin "
      "20";
  const double r = 0.5, theta = 20.0 * std::numbers::pi / 180.0, mu = 0.3;
  const Vec2 down(std::cos(theta), -std::sin(theta));
  const Vec2 normal(std::sin(theta), std::cos(theta));  // the incline's upper side
  SceneDef& s = t.scene;
  s.name = t.name;
  s.gravity = {0.0, -kG};
  s.contact = {0.0, mu};
  s.walls = {wall({0, 0}, 12.0 * down)};
  s.balls = {ball(1.0 * down + r * normal, r, 1.0)};
  s.dt = 1e-3;
  s.duration = 1.0;
  const double a = 2.0 / 3.0 * kG * std::sin(theta);
  t.metric = [=](const std::vector<double>&) { return constantAcceleration(0, down, a); };
  return t;
}

TimestepScene obliqueSpin() {
  TimestepScene t;
  t.name = "oblique_spin";
  t.description =
      "spinning ball hits a floor obliquely (no gravity), e = 0.5, mu = 0.2: sliding impact, "
      "closed form";
  const double r = 0.5, d = 0.1, e = 0.5, mu = 0.2, w0 = 5.0;
  const Vec2 v0(2.0, -1.0);
  SceneDef& s = t.scene;
  s.name = t.name;
  s.contact = {e, mu};
  s.walls = {wall({-10, 0}, {10, 0})};
  s.balls = {ball({0, r + d}, r, 1.0, v0, w0)};
  s.dt = 1e-3;
  s.duration = 0.5;
  const double tc = d / -v0.y();  // contact at t = 0.1 s
  const FloorBounce after = floorBounce(v0.x(), v0.y(), w0, r, 0.5, e, mu);
  const Vec2 x0(0.0, r + d), xc = x0 + tc * v0;
  ExactState exact = [=](double time) {
    if (time <= tc) return BallState{x0 + time * v0, v0, 0.0, w0};
    const Vec2 v(after.vx, after.vy);
    return BallState{xc + (time - tc) * v, v, 0.0, after.w};
  };
  const double speed = v0.norm() + std::fabs(w0) * r;
  t.metric = [=](const std::vector<double>&) {
    return exactTrajectory(0, exact, r, r, speed, {tc});
  };
  return t;
}

TimestepScene pull() {
  TimestepScene t;
  t.name = "pull";
  t.description = "pull force k = 4 N/m on 1 kg toward the origin: x = cos 2t, y = 0.5 sin 2t";
  SceneDef& s = t.scene;
  s.name = t.name;
  s.balls = {ball({1, 0}, 0.5, 1.0, {0, 1})};
  ForceDef f;
  f.type = ForceType::Pull;
  f.ball = 0;
  f.target = {0, 0};
  f.stiffness = 4.0;
  s.forces = {f};
  s.dt = 1e-3;
  s.duration = 2.0;
  ExactState exact = [](double time) {
    const double c = std::cos(2 * time), sn = std::sin(2 * time);
    return BallState{{c, 0.5 * sn}, {-2 * sn, c}, 0.0, 0.0};
  };
  t.metric = [=](const std::vector<double>&) { return exactTrajectory(0, exact, 0.5, 1.0, 2.0); };
  return t;
}

TimestepScene cradle() {
  TimestepScene t;
  t.name = "cradle";
  t.description =
      "Newton's cradle, 5 touching balls, e = 1, mu = 0: the last leaves at v0, the rest stay";
  const double v0 = 2.0, r = 0.5;
  SceneDef& s = t.scene;
  s.name = t.name;
  s.contact = {1.0, 0.0};
  for (int i = 0; i < 5; ++i) s.balls.push_back(ball({2 * r * i, 0}, r, 1.0, {i == 0 ? v0 : 0, 0}));
  s.dt = 1e-3;
  s.duration = 0.5;
  std::vector<BallState> exact;
  for (int i = 0; i < 5; ++i) exact.push_back({{2 * r * i, 0}, {0, 0}, 0.0, 0.0});
  exact[4] = {{2 * r * 4 + v0 * s.duration, 0}, {v0, 0}, 0.0, 0.0};
  const double length = v0 * s.duration;
  t.metric = [=](const std::vector<double>&) {
    return exactFinalState(exact, std::vector<double>(5, r), length, v0);
  };
  return t;
}

std::vector<double> positions(const Stepper& s) {
  std::vector<double> o;
  for (std::size_t i = 0; i < s.ballCount(); ++i) {
    const BallState b = s.ball(i);
    o.push_back(b.position.x());
    o.push_back(b.position.y());
  }
  return o;
}

TimestepScene billiards() {
  TimestepScene t;
  t.name = "billiards";
  t.description =
      "break: cue ball at 6 m/s into a rack of 15 (1 mm gaps), e = 0.95, mu = 0.05; positions at "
      "0.5 s, in radii";
  t.kind = MetricKind::ConvergedReference;
  const double r = 0.1, gap = 1e-3;
  SceneDef& s = t.scene;
  s.name = t.name;
  s.contact = {0.95, 0.05};
  s.walls = boxWalls({0, 0}, {5, 2.5});
  for (WallDef& w : s.walls) w.restitution = 0.8;
  // The cue is 2 cm off the rack's axis, so no two collisions are exactly
  // simultaneous and the limit dt -> 0 is one well-defined sequence.
  s.balls.push_back(ball({1.0, 1.25 + 0.02}, r, 0.17, {6.0, 0}));
  const double dx = (2 * r + gap) * std::sqrt(3.0) / 2, dy = 2 * r + gap;
  for (int row = 0; row < 5; ++row)
    for (int k = 0; k <= row; ++k)
      s.balls.push_back(ball({3.5 + row * dx, 1.25 + (k - row / 2.0) * dy}, r, 0.17));
  s.dt = 1e-3;
  s.duration = 0.5;
  t.referenceDt = 2e-6;
  t.observable = positions;
  t.referenceScale = r;  // error in ball radii
  t.metric = [](const std::vector<double>& ref) { return referenceMatch(positions, ref, 0.1); };
  return t;
}

std::vector<double> centreOfMassHeight(const Stepper& s) {
  double y = 0.0;
  for (std::size_t i = 0; i < s.ballCount(); ++i) y += s.ball(i).position.y();
  return {y / static_cast<double>(s.ballCount())};
}

TimestepScene pile() {
  TimestepScene t;
  t.name = "pile";
  t.description =
      "200 balls dropped into a 3 m wide box, e = 0.3, mu = 0.5, 1.5 s: settled centre-of-mass "
      "height";
  t.kind = MetricKind::ConvergedReference;
  const double r = 0.1;
  SceneDef& s = t.scene;
  s.name = t.name;
  s.gravity = {0.0, -kG};
  s.contact = {0.3, 0.5};
  s.walls = boxWalls({0, 0}, {3, 8});
  SplitMix rng{7};
  for (int row = 0; row < 20; ++row)
    for (int col = 0; col < 10; ++col)
      s.balls.push_back(
          ball({0.3 + 0.27 * col + 0.02 * (rng.uniform() - 0.5), 0.15 + 0.22 * row}, r, 1.0));
  s.dt = 1e-3;
  s.duration = 1.5;
  t.referenceDt = 1e-4;
  t.observable = centreOfMassHeight;
  t.referenceScale = r;
  t.metric = [](const std::vector<double>& ref) {
    return referenceMatch(centreOfMassHeight, ref, 0.1);
  };
  return t;
}

TimestepScene gas() {
  TimestepScene t;
  t.name = "gas";
  t.description =
      "1000 elastic smooth balls in a 20 m box, random velocities 0.5-1.5 m/s, 0.25 s: energy "
      "drift";
  t.kind = MetricKind::Conservation;
  SceneDef& s = t.scene;
  s.name = t.name;
  s.contact = {1.0, 0.0};
  s.walls = boxWalls({0, 0}, {20, 20});
  SplitMix rng{11};
  for (int k = 0; k < 1000; ++k) {
    const double angle = 2 * std::numbers::pi * rng.uniform(), speed = 0.5 + rng.uniform();
    s.balls.push_back(ball({0.5 + 0.6 * (k % 32), 0.5 + 0.6 * (k / 32)}, 0.1, 1.0,
                           {speed * std::cos(angle), speed * std::sin(angle)}));
  }
  s.dt = 1e-3;
  s.duration = 0.25;  // ~250 collisions; the bench sweeps it 20 times
  t.metric = [m = masses(s), j = inertias(s)](const std::vector<double>&) {
    return energyDrift(m, j);
  };
  return t;
}

}  // namespace

std::vector<TimestepScene> catalogue() {
  return {bounce(), slideRoll(), inclineRoll(), obliqueSpin(), pull(),
          cradle(), billiards(), pile(),        gas()};
}

TimestepScene catalogueScene(const std::string& name) {
  for (TimestepScene& t : catalogue())
    if (t.name == name) return t;
  throw std::out_of_range("no time-stepped scene named '" + name + "'");
}

SceneDef withStep(const SceneDef& scene, double dt) {
  SceneDef s = scene;
  s.dt = dt;
  return s;
}

Reference computeReference(const TimestepScene& t) {
  auto observe = [&](double dt) {
    const SceneDef s = withStep(t.scene, dt);
    auto stepper = engineStepper(s);
    const long long n = s.stepCount();
    for (long long k = 0; k < n; ++k) stepper->step();
    return t.observable(*stepper);
  };
  Reference ref;
  ref.values = observe(t.referenceDt);
  const std::vector<double> coarse = observe(2 * t.referenceDt);
  for (std::size_t i = 0; i < coarse.size(); ++i)
    ref.convergence =
        std::max(ref.convergence, std::fabs(coarse[i] - ref.values[i]) / t.referenceScale);
  return ref;
}

}  // namespace particles::timestep
