#pragma once
// Screw systems (GF ch. 8): an n-system is an n-dimensional linear subspace of se(3), twists
// ordered (ω, v) with moment v = q × ω + p ω. A ScrewSystem stores an orthonormal basis (in the
// coefficient space R⁶; a numerical convenience, not an invariant), found from any set of
// generators with a rank decision from Tolerance<S>::rank(). Reciprocity uses the Klein form
// Q₀ = [[0, I], [I, 0]]; pitch uses Q∞ = [[−2I, 0], [0, 0]] (GF §6.4, §8.1).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/reciprocal_product.hpp"
#include "soma/algebra/screw_bracket.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <vector>

namespace soma {

/// Generators or a basis of a screw system: 6 rows, at most 6 columns (no heap allocation).
template <class S> using ScrewBasis = Eigen::Matrix<S, 6, Eigen::Dynamic, 0, 6, 6>;
/// Dynamic matrix used by the decompositions (one instantiation per scalar).
template <class S> using ScrewMatX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// Klein form Q₀: sᵀQ₀r = ω_s·v_r + ω_r·v_s, the reciprocal product. GF §6.4, §8.1
template <class S> Mat6<S> kleinForm() {
  Mat6<S> q = Mat6<S>::Zero();
  q.template topRightCorner<3, 3>().setIdentity();
  q.template bottomLeftCorner<3, 3>().setIdentity();
  return q;
}
/// The degenerate pitch quadric Q∞ = diag(−2I, 0): sᵀQ∞s = −2|ω|². GF §8.1, GF-8.1-1-systems-moduli
template <class S> Mat6<S> infinityForm() {
  Mat6<S> q = Mat6<S>::Zero();
  q.template topLeftCorner<3, 3>() = -S(2) * Mat3<S>::Identity();
  return q;
}

template <class S> class ScrewSystem {
 public:
  using Basis = ScrewBasis<S>;

  /// The 0-system {0}.
  ScrewSystem() : basis_(6, 0) {}
  /// span(generators): each generator is scaled to unit norm (a zero column is skipped), then
  /// the rank is decided by singular values > Tolerance::rank()·σ_max. Throws InvalidInput for a
  /// NaN or infinite entry. GF §8.1, GF-8.1-screw-system-and-grassmannian
  explicit ScrewSystem(const ScrewMatX<S>& generators);

  int dimension() const { return int(basis_.cols()); }
  /// Orthonormal basis (6 × n) of the system.
  const Basis& basis() const { return basis_; }
  /// σ_min/σ_max of the kept singular values of the normalised generators (1 for an
  /// orthonormal input; small when the generators are nearly dependent).
  const S& conditioning() const { return conditioning_; }
  /// Largest dropped singular value ratio (0 when the generators were independent).
  const S& droppedRatio() const { return dropped_; }

  /// Reciprocal system {s : sᵀQ₀s_i = 0 ∀ i}, dimension 6 − n. GF §8.1, GF-8.1-reciprocal-system
  ScrewSystem reciprocal() const;
  /// Ad(g)·Δ. GF §8.1 (the action ∧ⁿAd on the Grassmannian)
  ScrewSystem transformed(const SE3<S>& g) const;
  /// |s − P s|/|s| with P the orthogonal projector on the system.
  S residualOf(const Vec6<S>& s) const;
  /// Sine of the largest principal angle between two systems of equal dimension (0 when equal);
  /// 1 when the dimensions differ.
  S distanceTo(const ScrewSystem& o) const;
  /// True when [Δ, Δ] ⊆ Δ within Tolerance::rank() (Δ is a Lie subalgebra).
  bool isSubalgebra() const;

  static ScrewSystem fromOrthonormal(const Basis& b, const S& cond = S(1));

 private:
  Basis basis_;
  S conditioning_{1};
  S dropped_{0};
};

/// Union Δ_a ∪ Δ_b = span of both (the wedge s₁∧…∧s_{m+n} when transversal). GF §8.5, GF-8.5-union-intersection
template <class S> ScrewSystem<S> unionOf(const ScrewSystem<S>& a, const ScrewSystem<S>& b);
/// Intersection Δ_a ∩ Δ_b, computed by de Morgan as the reciprocal of the union of the
/// reciprocals (exact for non-transversal pairs, where the shuffle product vanishes).
// GF §8.5, GF-8.5-union-intersection (de Morgan laws of §8.5)
template <class S> ScrewSystem<S> intersectionOf(const ScrewSystem<S>& a, const ScrewSystem<S>& b);
/// Isotropy algebra {s : [s, Δ] ⊆ Δ}, the linear version of [s,s₁]∧s₂ + s₁∧[s,s₂] = 0.
// GF §8.2, GF-8.2-isotropy-algebra
template <class S> ScrewSystem<S> isotropyAlgebra(const ScrewSystem<S>& d);
/// Completion Δ_∞: Δ_{i+1} = Δ_i ⊕ [Δ₁, Δ_i] until it stabilises (the Lie algebra of the
/// completion group). `dims` receives dim Δ₁, dim Δ₂, … GF §8.1, GF-8.1-derived-systems-completion
template <class S>
ScrewSystem<S> completion(const ScrewSystem<S>& d, std::vector<int>* dims = nullptr);
/// Plücker (Grassmann) coordinates s₁∧…∧s_n of the columns: the C(6, n) n×n minors, rows in
/// lexicographic order of index sets. GF §8.1, GF-8.1-screw-system-and-grassmannian
template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> wedge(const ScrewMatX<S>& generators);
/// Orthonormal basis of the orthogonal complement of the column span of an orthonormal 6×k.
template <class S> ScrewBasis<S> orthogonalComplement(const ScrewBasis<S>& b);

#define SOMA_SCREW_SYSTEM_EXTERN(S)                                                        \
  extern template class ScrewSystem<S>;                                                    \
  extern template ScrewSystem<S> unionOf<S>(const ScrewSystem<S>&, const ScrewSystem<S>&); \
  extern template ScrewSystem<S> intersectionOf<S>(const ScrewSystem<S>&,                  \
                                                   const ScrewSystem<S>&);                 \
  extern template ScrewSystem<S> isotropyAlgebra<S>(const ScrewSystem<S>&);                \
  extern template ScrewSystem<S> completion<S>(const ScrewSystem<S>&, std::vector<int>*);  \
  extern template Eigen::Matrix<S, Eigen::Dynamic, 1> wedge<S>(const ScrewMatX<S>&);       \
  extern template ScrewBasis<S> orthogonalComplement<S>(const ScrewBasis<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_SCREW_SYSTEM_EXTERN)
#undef SOMA_SCREW_SYSTEM_EXTERN

}  // namespace soma

#ifdef SOMA_SCREW_SYSTEM_IMPL
#include "soma/geometry/screws/screw_system_impl.hpp"
#endif
