// The simulation world: balls, walls and forces from a SceneDef, advanced by
// fixed steps. The step is readable top to bottom in World::step().
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "particles/broad_phase.h"
#include "particles/scale_solver.h"
#include "particles/scene.h"
#include "particles/step_error.h"
#include "particles/swept_ball.h"

namespace particles {

// What a caller may read of one ball.
struct BallState {
  Vec2 position;           // m
  Vec2 velocity;           // m/s
  double angle;            // rad
  double angularVelocity;  // rad/s
};

// One contact that exchanged an impulse during the last step, with the
// impulses summed over the step's passes (b receives +P, a receives -P).
struct ImpactEvent {
  int a = 0;  // ball index
  int b = 0;  // ball index, or wall index when `wall`
  bool wall = false;
  // unit, from a to b, at the start of the step (at the time of impact for a
  // swept contact: SolverSettings::sweptWalls, sweptBalls)
  Vec2 normal{1.0, 0.0};
  double normalImpulse = 0.0;   // N s, sum of lambdaN (>= 0)
  double tangentImpulse = 0.0;  // N s, sum of lambdaT
  double frictionBound = 0.0;   // N s, sum of mu lambdaN (inf for no-slip)
};

// Counters of the last step, and totals since the world was built.
struct StepStats {
  int contacts = 0;             // contacts found this step (ball-ball + ball-wall)
  int passes = 0;               // velocity passes used this step
  int correctionPasses = 0;     // position passes used this step
  double maxOverlap = 0.0;      // m, largest overlap seen by the position pass
  long long passLimitHits = 0;  // steps (in total) that ended at SolverSettings::contactPasses
  long long steps = 0;          // steps taken in total
  // The large-scene path with SolverSettings::scaleSequentialImpacts, this
  // step: the groups replayed in sequence (two impulses or more on one ball,
  // or a lone touching impact), and the groups left to the velocity passes
  // (under gravity or scene forces, with a touching contact among them).
  int sequentialGroups = 0;
  int sequentialGroupsLeft = 0;
};

// Which optional stages this scene needs; decided once when the world is
// built, so a scene pays only for what it uses.
struct StagePlan {
  bool walls = false;       // any wall: otherwise no wall pass at all
  bool tangential = false;  // any contact with mu > 0: otherwise no tangential/angular contact work
  bool torques = false;     // any force with a torque
  bool forces = false;      // any scene force
  bool gravity = false;     // non-zero gravity
  bool spin = false;        // anything can rotate: otherwise angles are not integrated
  bool grid = false;        // uniform grid instead of brute-force pairs
  bool scale = false;       // the large-scene path (SolverSettings::scaleThreshold)
  // continuous collision (sweptWalls with walls, or sweptBalls): per-ball
  // times of impact this step
  bool sweep = false;
};

class World {
 public:
  explicit World(const SceneDef& scene);
  // Rebuilds the world for another scene, as if newly constructed.
  void reset(const SceneDef& scene);

  // Advances the world by one step of SceneDef::dt.
  // Throws StepError when the state can no longer be stepped in bounded
  // memory (a blow-up; step_error.h).
  void step();
  // Advances by n steps.
  void run(long long steps);

  double time() const { return static_cast<double>(stepIndex_) * dt_; }
  long long stepIndex() const { return stepIndex_; }
  double dt() const { return dt_; }
  std::size_t ballCount() const { return position_.size(); }
  BallState ball(std::size_t i) const;
  // Every ball's state, in the scene's order.
  std::vector<BallState> balls() const;
  const StepStats& stats() const { return stats_; }
  const StagePlan& plan() const { return plan_; }
  const SceneDef& scene() const { return scene_; }
  // Bytes this world holds: the object itself and the capacity of every
  // container it owns (state, scene copy, scratch, grid). Measured from the
  // containers, not the process, so it is exact and repeatable.
  std::size_t memoryBytes() const;

  // Replaces the target of a pull force (the viewer's mouse drag).
  void setPullTarget(std::size_t force, const Vec2& target);

  // When on, each step records the contacts that exchanged an impulse
  // (impacts()); off by default, since it costs a little per contact.
  void recordImpacts(bool on) { recordImpacts_ = on; }
  const std::vector<ImpactEvent>& impacts() const { return impacts_; }

 private:
  void applyForces();
  void resolveContacts();
  template <Mutation M, bool Tangential>
  void resolveContactsAs();
  void integratePositions();
  void correctOverlaps();
  void scaleStep();

  void findBallContacts(std::vector<BallPair>& out);
  void beginSweep();
  void addSweptWallHits();
  void addSweptBallPairs();

  SceneDef scene_;
  StagePlan plan_;
  double dt_ = 0.0;
  long long stepIndex_ = 0;
  StepStats stats_;

  // Hot per-ball data, structure of arrays.
  std::vector<Vec2> position_, velocity_;
  std::vector<double> angle_, angularVelocity_;
  std::vector<double> radius_, invMass_, invInertia_;
  std::vector<ContactMaterial> material_;  // per ball, overrides applied
  std::vector<ContactMaterial> wallMaterial_;
  std::vector<Vec2> forcedVelocity_;  // what this step's forces added to each velocity
  // SolverSettings::sweptWalls and sweptBalls: per ball, its earliest time
  // of impact this step (s, < 0 for none) and the velocity it moved with
  // until then.
  std::vector<double> sweptTime_;
  std::vector<Vec2> sweptVelocity_;

  // Scratch reused across steps so a step allocates nothing once warm.
  std::vector<BallPair> pairs_;
  std::vector<WallHit> wallHits_;
  BroadPhase broadPhase_;
  SweptPairFinder sweptPairFinder_;  // SolverSettings::sweptBalls
  std::vector<SweptPair> sweptPairs_;
  ScaleSolver scaleSolver_;  // the large-scene path's contacts and warm-start impulses

  bool recordImpacts_ = false;
  std::vector<ImpactEvent> impacts_;
};

}  // namespace particles
