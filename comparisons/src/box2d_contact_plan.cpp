// Stage 1 of the Box2D 2.4.1 model: the contact list, in float as Box2D
// makes it (box2d_contact_plan.h).
#include "box2d_contact_plan.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace particles::compare::detail {
namespace {

// Box2D 2.4.1 constant (b2_common.h with b2_lengthUnitsPerMeter = 1).
constexpr float kAabbExtension = 0.1f;  // b2_aabbExtension, m

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

}  // namespace

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

}  // namespace particles::compare::detail
