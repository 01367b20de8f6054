#include "particles/compare/impact_case.h"

namespace particles::compare {

std::string_view familyName(Family f) {
  switch (f) {
    case Family::NoSlip:
      return "no-slip";
    case Family::FrictionSliding:
      return "friction-sliding";
    case Family::FrictionSticking:
      return "friction-sticking";
    case Family::Wall:
      return "wall";
    case Family::Smooth:
      return "smooth";
    case Family::MultiContact:
      return "multi-contact";
  }
  return "unknown";
}

}  // namespace particles::compare
