#pragma once
// Serial-robot dynamics in the form of GF chapter 13: joint screws s_i(θ) and link inertias N_i(θ)
// in ONE fixed inertial frame, the equations of motion τ_i = A_ij θ̈_j + B_ijk θ̇_j θ̇_k + C_i
// (GF §13.2.2, corrected: errata 1 and 2 of the catalogue), the payload increments (§13.2.3), the
// recursive Newton–Euler algorithm in home-position coordinates (§13.3), the Lagrangian energies
// and the gradient of E_K (§13.4), the Hessian of E_P (§13.4.3, corrected: erratum 8) and the
// Hamiltonian vector field in canonical coordinates (θ, π) (§13.5, corrected: erratum 10).
//
// Conventions (GF ch. 13, catalogue "conventions to copy exactly"): screws s = (ω, v),
// ad(s) = [[Ω, 0], [V, Ω]], [s₁, s₂] = ad(s₁) s₂; co-screws (moment, force); the gravity screw is
// g = (0, −g k) (gravity along −z of the base frame, g ≥ 0); N_i is the 6×6 inertia about the
// ORIGIN of the fixed frame. The joint variable θ_i is the angle (or slide) away from the home
// configuration at which the home screws s_i⁰ and home inertias N_i⁰ are given.
//
// The model is independent of how the chain was described (DH, POE): build it from the home joint
// screws and the home link inertias (robot_dynamics.hpp converts a SerialRobot plus link data).
// Everything is defined in serial_dynamics_impl.hpp and instantiated for the five scalars in
// geometry/src/dynamics/serial_dynamics.cpp.
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#include <Eigen/Core>
#include <vector>

namespace soma {

template <class S> using DynVector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <class S> using DynMatrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// The chain at one configuration θ, all in the fixed frame (GF §13.2.2, §13.3 line 7965).
template <class S> struct ChainConfiguration {
  std::vector<SE3<S>> placements;   ///< G_i = exp(θ₁s₁⁰)···exp(θ_i s_i⁰): link i's motion from home
  std::vector<Vec6<S>> screws;      ///< s_i(θ) = Ad(G_i) s_i⁰
  std::vector<Mat6<S>> inertias;    ///< N_i(θ) = G_i⁻ᵀ N_i⁰ G_i⁻¹ (coadjoint)
  std::vector<Mat6<S>> tails;       ///< N̄_i = N_i + … + N_n
};

/// The payload increments A^p, B^p, C^p of GF §13.2.3 (B^p as B[i](j, k) = B^p_ijk).
template <class S> struct PayloadTerms {
  DynMatrix<S> A;
  std::vector<DynMatrix<S>> B;
  DynVector<S> C;
};

template <class S> class SerialDynamics {
 public:
  /// n joints: home screws s_i⁰ (unit: |ω| = 1 for a revolute or screw joint, ω = 0 and |v| = 1 for
  /// a prismatic one) and the home inertias of the n moving links, gravity g ≥ 0 along −z.
  /// InvalidInput for n = 0, mismatched counts, a non-unit or NaN screw, a NaN or negative g.
  /// A massless link cannot be given: SpatialInertia rejects mass ≤ 0 (GF-13.1 extreme m → 0).
  SerialDynamics(std::vector<SE3Tangent<S>> homeScrews, std::vector<SpatialInertia<S>> homeLinks,
                 const S& gravity);

  int dof() const { return int(screws_.size()); }
  const std::vector<SE3Tangent<S>>& homeScrews() const { return screws_; }
  const std::vector<SpatialInertia<S>>& homeLinks() const { return links_; }
  const std::vector<Mat6<S>>& homeInertias() const { return N0_; }
  const S& gravity() const { return g_; }
  /// g = (0, 0, 0, 0, 0, −g). GF §13.2.2 line 7857
  Vec6<S> gravityScrew() const;
  /// The same robot carrying a payload rigidly fixed to the last link (its home inertia added to
  /// N_n⁰). GF §13.2.3
  SerialDynamics withPayload(const SpatialInertia<S>& payloadHome) const;
  SerialDynamics withGravity(const S& gravity) const;

  /// Screws, inertias and tail sums at θ. InvalidInput if θ has the wrong size or a NaN.
  ChainConfiguration<S> configuration(const DynVector<S>& theta) const;
  /// Link velocities q̇_i = Σ_{j≤i} θ̇_j s_j (GF §13.2.2 line 7865).
  std::vector<Vec6<S>> linkVelocities(const ChainConfiguration<S>& c, const DynVector<S>& thetaDot) const;
  /// Link accelerations q̈_i = Σ_{j≤i} θ̈_j s_j + Σ_{k<l≤i} θ̇_k θ̇_l [s_k, s_l] (line 7873, erratum 15).
  std::vector<Vec6<S>> linkAccelerations(const ChainConfiguration<S>& c, const DynVector<S>& thetaDot,
                                         const DynVector<S>& thetaDDot) const;

  /// A_ij = s_iᵀ N̄_max(i,j) s_j. GF §13.2.2 lines 7877–7887, GF-13.2.2-generalised-inertia-A
  DynMatrix<S> massMatrix(const DynVector<S>& theta) const;
  DynMatrix<S> massMatrix(const ChainConfiguration<S>& c) const;
  /// B[i](j, k) = B_ijk with x = max(i, j, k):
  /// ½(s_jᵀN̄_x[s_i,s_k] + s_kᵀN̄_x[s_i,s_j] − s_iᵀN̄_x[s_max(j,k), s_min(j,k)]).
  /// GF §13.2.2 lines 7889–7895, GF-13.2.2-coriolis-B (corrected, erratum 2: the book prints the
  /// third terms [s_k, s_i] (j ≤ k) and [s_i, s_k] (k < j); studies/gf13/equations.cpp computes them).
  std::vector<DynMatrix<S>> coriolisTensor(const DynVector<S>& theta) const;
  std::vector<DynMatrix<S>> coriolisTensor(const ChainConfiguration<S>& c) const;
  /// C_i = −s_iᵀ N̄_i g = ∂E_P/∂θ_i. GF §13.2.2 line 7899, GF-13.2.2-gravity-C (corrected,
  /// erratum 1: the book prints +s_iᵀ N̄_i g; studies/gf13/equations.cpp computes it).
  DynVector<S> gravityTorque(const DynVector<S>& theta) const;
  DynVector<S> gravityTorque(const ChainConfiguration<S>& c) const;
  /// τ = A θ̈ + B θ̇ θ̇ + C from the closed form (O(n³) through the tensor B). GF §13.2.2
  DynVector<S> inverseDynamicsClosedForm(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                         const DynVector<S>& thetaDDot) const;
  /// τ_i = Σ_{j≥i} ((q̈_j − g)ᵀ N_j s_i + q̇_jᵀ N_j [s_i, q̇_j]): the spatial formula of GF §13.2.2
  /// line 7861 (GF-13.2.2-gravity-wrench), O(n²).
  DynVector<S> inverseDynamicsSpatial(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                      const DynVector<S>& thetaDDot) const;
  /// The recursive Newton–Euler algorithm of GF §13.3 (box at lines 8041–8065), in home-position
  /// coordinates: H_i = exp(θ_i s_i⁰) is the only transform per joint; O(n). GF-13.3-recursive-newton-euler
  DynVector<S> inverseDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                               const DynVector<S>& thetaDDot) const;
  /// The same into caller storage (no allocation when tau has size n): the benchmark path.
  void inverseDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                       const DynVector<S>& thetaDDot, DynVector<S>& tau) const;

  /// E_K = ½ Σ q̇_iᵀ N_i q̇_i from the link velocities (not from A). GF §13.1, §13.4
  S kineticEnergy(const DynVector<S>& theta, const DynVector<S>& thetaDot) const;
  /// E_P = Σ m_i g z_i (c.o.m. heights). GF §13.4 (corrected, erratum 3: the book prints
  /// E_P = Σ g̃ᵀc̃_i, which is −Σ m_i g z_i; studies/gf13/lagrange.cpp computes it).
  S potentialEnergy(const DynVector<S>& theta) const;
  /// ∂E_K/∂θ_i = −(Σ_{j≥i} N_j q̇_j)ᵀ [s_i, q̇_i] = B_jik θ̇_j θ̇_k, from the partials of GF §13.4.1
  /// (∂q̇_j/∂θ_i = [s_i, q̇_j − q̇_i], ∂N_j/∂θ_i = −ad(s_i)ᵀN_j − N_j ad(s_i), i ≤ j; errata 4, 5).
  DynVector<S> kineticEnergyGradient(const DynVector<S>& theta, const DynVector<S>& thetaDot) const;
  /// Q_ij = ∂²E_P/∂θ_i∂θ_j = s_aᵀ N̄_a [s_b, g], a = max(i, j), b = min(i, j).
  /// GF §13.4.3 lines 8206–8210 (corrected, erratum 8: the book prints s_aᵀN̄_a[g, s_b];
  /// studies/gf13/lagrange.cpp computes it).
  DynMatrix<S> potentialHessian(const DynVector<S>& theta) const;
  /// A^p, B^p, C^p of a payload of home inertia N_p⁰ on the last link. GF §13.2.3 (C^p corrected,
  /// erratum 1: −s_iᵀN_p g).
  PayloadTerms<S> payloadTerms(const DynVector<S>& theta, const SpatialInertia<S>& payloadHome) const;

  /// θ̈ solving A θ̈ = τ − (B θ̇ θ̇ + C) (bias from RNEA with θ̈ = 0, A by Cholesky).
  /// InvalidInput if A is not positive definite (cannot happen for valid links; NaN input).
  DynVector<S> forwardDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                               const DynVector<S>& tau) const;

  /// Canonical momenta π = A θ̇ (GF §13.5 line 8269).
  DynVector<S> momentum(const DynVector<S>& theta, const DynVector<S>& thetaDot) const;
  /// θ̇ = A⁻¹ π.
  DynVector<S> velocity(const DynVector<S>& theta, const DynVector<S>& momentum) const;
  /// h(θ, π) = ½ πᵀA⁻¹π + E_P (GF §13.5 line 8279).
  S hamiltonian(const DynVector<S>& theta, const DynVector<S>& momentum) const;
  /// Hamilton's equations: θ̇ = ∂h/∂π = A⁻¹π, π̇ = −∂h/∂θ + τ = B_jik θ̇_j θ̇_k − C_i + τ_i.
  /// GF §13.5 lines 8289, 8345 (corrected, erratum 10).
  void hamiltonField(const DynVector<S>& theta, const DynVector<S>& momentum, const DynVector<S>& tau,
                     DynVector<S>& thetaDot, DynVector<S>& momentumDot) const;

 private:
  void checkState(const DynVector<S>& v, const char* what) const;
  std::vector<SE3Tangent<S>> screws_;
  std::vector<SpatialInertia<S>> links_;
  std::vector<Mat6<S>> N0_;
  std::vector<bool> revolute_;
  S g_;
};

#define SOMA_SERIAL_DYNAMICS_EXTERN(S) extern template class SerialDynamics<S>;
SOMA_FOR_EACH_SCALAR(SOMA_SERIAL_DYNAMICS_EXTERN)
#undef SOMA_SERIAL_DYNAMICS_EXTERN

}  // namespace soma
