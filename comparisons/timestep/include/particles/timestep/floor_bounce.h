// Closed form of one impact of a disk on a fixed floor (normal +y), Walton's
// model with beta0 = 0 (docs/closed-form.md), derived here on its own for the
// time-stepped oblique-bounce scene; the tests check it against the long-double
// truth of comparisons/truth.
#pragma once

namespace particles::timestep {

struct FloorBounce {
  double vx, vy, w;  // m/s, m/s, rad/s after the impact
  bool sticking;     // true: the contact point leaves with zero slip
};

// A disk of radius r with inertia ratio q = J/(m r^2) arriving with
// (vx, vy < 0) and spin w; restitution e, friction mu (>= 0, may be +inf).
// Slip of the contact point: s = vx + w r. Sticking iff |s| <= mu (1 + e)
// |vy| (1 + q) / q; then vx' = (vx - q w r)/(1 + q), w' = -vx'/r. Otherwise
// vx' = vx - mu (1 + e) |vy| sign(s), w' = w - mu (1 + e) |vy| sign(s) / (q r).
FloorBounce floorBounce(double vx, double vy, double w, double r, double q, double e, double mu);

}  // namespace particles::timestep
