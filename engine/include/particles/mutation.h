// Deliberately wrong variants of the impulse solver, for the comparison
// suite's mutation check: the handout warns that its signs may be wrong, so
// the suite must prove it would notice each wrong sign. Never used by a
// scene; SolverSettings::mutation defaults to None and the normal path is
// compiled without any mutation test (the solver is a template on it).
#pragma once

#include <array>
#include <string_view>

namespace particles {

enum class Mutation {
  None,
  NormalImpulseSign,   // lambdaN = +(1 + e) gn / k
  RestitutionSign,     // (1 - e) instead of (1 + e)
  TangentImpulseSign,  // lambdaT = +gt / k
  SlipLinearSign,      // gt with -(v_b - v_a).tau
  SlipSpinASign,       // gt with +w_a r_a
  SlipSpinBSign,       // gt with +w_b r_b
  ImpulseOnASign,      // a receives +P instead of -P
  SpinUpdateASign,     // w_a += r_a lambdaT / J_a
  SpinUpdateBSign,     // w_b += r_b lambdaT / J_b
  ClampDropsSign,      // sliding lambdaT = mu lambdaN, sign lost
  WallTangentFlipped,  // a wall contact uses tau = -(z x n)
};

inline constexpr std::array<Mutation, 11> kAllMutations = {
    Mutation::NormalImpulseSign, Mutation::RestitutionSign,    Mutation::TangentImpulseSign,
    Mutation::SlipLinearSign,    Mutation::SlipSpinASign,      Mutation::SlipSpinBSign,
    Mutation::ImpulseOnASign,    Mutation::SpinUpdateASign,    Mutation::SpinUpdateBSign,
    Mutation::ClampDropsSign,    Mutation::WallTangentFlipped,
};

std::string_view mutationName(Mutation m);

}  // namespace particles
