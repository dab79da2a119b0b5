#pragma once
// Reflections in a plane π (a grade-1 versor of Cl(0,3,1), ππ* = |n|²), GF §9.1 (the Pin action)
// applied to the elements of §10.1. The sandwich π x π maps each generator by the mirror, so a
// product of k generators picks up (π²)^{k−1} = (−1)^{k−1}: a reflected point πpπ comes out with
// weight −w (reflections reverse orientation: a positive point becomes a negative point). Each
// function returns the geometric mirror image with the orientation convention of its type:
// planes with the mirrored normal, points with their weight kept, lines with the mirrored direction.
#include "soma/geometry/pga/perpendicular.hpp"

namespace soma::pga {

/// π x π/|n|²: the plane with normal and distance mirrored. GF §9.1 with GF-10.1.1-planes
template <class S> Plane<S> reflect(const Plane<S>& x, const Plane<S>& mirror);
/// −π p π/|n|²: the mirror image with the weight of p. GF §9.1 with GF-10.1.2-points-and-free-vectors
template <class S> Point<S> reflect(const Point<S>& x, const Plane<S>& mirror);
/// π ℓ π/|n|²: the mirrored directed line. GF §9.1 with GF-10.1.3-lines
template <class S> Line<S> reflect(const Line<S>& x, const Plane<S>& mirror);

#define SOMA_PGA_REFLECTION_EXTERN(S)                               \
  extern template Plane<S> reflect(const Plane<S>&, const Plane<S>&); \
  extern template Point<S> reflect(const Point<S>&, const Plane<S>&); \
  extern template Line<S> reflect(const Line<S>&, const Plane<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_REFLECTION_EXTERN)
#undef SOMA_PGA_REFLECTION_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Plane<S> reflect(const Plane<S>& x, const Plane<S>& m) {
  detail::requireProperPlane(m, "pga::reflect: mirror");
  return Plane<S>((m.element() * x.element() * m.element()).template grade<1>() / m.normSquared());
}
template <class S> Point<S> reflect(const Point<S>& x, const Plane<S>& m) {
  detail::requireProperPlane(m, "pga::reflect: mirror");
  return Point<S>((m.element() * x.element() * m.element()).template grade<3>() / (-m.normSquared()));
}
template <class S> Line<S> reflect(const Line<S>& x, const Plane<S>& m) {
  detail::requireProperPlane(m, "pga::reflect: mirror");
  return Line<S>((m.element() * x.element() * m.element()).template grade<2>() / m.normSquared());
}

}  // namespace soma::pga
