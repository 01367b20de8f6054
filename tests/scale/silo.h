// A flat-bottomed 2D silo of frictional disks discharging through an
// orifice in its floor into a bin below, and Beverloo's law it is checked
// against (../shared/PHYSICS-REFERENCES.md, "Silo discharge"; docs/scale.md,
// "The silo"). Written here, apart from the engine.
#pragma once

#include <numbers>
#include <random>
#include <vector>

#include "particles/scene.h"
#include "particles/world.h"

namespace particles::test {

// The silo's dimensions and material. Lengths in m; the mean diameter is
// 1 m, so lengths are also in mean diameters.
struct SiloDef {
  int balls = 3200;
  double width = 44.0;       // m, inner width of silo and bin
  double orifice = 8.0;      // m, the opening D in the middle of the floor
  double binDepth = 40.0;    // m, the bin's floor below the silo's
  double radiusLo = 0.45;    // m, radii uniform in [radiusLo, radiusHi]:
  double radiusHi = 0.55;    //    polydisperse, so the fill does not crystallise
  double density = 1.0;      // kg/m^2
  double restitution = 0.5;  // the pile's (issue 5)
  double friction = 0.5;     // the pile's
  double gravity = 10.0;     // m/s^2
  double dt = 1.0 / 60.0;    // s, the pile's (issue 5)
  unsigned seed = 20261208;
};

// The silo's floor is the line y = 0; the orifice spans |x| < D/2; the bin's
// floor is y = -binDepth. Wall order: the box (bottom, right, top, left),
// then the floor: shut, one segment across the silo; open, its two halves,
// two-sided (a ball leaving through the orifice passes their ends with its
// centre below the line). The fill: a jittered grid of spacing 1.2 m above
// the floor, row by row, at rest.
inline SceneDef siloScene(const SiloDef& d, bool open) {
  SceneDef s;
  s.dt = d.dt;
  s.gravity = {0.0, -d.gravity};
  s.contact = {d.restitution, d.friction};
  const double half = 0.5 * d.width;
  const int cols = static_cast<int>((d.width - 1.2) / 1.2);
  const int rows = (d.balls + cols - 1) / cols;
  s.walls = boxWalls({-half, -d.binDepth}, {half, 1.2 * rows + 2.0});
  const auto floor = [&](double x0, double x1) {
    WallDef w;
    w.a = {x0, 0.0};
    w.b = {x1, 0.0};
    s.walls.push_back(w);
  };
  if (open) {
    floor(-half, -0.5 * d.orifice);
    floor(0.5 * d.orifice, half);
  } else {
    floor(-half, half);
  }
  std::mt19937_64 rng(d.seed);
  const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (int k = 0; k < d.balls; ++k) {
    BallDef b;
    b.radius = d.radiusLo + (d.radiusHi - d.radiusLo) * uniform();
    b.mass = d.density * std::numbers::pi * b.radius * b.radius;
    const int i = k % cols, j = k / cols;
    b.position = {-half + 1.2 * (i + 0.5) + 0.1 * (uniform() - 0.5) + 0.05,
                  1.2 * (j + 0.5) + 0.1 * (uniform() - 0.5)};
    s.balls.push_back(b);
  }
  return s;
}

// The fill settled for `steps` on the shut floor: the same for every
// orifice, so a seed's fill is settled once for all of them.
inline std::vector<BallState> settledFill(const SiloDef& d, long long steps) {
  World w(siloScene(d, false));
  w.run(steps);
  return w.balls();
}

// The silo with orifice d.orifice open under the settled fill.
inline SceneDef openSilo(const SiloDef& d, const std::vector<BallState>& fill) {
  SceneDef open = siloScene(d, true);
  for (std::size_t i = 0; i < open.balls.size(); ++i) {
    open.balls[i].position = fill[i].position;
    open.balls[i].velocity = fill[i].velocity;
    open.balls[i].angle = fill[i].angle;
    open.balls[i].angularVelocity = fill[i].angularVelocity;
  }
  return open;
}

// The mass (kg) of the balls whose centre lies below the silo's floor: the
// mass discharged.
inline double dischargedMass(const World& w) {
  double m = 0.0;
  for (std::size_t i = 0; i < w.ballCount(); ++i)
    if (w.ball(i).position.y() < 0.0) m += w.scene().balls[i].mass;
  return m;
}

// The bulk density (kg/m^2) of a settled fill: the mass of the balls whose
// centre lies in the window [lo, hi] over the window's area.
inline double bulkDensity(const SiloDef& d, const std::vector<BallState>& fill, Vec2 lo, Vec2 hi) {
  const SceneDef s = siloScene(d, false);  // the masses
  double m = 0.0;
  for (std::size_t i = 0; i < fill.size(); ++i) {
    const Vec2 x = fill[i].position;
    if (x.x() >= lo.x() && x.x() < hi.x() && x.y() >= lo.y() && x.y() < hi.y())
      m += s.balls[i].mass;
  }
  return m / ((hi.x() - lo.x()) * (hi.y() - lo.y()));
}

// A straight line y = slope x + intercept fitted by least squares to the
// points added one by one.
struct LineFit {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  void add(double x, double y) {
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  double slope() const { return (n * sxy - sx * sy) / (n * sxx - sx * sx); }
  double intercept() const { return (sy - slope() * sx) / n; }
};

// The mass flow rate (kg/s) through the orifice d.orifice under the settled
// fill, fitted by least squares to the mass discharged, sampled every 6
// steps from `from` s to `to` s after the orifice opens.
inline double dischargeRate(const SiloDef& d, const std::vector<BallState>& fill, double from,
                            double to) {
  World w(openSilo(d, fill));
  const long long every = 6;
  LineFit discharged;
  while (w.time() < to - 0.5 * d.dt) {
    w.run(every);
    if (w.time() < from - 0.5 * d.dt) continue;
    discharged.add(w.time(), dischargedMass(w));
  }
  return discharged.slope();
}

}  // namespace particles::test
