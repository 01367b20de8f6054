#include <array>

#include "json_values.h"
#include "particles/scene_output.h"
#include "readers.h"

namespace particles::scenefile {
namespace {

constexpr std::array<std::string_view, 5> kWallKeys{"a", "b", "restitution", "friction",
                                                    "one_sided"};
constexpr std::array<std::string_view, 4> kBoxKeys{"min", "max", "restitution", "friction"};

std::string text(const Vec2& v) {
  std::string out = "[";
  out += formatDouble(v.x());
  out += ", ";
  out += formatDouble(v.y());
  out += ']';
  return out;
}

}  // namespace

// A wall with a == b is legal: a point obstacle (the engine pushes balls out
// along the line from the point).
WallDef readWall(const Node& node) {
  node.allowKeys(kWallKeys);
  WallDef wall;
  wall.a = readVec2(node.required("a"));
  wall.b = readVec2(node.required("b"));
  if (auto e = node.optional("restitution")) wall.restitution = readRestitution(*e);
  if (auto mu = node.optional("friction")) wall.friction = readFriction(*mu);
  if (auto side = node.optional("one_sided")) wall.oneSided = readBool(*side);
  return wall;
}

std::vector<WallDef> readBox(const Node& node) {
  node.allowKeys(kBoxKeys);
  const Vec2 lo = readVec2(node.required("min"));
  const Node maxNode = node.required("max");
  const Vec2 hi = readVec2(maxNode);
  if (!(lo.x() < hi.x() && lo.y() < hi.y()))
    maxNode.fail("must be greater than min in both x and y, got min " + text(lo) + ", max " +
                 text(hi));
  std::vector<WallDef> walls = boxWalls(lo, hi);
  std::optional<double> restitution, friction;
  if (auto e = node.optional("restitution")) restitution = readRestitution(*e);
  if (auto mu = node.optional("friction")) friction = readFriction(*mu);
  for (WallDef& w : walls) {
    w.restitution = restitution;
    w.friction = friction;
  }
  return walls;
}

}  // namespace particles::scenefile
