// Box2D 2.4.1's step, as far as it decides a case's velocities, replayed in
// double. Written from Box2D's sources (b2_broad_phase, b2_dynamic_tree,
// b2_contact_manager, b2_world, b2_island, b2_contact_solver,
// b2_collide_circle, b2_collide_edge, b2WorldManifold), not copied from
// them; docs/box2d-twin.md says what is replicated and why.
//
// Three stages, as in b2World::Step for a fresh world:
//  1. Which contacts exist and in which order (broad phase, contact manager,
//     island search), in box2d_contact_plan.cpp: discrete decisions, made in
//     Box2D's own float arithmetic.
//  2. The contact geometry (normal, point in the middle of the overlap, lever
//     arms), in double from the scene's double positions.
//  3. The velocity step (forces and gravity, restitution bias, sequential
//     impulses with friction before the normal row, the per-step motion
//     clamps), in double.
#include "particles/compare/box2d_model.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "box2d_contact_plan.h"
#include "particles/material.h"

namespace particles::compare {
namespace {

using detail::ContactPlan;
using detail::ContactRecord;
using detail::EdgeRegion;
using detail::Fixture;
using detail::planContacts;

// Box2D 2.4.1 constants (b2_common.h with b2_lengthUnitsPerMeter = 1).
constexpr double kMaxTranslation = 2.0;                            // b2_maxTranslation, m per step
constexpr double kMaxRotation = 0.5 * std::numbers::pi;            // b2_maxRotation, rad per step
constexpr double kCoincident = double(FLT_EPSILON) * FLT_EPSILON;  // b2_epsilon^2, m^2

// ---------------------------------------------------------------------------
// Stages 2 and 3: geometry and velocities, in double.

struct BodyState {
  Vec2 v{0.0, 0.0};
  double w = 0.0;
  double invMass = 0.0, invInertia = 0.0;  // 0 for the static body
};

// The scalar-vector cross product w x r.
Vec2 spinCross(double w, const Vec2& r) {
  return Vec2(-w * r.y(), w * r.x());
}

struct Constraint {
  int bodyA = 0, bodyB = 0;
  Vec2 normal{1.0, 0.0};  // from A to B
  Vec2 rA{0.0, 0.0}, rB{0.0, 0.0};
  double normalMass = 0.0, tangentMass = 0.0;
  double friction = 0.0, restitution = 0.0, threshold = 0.0;
  double velocityBias = 0.0;
  double normalImpulse = 0.0, tangentImpulse = 0.0;
};

// A body's own material as a Box2D fixture holds it: kNoSlip becomes the
// large finite stand-in, so that mixing is Box2D's sqrt(mu1 mu2).
ContactMaterial fixtureMaterial(const SceneDef& s, const Fixture& f,
                                const Box2DModelSettings& settings) {
  ContactMaterial m =
      f.wall ? resolveMaterial(s.contact, s.walls[f.index].restitution, s.walls[f.index].friction)
             : resolveMaterial(s.contact, s.balls[f.index].restitution, s.balls[f.index].friction);
  if (std::isinf(m.friction)) m.friction = settings.noSlipFriction;
  return m;
}

// b2WorldManifold::Initialize for the contact: the normal from A to B and the
// point half-way between the two surfaces; then the lever arms.
void setGeometry(const SceneDef& s, const ContactRecord& rec, const Box2DModelSettings& settings,
                 Constraint& k) {
  const BallDef& ballB = s.balls[rec.b.index];
  const Vec2 centreB = ballB.position;
  Vec2 centreA(0.0, 0.0), surfaceA;
  double radiusA = 0.0;
  if (rec.a.wall) {
    const WallDef& w = s.walls[rec.a.index];
    if (rec.region == EdgeRegion::Face) {
      const Vec2 e = w.b - w.a;
      k.normal = Vec2(e.y(), -e.x()).normalized();
      if (rec.flip) k.normal = -k.normal;
      // The foot of the centre on the edge's line (the edge has no skin).
      surfaceA = centreB - (centreB - w.a).dot(k.normal) * k.normal;
    } else {
      const Vec2 vertex = rec.region == EdgeRegion::VertexA ? w.a : w.b;
      const Vec2 d = centreB - vertex;
      k.normal = d.squaredNorm() > kCoincident ? d.normalized() : Vec2(1.0, 0.0);
      surfaceA = vertex;
    }
  } else {
    const BallDef& ballA = s.balls[rec.a.index];
    centreA = ballA.position;
    radiusA = ballA.radius;
    const Vec2 d = centreB - centreA;
    k.normal = d.squaredNorm() > kCoincident ? d.normalized() : Vec2(1.0, 0.0);
    surfaceA = centreA + radiusA * k.normal;
  }
  const Vec2 surfaceB = centreB - ballB.radius * k.normal;
  if (settings.midOverlapContact) {
    const Vec2 point = 0.5 * (surfaceA + surfaceB);
    k.rA = point - centreA;
    k.rB = point - centreB;
  } else {
    k.rA = rec.a.wall ? Vec2(surfaceA - centreA) : Vec2(radiusA * k.normal);
    k.rB = -ballB.radius * k.normal;
  }
}

double crossRV(const Vec2& r, const Vec2& v) {
  return r.x() * v.y() - r.y() * v.x();
}

// Relative velocity of B's contact point with respect to A's.
Vec2 relativeVelocity(const std::vector<BodyState>& bodies, const Constraint& k) {
  const BodyState& a = bodies[k.bodyA];
  const BodyState& b = bodies[k.bodyB];
  return b.v + spinCross(b.w, k.rB) - a.v - spinCross(a.w, k.rA);
}

void applyImpulse(std::vector<BodyState>& bodies, const Constraint& k, const Vec2& p) {
  BodyState& a = bodies[k.bodyA];
  BodyState& b = bodies[k.bodyB];
  a.v -= a.invMass * p;
  a.w -= a.invInertia * crossRV(k.rA, p);
  b.v += b.invMass * p;
  b.w += b.invInertia * crossRV(k.rB, p);
}

// b2ContactSolver::SolveVelocityConstraints for single-point manifolds:
// friction first, clamped by the normal impulse accumulated so far, then the
// normal row towards the restitution bias.
void solveOnce(std::vector<BodyState>& bodies, Constraint& k) {
  const Vec2 tangent(k.normal.y(), -k.normal.x());
  {
    const double vt = relativeVelocity(bodies, k).dot(tangent);
    const double maxFriction = k.friction * k.normalImpulse;
    const double total =
        std::clamp(k.tangentImpulse - k.tangentMass * vt, -maxFriction, maxFriction);
    const double lambda = total - k.tangentImpulse;
    k.tangentImpulse = total;
    applyImpulse(bodies, k, lambda * tangent);
  }
  {
    const double vn = relativeVelocity(bodies, k).dot(k.normal);
    const double total = std::max(k.normalImpulse - k.normalMass * (vn - k.velocityBias), 0.0);
    const double lambda = total - k.normalImpulse;
    k.normalImpulse = total;
    applyImpulse(bodies, k, lambda * k.normal);
  }
}

bool allFinite(const Outcome& o) {
  return std::all_of(o.balls.begin(), o.balls.end(), [](const BodyVelocity& b) {
    return b.velocity.allFinite() && std::isfinite(b.angularVelocity);
  });
}

}  // namespace

Box2DModelResult runBox2DModelDetailed(const ImpactCase& c, const Box2DModelSettings& settings) {
  const SceneDef& s = c.scene;
  const int nBalls = static_cast<int>(s.balls.size());
  const double h = s.dt;

  // b2Island::Solve, first loop: v += h (g + F / m), w += h T / J. Forces are
  // the twin's, from the state at the start of the step (t = 0).
  std::vector<BodyState> bodies(nBalls + 1);  // the last one is the static body
  for (int i = 0; i < nBalls; ++i) {
    const BallDef& b = s.balls[i];
    bodies[i] = {b.velocity, b.angularVelocity, 1.0 / b.mass, 1.0 / b.resolvedInertia()};
  }
  std::vector<Vec2> force(nBalls, Vec2::Zero());
  std::vector<double> torque(nBalls, 0.0);
  for (const ForceDef& f : s.forces) {
    if (!f.activeAt(0.0) || f.ball < 0 || f.ball >= nBalls) continue;
    if (f.type == ForceType::Pull) {
      force[f.ball] += f.stiffness * (f.target - s.balls[f.ball].position);
    } else {
      force[f.ball] += f.force;
      torque[f.ball] += f.torque;
    }
  }
  for (int i = 0; i < nBalls; ++i) {
    bodies[i].v += h * (s.gravity + bodies[i].invMass * force[i]);
    bodies[i].w += h * bodies[i].invInertia * torque[i];
  }

  // b2ContactSolver::InitializeVelocityConstraints, in solve order; the
  // restitution bias is set from the velocities before any iteration.
  const ContactPlan plan = planContacts(s);
  std::vector<Constraint> constraints;
  for (const int index : plan.solveOrder) {
    const ContactRecord& rec = plan.created[index];
    Constraint k;
    k.bodyA = rec.a.wall ? nBalls : rec.a.index;
    k.bodyB = rec.b.index;
    setGeometry(s, rec, settings, k);
    const ContactMaterial mixed =
        mixMaterials(fixtureMaterial(s, rec.a, settings), fixtureMaterial(s, rec.b, settings));
    k.friction = mixed.friction;
    k.restitution = mixed.restitution;
    k.threshold = settings.restitutionThreshold;  // b2MixRestitutionThreshold of equal values

    const BodyState& a = bodies[k.bodyA];
    const BodyState& b = bodies[k.bodyB];
    const Vec2 tangent(k.normal.y(), -k.normal.x());
    const double rnA = crossRV(k.rA, k.normal), rnB = crossRV(k.rB, k.normal);
    const double kNormal =
        a.invMass + b.invMass + a.invInertia * rnA * rnA + b.invInertia * rnB * rnB;
    k.normalMass = kNormal > 0.0 ? 1.0 / kNormal : 0.0;
    const double rtA = crossRV(k.rA, tangent), rtB = crossRV(k.rB, tangent);
    const double kTangent =
        a.invMass + b.invMass + a.invInertia * rtA * rtA + b.invInertia * rtB * rtB;
    k.tangentMass = kTangent > 0.0 ? 1.0 / kTangent : 0.0;
    const double vRel = relativeVelocity(bodies, k).dot(k.normal);
    if (vRel < -k.threshold) k.velocityBias = -k.restitution * vRel;
    constraints.push_back(k);
  }

  // No warm starting: every contact is new, its stored impulses are 0. An
  // iteration that leaves every accumulated impulse unchanged, bit for bit,
  // has reached a fixed point: every later one would repeat it exactly, so
  // stopping there gives the same answer as running all of them (and makes
  // the comparator's 100-iteration "converged" trials cheap).
  for (int it = 0; it < settings.velocityIterations; ++it) {
    bool changed = false;
    for (Constraint& k : constraints) {
      const double normal = k.normalImpulse, tangent = k.tangentImpulse;
      solveOnce(bodies, k);
      changed = changed || normal != k.normalImpulse || tangent != k.tangentImpulse;
    }
    if (!changed) break;
  }

  // b2Island::Solve, position integration: the velocity is scaled down where
  // one step would move or turn a body past Box2D's bounds.
  if (settings.motionClamps) {
    for (int i = 0; i < nBalls; ++i) {
      const double travel = h * bodies[i].v.norm();
      if (travel > kMaxTranslation) bodies[i].v *= kMaxTranslation / travel;
      const double turn = h * std::abs(bodies[i].w);
      if (turn > kMaxRotation) bodies[i].w *= kMaxRotation / turn;
    }
  }

  Box2DModelResult result;
  for (int i = 0; i < nBalls; ++i) result.outcome.balls.push_back({bodies[i].v, bodies[i].w});
  result.outcome.finite = allFinite(result.outcome);

  // Report in solve order, with each contact's place in the world's list
  // (newest first) among the touching ones.
  std::vector<int> worldIndex(plan.created.size(), -1);
  int place = 0;
  for (int k = static_cast<int>(plan.created.size()) - 1; k >= 0; --k)
    if (plan.created[k].touching) worldIndex[k] = place++;
  for (std::size_t j = 0; j < constraints.size(); ++j) {
    const ContactRecord& rec = plan.created[plan.solveOrder[j]];
    Box2DModelContact out;
    out.wall = rec.a.wall;
    out.a = rec.a.wall ? rec.b.index : std::min(rec.a.index, rec.b.index);
    out.b = rec.a.wall ? rec.a.index : std::max(rec.a.index, rec.b.index);
    out.worldListIndex = worldIndex[plan.solveOrder[j]];
    out.normalImpulse = constraints[j].normalImpulse;
    out.tangentImpulse = constraints[j].tangentImpulse;
    result.contacts.push_back(out);
  }
  return result;
}

Outcome runBox2DModel(const ImpactCase& c, const Box2DModelSettings& settings) {
  return runBox2DModelDetailed(c, settings).outcome;
}

}  // namespace particles::compare
