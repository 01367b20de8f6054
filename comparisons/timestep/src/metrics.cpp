#include "particles/timestep/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace particles::timestep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class ApexHeights : public Metric {
 public:
  ApexHeights(std::size_t ball, double floorY, double radius, double e, double h0, int apexes)
      : ball_(ball), floor_(floorY + radius), e_(e), h0_(h0), apexes_(apexes) {}
  void start(const Stepper& s) override {
    const BallState b = s.ball(ball_);
    previousVy_ = b.velocity.y();
  }
  void observe(const Stepper& s) override {
    const BallState b = s.ball(ball_);
    const double h = b.position.y() - floor_;
    const double vy = b.velocity.y();
    if (vy > 0.0) {
      rising_ = true;
      arcTop_ = std::max(arcTop_, h);
    } else if (rising_ && previousVy_ > 0.0) {
      // The arc ends at the first sample that no longer rises; it may itself
      // be the highest one.
      measured_.push_back(std::max(arcTop_, h));
      rising_ = false;
      arcTop_ = -kInf;
    }
    previousVy_ = vy;
  }
  double error() const override {
    double worst = 0.0;
    for (int k = 1; k <= apexes_; ++k) {
      if (static_cast<std::size_t>(k) > measured_.size()) return std::max(worst, 1.0);
      const double expected = std::pow(e_, 2.0 * k) * h0_;
      worst = std::max(worst, std::fabs(measured_[k - 1] - expected) / h0_);
    }
    return worst;
  }

 private:
  std::size_t ball_;
  double floor_, e_, h0_;
  int apexes_;
  double previousVy_ = 0.0, arcTop_ = -kInf;
  bool rising_ = false;
  std::vector<double> measured_;
};

class SlideToRoll : public Metric {
 public:
  SlideToRoll(std::size_t ball, double v0, double radius, double q, double mu, double g)
      : ball_(ball),
        v0_(v0),
        r_(radius),
        tStar_(v0 / (mu * g * (1.0 + 1.0 / q))),
        vf_(v0 / (1.0 + q)) {}
  void observe(const Stepper& s) override {
    const BallState b = s.ball(ball_);
    const double slip = b.velocity.x() + b.angularVelocity * r_;
    if (tRoll_ < 0.0) {
      if (std::fabs(slip) <= 1e-4 * v0_) {
        // While sliding the slip falls linearly (constant friction force):
        // extend the line through the last two sliding samples to zero, so
        // the time is not rounded up to the sample after t*.
        tRoll_ = s.time();
        if (samples_ >= 2 && slip0_ > slip1_) {
          const double t = t1_ + slip1_ * (t1_ - t0_) / (slip0_ - slip1_);
          tRoll_ = std::clamp(t, t1_, s.time());
        }
      } else {
        t0_ = t1_, slip0_ = slip1_;
        t1_ = s.time(), slip1_ = std::fabs(slip);
        ++samples_;
      }
    }
    vx_ = b.velocity.x();
  }
  double error() const override {
    if (tRoll_ < 0.0) return 1.0;
    return std::max(std::fabs(tRoll_ - tStar_) / tStar_, std::fabs(vx_ - vf_) / vf_);
  }

 private:
  std::size_t ball_;
  double v0_, r_, tStar_, vf_;
  double tRoll_ = -1.0, vx_ = 0.0;
  double t0_ = 0.0, slip0_ = 0.0, t1_ = 0.0, slip1_ = 0.0;  // the last two sliding samples
  int samples_ = 0;
};

class ConstantAcceleration : public Metric {
 public:
  ConstantAcceleration(std::size_t ball, Vec2 dir, double a) : ball_(ball), dir_(dir), a_(a) {}
  void start(const Stepper& s) override { start_ = s.ball(ball_).position; }
  void observe(const Stepper& s) override {
    const double t = s.time();
    const double along = (s.ball(ball_).position - start_).dot(dir_);
    worst_ = std::max(worst_, std::fabs(along - 0.5 * a_ * t * t));
    tEnd_ = t;
  }
  double error() const override {
    const double scale = 0.5 * a_ * tEnd_ * tEnd_;
    return scale > 0.0 ? worst_ / scale : kInf;
  }

 private:
  std::size_t ball_;
  Vec2 dir_, start_{0.0, 0.0};
  double a_, worst_ = 0.0, tEnd_ = 0.0;
};

double stateError(const BallState& b, const BallState& x, double radius, double lengthScale,
                  double speedScale) {
  return std::max({(b.position - x.position).norm() / lengthScale,
                   (b.velocity - x.velocity).norm() / speedScale,
                   std::fabs(b.angularVelocity - x.angularVelocity) * radius / speedScale});
}

class ExactTrajectory : public Metric {
 public:
  ExactTrajectory(std::size_t ball, ExactState exact, double radius, double length, double speed,
                  std::vector<double> jumps)
      : ball_(ball),
        exact_(std::move(exact)),
        r_(radius),
        length_(length),
        speed_(speed),
        jumps_(std::move(jumps)) {}
  void observe(const Stepper& s) override {
    const BallState b = s.ball(ball_);
    const double t = s.time();
    double e = stateError(b, exact_(t), r_, length_, speed_);
    for (double tj : jumps_)
      if (std::fabs(t - tj) <= 1e-9)
        e = std::min({e, stateError(b, exact_(tj), r_, length_, speed_),
                      stateError(b, exact_(std::nextafter(tj, INFINITY)), r_, length_, speed_)});
    worst_ = std::max(worst_, e);
  }
  double error() const override { return worst_; }

 private:
  std::size_t ball_;
  ExactState exact_;
  double r_, length_, speed_, worst_ = 0.0;
  std::vector<double> jumps_;
};

class ExactFinalState : public Metric {
 public:
  ExactFinalState(std::vector<BallState> exact, std::vector<double> radii, double length,
                  double speed)
      : exact_(std::move(exact)), radii_(std::move(radii)), length_(length), speed_(speed) {}
  void observe(const Stepper& s) override {
    last_ = 0.0;
    for (std::size_t i = 0; i < exact_.size(); ++i)
      last_ = std::max(last_, stateError(s.ball(i), exact_[i], radii_[i], length_, speed_));
  }
  double error() const override { return last_; }

 private:
  std::vector<BallState> exact_;
  std::vector<double> radii_;
  double length_, speed_, last_ = 0.0;
};

class EnergyDrift : public Metric {
 public:
  EnergyDrift(std::vector<double> m, std::vector<double> j) : m_(std::move(m)), j_(std::move(j)) {}
  void start(const Stepper& s) override { e0_ = energy(s); }
  void observe(const Stepper& s) override {
    worst_ = std::max(worst_, std::fabs(energy(s) - e0_) / e0_);
  }
  double error() const override { return worst_; }

 private:
  double energy(const Stepper& s) const {
    double e = 0.0;
    for (std::size_t i = 0; i < m_.size(); ++i) {
      const BallState b = s.ball(i);
      e += 0.5 * m_[i] * b.velocity.squaredNorm() +
           0.5 * j_[i] * b.angularVelocity * b.angularVelocity;
    }
    return e;
  }
  std::vector<double> m_, j_;
  double e0_ = 0.0, worst_ = 0.0;
};

class ReferenceMatch : public Metric {
 public:
  ReferenceMatch(Observable o, std::vector<double> ref, double scale)
      : observable_(std::move(o)), ref_(std::move(ref)), scale_(scale) {}
  // Only the final state counts: keep the stepper (alive until error() is
  // asked, as in measure()) and read the observable then.
  void observe(const Stepper& s) override { last_ = &s; }
  double error() const override {
    if (last_ == nullptr) return kInf;
    const std::vector<double> o = observable_(*last_);
    double worst = 0.0;
    for (std::size_t i = 0; i < o.size() && i < ref_.size(); ++i)
      worst = std::max(worst, std::fabs(o[i] - ref_[i]) / scale_);
    return std::isfinite(worst) ? worst : kInf;
  }

 private:
  Observable observable_;
  std::vector<double> ref_;
  double scale_;
  const Stepper* last_ = nullptr;
};

bool finiteState(const Stepper& s) {
  for (std::size_t i = 0; i < s.ballCount(); ++i) {
    const BallState b = s.ball(i);
    if (!std::isfinite(b.position.x()) || !std::isfinite(b.position.y()) ||
        !std::isfinite(b.velocity.x()) || !std::isfinite(b.velocity.y()) ||
        !std::isfinite(b.angularVelocity))
      return false;
  }
  return true;
}

}  // namespace

const char* metricKindName(MetricKind kind) {
  switch (kind) {
    case MetricKind::Analytic:
      return "analytic";
    case MetricKind::ConvergedReference:
      return "converged reference";
    case MetricKind::Conservation:
      return "conservation";
  }
  return "?";
}

std::unique_ptr<Metric> apexHeights(std::size_t ball, double floorY, double radius, double e,
                                    double h0, int apexes) {
  return std::make_unique<ApexHeights>(ball, floorY, radius, e, h0, apexes);
}
std::unique_ptr<Metric> slideToRoll(std::size_t ball, double v0, double radius, double q, double mu,
                                    double g) {
  return std::make_unique<SlideToRoll>(ball, v0, radius, q, mu, g);
}
std::unique_ptr<Metric> constantAcceleration(std::size_t ball, Vec2 downhill, double a) {
  return std::make_unique<ConstantAcceleration>(ball, downhill.normalized(), a);
}
std::unique_ptr<Metric> exactTrajectory(std::size_t ball, ExactState exact, double radius,
                                        double lengthScale, double speedScale,
                                        std::vector<double> jumps) {
  return std::make_unique<ExactTrajectory>(ball, std::move(exact), radius, lengthScale, speedScale,
                                           std::move(jumps));
}
std::unique_ptr<Metric> exactFinalState(std::vector<BallState> exact, std::vector<double> radii,
                                        double lengthScale, double speedScale) {
  return std::make_unique<ExactFinalState>(std::move(exact), std::move(radii), lengthScale,
                                           speedScale);
}
std::unique_ptr<Metric> energyDrift(std::vector<double> masses, std::vector<double> inertias) {
  return std::make_unique<EnergyDrift>(std::move(masses), std::move(inertias));
}
std::unique_ptr<Metric> referenceMatch(Observable observe, std::vector<double> reference,
                                       double scale) {
  return std::make_unique<ReferenceMatch>(std::move(observe), std::move(reference), scale);
}

double measure(Stepper& s, Metric& m, long long steps) {
  m.start(s);
  for (long long k = 0; k < steps; ++k) {
    s.step();
    m.observe(s);
    if (k % 1000 == 999 && !finiteState(s)) return kInf;
  }
  if (!finiteState(s)) return kInf;
  const double e = m.error();
  return std::isnan(e) ? kInf : e;
}

}  // namespace particles::timestep
