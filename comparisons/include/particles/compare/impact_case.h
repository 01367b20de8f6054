// One comparison case: a scene whose bodies start at contact, run for one
// step in each engine. Families follow the design card's no-slip,
// friction-limited and wall cases, plus smooth and multi-contact ones.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "particles/scene.h"

namespace particles::compare {

enum class Family {
  NoSlip,            // ball-ball, mu infinite
  FrictionSliding,   // ball-ball, finite mu below the sticking threshold
  FrictionSticking,  // ball-ball, finite mu above it
  Wall,              // ball-wall, any tangential mode
  Smooth,            // ball-ball, mu = 0
  MultiContact,      // three balls at once, a ball in a corner, Newton's cradles
};

inline constexpr std::array<Family, 6> kAllFamilies = {
    Family::NoSlip, Family::FrictionSliding, Family::FrictionSticking,
    Family::Wall,   Family::Smooth,          Family::MultiContact};

std::string_view familyName(Family f);  // "no-slip", "friction-sliding", ...

// The parameters a case was drawn from, kept for the report.
struct CaseParams {
  double massRatio = 1.0;    // m_b / m_a (wall: 0)
  double radiusRatio = 1.0;  // r_b / r_a (wall: 0)
  double restitution = 1.0;
  double friction = 0.0;     // may be kNoSlip
  double impactAngle = 0.0;  // rad, between the approach velocity and -n
  double speed = 0.0;        // m/s, |relative velocity| at the contact
};

struct ImpactCase {
  std::string name;  // "catalogue/head-on same spin" or "random/no-slip/17"
  Family family = Family::NoSlip;
  SceneDef scene;  // bodies at contact, one step long
  CaseParams params;
  // Exactly one contact (two balls, or one ball and one wall): the closed
  // form applies. Body a is balls[0]; body b is balls[1] or walls[0].
  bool isolated = true;
};

// Cases are placed at contact with this overlap, relative to the radii sum:
// Box2D stores positions as float, and an exact contact rounded to float
// opens a gap half of the time, so Box2D would see no contact at all. The
// overlap moves Box2D's contact point (the middle of the overlap) by 5e-7 of
// the radii, far below float tolerance.
inline constexpr double kPlacementOverlap = 1e-6;

}  // namespace particles::compare
