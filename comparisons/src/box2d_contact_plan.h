// Stage 1 of the Box2D 2.4.1 model (box2d_model.cpp): which contacts a fresh
// world's first step creates and in which order it solves them, decided
// with Box2D's own float arithmetic on the float-rounded scene, so that the
// model takes the same branch as Box2D even where double would round the
// other way. Written from Box2D's sources (b2_broad_phase, b2_dynamic_tree,
// b2_contact_manager, b2_world, b2_island, b2_collide_circle,
// b2_collide_edge), not copied from them; docs/box2d-twin.md.
#pragma once

#include <vector>

#include "particles/scene.h"

namespace particles::compare::detail {

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

// The contacts of the fresh world's first step, in creation order, with the
// world's contact list and island search replayed to give the solve order.
struct ContactPlan {
  std::vector<ContactRecord> created;  // b2ContactManager::AddPair order
  std::vector<int> solveOrder;         // indices into `created`, touching only
};

ContactPlan planContacts(const SceneDef& s);

}  // namespace particles::compare::detail
