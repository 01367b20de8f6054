// Reading one JSON value as a number, vector, string or integer, with the
// constraint checks the scene format needs. Each fails with the node's path.
#pragma once

#include <string>

#include "json_node.h"
#include "particles/types.h"

namespace particles::scenefile {

double readNumber(const Node& node);       // any finite number
double readPositive(const Node& node);     // finite, > 0
double readNonNegative(const Node& node);  // finite, >= 0
double readRestitution(const Node& node);  // in [0, 1]
double readFriction(const Node& node);     // >= 0, or "infinite" (kNoSlip)
Vec2 readVec2(const Node& node);           // [x, y], two finite numbers
std::string readString(const Node& node);
bool readBool(const Node& node);  // true or false (JSON booleans only, not 0/1 or "true")
// An integer in [lo, hi]; integral numbers written as 2.0 count.
long long readInteger(const Node& node, long long lo, long long hi);

}  // namespace particles::scenefile
