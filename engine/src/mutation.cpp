#include "particles/mutation.h"

namespace particles {

std::string_view mutationName(Mutation m) {
  switch (m) {
    case Mutation::None:
      return "none";
    case Mutation::NormalImpulseSign:
      return "normal impulse sign";
    case Mutation::RestitutionSign:
      return "restitution sign (1 - e)";
    case Mutation::TangentImpulseSign:
      return "tangent impulse sign";
    case Mutation::SlipLinearSign:
      return "slip: linear term sign";
    case Mutation::SlipSpinASign:
      return "slip: spin of a sign";
    case Mutation::SlipSpinBSign:
      return "slip: spin of b sign";
    case Mutation::ImpulseOnASign:
      return "impulse on a sign";
    case Mutation::SpinUpdateASign:
      return "spin update of a sign";
    case Mutation::SpinUpdateBSign:
      return "spin update of b sign";
    case Mutation::ClampDropsSign:
      return "Coulomb clamp drops the sign";
    case Mutation::WallTangentFlipped:
      return "wall with the wrong tangent";
  }
  return "unknown";
}

}  // namespace particles
