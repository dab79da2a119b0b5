#pragma once
// The geometry of SE(3) pulled back to the joint space of a serial robot (GF §15.1, lines 9529–9621):
// forward kinematics ρ(θ) = e^{θ₁s₁}···e^{θₙsₙ}, the current joint screws s_i(θ) (the spatial
// Jacobian), the pull-back metric JᵀQ_pJ, the covariant derivative ∇_U V, the geodesic equation
// θ̈_i + Σ_{j<k} W_i([s_j, s_k]) θ̇_jθ̇_k = 0, the Christoffel symbols in the book's form and as the
// Levi-Civita symbols of JᵀQ_pJ, a geodesic integrator, and the pulled-back Maurer–Cartan form.
//
// The co-screws W_i (rows of J⁻¹) need a 6-joint robot at a non-singular configuration: otherwise
// InvalidInput naming the configuration and σ_min/σ_max of J (never a NaN).
// Definitions and the five-scalar instantiation: geometry/src/riemannian/joint_space_geometry_impl.hpp (one scalar per TU: joint_space_geometry_<scalar>.cpp).
#include "soma/geometry/riemannian/invariant_metric.hpp"

#include <Eigen/Core>
#include <vector>

namespace soma {

template <class S> using DgVector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <class S> using DgMatrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S> using ScrewMatrix = Eigen::Matrix<S, 6, Eigen::Dynamic>;

template <class S> class JointSpaceGeometry {
 public:
  /// n ≥ 1 home joint screws s_i(0) (any pitch, finite). InvalidInput for n = 0 or a NaN.
  explicit JointSpaceGeometry(std::vector<Vec6<S>> homeScrews, InvariantMetric<S> metric = {});

  int dof() const { return int(home_.size()); }
  const std::vector<Vec6<S>>& homeScrews() const { return home_; }
  const InvariantMetric<S>& metric() const { return Q_; }

  /// ρ(θ) = e^{θ₁s₁}···e^{θₙsₙ}. GF §15.1 line 9533
  SE3<S> forward(const DgVector<S>& theta) const;
  /// The current screws as columns: s_i(θ) = Ad(e^{θ₁s₁}···e^{θ_{i−1}s_{i−1}}) s_i(0), i.e. the
  /// spatial Jacobian J(θ). GF §15.1 line 9547 (corrected, erratum E15.3: the adjoint form).
  ScrewMatrix<S> screws(const DgVector<S>& theta) const;
  /// ∂s_j/∂θ_i = [s_i, s_j] for i < j, 0 otherwise: D[i] is the 6×n matrix of ∂s_·/∂θ_i.
  /// GF §15.1 line 9551, GF-15.1-joint-space-pullback-metric
  std::vector<ScrewMatrix<S>> screwDerivatives(const ScrewMatrix<S>& J) const;

  /// The pull-back metric Q_p* = JᵀQ_pJ. GF §15.1 line 9537
  DgMatrix<S> pullbackMetric(const DgVector<S>& theta) const;
  /// ∂_i(JᵀQJ)_jk = Q(∂_is_j, s_k) + Q(s_j, ∂_is_k): dG[i](j, k).
  std::vector<DgMatrix<S>> pullbackMetricDerivative(const DgVector<S>& theta) const;

  /// The co-screws W_i as the rows of J⁻¹ (n = 6). InvalidInput if n ≠ 6 or J is singular
  /// (σ_min/σ_max ≤ Tolerance::rank()). GF §15.1 line 9571
  DgMatrix<S> coScrews(const ScrewMatrix<S>& J) const;

  /// Γ[i](j, k) = Γ^i_jk = ½W_i([s_min(j,k), s_max(j,k)]) (0 for j = k): the book's case formula,
  /// symmetric in j, k (erratum E15.1: the book's "anti-symmetric" reading ½W_i([s_j, s_k]) for all
  /// j, k is computed in studies/gf15/metric.cpp). GF §15.1 line 9581, GF-15.1-joint-space-christoffel
  std::vector<DgMatrix<S>> christoffelBook(const DgVector<S>& theta) const;
  /// The Levi-Civita symbols Γ^i_jk = ½G^{il}(∂_jG_lk + ∂_kG_lj − ∂_lG_jk) of G = JᵀQ_pJ (analytic
  /// ∂G from the brackets). InvalidInput if G is singular (n ≠ 6, singular J, or α = 0).
  std::vector<DgMatrix<S>> christoffelLeviCivita(const DgVector<S>& theta) const;

  /// Σ_{i<j} θ̇_iθ̇_j[s_i, s_j]: the velocity-product part of q̈₆. GF §15.1 line 9567 (corrected,
  /// erratum E15.2: θ̇_iθ̇_j).
  Vec6<S> velocityProductTerm(const ScrewMatrix<S>& J, const DgVector<S>& thetaDot) const;
  /// q̈₆ = Σ θ̈_i s_i + Σ_{i<j} θ̇_iθ̇_j[s_i, s_j] = ∇_U U, the spatial end-effector acceleration.
  Vec6<S> endEffectorAcceleration(const DgVector<S>& theta, const DgVector<S>& thetaDot,
                                  const DgVector<S>& thetaDDot) const;
  /// ∇_U V with U = Jθ̇, V = Jφ̇: Σφ̈_is_i + ½Σ_{i<k}θ̇_iφ̇_k[s_i,s_k] − ½Σ_{k<i}θ̇_iφ̇_k[s_i,s_k].
  /// GF §15.1 line 9563, GF-15.1-joint-space-covariant-derivative
  Vec6<S> covariantDerivative(const DgVector<S>& theta, const DgVector<S>& thetaDot, const DgVector<S>& phiDot,
                              const DgVector<S>& phiDDot) const;
  /// θ̈ of the geodesic: θ̈_i = −Σ_{j<k} W_i([s_j, s_k]) θ̇_jθ̇_k (n = 6, non-singular).
  /// GF §15.1 line 9575, GF-15.1-joint-space-geodesic-equation
  DgVector<S> geodesicAcceleration(const DgVector<S>& theta, const DgVector<S>& thetaDot) const;
  /// One classical RK4 step of length h on the geodesic equation (θ, θ̇) ↦ (θ, θ̇)(h).
  void geodesicStep(DgVector<S>& theta, DgVector<S>& thetaDot, const S& h) const;

  /// ρ*Ω = Σ s_i ⊗ dθ_i: column i is the Lie-algebra value on ∂/∂θ_i (= s_i(θ)).
  /// GF §15.1 line 9615, GF-15.1-maurer-cartan-pullback
  ScrewMatrix<S> maurerCartanPullback(const DgVector<S>& theta) const { return screws(theta); }
  /// d(ρ*Ω)(∂_i, ∂_j) = ∂_i s_j − ∂_j s_i = [s_i, s_j] (i < j): the structure equation
  /// dΩ = +½[Ω, Ω] of the right-invariant form dg g⁻¹ (erratum E15.14). Entry (i, j) of the
  /// returned n×n table, i < j (the others are zero).
  std::vector<std::vector<Vec6<S>>> maurerCartanDifferential(const DgVector<S>& theta) const;

 private:
  void checkTheta(const DgVector<S>& theta, const char* what) const;
  std::vector<Vec6<S>> home_;
  InvariantMetric<S> Q_;
};

#define SOMA_JOINT_SPACE_GEOMETRY_EXTERN(S) extern template class JointSpaceGeometry<S>;
SOMA_FOR_EACH_SCALAR(SOMA_JOINT_SPACE_GEOMETRY_EXTERN)
#undef SOMA_JOINT_SPACE_GEOMETRY_EXTERN

}  // namespace soma
