// Constraint quadrics in Study parameters (GF §11.4–11.5).
#pragma once
#include "soma/geometry/study/constraint_quadrics.hpp"

#include "soma/geometry/study/quaternion_matrices.hpp"

namespace soma {

template <class S> Mat8<S> sphereConstraintQuadric(const Vec3<S>& p, const Vec3<S>& q, const S& L) {
  if (!allFinite(p) || !allFinite(q) || !isFinite(L))
    throw InvalidInput("sphereConstraintQuadric: a point or the length has a NaN or infinite coordinate");
  if (L < S(0)) throw InvalidInput("sphereConstraintQuadric: negative leg length " + toString(L, 6));
  const Vec4<S> qq(S(0), q.x(), q.y(), q.z()), pp(S(0), p.x(), p.y(), p.z());
  Eigen::Matrix<S, 4, 8> B;
  B << quaternionRightMatrix<S>(qq) - quaternionLeftMatrix<S>(pp), S(2) * Mat4<S>::Identity();
  Mat8<S> Q = B.transpose() * B;
  Q.template topLeftCorner<4, 4>() -= L * L * Mat4<S>::Identity();
  return Q;
}

template <class S> Mat8<S> studyQuadricMatrix() {
  Mat8<S> Q = Mat8<S>::Zero();
  Q.template topRightCorner<4, 4>() = Mat4<S>::Identity() / S(2);
  Q.template bottomLeftCorner<4, 4>() = Mat4<S>::Identity() / S(2);
  return Q;
}

template <class S> S quadricResidual(const Mat8<S>& Q, const Vec8<S>& x) {
  const S n2 = x.squaredNorm();
  return n2 > S(0) ? S(x.dot(Q * x) / n2) : S(0);
}

template <class S> Eigen::Matrix<S, 4, 8> twoRevoluteEquations(const S& l, const S& alpha) {
  using std::cos;
  using std::sin;
  const S ca = cos(alpha), sa = sin(alpha);
  Eigen::Matrix<S, 4, 8> E = Eigen::Matrix<S, 4, 8>::Zero();
  // columns: a0 a1 a2 a3 c0 c1 c2 c3
  E(0, 2) = l, E(0, 7) = S(-1);        // l a2 − c3
  E(1, 1) = l, E(1, 4) = S(-1);        // l a1 − c0
  E(2, 1) = l * ca, E(2, 5) = -sa;     // l a1 cos α − c1 sin α
  E(3, 2) = l * ca, E(3, 6) = -sa;     // l a2 cos α − c2 sin α
  return E;
}

#define SOMA_INSTANTIATE_CONSTRAINT_QUADRICS(S)                                                     \
  template Mat8<S> sphereConstraintQuadric<S>(const Vec3<S>&, const Vec3<S>&, const S&); \
  template Mat8<S> studyQuadricMatrix<S>();                                              \
  template S quadricResidual<S>(const Mat8<S>&, const Vec8<S>&);                         \
  template Eigen::Matrix<S, 4, 8> twoRevoluteEquations<S>(const S&, const S&);

}  // namespace soma
