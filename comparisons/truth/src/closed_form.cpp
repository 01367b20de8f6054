// Closed-form truth for one impact: the post-impact state is the solution of a small linear
// system made of conservation laws plus the two contact conditions (restitution and the
// tangential condition). Written from first principles; see docs/closed-form.md.
//
// Unknowns. The unknowns are the post-impact velocities and spins. Every equation is linear in
// them, and every equation also holds trivially for "no impact" in the sense that its left side
// evaluated at the pre-impact state is known in closed form (0 for conservation laws, g_n or g_t
// for the contact conditions). So we write x' = x + u and solve for the change u: A x' = b is
// the same as A u = b - A x, with b - A x written analytically (no cancellation between large
// momenta of a heavy body and small ones of a light body).
#include "particles/truth/closed_form.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace particles::truth {
namespace {

using Real = long double;

template <std::size_t N>
using Matrix = std::array<std::array<Real, N>, N>;
template <std::size_t N>
using Vector = std::array<Real, N>;

/// Gaussian elimination with row equilibration and partial pivoting (scaled partial pivoting).
/// Rows are first divided by their largest coefficient so that a momentum row written in kg
/// (possibly 1e15 kg) competes fairly with a kinematic row written in plain numbers.
template <std::size_t N>
Vector<N> solveLinear(Matrix<N> A, Vector<N> rhs) {
  for (std::size_t i = 0; i < N; ++i) {
    Real scale = 0;
    for (std::size_t j = 0; j < N; ++j) scale = std::max(scale, std::fabs(A[i][j]));
    if (!(scale > 0)) throw std::runtime_error("truth::solveImpact: empty equation (bug)");
    for (std::size_t j = 0; j < N; ++j) A[i][j] /= scale;
    rhs[i] /= scale;
  }
  for (std::size_t k = 0; k < N; ++k) {
    std::size_t pivot = k;
    for (std::size_t i = k + 1; i < N; ++i) {
      if (std::fabs(A[i][k]) > std::fabs(A[pivot][k])) pivot = i;
    }
    // The systems are non-singular by construction (docs/closed-form.md); after equilibration a
    // pivot this small can only mean a bug or absurd inputs.
    if (std::fabs(A[pivot][k]) < 1e-30L) {
      throw std::runtime_error("truth::solveImpact: singular system");
    }
    std::swap(A[k], A[pivot]);
    std::swap(rhs[k], rhs[pivot]);
    for (std::size_t i = k + 1; i < N; ++i) {
      const Real f = A[i][k] / A[k][k];
      if (f == 0) continue;
      for (std::size_t j = k; j < N; ++j) A[i][j] -= f * A[k][j];
      rhs[i] -= f * rhs[k];
    }
  }
  Vector<N> x{};
  for (std::size_t k = N; k-- > 0;) {
    Real s = rhs[k];
    for (std::size_t j = k + 1; j < N; ++j) s -= A[k][j] * x[j];
    x[k] = s / A[k][k];
  }
  return x;
}

enum class Tangential { Smooth, Stick, Slide };

struct Frame {
  Real nx, ny, tx, ty;  // n and tau = z x n
};

/// Change (du) of the state of two discs. Unknowns u = (dvx_a, dvy_a, dw_a, dvx_b, dvy_b, dw_b).
Vector<6> solveTwoDiscs(const Body& a, const Body& b, const Frame& f, Real gn, Real gt, Real e,
                        Tangential mode, Real slideCoef /* s mu */) {
  const Real ma = a.mass, mb = b.mass, Ja = a.inertia, Jb = b.inertia;
  const Real ra = a.radius, rb = b.radius;
  Matrix<6> A{};
  Vector<6> r{};
  // (0, 1) Total linear momentum: m_a v_a + m_b v_b is conserved.
  A[0] = {ma, 0, 0, mb, 0, 0};
  A[1] = {0, ma, 0, 0, mb, 0};
  // (2) Angular momentum of a about c: L_a = J_a w_a + m_a (x_a - c) x v_a, x_a - c = -r_a n,
  //     (-r_a n) x v = -r_a (n_x v_y - n_y v_x) = -r_a (tau . v). The contact force acts at c.
  A[2] = {-ma * ra * f.tx, -ma * ra * f.ty, Ja, 0, 0, 0};
  // (3) Angular momentum of b about c: x_b - c = +r_b n, so L_b = J_b w_b + m_b r_b (tau . v_b).
  A[3] = {0, 0, 0, mb * rb * f.tx, mb * rb * f.ty, Jb};
  // (4) Restitution: g_n' = -e g_n, i.e. the change of g_n is -(1 + e) g_n.
  A[4] = {-f.nx, -f.ny, 0, f.nx, f.ny, 0};
  r[4] = -(1 + e) * gn;
  // (5) Tangential condition.
  switch (mode) {
    case Tangential::Stick:  // g_t' = 0: the change of g_t is -g_t.
      A[5] = {-f.tx, -f.ty, -ra, f.tx, f.ty, -rb};
      r[5] = -gt;
      break;
    case Tangential::Slide:  // tangential momentum change of b = s mu times its normal one.
      A[5] = {0, 0, 0, mb * (f.tx - slideCoef * f.nx), mb * (f.ty - slideCoef * f.ny), 0};
      break;
    case Tangential::Smooth:  // b's tangential momentum is unchanged.
      A[5] = {0, 0, 0, mb * f.tx, mb * f.ty, 0};
      break;
  }
  return solveLinear<6>(A, r);
}

/// Change of the state of disc a against a wall b. Unknowns u = (dvx_a, dvy_a, dw_a). The wall
/// takes any momentum, so total linear momentum gives no equation; the three that hold are
/// a's angular momentum about c, restitution and the tangential condition. (That a's momentum
/// change is along the impulse is then automatic: the impulse is defined as that change.)
Vector<3> solveDiscWall(const Body& a, const Frame& f, Real gn, Real gt, Real e, Tangential mode,
                        Real slideCoef) {
  const Real ma = a.mass, Ja = a.inertia, ra = a.radius;
  Matrix<3> A{};
  Vector<3> r{};
  A[0] = {-ma * ra * f.tx, -ma * ra * f.ty, Ja};  // angular momentum of a about c
  A[1] = {-f.nx, -f.ny, 0};                       // g_n = -v_a . n; change -(1 + e) g_n
  r[1] = -(1 + e) * gn;
  switch (mode) {
    case Tangential::Stick:  // g_t = -v_a . tau - w_a r_a; change -g_t
      A[2] = {-f.tx, -f.ty, -ra};
      r[2] = -gt;
      break;
    case Tangential::Slide:  // impulse on the wall P = -m_a dv_a; P.tau = s mu P.n
      A[2] = {-ma * (f.tx - slideCoef * f.nx), -ma * (f.ty - slideCoef * f.ny), 0};
      break;
    case Tangential::Smooth:  // P.tau = 0
      A[2] = {-ma * f.tx, -ma * f.ty, 0};
      break;
  }
  return solveLinear<3>(A, r);
}

struct Trial {
  Body a, b;
  Real jn = 0, jt = 0;
};

/// Solves with b a disc or a wall (a is never a wall here) and reads back the impulse on b.
Trial solve(const Body& a, const Body& b, const Frame& f, Real gn, Real gt, Real e, Tangential mode,
            Real slideCoef) {
  Trial t{a, b, 0, 0};
  // Impulse on b, P = -m_a dv_a = m_b dv_b (equal by momentum conservation). Read it from the
  // lighter body: its velocity change is the larger one, hence the better resolved.
  Real px = 0, py = 0;
  if (b.wall) {
    const Vector<3> u = solveDiscWall(a, f, gn, gt, e, mode, slideCoef);
    t.a.vx += u[0];
    t.a.vy += u[1];
    t.a.w += u[2];
    px = -a.mass * u[0];
    py = -a.mass * u[1];
  } else {
    const Vector<6> u = solveTwoDiscs(a, b, f, gn, gt, e, mode, slideCoef);
    t.a.vx += u[0];
    t.a.vy += u[1];
    t.a.w += u[2];
    t.b.vx += u[3];
    t.b.vy += u[4];
    t.b.w += u[5];
    if (a.mass <= b.mass) {
      px = -a.mass * u[0];
      py = -a.mass * u[1];
    } else {
      px = b.mass * u[3];
      py = b.mass * u[4];
    }
  }
  t.jn = px * f.nx + py * f.ny;
  t.jt = px * f.tx + py * f.ty;
  return t;
}

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("truth::solveImpact: ") + what);
}

void checkBody(const Body& body) {
  if (body.wall) return;
  require(std::isfinite(body.mass) && body.mass > 0, "mass must be finite and > 0");
  require(std::isfinite(body.inertia) && body.inertia > 0, "inertia must be finite and > 0");
  require(std::isfinite(body.radius) && body.radius >= 0, "radius must be finite and >= 0");
  require(std::isfinite(body.vx) && std::isfinite(body.vy) && std::isfinite(body.w),
          "velocity and spin must be finite");
}

}  // namespace

Impact solveImpact(const Body& a, const Body& b, long double nx, long double ny,
                   long double restitution, long double friction) {
  require(!(a.wall && b.wall), "two walls");
  checkBody(a);
  checkBody(b);
  require(std::isfinite(nx) && std::isfinite(ny), "normal must be finite");
  const Real len = std::sqrt(nx * nx + ny * ny);
  require(std::fabs(len - 1) <= 1e-6L, "normal must be a unit vector");
  require(restitution >= 0 && restitution <= 1, "restitution must be in [0, 1]");
  require(friction >= 0, "friction must be >= 0 (may be +infinity)");  // also rejects NaN

  if (a.wall) {
    // Swap roles: with a' = b, b' = a and n' = -n we get tau' = -tau, the same g_n and g_t, and
    // the impulse on b' is +(J_n n' + J_t tau') = -(J_n n + J_t tau): the same J_n and J_t.
    Impact swapped = solveImpact(b, a, -nx, -ny, restitution, friction);
    std::swap(swapped.a, swapped.b);
    return swapped;
  }

  Frame f{};
  f.nx = nx / len;
  f.ny = ny / len;
  f.tx = -f.ny;
  f.ty = f.nx;

  // Pre-impact relative velocities at the contact (a wall is at rest, w_b r_b = 0).
  const Real bvx = b.wall ? 0 : b.vx, bvy = b.wall ? 0 : b.vy;
  const Real bwr = b.wall ? 0 : b.w * b.radius;
  const Real dvx = bvx - a.vx, dvy = bvy - a.vy;
  const Real gn = dvx * f.nx + dvy * f.ny;
  const Real gt = dvx * f.tx + dvy * f.ty - bwr - a.w * a.radius;

  Impact out{a, b, Regime::Separating, 0, 0};
  if (!(gn < 0)) return out;  // not approaching: nothing happens

  const Real e = restitution, mu = friction;
  Trial t;
  if (mu == 0) {
    t = solve(a, b, f, gn, gt, e, Tangential::Smooth, 0);
    out.regime = Regime::Smooth;
  } else {
    // Try sticking first; keep it if its impulse is inside the Coulomb cone.
    t = solve(a, b, f, gn, gt, e, Tangential::Stick, 0);
    out.regime = Regime::Sticking;
    if (!std::isinf(mu) && std::fabs(t.jt) > mu * t.jn) {
      const Real s = gt > 0 ? -1 : 1;  // gt != 0 here, else sticking needed J_t = 0
      t = solve(a, b, f, gn, gt, e, Tangential::Slide, s * mu);
      out.regime = Regime::Sliding;
    }
  }
  out.a = t.a;
  out.b = t.b;
  out.normalImpulse = t.jn;
  out.tangentImpulse = t.jt;
  return out;
}

}  // namespace particles::truth
