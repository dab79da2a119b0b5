#pragma once
// Shared helpers for the GF chapter 15 studies (double): random screws and robots with fixed seeds,
// finite differences, and the "printed formula fails" record.
#include "soma/geometry/dynamics/serial_dynamics.hpp"
#include "soma/geometry/riemannian/geodesic_control.hpp"
#include "soma/geometry/riemannian/hybrid_control.hpp"
#include "soma/geometry/riemannian/invariant_metric.hpp"
#include "soma/geometry/riemannian/joint_space_geometry.hpp"
#include "soma/geometry/riemannian/mobility.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <type_traits>
#include <random>

namespace soma::studies::gf15 {

inline constexpr const char* kChapter = "GF 15 — Differential Geometry";
using V3 = Vec3<double>;
using V6 = Vec6<double>;
using M3 = Mat3<double>;
using M6 = Mat6<double>;
using DV = DgVector<double>;
using DM = DgMatrix<double>;
using SM = ScrewMatrix<double>;
using std::abs;

/// n/d in S (exact for the small fractions the studies use as inputs).
template <class S> S frac(long n, long d = 1) { return S(n) / S(d); }
inline double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
inline V3 rv3(std::mt19937_64& g, double lo = -1, double hi = 1) { return V3(uni(g, lo, hi), uni(g, lo, hi), uni(g, lo, hi)); }
inline V6 rv6(std::mt19937_64& g) {
  V6 v;
  for (int i = 0; i < 6; ++i) v(i) = uni(g);
  return v;
}
inline DV rvec(std::mt19937_64& g, int n, double lo = -1, double hi = 1) {
  DV v(n);
  for (int i = 0; i < n; ++i) v(i) = uni(g, lo, hi);
  return v;
}
inline V3 unit3(std::mt19937_64& g) {
  V3 v;
  do v = rv3(g);
  while (v.squaredNorm() < 1e-2 || v.squaredNorm() > 1);
  return v.normalized();
}
inline V6 br(const V6& a, const V6& b) { return SE3Tangent<double>(a).ad() * b; }
inline V6 lineScrew(const V3& w, const V3& r, double pitch = 0) {
  V6 s;
  s << w, r.cross(w) + pitch * w;
  return s;
}
inline std::vector<V6> randomScrews(std::mt19937_64& g, int n) {
  std::vector<V6> s;
  for (int i = 0; i < n; ++i) s.push_back(lineScrew(unit3(g), rv3(g)));
  return s;
}
inline double maxAbs(const DV& v) { return v.cwiseAbs().maxCoeff(); }
inline double maxAbs(const DM& v) { return v.cwiseAbs().maxCoeff(); }
/// 4th-order central difference of a vector-valued f at 0.
template <class F> auto cdiff(F&& f, double h = 1e-3) {
  using R = std::decay_t<decltype(f(0.0).eval())>;
  return R((8 * (f(h) - f(-h)) - (f(2 * h) - f(-2 * h))) / (12 * h));
}
/// A random 6R robot with random links (g = 9.81): the ch. 13 model.
inline SerialDynamics<double> randomRobot(std::mt19937_64& g, int n = 6, double grav = 9.81) {
  std::vector<SE3Tangent<double>> s;
  std::vector<SpatialInertia<double>> l;
  for (int i = 0; i < n; ++i) {
    s.emplace_back(lineScrew(unit3(g), rv3(g)));
    const V3 d = rv3(g, 0.05, 0.5);
    const M3 R = SO3<double>::Random(g).matrix();
    M3 I = R * V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose();
    I = (I + I.transpose()) / 2;
    l.emplace_back(uni(g, 0.5, 3), rv3(g), I);
  }
  return SerialDynamics<double>(s, l, grav);
}


// Scalar-generic helpers (the studies converted to run in the asked scalar S; draws stay in double).
template <class S> S tol(int ulps) { return Tolerance<S>::identity(ulps); }
template <class S> Vec6<S> brS(const Vec6<S>& a, const Vec6<S>& b) { return SE3Tangent<S>(a).ad() * b; }
/// A line screw (pitch p) from a double draw: the direction normalised in S (|ω| = 1 to S's rounding).
template <class S> Vec6<S> lineScrewS(const V3& w, const V3& r, const S& pitch = S(0)) {
  Vec3<S> ws = castMatrix<S>(w);
  using std::sqrt;
  ws /= S(sqrt(S(ws.squaredNorm())));
  const Vec3<S> rs = castMatrix<S>(r);
  return (Vec6<S>() << ws, Vec3<S>(rs.cross(ws) + pitch * ws)).finished();
}
template <class S> std::vector<Vec6<S>> randomScrewsS(std::mt19937_64& g, int n) {
  std::vector<Vec6<S>> s;
  for (int i = 0; i < n; ++i) {
    const V3 w = unit3(g), r = rv3(g);
    s.push_back(lineScrewS<S>(w, r));
  }
  return s;
}
template <class S> DgVector<S> rvecS(std::mt19937_64& g, int n, double lo = -1, double hi = 1) { return castMatrix<S>(rvec(g, n, lo, hi)); }
template <class S, class M> S mx(const M& m) {
  S r = S(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      using std::abs;
      r = std::max<S>(r, S(abs(S(m(i, j)))));
    }
  return r;
}
// 4th-order central differences at h = ε^(1/5): truncation h⁴|f⁽⁵⁾|/30 and rounding 3ε|f|/(2h) are both
// ≈ ε^(4/5); fdTol = 2048 ε^(4/5) (6.4e-10 in double, 1e-9 before) for the O(1) derivatives of these
// unit-scale robots.
template <class S> S fdStep() { return Tolerance<S>::precision(4); }
template <class S> S fdTol() {
  using std::pow;
  return S(2048) * pow(Tolerance<S>::epsilon(), S(4) / S(5));
}
template <class S, class F> auto cdiffS(F&& f, const S& h) {
  using R = std::decay_t<decltype(f(S(0)).eval())>;
  return R((S(8) * R(f(h) - f(S(-h))) - R(f(S(2 * h)) - f(S(-2 * h)))) / (S(12) * h));
}
/// The condition number σ_max/σ_min of a square matrix (soma's one-sided Jacobi).
template <class S> S cond(const DgMatrix<S>& a) {
  const std::vector<S> sv = detail::smallSingularValues<S>(detail::SmallMat<S>(a));
  S lo = sv[0], hi = sv[0];
  for (const S& x : sv) {
    lo = std::min<S>(lo, x);
    hi = std::max<S>(hi, x);
  }
  return S(hi / lo);
}
// The fixed-step RK4 runs below have a truncation error of the method, not of the scalar: it is bounded by
// its value in double (1e-9, from h⁴ = 1e-8 at h = 0.01 for these slow |θ̇| ≤ 0.3 motions) plus 64 ε of
// rounding per step.
template <class S> S rk4Tol(int steps, double method = 1e-9, int ulpsPerStep = 64) { return S(method) + S(steps) * tol<S>(ulpsPerStep); }

/// The inverse of a 6×6 matrix column by column (soma's Gaussian elimination; Eigen's LU in five scalars
/// costs compile time).
template <class S> Mat6<S> inverse6(const Mat6<S>& a) {
  Mat6<S> r;
  for (int j = 0; j < 6; ++j) {
    Vec6<S> e = Vec6<S>::Unit(j);
    detail::smallSolveInPlace<S, 6>(a, e);
    r.col(j) = e;
  }
  return r;
}
/// randomRobot's draws with the robot built in S (unit axes normalised, inertias symmetrised in S; g = 981/100).
template <class S> SerialDynamics<S> randomRobotS(std::mt19937_64& g, int n = 6) {
  std::vector<SE3Tangent<S>> s;
  std::vector<SpatialInertia<S>> l;
  for (int i = 0; i < n; ++i) {
    const V3 w = unit3(g), r = rv3(g);
    s.emplace_back(lineScrewS<S>(w, r));
    const V3 d = rv3(g, 0.05, 0.5);
    const Mat3<S> R = castMatrix<S>(M3(SO3<double>::Random(g).matrix()));
    Mat3<S> I = R * Vec3<S>(castMatrix<S>(V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)))).asDiagonal() * R.transpose();
    I = Mat3<S>((I + I.transpose()) / S(2));
    const double m = uni(g, 0.5, 3);
    const V3 c = rv3(g);
    l.emplace_back(S(m), castMatrix<S>(c), I);
  }
  return SerialDynamics<S>(s, l, frac<S>(981, 100));
}

}  // namespace soma::studies::gf15
