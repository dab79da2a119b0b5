// GF §15.1, §15.3: invariant metrics, the bi-invariant connection and its curvature on se(3).
#pragma once
#include "soma/geometry/riemannian/invariant_metric.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"

namespace soma {
namespace {
template <class S> Vec6<S> br(const Vec6<S>& a, const Vec6<S>& b) { return SE3Tangent<S>(a).ad() * b; }
}  // namespace

template <class S> Mat6<S> reciprocalProductMatrix() {
  Mat6<S> q = Mat6<S>::Zero();
  q.template topRightCorner<3, 3>().setIdentity();
  q.template bottomLeftCorner<3, 3>().setIdentity();
  return q;
}
template <class S> Mat6<S> killingMatrixQinf() {
  Mat6<S> q = Mat6<S>::Zero();
  q.template topLeftCorner<3, 3>().setIdentity();
  return q;
}

template <class S> Mat6<S> InvariantMetric<S>::matrix() const {
  return Mat6<S>(alpha * reciprocalProductMatrix<S>() + beta * killingMatrixQinf<S>());
}
template <class S> S InvariantMetric<S>::operator()(const Vec6<S>& a, const Vec6<S>& b) const {
  // αQ₀ + βQ∞ without forming the matrix: α(ω_a·v_b + v_a·ω_b) + β ω_a·ω_b
  const Vec3<S> wa = a.template head<3>(), va = a.template tail<3>();
  const Vec3<S> wb = b.template head<3>(), vb = b.template tail<3>();
  return alpha * (wa.dot(vb) + va.dot(wb)) + beta * wa.dot(wb);
}
// GF §15.1 line 9519: p = −β/2α
template <class S> S InvariantMetric<S>::nullPitch() const {
  using std::abs;
  if (!(abs(alpha) > Tolerance<S>::epsilon()))
    throw InvalidInput("InvariantMetric::nullPitch: alpha = 0 (Q_p = beta*Q_inf is degenerate; no pitch is null)");
  return -beta / (S(2) * alpha);
}
template <class S> InvariantMetric<S> InvariantMetric<S>::withNullPitch(const S& p) {
  return InvariantMetric{S(1), S(-2) * p};
}

template <class S> std::array<Mat6<S>, 6> structureConstants() {
  std::array<Mat6<S>, 6> c;
  for (auto& m : c) m.setZero();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const Vec6<S> b = br<S>(Vec6<S>::Unit(i), Vec6<S>::Unit(j));
      for (int k = 0; k < 6; ++k) c[std::size_t(k)](i, j) = b(k);
    }
  return c;
}

template <class S> S invarianceDefect(const Mat6<S>& Q) {
  using std::abs;
  const auto C = structureConstants<S>();
  S worst = S(0);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        S v = S(0);
        for (int l = 0; l < 6; ++l) v += C[std::size_t(l)](i, j) * Q(l, k) + C[std::size_t(l)](i, k) * Q(l, j);
        if (abs(v) > worst) worst = abs(v);
      }
  return worst;
}

template <class S> std::array<Mat6<S>, 6> biinvariantChristoffel() {
  auto c = structureConstants<S>();
  for (auto& m : c) m *= S(-1) / S(2);
  return c;
}

template <class S> Vec6<S> biinvariantCovariant(const Vec6<S>& X, const Vec6<S>& Y) {
  return Vec6<S>(br<S>(X, Y) / S(2));
}
template <class S> Vec6<S> curvatureFromConnection(const Vec6<S>& X, const Vec6<S>& Y, const Vec6<S>& Z) {
  const auto nab = [](const Vec6<S>& a, const Vec6<S>& b) { return biinvariantCovariant<S>(a, b); };
  return Vec6<S>(-nab(X, nab(Y, Z)) + nab(Y, nab(X, Z)) + nab(br<S>(X, Y), Z));
}
template <class S> Vec6<S> curvature(const Vec6<S>& X, const Vec6<S>& Y, const Vec6<S>& Z) {
  return Vec6<S>(br<S>(br<S>(X, Y), Z) / S(4));
}
template <class S> S sectionalCurvature(const InvariantMetric<S>& Q, const Vec6<S>& X, const Vec6<S>& Z) {
  const Vec6<S> b = br<S>(X, Z);
  return Q(b, b) / S(4);
}

#define SOMA_INSTANTIATE_INVARIANT_METRIC(S)                                                              \
  template struct InvariantMetric<S>;                                                              \
  template Mat6<S> reciprocalProductMatrix<S>();                                                   \
  template Mat6<S> killingMatrixQinf<S>();                                                         \
  template std::array<Mat6<S>, 6> structureConstants<S>();                                         \
  template S invarianceDefect<S>(const Mat6<S>&);                                                  \
  template std::array<Mat6<S>, 6> biinvariantChristoffel<S>();                                     \
  template Vec6<S> biinvariantCovariant<S>(const Vec6<S>&, const Vec6<S>&);                        \
  template Vec6<S> curvatureFromConnection<S>(const Vec6<S>&, const Vec6<S>&, const Vec6<S>&);     \
  template Vec6<S> curvature<S>(const Vec6<S>&, const Vec6<S>&, const Vec6<S>&);                   \
  template S sectionalCurvature<S>(const InvariantMetric<S>&, const Vec6<S>&, const Vec6<S>&);

}  // namespace soma
