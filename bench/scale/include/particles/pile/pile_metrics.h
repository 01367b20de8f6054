// What `particles bench --scale` measures on a pile, for either engine: the
// overlap between touching disks, the kinetic energy, and when the pile is at
// rest. Definitions in docs/scale.md, "Figures".
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "particles/scene.h"
#include "particles/world.h"

namespace particles::pile {

// Overlap of touching disk pairs, each as a fraction of the pair's smaller
// radius: (r_a + r_b - |x_b - x_a|) / min(r_a, r_b), 0 for pairs that touch
// without overlapping. "Touching" is the engine's contact test:
// |x_b - x_a| <= (r_a + r_b)(1 + 1e-9). Walls are not included.
struct OverlapFigures {
  long long touchingPairs = 0;  // pairs that touch
  double max = 0.0;             // largest fraction (dimensionless), 0 if none touch
  double mean = 0.0;            // mean fraction over touching pairs, 0 if none touch
};

OverlapFigures measureOverlap(std::span<const BallState> balls, std::span<const BallDef> defs);

// Balls whose centre lies outside the box [lo, hi] (m), borders included as
// inside: balls that left the pile's box. A ball in the box keeps its centre
// at least its radius from every wall, so any count above 0 is a defect (a
// one-sided wall puts a ball that crossed it back the next step; docs/scale.md,
// "Walls with a side").
long long countOutside(std::span<const BallState> balls, const Vec2& lo, const Vec2& hi);

// Total kinetic energy, J: sum of m |v|^2 / 2 + J w^2 / 2 with the masses and
// inertias of `defs` (same order as `balls`).
double kineticEnergy(std::span<const BallState> balls, std::span<const BallDef> defs);

// A pile is at rest when its kinetic energy is below that of all its mass
// moving at kRestSpeed: E <= M kRestSpeed^2 / 2 (M the total mass).
// 0.01 m/s is 6 % of what gravity adds in one step (g dt = 0.167 m/s).
inline constexpr double kRestSpeed = 0.01;  // m/s

double restEnergy(std::span<const BallDef> defs);  // J, M kRestSpeed^2 / 2

// The first step index s (energies[k] is the energy after step k + 1) from
// which every later energy is at most `threshold`: the pile came to rest
// after step s + 1 and stayed there until the end. nullopt if the last
// energy is above the threshold (not at rest at the end).
std::optional<long long> restStep(std::span<const double> energies, double threshold);

}  // namespace particles::pile
