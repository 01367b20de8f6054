// Box2D 2.4.1's step, as far as it decides a case's velocities, replayed in
// double. Written from Box2D's sources (b2_broad_phase, b2_dynamic_tree,
// b2_contact_manager, b2_world, b2_island, b2_contact_solver,
// b2_collide_circle, b2_collide_edge, b2WorldManifold), not copied from
// them; docs/box2d-twin.md says what is replicated and why.
//
// Three stages, as in b2World::Step for a fresh world:
//  1. Which contacts exist and in which order (broad phase, contact manager,
//     island search). These are discrete decisions, so they are made with
//     Box2D's own float arithmetic on the float-rounded scene: the model then
//     takes the same branch as Box2D even where double would round the other
//     way.
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

#include "particles/material.h"

namespace particles::compare {
namespace {

// Box2D 2.4.1 constants (b2_common.h with b2_lengthUnitsPerMeter = 1).
constexpr float kAabbExtension = 0.1f;                             // b2_aabbExtension, m
constexpr double kMaxTranslation = 2.0;                            // b2_maxTranslation, m per step
constexpr double kMaxRotation = 0.5 * std::numbers::pi;            // b2_maxRotation, rad per step
constexpr double kCoincident = double(FLT_EPSILON) * FLT_EPSILON;  // b2_epsilon^2, m^2

// ---------------------------------------------------------------------------
// Stage 1: the contact list, in float as Box2D makes it.

struct FloatVec {
  float x = 0.0f, y = 0.0f;
};
FloatVec toFloat(const Vec2& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}
FloatVec operator-(FloatVec a, FloatVec b) {
  return {a.x - b.x, a.y - b.y};
}
float dot(FloatVec a, FloatVec b) {
  return a.x * b.x + a.y * b.y;
}

// b2AABB: lower and upper corners, float.
struct FloatBox {
  FloatVec lo, hi;
};
FloatBox combine(const FloatBox& a, const FloatBox& b) {
  return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y)},
          {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y)}};
}
// b2AABB::GetPerimeter, the tree's cost measure.
float perimeter(const FloatBox& b) {
  const float wx = b.hi.x - b.lo.x;
  const float wy = b.hi.y - b.lo.y;
  return 2.0f * (wx + wy);
}
// b2TestOverlap: touching boxes overlap.
bool overlap(const FloatBox& a, const FloatBox& b) {
  return !(b.lo.x - a.hi.x > 0.0f || b.lo.y - a.hi.y > 0.0f || a.lo.x - b.hi.x > 0.0f ||
           a.lo.y - b.hi.y > 0.0f);
}
FloatBox fatten(const FloatBox& b) {
  return {{b.lo.x - kAabbExtension, b.lo.y - kAabbExtension},
          {b.hi.x + kAabbExtension, b.hi.y + kAabbExtension}};
}

// The shape of b2DynamicTree that decides in which order a query meets the
// proxies: the surface-area-heuristic insertion with its AVL-like rotations,
// and the stack-based query (child2 is searched before child1). Nodes are
// numbered in allocation order, as the tree's free list hands them out in a
// fresh world (nothing is freed before the first step), so the ids are
// Box2D's proxy ids.
class ProxyTree {
 public:
  int createProxy(const FloatBox& shapeBox) {
    const int leaf = allocate();
    nodes_[leaf].box = fatten(shapeBox);
    insertLeaf(leaf);
    return leaf;
  }
  const FloatBox& fatBox(int proxy) const { return nodes_[proxy].box; }

  // Calls visit(proxy) for every leaf whose box overlaps `box`, in
  // b2DynamicTree::Query's order.
  template <class Visit>
  void query(const FloatBox& box, Visit&& visit) const {
    std::vector<int> stack{root_};
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      if (id < 0 || !overlap(nodes_[id].box, box)) continue;
      if (nodes_[id].leaf()) {
        visit(id);
      } else {
        stack.push_back(nodes_[id].child1);
        stack.push_back(nodes_[id].child2);
      }
    }
  }

 private:
  struct Node {
    FloatBox box;
    int parent = -1, child1 = -1, child2 = -1;
    int height = 0;  // leaf 0
    bool leaf() const { return child1 < 0; }
  };

  int allocate() {
    nodes_.emplace_back();
    return static_cast<int>(nodes_.size()) - 1;
  }

  // Cost of making `leafBox` a sibling somewhere below `child`: a leaf child
  // would get a new parent around both, an inner one grows.
  float descentCost(int child, const FloatBox& leafBox, float inheritance) const {
    const float grown = perimeter(combine(leafBox, nodes_[child].box));
    if (nodes_[child].leaf()) return grown + inheritance;
    return (grown - perimeter(nodes_[child].box)) + inheritance;
  }

  void insertLeaf(int leaf) {
    if (root_ < 0) {
      root_ = leaf;
      return;
    }
    const FloatBox leafBox = nodes_[leaf].box;
    // Walk down to the cheapest sibling.
    int at = root_;
    while (!nodes_[at].leaf()) {
      const float area = perimeter(nodes_[at].box);
      const float combined = perimeter(combine(nodes_[at].box, leafBox));
      const float here = 2.0f * combined;                  // new parent right here
      const float inheritance = 2.0f * (combined - area);  // every level below grows this
      const float cost1 = descentCost(nodes_[at].child1, leafBox, inheritance);
      const float cost2 = descentCost(nodes_[at].child2, leafBox, inheritance);
      if (here < cost1 && here < cost2) break;
      at = cost1 < cost2 ? nodes_[at].child1 : nodes_[at].child2;
    }
    const int sibling = at;
    const int oldParent = nodes_[sibling].parent;
    const int parent = allocate();
    nodes_[parent].parent = oldParent;
    nodes_[parent].box = combine(leafBox, nodes_[sibling].box);
    nodes_[parent].height = nodes_[sibling].height + 1;
    nodes_[parent].child1 = sibling;
    nodes_[parent].child2 = leaf;
    nodes_[sibling].parent = parent;
    nodes_[leaf].parent = parent;
    if (oldParent < 0) {
      root_ = parent;
    } else if (nodes_[oldParent].child1 == sibling) {
      nodes_[oldParent].child1 = parent;
    } else {
      nodes_[oldParent].child2 = parent;
    }
    // Back up to the root, rebalancing and refitting.
    for (int up = nodes_[leaf].parent; up >= 0; up = nodes_[up].parent) {
      up = rebalance(up);
      const Node& n = nodes_[up];
      nodes_[up].height = 1 + std::max(nodes_[n.child1].height, nodes_[n.child2].height);
      nodes_[up].box = combine(nodes_[n.child1].box, nodes_[n.child2].box);
    }
  }

  void replaceChild(int parent, int oldChild, int newChild) {
    if (parent < 0) {
      root_ = newChild;
    } else if (nodes_[parent].child1 == oldChild) {
      nodes_[parent].child1 = newChild;
    } else {
      nodes_[parent].child2 = newChild;
    }
  }

  // b2DynamicTree::Balance: if one child of `a` is more than one level
  // taller than the other, it is rotated up; returns the subtree's new root.
  int rebalance(int a) {
    if (nodes_[a].leaf() || nodes_[a].height < 2) return a;
    const int b = nodes_[a].child1, c = nodes_[a].child2;
    const int lean = nodes_[c].height - nodes_[b].height;
    if (lean > 1) return rotateUp(a, c, /*tallIsChild2=*/true);
    if (lean < -1) return rotateUp(a, b, /*tallIsChild2=*/false);
    return a;
  }

  // Moves the tall child `t` of `a` into a's place; a becomes t's child1 and
  // keeps the shorter of t's children, t keeps the taller.
  int rotateUp(int a, int t, bool tallIsChild2) {
    const int f = nodes_[t].child1, g = nodes_[t].child2;
    const int oldParent = nodes_[a].parent;
    nodes_[t].child1 = a;
    nodes_[t].parent = oldParent;
    nodes_[a].parent = t;
    replaceChild(oldParent, a, t);
    const bool keepF = nodes_[f].height > nodes_[g].height;
    const int kept = keepF ? f : g, given = keepF ? g : f;
    nodes_[t].child2 = kept;
    if (tallIsChild2) {
      nodes_[a].child2 = given;
    } else {
      nodes_[a].child1 = given;
    }
    nodes_[given].parent = a;
    const int stay = tallIsChild2 ? nodes_[a].child1 : nodes_[a].child2;
    nodes_[a].box = combine(nodes_[stay].box, nodes_[given].box);
    nodes_[t].box = combine(nodes_[a].box, nodes_[kept].box);
    nodes_[a].height = 1 + std::max(nodes_[stay].height, nodes_[given].height);
    nodes_[t].height = 1 + std::max(nodes_[a].height, nodes_[kept].height);
    return t;
  }

  std::vector<Node> nodes_;
  int root_ = -1;
};

// A fixture: one ball's circle or one wall's edge. Bodies are numbered
// 0..N-1 for the balls and N for the static body that carries every wall
// (the twin's layout).
struct Fixture {
  bool wall = false;
  int index = 0;  // ball or wall index
};

// How a touching circle meets an edge (b2CollideEdgeAndCircle's regions).
enum class EdgeRegion { Face, VertexA, VertexB };

struct ContactRecord {
  Fixture a, b;  // Box2D's fixture A and B: the edge is always A
  bool touching = false;
  EdgeRegion region = EdgeRegion::Face;
  bool flip = false;  // face region: the circle is on the side of -(e_y, -e_x)
};

// b2CollideCircles' test: touching unless the float distance squared
// exceeds the float radius sum squared.
bool circlesTouch(const BallDef& a, const BallDef& b) {
  const FloatVec d = toFloat(b.position) - toFloat(a.position);
  const float radius = static_cast<float>(a.radius) + static_cast<float>(b.radius);
  return !(dot(d, d) > radius * radius);
}

// b2CollideEdgeAndCircle for a two-sided edge of skin radius 0 on a body at
// the origin, in float.
void collideEdge(const WallDef& w, const BallDef& ball, ContactRecord& rec) {
  const FloatVec q = toFloat(ball.position), a = toFloat(w.a), b = toFloat(w.b);
  const FloatVec e = b - a;
  const FloatVec n{e.y, -e.x};
  const float offset = dot(n, q - a);
  const float u = dot(e, b - q), v = dot(e, q - a);
  const float radius = 0.0f + static_cast<float>(ball.radius);
  auto near = [&](FloatVec p) {
    const FloatVec d = q - p;
    return !(dot(d, d) > radius * radius);
  };
  if (v <= 0.0f) {
    rec.region = EdgeRegion::VertexA;
    rec.touching = near(a);
    return;
  }
  if (u <= 0.0f) {
    rec.region = EdgeRegion::VertexB;
    rec.touching = near(b);
    return;
  }
  const float den = dot(e, e);
  if (!(den > 0.0f)) return;  // a wall of no length: Box2D asserts
  const float s = 1.0f / den;
  const FloatVec p{s * (u * a.x + v * b.x), s * (u * a.y + v * b.y)};
  rec.region = EdgeRegion::Face;
  rec.touching = near(p);
  rec.flip = offset < 0.0f;
}

// The contacts of the fresh world's first step, in creation order, with the
// world's contact list and island search replayed to give the solve order.
struct ContactPlan {
  std::vector<ContactRecord> created;  // b2ContactManager::AddPair order
  std::vector<int> solveOrder;         // indices into `created`, touching only
};

ContactPlan planContacts(const SceneDef& s) {
  const int nBalls = static_cast<int>(s.balls.size());
  const int ground = nBalls;
  auto bodyOf = [&](const Fixture& f) { return f.wall ? ground : f.index; };

  // Proxies in fixture creation order: the twin adds the walls (one static
  // body) first, then each ball. Every new proxy is in the move buffer.
  ProxyTree tree;
  std::vector<Fixture> proxyFixture;  // by proxy id; inner nodes stay unused
  std::vector<int> moveBuffer;
  auto addProxy = [&](const Fixture& f, const FloatBox& box) {
    const int id = tree.createProxy(box);
    if (proxyFixture.size() <= static_cast<std::size_t>(id)) proxyFixture.resize(id + 1);
    proxyFixture[id] = f;
    moveBuffer.push_back(id);
  };
  for (int k = 0; k < static_cast<int>(s.walls.size()); ++k) {
    const FloatVec a = toFloat(s.walls[k].a), b = toFloat(s.walls[k].b);
    addProxy({true, k},
             {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}});
  }
  for (int i = 0; i < nBalls; ++i) {
    const FloatVec p = toFloat(s.balls[i].position);
    const float r = static_cast<float>(s.balls[i].radius);
    addProxy({false, i}, {{p.x - r, p.y - r}, {p.x + r, p.y + r}});
  }

  // b2BroadPhase::UpdatePairs: each moved proxy queries the tree; as every
  // proxy moved, a pair is reported by its higher id's query only.
  std::vector<std::pair<int, int>> pairs;
  for (const int q : moveBuffer) {
    tree.query(tree.fatBox(q), [&](int p) {
      if (p < q) pairs.emplace_back(p, q);
    });
  }

  // b2ContactManager::AddPair: no contact within one body (two walls); the
  // edge-circle contact puts the edge first, two circles keep the pair order.
  ContactPlan plan;
  for (const auto& [p, q] : pairs) {
    Fixture fa = proxyFixture[p], fb = proxyFixture[q];
    if (bodyOf(fa) == bodyOf(fb)) continue;
    if (fb.wall) std::swap(fa, fb);
    ContactRecord rec;
    rec.a = fa;
    rec.b = fb;
    if (fa.wall) {
      collideEdge(s.walls[fa.index], s.balls[fb.index], rec);
    } else {
      rec.touching = circlesTouch(s.balls[fa.index], s.balls[fb.index]);
    }
    plan.created.push_back(rec);
  }

  // Each new contact is put at the head of both bodies' contact lists.
  std::vector<std::vector<int>> bodyContacts(nBalls + 1);
  for (int k = static_cast<int>(plan.created.size()) - 1; k >= 0; --k) {
    bodyContacts[bodyOf(plan.created[k].a)].push_back(k);
    bodyContacts[bodyOf(plan.created[k].b)].push_back(k);
  }

  // b2World::Solve: seeds in world body order (last created first, the
  // static body never), depth first over touching contacts; a static body
  // joins an island but does not carry it on, and is released after it.
  std::vector<bool> bodyFlag(nBalls + 1, false), contactFlag(plan.created.size(), false);
  for (int seed = nBalls - 1; seed >= 0; --seed) {
    if (bodyFlag[seed]) continue;
    std::vector<int> stack{seed};
    bodyFlag[seed] = true;
    while (!stack.empty()) {
      const int body = stack.back();
      stack.pop_back();
      if (body == ground) continue;
      for (const int k : bodyContacts[body]) {
        if (contactFlag[k] || !plan.created[k].touching) continue;
        plan.solveOrder.push_back(k);
        contactFlag[k] = true;
        const int ba = bodyOf(plan.created[k].a);
        const int other = ba == body ? bodyOf(plan.created[k].b) : ba;
        if (bodyFlag[other]) continue;
        stack.push_back(other);
        bodyFlag[other] = true;
      }
    }
    bodyFlag[ground] = false;
  }
  return plan;
}

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
