// One reader per part of a scene file; each validates what it reads and
// fails with the JSON path of the offending value (docs/scene-format.md).
#pragma once

#include <string>
#include <vector>

#include "json_node.h"
#include "particles/scene.h"

namespace particles::scenefile {

BallDef readBall(const Node& node);
WallDef readWall(const Node& node);
// The four walls of "box": {"min", "max", "restitution", "friction"}, in
// boxWalls' order (bottom, right, top, left).
std::vector<WallDef> readBox(const Node& node);
// `ballCount` bounds the force's ball index.
ForceDef readForce(const Node& node, std::size_t ballCount);
ContactMaterial readContact(const Node& node);
// `dt` (s), the scene's step, bounds the soft step's contact spring.
SolverSettings readSolver(const Node& node, double dt);

}  // namespace particles::scenefile
