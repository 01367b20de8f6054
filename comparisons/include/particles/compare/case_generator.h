// Draws comparison cases from parameters with a seed, and holds the fixed
// catalogue of named cases (the handout's thought experiments among them).
#pragma once

#include <cstdint>
#include <vector>

#include "particles/compare/impact_case.h"

namespace particles::compare {

struct GeneratorSettings {
  double minMassRatio = 1e-3, maxMassRatio = 1e3;    // m_b / m_a, log-uniform
  double minRadiusRatio = 0.1, maxRadiusRatio = 10;  // r_b / r_a, log-uniform
  double minSpeed = 0.1, maxSpeed = 10.0;            // m/s, relative speed at contact
  double maxImpactAngle = 1.4;                       // rad, 0 = head-on (80 deg)
  double dt = 1.0 / 60.0;                            // s, the one step a case runs
};

// The case with this index in a family's random sequence. Each case has its
// own generator state derived from (seed, family, index), so case k is the
// same whatever the number of cases, threads or shards.
ImpactCase randomCase(Family family, std::uint64_t seed, int index,
                      const GeneratorSettings& settings = {});

// The named cases, in a fixed order.
std::vector<ImpactCase> catalogue();

}  // namespace particles::compare
