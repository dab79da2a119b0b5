// Cusp points of a 3R arm from the triple-root condition of its IK equation (see cusps.hpp for
// the derivation). Instantiated for one scalar (soma_instantiate).
#pragma once
#include "soma/geometry/cuspidal/cusps.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/polynomial.hpp"
#include "soma/algebra/wrap_angle.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace soma {

namespace {

/// A trigonometric polynomial of degree n in φ as the numerator N(t) (degree 2n) of
/// N(t) / (1 + t²)^n, t = tan(φ/2): cos φ = (1 − t²)/(1 + t²), sin φ = 2t/(1 + t²).
template <class S> struct TrigPoly {
  int n = 0;
  std::vector<S> c{S(0)};
};

template <class S> TrigPoly<S> tpConst(const S& k) { return {0, {k}}; }
/// k0 + k1 cos φ + k2 sin φ.
template <class S> TrigPoly<S> tpLinear(const S& k0, const S& k1, const S& k2) {
  return {1, {k0 + k1, S(2) * k2, k0 - k1}};
}
template <class S> TrigPoly<S> tpRaise(const TrigPoly<S>& p, int m) {
  TrigPoly<S> r = p;
  while (r.n < m) {  // multiply by 1 + t²
    std::vector<S> c(r.c.size() + 2, S(0));
    for (std::size_t i = 0; i < r.c.size(); ++i) {
      c[i] += r.c[i];
      c[i + 2] += r.c[i];
    }
    r.c = std::move(c);
    ++r.n;
  }
  return r;
}
template <class S> TrigPoly<S> operator*(const TrigPoly<S>& p, const TrigPoly<S>& q) {
  TrigPoly<S> r;
  r.n = p.n + q.n;
  r.c.assign(p.c.size() + q.c.size() - 1, S(0));
  for (std::size_t i = 0; i < p.c.size(); ++i)
    for (std::size_t j = 0; j < q.c.size(); ++j) r.c[i + j] += p.c[i] * q.c[j];
  return r;
}
template <class S> TrigPoly<S> operator*(const S& k, TrigPoly<S> p) {
  for (auto& x : p.c) x *= k;
  return p;
}
template <class S> TrigPoly<S> operator+(const TrigPoly<S>& p, const TrigPoly<S>& q) {
  const int m = std::max(p.n, q.n);
  TrigPoly<S> a = tpRaise(p, m), b = tpRaise(q, m);
  for (std::size_t i = 0; i < a.c.size(); ++i) a.c[i] += b.c[i];
  return a;
}
template <class S> TrigPoly<S> operator-(const TrigPoly<S>& p, const TrigPoly<S>& q) {
  return p + (S(-1) * q);
}

/// The scaled quantities of the triple-root elimination at one φ (cusps.hpp): values and
/// φ-derivatives of U = X + W − Q − a1² and T = Y + V, and Q = ρ², X, Y.
template <class S> struct CuspTerms {
  S U, dU, T, dT, Q, X, Y;
};

template <class S> struct Scaled {
  S a1, s1, c1, a, b, E;
  Vec3<S> W, V;  // rotated by the phase

  CuspTerms<S> at(const S& phi) const {
    using std::cos;
    using std::sin;
    const S cs = cos(phi), sn = sin(phi);
    const S w = W(0) + W(1) * cs + W(2) * sn, v = V(0) + V(1) * cs + V(2) * sn;
    const S w1 = -W(1) * sn + W(2) * cs, v1 = -V(1) * sn + V(2) * cs;  // first derivatives
    const S w2 = -(w - W(0)), v2 = -(v - V(0));                        // second derivatives
    const S K = a * w1 * w1 + b * v1 * v1, dK = S(2) * (a * w1 * w2 + b * v1 * v2);
    const S X = -v1 * K / (a * E), dX = -(v2 * K + v1 * dK) / (a * E);
    const S Y = w1 * K / (b * E), dY = (w2 * K + w1 * dK) / (b * E);
    const S den = a * a * b * b * E * E;
    const S Q = K * K * K / den, dQ = S(3) * K * K * dK / den;
    return {X + w - Q - a1 * a1, dX + w1 - dQ, Y + v, dY + v1, Q, X, Y};
  }
  /// G(φ) = c1²·(a²b²E²)·U − (a b E)²·T² (the polynomial's value, up to (1 + t²)^6).
  S g(const S& phi) const {
    const CuspTerms<S> t = at(phi);
    const S abE = a * b * E;
    return abE * abE * (c1 * c1 * t.U - t.T * t.T);
  }
};

}  // namespace

template <class S> Arm3RFrame<S> arm3RFrame(const SerialRobot<S>& robot) {
  using std::abs;
  using std::sqrt;
  if (robot.dof() != 3)
    throw InvalidInput("cuspidal: robot '" + robot.name() + "' has " + std::to_string(robot.dof()) +
                       " joints; a 3R positioning arm needs exactly 3 revolute joints");
  for (int i = 0; i < 3; ++i)
    if (robot.joints()[i].type != JointType::Revolute)
      throw InvalidInput("cuspidal: joint " + std::to_string(i + 1) + " of robot '" + robot.name() +
                         "' is prismatic; a 3R positioning arm needs 3 revolute joints");
  const auto& J = robot.joints();
  Arm3RFrame<S> f;
  f.scale = robot.lengthScale();
  const S L = f.scale;
  const Vec3<S> v1 = J[0].axis, r1 = J[0].point, v2 = J[1].axis, q2 = J[1].point;
  const Vec3<S> v3 = J[2].axis, r3 = J[2].point;
  f.ez = v1;
  f.v2 = v2;
  f.p0 = robot.home().translation();
  const Vec3<S> n = v1.cross(v2);
  const S sn = sqrt(n.squaredNorm());
  f.s1 = sn;
  f.c1 = v1.dot(v2);
  if (sn > Tolerance<S>::rank()) {
    f.ex = n / sn;
    // Feet of the common normal: O1 = r1 + t1 v1, r2 = q2 + t2 v2.
    const Vec3<S> w = r1 - q2;
    const S bb = f.c1, d = v1.dot(w), e = v2.dot(w), den = sn * sn;
    const S t1 = (bb * e - d) / den;
    f.o1 = r1 + v1 * t1;
    f.a1 = f.ex.dot(q2 - r1);
  } else {
    f.o1 = r1 + v1 * v1.dot(q2 - r1);
    const Vec3<S> perp = q2 - f.o1;
    const S pn = sqrt(perp.squaredNorm());
    f.a1 = pn;
    // Any unit vector ⟂ v1 when the axes coincide.
    Vec3<S> ref = abs(v1(0)) < S(0.9) ? Vec3<S>::UnitX() : Vec3<S>::UnitY();
    f.ex = pn > S(0) ? Vec3<S>(perp / pn) : Vec3<S>((ref - v1 * v1.dot(ref)).normalized());
  }
  f.ey = f.ez.cross(f.ex);
  f.r2 = f.o1 + f.ex * f.a1;
  const Vec3<S> o = robot.base().translation();
  f.c = r1 + v1 * v1.dot(o - r1);
  f.z0 = v1.dot(f.o1 - f.c);
  // The tool point on its circle about axis 3: a(φ) = c0 + cc cos φ + cs sin φ.
  const Vec3<S> u = f.p0 - r3, vvu = v3 * v3.dot(u);
  const Vec3<S> c0 = r3 + vvu, cc = u - vvu, cs = v3.cross(u);
  const Vec3<S> d0 = c0 - f.r2;
  f.W = Vec3<S>(d0.squaredNorm() + cc.squaredNorm(), S(2) * d0.dot(cc), S(2) * d0.dot(cs));
  f.V = Vec3<S>(v2.dot(d0), v2.dot(cc), v2.dot(cs));
  f.E = f.W(1) * f.V(2) - f.W(2) * f.V(1);
  // Decoupled cases: the IK equation factors into quadratics (no triple root).
  if (abs(f.a1) <= Tolerance<S>::rank() * L) {
    f.decoupled = true;
    f.reason = "axes 1 and 2 meet";
  } else if (f.s1 <= Tolerance<S>::rank()) {
    f.decoupled = true;
    f.reason = "axes 1 and 2 are parallel";
  } else if (abs(f.E) <= Tolerance<S>::rank() * L * L * L) {
    f.decoupled = true;
    f.reason = "axes 2 and 3 meet or are parallel, or the tool point lies on axis 3";
  }
  return f;
}

template <class S>
Vec2<S> workspaceSection(const Arm3RFrame<S>& f, const SerialRobot<S>& robot, const JointVector<S>& q) {
  using std::sqrt;
  const Vec3<S> d = robot.fk(q).translation() - f.c;
  const S z = f.ez.dot(d);
  const Vec3<S> perp = d - f.ez * z;
  return Vec2<S>(sqrt(perp.squaredNorm()), z);
}

template <class S> Vec3<S> ikFunction(const Arm3RFrame<S>& f, const S& rho, const S& z, const S& phi) {
  using std::cos;
  using std::sin;
  const S cs = cos(phi), sn = sin(phi);
  const S w = f.W(0) + f.W(1) * cs + f.W(2) * sn, v = f.V(0) + f.V(1) * cs + f.V(2) * sn;
  const S w1 = -f.W(1) * sn + f.W(2) * cs, v1 = -f.V(1) * sn + f.V(2) * cs;
  const S w2 = -(w - f.W(0)), v2 = -(v - f.V(0));
  const S zp = z - f.z0;
  const S X = rho * rho + zp * zp + f.a1 * f.a1 - w, Y = f.c1 * zp - v;
  const S a = f.s1 * f.s1, b = S(4) * f.a1 * f.a1;
  return Vec3<S>(a * X * X + b * Y * Y - a * b * rho * rho, S(-2) * (a * X * w1 + b * Y * v1),
                 S(2) * (a * (w1 * w1 - X * w2) + b * (v1 * v1 - Y * v2)));
}

// GF §5.2.3, GF-5.2.3-cuspidal-posture-change (triple root of the IK quartic, GF-5.2.1-3r-ik-procedure)
template <class S> CuspAnalysis<S> findCusps(const SerialRobot<S>& robot) {
  using std::abs;
  using std::atan;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const auto t0 = std::chrono::steady_clock::now();
  CuspAnalysis<S> out;
  out.frame = arm3RFrame(robot);
  const Arm3RFrame<S>& f = out.frame;
  auto done = [&]() {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (f.decoupled) return done();
  const S L = f.scale;
  Scaled<S> sc;
  sc.a1 = f.a1 / L;
  sc.s1 = f.s1;
  sc.c1 = f.c1;
  sc.a = f.s1 * f.s1;
  sc.b = S(4) * sc.a1 * sc.a1;
  sc.E = f.E / (L * L * L);
  sc.W = Vec3<S>(f.W(0) / (L * L), f.W(1) / (L * L), f.W(2) / (L * L));
  sc.V = f.V / L;
  // Phase φ0: t = tan((φ − φ0)/2) puts φ = φ0 + π at t = ∞; pick φ0 where |G(φ0 + π)| is largest
  // among 16 directions, so no root sits near infinity (the leading coefficient is G(φ0 + π)).
  S phase = S(0), best = S(-1);
  for (int j = 0; j < 16; ++j) {
    const S ph = S(2) * pi<S>() * S(j) / S(16);
    const S val = abs(sc.g(ph + pi<S>()));
    if (val > best) {
      best = val;
      phase = ph;
    }
  }
  out.phase = phase;
  Scaled<S> rot = sc;  // coefficients in ψ = φ − φ0
  const S cp = cos(phase), sp = sin(phase);
  rot.W = Vec3<S>(sc.W(0), sc.W(1) * cp + sc.W(2) * sp, sc.W(2) * cp - sc.W(1) * sp);
  rot.V = Vec3<S>(sc.V(0), sc.V(1) * cp + sc.V(2) * sp, sc.V(2) * cp - sc.V(1) * sp);
  {
    const S a = rot.a, b = rot.b, E = rot.E;
    const TrigPoly<S> W = tpLinear(rot.W(0), rot.W(1), rot.W(2)), V = tpLinear(rot.V(0), rot.V(1), rot.V(2));
    const TrigPoly<S> Wp = tpLinear(S(0), rot.W(2), S(-rot.W(1))), Vp = tpLinear(S(0), rot.V(2), S(-rot.V(1)));
    const TrigPoly<S> K = a * (Wp * Wp) + b * (Vp * Vp);
    const TrigPoly<S> inner = S(-a * b * b * E) * (Vp * K) + S(a * a * b * b * E * E) * (W - tpConst(rot.a1 * rot.a1)) -
                              K * K * K;
    const TrigPoly<S> T = Wp * K + S(b * E) * V;
    const TrigPoly<S> G = S(rot.c1 * rot.c1) * inner - S(a * a) * (T * T);
    out.polynomial = tpRaise(G, 6).c;
  }
  // Newton seeds: the real parts of ALL roots of G (for a1 or s1 near 0 the cusps sit in a cluster
  // of nearly multiple roots that round-off turns complex), and 16 angles as a safety net; the
  // 2-D Newton below converges only onto genuine (real) solutions.
  std::vector<S> cand;
  for (const auto& r : polynomialRoots<S>(out.polynomial)) {
    const S re = r.real();
    if (abs(r.imag()) <= Tolerance<S>::input() * std::max<S>(S(1), abs(re))) ++out.candidates;
    cand.push_back(phase + S(2) * atan(re));
  }
  for (int j = 0; j < 16; ++j) cand.push_back(S(2) * pi<S>() * S(j) / S(16));
  // Newton on (φ, u), u = z′/L: F1 = u² − U(φ), F2 = c1 u − T(φ). Its Jacobian stays regular at a
  // simple cusp even when c1 = 0 (orthogonal axes 1, 2), where the roots of G are double.
  struct Sol {
    S phi, u;
  };
  std::vector<Sol> sols;
  for (const S& phi0 : cand) {
    const CuspTerms<S> t0c = sc.at(phi0);
    std::vector<S> us;
    const S r = sqrt(std::max<S>(t0c.U, S(0)));
    us.push_back(r);
    us.push_back(-r);
    if (abs(sc.c1) > Tolerance<S>::sqrtEpsilon()) us.push_back(t0c.T / sc.c1);
    for (S u : us) {
      S phi = phi0;
      bool ok = false;
      for (int it = 0; it < 60; ++it) {
        const CuspTerms<S> t = sc.at(phi);
        const S F1 = u * u - t.U, F2 = sc.c1 * u - t.T;
        const S j11 = -t.dU, j12 = S(2) * u, j21 = -t.dT, j22 = sc.c1;
        const S det = j11 * j22 - j12 * j21;
        if (det == S(0)) break;
        const S dphi = (F1 * j22 - F2 * j12) / det, du = (j11 * F2 - j21 * F1) / det;
        phi -= dphi;
        u -= du;
        if (abs(dphi) + abs(du) <= Tolerance<S>::identity() * (S(1) + abs(u))) {
          ok = true;
          break;
        }
      }
      if (!ok) {  // accept a stalled iteration only if it sits on the solution to round-off (a looser
                  // √eps here let near-misses at a merging pair of cusps through: 2–25 spurious cusps at z ≈ 0)
        const CuspTerms<S> t = sc.at(phi);
        const S res = abs(u * u - t.U) + abs(sc.c1 * u - t.T);
        const S scl = S(1) + abs(t.U) + abs(t.T);
        ok = res <= Tolerance<S>::identity(4096) * scl;
      }
      if (!ok) continue;
      phi = wrapAngle(phi);
      bool known = false;
      for (const auto& s : sols)
        known = known || (abs(wrapAngle(S(s.phi - phi))) <= Tolerance<S>::input() &&
                          abs(s.u - u) <= Tolerance<S>::input() * (S(1) + abs(u)));
      if (!known) sols.push_back({phi, u});
    }
  }
  const auto& J = robot.joints();
  for (const auto& s : sols) {
    const CuspTerms<S> t = sc.at(s.phi);
    if (!(t.Q > S(0))) continue;
    const S rhon = sqrt(t.Q);
    // cos ψ = X/(2 a1 ρ), sin ψ = Y/(s1 ρ)
    const S psi = atan2(t.Y / sc.s1, t.X / (S(2) * sc.a1));
    CuspPoint<S> c;
    c.rho = rhon * L;
    c.z = s.u * L + f.z0;
    const Vec3<S> b = f.o1 + L * (rhon * cos(psi) * f.ex + rhon * sin(psi) * f.ey + s.u * f.ez);
    // a(φ3): the home tool point turned about axis 3; φ2 turns a into b about axis 2.
    const Vec3<S> v3 = J[2].axis, r3 = J[2].point;
    const Vec3<S> uu = f.p0 - r3, vvu = v3 * v3.dot(uu);
    const Vec3<S> a = r3 + vvu + (uu - vvu) * cos(s.phi) + v3.cross(uu) * sin(s.phi);
    const Vec3<S> ap = (a - f.r2) - f.v2 * f.v2.dot(a - f.r2), bp = (b - f.r2) - f.v2 * f.v2.dot(b - f.r2);
    const S phi2 = atan2(f.v2.dot(ap.cross(bp)), ap.dot(bp));
    JointVector<S> q(3);
    q << -J[0].offset, wrapAngle(S(phi2 - J[1].offset)), wrapAngle(S(s.phi - J[2].offset));
    c.posture = q;
    c.residual = sqrt((robot.fk(q).translation() - b).squaredNorm()) / L;
    out.cusps.push_back(c);
  }
  std::sort(out.cusps.begin(), out.cusps.end(), [](const CuspPoint<S>& x, const CuspPoint<S>& y) {
    return x.z < y.z || (x.z == y.z && x.rho < y.rho);
  });
  return done();
}

#define SOMA_INSTANTIATE_CUSPS(S)                                                               \
  template Arm3RFrame<S> arm3RFrame<S>(const SerialRobot<S>&);                                 \
  template Vec2<S> workspaceSection<S>(const Arm3RFrame<S>&, const SerialRobot<S>&,            \
                                       const JointVector<S>&);                                 \
  template CuspAnalysis<S> findCusps<S>(const SerialRobot<S>&);                                \
  template Vec3<S> ikFunction<S>(const Arm3RFrame<S>&, const S&, const S&, const S&);

}  // namespace soma
