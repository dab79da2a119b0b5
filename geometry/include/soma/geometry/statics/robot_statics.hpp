#pragma once
// Statics of a serial robot (GF §12.4): the wrench at the end-effector from the joint efforts
// (𝒲ᵀ J = w), the joint stiffness model w_i = k_i δθ_i, the Cartesian stiffness J⁻ᵀ K J⁻¹ (a map
// from screws to co-screws), the compliance C = J K⁻¹ Jᵀ, and the eigenscrews of a stiffness.
// J is any 6 × n matrix whose columns are the joint screws in one frame (e.g.
// SerialRobot::spatialJacobian); the wrench is then in that frame.
#include "soma/geometry/statics/wrench.hpp"

#include <array>
#include <vector>

namespace soma {

template <class S> using ScrewColumns = Eigen::Matrix<S, 6, Eigen::Dynamic>;
template <class S> using VecX = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// Joint efforts w_i = 𝒲(s_i), i.e. w = Jᵀ 𝒲 (torques for R joints, forces for P joints).
/// GF §12.4, GF-12.4-joint-torques-to-wrench
template <class S> VecX<S> jointEfforts(const ScrewColumns<S>& J, const Wrench<S>& W);

/// The end-effector wrench that joint efforts w hold in static equilibrium.
template <class S> struct EndEffectorWrench {
  Wrench<S> wrench;          ///< least-squares, minimum-norm solution of Jᵀ 𝒲 = w
  int rank = 0;              ///< numerical rank of J (Tolerance::rank)
  S condition = S(0);        ///< σ_max/σ_min of J (infinite when rank < 6)
  S residual = S(0);         ///< ‖Jᵀ 𝒲 − w‖: nonzero when w has a part no wrench can balance
  std::vector<Wrench<S>> structureWrenches;  ///< basis of {𝒲 : Jᵀ 𝒲 = 0}: wrenches held by the
                                             ///< structure, unresolvable from the joint efforts
};
/// 𝒲 = J⁻ᵀ w for a non-singular 6 × 6 J; in general the SVD least-squares solution, with the
/// rank and the unresolvable wrench directions. GF §12.4, GF-12.4-joint-torques-to-wrench
template <class S> EndEffectorWrench<S> endEffectorWrench(const ScrewColumns<S>& J, const VecX<S>& w);

/// Cartesian stiffness J⁻ᵀ K J⁻¹ (K = diag k, k_i > 0): the wrench 𝒲 = K_x δx that holds the
/// displacement screw δx. InvalidInput if J is not 6 × 6 or is singular (rank < 6).
/// GF §12.4, GF-12.4-stiffness-compliance
template <class S> Mat6<S> cartesianStiffness(const ScrewColumns<S>& J, const VecX<S>& k);
/// Compliance C = J K⁻¹ Jᵀ: the displacement δx = C 𝒲 caused by a wrench. k_i = +∞ is a rigid
/// joint (1/k_i = 0); J may be singular or have n ≠ 6 columns. GF §12.4, GF-12.4-stiffness-compliance
template <class S> Mat6<S> compliance(const ScrewColumns<S>& J, const VecX<S>& k);

/// An eigenscrew of a stiffness: K s = λ Q₀ s with Q₀ = [[0, I], [I, 0]] (Q₀ s is the wrench on
/// the same screw axis as s with the same pitch): a displacement about s is held by a wrench on s.
template <class S> struct Eigenscrew {
  S stiffness;          ///< λ (signed: λ Q₀-pairs with s; sᵀ K s = λ sᵀQ₀s > 0)
  SE3Tangent<S> screw;  ///< s, scaled so |sᵀ Q₀ s| = 1
  S pitch;              ///< ω·v / ω·ω (of s and of its wrench)
};
/// The six eigenscrews of a symmetric positive definite 6 × 6 stiffness (Cholesky K = L Lᵀ, then
/// the symmetric L⁻¹ Q₀ L⁻ᵀ, so the eigenvalues are real and the screws K-orthogonal).
/// InvalidInput if K is not symmetric positive definite. GF §12.4 (stiffness as a map from screws
/// to co-screws), GF-12.4-stiffness-compliance
template <class S> std::array<Eigenscrew<S>, 6> stiffnessEigenscrews(const Mat6<S>& K);

}  // namespace soma
