// The silo (issue 5's "sand in an hourglass") against Beverloo's law, in 2D
// W = C rho_b sqrt(g) (D - k d)^(3/2) (../shared/PHYSICS-REFERENCES.md,
// "Silo discharge"; docs/scale.md, "The silo"). The geometry keeps to the
// conditions under which the law is observed (Mankoc et al., Granular
// Matter 9, 407, 2007): silo width L > 2.5 D and L > D + 30 d, and a fill
// higher than 1.2 L while it is measured, so the flow sees neither the
// width nor the height.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "silo.h"

namespace particles::test {
namespace {

// Beverloo's law with exponent beta fitted to flow rates Q (kg/s) at
// orifices D (m): Q^(1/beta) is linear in D, (A^(1/beta)) (D - k), fitted
// by least squares; `worst` is the largest |fit / Q - 1|.
struct PowerFit {
  double k = 0.0;          // m
  double prefactor = 0.0;  // A, kg s^-1 m^-beta
  double worst = 0.0;
};

PowerFit fitPower(const std::vector<double>& D, const std::vector<double>& Q, double beta) {
  LineFit line;
  for (std::size_t i = 0; i < D.size(); ++i) line.add(D[i], std::pow(Q[i], 1.0 / beta));
  PowerFit f;
  f.k = -line.intercept() / line.slope();
  f.prefactor = std::pow(line.slope(), beta);
  for (std::size_t i = 0; i < D.size(); ++i)
    f.worst = std::max(f.worst, std::abs(f.prefactor * std::pow(D[i] - f.k, beta) / Q[i] - 1.0));
  return f;
}

// Settled for 10 s on the shut floor (the fill falls from up to 90 m), then
// measured from 1 s after the orifice opens (the flow's start-up) to 7 s.
constexpr long long kSettleSteps = 600;

// Three fills (seeds 1, 2, 3): the rate of one fill is good to about 3 %
// (seeds 1 and 2 differ by 6 % at D = 12 d).
constexpr int kSeeds = 3;

// The mean flow rate (kg/s) at each orifice D (m) over `seeds` fills of the
// silo `d`, measured from `from` to `to` s after opening; the fills' mean
// bulk density (kg/m^2) in `density`, from a window above the orifices'
// reach, away from the walls.
std::vector<double> meanRates(SiloDef d, const std::vector<double>& orifices, int seeds,
                              long long settleSteps, double from, double to, double& density) {
  std::vector<double> rates(orifices.size(), 0.0);
  density = 0.0;
  for (int seed = 1; seed <= seeds; ++seed) {
    d.seed = static_cast<unsigned>(seed);
    const std::vector<BallState> fill = settledFill(d, settleSteps);
    const double rho =
        bulkDensity(d, fill, {-0.5 * d.width + 4.0, 30.0}, {0.5 * d.width - 4.0, 40.0});
    density += rho / seeds;
    for (std::size_t i = 0; i < orifices.size(); ++i) {
      d.orifice = orifices[i];
      const double q = dischargeRate(d, fill, from, to);
      std::printf("D = %4.1f m, g = %4.1f m/s^2, seed %d: %.2f kg/s (fill %.4f kg/m^2)\n",
                  d.orifice, d.gravity, seed, q, rho);
      rates[i] += q / seeds;
    }
  }
  return rates;
}

TEST(ScaleSilo, DischargeFollowsBeverloosLaw) {
  const std::vector<double> orifices = {6.0, 7.0, 8.0, 10.0, 12.0, 14.0};
  double density = 0.0;
  const std::vector<double> rates =
      meanRates(SiloDef{}, orifices, kSeeds, kSettleSteps, 1.0, 7.0, density);
  const PowerFit beverloo = fitPower(orifices, rates, 1.5);
  const PowerFit linear = fitPower(orifices, rates, 1.0);
  const double g = SiloDef{}.gravity;
  const double C = beverloo.prefactor / (density * std::sqrt(g));
  std::printf(
      "Beverloo (3/2): k = %.2f d, C = %.3f (bulk %.4f kg/m^2), worst %.2f %%; "
      "exponent 1: worst %.2f %%; exponent 2: worst %.2f %%\n",
      beverloo.k, C, density, 100.0 * beverloo.worst, 100.0 * linear.worst,
      100.0 * fitPower(orifices, rates, 2.0).worst);
  // Every mean rate on the law to within the spread of three fills (about
  // 2 %) plus the law's own approximation at small openings, a few % at
  // D = 6 d in Mankoc et al.'s 2D data.
  EXPECT_LT(beverloo.worst, 0.05);
  // The flow grows faster than the opening: the grains leave faster
  // through a wider one (from an arch of height ~D/2), where a linear law
  // would have them leave at one speed. Over this range of D the exponent
  // 3/2 and k trade against each other (2 fits almost as well, with k < 0:
  // docs/scale.md, "The silo"), so only the linear law is excluded.
  EXPECT_LT(1.5 * beverloo.worst, linear.worst);
  // The empty annulus: grains of diameter d cannot use the last ~d/2 of the
  // opening on either side; k is of order one diameter, positive.
  EXPECT_GT(beverloo.k, 0.0);
  EXPECT_LT(beverloo.k, 3.0);
  // C is not a closed form: the free-fall arch (grains falling freely from
  // rest on an arch of radius D/2, at the bulk density) gives
  // B(1/2, 5/4) / 2 = 0.874, a heuristic, and C depends on the solver: the
  // default's velocity shock (SolverSettings::scaleVelocityShock) slows
  // this flow by about a fifth (C = 0.875; without it 1.117, Box2D 2.4.1
  // about 1.25: docs/scale.md, "The silo"). So C is only checked to be of
  // order one, which catches a wrong density, g or unit, not the solver's
  // bias.
  const double arch = 0.5 * std::tgamma(0.5) * std::tgamma(1.25) / std::tgamma(1.75);
  std::printf("free-fall arch: C = %.4f; measured / arch = %.4f\n", arch, C / arch);
  EXPECT_GT(C, 0.5);
  EXPECT_LT(C, 1.5);
}

// Dimensional analysis: with the geometry and the material fixed, the flow
// rate goes as sqrt(g) (the law's sqrt(g) is not fitted above). At g / 4
// the flow takes twice as long for the same mass, so the fill settles and
// is measured over doubled times; the step stays 1/60 s, so the run at g / 4
// is also the run at g with half the step.
TEST(ScaleSilo, FlowRateGoesAsTheRootOfGravity) {
  SiloDef quarter;
  quarter.gravity = 2.5;
  double density = 0.0;
  const double full = meanRates(SiloDef{}, {10.0}, 2, kSettleSteps, 1.0, 7.0, density)[0];
  const double slow = meanRates(quarter, {10.0}, 2, 2 * kSettleSteps, 2.0, 14.0, density)[0];
  std::printf("Q(g = 10) / Q(g = 2.5) = %.4f (sqrt(4) = 2)\n", full / slow);
  // The spread of two fills, about 3 % each way.
  EXPECT_NEAR(full / slow, 2.0, 2.0 * 0.05);
}

}  // namespace
}  // namespace particles::test
