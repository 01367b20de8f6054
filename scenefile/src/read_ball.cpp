#include <array>
#include <cmath>
#include <numbers>

#include "json_values.h"
#include "particles/scene_output.h"
#include "readers.h"

namespace particles::scenefile {
namespace {

constexpr std::array<std::string_view, 10> kBallKeys{
    "position", "velocity", "angle",   "angular_velocity", "radius",
    "mass",     "density",  "inertia", "restitution",      "friction"};

bool usable(double x) {
  return std::isfinite(x) && x > 0.0;
}

}  // namespace

BallDef readBall(const Node& node) {
  node.allowKeys(kBallKeys);
  BallDef ball;
  ball.position = readVec2(node.required("position"));
  if (auto v = node.optional("velocity")) ball.velocity = readVec2(*v);
  if (auto a = node.optional("angle")) ball.angle = readNumber(*a);
  if (auto w = node.optional("angular_velocity")) ball.angularVelocity = readNumber(*w);
  const Node radius = node.required("radius");
  ball.radius = readPositive(radius);

  const std::optional<Node> mass = node.optional("mass");
  const std::optional<Node> density = node.optional("density");
  if (mass && density) node.fail("give either 'mass' or 'density', not both");
  if (!mass && !density) node.fail("missing required key 'mass' (or 'density')");
  if (mass) {
    ball.mass = readPositive(*mass);
  } else {
    const double rho = readPositive(*density);
    ball.mass = rho * std::numbers::pi * ball.radius * ball.radius;  // kg/m^2 times area
    if (!usable(ball.mass))
      density->fail("gives mass = density * pi * r^2 = " + formatDouble(ball.mass) +
                    ", which must be finite and > 0");
  }

  if (auto j = node.optional("inertia")) {
    ball.inertia = readPositive(*j);
  } else if (!usable(ball.resolvedInertia())) {
    radius.fail("gives the default inertia m r^2 / 2 = " + formatDouble(ball.resolvedInertia()) +
                ", which must be finite and > 0; give 'inertia' explicitly");
  }
  if (auto e = node.optional("restitution")) ball.restitution = readRestitution(*e);
  if (auto mu = node.optional("friction")) ball.friction = readFriction(*mu);
  return ball;
}

}  // namespace particles::scenefile
