// The kinetic theory of a gas of equal rough disks (normal restitution e,
// Coulomb friction mu, the engine's impact law), apart from the engine: the tests compare the
// engine's rough gas with it. Derived in docs/scale.md, "The rough gas",
// after Huthmann & Zippelius (1997) and Luding, Huthmann, McNamara &
// Zippelius, PRE 58, 3416 (1998), from molecular chaos: at a collision the
// two disks' velocities and spins are independent, Maxwellian, and the
// collision picks pairs in proportion to their normal approach.
//
// Units: k_B = 1. The translational temperature is the mean translational
// kinetic energy per disk, Ttr = m <|v|^2> / 2 (two degrees of freedom), the
// rotational one twice the mean rotational energy, Trot = J <w^2> (one
// degree of freedom): at equipartition Trot = Ttr. J = q m r^2.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "particles/types.h"
#include "particles/world.h"

namespace particles::test {

// Equal uniform disks with the engine's impact law (Walton's with
// beta0 = 0): normal restitution e, and a tangential impulse that stops the
// contact's slip (sticks) unless that needs more than mu times the normal
// impulse, when it is mu times the normal impulse against the slip (slides).
struct RoughDisks {
  double restitution = 1.0;   // e, dimensionless
  double friction = kNoSlip;  // mu, dimensionless; kNoSlip: always sticks
  double q = 0.5;             // J / (m r^2), 1/2 for a uniform disk
};

// The mean changes of the pair's translational and rotational kinetic energy
// per collision, in units of Ttr, at R = Trot / Ttr. The impulse on disk 1
// is P = -m (eta_n g_n n + kappa g_t tau) with eta_n = (1 + e) / 2 and
// kappa = eta0 = M_t / m = q / (2 (1 + q)) when the contact sticks,
// eta0 k g_n / |g_t| when it slides, k = mu (1 + e) M_n / M_t. Over the
// collisions g_n has the density (g_n / s^2) exp(-g_n^2 / 2 s^2) (the
// Maxwellian, weighted by the approach), s^2 = 2 Ttr / m, and g_t = u + W
// is Gaussian of variance sigma^2 = s^2 + w^2 independent of g_n, u the
// relative velocity along tau (variance s^2) and W = r (w1 + w2) (variance
// w^2 = 2 Trot / (q m)); so <kappa g_t W> = (w^2 / sigma^2) <kappa g_t^2>.
// With A = <kappa g_t^2> and B = <kappa^2 g_t^2> (m = Ttr = 1):
//   dEtr  = -4 eta_n (1 - eta_n) - (s^2 / sigma^2) A + B
//   dErot = -(w^2 / sigma^2) A + B / q
// (sticking always, A = eta0 sigma^2 and B = eta0^2 sigma^2, Huthmann and
// Zippelius's rough disks with beta = 0).
struct PairEnergyChange {
  double translational;
  double rotational;
};

inline PairEnergyChange pairEnergyChange(const RoughDisks& d, double R) {
  const double en = 0.5 * (1.0 + d.restitution);
  const double eta0 = d.q / (2.0 * (1.0 + d.q));
  const double s2 = 2.0, w2 = 2.0 * R / d.q, sigma2 = s2 + w2;
  double A = eta0 * sigma2, B = eta0 * eta0 * sigma2;
  if (!std::isinf(d.friction)) {
    // M_n / M_t = (m / 2) / (eta0 m) for equal disks.
    const double k = d.friction * (1.0 + d.restitution) * 0.5 / eta0;
    const double sigma = std::sqrt(sigma2);
    // Over g_n (Simpson, 4,000 intervals up to 12 s), the Gaussian g_t in
    // closed form: with a = k g_n, z = a / sigma and phi, Phi the standard
    // normal density and distribution,
    //   E[g_t^2; |g_t| <= a] = sigma^2 (2 Phi(z) - 1) - 2 a sigma phi(z),
    //   E[|g_t|; |g_t| > a] = 2 sigma phi(z),  P(|g_t| > a) = 2 (1 - Phi(z)).
    const int n = 4000;
    const double top = 12.0 * std::sqrt(s2), h = top / n;
    double sumA = 0.0, sumB = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double gn = i * h, a = k * gn, z = a / sigma;
      const double density = gn / s2 * std::exp(-gn * gn / (2.0 * s2));
      const double phi = std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
      const double tail = std::erfc(z / std::numbers::sqrt2);  // 2 (1 - Phi(z))
      const double stick = sigma2 * (1.0 - tail) - 2.0 * a * sigma * phi;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sumA += w * density * (stick + a * 2.0 * sigma * phi);
      sumB += w * density * (stick + a * a * tail);
    }
    A = eta0 * sumA * h / 3.0;
    B = eta0 * eta0 * sumB * h / 3.0;
  }
  return {-4.0 * en * (1.0 - en) - s2 / sigma2 * A + B, -w2 / sigma2 * A + B / d.q};
}

// Per collision counted at each of its two disks (c: collisions per disk,
// each collision adding 1 to both), Ttr = sum m v^2 / 2 / N changes by the
// pair's change / 2 per unit c and Trot / 2 = sum J w^2 / 2 / N by the same,
// so  dTtr/dc = Ttr dEtr / 2,  dTrot/dc = Ttr dErot,
// and R = Trot / Ttr obeys dR/dc = dErot - R dEtr / 2, free of the collision
// rate and of the density.
inline double ratioSlope(const RoughDisks& d, double R) {
  const PairEnergyChange c = pairEnergyChange(d, R);
  return c.rotational - 0.5 * R * c.translational;
}

// The fixed point of dR/dc (the homogeneous cooling state's ratio): the
// positive root of the quadratic ratioSlope(R) = 0, found by bisection on
// [0, 1e3] (ratioSlope is > 0 at 0 and < 0 for large R).
inline double coolingStateRatio(const RoughDisks& d) {
  double lo = 0.0, hi = 1e3;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (ratioSlope(d, mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Ttr and Trot after c collisions per disk from (Ttr0, Trot0): the two
// equations above, integrated by classical Runge-Kutta in steps of c / 1000.
struct Temperatures {
  double translational;
  double rotational;
};

inline Temperatures afterCollisions(const RoughDisks& d, Temperatures t, double c) {
  const int steps = 1000;
  const double h = c / steps;
  const auto slope = [&](const Temperatures& s) {
    const PairEnergyChange e = pairEnergyChange(d, s.rotational / s.translational);
    return Temperatures{0.5 * s.translational * e.translational, s.translational * e.rotational};
  };
  const auto plus = [](const Temperatures& s, const Temperatures& k, double w) {
    return Temperatures{s.translational + w * k.translational, s.rotational + w * k.rotational};
  };
  for (int i = 0; i < steps; ++i) {
    const Temperatures k1 = slope(t), k2 = slope(plus(t, k1, h / 2)),
                       k3 = slope(plus(t, k2, h / 2)), k4 = slope(plus(t, k3, h));
    t.translational +=
        h / 6 * (k1.translational + 2 * k2.translational + 2 * k3.translational + k4.translational);
    t.rotational += h / 6 * (k1.rotational + 2 * k2.rotational + 2 * k3.rotational + k4.rotational);
  }
  return t;
}

// The measured temperatures of a gas of disks of mass m (kg), radius r (m)
// and uniform-disk inertia.
inline Temperatures measuredTemperatures(const std::vector<BallState>& balls, double m, double r) {
  double tr = 0.0, rot = 0.0;
  for (const BallState& b : balls) {
    tr += 0.5 * m * b.velocity.squaredNorm();
    rot += 0.5 * m * r * r * b.angularVelocity * b.angularVelocity;
  }
  const double n = static_cast<double>(balls.size());
  return {tr / n, rot / n};
}

}  // namespace particles::test
