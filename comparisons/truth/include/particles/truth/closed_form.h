// Closed-form truth for one isolated impact of two discs (or a disc and a wall).
//
// This is the "third voice" that decides between the engine (engine/) and Box2D (reference/).
// It is derived from conservation laws alone and shares no code and no formulas with
// engine/src/contact_impulse.cpp; see docs/closed-form.md for the derivation.
//
// Units SI, y up, angles and spins counter-clockwise positive.
//
// Geometry (implied, positions are not inputs): body a is at the origin, body b at
// (r_a + r_b) n, so the contact point is c = r_a n. A wall is a half-plane whose surface passes
// through c with normal n; it has infinite mass and inertia and is at rest (its velocity, spin,
// mass, inertia and radius are ignored).
//
// Sign conventions:
//   n   unit normal from a to b (renormalised in long double; its length must be 1 within 1e-6);
//   tau = z x n = (-n_y, n_x);
//   g_n = (v_b - v_a).n                              normal relative velocity, < 0 = approaching;
//   g_t = (v_b - v_a).tau - w_b r_b - w_a r_a        slip of b's surface relative to a's at c;
//   the impulse on b is +(J_n n + J_t tau) applied at c, the impulse on a is -(J_n n + J_t tau);
//   J_n >= 0 always (the contact can only push), J_t has either sign.
//
// Impact model (Walton with beta0 = 0): g_n' = -e g_n if g_n < 0, otherwise nothing happens;
//   friction mu = 0          smooth: J_t = 0;
//   friction mu = +infinity  no slip: g_t' = 0;
//   0 < mu < infinity        sticking (g_t' = 0) if that needs |J_t| <= mu J_n, otherwise
//                            sliding: J_t = s mu J_n with s = -sign(g_t).
#pragma once

namespace particles::truth {

/// A disc (or a wall when `wall` is true). For a wall every other field is ignored.
struct Body {
  long double mass = 0;        ///< kg, > 0 (the default is rejected for a disc)
  long double inertia = 0;     ///< kg m^2 about the centre, > 0
  long double radius = 0;      ///< m, >= 0
  long double vx = 0, vy = 0;  ///< m/s
  long double w = 0;           ///< rad/s, counter-clockwise
  bool wall = false;
};

enum class Regime {
  Separating,  ///< g_n >= 0: no impulse, bodies unchanged
  Smooth,      ///< mu = 0: normal impulse only
  Sticking,    ///< g_t' = 0 (always for mu = +infinity)
  Sliding,     ///< |J_t| = mu J_n, J_t opposing the slip g_t
};

/// Post-impact state. `a` and `b` are the bodies after the impact (a wall is returned as given).
/// `normalImpulse` = J_n >= 0 and `tangentImpulse` = J_t are the components of the impulse on b
/// along n and tau (the impulse on a is the opposite), in N s.
struct Impact {
  Body a, b;
  Regime regime = Regime::Separating;
  long double normalImpulse = 0;
  long double tangentImpulse = 0;
};

/// Solves one impact from conservation laws (see the file comment and docs/closed-form.md).
/// Either body (not both) may be a wall. `restitution` e in [0, 1]; `friction` mu >= 0, may be
/// +infinity. Throws std::invalid_argument for non-finite or out-of-range inputs (mass or
/// inertia <= 0, radius < 0, two walls, a normal that is not a unit vector).
Impact solveImpact(const Body& a, const Body& b, long double nx, long double ny,
                   long double restitution, long double friction);

}  // namespace particles::truth
