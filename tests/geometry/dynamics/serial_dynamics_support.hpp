#pragma once
// Random serial robots for the GF ch. 13 tests: parameters drawn in double with a fixed seed, then
// converted exactly to any scalar, so one robot can be evaluated in double and in __float128.
#include "soma/geometry/dynamics/serial_dynamics.hpp"

#include "../../support/scalars.hpp"

#include <vector>

namespace soma::test {

struct RobotSpec {
  std::vector<Vec6<double>> screws;
  std::vector<double> masses;
  std::vector<Vec3<double>> coms;
  std::vector<Mat3<double>> inertias;  // about the c.o.m.
  double gravity = 9.81;
};

/// n joints, lengths O(1) m, masses 0.5–3 kg; `prismatic` makes joint 2 (if n ≥ 3) a slide.
inline RobotSpec randomRobot(std::mt19937_64& g, int n, bool prismatic = false) {
  RobotSpec r;
  for (int i = 0; i < n; ++i) {
    const Vec3<double> w = unitVec3<double>(g);
    const Vec3<double> p = uniformVec<double, 3>(g, -1, 1);
    Vec6<double> s;
    if (prismatic && i == 2 && n >= 3) {
      s << 0, 0, 0, w;
    } else {
      s << w, p.cross(w);
    }
    r.screws.push_back(s);
    r.masses.push_back(uniform<double>(g, 0.5, 3));
    r.coms.push_back(uniformVec<double, 3>(g, -1, 1));
    const Vec3<double> d = uniformVec<double, 3>(g, 0.05, 0.5);
    // principal moments must satisfy the triangle inequality of a real body: d_i ≤ d_j + d_k
    const Mat3<double> R = SO3<double>::Random(g).matrix();
    r.inertias.push_back(R * Vec3<double>(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose());
  }
  return r;
}

template <class S> SerialDynamics<S> build(const RobotSpec& r, double lengthScale = 1, double massScale = 1) {
  std::vector<SE3Tangent<S>> screws;
  std::vector<SpatialInertia<S>> links;
  for (std::size_t i = 0; i < r.screws.size(); ++i) {
    Vec6<double> s = r.screws[i];
    if (s.head<3>().squaredNorm() > 0.5) s.tail<3>() *= lengthScale;
    Vec6<S> sx = castMatrix<S>(s);
    using std::sqrt;
    const S w2 = sx.template head<3>().squaredNorm();
    sx /= w2 > S(0) ? S(sqrt(w2)) : S(sx.template tail<3>().norm());  // unit in S, not only in double
    screws.emplace_back(sx);
    const Mat3<S> I = castMatrix<S>(Mat3<double>(r.inertias[i] * massScale * lengthScale * lengthScale));
    links.emplace_back(scalarCast<S>(r.masses[i] * massScale), castMatrix<S>(Vec3<double>(r.coms[i] * lengthScale)),
                       Mat3<S>((I + I.transpose()) / S(2)));  // exactly symmetric in S
  }
  return SerialDynamics<S>(screws, links, scalarCast<S>(r.gravity * lengthScale));
}

template <class S> DynVector<S> randomJoints(std::mt19937_64& g, int n, double lo = -1.5, double hi = 1.5) {
  DynVector<S> v(n);
  for (int i = 0; i < n; ++i) v(i) = uniform<S>(g, lo, hi);
  return v;
}
template <class To, class From> DynVector<To> castVec(const DynVector<From>& v) {
  DynVector<To> o(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) o(i) = scalarCast<To>(v(i));
  return o;
}

/// f'(0) by the 8th-order central difference with step d: Σ_k c_k (f(kd) − f(−kd)) / d,
/// c = (4/5, −1/5, 4/105, −1/280). Truncation error ≤ d⁸ max|f⁽⁹⁾| / 630; rounding ≈ 2.3 ε max|f| / d.
template <class S, class F> S centralDiff8(F&& f, const S& d) {
  const S c[4] = {S(4) / S(5), S(-1) / S(5), S(4) / S(105), S(-1) / S(280)};
  S r = S(0);
  for (int k = 1; k <= 4; ++k) r += c[k - 1] * (f(S(k) * d) - f(S(-k) * d));
  return r / d;
}

}  // namespace soma::test
