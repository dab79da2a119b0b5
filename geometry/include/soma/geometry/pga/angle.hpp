#pragma once
// Angles by contraction (cosine) and exterior product or commutator (sine), GF §10.2.4,
// recovered with atan2 (never acos); scale-free, so the inputs need not be normalised.
#include "soma/geometry/pga/meet.hpp"

namespace soma::pga {

/// Angle between the normals of two planes, in [0, π]: cos = −π1⌋π2/(|n1||n2|) (GF: π1⌋π2 =
/// −n·m), sin from |π1 ∧ π2| (its direction part n1 × n2). GF §10.2.4, GF-10.2.4-plane-plane-angle
template <class S> S angle(const Plane<S>& a, const Plane<S>& b);
/// Angle between the directions of two lines, in [0, π]: cos = −ℓ1⌋ℓ2 (the Killing form, GF:
/// ℓ1⌋ℓ2 = −v·w), sin from the commutator ½[ℓ1, ℓ2] (direction v × w). GF-10.2.4-line-line-angle
template <class S> S angle(const Line<S>& a, const Line<S>& b);
/// Angle of a line to a plane, in [−π/2, π/2], positive when v points to the side of n:
/// sin = n·v (the e1e2e3 part of π ∧ ℓ), cos = |n × v| (the normal of π⌋ℓ). GF §10.2.4
template <class S> S angle(const Line<S>& l, const Plane<S>& pi);

#define SOMA_PGA_ANGLE_EXTERN(S)                              \
  extern template S angle(const Plane<S>&, const Plane<S>&);  \
  extern template S angle(const Line<S>&, const Line<S>&);    \
  extern template S angle(const Line<S>&, const Plane<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_ANGLE_EXTERN)
#undef SOMA_PGA_ANGLE_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> S angle(const Plane<S>& a, const Plane<S>& b) {
  using std::atan2;
  const S c = -(a.element() | b.element()).scalarPart();
  const S s = wedge(a, b).direction().norm();
  return atan2(s, c);
}

template <class S> S angle(const Line<S>& a, const Line<S>& b) {
  using std::atan2;
  const S c = -(a.element() | b.element()).scalarPart();
  const Line<S> comm(((a.element() * b.element() - b.element() * a.element()) * (S(1) / S(2))).template grade<2>());
  return atan2(S(comm.direction().norm()), c);
}

template <class S> S angle(const Line<S>& l, const Plane<S>& pi) {
  using std::atan2;
  const S s = bookCoeff(pi.element() ^ l.element(), basis::e123);
  const S c = Plane<S>((pi.element() | l.element()).template grade<1>()).normal().norm();
  return atan2(s, c);
}

}  // namespace soma::pga
