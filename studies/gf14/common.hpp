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

/// n/d in S (exact for the small fractions the studies use as inputs).
template <class S> S frac(long n, long d = 1) { return S(n) / S(d); }
inline double uni(std::mt19937_64& g, double lo = -1, double hi = 1) { return std::uniform_real_distribution<double>(lo, hi)(g); }
inline V3 rv3(std::mt19937_64& g, double lo = -1, double hi = 1) { return V3(uni(g, lo, hi), uni(g, lo, hi), uni(g, lo, hi)); }
inline V3 unit3(std::mt19937_64& g) {
  V3 v;
  do v = rv3(g);
  while (v.squaredNorm() < 1e-2 || v.squaredNorm() > 1);
  return v.normalized();
}
inline DV rvec(std::mt19937_64& g, int n, double r = 1.5) {
  DV v(n);
  for (int i = 0; i < n; ++i) v(i) = uni(g, -r, r);
  return v;
}
inline double maxAbs(const DV& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }
inline SpatialInertia<double> randomBody(std::mt19937_64& g) {
  const V3 d(uni(g, 0.05, 0.5), uni(g, 0.05, 0.5), uni(g, 0.05, 0.5));
  const Mat3<double> R = SO3<double>::Random(g).matrix();
  return SpatialInertia<double>(uni(g, 0.5, 3), rv3(g), Mat3<double>(R * V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose()));
}
/// randomBody's draws (mass, centre, principal moments, axes) with the body built in S: its 6×6 matrix
/// symmetrised in S (a double matrix cast to a wider S is symmetric only to double's rounding).
template <class S> Mat6<S> randomBodyMatrix(std::mt19937_64& g) {
  const V3 d(uni(g, 0.05, 0.5), uni(g, 0.05, 0.5), uni(g, 0.05, 0.5));
  const Mat3<S> R = castMatrix<S>(Mat3<double>(SO3<double>::Random(g).matrix()));
  const double m = uni(g, 0.5, 3);
  const V3 c = rv3(g);
  const Mat3<S> I = R * Vec3<S>(castMatrix<S>(V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)))).asDiagonal() * R.transpose();
  const Mat6<S> n = SpatialInertia<S>(S(m), castMatrix<S>(c), I).matrix();
  return Mat6<S>((n + n.transpose()) / S(2));
}
/// A random tree with the given parents: revolute joints on random lines, random bodies, g along −z.
template <class S = double> TreeDynamics<S> randomTree(std::mt19937_64& g, const std::vector<int>& parent, const S& grav = frac<S>(981, 100)) {
  std::vector<Vec6<S>> s;
  std::vector<Mat6<S>> N;
  for (std::size_t i = 0; i < parent.size(); ++i) {
    const V3 w = unit3(g), p = rv3(g);
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

/// The invented Grashof crank–rocker of checks/fourbar_check.py: d = (1, 2.2, 1.8, 2.5).
inline FourBarDynamics<double> crankRocker(double d2 = 2.2) {
  return FourBarDynamics<double>(1.0, d2, 1.8, 2.5,
                         {PlanarLink<double>{1.0, 0.5, 0.1, 0.1}, PlanarLink<double>{2.0, 1.0, -0.2, 0.8},
                          PlanarLink<double>{1.5, 0.9, 0.15, 0.45}});
}
inline BipedParameters<double> bipedParameters() { return {10, 0.3, 0.5, 0.45, 4, 0.07, 0.45, 3, 0.05, 9.81}; }
inline BipedPose<double> bipedHome() {
  return {Eigen::Vector2d(0, 0.75), Eigen::Vector2d(0.2, 0), Eigen::Vector2d(-0.2, 0), 0.0};
}
/// A 6-6 Stewart platform (base radius 1, platform radius 0.5, legs 1 m high) with massive or massless legs.
inline StewartDynamics<double> stewartExample(bool masslessLegs) {
  std::array<V3, 6> base, plat, paired;
  const double deg = M_PI / 180;
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      const double a = (120 * k + (s ? 12 : -12)) * deg, b = (120 * k + 60 + (s ? -15 : 15)) * deg;
      base[std::size_t(2 * k + s)] = V3(std::cos(a), std::sin(a), 0);
      plat[std::size_t(2 * k + s)] = V3(std::cos(b) / 2, std::sin(b) / 2, 0);
    }
  for (int i = 0; i < 6; ++i) paired[std::size_t(i)] = plat[std::size_t((i + 5) % 6)];
  const SpatialInertia<double> P(5, V3(0, 0, 0.05), Mat3<double>(V3(0.3, 0.3, 0.5).asDiagonal()));
  const StewartLegInertia<double> leg = masslessLegs ? StewartLegInertia<double>{0, 0, 0, 0, 0, 0}
                                                     : StewartLegInertia<double>{1, 0.2, 0.02, 1.5, 0.3, 0.04};
  return StewartDynamics<double>(base, paired, P, leg, 9.81);
}
inline SE3<double> stewartPose(double t = 0) {
  V6 x;
  x << 0.05 + 0.1 * std::sin(t), -0.04, 0.033, 0.02, -0.03, 1.0 + 0.05 * std::sin(2 * t);
  return SE3Tangent<double>(x).exp();
}

}  // namespace soma::studies::gf14
