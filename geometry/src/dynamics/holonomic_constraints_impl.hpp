// Holonomic constraints of GF §14.2 (holonomic_constraints.hpp), five scalars.
#pragma once
#include "soma/geometry/dynamics/holonomic_constraints.hpp"

#include "soma/algebra/small_linalg.hpp"


namespace soma {

// GF §14.2.1 line 8866 (corrected, erratum 4: W_iᵀz_j = 0 for n+1 ≤ i ≤ 6, 1 ≤ j ≤ n)
template <class S> Mat6X<S> constraintWrenchBasis(const Mat6X<S>& Z) {
  if (!allFinite(Z)) throw InvalidInput("constraintWrenchBasis: a freedom screw has a NaN entry");
  if (Z.cols() > 0 && detail::smallNumericalRank<S>(Z) < Z.cols())
    throw InvalidInput("constraintWrenchBasis: the " + std::to_string(Z.cols()) + " freedom screws are linearly dependent");
  return nullSpace<S>(DynMatrix<S>(Z.transpose()));
}

template <class S> Mat6X<S> dualComplement(const Mat6X<S>& W) {
  const DynMatrix<S> G = W.transpose() * W;
  Mat6X<S> out(6, W.cols());
  for (Eigen::Index j = 0; j < W.cols(); ++j)
    out.col(j) = W * minimumNormSolve<S>(G, DynVector<S>(DynVector<S>::Unit(W.cols(), j)));
  return out;
}

// GF §14.2.1 lines 8928–8942
template <class S> Mat6X<S> quadricSurfaceFreedoms(const S& kx, const S& ky, const S& x, const S& y) {
  const S z = (kx * x * x + ky * y * y) / S(2);
  Mat6X<S> Z(6, 3);
  Z.col(0) << -kx * x, -ky * y, S(1), y * (S(1) + ky * z), -x * (S(1) + kx * z), (kx - ky) * x * y;
  Z.col(1) << S(0), S(0), S(0), S(1), S(0), kx * x;
  Z.col(2) << S(0), S(0), S(0), kx * ky * x * y, -(S(1) + kx * kx * x * x), -ky * y;
  return Z;
}
template <class S> Mat6X<S> quadricSurfaceWrenches(const S& kx, const S& ky, const S& x, const S& y) {
  const S z = (kx * x * x + ky * y * y) / S(2);
  Mat6X<S> W(6, 3);
  W.col(0) << y * (S(1) + ky * z), -x * (S(1) + kx * z), (kx - ky) * x * y, -kx * x, -ky * y, S(1);
  W.col(1) << S(1), S(0), kx * x, S(0), S(0), S(0);
  W.col(2) << kx * ky * x * y, -(S(1) + kx * kx * x * x), -ky * y, S(0), S(0), S(0);
  return W;
}

// GF §14.2.1 lines 8896–8924 (corrected, errata 5, 6)
template <class S>
Vec3<S> quadricSurfaceQuartics(const S& kx, const S& ky, const Eigen::Matrix<S, 4, 1>& a, const Eigen::Matrix<S, 4, 1>& b) {
  const S X = a(0) * b(1) - a(1) * b(0) + a(2) * b(3) - a(3) * b(2);
  const S Y = a(0) * b(2) - a(1) * b(3) - a(2) * b(0) + a(3) * b(1);
  const S Z = a(0) * b(3) + a(1) * b(2) - a(2) * b(1) - a(3) * b(0);
  const S na = a.squaredNorm();
  const S n3 = a(0) * a(0) - a(1) * a(1) - a(2) * a(2) + a(3) * a(3);
  return Vec3<S>(kx * X * X + ky * Y * Y - Z * na, kx * n3 * X + (a(0) * a(2) + a(1) * a(3)) * na,
                 ky * n3 * Y + (a(2) * a(3) - a(0) * a(1)) * na);
}

template <class S>
ConstrainedRigidBody<S>::ConstrainedRigidBody(SpatialInertia<S> homeInertia, Mat6X<S> freedoms)
    : N0_(std::move(homeInertia)), Z_(std::move(freedoms)), W_(constraintWrenchBasis<S>(Z_)) {}

// GF §14.2.2 lines 8958–8964 (reduced equations)
template <class S> Vec6<S> ConstrainedRigidBody<S>::acceleration(const SE3<S>& pose, const Vec6<S>& qdot, const Vec6<S>& F) const {
  const Mat6<S> N = inertia(pose);
  const DynMatrix<S> A = Z_.transpose() * N * Z_;
  const DynVector<S> rhs = Z_.transpose() * (F - coadjoint(SE3Tangent<S>(qdot), Vec6<S>(N * qdot)));
  return Z_ * minimumNormSolve<S>(A, rhs);
}

// GF §14.2.2 line 8950 (braces restored, erratum 7): N q̈ + {q̇, N q̇} = F + Σ λ_j W_j
template <class S>
std::pair<Vec6<S>, DynVector<S>> ConstrainedRigidBody<S>::solveMultipliers(const SE3<S>& pose, const Vec6<S>& qdot,
                                                                           const Vec6<S>& F) const {
  const Mat6<S> N = inertia(pose);
  const Eigen::Index m = W_.cols();
  DynMatrix<S> K = DynMatrix<S>::Zero(6 + m, 6 + m);
  K.topLeftCorner(6, 6) = N;
  K.topRightCorner(6, m) = -W_;
  K.bottomLeftCorner(m, 6) = W_.transpose();
  DynVector<S> rhs = DynVector<S>::Zero(6 + m);
  rhs.head(6) = F - coadjoint(SE3Tangent<S>(qdot), Vec6<S>(N * qdot));
  const DynVector<S> x = minimumNormSolve<S>(K, rhs);
  return {Vec6<S>(x.head(6)), DynVector<S>(x.tail(m))};
}

template <class S>
DynVector<S> ConstrainedRigidBody<S>::multipliersByDualBasis(const SE3<S>& pose, const Vec6<S>& qdot, const Vec6<S>& qddot,
                                                             const Vec6<S>& F, const Mat6X<S>& complement) const {
  const Mat6<S> N = inertia(pose);
  const Vec6<S> r = N * qddot + coadjoint(SE3Tangent<S>(qdot), Vec6<S>(N * qdot)) - F;
  return complement.transpose() * r;
}

// GF §14.2.3 lines 8978–9030
template <class S> ConstrainedTree<S> constrainedSerialRobot(const SerialDynamics<S>& robot, const std::vector<Vec6<S>>& wrenches) {
  const int n = robot.dof();
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::vector<Vec6<S>> s;
  for (int i = 0; i < n; ++i) {
    parent[std::size_t(i)] = i - 1;
    s.push_back(robot.homeScrews()[std::size_t(i)].coeffs());
  }
  std::vector<LoopConstraint<S>> cons;
  for (const Vec6<S>& w : wrenches) cons.push_back(LoopConstraint<S>::fixedWrench(n - 1, -1, w));
  return ConstrainedTree<S>(TreeDynamics<S>(TreeTopology(parent), s, robot.homeInertias(), Vec3<S>(S(0), S(0), -robot.gravity())),
                            cons);
}

#define SOMA_INSTANTIATE_HOLONOMIC_CONSTRAINTS(S)                                                                       \
  template Mat6X<S> constraintWrenchBasis<S>(const Mat6X<S>&);                                            \
  template Mat6X<S> dualComplement<S>(const Mat6X<S>&);                                                   \
  template Mat6X<S> quadricSurfaceFreedoms<S>(const S&, const S&, const S&, const S&);                    \
  template Mat6X<S> quadricSurfaceWrenches<S>(const S&, const S&, const S&, const S&);                    \
  template Vec3<S> quadricSurfaceQuartics<S>(const S&, const S&, const Eigen::Matrix<S, 4, 1>&,           \
                                             const Eigen::Matrix<S, 4, 1>&);                              \
  template class ConstrainedRigidBody<S>;                                                                \
  template ConstrainedTree<S> constrainedSerialRobot<S>(const SerialDynamics<S>&, const std::vector<Vec6<S>>&);

}  // namespace soma
