#pragma once
// Gibson–Hunt classification of screw systems (GF ch. 8, Tables 8.1 and 8.2) and the
// identification of any basis: type, parameters and the canonical frame g with
// span(Ad(g)·normal form) = the input.
//
// The identification does NOT use the book's polynomial invariants i₄, i₅ (not rigid
// invariants, erratum E8.3) nor Table 8.4 as printed (IC rows wrong, E8.9). It reduces the system
// geometrically (GF §8.2.7, §8.3.6): the ω-projection rank r, the translation subspace
// T = Δ ∩ {(0, v)}, the principal pitches (eigenvalues of the symmetric pitch matrix
// u_i·v_j on an orthonormal ω-basis) and the angle between T and the ω-directions.
//  n = 2: r = 0 IIC; r = 1 IB⁰ (t ∥ ω), IB(p = tan∠(ω, t)), IIB(h) (t ⟂ ω); r = 2 IA(p_a > p_b), IIA(p).
//  n = 3: r = 0 IID; r = 1 IC⁰ (ω ∈ T), IC(p = tan∠(ω, T)), IIC(h) (ω ⟂ T);
//         r = 2 IB₀(p_a, p_b = tan∠(t, W)) when t ∉ W^⟂, else IB₃(p_a > p_b) / IIB(p);
//         r = 3 IA₁(p_a > p_b > p_c), IA₂(p_a single, p_b double), IIA(p).
//  n = 1, 5: pitch (0, finite, ∞) of the screw / of the reciprocal screw; n = 4: the type of
//  the reciprocal 2-system (GF §8.1: 4-systems ↔ reciprocal 2-systems).
#include "soma/geometry/screws/screw_system.hpp"

#include <array>
#include <string>

namespace soma {

/// One row of GF Tables 8.1/8.2 (plus 0-, 1- and 6-systems). 4- and 5-systems are reported by
/// the type of their reciprocal 2- or 1-system (ScrewSystemIdentification::viaReciprocal).
enum class ScrewSystemType {
  Zero,            ///< {0}
  Line,            ///< 1-system, pitch 0
  Screw,           ///< 1-system, finite pitch p ≠ 0            params {p}
  Translation,     ///< 1-system, pitch ∞
  IIC_2,           ///< R²: (0,i), (0,j)
  IB0sup_2,        ///< IB⁰, SO(2)×R: (i,0), (0,i)
  IIA0_2,          ///< IIA(p=0), SO(3): (i,0), (j,0)
  IIBp_2,          ///< IIB(p≠0), H_p⋉R²: (i,p i), (0,j)          params {p}
  IIB0_2,          ///< IIB(p=0), SE(2): (i,0), (0,j)
  IBp_2,           ///< IB(p≠0), SE(2)×R: (i,0), (0, i+p j)       params {p > 0}
  IIAp_2,          ///< IIA(p≠0), SE(3): (i,p i), (j,p j)         params {p}
  IA_2,            ///< IA, SE(3): (i,p_a i), (j,p_b j)           params {p_a > p_b}
  IID_3,           ///< R³
  IIA0_3,          ///< IIA(p=0), SO(3)
  IIC0_3,          ///< IIC(p=0), SE(2): (i,0), (0,j), (0,k)
  IICp_3,          ///< IIC(p≠0): (i,p i), (0,j), (0,k)           params {p}
  ICp_3,           ///< IC(p≠0): (i,0), (0,j), (0, i+p k)         params {p > 0}
  IC0_3,           ///< IC⁰: (i,0), (0,j), (0,i)
  IIB_3,           ///< IIB: (i,p i), (j,p j), (0,k)              params {p}
  IB0_3,           ///< IB₀: (i,p_a i), (j,p_a j), (0, i+p_b k)  params {p_a, p_b ≥ 0}
  IB3_3,           ///< IB₃: (i,p_a i), (j,p_b j), (0,k)         params {p_a > p_b}
  IIAp_3,          ///< IIA(p≠0): (e_i, p e_i)                   params {p}
  IA2_3,           ///< IA₂: (i,p_a i), (j,p_b j), (k,p_b k)     params {p_a, p_b}
  IA1_3,           ///< IA₁: (e_i, p_i e_i)                      params {p_a > p_b > p_c}
  Whole,           ///< se(3)
  Unknown
};

/// Name as in the book's tables, e.g. "IIA(p=0)", "IB₀".
std::string screwSystemTypeName(ScrewSystemType t);
/// Dimension of the normal form of a type (1, 2 or 3; 0 for Zero, 6 for Whole).
int screwSystemTypeDimension(ScrewSystemType t);
/// Number of continuous parameters of a type.
int screwSystemTypeParameterCount(ScrewSystemType t);

/// A decision taken by the identification: `value` compared with `tolerance`.
template <class S> struct ScrewSystemDecision {
  std::string quantity;  ///< e.g. "|p_a − p_b|", "σ₂(Ω)", "|u·t|"
  S value{0};
  S tolerance{0};
  bool nonzero{false};   ///< value > tolerance
};

template <class S> struct ScrewSystemIdentification {
  int dimension{0};
  ScrewSystemType type{ScrewSystemType::Unknown};  ///< for n = 4, 5: the reciprocal's type
  bool viaReciprocal{false};                       ///< n = 4, 5
  std::array<S, 3> parameters{};                   ///< see ScrewSystemType
  int parameterCount{0};
  SE3<S> frame;                  ///< span(Ad(frame)·normalForm) = the input system
  ScrewBasis<S> normalForm;      ///< the normal form basis (6 × n; the reciprocal of the 2-/1-system normal form for n = 4, 5)
  S frameResidual{0};            ///< distance (largest principal-angle sine) of Ad(frame)·normalForm from the input
  std::vector<ScrewSystemDecision<S>> decisions;
  /// The type obtained by flipping the decision whose value is nearest its tolerance (in
  /// ratio), and that decision's value: the input lies that far (in the units of the
  /// quantity) from the boundary with that type. Unknown / +∞ when every deciding quantity is
  /// exactly 0 (the input is exactly of a most special type).
  ScrewSystemType nearestOtherType{ScrewSystemType::Unknown};
  S boundaryDistance{0};
  std::string boundaryQuantity;
  std::string name() const;  ///< e.g. "IA(p_a = 0.7, p_b = −0.3)" or "4-system reciprocal to IIC"
};

/// Normal form (GF Tables 8.1, 8.2) of a type with its parameters (6 × dim).
// GF §8.2–8.3, GF-8.2-normal-forms-2-systems, GF-8.3-normal-forms-3-systems
template <class S>
ScrewBasis<S> screwSystemNormalForm(ScrewSystemType t, const std::array<S, 3>& params);

/// Identify a system: type, parameters, canonical frame, distance to the nearest other type.
// GF §8.2.7, §8.3.6, §8.4; GF-8.4.2-extra-invariants-table-8.3 and GF-8.4.4-3-system-invariants
// (corrected: errata E8.3, E8.9, E8.10 avoided by a geometric reduction)
template <class S> ScrewSystemIdentification<S> identifyScrewSystem(const ScrewSystem<S>& system);
/// Identify span(generators) (6 × k, any k; rank from Tolerance::rank()).
template <class S>
ScrewSystemIdentification<S> identifyScrewSystem(const ScrewMatX<S>& generators) {
  return identifyScrewSystem(ScrewSystem<S>(generators));
}

#define SOMA_SCREW_ID_EXTERN(S)                                                              \
  extern template ScrewBasis<S> screwSystemNormalForm<S>(ScrewSystemType,                    \
                                                         const std::array<S, 3>&);           \
  extern template ScrewSystemIdentification<S> identifyScrewSystem<S>(const ScrewSystem<S>&); \
  extern template struct ScrewSystemIdentification<S>;
SOMA_FOR_EACH_SCALAR(SOMA_SCREW_ID_EXTERN)
#undef SOMA_SCREW_ID_EXTERN

}  // namespace soma

#ifdef SOMA_SCREW_IDENTIFICATION_IMPL
#include "soma/geometry/screws/identification_impl.hpp"
#endif
