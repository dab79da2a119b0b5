#pragma once
// Statics of a serial robot: GF §12.4, GF-12.4-joint-torques-to-wrench, GF-12.4-stiffness-compliance.
#include "soma/geometry/statics/robot_statics.hpp"

#include "soma/algebra/small_linalg.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <limits>

namespace soma {
namespace {
template <class S> void checkJacobian(const ScrewColumns<S>& J, const char* who) {
  if (J.cols() == 0) throw InvalidInput(std::string(who) + ": the Jacobian has no columns");
  if (!allFinite(J)) throw InvalidInput(std::string(who) + ": the Jacobian has a NaN or infinite entry");
}
}  // namespace

// GF §12.4, GF-12.4-joint-torques-to-wrench: w_i = 𝒲_tot(s_i), i.e. 𝒲ᵀ J = wᵀ.
template <class S> VecX<S> jointEfforts(const ScrewColumns<S>& J, const Wrench<S>& W) {
  checkJacobian(J, "jointEfforts");
  return J.transpose() * W.coeffs();
}

// GF §12.4, GF-12.4-joint-torques-to-wrench: 𝒲 = J⁻ᵀ w, by the SVD of Jᵀ (least squares).
template <class S> EndEffectorWrench<S> endEffectorWrench(const ScrewColumns<S>& J, const VecX<S>& w) {
  checkJacobian(J, "endEffectorWrench");
  if (w.size() != J.cols())
    throw InvalidInput("endEffectorWrench: " + std::to_string(w.size()) + " joint efforts for a Jacobian with " +
                       std::to_string(J.cols()) + " columns");
  if (!allFinite(w)) throw InvalidInput("endEffectorWrench: a joint effort is NaN or infinite");
  // Jᵀ = U Σ Vᵀ (n × 6): the columns of V are wrench directions, σ_k their joint-effort gains.
  using M = detail::SmallMat<S>;
  const M jt = J.transpose();
  M u, v;
  std::vector<S> sig;
  detail::smallSvd<S>(jt, u, sig, v);
  EndEffectorWrench<S> out;
  const S smax = sig.empty() ? S(0) : sig[0];
  Vec6<S> W = Vec6<S>::Zero();
  for (std::size_t k = 0; k < sig.size(); ++k) {
    if (smax > S(0) && sig[k] > Tolerance<S>::rank() * smax) {
      ++out.rank;
      W += (u.col(Eigen::Index(k)).dot(w) / sig[k]) * Vec6<S>(v.col(Eigen::Index(k)));
    } else {
      out.structureWrenches.push_back(Wrench<S>(Vec6<S>(v.col(Eigen::Index(k)))));
    }
  }
  out.condition = out.rank == 6 ? smax / sig[5] : std::numeric_limits<S>::infinity();
  out.wrench = Wrench<S>(W);
  out.residual = (J.transpose() * W - w).norm();
  return out;
}

// GF §12.4, GF-12.4-stiffness-compliance: 𝒲 = J⁻ᵀ K J⁻¹ δx.
template <class S> Mat6<S> cartesianStiffness(const ScrewColumns<S>& J, const VecX<S>& k) {
  checkJacobian(J, "cartesianStiffness");
  if (J.cols() != 6) throw InvalidInput("cartesianStiffness: needs a 6 × 6 Jacobian, got 6 × " + std::to_string(J.cols()));
  if (k.size() != 6) throw InvalidInput("cartesianStiffness: needs 6 joint stiffnesses, got " + std::to_string(k.size()));
  for (Eigen::Index i = 0; i < 6; ++i)
    if (!isFinite(k(i)) || !(k(i) > S(0)))
      throw InvalidInput("cartesianStiffness: joint stiffness k" + std::to_string(i + 1) + " = " + toString(k(i)) +
                         " is not a positive finite number");
  const Mat6<S> J6 = J;
  if (detail::smallNumericalRank<S>(detail::SmallMat<S>(J6)) < 6)
    throw InvalidInput("cartesianStiffness: the Jacobian is singular (rank < 6); use compliance()");
  const Mat6<S> Jinv = J6.inverse();
  const Mat6<S> Kx = Jinv.transpose() * k.asDiagonal() * Jinv;
  return (Kx + Kx.transpose()) / S(2);
}

// GF §12.4, GF-12.4-stiffness-compliance: C = J K⁻¹ Jᵀ (k = ∞: a rigid joint contributes 0).
template <class S> Mat6<S> compliance(const ScrewColumns<S>& J, const VecX<S>& k) {
  checkJacobian(J, "compliance");
  if (k.size() != J.cols())
    throw InvalidInput("compliance: " + std::to_string(k.size()) + " joint stiffnesses for " +
                       std::to_string(J.cols()) + " joints");
  VecX<S> inv(k.size());
  for (Eigen::Index i = 0; i < k.size(); ++i) {
    if (!(k(i) == k(i)) || !(k(i) > S(0)))
      throw InvalidInput("compliance: joint stiffness k" + std::to_string(i + 1) + " = " + toString(k(i)) +
                         " is not positive");
    inv(i) = isFinite(k(i)) ? S(1) / k(i) : S(0);
  }
  return J * inv.asDiagonal() * J.transpose();
}

// Generalised eigenproblem K s = λ Q₀ s. GF §12.4, GF-12.4-stiffness-compliance
template <class S> std::array<Eigenscrew<S>, 6> stiffnessEigenscrews(const Mat6<S>& K) {
  using std::abs;
  using std::sqrt;
  if (!allFinite(K)) throw InvalidInput("stiffnessEigenscrews: the stiffness has a NaN or infinite entry");
  const S scale = K.cwiseAbs().maxCoeff();
  if ((K - K.transpose()).cwiseAbs().maxCoeff() > Tolerance<S>::input() * scale)
    throw InvalidInput("stiffnessEigenscrews: the stiffness matrix is not symmetric");
  const Eigen::LLT<Mat6<S>> llt(K);
  if (llt.info() != Eigen::Success || !(scale > S(0)))
    throw InvalidInput("stiffnessEigenscrews: the stiffness matrix is not positive definite");
  const Mat6<S> L = llt.matrixL();
  Mat6<S> Q0 = Mat6<S>::Zero();
  Q0.template topRightCorner<3, 3>().setIdentity();
  Q0.template bottomLeftCorner<3, 3>().setIdentity();
  // Q₀ s = μ K s, s = L⁻ᵀ y  ⇒  L⁻¹ Q₀ L⁻ᵀ y = μ y (symmetric), λ = 1/μ (μ ≠ 0: Q₀ invertible).
  const Mat6<S> Linv = L.template triangularView<Eigen::Lower>().solve(Mat6<S>::Identity());
  const Mat6<S> B = Linv * Q0 * Linv.transpose();
  std::vector<S> mu;
  detail::SmallMat<S> Y;
  detail::smallSymEigen<S>(detail::SmallMat<S>(B), mu, Y);
  std::array<Eigenscrew<S>, 6> out;
  for (int i = 0; i < 6; ++i) {
    Vec6<S> s = Linv.transpose() * Vec6<S>(Y.col(i));
    const S q = s.dot(Q0 * s);  // = μ sᵀKs, nonzero
    s /= sqrt(abs(q));
    const SE3Tangent<S> t(s);
    const S ww = t.ang().squaredNorm();
    out[std::size_t(i)] = {S(1) / mu[std::size_t(i)], t,
                           ww > S(0) ? S(t.ang().dot(t.lin()) / ww) : std::numeric_limits<S>::infinity()};
  }
  return out;
}

#define SOMA_STATICS_ROBOT_INST(S)                                                                 \
  template VecX<S> jointEfforts<S>(const ScrewColumns<S>&, const Wrench<S>&);                      \
  template EndEffectorWrench<S> endEffectorWrench<S>(const ScrewColumns<S>&, const VecX<S>&);      \
  template Mat6<S> cartesianStiffness<S>(const ScrewColumns<S>&, const VecX<S>&);                  \
  template Mat6<S> compliance<S>(const ScrewColumns<S>&, const VecX<S>&);                          \
  template std::array<Eigenscrew<S>, 6> stiffnessEigenscrews<S>(const Mat6<S>&);

}  // namespace soma
