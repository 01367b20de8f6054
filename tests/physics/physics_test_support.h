// Shared helpers of the physics tests: a ball with its full state (position,
// velocity, spin, mass properties), the invariants computed from first
// principles (never through the engine's own formulas), and a reproducible
// generator of random ball-ball impacts.
//
// Every quantity here is computed from its definition:
//   surface velocity of a ball at a point p:  v + w z x (p - x)
//   linear momentum:                          m v
//   angular momentum about a point c:         J w + m (x - c) x v
//   kinetic energy:                           m v^2 / 2 + J w^2 / 2
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "particles/contact_impulse.h"
#include "particles/material.h"
#include "particles/types.h"

namespace physics_test {

using particles::Vec2;

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

// Relative tolerance for quantities that are exact in real arithmetic and
// differ only by rounding. One impact is a chain of fewer than ~30 flops on
// operands of the size of the scale used, so rounding stays below ~30 eps
// = 7e-15 of the scale; 1e-12 (~4500 eps) leaves margin for the scale being a
// sum of terms, and is still 10 orders of magnitude below any physics error
// (a wrong sign or a missing term shows at O(1) of the scale).
inline constexpr double kRoundingRel = 1e-12;

// z x v, written out here rather than borrowed from the engine.
inline Vec2 zCross(const Vec2& v) {
  return Vec2(-v.y(), v.x());
}
// z component of a x b.
inline double crossZ(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A ball with everything the invariants need.
struct Ball {
  Vec2 x{0.0, 0.0};  // centre, m
  Vec2 v{0.0, 0.0};  // m/s
  double w = 0.0;    // rad/s, CCW
  double m = 1.0;    // kg
  double r = 0.5;    // m
  double J = 0.125;  // kg m^2
};

inline Vec2 surfaceVelocity(const Ball& b, const Vec2& p) {
  return b.v + b.w * zCross(p - b.x);
}
inline Vec2 momentum(const Ball& b) {
  return b.m * b.v;
}
inline double angularMomentumAbout(const Ball& b, const Vec2& c) {
  return b.J * b.w + b.m * crossZ(b.x - c, b.v);
}
inline double kineticEnergy(const Ball& b) {
  return 0.5 * b.m * b.v.squaredNorm() + 0.5 * b.J * b.w * b.w;
}

inline particles::ContactBody contactBody(const Ball& b) {
  particles::ContactBody body;
  body.velocity = b.v;
  body.angularVelocity = b.w;
  body.invMass = 1.0 / b.m;
  body.invInertia = 1.0 / b.J;
  body.leverArm = b.r;
  return body;
}

// A wall as the engine's contact formulas see it: immovable, not rotating.
inline particles::ContactBody wallBody() {
  return particles::ContactBody{};
}

enum class Friction { NoSlip, Limited, Smooth };

inline const char* toString(Friction f) {
  switch (f) {
    case Friction::NoSlip:
      return "no-slip";
    case Friction::Limited:
      return "friction-limited";
    case Friction::Smooth:
      return "smooth";
  }
  return "?";
}

// One ball-ball impact: a and b touch at c = x_a + r_a n = x_b - r_b n.
struct ImpactCase {
  std::uint64_t index = 0;
  Friction mode = Friction::NoSlip;
  Ball a, b;
  Vec2 n{1.0, 0.0};  // unit, from a to b
  Vec2 c{0.0, 0.0};  // contact point
  particles::ContactMaterial material;

  std::string describe() const {
    std::ostringstream s;
    s.precision(17);
    auto ball = [&s](const char* name, const Ball& q) {
      s << "  " << name << ": x=(" << q.x.x() << ", " << q.x.y() << ") v=(" << q.v.x() << ", "
        << q.v.y() << ") w=" << q.w << " m=" << q.m << " r=" << q.r << " J=" << q.J
        << " (q=" << q.J / (q.m * q.r * q.r) << ")\n";
    };
    s << "case #" << index << " (" << toString(mode) << ")\n";
    ball("a", a);
    ball("b", b);
    s << "  n=(" << n.x() << ", " << n.y() << ") c=(" << c.x() << ", " << c.y()
      << ") e=" << material.restitution << " mu=" << material.friction << "\n";
    return s.str();
  }
};

// Relative velocity of b's surface with respect to a's at the contact point,
// from the geometry (c - x), split on (n, tau = z x n).
struct Slip {
  double normal = 0.0;
  double tangent = 0.0;
};
inline Slip contactSlip(const Ball& a, const Ball& b, const Vec2& n, const Vec2& c) {
  const Vec2 g = surfaceVelocity(b, c) - surfaceVelocity(a, c);
  return {g.dot(n), g.dot(zCross(n))};
}

// Speed scale of an impact: every speed that enters the contact velocities.
inline double speedScale(const Ball& a, const Ball& b) {
  return a.v.norm() + b.v.norm() + std::abs(a.w) * a.r + std::abs(b.w) * b.r;
}

struct ImpactResult {
  Ball a, b;
  particles::ContactImpulse impulse;
};

// Runs the engine's resolveImpact on the case (with the given material).
inline ImpactResult collide(const ImpactCase& k, const particles::ContactMaterial& material) {
  particles::ContactBody ca = contactBody(k.a), cb = contactBody(k.b);
  ImpactResult out;
  out.impulse = particles::resolveImpact(ca, cb, k.n, material);
  out.a = k.a;
  out.b = k.b;
  out.a.v = ca.velocity;
  out.a.w = ca.angularVelocity;
  out.b.v = cb.velocity;
  out.b.w = cb.angularVelocity;
  return out;
}
inline ImpactResult collide(const ImpactCase& k) {
  return collide(k, k.material);
}

// Uniform doubles from raw 64-bit draws (std::uniform_real_distribution is
// implementation-defined, so it would not reproduce across standard
// libraries; this does).
class Random {
 public:
  explicit Random(std::uint64_t seed) : rng_(seed) {}
  double uniform01() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  std::uint64_t bits() { return rng_(); }

 private:
  std::mt19937_64 rng_;
};

// Random approaching impacts covering the brief's ranges: mass ratio m_b/m_a
// log-uniform in [1e-3, 1e3], radius ratio in [0.1, 10], inertia factor
// q = J/(m r^2) either a uniform disk (1/2) or uniform in (0.1, 1), random
// spins and approach geometry with g_n < 0, e in [0, 1] with both ends
// included, mu log-uniform in [0.01, 10] for friction-limited impacts.
class ImpactGenerator {
 public:
  explicit ImpactGenerator(std::uint64_t seed) : rand_(seed) {}

  ImpactCase next(Friction mode) {
    ImpactCase k;
    k.index = count_++;
    k.mode = mode;
    k.a.m = rand_.logUniform(0.1, 10.0);
    k.b.m = k.a.m * rand_.logUniform(1e-3, 1e3);
    k.a.r = rand_.logUniform(0.05, 1.0);
    k.b.r = k.a.r * rand_.logUniform(0.1, 10.0);
    k.a.J = inertiaFactor() * k.a.m * k.a.r * k.a.r;
    k.b.J = inertiaFactor() * k.b.m * k.b.r * k.b.r;
    const double phi = rand_.uniform(0.0, 2.0 * std::numbers::pi);
    k.n = Vec2(std::cos(phi), std::sin(phi));
    k.c = Vec2(rand_.uniform(-5.0, 5.0), rand_.uniform(-5.0, 5.0));
    k.a.x = k.c - k.a.r * k.n;
    k.b.x = k.c + k.b.r * k.n;
    // Draw velocities until the balls approach clearly (g_n < -0.01 m/s).
    do {
      k.a.v = Vec2(rand_.uniform(-3.0, 3.0), rand_.uniform(-3.0, 3.0));
      k.b.v = Vec2(rand_.uniform(-3.0, 3.0), rand_.uniform(-3.0, 3.0));
    } while ((k.b.v - k.a.v).dot(k.n) > -0.01);
    k.a.w = rand_.uniform(-3.0, 3.0) / k.a.r;
    k.b.w = rand_.uniform(-3.0, 3.0) / k.b.r;
    const double pick = rand_.uniform01();
    k.material.restitution = pick < 0.1 ? 0.0 : pick < 0.2 ? 1.0 : rand_.uniform01();
    switch (mode) {
      case Friction::NoSlip:
        k.material.friction = particles::kNoSlip;
        break;
      case Friction::Limited:
        k.material.friction = rand_.logUniform(0.01, 10.0);
        break;
      case Friction::Smooth:
        k.material.friction = 0.0;
        break;
    }
    return k;
  }

 private:
  double inertiaFactor() { return rand_.uniform01() < 0.3 ? 0.5 : rand_.uniform(0.1, 1.0); }

  Random rand_;
  std::uint64_t count_ = 0;
};

inline constexpr int kCasesPerMode = 5000;
inline constexpr Friction kAllModes[] = {Friction::NoSlip, Friction::Limited, Friction::Smooth};

// Largest value of a residual seen over a run of cases, printed at the end of
// a test so the report can quote measured figures.
class Worst {
 public:
  explicit Worst(std::string what) : what_(std::move(what)) {}
  void add(double value, std::uint64_t index) {
    if (value > value_) {
      value_ = value;
      index_ = index;
    }
  }
  double value() const { return value_; }
  ~Worst() {
    std::printf("[ measured ] %s: %.3e (case #%llu)\n", what_.c_str(), value_,
                static_cast<unsigned long long>(index_));
  }

 private:
  std::string what_;
  double value_ = 0.0;
  std::uint64_t index_ = 0;
};

}  // namespace physics_test
