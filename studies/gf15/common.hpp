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

}  // namespace soma::studies::gf15
