#pragma once
// Rigid-body dynamics in the Clifford algebra Cl(0,6,2) (Selig & Bayro-Corrochano 2010, "SB"):
// velocities (screws), momenta (co-screws), inertias as elements; the bar involution, the invariants
// Q0, A, E; the shuffle product; the action of rigid motions; the equations of motion in SB's form
//   N ∧ ṡ + ½((s̄N − N s̄) ∧ s) = W E          (SB §6, SB-6-E-form).
//
// Generators. SB orders them a₁,a₂,a₃,a,e₁,e₂,e₃,e (a_i² = e_i² = −1, a² = e² = 0). soma's
// Cl(0,6,2) (clifford/signature.hpp) puts the two null generators last, so the library indices are
//   a₁=0, a₂=1, a₃=2, e₁=3, e₂=4, e₃=5, a=6, e=7.
// The library's regressive product ∨ is the Grassmann–Cayley shuffle for ITS orientation
// g0 g1 … g7 = a₁a₂a₃e₁e₂e₃ae, which is −(SB's a₁a₂a₃ae₁e₂e₃e). SB's shuffle (§4, every det taken
// in SB's order) is therefore `shuffle(x, y) = orientationSign · regressive(x, y)` with
// orientationSign = −1; `shuffleByDefinition` evaluates SB's literal §4 formula on blades so the
// two can be compared (tests, SB-4-shuffle-definition).
//
// Screws s = ω_x e₂e₃ + ω_y e₃e₁ + ω_z e₁e₂ + v_x e₁e + v_y e₂e + v_z e₃e (SB §3);
// co-screws P = p_x a₂a₃ + p_y a₃a₁ + p_z a₁a₂ + l_x a₁a + l_y a₂a + l_z a₃a (SB §5: linear momentum
// on the a_ia_j, angular on the a_ia — swapped relative to the screws).
// The 6-vector forms are soma's: screw (ω, v) as SE3Tangent, co-screw (l, p) as Vec6.
#include "soma/algebra/clifford/multivector.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/QR>
#include <array>
#include <initializer_list>

namespace soma::clifford_dynamics {

using Sig = clifford::Signature<0, 6, 2>;
using clifford::Blade;
using clifford::GradeMask;
using clifford::gradeBit;

/// Library generator indices of SB's generators.
enum Gen : int { a1 = 0, a2 = 1, a3 = 2, e1 = 3, e2 = 4, e3 = 5, a = 6, e = 7 };

template <class S> using Bivector = clifford::Bivector<Sig, S>;      // screws, co-screws
template <class S> using Quadvector = clifford::Multivector<Sig, S, gradeBit(4)>;  // inertias
template <class S> using Hexavector = clifford::Multivector<Sig, S, gradeBit(6)>;  // W E
template <class S> using Even = clifford::Even<Sig, S>;              // motors g, ḡ, g ḡ
template <class S> using Dense = clifford::Dense<Sig, S>;

/// A basis blade with the sign of the ordered product of distinct generators.
struct SignedBlade {
  Blade blade = 0;
  int sign = 1;
};
/// g_{i₁} g_{i₂} … (distinct generators, any order) = sign · blade.
constexpr SignedBlade signedBlade(std::initializer_list<int> gens) {
  Blade b = 0;
  int sign = 1;
  for (int g : gens) {
    const Blade x = Blade(1) << g;
    sign *= Sig::outerSign(b, x);  // 0 if repeated; callers pass distinct generators
    b |= x;
  }
  return {b, sign};
}
/// Permutation sign of SB's generator order a₁,a₂,a₃,a,e₁,e₂,e₃,e relative to the library's.
constexpr int orientationSign() { return signedBlade({a1, a2, a3, a, e1, e2, e3, e}).sign; }

/// Screw basis in SB's order ω_x, ω_y, ω_z, v_x, v_y, v_z (SB §3).
inline constexpr std::array<SignedBlade, 6> screwBasis{
    signedBlade({e2, e3}), signedBlade({e3, e1}), signedBlade({e1, e2}),
    signedBlade({e1, e}),  signedBlade({e2, e}),  signedBlade({e3, e})};
/// Co-screw basis in soma's order l_x, l_y, l_z, p_x, p_y, p_z (SB §5).
inline constexpr std::array<SignedBlade, 6> coScrewBasis{
    signedBlade({a1, a}),  signedBlade({a2, a}),  signedBlade({a3, a}),
    signedBlade({a2, a3}), signedBlade({a3, a1}), signedBlade({a1, a2})};

/// The element σ·blade of any stored grade mask M.
template <class S, GradeMask M = (GradeMask(1) << 9) - 1>
clifford::Multivector<Sig, S, M & Sig::allGrades> element(const SignedBlade& b,
                                                           const S& c = S(1)) {
  return clifford::Multivector<Sig, S, M & Sig::allGrades>::basisBlade(b.blade,
                                                                       b.sign > 0 ? c : S(-c));
}

/// Screw element s (SB §3, SB-3-screw-bivector-lie-bracket) and back.
template <class S> Bivector<S> screwElement(const SE3Tangent<S>& s);
template <class S> SE3Tangent<S> screwOf(const Bivector<S>& x);
/// Co-screw element P from (l, p) (SB §5, SB-5-coscrew-element-bar-involution) and back.
template <class S> Bivector<S> coScrewElement(const Vec6<S>& lp);
template <class S> Vec6<S> coScrewOf(const Bivector<S>& x);

/// The bar involution a_i ↔ e_i, a ↔ e, an automorphism (x̄ȳ = (xy)‾) of Cl(0,6,2).
/// SB §5, SB-5-coscrew-element-bar-involution
template <class S, GradeMask M>
clifford::Multivector<Sig, S, M> bar(const clifford::Multivector<Sig, S, M>& x) {
  constexpr int image[8] = {e1, e2, e3, a1, a2, a3, e, a};
  clifford::Multivector<Sig, S, M> out;
  for (int i = 0; i < x.size; ++i) {
    const Blade b = x.blade(i);
    Blade nb = 0;
    int sign = 1;
    for (int g = 0; g < 8; ++g)
      if (b & (Blade(1) << g)) {
        const Blade y = Blade(1) << image[g];
        sign *= Sig::outerSign(nb, y);
        nb |= y;
      }
    out.setCoeff(nb, sign > 0 ? x[i] : S(-x[i]));
  }
  return out;
}

/// SB's shuffle product (§4) with determinants in SB's generator order:
/// orientationSign() · (library regressive product). SB-4-shuffle-definition
template <class S, GradeMask A, GradeMask B>
auto shuffle(const clifford::Multivector<Sig, S, A>& x, const clifford::Multivector<Sig, S, B>& y) {
  auto r = clifford::regressive(x, y);
  if constexpr (orientationSign() < 0) r = -r;
  return r;
}
/// SB §4's definition taken literally on two basis blades (bitmasks in library indices):
/// b ∨ c = Σ_σ sign(σ) det(b_σ(1…n−k), c₁…c_k) b_σ(n−k+1) ∧ … ∧ b_σ(j), determinants with the
/// columns expressed in SB's generator order. Returns the coefficient (−1, 0, +1) of `result`.
/// An independent reference for `shuffle` (no complements, no library sign tables).
struct ShuffleTerm {
  int sign = 0;
  Blade result = 0;
};
ShuffleTerm shuffleByDefinition(Blade b, Blade c);

/// The invariants of SB §5–6: A = a₁a₂a₃a, E = Ā = e₁e₂e₃e, and
/// Q0 = a₂a₃e₁e + a₃a₁e₂e + a₁a₂e₃e + a₁ae₂e₃ + a₂ae₃e₁ + a₃ae₁e₂ (SB-5-Q0-evaluation).
template <class S> Quadvector<S> elementA();
template <class S> Quadvector<S> elementE();
template <class S> Quadvector<S> elementQ0();

/// The grade-4 element of a 6×6 matrix M (co-screw = M · screw): N = Σ_ij M_ij σ_ij P_i K_j with
/// P_i the co-screw blades, K_j the e-bivector complementary to screw blade j in e₁e₂e₃e
/// (e₂e₃ ↔ e₁e, …), σ_ij = ±1 so that A ∨ (P_iK_j ∧ s_j) = P_i. For a symmetric M this is an
/// inertia (or stiffness/damping, SB §7); a diagonal M gives SB's printed N
/// (SB-5-diagonal-inertia-element).
template <class S> Quadvector<S> formElement(const Mat6<S>& M);
template <class S> Quadvector<S> inertiaElement(const Mat6<S>& N) { return formElement(N); }
/// The 6×6 matrix of s ↦ A ∨ (N ∧ s), read from the element's action on the six basis screws.
template <class S> Mat6<S> formMatrix(const Quadvector<S>& N);

/// Momentum P = A ∨ (N ∧ s) (SB-5-momentum-A-shuffle).
template <class S> Bivector<S> momentum(const Quadvector<S>& N, const Bivector<S>& s);
/// Evaluation P(s) = P ∨ (Q0 ∧ s) = l·ω + p·v (SB-5-Q0-evaluation).
template <class S> S pairing(const Bivector<S>& P, const Bivector<S>& s);
/// Kinetic energy E_k = ½ s̄ ∨ (N ∧ s) (SB-5-kinetic-energy).
template <class S> S kineticEnergy(const Quadvector<S>& N, const Bivector<S>& s);

/// Motor g = t r ∈ Cl(0,3,1) ⊂ Cl(0,6,2) of a rigid motion: r = cos θ/2 + sin θ/2 (u·(e₂e₃, e₃e₁,
/// e₁e₂)), t = 1 + ½ (t·(e₁e, e₂e, e₃e)) (SB §3, SB-3-cl031-rotations-translations).
template <class S> Even<S> motorElement(const SE3<S>& g);
/// Screws move by s ↦ g s g*, co-screws by P ↦ ḡ P ḡ*, inertias by N ↦ (gḡ) N (gḡ)*
/// (SB §5, SB-5-inertia-transformation). g is a motor (g g* = 1).
template <class S> Bivector<S> actScrew(const Even<S>& g, const Bivector<S>& s);
template <class S> Bivector<S> actCoScrew(const Even<S>& g, const Bivector<S>& P);
template <class S> Quadvector<S> actInertia(const Even<S>& g, const Quadvector<S>& N);

/// Coadjoint action {s, P} = ½ (s̄ P − P s̄), grade-2 part (SB §6, SB-6-coadjoint-action).
template <class S> Bivector<S> coadjoint(const Bivector<S>& s, const Bivector<S>& P);
/// dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄) for a body moving with velocity s (SB-6-inertia-derivative).
template <class S> Quadvector<S> inertiaDerivative(const Quadvector<S>& N, const Bivector<S>& s);

/// SB's equation of motion in E-form (SB-6-E-form): the left side N ∧ ṡ + ½((s̄N − Ns̄) ∧ s)
/// (all grades the products produce; SB's claim is that only grade 6 survives) and W E.
template <class S>
clifford::Multivector<Sig, S, gradeBit(4) | gradeBit(6) | gradeBit(8)> eFormLeft(
    const Quadvector<S>& N, const Bivector<S>& s, const Bivector<S>& sdot);
template <class S> Hexavector<S> eFormRight(const Bivector<S>& W);

/// ṡ from SB's E-form: solves N ∧ ṡ = W E − ½((s̄N − Ns̄) ∧ s) as a 28×6 linear system on the
/// grade-6 coefficients (Householder QR). `residual` is max |left − right| over all grades after
/// the solve (0 up to rounding when SB's form is consistent).
template <class S> struct CliffordAcceleration {
  Bivector<S> sdot;
  S residual;
};
template <class S>
CliffordAcceleration<S> rigidBodyAcceleration(const Quadvector<S>& N, const Bivector<S>& s,
                                              const Bivector<S>& W);

#define SOMA_CLIFFORD_DYNAMICS_EXTERN(S)                                                                  \
  extern template Bivector<S> screwElement<S>(const SE3Tangent<S>&);                          \
  extern template SE3Tangent<S> screwOf<S>(const Bivector<S>&);                               \
  extern template Bivector<S> coScrewElement<S>(const Vec6<S>&);                              \
  extern template Vec6<S> coScrewOf<S>(const Bivector<S>&);                                   \
  extern template Quadvector<S> elementA<S>();                                                \
  extern template Quadvector<S> elementE<S>();                                                \
  extern template Quadvector<S> elementQ0<S>();                                               \
  extern template Quadvector<S> formElement<S>(const Mat6<S>&);                               \
  extern template Mat6<S> formMatrix<S>(const Quadvector<S>&);                                \
  extern template Bivector<S> momentum<S>(const Quadvector<S>&, const Bivector<S>&);          \
  extern template S pairing<S>(const Bivector<S>&, const Bivector<S>&);                       \
  extern template S kineticEnergy<S>(const Quadvector<S>&, const Bivector<S>&);               \
  extern template Even<S> motorElement<S>(const SE3<S>&);                                     \
  extern template Bivector<S> actScrew<S>(const Even<S>&, const Bivector<S>&);                \
  extern template Bivector<S> actCoScrew<S>(const Even<S>&, const Bivector<S>&);              \
  extern template Quadvector<S> actInertia<S>(const Even<S>&, const Quadvector<S>&);          \
  extern template Bivector<S> coadjoint<S>(const Bivector<S>&, const Bivector<S>&);           \
  extern template Quadvector<S> inertiaDerivative<S>(const Quadvector<S>&, const Bivector<S>&); \
  extern template clifford::Multivector<Sig, S, gradeBit(4) | gradeBit(6) | gradeBit(8)>      \
  eFormLeft<S>(const Quadvector<S>&, const Bivector<S>&, const Bivector<S>&);                 \
  extern template Hexavector<S> eFormRight<S>(const Bivector<S>&);                            \
  extern template CliffordAcceleration<S> rigidBodyAcceleration<S>(                           \
      const Quadvector<S>&, const Bivector<S>&, const Bivector<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_CLIFFORD_DYNAMICS_EXTERN)
#undef SOMA_CLIFFORD_DYNAMICS_EXTERN

}  // namespace soma::clifford_dynamics
