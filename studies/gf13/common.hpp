#pragma once
// Shared helpers for the GF chapter 13 studies (double, and templated on S for the studies that run
// in the asked scalar): screw algebra in the book's conventions,
// random bodies and robots with fixed seeds, finite differences, the PUMA 560 with the inertias of
// studies/robots/puma560_dynamics.json, and "the printed formula fails" checks.
#include "soma/studies/scalar_draws.hpp"
#include "soma/geometry/dynamics/joint_integrators.hpp"
#include "soma/geometry/dynamics/robot_dynamics.hpp"
#include "soma/geometry/dynamics/serial_dynamics.hpp"
#include "soma/geometry/dynamics/spatial_inertia.hpp"
#include "soma/io/link_inertia_file.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <filesystem>
#include <random>

namespace soma::studies::gf13 {

inline constexpr const char* kChapter = "GF 13 — Dynamics";
using V3 = Vec3<double>;
using V6 = Vec6<double>;
using M3 = Mat3<double>;
using M6 = Mat6<double>;
using DV = DynVector<double>;
using DM = DynMatrix<double>;
using Q = __float128;
using std::abs;

inline double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
inline V3 rv3(std::mt19937_64& g, double lo = -1, double hi = 1) { return V3(uni(g, lo, hi), uni(g, lo, hi), uni(g, lo, hi)); }
inline V6 rv6(std::mt19937_64& g) {
  V6 v;
  for (int i = 0; i < 6; ++i) v(i) = uni(g);
  return v;
}
inline V3 unit3(std::mt19937_64& g) {
  V3 v;
  do v = rv3(g);
  while (v.squaredNorm() < 1e-2 || v.squaredNorm() > 1);
  return v.normalized();
}
inline M3 hat(const V3& v) { return skew(v); }
/// ad(s) = [[Ω, 0], [V, Ω]] and [a, b] = ad(a) b (GF §13.1 conventions).
inline M6 adm(const V6& s) { return SE3Tangent<double>(s).ad(); }
inline V6 br(const V6& a, const V6& b) { return adm(a) * b; }
/// {s, P} = −ad(s)ᵀ P
inline V6 coad(const V6& s, const V6& P) { return -adm(s).transpose() * P; }
inline M6 q0() {
  M6 Q0 = M6::Zero();
  Q0.topRightCorner<3, 3>().setIdentity();
  Q0.bottomLeftCorner<3, 3>().setIdentity();
  return Q0;
}
inline V6 lineScrew(const V3& w, const V3& r, double pitch = 0) {
  V6 s;
  s << w, r.cross(w) + pitch * w;
  return s;
}
inline SpatialInertia<double> randomBody(std::mt19937_64& g, double comRange = 1) {
  const V3 d = rv3(g, 0.05, 0.5);
  const M3 R = SO3<double>::Random(g).matrix();
  M3 I = R * V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose();
  I = (I + I.transpose()) / 2;
  return SpatialInertia<double>(uni(g, 0.5, 3), rv3(g, -comRange, comRange), I);
}

/// A random n-joint robot (revolute axes through random points; `prismaticJoint` ≥ 0 makes that
/// joint a slide), random links, g = 9.81 unless given.
inline SerialDynamics<double> randomRobot(std::mt19937_64& g, int n, int prismaticJoint = -1, double grav = 9.81) {
  std::vector<SE3Tangent<double>> s;
  std::vector<SpatialInertia<double>> l;
  for (int i = 0; i < n; ++i) {
    const V3 w = unit3(g);
    V6 x;
    if (i == prismaticJoint)
      x << 0, 0, 0, w;
    else
      x = lineScrew(w, rv3(g));
    s.emplace_back(x);
    l.push_back(randomBody(g));
  }
  return SerialDynamics<double>(s, l, grav);
}
template <class S> SerialDynamics<S> castRobot(const SerialDynamics<double>& r) {
  std::vector<SE3Tangent<S>> s;
  std::vector<SpatialInertia<S>> l;
  for (int i = 0; i < r.dof(); ++i) {
    s.emplace_back(castMatrix<S>(r.homeScrews()[std::size_t(i)].coeffs()));
    const SpatialInertia<double>& b = r.homeLinks()[std::size_t(i)];
    const Mat3<S> I = castMatrix<S>(b.inertiaAboutCentre());
    l.emplace_back(scalarCast<S>(b.mass()), castMatrix<S>(b.centreOfMass()), Mat3<S>((I + I.transpose()) / S(2)));
  }
  return SerialDynamics<S>(s, l, scalarCast<S>(r.gravity()));
}
/// A robot drawn in double (randomRobot) and cast to S with its joint screws made unit in S: a
/// revolute axis ω/|ω| with v less its ω component (pitch 0), a slide v/|v|. castRobot keeps the
/// double's |ω| = 1 ± 1e-16, which mpfr rejects (Tolerance::input) and which turns θ + 200π into a
/// rotation that differs by 200π·1e-16.
template <class S, class T = double> SerialDynamics<S> castRobotUnit(const SerialDynamics<T>& r) {
  // std's sqrt by name: __float128 is a builtin type (no argument-dependent lookup), so an
  // unqualified sqrt finds only the C library's ::sqrt(double) and normalises to double's 1e-16
  using std::sqrt;
  std::vector<SE3Tangent<S>> s;
  std::vector<SpatialInertia<S>> l;
  for (int i = 0; i < r.dof(); ++i) {
    const SE3Tangent<T>& x = r.homeScrews()[std::size_t(i)];
    Vec3<S> w = castMatrix<S>(Vec3<T>(x.ang())), v = castMatrix<S>(Vec3<T>(x.lin()));
    if (w.squaredNorm() > S(0)) {
      w /= sqrt(w.squaredNorm());
      v -= w.dot(v) * w;
    } else {
      v /= sqrt(v.squaredNorm());
    }
    s.emplace_back(w, v);
    const SpatialInertia<T>& b = r.homeLinks()[std::size_t(i)];
    const Mat3<S> I = castMatrix<S>(Mat3<T>(b.inertiaAboutCentre()));
    l.emplace_back(scalarCast<S>(b.mass()), castMatrix<S>(b.centreOfMass()), Mat3<S>((I + I.transpose()) / S(2)));
  }
  return SerialDynamics<S>(s, l, scalarCast<S>(r.gravity()));
}
inline DV rjoints(std::mt19937_64& g, int n, double lo = -1.5, double hi = 1.5) {
  DV v(n);
  for (int i = 0; i < n; ++i) v(i) = uni(g, lo, hi);
  return v;
}
template <class To, class From> DynVector<To> castV(const DynVector<From>& v) {
  DynVector<To> o(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) o(i) = scalarCast<To>(v(i));
  return o;
}
/// f'(0), 8th-order central differences (error d⁸ |f⁽⁹⁾|/630 + 2.3 ε |f| / d).
template <class S, class F> S diff8(F&& f, const S& d) {
  const S c[4] = {S(4) / S(5), S(-1) / S(5), S(4) / S(105), S(-1) / S(280)};
  S r = S(0);
  for (int k = 1; k <= 4; ++k) r += c[k - 1] * (f(S(k) * d) - f(S(-k) * d));
  return r / d;
}
/// f'(0) in __float128 with d = 2⁻⁸: accurate to ~1e-20 relative for the smooth functions here.
template <class F> double dq(F&& f) { return double(diff8<Q>(f, Q(1) / Q(256))); }
/// Matrix-valued central difference (4th order, double) with step d.
template <class F> auto dmat(F&& f, double d = 1e-3) {
  using R = std::decay_t<decltype(f(d))>;  // evaluate: no Eigen expression may outlive the temporaries
  return R(((f(-2 * d) - f(2 * d)) / 12 + (f(d) - f(-d)) * (2.0 / 3.0)) / d);
}

inline double maxAbs(const DV& v) { return v.cwiseAbs().maxCoeff(); }
inline double maxAbs(const DM& v) { return v.cwiseAbs().maxCoeff(); }

// ---- The same helpers templated on the working scalar S (the studies that run in the asked scalar):
// draws in double cast to S (the same inputs on every rung of the ladder).
using draws::frac;
using draws::maxOf;
using draws::rv3;
using draws::rv6;
using draws::uni;  // soma/studies/scalar_draws.hpp
template <class S> Mat6<S> adm(const Vec6<S>& s) { return SE3Tangent<S>(s).ad(); }
template <class S> Vec6<S> br(const Vec6<S>& a, const Vec6<S>& b) { return adm(a) * b; }
template <class S> Vec6<S> coad(const Vec6<S>& s, const Vec6<S>& P) { return -adm(s).transpose() * P; }
template <class S> Mat6<S> q0() {
  Mat6<S> Q0 = Mat6<S>::Zero();
  Q0.template topRightCorner<3, 3>().setIdentity();
  Q0.template bottomLeftCorner<3, 3>().setIdentity();
  return Q0;
}
template <class S> Vec6<S> lineScrew(const Vec3<S>& w, const Vec3<S>& r, const S& pitch) {
  Vec6<S> s;
  s << w, r.cross(w) + pitch * w;
  return s;
}
/// A body drawn in double (randomBody) and cast to S, its inertia symmetrised in S.
template <class S> SpatialInertia<S> castBody(const SpatialInertia<double>& b) {
  const Mat3<S> I = castMatrix<S>(b.inertiaAboutCentre());
  return SpatialInertia<S>(scalarCast<S>(b.mass()), castMatrix<S>(b.centreOfMass()), Mat3<S>((I + I.transpose()) / S(2)));
}
template <class D> typename D::Scalar maxAbsOf(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }
/// Joint values drawn in double (rjoints) and cast to S.
template <class S> DynVector<S> rjointsS(std::mt19937_64& g, int n, double lo = -1.5, double hi = 1.5) {
  const DynVector<double> v = rjoints(g, n, lo, hi);
  DynVector<S> o(n);
  for (int i = 0; i < n; ++i) o(i) = scalarCast<S>(v(i));
  return o;
}
template <class S> S tol(int ulps = 64) { return Tolerance<S>::identity(ulps); }

// Reference derivatives of a study in S: in __float128 for the scalars narrower than it (8th-order
// central differences at d = 2⁻⁸: truncation d⁸|f⁽⁹⁾|/630 ≈ 1e-22|f⁽⁹⁾|, rounding 2.3 ε_q|f|/d ≈
// 1e-31|f|, both below long double's ε), in S itself for __float128 and mpfr at d = ε^(1/9) (rounding
// 2.3 ε|f|/d and truncation d⁸|f⁽⁹⁾|/630 both ≈ ε^(8/9)); refTol<S>() is that bound with the constant
// 4096 for |f| and |f⁽⁹⁾| of the O(1) random states (0 below __float128). As gf14/trees.cpp.
template <class S>
inline constexpr bool kWideRef = std::is_same_v<S, float> || std::is_same_v<S, double> || std::is_same_v<S, long double>;
template <class S> using Ref = std::conditional_t<kWideRef<S>, Q, S>;
template <class S> Ref<S> refStep() {
  if constexpr (kWideRef<S>)
    return Q(1) / Q(256);
  else
    return Tolerance<S>::precision(8);
}
template <class S> S refTol() {
  if constexpr (kWideRef<S>) {
    return S(0);
  } else {
    using std::pow;
    return S(4096) * pow(Tolerance<S>::epsilon(), S(8) / S(9));
  }
}
template <class S> const char* refHow() { return kWideRef<S> ? "differences in __float128" : "differences in S at d = ε^(1/9)"; }
/// f'(0) for f: Ref<S> → Ref<S>, as S (diff8 in Ref<S> at refStep).
template <class S, class F> S refDiff(F&& f) { return scalarCast<S>(diff8<Ref<S>>(f, refStep<S>())); }
/// The same for a vector- or matrix-valued f, as the matrix in S.
template <class S, class F> auto refDiffM(F&& f) {
  using R = Ref<S>;
  const R d = refStep<S>();
  using M = std::decay_t<decltype(f(d))>;  // evaluated: no Eigen expression outlives its temporaries
  const R c[4] = {R(4) / R(5), R(-1) / R(5), R(4) / R(105), R(-1) / R(280)};
  M r = M(f(d) - f(R(-1) * d)) * c[0];
  for (int k = 2; k <= 4; ++k) r += M(M(f(R(k) * d)) - M(f(R(-k) * d))) * c[k - 1];
  return castMatrix<S>(M(r / d));
}

/// The PUMA 560 (standard DH) with the Armstrong–Khatib–Burdick inertias of puma560_dynamics.json.
inline std::filesystem::path robotsDir() {
  return sourceRoot() / "studies" / "robots";
}
inline std::vector<SpatialInertia<double>> pumaLinks() { return io::readLinkInertias(robotsDir() / "puma560_dynamics.json"); }
inline SerialDynamics<double> puma(double grav = 9.81) { return serialDynamicsOf(puma560Robot<double>(), pumaLinks(), grav); }
/// The same PUMA in S (the inertias read in double and cast), g = 9.81 m/s² as S rounds 981/100.
template <class S> SerialDynamics<S> pumaIn() {
  std::vector<SpatialInertia<S>> links;
  for (const auto& b : pumaLinks()) links.push_back(castBody<S>(b));
  return serialDynamicsOf(puma560Robot<S>(), links, S(981) / S(100));
}

}  // namespace soma::studies::gf13
