// 3-planes of the Study quadric and their intersections (GF §11.2.2–11.2.3).
#pragma once
#include "soma/geometry/study/study_plane.hpp"

#include "soma/geometry/study/quaternion_matrices.hpp"

#include "soma/algebra/small_linalg.hpp"

#include <Eigen/LU>

namespace soma {

namespace {
template <class S> std::string str(const S& x) { return toString(x, 3); }

/// Numerical rank: singular values above Tolerance::rank × the largest (0 for the zero matrix).
template <class S, int R, int C> int numericalRank(const Eigen::Matrix<S, R, C>& m) {
  return detail::smallNumericalRank<S>(detail::SmallMat<S>(m));
}
}  // namespace

template <class S> StudyPlane<S> StudyPlane<S>::fromOrthogonal(const Mat4<S>& M) {
  if (!allFinite(M)) throw InvalidInput("StudyPlane::fromOrthogonal: M has a NaN or infinite entry");
  const S defect = (M.transpose() * M - Mat4<S>::Identity()).cwiseAbs().maxCoeff();
  if (defect > Tolerance<S>::input())
    throw InvalidInput("StudyPlane::fromOrthogonal: M is not orthogonal (max |MᵀM − I| = " + str(defect) +
                       " > " + str(Tolerance<S>::input()) + ")");
  return StudyPlane(M, M.determinant() > S(0) ? StudyPlaneKind::A : StudyPlaneKind::B);
}

// GF §11.2.2, GF-11.2.2-A-plane-cosets: x = (a + c)/2 = M y, y = (a − c)/2 on every point.
template <class S> StudyPlane<S> StudyPlane<S>::fromSpan(const Mat84& P) {
  using std::sqrt;  // by name: __float128 and long double have no ADL, and ::sqrt is double's
  if (!allFinite(P)) throw InvalidInput("StudyPlane::fromSpan: a point has a NaN or infinite coordinate");
  Mat84 Q = P;
  for (int k = 0; k < 4; ++k) {
    const S n = sqrt(Q.col(k).squaredNorm());
    if (!(n > S(0))) throw InvalidInput("StudyPlane::fromSpan: point " + std::to_string(k) + " is zero");
    Q.col(k) /= n;
  }
  const Mat4<S> X = (Q.template topRows<4>() + Q.template bottomRows<4>()) / S(2);
  const Mat4<S> Y = (Q.template topRows<4>() - Q.template bottomRows<4>()) / S(2);
  if (numericalRank(Q) < 4) throw InvalidInput("StudyPlane::fromSpan: the four points are linearly dependent (they span less than a 3-plane)");
  if (numericalRank(Y) < 4)
    throw InvalidInput("StudyPlane::fromSpan: the span is not a 3-plane of the Study quadric (y = (a − c)/2 is degenerate on it)");
  const Mat4<S> M = X * Y.inverse();
  const S defect = (M.transpose() * M - Mat4<S>::Identity()).cwiseAbs().maxCoeff();
  if (defect > Tolerance<S>::input())
    throw InvalidInput("StudyPlane::fromSpan: the span is not contained in the Study quadric (x = M y with max |MᵀM − I| = " +
                       str(defect) + ")");
  return StudyPlane(M, M.determinant() > S(0) ? StudyPlaneKind::A : StudyPlaneKind::B);
}

template <class S> Mat3<S> cayleyRotation(const Vec3<S>& p) {
  Mat3<S> K;
  K << S(0), -p.z(), p.y(), p.z(), S(0), -p.x(), -p.y(), p.x(), S(0);
  const Mat3<S> I = Mat3<S>::Identity();
  return (I + K) * (I - K).inverse();  // I − K is invertible for every real p (K skew)
}

template <class S> StudyPlane<S> StudyPlane<S>::rotationsAbout(const Vec3<S>& p) {
  if (!allFinite(p)) throw InvalidInput("StudyPlane::rotationsAbout: the centre has a NaN or infinite coordinate");
  Mat4<S> M = Mat4<S>::Identity();
  M.template bottomRightCorner<3, 3>() = cayleyRotation<S>(p);
  return StudyPlane(M, StudyPlaneKind::A);
}

template <class S> StudyPlane<S> StudyPlane<S>::planarMotions(const Vec3<S>& n) {
  if (!allFinite(n)) throw InvalidInput("StudyPlane::planarMotions: the normal has a NaN or infinite coordinate");
  const S d = n.squaredNorm() - S(1);
  if (abs(d) > Tolerance<S>::input())
    throw InvalidInput("StudyPlane::planarMotions: the normal is not a unit vector (|n|² − 1 = " + str(d) + ")");
  Mat4<S> M = Mat4<S>::Identity();
  M.template bottomRightCorner<3, 3>() = S(2) * n * n.transpose() - Mat3<S>::Identity();  // half-turn about n
  return StudyPlane(M, StudyPlaneKind::A);
}

template <class S> StudyPlane<S> StudyPlane<S>::translations() {
  Mat4<S> M = -Mat4<S>::Identity();
  M(0, 0) = S(1);
  return StudyPlane(M, StudyPlaneKind::B);
}

template <class S> StudyPlane<S> StudyPlane<S>::atInfinity() { return StudyPlane(-Mat4<S>::Identity(), StudyPlaneKind::A); }

template <class S> typename StudyPlane<S>::Mat48 StudyPlane<S>::equations() const {
  Mat48 e;
  e << Mat4<S>::Identity() - M_, Mat4<S>::Identity() + M_;
  return e;
}

template <class S> typename StudyPlane<S>::Mat84 StudyPlane<S>::basis() const {
  Mat84 b;
  b << M_ + Mat4<S>::Identity(), M_ - Mat4<S>::Identity();
  return b;
}

template <class S> Vec8<S> StudyPlane<S>::point(const Vec4<S>& y) const {
  Vec8<S> x;
  x << (M_ + Mat4<S>::Identity()) * y, (M_ - Mat4<S>::Identity()) * y;
  return x;
}

template <class S> S StudyPlane<S>::residual(const Vec8<S>& x) const {
  using std::sqrt;  // by name: __float128 and long double have no ADL, and ::sqrt is double's
  const S n = sqrt(x.squaredNorm());
  return n > S(0) ? S(sqrt((equations() * x).squaredNorm()) / n) : S(0);
}

template <class S> StudyPlane<S> StudyPlane<S>::leftTranslated(const DualQuaternion<S>& g) const {
  return fromSpan(dualQuaternionLeftMatrix<S>(g) * basis());
}

template <class S> StudyPlane<S> StudyPlane<S>::rightTranslated(const DualQuaternion<S>& g) const {
  return fromSpan(dualQuaternionRightMatrix<S>(g) * basis());
}

template <class S> int intersectionDimension(const StudyPlane<S>& p, const StudyPlane<S>& q) {
  Eigen::Matrix<S, 8, 8> m;
  m << p.equations(), q.equations();
  return 8 - numericalRank(m) - 1;
}

template <class S> int intersectionDimensionByEigenvalues(const StudyPlane<S>& p, const StudyPlane<S>& q) {
  const Mat4<S> K = p.M() * q.M().transpose() - Mat4<S>::Identity();
  // K = 0 (the same plane): rank 0. Otherwise compare with the scale of M (1), not of K.
  int r = 0;
  for (const S& sigma : detail::smallSingularValues<S>(detail::SmallMat<S>(K)))
    if (sigma > Tolerance<S>::rank()) ++r;
  return 4 - r - 1;
}

#define SOMA_INSTANTIATE_STUDY_PLANE(S)                                                                  \
  template class StudyPlane<S>;                                                              \
  template int intersectionDimension<S>(const StudyPlane<S>&, const StudyPlane<S>&);         \
  template int intersectionDimensionByEigenvalues<S>(const StudyPlane<S>&, const StudyPlane<S>&); \
  template Mat3<S> cayleyRotation<S>(const Vec3<S>&);

}  // namespace soma
