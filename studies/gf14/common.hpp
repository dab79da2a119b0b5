#pragma once
// Shared helpers for the GF chapter 14 studies (draws in double, cast to the study's scalar; __float128
// for reference differences):
// random trees, finite differences, "the printed formula fails" records, the example mechanisms.
#include "soma/geometry/dynamics/biped_dynamics.hpp"
#include "soma/geometry/dynamics/constrained_tree.hpp"
#include "soma/geometry/dynamics/fourbar_dynamics.hpp"
#include "soma/geometry/dynamics/holonomic_constraints.hpp"
#include "soma/geometry/dynamics/stewart_dynamics.hpp"
#include "soma/geometry/dynamics/tree_dynamics.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <random>

namespace soma::studies::gf14 {

inline constexpr const char* kChapter = "GF 14 — Constrained dynamics";
using V3 = Vec3<double>;
using V6 = Vec6<double>;
using M6 = Mat6<double>;
using DV = DynVector<double>;
using DM = DynMatrix<double>;
using Q = __float128;

using draws::frac;
using draws::maxOf;
using draws::rv3;
using draws::uni;  // soma/studies/scalar_draws.hpp
inline V3 unit3(std::mt19937_64& g) {
  V3 v;
  do v = rv3<double>(g);
  while (v.squaredNorm() < 1e-2 || v.squaredNorm() > 1);
  return v.normalized();
}
inline DV rvec(std::mt19937_64& g, int n, double r = 1.5) {
  DV v(n);
  for (int i = 0; i < n; ++i) v(i) = uni<double>(g, -r, r);
  return v;
}
/// randomBody's draws (mass, centre, principal moments, axes) with the body built in S: its 6×6 matrix
/// symmetrised in S (a double matrix cast to a wider S is symmetric only to double's rounding).
template <class S> Mat6<S> randomBodyMatrix(std::mt19937_64& g) {
  const V3 d = rv3<double>(g, 0.05, 0.5);
  const Mat3<S> R = castMatrix<S>(Mat3<double>(SO3<double>::Random(g).matrix()));
  const double m = uni<double>(g, 0.5, 3);
  const V3 c = rv3<double>(g);
  const Mat3<S> I = R * Vec3<S>(castMatrix<S>(V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)))).asDiagonal() * R.transpose();
  const Mat6<S> n = SpatialInertia<S>(S(m), castMatrix<S>(c), I).matrix();
  return Mat6<S>((n + n.transpose()) / S(2));
}
/// A random tree with the given parents: revolute joints on random lines, random bodies, g along −z.
template <class S = double> TreeDynamics<S> randomTree(std::mt19937_64& g, const std::vector<int>& parent, const S& grav = frac<S>(981, 100)) {
  std::vector<Vec6<S>> s;
  std::vector<Mat6<S>> N;
  for (std::size_t i = 0; i < parent.size(); ++i) {
    const V3 w = unit3(g), p = rv3<double>(g);
    V6 x;
    x << w, p.cross(w);
    Vec6<S> xs = castMatrix<S>(x);
    using std::sqrt;
    xs /= S(sqrt(S(xs.template head<3>().squaredNorm())));
    s.push_back(xs);
    N.push_back(randomBodyMatrix<S>(g));
  }
  return TreeDynamics<S>(TreeTopology(parent), s, N, Vec3<S>(S(0), S(0), S(-grav)));
}
template <class S, class T> TreeDynamics<S> castTree(const TreeDynamics<T>& t) {
  std::vector<Vec6<S>> s;
  std::vector<Mat6<S>> N;
  for (int i = 0; i < t.dof(); ++i) {
    Vec6<S> x = castMatrix<S>(t.homeScrews()[std::size_t(i)]);
    using std::sqrt;
    x /= S(sqrt(S(x.template head<3>().squaredNorm())));
    s.push_back(x);
    N.push_back(castMatrix<S>(t.homeInertias()[std::size_t(i)]));
  }
  return TreeDynamics<S>(t.topology(), s, N, castMatrix<S>(t.gravity()));
}
/// 8th-order central difference of f at 0 with step d.
template <class S, class F> S diff8(F&& f, const S& d) {
  const S c[4] = {S(4) / S(5), S(-1) / S(5), S(4) / S(105), S(-1) / S(280)};
  S r = S(0);
  for (int k = 1; k <= 4; ++k) r += c[k - 1] * (f(S(k) * d) - f(S(-k) * d));
  return r / d;
}

/// The invented Grashof crank–rocker of checks/fourbar_check.py: d = (1, 2.2, 1.8, 2.5), in S from exact fractions.
template <class S = double> FourBarDynamics<S> crankRocker(const S& d2 = frac<S>(22, 10)) {
  return FourBarDynamics<S>(S(1), d2, frac<S>(18, 10), frac<S>(25, 10),
                            {PlanarLink<S>{S(1), frac<S>(1, 2), frac<S>(1, 10), frac<S>(1, 10)},
                             PlanarLink<S>{S(2), S(1), frac<S>(-2, 10), frac<S>(8, 10)},
                             PlanarLink<S>{frac<S>(3, 2), frac<S>(9, 10), frac<S>(15, 100), frac<S>(45, 100)}});
}
template <class S = double> BipedParameters<S> bipedParameters() {
  return {S(10), frac<S>(3, 10), frac<S>(1, 2), frac<S>(45, 100), S(4), frac<S>(7, 100), frac<S>(45, 100), S(3), frac<S>(5, 100), frac<S>(981, 100)};
}
template <class S = double> BipedPose<S> bipedHome() {
  using V2 = Eigen::Matrix<S, 2, 1>;
  return {V2(S(0), frac<S>(3, 4)), V2(frac<S>(1, 5), S(0)), V2(frac<S>(-1, 5), S(0)), S(0)};
}
/// A 6-6 Stewart platform (base radius 1, platform radius 0.5, legs 1 m high) with massive or massless legs;
/// joint angles 120k ± 12° and 120k + 60 ∓ 15° evaluated in S.
template <class S = double> StewartDynamics<S> stewartExample(bool masslessLegs) {
  std::array<Vec3<S>, 6> base, plat, paired;
  const S deg = pi<S>() / S(180);
  using std::cos, std::sin;
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      const S a = S(120 * k + (s ? 12 : -12)) * deg, b = S(120 * k + 60 + (s ? -15 : 15)) * deg;
      base[std::size_t(2 * k + s)] = Vec3<S>(S(cos(a)), S(sin(a)), S(0));
      plat[std::size_t(2 * k + s)] = Vec3<S>(S(cos(b) / 2), S(sin(b) / 2), S(0));
    }
  for (int i = 0; i < 6; ++i) paired[std::size_t(i)] = plat[std::size_t((i + 5) % 6)];
  const SpatialInertia<S> P(S(5), Vec3<S>(S(0), S(0), frac<S>(1, 20)), Mat3<S>(Vec3<S>(frac<S>(3, 10), frac<S>(3, 10), frac<S>(1, 2)).asDiagonal()));
  const StewartLegInertia<S> leg = masslessLegs ? StewartLegInertia<S>{S(0), S(0), S(0), S(0), S(0), S(0)}
                                                : StewartLegInertia<S>{S(1), frac<S>(1, 5), frac<S>(1, 50), frac<S>(3, 2), frac<S>(3, 10), frac<S>(1, 25)};
  return StewartDynamics<S>(base, paired, P, leg, frac<S>(981, 100));
}
template <class S = double> SE3<S> stewartPose(const S& t = S(0)) {
  using std::sin;
  Vec6<S> x;
  x << frac<S>(1, 20) + S(sin(t)) / 10, frac<S>(-1, 25), frac<S>(33, 1000), frac<S>(1, 50), frac<S>(-3, 100), S(1) + S(sin(S(2 * t))) / 20;
  return SE3Tangent<S>(x).exp();
}

// ---- Scalar-generic helpers of the studies that run in the asked scalar S.
// Reference derivatives: in __float128 for the scalars narrower than it (8th-order central
// differences at d = 1/256: truncation d⁸·|f⁽⁹⁾|/630 ≈ 1e-19·|f⁽⁹⁾|, below long double's rounding), in S
// itself for __float128 and mpfr at d = ε^(1/9) (rounding ≈ 2ε|f|/d and truncation d⁸|f⁽⁹⁾|/630 both
// ≈ ε^(8/9)); fdTol is that bound with the constant 4096 for |f|, |f⁽⁹⁾| of the O(1) random states.
template <class S> constexpr bool kWideRef = std::is_same_v<S, float> || std::is_same_v<S, double> || std::is_same_v<S, long double>;
template <class S> using Ref = std::conditional_t<kWideRef<S>, Q, S>;
template <class S> Ref<S> diffStep() {
  if constexpr (kWideRef<S>)
    return Q(1) / 256;
  else
    return Tolerance<S>::precision(8);
}
template <class S> S fdTol() {
  if constexpr (kWideRef<S>)
    return S(0);
  else {
    using std::pow;
    return S(4096) * pow(Tolerance<S>::epsilon(), S(8) / S(9));
  }
}
/// 5-point central differences at d = ε^(1/5): truncation d⁴|f⁽⁵⁾|/30 and rounding 3ε|f|/(2d) are both ≈ ε^(4/5);
/// fd4Tol = 2048 ε^(4/5) relative (6.4e-10 in double) for the O(1) momenta of the mechanisms' motions.
template <class S> S fd4Step() { return Tolerance<S>::precision(4); }
template <class S> S fd4Tol() {
  using std::pow;
  return S(2048) * S(pow(Tolerance<S>::epsilon(), S(4) / S(5)));
}
template <class S> S tol(int ulps) { return Tolerance<S>::identity(ulps); }
template <class S> DynVector<S> rvecS(std::mt19937_64& g, int n, double r = 1.5) { return castMatrix<S>(rvec(g, n, r)); }
/// max |m_ij| over a vector or matrix in S (0 for an empty one; NaN propagates).
template <class S, class M> S maxAbsM(const M& m) {
  S r = S(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      using std::abs;
      r = maxOf<S>(r, S(abs(S(m(i, j)))));
    }
  return r;
}
template <class S> S maxAbsS(const DynVector<S>& v) { return maxAbsM<S>(v); }
template <class S> Vec6<S> v6(const Vec3<S>& a, const Vec3<S>& b) { return (Vec6<S>() << a, b).finished(); }
template <class S> Mat6<S> bodyS(std::mt19937_64& g) { return randomBodyMatrix<S>(g); }
/// randomBody's draws as a SpatialInertia in S (built and symmetrised in S by randomBodyMatrix).
template <class S> SpatialInertia<S> randomBodyS(std::mt19937_64& g) { return SpatialInertia<S>::fromMatrix(randomBodyMatrix<S>(g)); }

}  // namespace soma::studies::gf14
