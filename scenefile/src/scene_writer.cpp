#include "particles/scene_writer.h"

#include <algorithm>
#include <cmath>

namespace particles {
namespace {

nlohmann::json vec(const Vec2& v) {
  return nlohmann::json::array({v.x(), v.y()});
}

nlohmann::json friction(double mu) {
  if (std::isinf(mu)) return "infinite";
  return mu;
}

}  // namespace

nlohmann::json sceneJson(const SceneDef& s) {
  nlohmann::json j;
  j["name"] = s.name;
  j["gravity"] = vec(s.gravity);
  j["contact"] = {{"restitution", s.contact.restitution},
                  {"friction", friction(s.contact.friction)}};
  j["walls"] = nlohmann::json::array();
  for (const WallDef& w : s.walls) {
    nlohmann::json o{{"a", vec(w.a)}, {"b", vec(w.b)}};
    if (w.restitution) o["restitution"] = *w.restitution;
    if (w.friction) o["friction"] = friction(*w.friction);
    if (w.oneSided) o["one_sided"] = true;
    j["walls"].push_back(o);
  }
  j["balls"] = nlohmann::json::array();
  for (const BallDef& b : s.balls) {
    nlohmann::json o{
        {"position", vec(b.position)},           {"velocity", vec(b.velocity)}, {"angle", b.angle},
        {"angular_velocity", b.angularVelocity}, {"radius", b.radius},          {"mass", b.mass},
        {"inertia", b.resolvedInertia()}};
    if (b.restitution) o["restitution"] = *b.restitution;
    if (b.friction) o["friction"] = friction(*b.friction);
    j["balls"].push_back(o);
  }
  j["forces"] = nlohmann::json::array();
  for (const ForceDef& f : s.forces) {
    nlohmann::json o{{"ball", f.ball}, {"start", f.start}};
    if (f.type == ForceType::Pull) {
      o["type"] = "pull";
      o["target"] = vec(f.target);
      o["stiffness"] = f.stiffness;
    } else {
      o["type"] = "constant";
      o["force"] = vec(f.force);
      o["torque"] = f.torque;
    }
    if (std::isfinite(f.end)) o["end"] = f.end;
    j["forces"].push_back(o);
  }
  j["dt"] = s.dt;
  j["duration"] = s.duration;
  j["solver"] = {{"contact_passes", s.solver.contactPasses},
                 {"correction_passes", s.solver.correctionPasses},
                 {"grid_threshold", s.solver.gridThreshold},
                 {"swept_walls", s.solver.sweptWalls},
                 {"swept_balls", s.solver.sweptBalls}};
  // Only when on: scene files written before it keep their text.
  if (s.solver.scaleSequentialImpacts) j["solver"]["sequential_impacts"] = true;
  if (!s.solver.scaleVelocityShock) j["solver"]["velocity_shock"] = false;
  // The soft step's keys only with substeps: the loader refuses its spring's
  // keys without them.
  if (s.solver.scaleSubsteps > 0) {
    nlohmann::json& solver = j["solver"];
    solver["soft_substeps"] = s.solver.scaleSubsteps;
    // The engine clamps the spring to a quarter of the substep rate and the
    // loader refuses more: written clamped, it runs the same.
    const double most = softContactHertzMost(s.dt, s.solver.scaleSubsteps);
    if (s.solver.scaleContactHertz > 0.0)
      solver["soft_contact_hertz"] = std::min(s.solver.scaleContactHertz, most);
    solver["soft_contact_damping_ratio"] = s.solver.scaleContactDampingRatio;
    solver["soft_contact_push_speed"] = s.solver.scaleContactPushSpeed;
  }
  return j;
}

std::string sceneText(const SceneDef& scene) {
  return sceneJson(scene).dump(1) + "\n";
}

}  // namespace particles
