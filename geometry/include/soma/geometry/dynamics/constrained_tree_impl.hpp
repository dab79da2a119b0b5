#pragma once
// Definitions for constrained_tree.hpp (included only by its instantiations, soma_instantiate (cmake/SomaInstantiate.cmake)).
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/dynamics/constrained_tree.hpp"

namespace soma {

template <class S> DynVector<S> minimumNormSolve(const DynMatrix<S>& M, const DynVector<S>& b, int* rankOut) {
  detail::SmallMat<S> U, V;
  std::vector<S> sig;
  detail::smallSvd<S>(M, U, sig, V);
  DynVector<S> x = DynVector<S>::Zero(M.cols());
  int r = 0;
  if (!sig.empty() && sig[0] > S(0))
    for (std::size_t k = 0; k < sig.size(); ++k) {
      if (!(sig[k] > Tolerance<S>::rank() * sig[0])) break;
      x += V.col(Eigen::Index(k)) * (U.col(Eigen::Index(k)).dot(b) / sig[k]);
      ++r;
    }
  if (rankOut) *rankOut = r;
  return x;
}

template <class S> DynMatrix<S> nullSpace(const DynMatrix<S>& M) {
  detail::SmallMat<S> U, V;
  std::vector<S> sig;
  detail::smallSvd<S>(M, U, sig, V);
  Eigen::Index r = 0;
  if (!sig.empty() && sig[0] > S(0))
    while (r < Eigen::Index(sig.size()) && sig[std::size_t(r)] > Tolerance<S>::rank() * sig[0]) ++r;
  return V.rightCols(M.cols() - r);
}

template <class S>
ConstrainedTree<S>::ConstrainedTree(TreeDynamics<S> tree, std::vector<LoopConstraint<S>> constraints)
    : tree_(std::move(tree)), cons_(std::move(constraints)) {
  using std::abs;
  const int n = tree_.dof();
  for (std::size_t k = 0; k < cons_.size(); ++k) {
    const LoopConstraint<S>& c = cons_[k];
    const std::string name = "ConstrainedTree: constraint " + std::to_string(k);
    if (c.linkA < 0 || c.linkA >= n || c.linkB < -1 || c.linkB >= n)
      throw InvalidInput(name + " names a link out of range (A = " + std::to_string(c.linkA) + ", B = " + std::to_string(c.linkB) + ")");
    if (c.linkA == c.linkB) throw InvalidInput(name + " joins link " + std::to_string(c.linkA) + " to itself");
    if (c.kind == LoopConstraint<S>::Kind::Point) {
      if (!allFinite(c.homePoint) || !allFinite(c.direction)) throw InvalidInput(name + " has a NaN point or direction");
      if (abs(c.direction.squaredNorm() - S(1)) > Tolerance<S>::input()) throw InvalidInput(name + ": direction is not a unit vector");
    } else if (!allFinite(c.wrench) || !(c.wrench.squaredNorm() > S(0))) {
      throw InvalidInput(name + ": fixed wrench is zero or has a NaN entry");
    }
  }
}

template <class S> std::vector<Vec6<S>> ConstrainedTree<S>::constraintWrenches(const TreeConfiguration<S>& c) const {
  std::vector<Vec6<S>> W;
  for (const LoopConstraint<S>& k : cons_) {
    if (k.kind == LoopConstraint<S>::Kind::FixedWrench) {
      W.push_back(k.wrench);
    } else {  // GF §14.6 lines 9300–9304: W = (r × e, e)
      const Vec3<S> r = c.placements[std::size_t(k.linkA)] * k.homePoint;
      Vec6<S> w;
      w << r.cross(k.direction), k.direction;
      W.push_back(w);
    }
  }
  return W;
}

// GF §14.3.1 line 9050: row k = (W_kᵀ s_j) over the ancestry of A minus that of B
template <class S> DynMatrix<S> ConstrainedTree<S>::constraintMatrix(const TreeConfiguration<S>& c) const {
  const std::vector<Vec6<S>> W = constraintWrenches(c);
  const int n = dof(), m = numConstraints();
  DynMatrix<S> C = DynMatrix<S>::Zero(m, n);
  for (int k = 0; k < m; ++k) {
    const LoopConstraint<S>& q = cons_[std::size_t(k)];
    for (int j : tree_.topology().ancestry(q.linkA)) C(k, j) += W[std::size_t(k)].dot(c.screws[std::size_t(j)]);
    if (q.linkB >= 0)
      for (int j : tree_.topology().ancestry(q.linkB)) C(k, j) -= W[std::size_t(k)].dot(c.screws[std::size_t(j)]);
  }
  return C;
}

template <class S> int ConstrainedTree<S>::constraintRank(const DynVector<S>& theta) const {
  return detail::smallNumericalRank<S>(constraintMatrix(theta));
}

template <class S> S ConstrainedTree<S>::conditionRatio(const DynVector<S>& theta) const {
  const DynMatrix<S> C = constraintMatrix(theta);
  const std::vector<S> sig = detail::smallSingularValues<S>(C);
  const std::size_t r = std::size_t(std::min(C.rows(), C.cols()));
  if (r == 0 || !(sig[0] > S(0))) return S(0);
  return sig[r - 1] / sig[0];
}

template <class S> DynMatrix<S> ConstrainedTree<S>::freedomBasis(const DynVector<S>& theta) const {
  return nullSpace<S>(constraintMatrix(theta));
}

template <class S> DynVector<S> ConstrainedTree<S>::positionResidual(const DynVector<S>& theta) const {
  const TreeConfiguration<S> c = tree_.configuration(theta);
  DynVector<S> r(numConstraints());
  for (int k = 0; k < numConstraints(); ++k) {
    const LoopConstraint<S>& q = cons_[std::size_t(k)];
    const SE3<S> KA = c.placements[std::size_t(q.linkA)];
    const SE3<S> KB = q.linkB < 0 ? SE3<S>::Identity() : c.placements[std::size_t(q.linkB)];
    if (q.kind == LoopConstraint<S>::Kind::Point)
      r(k) = q.direction.dot(Vec3<S>(KA * q.homePoint - KB * q.homePoint));
    else
      r(k) = q.wrench.dot((KA * KB.inverse()).log().coeffs());
  }
  return r;
}

template <class S>
DynVector<S> ConstrainedTree<S>::accelerationBias(const DynVector<S>& theta, const DynVector<S>& thetaDot) const {
  const TreeConfiguration<S> c = tree_.configuration(theta);
  const std::vector<Vec6<S>> v = tree_.linkVelocities(c, thetaDot);
  const std::vector<Vec6<S>> a = tree_.linkAccelerations(c, thetaDot, DynVector<S>::Zero(dof()));
  DynVector<S> g(numConstraints());
  auto pointAcc = [&](int link, const Vec3<S>& r) -> Vec3<S> {  // r̈ = v̇ + ω̇ × r + ω × (v + ω × r)
    if (link < 0) return Vec3<S>::Zero();
    const Vec6<S>& q = v[std::size_t(link)];
    const Vec6<S>& qa = a[std::size_t(link)];
    const Vec3<S> w = q.template head<3>(), rd = Vec3<S>(q.template tail<3>() + w.cross(r));
    return Vec3<S>(qa.template tail<3>() + Vec3<S>(qa.template head<3>()).cross(r) + w.cross(rd));
  };
  for (int k = 0; k < numConstraints(); ++k) {
    const LoopConstraint<S>& q = cons_[std::size_t(k)];
    if (q.kind == LoopConstraint<S>::Kind::Point) {
      const Vec3<S> r = c.placements[std::size_t(q.linkA)] * q.homePoint;
      g(k) = q.direction.dot(Vec3<S>(pointAcc(q.linkA, r) - pointAcc(q.linkB, r)));
    } else {
      const Vec6<S> aB = q.linkB < 0 ? Vec6<S>::Zero() : a[std::size_t(q.linkB)];
      g(k) = q.wrench.dot(Vec6<S>(a[std::size_t(q.linkA)] - aB));
    }
  }
  return g;
}

// GF §14.3.2 lines 9070–9086, GF-14.3.2-parallel-mechanism-equations
template <class S>
ConstrainedForces<S> ConstrainedTree<S>::inverseDynamicsAlpha(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                              const DynVector<S>& thetaDDot, const DynMatrix<S>& B) const {
  const DynVector<S> tid = tree_.inverseDynamics(theta, thetaDot, thetaDDot);
  const DynMatrix<S> Z = freedomBasis(theta);
  ConstrainedForces<S> out;
  out.actuators = minimumNormSolve<S>(DynMatrix<S>(Z.transpose() * B), DynVector<S>(Z.transpose() * tid));
  const DynMatrix<S> Ct = constraintMatrix(theta).transpose();
  out.lambda = minimumNormSolve<S>(Ct, DynVector<S>(tid - B * out.actuators));
  out.residual = (B * out.actuators + Ct * out.lambda - tid).cwiseAbs().maxCoeff();
  return out;
}

template <class S>
ConstrainedForces<S> ConstrainedTree<S>::inverseDynamicsMultipliers(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                                    const DynVector<S>& thetaDDot, const DynMatrix<S>& B) const {
  const DynVector<S> tid = tree_.inverseDynamics(theta, thetaDot, thetaDDot);
  const DynMatrix<S> Ct = constraintMatrix(theta).transpose();
  DynMatrix<S> M(dof(), B.cols() + Ct.cols());
  M << B, Ct;
  const DynVector<S> x = minimumNormSolve<S>(M, tid);
  ConstrainedForces<S> out;
  out.actuators = x.head(B.cols());
  out.lambda = x.tail(Ct.cols());
  out.residual = (M * x - tid).cwiseAbs().maxCoeff();
  return out;
}

// GF §14.3.2 lines 9088–9100, GF-14.3.2-constraint-magnitude
template <class S>
DynVector<S> ConstrainedTree<S>::multipliersByDualVectors(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                          const DynVector<S>& thetaDDot, const DynVector<S>& tau) const {
  tree_.checkState(tau, "τ");
  const DynMatrix<S> C = constraintMatrix(theta);
  const int m = numConstraints();
  if (detail::smallNumericalRank<S>(C) < m)
    throw InvalidInput("ConstrainedTree::multipliersByDualVectors: the constraint matrix has rank < " + std::to_string(m) +
                       " (redundant constraints or a singular posture): the dual vectors do not exist");
  const DynVector<S> rhs = tree_.inverseDynamics(theta, thetaDot, thetaDDot) - tau;
  DynVector<S> lambda(m);
  for (int k = 0; k < m; ++k) {
    const DynVector<S> vk = minimumNormSolve<S>(C, DynVector<S>(DynVector<S>::Unit(m, k)));
    lambda(k) = vk.dot(rhs);
  }
  return lambda;
}

template <class S>
DynVector<S> ConstrainedTree<S>::forwardDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                 const DynVector<S>& tau) const {
  tree_.checkState(tau, "τ");
  const TreeConfiguration<S> c = tree_.configuration(theta);
  const DynMatrix<S> C = constraintMatrix(c);
  const DynVector<S> ddp = minimumNormSolve<S>(C, DynVector<S>(-accelerationBias(theta, thetaDot)));
  const DynMatrix<S> Z = nullSpace<S>(C);
  const DynMatrix<S> A = tree_.massMatrix(c);
  const DynVector<S> bias = tree_.inverseDynamics(theta, thetaDot, DynVector<S>::Zero(dof()));
  const DynMatrix<S> Ar = Z.transpose() * A * Z;
  const DynVector<S> rhs = Z.transpose() * (tau - bias - A * ddp);
  int rank = 0;
  const DynVector<S> u = minimumNormSolve<S>(Ar, rhs, &rank);
  if (rank < Ar.rows())
    throw InvalidInput("ConstrainedTree::forwardDynamics: the reduced mass matrix ZᵀAZ is singular (a freedom moves no mass)");
  return ddp + Z * u;
}

template <class S> ConstrainedState<S> ConstrainedTree<S>::project(const ConstrainedState<S>& y) const {
  ConstrainedState<S> out = y;
  const S tol = Tolerance<S>::identity(64);
  // Newton with the velocity constraint matrix C for the residual's Jacobian: exact for point constraints
  // (quadratic convergence), but for a fixed-wrench constraint Wᵀlog(K_A K_B⁻¹) C stands in for Wᵀdexp⁻¹J,
  // and the convergence is linear (rate ≈ 0.2 for the pen-holding 6R). A rate ≤ 1/2 gains a bit a sweep:
  // digits<S>() sweeps reach 64 ε from O(1) on every rung (20 ended at 2.7e-26 in __float128); near
  // rounding (residual below √ε) stop early when a sweep no longer reduces it.
  S last = S(0);
  for (int it = 0; it < digits<S>() + 20; ++it) {
    const DynVector<S> r = positionResidual(out.theta);
    if (r.size() == 0) break;
    const S res = r.cwiseAbs().maxCoeff();
    if (res <= tol || (it > 0 && res < Tolerance<S>::sqrtEpsilon() && !(res < last))) break;
    last = res;
    out.theta -= minimumNormSolve<S>(constraintMatrix(out.theta), r);
  }
  const DynMatrix<S> Z = freedomBasis(out.theta);
  out.thetaDot = Z * (Z.transpose() * out.thetaDot);
  return out;
}

template <class S>
ConstrainedState<S> ConstrainedTree<S>::rk4Step(const ConstrainedState<S>& y, const S& h, const DynVector<S>& tau,
                                                bool projectAfter) const {
  if (!isFinite(h) || !(h > S(0))) throw InvalidInput("ConstrainedTree::rk4Step: step " + toString(h) + " is not finite and positive");
  const S half = h / S(2);
  const DynVector<S> a1 = forwardDynamics(y.theta, y.thetaDot, tau);
  const DynVector<S> q2 = y.theta + half * y.thetaDot, v2 = y.thetaDot + half * a1;
  const DynVector<S> a2 = forwardDynamics(q2, v2, tau);
  const DynVector<S> q3 = y.theta + half * v2, v3 = y.thetaDot + half * a2;
  const DynVector<S> a3 = forwardDynamics(q3, v3, tau);
  const DynVector<S> q4 = y.theta + h * v3, v4 = y.thetaDot + h * a3;
  const DynVector<S> a4 = forwardDynamics(q4, v4, tau);
  const S sixth = h / S(6);
  ConstrainedState<S> out;
  out.theta = y.theta + sixth * (y.thetaDot + S(2) * v2 + S(2) * v3 + v4);
  out.thetaDot = y.thetaDot + sixth * (a1 + S(2) * a2 + S(2) * a3 + a4);
  return projectAfter ? project(out) : out;
}

}  // namespace soma

// Explicit instantiation for one scalar (the rule: cmake/SomaInstantiate.cmake).
#define SOMA_INSTANTIATE_CONSTRAINED_TREE(S)                                        \
  template class ConstrainedTree<S>;                                                \
  template DynVector<S> minimumNormSolve<S>(const DynMatrix<S>&, const DynVector<S>&, int*); \
  template DynMatrix<S> nullSpace<S>(const DynMatrix<S>&);
