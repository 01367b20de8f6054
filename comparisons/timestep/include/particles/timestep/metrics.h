// Error metrics of time-stepped scenes. Each metric watches a run (start(),
// then observe() after every step) and returns one dimensionless error:
// 0 is perfect, 1 is "as large as the quantity itself". Which scale each
// metric divides by is said next to it, and in docs/bench.md.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "particles/timestep/stepper.h"

namespace particles::timestep {

enum class MetricKind {
  Analytic,            // against a closed-form answer
  ConvergedReference,  // against the same engine at a far smaller dt
  Conservation,        // a conserved quantity's drift
};
const char* metricKindName(MetricKind kind);

class Metric {
 public:
  virtual ~Metric() = default;
  virtual void start(const Stepper& s) { observe(s); }
  virtual void observe(const Stepper& s) = 0;
  virtual double error() const = 0;  // dimensionless, >= 0; +inf when it cannot be judged
};

// A ball dropped from rest with its lowest point h0 above a floor at
// y = floorY, restitution e: apex k (k = 1..apexes) is at h_k = e^{2k} h0.
// Error: max_k |h_k,measured - h_k| / h0; a missing apex counts as 1.
// The apex of an arc is the highest sample on it (the first sample after the
// ball stops rising ends the arc).
std::unique_ptr<Metric> apexHeights(std::size_t ball, double floorY, double radius, double e,
                                    double h0, int apexes);

// A disk (inertia ratio q = J/(m r^2)) on a floor with velocity v0 > 0 along
// +x and no spin, friction mu, gravity g: it slides until t* = v0 / (mu g (1
// + 1/q)) and then rolls at vf = v0 / (1 + q) (2/3 v0 for a uniform disk).
// Rolling is seen at the first sample with |vx + w r| <= 1e-4 v0; t_roll is
// where the line through the last two sliding samples' slips reaches zero
// (the slip falls linearly while sliding), kept between those samples.
// Error: max(|t_roll - t*| / t*, |vx(end) - vf| / vf); never rolling counts as 1.
std::unique_ptr<Metric> slideToRoll(std::size_t ball, double v0, double radius, double q, double mu,
                                    double g);

// Displacement of a ball along a unit direction `downhill` from its start:
// s(t) = a t^2 / 2 (a constant acceleration a, from rest).
// Error: max over samples |s - a t^2/2| / (a T^2 / 2), T the last sample's time.
std::unique_ptr<Metric> constantAcceleration(std::size_t ball, Vec2 downhill, double a);

// A ball's whole state against an exact trajectory `exact(t)`.
// Error: max over samples of max(|dx| / lengthScale, |dv| / speedScale,
// |dw| r / speedScale). At an impact time in `jumps` (s) the exact velocity
// has two values, before and after; a sample within 1e-9 s of one is
// compared with the nearer of the two (exact(t_j) and exact(just after t_j)).
using ExactState = std::function<BallState(double t)>;
std::unique_ptr<Metric> exactTrajectory(std::size_t ball, ExactState exact, double radius,
                                        double lengthScale, double speedScale,
                                        std::vector<double> jumps = {});

// The final state against exact final states (only the last sample counts).
// Error: max over balls of max(|dx| / lengthScale, |dv| / speedScale, |dw| r_i / speedScale).
std::unique_ptr<Metric> exactFinalState(std::vector<BallState> exact, std::vector<double> radii,
                                        double lengthScale, double speedScale);

// Energy of free balls (kinetic + rotational, no potential): max over samples
// |E(t) - E(0)| / E(0).
std::unique_ptr<Metric> energyDrift(std::vector<double> masses, std::vector<double> inertias);

// Observables of the final state against the same observables of a reference
// run. Error: max_i |o_i - o_i,ref| / scale.
using Observable = std::function<std::vector<double>(const Stepper&)>;
std::unique_ptr<Metric> referenceMatch(Observable observe, std::vector<double> reference,
                                       double scale);

// Runs `steps` steps of `s` under `m` and returns m.error(); +inf if a ball's
// state turned non-finite (checked at the end and every 1000 steps).
double measure(Stepper& s, Metric& m, long long steps);

}  // namespace particles::timestep
