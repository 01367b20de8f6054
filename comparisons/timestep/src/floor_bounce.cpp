#include "particles/timestep/floor_bounce.h"

#include <cmath>

namespace particles::timestep {

// Derivation (docs/bench.md): the floor pushes at the contact point (0, -r)
// from the centre with an impulse (Fx, Pn). Pn = m (1 + e)|vy| gives vy' =
// -e vy. Fx changes vx by Fx/m and the spin by r Fx / J (the torque of Fx
// applied below the centre), so the slip s = vx + w r changes by
// Fx (1 + 1/q) / m. Sticking cancels it: Fx = -m s q / (1 + q), allowed
// while |Fx| <= mu Pn; otherwise Fx = -mu Pn sign(s).
FloorBounce floorBounce(double vx, double vy, double w, double r, double q, double e, double mu) {
  const double s = vx + w * r;
  const double pn = (1.0 + e) * std::fabs(vy);  // normal impulse per unit mass
  FloorBounce out{vx, -e * vy, w, true};
  const double stickFx = -s * q / (1.0 + q);  // per unit mass
  if (std::fabs(stickFx) <= mu * pn) {
    out.vx = (vx - q * w * r) / (1.0 + q);
    out.w = w - s / ((1.0 + q) * r);
    return out;
  }
  const double sign = s > 0.0 ? 1.0 : -1.0;
  out.sticking = false;
  out.vx = vx - mu * pn * sign;
  out.w = w - mu * pn * sign / (q * r);
  return out;
}

}  // namespace particles::timestep
