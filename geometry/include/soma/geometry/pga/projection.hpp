#pragma once
// Orthogonal projections, built from the contraction (a perpendicular) and the exterior product
// (a meet), GF §10.2.4 with §10.2.2.
#include "soma/geometry/pga/perpendicular.hpp"

namespace soma::pga {

/// Foot of the perpendicular from p to π: (−π⌋p) ∧ π, weight +1. GF §10.2.4, GF-10.2.4-plane-point-perpendicular-line
template <class S> Point<S> project(const Point<S>& p, const Plane<S>& pi);
/// Foot of the perpendicular from p to ℓ: ℓ ∧ (−ℓ⌋p), weight +1 (equals ½(p − ℓpℓ) of GF
/// §10.3.3 for a unit line). GF §10.2.4, GF-10.2.4-line-point-perpendicular-plane
template <class S> Point<S> project(const Point<S>& p, const Line<S>& l);
/// Orthogonal projection of ℓ into π: (π⌋ℓ) ∧ π, |v| = 1, directed like ℓ's projection.
/// ℓ ⟂ π (its projection is a point): InvalidInput. GF §10.2.4, GF-10.2.4-plane-line-perpendicular-plane
template <class S> Line<S> project(const Line<S>& l, const Plane<S>& pi);

#define SOMA_PGA_PROJECTION_EXTERN(S)                               \
  extern template Point<S> project(const Point<S>&, const Plane<S>&); \
  extern template Point<S> project(const Point<S>&, const Line<S>&);  \
  extern template Line<S> project(const Line<S>&, const Plane<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_PROJECTION_EXTERN)
#undef SOMA_PGA_PROJECTION_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Point<S> project(const Point<S>& p, const Plane<S>& pi) {
  return meet(perpendicularLine(pi, p), pi);
}

template <class S> Point<S> project(const Point<S>& p, const Line<S>& l) {
  return meet(l, perpendicularPlane(l, p));
}

template <class S> Line<S> project(const Line<S>& l, const Plane<S>& pi) {
  const Line<S> m = meet(perpendicularPlane(pi, l), pi);
  return m.direction().dot(l.direction()) < S(0) ? -m : m;
}

}  // namespace soma::pga
