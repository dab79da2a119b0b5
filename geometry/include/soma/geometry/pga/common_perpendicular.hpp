#pragma once
// The common perpendicular of two lines, GF §10.2.4 (GF-10.2.4-common-perpendicular): the
// commutator s = ℓ1ℓ2 − ℓ2ℓ1 satisfies s⌋ℓi = 0 and s ∨ ℓi = 0 but is a screw of pitch
// h = (s ∨ s)/(−2 s⌋s); removing the pitch,
//   λ = −2(s⌋s) s + (s⌋e1e2e3𝐞)(s ∨ s),   ℓ = λ/√(λλ*).
// Parallel lines (s⌋s = s ∨ s = 0) have no unique common perpendicular: InvalidInput.
#include "soma/geometry/pga/join.hpp"

namespace soma::pga {

/// The commutator s = ℓ1ℓ2 − ℓ2ℓ1 (a screw along the common perpendicular).
template <class S> Line<S> commutator(const Line<S>& a, const Line<S>& b) {
  return Line<S>((a.element() * b.element() - b.element() * a.element()).template grade<2>());
}
/// The book's construction, normalised (|v| = 1, direction along v1 × v2). InvalidInput when
/// |v1 × v2| ≤ rank·|v1||v2| (parallel lines). GF §10.2.4, GF-10.2.4-common-perpendicular
template <class S> Line<S> commonPerpendicular(const Line<S>& a, const Line<S>& b);

#define SOMA_PGA_COMMON_PERP_EXTERN(S) \
  extern template Line<S> commonPerpendicular(const Line<S>&, const Line<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_COMMON_PERP_EXTERN)
#undef SOMA_PGA_COMMON_PERP_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Line<S> commonPerpendicular(const Line<S>& a, const Line<S>& b) {
  const Vec3<S> va = a.direction(), vb = b.direction();
  if (!(va.cross(vb).norm() > Tolerance<S>::rank() * va.norm() * vb.norm()))
    throw InvalidInput("pga::commonPerpendicular: the lines are parallel (s⌋s = s ∨ s = 0), so "
                       "their common perpendicular is not unique");
  const Line<S> s = commutator(a, b);
  const S ss = (s.element() | s.element()).scalarPart();  // s⌋s
  const S sj = shuffle(s, s);                              // s ∨ s
  const auto I = Grade4<S>::basisBlade(basis::e123e.mask);
  const Line<S> sI((s.element() | I).template grade<2>());  // s⌋e1e2e3𝐞
  const Line<S> lambda(Grade2<S>(s.element() * (S(-2) * ss) + sI.element() * sj));
  return lambda.normalized();
}

}  // namespace soma::pga
