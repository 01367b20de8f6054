#include <array>
#include <cmath>

#include "edit_distance.h"
#include "json_values.h"
#include "particles/scene_output.h"
#include "readers.h"

namespace particles::scenefile {
namespace {

constexpr std::array<std::string_view, 2> kForceTypes{"pull", "constant"};
constexpr std::array<std::string_view, 6> kPullKeys{"type",      "ball",  "target",
                                                    "stiffness", "start", "end"};
constexpr std::array<std::string_view, 6> kConstantKeys{"type",   "ball",  "force",
                                                        "torque", "start", "end"};

ForceType readType(const Node& node) {
  const std::string type = readString(node);
  if (type == "pull") return ForceType::Pull;
  if (type == "constant") return ForceType::Constant;
  const std::string suggestion = closestMatch(type, kForceTypes);
  node.fail("unknown force type '" + type + "'" +
            (suggestion.empty() ? "" : "; did you mean '" + suggestion + "'?") +
            " (known types: " + quotedList(kForceTypes) + ")");
}

// A valid index into the scene's balls (ballCount >= 1); 2.0 counts as 2.
int readBallIndex(const Node& node, std::size_t ballCount) {
  const nlohmann::json& v = node.value();
  const double x = v.is_number() ? v.get<double>() : 0.5;
  if (!std::isfinite(x) || x != std::floor(x))
    node.fail("must be an integer ball index, got " + describe(v));
  if (x < 0.0 || x >= static_cast<double>(ballCount))
    node.fail("ball " + describe(v) + " does not exist (" +
              (ballCount == 1 ? std::string("the scene has 1 ball, index 0")
                              : "the scene has " + std::to_string(ballCount) +
                                    " balls, indices 0.." + std::to_string(ballCount - 1)) +
              ")");
  return static_cast<int>(x);
}

}  // namespace

ForceDef readForce(const Node& node, std::size_t ballCount) {
  node.requireObject();
  ForceDef force;
  force.type = readType(node.required("type"));
  if (force.type == ForceType::Pull) {
    node.allowKeys(kPullKeys);
    force.target = readVec2(node.required("target"));
    force.stiffness = readNonNegative(node.required("stiffness"));
  } else {
    node.allowKeys(kConstantKeys);
    if (auto f = node.optional("force")) force.force = readVec2(*f);
    if (auto t = node.optional("torque")) force.torque = readNumber(*t);
  }
  force.ball = readBallIndex(node.required("ball"), ballCount);
  // Active while start <= t < end; start == end is legal and never active.
  if (auto s = node.optional("start")) force.start = readNumber(*s);
  if (auto e = node.optional("end")) {
    force.end = readNumber(*e);
    if (force.end < force.start)
      e->fail("must be >= start (" + formatDouble(force.start) + "), got " +
              formatDouble(force.end));
  }
  return force;
}

}  // namespace particles::scenefile
