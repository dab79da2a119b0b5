#pragma once
// Mobility of single-loop mechanisms (GF §15.2, lines 9623–9704): the Kutzbach–Grübler count, the
// infinitesimal mobility n − dim Span(s_i), the completion algebra Δ∞ (iterated brackets to
// closure) and m = n − dim Δ∞, the subalgebra test (full-cycle mobility ⟺ Δ = Δ∞, totally
// geodesic image), the ten subalgebras of Table 15.1, and — as the paradoxical check — the Bennett
// 4R loop built from its standard conditions, whose solution set is traced numerically.
// Definitions and the five-scalar instantiation: geometry/src/riemannian/mobility_impl.hpp (one scalar per TU).
#include "soma/geometry/riemannian/joint_space_geometry.hpp"

#include <string>

namespace soma {

/// Kutzbach–Grübler: m = d(links − joints − 1) + Σ f_i (links include the ground; d = 6 spatial,
/// 3 planar/spherical). A single loop of n one-freedom joints (links = joints = n): m = n − d.
/// GF §15.2 line 9645, GF-15.2-loop-equation-kutzbach. InvalidInput for negative counts or d ∉ {3, 6}.
int kutzbachGrubler(int links, int joints, int sumJointFreedoms, int d = 6);

/// Numerical dimension of Span(s₁, …, sₙ) (singular values of [s₁ … sₙ] above Tolerance::rank()).
template <class S> int screwSystemDimension(const std::vector<Vec6<S>>& screws);
/// Infinitesimal mobility of the loop at θ = 0: n − dim Span(s_i) (the kernel of Σθ̇_is_i = 0).
/// GF §15.2 lines 9631, 9647, GF-15.2-mobility-definitions
template <class S> int infinitesimalMobility(const std::vector<Vec6<S>>& screws);
/// An orthonormal basis (columns) of the completion algebra Δ∞: the span of the s_i and all their
/// iterated brackets. GF §15.2 line 9658, GF-15.2-completion-group-mobility
template <class S> ScrewMatrix<S> completionAlgebra(const std::vector<Vec6<S>>& screws);
/// The loop mobility predicted from the completion group, m = n − dim Δ∞ (generic; the Bennett
/// loop is the exception). GF §15.2 line 9660
template <class S> int completionMobility(const std::vector<Vec6<S>>& screws);
/// Δ₁ = Span(s_i) is closed under the bracket: [s_i, s_k] ∈ Δ₁ for all i < k (then Δ₁ = Δ∞).
/// GF §15.2 line 9680, GF-15.2-totally-geodesic-subalgebra
template <class S> bool isSubalgebra(const std::vector<Vec6<S>>& screws);
/// max_{i<k} of the distance of [s_i, s_k] from Δ₁ (0 for a subalgebra): the residual behind isSubalgebra.
template <class S> S subalgebraDefect(const std::vector<Vec6<S>>& screws);

/// One row of Table 15.1: completion group, Gibson–Hunt type, normal-form basis.
template <class S> struct SubalgebraRow {
  std::string group, huntType;
  std::vector<Vec6<S>> basis;
};
/// The ten screw systems of Table 15.1 (p ≠ 0 is the pitch of the H_p rows). GF §15.2 lines 9688–9704,
/// GF-15.2-table-15.1. InvalidInput if p = 0 or not finite (the H_p rows would repeat SO(2) rows).
template <class S> std::vector<SubalgebraRow<S>> table15_1(const S& p);

/// Joint screws of a closed Bennett 4R loop at the configuration θ₁ (standard DH Rz(θ)Tx(a)Rx(α)):
/// a₁ = a₃ = a, a₂ = a₄ = b = a sin β / sin α, α₁ = α₃ = α, α₂ = α₄ = β, d_i = 0, closed at
/// tan(θ₁/2) tan(θ₂/2) = sin((β+α)/2)/sin((β−α)/2), θ₃ = −θ₁, θ₄ = −θ₂ (Bennett's conditions; not in
/// GF). The returned screws are the home screws s_i(0) of the loop equation at that configuration.
/// InvalidInput if α, β ∉ (0, π), α = β, or a ≤ 0. GF §15.2 line 9682 (paradoxical mechanisms)
template <class S> std::vector<Vec6<S>> bennettLoop(const S& a, const S& alpha, const S& beta, const S& theta1);

/// |log ρ(θ)| (max-norm) of the loop equation e^{θ₁s₁}···e^{θₙsₙ} = I. GF §15.2 line 9635
template <class S> S loopResidual(const std::vector<Vec6<S>>& screws, const DgVector<S>& theta);

/// The solution set of the loop equation traced from θ = 0 by predictor (unit kernel vector of
/// J(θ)) and Gauss–Newton corrector. `kernelDimension` is the kernel dimension of J at θ = 0;
/// tracing is attempted only when it is 1. `closed` says whether every corrector reached
/// |log ρ| ≤ Tolerance::identity(1024); `maxResidual` is the worst one; `path` holds θ per step.
template <class S> struct LoopTrace {
  int kernelDimension = 0;
  bool closed = false;
  S maxResidual = S(0);
  std::vector<DgVector<S>> path;
};
template <class S> LoopTrace<S> traceLoop(const std::vector<Vec6<S>>& screws, const S& stepLength, int steps);

#define SOMA_MOBILITY_EXTERN(S)                                                                           \
  extern template int screwSystemDimension<S>(const std::vector<Vec6<S>>&);                              \
  extern template int infinitesimalMobility<S>(const std::vector<Vec6<S>>&);                             \
  extern template ScrewMatrix<S> completionAlgebra<S>(const std::vector<Vec6<S>>&);                      \
  extern template int completionMobility<S>(const std::vector<Vec6<S>>&);                                \
  extern template bool isSubalgebra<S>(const std::vector<Vec6<S>>&);                                     \
  extern template S subalgebraDefect<S>(const std::vector<Vec6<S>>&);                                    \
  extern template std::vector<SubalgebraRow<S>> table15_1<S>(const S&);                                  \
  extern template std::vector<Vec6<S>> bennettLoop<S>(const S&, const S&, const S&, const S&);           \
  extern template S loopResidual<S>(const std::vector<Vec6<S>>&, const DgVector<S>&);                    \
  extern template LoopTrace<S> traceLoop<S>(const std::vector<Vec6<S>>&, const S&, int);
SOMA_FOR_EACH_SCALAR(SOMA_MOBILITY_EXTERN)
#undef SOMA_MOBILITY_EXTERN

}  // namespace soma
