#include "particles/world.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "contact_impulse_impl.h"
#include "particles/swept_wall.h"

namespace particles {
namespace {

// A contact counts as approaching when its normal relative velocity is below
// -kApproachTolerance times the speeds involved: after an e = 0 impulse the
// residual is rounding noise (~1e-16 of the speeds), and chasing it would
// only burn passes.
constexpr double kApproachTolerance = 1e-12;

// Overlap the position pass leaves alone, relative to the radii involved:
// rounding after a projection, not penetration.
constexpr double kOverlapTolerance = 1e-9;

bool approaching(const ContactBody& a, const ContactBody& b, double gn) {
  const double scale = a.velocity.norm() + b.velocity.norm() +
                       std::abs(a.angularVelocity) * a.leverArm +
                       std::abs(b.angularVelocity) * b.leverArm;
  return gn < -kApproachTolerance * scale;
}

}  // namespace

World::World(const SceneDef& scene) {
  reset(scene);
}

// Building reuses the vectors' storage, so a World reset for case after case
// (the comparison suite) allocates nothing once warm.
void World::reset(const SceneDef& scene) {
  if (!(scene.dt > 0.0)) throw std::invalid_argument("World: dt must be > 0");
  scene_ = scene;
  dt_ = scene.dt;
  stepIndex_ = 0;
  stats_ = {};
  impacts_.clear();
  position_.clear();
  velocity_.clear();
  angle_.clear();
  angularVelocity_.clear();
  radius_.clear();
  invMass_.clear();
  invInertia_.clear();
  material_.clear();
  wallMaterial_.clear();
  bool spinning = false;
  for (const BallDef& b : scene.balls) {
    position_.push_back(b.position);
    velocity_.push_back(b.velocity);
    angle_.push_back(b.angle);
    angularVelocity_.push_back(b.angularVelocity);
    radius_.push_back(b.radius);
    invMass_.push_back(1.0 / b.mass);
    invInertia_.push_back(1.0 / b.resolvedInertia());
    material_.push_back(resolveMaterial(scene.contact, b.restitution, b.friction));
    spinning = spinning || b.angularVelocity != 0.0;
  }
  for (const WallDef& w : scene.walls)
    wallMaterial_.push_back(resolveMaterial(scene.contact, w.restitution, w.friction));

  plan_ = {};
  plan_.walls = !scene.walls.empty();
  plan_.gravity = scene.gravity != Vec2::Zero();
  plan_.forces = !scene.forces.empty();
  for (const ForceDef& f : scene.forces)
    plan_.torques = plan_.torques || (f.type == ForceType::Constant && f.torque != 0.0);
  // Tangential work is needed if any pair of bodies that could meet mixes to
  // mu > 0. mixFriction is 0 as soon as one side is 0, so it is enough to find
  // one ball with mu > 0 and another body (ball or wall) with mu > 0.
  int gripBalls = 0;
  for (const ContactMaterial& m : material_) gripBalls += m.friction > 0.0;
  bool gripWalls = false;
  for (const ContactMaterial& m : wallMaterial_) gripWalls = gripWalls || m.friction > 0.0;
  plan_.tangential = gripBalls >= 2 || (gripBalls >= 1 && gripWalls);
  plan_.spin = spinning || plan_.tangential || plan_.torques;
  plan_.grid = static_cast<int>(scene.balls.size()) >= scene.solver.gridThreshold;
  // The mutants are the small-scene solver with one sign changed; they never
  // take the large-scene path.
  const int scaleFrom =
      plan_.gravity ? std::min(scene.solver.scaleThreshold, scene.solver.scaleThresholdUnderGravity)
                    : scene.solver.scaleThreshold;
  plan_.scale =
      static_cast<int>(scene.balls.size()) >= scaleFrom && scene.solver.mutation == Mutation::None;
  plan_.sweep = (plan_.walls && scene.solver.sweptWalls) || scene.solver.sweptBalls;
  scaleSolver_.reset();
}

BallState World::ball(std::size_t i) const {
  return {position_[i], velocity_[i], angle_[i], angularVelocity_[i]};
}

std::vector<BallState> World::balls() const {
  std::vector<BallState> all(ballCount());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = ball(i);
  return all;
}

namespace {
template <typename T>
std::size_t heapBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}
}  // namespace

std::size_t World::memoryBytes() const {
  return sizeof(World) + heapBytes(scene_.balls) + heapBytes(scene_.walls) +
         heapBytes(scene_.forces) + scene_.name.capacity() + heapBytes(position_) +
         heapBytes(velocity_) + heapBytes(angle_) + heapBytes(angularVelocity_) +
         heapBytes(radius_) + heapBytes(invMass_) + heapBytes(invInertia_) + heapBytes(material_) +
         heapBytes(wallMaterial_) + heapBytes(forcedVelocity_) + heapBytes(pairs_) +
         heapBytes(wallHits_) + broadPhase_.memoryBytes() + heapBytes(impacts_) +
         scaleSolver_.memoryBytes() + heapBytes(sweptTime_) + heapBytes(sweptVelocity_) +
         sweptPairFinder_.memoryBytes() + heapBytes(sweptPairs_);
}

void World::setPullTarget(std::size_t force, const Vec2& target) {
  scene_.forces.at(force).target = target;
}

void World::run(long long steps) {
  for (long long s = 0; s < steps; ++s) step();
}

// One step, semi-implicit Euler with impulses (docs/physics.md, "The step"):
// velocities first, then contacts on the new velocities, then positions with
// the post-impact velocities, then overlap removal.
void World::step() {
  applyForces();
  if (plan_.scale) {
    scaleStep();  // the next three stages for a large scene (docs/scale.md)
  } else {
    resolveContacts();
    integratePositions();
    correctOverlaps();
  }
  ++stepIndex_;
  ++stats_.steps;
}

// Also records what the forces added to each velocity (forcedVelocity_), so
// that contacts can tell a bounce from a push (docs/physics.md).
void World::applyForces() {
  if (!plan_.gravity && !plan_.forces) return;
  const double t = time();
  forcedVelocity_.assign(position_.size(), dt_ * scene_.gravity);
  for (const ForceDef& f : scene_.forces) {
    if (!f.activeAt(t)) continue;
    const std::size_t i = static_cast<std::size_t>(f.ball);
    if (f.type == ForceType::Pull) {
      // The handout's drag: from the centre O toward the target M, |F| ~ |OM|.
      forcedVelocity_[i] += dt_ * invMass_[i] * f.stiffness * (f.target - position_[i]);
    } else {
      forcedVelocity_[i] += dt_ * invMass_[i] * f.force;
      angularVelocity_[i] += dt_ * invInertia_[i] * f.torque;
    }
  }
  for (std::size_t i = 0; i < velocity_.size(); ++i) velocity_[i] += forcedVelocity_[i];
}

void World::scaleStep() {
  ScaleBodies b;
  b.position = position_;
  b.velocity = velocity_;
  b.angle = angle_;
  b.angularVelocity = angularVelocity_;
  b.radius = radius_;
  b.invMass = invMass_;
  b.invInertia = invInertia_;
  b.material = material_;
  if (plan_.gravity || plan_.forces) b.forcedVelocity = forcedVelocity_;
  b.walls = scene_.walls;
  b.wallMaterial = wallMaterial_;
  b.dt = dt_;
  if (plan_.gravity && scene_.gravity.squaredNorm() > 0.0) {
    b.down = scene_.gravity.normalized();
    b.gravityStep = scene_.gravity.norm() * dt_;
  }
  b.spin = plan_.spin;
  scaleSolver_.step(b, scene_.solver, stats_, recordImpacts_ ? &impacts_ : nullptr);
}

void World::findBallContacts(std::vector<BallPair>& out) {
  if (plan_.grid)
    broadPhase_.findPairs(position_, radius_, out);
  else
    findPairsBruteForce(position_, radius_, out);
}

void World::resolveContacts() {
  findBallContacts(pairs_);
  wallHits_.clear();
  if (plan_.walls) findWallHits(position_, radius_, scene_.walls, wallHits_);
  if (plan_.sweep) {
    beginSweep();
    if (plan_.walls && scene_.solver.sweptWalls) addSweptWallHits();
    if (scene_.solver.sweptBalls) addSweptBallPairs();
  }
  stats_.contacts = static_cast<int>(pairs_.size() + wallHits_.size());
  stats_.passes = 0;
  impacts_.clear();
  if (stats_.contacts == 0) return;
  detail::withMutation(scene_.solver.mutation, [&]<Mutation M>() {
    if (plan_.tangential)
      resolveContactsAs<M, true>();
    else
      resolveContactsAs<M, false>();
  });
}

// One pass visits every contact in a fixed order (ball pairs sorted by index,
// then ball-wall contacts by ball and wall) and applies the impulse to each
// one still approaching, with the velocities left by the contacts before it
// (Gauss-Seidel). Passes repeat until none approaches. Without tangential
// work (every mu = 0) spins are neither read nor written.
template <Mutation M, bool Tangential>
void World::resolveContactsAs() {
  const bool forced = plan_.gravity || plan_.forces;
  auto body = [&](int i) {
    ContactBody c;
    c.velocity = velocity_[i];
    c.invMass = invMass_[i];
    if (forced) c.forcedVelocity = forcedVelocity_[i];
    if constexpr (Tangential) {
      c.angularVelocity = angularVelocity_[i];
      c.invInertia = invInertia_[i];
      c.leverArm = radius_[i];
    }
    return c;
  };
  auto store = [&](int i, const ContactBody& c) {
    velocity_[i] = c.velocity;
    if constexpr (Tangential) angularVelocity_[i] = c.angularVelocity;
  };
  const std::size_t count = pairs_.size() + wallHits_.size();
  if (recordImpacts_) {
    impacts_.assign(count, ImpactEvent{});
    for (std::size_t k = 0; k < pairs_.size(); ++k)
      impacts_[k] = {pairs_[k].a, pairs_[k].b, false, pairs_[k].normal, 0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < wallHits_.size(); ++k) {
      const WallHit& h = wallHits_[k];
      impacts_[pairs_.size() + k] = {h.ball, h.wall, true, h.normal, 0.0, 0.0, 0.0};
    }
  }
  auto record = [&](std::size_t k, const ContactImpulse& j, const ContactMaterial& m) {
    if (!recordImpacts_) return;
    impacts_[k].normalImpulse += j.normal;
    impacts_[k].tangentImpulse += j.tangent;
    impacts_[k].frictionBound += m.friction == 0.0 ? 0.0 : m.friction * j.normal;
  };

  const ContactBody wall;  // zero velocity, zero inverse mass and inertia
  auto pass = [&](bool apply) {
    bool any = false;
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      const BallPair& p = pairs_[k];
      ContactBody a = body(p.a), b = body(p.b);
      if (!approaching(a, b, detail::contactVelocityAs<M>(a, b, p.normal).normal)) continue;
      any = true;
      if (!apply) return true;
      const ContactMaterial m = mixMaterials(material_[p.a], material_[p.b]);
      record(k, detail::resolveImpactAs<M>(a, b, p.normal, m), m);
      store(p.a, a);
      store(p.b, b);
    }
    for (std::size_t k = 0; k < wallHits_.size(); ++k) {
      const WallHit& h = wallHits_[k];
      ContactBody a = body(h.ball), w = wall;
      if (!approaching(a, w, detail::contactVelocityAs<M>(a, w, h.normal).normal)) continue;
      any = true;
      if (!apply) return true;
      const ContactMaterial m = mixMaterials(material_[h.ball], wallMaterial_[h.wall]);
      record(pairs_.size() + k, detail::resolveImpactAs<M>(a, w, h.normal, m), m);
      store(h.ball, a);
    }
    return any;
  };

  const int maxPasses = std::max(1, scene_.solver.contactPasses);
  while (stats_.passes < maxPasses && pass(true)) ++stats_.passes;
  if (stats_.passes == maxPasses && pass(false)) ++stats_.passLimitHits;
  if (recordImpacts_)
    std::erase_if(impacts_, [](const ImpactEvent& e) { return e.normalImpulse == 0.0; });
}

// No ball has a time of impact yet this step (sweptWalls, sweptBalls).
void World::beginSweep() {
  sweptTime_.assign(position_.size(), -1.0);
  sweptVelocity_.resize(position_.size());
}

// SolverSettings::sweptWalls: each ball apart from a wall whose path this
// step reaches it gets that wall as a contact now (the earliest such wall
// only), so the impulse acts this step; integratePositions() then moves it
// with its incoming velocity up to the time of impact. Hits stay sorted by
// ball, then wall, as the contact order requires.
void World::addSweptWallHits() {
  const std::size_t n = position_.size();
  std::vector<WallHit> merged;
  std::size_t next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bool touching = false;
    for (; next < wallHits_.size() && wallHits_[next].ball == static_cast<int>(i); ++next) {
      merged.push_back(wallHits_[next]);
      touching = true;
    }
    if (touching) continue;
    std::optional<SweptHit> first;
    int wall = 0;
    for (std::size_t k = 0; k < scene_.walls.size(); ++k) {
      const auto h = sweepAgainstWall(position_[i], velocity_[i], radius_[i], scene_.walls[k], dt_);
      if (h && (!first || h->time < first->time)) {
        first = h;
        wall = static_cast<int>(k);
      }
    }
    if (!first) continue;
    merged.push_back({static_cast<int>(i), wall, first->normal, 0.0});
    sweptTime_[i] = first->time;
    sweptVelocity_[i] = velocity_[i];
  }
  wallHits_.swap(merged);
}

// SolverSettings::sweptBalls: the swept pairs follow the touching ones in
// pairs_, in order of their time of impact, so each pass meets a fast
// ball's first impact before those behind it (which, once it has bounced,
// are no longer approaching). A ball's time of impact is its earliest, over
// walls and balls.
void World::addSweptBallPairs() {
  sweptPairFinder_.find(position_, velocity_, radius_, dt_, plan_.grid, sweptPairs_);
  for (const SweptPair& p : sweptPairs_) {
    pairs_.push_back({p.a, p.b, p.normal, 0.0});
    for (const int i : {p.a, p.b}) {
      double& t = sweptTime_[static_cast<std::size_t>(i)];
      if (t < 0.0 || p.time < t) t = p.time;
      sweptVelocity_[static_cast<std::size_t>(i)] = velocity_[static_cast<std::size_t>(i)];
    }
  }
}

void World::integratePositions() {
  const std::size_t n = position_.size();
  if (plan_.sweep) {
    for (std::size_t i = 0; i < n; ++i) {
      const double t = sweptTime_[i];
      position_[i] +=
          t < 0.0 ? dt_ * velocity_[i] : Vec2(t * sweptVelocity_[i] + (dt_ - t) * velocity_[i]);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) position_[i] += dt_ * velocity_[i];
  }
  if (plan_.spin)
    for (std::size_t i = 0; i < n; ++i) angle_[i] += dt_ * angularVelocity_[i];
}

// Removes what overlap the step left by moving positions only (a projection):
// velocities are untouched, so no kinetic energy is injected and separating
// bodies are not held together. Each pair is moved apart along its normal by
// its overlap, shared in proportion to inverse mass; a ball against a wall
// moves the whole way. The contact set is found once, then re-measured on
// each pass (Gauss-Seidel), since one push can deepen a neighbour's overlap.
void World::correctOverlaps() {
  stats_.correctionPasses = 0;
  stats_.maxOverlap = 0.0;
  findBallContacts(pairs_);
  wallHits_.clear();
  if (plan_.walls) findWallHits(position_, radius_, scene_.walls, wallHits_);
  if (pairs_.empty() && wallHits_.empty()) return;

  const int maxPasses = std::max(1, scene_.solver.correctionPasses);
  for (int pass = 0; pass < maxPasses; ++pass) {
    bool moved = false;
    for (BallPair& p : pairs_) {
      if (!touchBalls(position_[p.a], radius_[p.a], position_[p.b], radius_[p.b], p)) continue;
      if (pass == 0) stats_.maxOverlap = std::max(stats_.maxOverlap, p.overlap);
      if (p.overlap <= kOverlapTolerance * (radius_[p.a] + radius_[p.b])) continue;
      const double share = p.overlap / (invMass_[p.a] + invMass_[p.b]);
      position_[p.a] -= share * invMass_[p.a] * p.normal;
      position_[p.b] += share * invMass_[p.b] * p.normal;
      moved = true;
    }
    for (WallHit& h : wallHits_) {
      if (!touchWall(position_[h.ball], radius_[h.ball], scene_.walls[h.wall], h)) continue;
      if (pass == 0) stats_.maxOverlap = std::max(stats_.maxOverlap, h.overlap);
      if (h.overlap <= kOverlapTolerance * radius_[h.ball]) continue;
      position_[h.ball] -= h.overlap * h.normal;
      moved = true;
    }
    if (!moved) break;
    ++stats_.correctionPasses;
  }
}

}  // namespace particles
