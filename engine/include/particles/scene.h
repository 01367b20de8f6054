// A scene: plain data that every part of the project reads (engine, Box2D
// twin, viewer, comparison suite). The JSON form is documented in
// docs/scene-format.md and parsed by the scenefile library; the engine itself
// never touches JSON.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "particles/material.h"
#include "particles/mutation.h"
#include "particles/types.h"

namespace particles {

// Moment of inertia of a uniform disk about its centre, kg m^2.
inline double diskInertia(double mass, double radius) {
  return 0.5 * mass * radius * radius;
}

struct BallDef {
  Vec2 position{0.0, 0.0};       // m
  Vec2 velocity{0.0, 0.0};       // m/s
  double angle = 0.0;            // rad, counter-clockwise
  double angularVelocity = 0.0;  // rad/s, counter-clockwise positive
  double radius = 0.5;           // m, > 0
  double mass = 1.0;             // kg, > 0
  // kg m^2, > 0. Unset means a uniform disk, m r^2 / 2.
  std::optional<double> inertia;
  // Per-ball overrides of the scene's contact material; mixed pairwise with
  // mixRestitution / mixFriction.
  std::optional<double> restitution;
  std::optional<double> friction;

  double resolvedInertia() const { return inertia ? *inertia : diskInertia(mass, radius); }
};

// A static line segment from a to b. Walls never move; in the contact
// formulas they are a body with zero inverse mass and inertia.
struct WallDef {
  Vec2 a{0.0, 0.0};  // m
  Vec2 b{1.0, 0.0};  // m
  std::optional<double> restitution;
  std::optional<double> friction;
  // Two-sided (false): a touching ball is pushed out on the side its centre
  // is on. One-sided (true): balls belong on the left of a -> b (the side a
  // box's walls face) and a touching ball whose centre has crossed to the
  // right is pushed back to the left, not on through. A pile pressing a ball
  // against a box wall can move its centre past the wall's line within one
  // step; a two-sided wall then lets it out (docs/scale.md, "Walls with a
  // side").
  bool oneSided = false;
};

// Four one-sided walls enclosing the axis-aligned box [lo, hi], facing in,
// in the order bottom, right, top, left (counter-clockwise).
std::vector<WallDef> boxWalls(const Vec2& lo, const Vec2& hi);

enum class ForceType {
  // The handout's mouse drag: F = stiffness * (target - centre), applied at
  // the ball's centre, so it exerts no torque.
  Pull,
  // A constant force at the centre plus a constant torque.
  Constant,
};

struct ForceDef {
  ForceType type = ForceType::Pull;
  int ball = 0;            // index into SceneDef::balls
  Vec2 target{0.0, 0.0};   // m, Pull only
  double stiffness = 0.0;  // N/m, Pull only
  Vec2 force{0.0, 0.0};    // N, Constant only
  double torque = 0.0;     // N m, Constant only (counter-clockwise positive)
  double start = 0.0;      // s, active while start <= t < end
  double end = std::numeric_limits<double>::infinity();  // s

  bool activeAt(double t) const { return t >= start && t < end; }
};

// Hz: the stiffest contact spring of the large-scene path's soft step for a
// step of dt seconds in `substeps` substeps, a quarter of the substep rate
// (SolverSettings::scaleContactHertz). The engine clamps to it, and scene
// files refuse more.
inline double softContactHertzMost(double dt, int substeps) {
  return 0.25 / (dt / substeps);
}

// How the engine integrates and resolves contacts. Defaults suit most scenes.
struct SolverSettings {
  // Upper bound on velocity passes over the contacts in one step; passes stop
  // earlier as soon as no contact is approaching. Hitting the bound is counted
  // in StepStats::passLimitHits.
  int contactPasses = 64;
  // Upper bound on position-projection passes that remove overlap after the
  // position update.
  int correctionPasses = 8;
  // Ball count from which the uniform grid replaces brute-force pair finding.
  // Measured with bench/broad_phase_bench (docs/performance.md). 0 = always grid.
  int gridThreshold = 48;
  // Continuous collision against walls (docs/stress.md, "The fix"): a ball
  // not touching a wall at the start of a step, whose straight path this step
  // would reach it, gets the wall contact this step, and its position moves
  // with the old velocity up to the time of impact and with the new one
  // after. Off by default: it changes results (every wall bounce then happens
  // at its time of impact instead of up to a step late), so the golden state
  // hashes and the comparison with Box2D keep the discrete step. Scene files
  // set it as solver.swept_walls. Ball-ball contacts: sweptBalls. The
  // large-scene path (scaleThreshold) does not sweep at all: its contact
  // margin is its guard against tunnelling (docs/scale.md).
  bool sweptWalls = false;
  // Continuous collision between balls (docs/stress.md, "The fix"), the same
  // idea: a pair apart at the start of a step whose straight relative motion
  // this step (velocities after the forces) brings it into contact, and which
  // is approaching, gets the ball-ball contact this step (the same impulse,
  // normal from centre to centre at the time of impact); each ball moves with
  // its old velocity up to its earliest time of impact (over walls and
  // balls) and with the new one after. Swept contacts are solved in order of
  // their time, after the touching ones, so a fast ball meets the first ball
  // in its path first. A ball set moving by a swept hit is not swept again
  // within the same step. Off by default for the same reason as sweptWalls;
  // scene files set it as solver.swept_balls. Pair finding: every pair below
  // gridThreshold, the grid on swept bounds above; when off the step does no
  // swept work at all. Measured (docs/stress.md): two balls closing at 5
  // radii per step tunnel without it and are stable with it; the 200-ball
  // piles of `particles stress` end with 0.09 / 0.03 J of kinetic energy
  // instead of 3.0 / 4.4 J. Cost in a dilute gas (bench skip study): about
  // 1.7-2x per step at 16-32 balls (brute force), +25-30 % at 64 and
  // +30-85 % at 256 (grid); with it off the step is unchanged.
  bool sweptBalls = false;
  // Worker threads of the step (>= 1; docs/scale.md). The result is
  // bit-identical for every count: threads only share work whose order does
  // not matter. Scene files cannot set it.
  int threads = 1;
  // Ball count from which the large-scene path replaces the three contact
  // stages (docs/scale.md): contacts found once per step with a margin,
  // accumulated impulses warm-started across steps, a fixed number of
  // Gauss-Seidel iterations in vertical strips shared by `threads`. Below it
  // (every example scene, every isolated impact) the step is exactly the one
  // of docs/physics.md. Measured on the pile (docs/scale.md).
  int scaleThreshold = 1000;
  // The same threshold for scenes with gravity (balls). Under gravity balls
  // come to rest on each other, and the small-scene step cannot hold a resting
  // pile still: its passes start from zero impulse every step, so a pile of
  // 50 or 200 balls jitters forever (docs/stress.md, "Resting contact"). The
  // large-scene path's warm-started impulses bring the same piles to rest.
  // Without gravity the small-scene step stays up to scaleThreshold: it
  // conserves an elastic gas's energy exactly, the large path does not.
  int scaleThresholdUnderGravity = 32;
  // Ball count from which the large-scene path shares its step among
  // `threads` (balls). Below it the step is too short for the threads'
  // barriers to pay: measured on the pile (docs/scale.md), 2 threads took
  // 2.9x as long as 1 at 1,000 balls. The result does not depend on it.
  int scaleParallelFrom = 5000;
  // Velocity iterations per step of the large-scene path (count).
  int scaleVelocityIterations = 8;
  // The large-scene path's soft step (docs/scale.md, "The soft step"):
  // substeps per step (count; 0 = the rigid step, the default). With k > 0
  // each step keeps its rows and, k times, adds 1/k of the forces, applies
  // the accumulated impulses again, solves every row once against a damped
  // spring on its overlap (scaleContactHertz, scaleContactDampingRatio; a
  // gap still open may close within the substep), moves the balls, and
  // solves every row once more without the spring; then the bounce of each
  // row that pushed. No over-relaxation, support sweep, settle iteration or
  // overlap removal: the impulses carry a pile's weight, so friction has its
  // true bound and momentum changes only by the forces and the walls.
  // Measured on the 100,000 pile over 3,600 steps (two threads, springs at
  // a quarter of the substep rate): with 16 substeps at rest from step 1,883, with
  // 2.08 % / 0.21 % largest / mean overlap; with 8, from step 3,474, with
  // 7.71 % / 0.80 %; the rigid step keeps 49 kJ at step 3,600 (5.73 % /
  // 0.15 %) and Box2D 2.4.1 637 kJ. At 10,000, 16 substeps: at rest from
  // step 431 (rigid: 557), 0.61 % / 0.07 %. The price is speed: 16
  // substeps ran at 0.45 / 0.88 M disk-steps/s at 10,000 and 0.30 / 0.66 M
  // at 100,000 on one / two threads, a quarter to a fifth of the rigid step. Not exact for an
  // isolated impact (the spring is soft), but momentum, the Coulomb bound and the bounce (-e times
  // the approach the bodies brought) hold. Scene files: solver.soft_substeps and the
  // soft_contact_* keys (docs/scene-format.md).
  int scaleSubsteps = 0;
  // Hz: the stiffness of the soft step's ball-ball contact spring, as the
  // frequency of a ball pair's oscillation on it; walls get twice this. At
  // most a quarter of the substep rate; 0 = that most (120 Hz with 8
  // substeps of a 1/60 s step). Softer springs let a pile sink deeper into
  // itself: in a first, one-thread program of the same step the 100,000
  // pile with 8 substeps had 26.7 % largest overlap at 60 Hz against 7.5 %
  // at 120 Hz (docs/scale.md, "The soft step").
  double scaleContactHertz = 0.0;
  // Dimensionless: the soft step's contact damping (1 = critical).
  double scaleContactDampingRatio = 10.0;
  // m/s: the fastest the soft step's spring pushes overlapping balls apart.
  double scaleContactPushSpeed = 3.0;
  // Over-relaxation of the large-scene path's normal impulses
  // (dimensionless, 1 <= w < 2; docs/scale.md, "Over-relaxation"): every
  // velocity iteration but the last changes a row's accumulated normal
  // impulse by w times the Gauss-Seidel change (successive over-relaxation,
  // still clamped at >= 0). The last iteration is plain (w = 1) and takes
  // the normal impulse before the friction, so an isolated contact still
  // ends with its exact impulses. A deep pile carries its weight to the
  // floor in far fewer iterations. Measured over 8 seeds of the 10,000 pile
  // at step 600 (with 2 overlap-removal passes): the mean largest overlap
  // 2.23 -> 0.44 % of the radius (worst 3.19 -> 1.01 %), kinetic energy
  // 82 -> 23 J; polydisperse 3.33 -> 0.22 %, 19 -> 1.6 J. 1 turns it off.
  // A stack solved with 4 iterations or fewer can keep bouncing with w >=
  // 1.7 (the few plain updates do not undo the overshoot), so it applies
  // only from scaleOverRelaxationFrom iterations on.
  double scaleOverRelaxation = 1.8;
  // The fewest velocity iterations (count) with which the large-scene path
  // over-relaxes (scaleOverRelaxation); with fewer every iteration is plain
  // Gauss-Seidel. With w = 1.8 and few iterations the overshoot of the
  // over-relaxed updates, kept by the warm start from step to step, erupts
  // a deep pile (docs/scale.md, "Few iterations and over-relaxation"): the
  // 100,000 pile with 4 iterations at step ~750 (51 % overlap, balls at
  // 67 m/s, then the row budget's StepError), with 2 by step 300, the
  // 10,000 pile with 2 by step 900; with w = 1 the same piles stay whole
  // (softer: 9-14 % overlap). With 6 iterations the 100,000 pile held
  // for 1,800 steps. 1 over-relaxes at any count.
  int scaleOverRelaxationFrom = 6;
  // Upper bound on overlap-removal passes of the large-scene path (count);
  // passes stop as soon as one moves nothing. 2, not 4, since the
  // over-relaxed iterations leave little overlap: at w = 1.8, 4 passes gave
  // the 10,000 pile 0.39 % (worst 0.97 %) against 0.44 % (1.01 %) for 2,
  // and each pass costs about 5 % of a step (docs/scale.md).
  int scalePositionPasses = 2;
  // Shock propagation in the large-scene path's velocities: after the
  // iterations, one sweep in cell order in which a ball pair stacked along
  // gravity (|n . g/|g|| >= 0.2) that still approaches stops approaching by
  // a change of the upper ball's velocity alone, as if the lower ball were
  // immovable, without leaving it rising more than |g| dt faster than the
  // lower ball (docs/scale.md, "Shock propagation in velocities" and
  // "Walls with a side"). 8
  // iterations do not carry the weight of a deep pile; this sweep carries
  // the floor's support up in one. Measured over 8 seeds at step 600: the
  // 10,000 pile's largest overlap 6.7 -> 3.0 % (worst 7.9 -> 4.1 %) and its
  // kinetic energy 1,864 -> 84 J; the 1,000 pile at rest in 6 of 6 runs
  // instead of 0. It does not conserve momentum (the lower ball takes no
  // reaction) and does nothing without gravity.
  bool scaleVelocityShock = true;
  // The settle iteration of the large-scene path: once a pile has settled
  // (after the last step the mean squared speed of its balls was below
  // (|g| dt)^2, what gravity adds in one step), one more plain Gauss-Seidel
  // iteration runs after the support sweep (docs/scale.md, "The settle
  // iteration"). The sweep changes velocities without impulses and without
  // friction: in a settled pile it touches about 93 % of the rows, and the
  // slips it leaves let the pile creep and give way again and again (the
  // 10,000 pile's top sank 0.9 m between steps 300 and 1,800 and it was at
  // rest in 5 % of steps 600-2,400). The iteration restores friction and
  // impulses after it: over 12 seeds of the 5,000 pile, steps 600-1,800 at
  // rest 69 % -> 97 %, 9 -> 12 piles at rest at step 1,800, 8 (instead of
  // 2) at rest for good by step 662; the 10,000 pile at rest in 64 % of
  // steps 600-2,400, against 10 % for a 9th iteration before the sweep
  // (4 seeds). Off while a pile still lands (it slows the sweep's carrying
  // of a deep pile's weight: the 100,000 pile's largest overlap at step 600
  // rose to 6.4-8.0 % on two of three seeds), and without gravity (no
  // sweep). Costs one iteration a settled step.
  bool scaleSettleIteration = true;
  // How far the large-scene path's pair search reaches for a ball that
  // moves fast against its neighbourhood (grid cells, 0 = not at all;
  // docs/scale.md, "Rows for fast pairs"). The search finds pairs within
  // 0.2 of the largest radius of touching; a ball closing on another faster
  // than that margin a step got no row and landed inside it (57 % of the
  // radius at the end of the 100,000 pile, 105 % in the million). A ball whose
  // velocity differs from some velocity in the cells around it (up to this
  // many cells away) by more than the margin a step also gets speculative
  // rows with every ball its relative motion can reach within the step, up
  // to this many cells away: 2 cells of 1.1 m catch approaches up to about
  // 70 m/s at 60 steps a second. At most the strips' width (7 columns).
  int scaleFastPairCells = 2;
  // Height of the bands of the large-scene path's Gauss-Seidel order (grid
  // rows of about 1.1 largest diameters; 0 = whole strips; docs/scale.md,
  // "Bands"). Every stage that goes over the rows takes them band by band
  // from the bottom, and within a band the even strips, then the odd ones.
  // With whole strips (each strip from the bottom to the top, all even strips
  // before the odd ones) a chain of balls that crosses a strip border was
  // carried up by one crossing per half sweep: the largest overlaps of the
  // 100,000 pile lay on the borders (8.37 % of the radius at step 600, 4.53 %
  // with bands of 2, kinetic energy 13.9 kJ -> 6.4 kJ). Threads wait for
  // each other only where their strips meet. The result does not depend on
  // the thread count.
  int scaleBandRows = 2;
  // Ball count from which the large-scene path takes its rows band by band
  // (balls; below it, whole strips). Bands pay where strips are tall: at
  // 10,000 balls they gave nothing (0.26 % -> 0.34 % largest overlap) and
  // cost about 10 % of the speed; at 100,000 they halved the largest overlap
  // at a cost within the host's noise (docs/scale.md, "Bands").
  int scaleBandsFrom = 50000;
  // Whether the large-scene path's velocity passes (warm start, iterations,
  // restitution, support sweep, settle iteration) run as a wavefront over
  // the bands: pass p on band j right after pass p - 1 on band j + lag,
  // instead of each pass over every band before the next. Rows of bands
  // further apart than the lag share no ball, so every ball sees its rows in
  // the same order and the result is the same to the bit; the bands a
  // wavefront works on stay in cache (docs/scale.md, "Passes as a
  // wavefront"). The soft step (scaleSubsteps) runs each substep's passes,
  // over rows and over balls, as a wavefront of its own ("The soft step's
  // wavefront"). Off only to test that claim and to time the wavefront
  // (bench --scale --no-wavefront).
  bool scaleWavefront = true;
  // Whether the large-scene path's rigid step resolves, after its velocity
  // passes, each group of balls that met one another within the step, with
  // two impulses or more on one ball, as a sequence of pairwise impacts (the
  // handout's impulse, resolveImpact) in the order of their times of impact,
  // instead of keeping the passes' simultaneous solution: an elastic gas then
  // keeps its energy to rounding, which it otherwise loses in exactly those
  // steps, at first order in dt (docs/scale.md, "Impacts in sequence").
  // Under gravity or scene forces a group with a touching contact, which may
  // carry a load, is left to the passes. Off by default: it changes a pile's
  // bits wherever balls meet in mid-air, and on the 10,000 pile it was mixed
  // for rest. The soft step (scaleSubsteps) ignores it.
  bool scaleSequentialImpacts = false;
  // Shock propagation in the large-scene path's overlap removal
  // (dimensionless, 0..1; docs/scale.md, "Shock propagation"). Under gravity
  // the part of a pair's move along gravity is shared with the lower ball's
  // weight scaled by 1 - k |n . g/|g||, the part across gravity by inverse
  // mass: at k = 1 a ball resting on another pushes only itself up, as the
  // floor pushes only the ball on it, so one pass in bottom-up order clears a
  // vertical stack; at k = 0 both share by inverse mass (the small-scene
  // projection). Measured on the 10,000-ball pile at step 600 (8 seeds):
  // k = 0.7 cuts the largest overlap from 6.7 % (worst 7.9 %) to 3.2 %
  // (worst 4.2 %) of the radius, and the shallow stress piles still come to
  // rest. Off by default: the lifted balls fall back, so the 1,000-ball pile
  // keeps more energy at step 600 (20 J against 2.5 J), and the 100,000-ball
  // pile lands with deeper overlaps and 9x the kinetic energy at step 1,500.
  // Without gravity it does nothing.
  double scaleShockPropagation = 0.0;
  // A deliberately wrong solver, for the comparison suite's mutation check
  // only. Scene files cannot set it.
  Mutation mutation = Mutation::None;
};

struct SceneDef {
  std::string name;
  Vec2 gravity{0.0, 0.0};   // m/s^2
  ContactMaterial contact;  // scene default material
  std::vector<WallDef> walls;
  std::vector<BallDef> balls;
  std::vector<ForceDef> forces;
  double dt = 1e-3;       // s, > 0
  double duration = 1.0;  // s, >= 0
  SolverSettings solver;

  // Number of steps that `duration` asks for: round(duration / dt).
  long long stepCount() const;
};

}  // namespace particles
