#include "json_values.h"

#include <cmath>

#include "particles/scene_output.h"

namespace particles::scenefile {

double readNumber(const Node& node) {
  const nlohmann::json& v = node.value();
  if (!v.is_number()) node.fail("must be a number, got " + describe(v));
  const double x = v.get<double>();
  // JSON cannot spell NaN or infinity, but 1e999 parses as infinity.
  if (!std::isfinite(x)) node.fail("must be a finite number, got " + describe(v));
  return x;
}

double readPositive(const Node& node) {
  const double x = readNumber(node);
  if (!(x > 0.0)) node.fail("must be > 0, got " + formatDouble(x));
  return x;
}

double readNonNegative(const Node& node) {
  const double x = readNumber(node);
  if (x < 0.0) node.fail("must be >= 0, got " + formatDouble(x));
  return x;
}

double readRestitution(const Node& node) {
  const double x = readNumber(node);
  if (x < 0.0 || x > 1.0) node.fail("must be in [0, 1], got " + formatDouble(x));
  return x;
}

double readFriction(const Node& node) {
  const nlohmann::json& v = node.value();
  if (v.is_string()) {
    if (v.get<std::string>() == "infinite") return kNoSlip;
    node.fail("must be a number >= 0 or \"infinite\", got " + describe(v));
  }
  if (!v.is_number()) node.fail("must be a number >= 0 or \"infinite\", got " + describe(v));
  return readNonNegative(node);
}

Vec2 readVec2(const Node& node) {
  const nlohmann::json& v = node.value();
  if (!v.is_array() || v.size() != 2)
    node.fail("must be an array of 2 numbers [x, y], got " + describe(v));
  const std::vector<Node> xy = node.elements();
  return Vec2(readNumber(xy[0]), readNumber(xy[1]));
}

std::string readString(const Node& node) {
  if (!node.value().is_string()) node.fail("must be a string, got " + describe(node.value()));
  return node.value().get<std::string>();
}

bool readBool(const Node& node) {
  if (!node.value().is_boolean()) node.fail("must be true or false, got " + describe(node.value()));
  return node.value().get<bool>();
}

long long readInteger(const Node& node, long long lo, long long hi) {
  const nlohmann::json& v = node.value();
  std::string range = "[";  // built up piecewise: GCC 12 -Wrestrict misfires on "[" + string
  range += std::to_string(lo);
  range += ", ";
  range += std::to_string(hi);
  range += ']';
  long long n = 0;
  if (v.is_number_unsigned()) {
    const auto u = v.get<unsigned long long>();
    if (hi < 0 || u > static_cast<unsigned long long>(hi))
      node.fail("must be an integer in " + range + ", got " + std::to_string(u));
    n = static_cast<long long>(u);
  } else if (v.is_number_integer()) {
    n = v.get<long long>();
  } else if (v.is_number()) {
    // A float counts when it is integral (2.0) and in range.
    const double x = readNumber(node);
    if (x != std::floor(x)) node.fail("must be an integer, got " + describe(v));
    if (x < static_cast<double>(lo) || x > static_cast<double>(hi) || std::abs(x) >= 0x1p63)
      node.fail("must be an integer in " + range + ", got " + describe(v));
    n = static_cast<long long>(x);
  } else {
    node.fail("must be an integer, got " + describe(v));
  }
  if (n < lo || n > hi) node.fail("must be an integer in " + range + ", got " + std::to_string(n));
  return n;
}

}  // namespace particles::scenefile
