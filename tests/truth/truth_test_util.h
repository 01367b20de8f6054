// Helpers shared by the tests of the closed-form truth (comparisons/truth/).
//
// Tolerance. Everything is computed in long double (x87 80-bit on x86-64: 64-bit mantissa,
// epsilon 1.08e-19). A 6x6 elimination with row equilibration loses at most a few hundred ulps
// for the mass and radius ratios used here (<= 100), so 1e-15 relative to the natural scale of
// each quantity leaves a margin of about four decades while still catching any formula error,
// which shows up at O(1). The worst residuals actually measured are printed at the end of a run.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "particles/truth/closed_form.h"

namespace truth_test {

using Real = long double;
inline constexpr Real kTol = 1e-15L;

/// Keeps the largest relative residual seen under `name` (printed when the program ends).
void record(const std::string& name, Real relResidual);

/// |actual - expected| <= kTol * scale, with the relative residual recorded under `bucket`.
inline ::testing::AssertionResult close(const char* bucket, Real actual, Real expected,
                                        Real scale) {
  const Real rel = std::fabs(actual - expected) / scale;
  record(bucket, rel);
  if (rel <= kTol) return ::testing::AssertionSuccess();
  char buf[256];
  std::snprintf(buf, sizeof buf, "actual %.21Lg expected %.21Lg: residual %.3Lg x scale %.3Lg",
                actual, expected, rel, scale);
  return ::testing::AssertionFailure() << buf;
}

// Kinematics written in the test's own words (positions, cross products), not the library's.
struct Vec {
  Real x, y;
};
inline Real dot(Vec u, Vec v) {
  return u.x * v.x + u.y * v.y;
}
inline Real cross(Vec u, Vec v) {
  return u.x * v.y - u.y * v.x;
}
inline Vec vel(const particles::truth::Body& b) {
  return b.wall ? Vec{0, 0} : Vec{b.vx, b.vy};
}

}  // namespace truth_test

#define EXPECT_CLOSE(bucket, actual, expected, scale) \
  EXPECT_TRUE(::truth_test::close(bucket, (actual), (expected), (scale))) << #actual
