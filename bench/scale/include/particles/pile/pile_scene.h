// The benchmark scene "pile" (issue 5, docs/scale.md): N disks dropped from a
// loose jittered grid into a four-walled box, to settle into a granular pile.
#pragma once

#include <cstdint>

#include "particles/scene.h"

namespace particles::pile {

struct PileParams {
  int count = 1000;               // number of disks, >= 1
  bool polydisperse = false;      // radius uniform in [0.4, 0.6] m instead of 0.5 m
  std::uint64_t seed = 20261201;  // jitter and radii; the same seed gives the same scene
  int threads = 1;                // SolverSettings::threads of the scene
};

// Fixed values of the scene (SI units).
inline constexpr double kRadius = 0.5;            // m, monodisperse radius
inline constexpr double kMinRadius = 0.4;         // m, polydisperse lower bound
inline constexpr double kMaxRadius = 0.6;         // m, polydisperse upper bound
inline constexpr double kDensity = 1.0;           // kg/m^2 (areal: 2D disks)
inline constexpr double kSpacing = 1.2;           // m, grid cell width (1.2 diameters)
inline constexpr double kWidthPerRootN = 1.25;    // box width = 1.25 sqrt(N) m
inline constexpr double kPackingFraction = 0.82;  // assumed area fraction of the settled pile
inline constexpr double kFillFraction = 0.6;      // settled pile height / box height
inline constexpr double kTimeStep = 1.0 / 60.0;   // s
inline constexpr double kGravity = -10.0;         // m/s^2, along y

// Box and grid of a pile of `count` disks. The box is [0, width] x [0, height].
struct PileGeometry {
  double width = 0.0;       // m, 1.25 sqrt(N)
  double height = 0.0;      // m, max(settled height / 0.6, grid top + one spacing)
  int columns = 0;          // grid cells per row, floor(width / spacing)
  int rows = 0;             // rows of the grid, ceil(N / columns)
  double gridLeft = 0.0;    // m, x of the grid's left edge (the grid is centred)
  double gridBottom = 0.0;  // m, y of the grid's bottom edge (half a spacing of air)
};

PileGeometry pileGeometry(int count);

// The scene: disks in row-major order from the bottom-left cell, each at its
// cell's centre plus a jitter of up to (spacing / 2 - r) per axis, so that
// every disk lies inside its own cell (no initial overlaps, none with a wall).
// Density 1, e = 0.5, mu = 0.5 (scene default, balls and walls), gravity -10,
// dt = 1/60 s, duration 10 s (600 steps), at rest.
SceneDef makePile(const PileParams& params);

}  // namespace particles::pile
