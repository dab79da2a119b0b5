#pragma once
// Hybrid force/position control in coordinate-free form (GF §15.4, lines 9820–10069):
//  * the dual-basis projectors AB (twists onto the freedoms S) and XY (wrenches onto the
//    constraint wrenches W) of §15.4.3, built from a freedom basis z₁..zₙ and a complement
//    z_{n+1}..z₆, with their transformation laws Ã = H⁻¹A, B̃ = BH, X̃ = HᵀX, Ỹ = YH⁻ᵀ;
//  * the N₆-orthonormal projectors AAᵀN₆ and XXᵀN₆⁻¹ = N₆YᵀY of §15.4.4;
//  * the rigid-body covariant derivative N₆∇_V V = N₆V̇ + {V, N₆V}, its normal part N₆II(V, V)
//    (the second fundamental form: the wrench that maintains the constraint) and the multipliers
//    λ_j = z_jᵀN₆V̇ + VᵀN₆[z_j, V];
//  * the hybrid law's error signals q̇_e, q̈_e and the force torques τ^f_i = Σ_{j>n} W_dᵀz_j W_jᵀs_i.
// Conventions: screws (ω, v); wrenches (moment, force), paired by Wᵀs; {V, P} = −ad(V)ᵀP; H = Ad(g).
// Definitions and the five-scalar instantiation: geometry/src/riemannian/hybrid_control_impl.hpp (one scalar per TU).
#include "soma/geometry/riemannian/joint_space_geometry.hpp"

namespace soma {

template <class S> struct HybridProjectors {
  DgMatrix<S> A;  ///< 6×n, columns z₁..zₙ (freedom screws)
  DgMatrix<S> B;  ///< n×6, rows W₁ᵀ..Wₙᵀ (the complement W' of W, dual to the z_i)
  DgMatrix<S> X;  ///< 6×(6−n), columns W_{n+1}..W₆ (constraint wrenches)
  DgMatrix<S> Y;  ///< (6−n)×6, rows z_{n+1}ᵀ..z₆ᵀ (the complement S' of S)
  int freedoms() const { return int(A.cols()); }
  /// AB: projects a twist error onto the freedoms. GF §15.4.3 line 9926
  Mat6<S> motionProjector() const { return Mat6<S>(A * B); }
  /// XY: projects a wrench error onto the constraint wrenches. GF §15.4.3 line 9936
  Mat6<S> wrenchProjector() const { return Mat6<S>(X * Y); }
};

/// The dual bases of §15.4.3 from the freedoms Z (6×n, 0 < n < 6) and a complement S' (6×(6−n)):
/// [W₁..W₆] = [Z S']⁻ᵀ, so W_iᵀz_j = δ_ij. InvalidInput if the sizes are wrong or [Z S'] is
/// singular. GF §15.4.3 lines 9868–9936, GF-15.4.3-dual-bases-projection
template <class S> HybridProjectors<S> dualBasisProjectors(const DgMatrix<S>& freedoms, const DgMatrix<S>& complement);

/// The same operators after a passive change of coordinates s̃ = H⁻¹s, W̃ = HᵀW (H = Ad(g)):
/// Ã = H⁻¹A, B̃ = BH, X̃ = HᵀX, Ỹ = YH⁻ᵀ. GF §15.4.3 lines 9946–9954, GF-15.4.3-projection-transformation
template <class S> HybridProjectors<S> transformedProjectors(const HybridProjectors<S>& p, const Mat6<S>& H);

/// N₆-orthonormal bases (§15.4.4): z₁..zₙ span the freedoms, z_iᵀN₆z_j = δ_ij for all six,
/// W_j = N₆z_j (j > n). Then B = AᵀN₆, X = N₆Yᵀ, AB = AAᵀN₆ and XY = XXᵀN₆⁻¹ = N₆YᵀY.
/// InvalidInput if N₆ is not symmetric positive definite or Z is rank-deficient.
/// GF §15.4.4 lines 10004–10018, GF-15.4.4-N6-orthonormal-projections
template <class S> HybridProjectors<S> n6Projectors(const DgMatrix<S>& freedoms, const Mat6<S>& N6);

/// {V, P} = −ad(V)ᵀP. GF §13.1 (the coadjoint action used in §15.4.4)
template <class S> Vec6<S> coadjointBrace(const Vec6<S>& V, const Vec6<S>& P);
/// N₆∇_V V = N₆V̇ + {V, N₆V}: the total wrench on a free rigid body (spatial V, N₆ about the
/// origin). GF §15.4.4 line 9990, GF-15.4.4-second-fundamental-form
template <class S> Vec6<S> rigidBodyWrench(const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot);
/// N₆II(V, V) = XXᵀN₆⁻¹(N₆∇_V V): the constraint wrench (p from n6Projectors). GF §15.4.4 line 10022
template <class S>
Vec6<S> secondFundamentalWrench(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot);
/// λ_j = z_jᵀN₆V̇ + VᵀN₆[z_j, V] (j = n+1..6; corrected, erratum E15.9: line 10034 prints z_i with i
/// the first constraint index n+1 for every j, computed in studies/gf15/hybrid.cpp).
/// GF-15.4.4-constraint-multipliers
template <class S>
DgVector<S> constraintMultipliers(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot);

/// q̇_e = AAᵀN₆(q̇_d − q̇₆). GF §15.4.4 line 10045
template <class S>
Vec6<S> hybridVelocityError(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& qdDesired, const Vec6<S>& qd);
/// q̈_e = AAᵀN₆(q̈_d − q̈₆) + AAᵀ{q̇_e, N₆q̇_e}. GF §15.4.4 line 10053 (braces restored, erratum E15.10)
template <class S>
Vec6<S> hybridAccelerationError(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& qddDesired,
                                const Vec6<S>& qdd, const Vec6<S>& qe);
/// τ^f_i = Σ_{j=n+1}^{6} (W_dᵀz_j)(W_jᵀs_i) for the current joint screws J (6×m).
/// GF §15.4.4 line 10065 (corrected, erratum E15.9: j from n+1), GF-15.4.4-hybrid-control-law
template <class S> DgVector<S> forceControlTorque(const HybridProjectors<S>& p, const Vec6<S>& Wd, const DgMatrix<S>& J);

#define SOMA_HYBRID_CONTROL_EXTERN(S)                                                                             \
  extern template HybridProjectors<S> dualBasisProjectors<S>(const DgMatrix<S>&, const DgMatrix<S>&);            \
  extern template HybridProjectors<S> transformedProjectors<S>(const HybridProjectors<S>&, const Mat6<S>&);       \
  extern template HybridProjectors<S> n6Projectors<S>(const DgMatrix<S>&, const Mat6<S>&);                      \
  extern template Vec6<S> coadjointBrace<S>(const Vec6<S>&, const Vec6<S>&);                                    \
  extern template Vec6<S> rigidBodyWrench<S>(const Mat6<S>&, const Vec6<S>&, const Vec6<S>&);                   \
  extern template Vec6<S> secondFundamentalWrench<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&, \
                                                     const Vec6<S>&);                                           \
  extern template DgVector<S> constraintMultipliers<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&, \
                                                       const Vec6<S>&);                                          \
  extern template Vec6<S> hybridVelocityError<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&,     \
                                                 const Vec6<S>&);                                               \
  extern template Vec6<S> hybridAccelerationError<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&, \
                                                     const Vec6<S>&, const Vec6<S>&);                           \
  extern template DgVector<S> forceControlTorque<S>(const HybridProjectors<S>&, const Vec6<S>&, const DgMatrix<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_HYBRID_CONTROL_EXTERN)
#undef SOMA_HYBRID_CONTROL_EXTERN

}  // namespace soma
