#pragma once
// Distances by shuffle and contraction, GF §10.2.4 (GF-10.2.4-distances). Homogeneous inputs are
// accepted (divided by their weights); points at infinity and elements at infinity have no
// distance (InvalidInput).
#include "soma/geometry/pga/perpendicular.hpp"

namespace soma::pga {

/// n·x − d over |n|: positive on the side the normal points to. The book's p ∨ π = d − x·n is
/// its negative (erratum E10.10: the book says p ∨ π is positive on the normal's side).
// GF §10.2.4, GF-10.2.4-distances (corrected, erratum E10.10)
template <class S> S signedDistance(const Point<S>& p, const Plane<S>& pi);
/// √((p ∨ ℓ)(p ∨ ℓ)*) over |w||v| = |u − x × v|/|v|. GF §10.2.4, GF-10.2.4-distances
template <class S> S distance(const Point<S>& p, const Line<S>& l);
/// √(−(p1 ∨ p2)⌋(p1 ∨ p2)) over |w1 w2| = |x2 − x1|. GF §10.2.4, GF-10.2.4-distances
template <class S> S distance(const Point<S>& a, const Point<S>& b);
/// Distance between two lines: |ℓ1 ∨ ℓ2|/|v1 × v2| (reciprocal product over the sine) when
/// sin∠ > sqrtEpsilon, else (nearly parallel) the distance of ℓ1's point nearest the origin from
/// ℓ2; each branch errs by ≲ sqrtEpsilon·scale at the switch. GF §10.2.3–10.2.4
template <class S> S distance(const Line<S>& a, const Line<S>& b);

#define SOMA_PGA_DISTANCE_EXTERN(S)                                  \
  extern template S signedDistance(const Point<S>&, const Plane<S>&); \
  extern template S distance(const Point<S>&, const Line<S>&);        \
  extern template S distance(const Point<S>&, const Point<S>&);       \
  extern template S distance(const Line<S>&, const Line<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_DISTANCE_EXTERN)
#undef SOMA_PGA_DISTANCE_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> S signedDistance(const Point<S>& p, const Plane<S>& pi) {
  detail::requireFinitePoint(p, "pga::signedDistance(point, plane)");
  detail::requireProperPlane(pi, "pga::signedDistance(point, plane)");
  return -shuffle(p, pi) / (p.weight() * pi.normal().norm());
}

template <class S> S distance(const Point<S>& p, const Line<S>& l) {
  using std::abs;
  using std::sqrt;
  detail::requireFinitePoint(p, "pga::distance(point, line)");
  detail::requireProperLine(l, "pga::distance(point, line)");
  const Plane<S> j = shuffle(p, l);
  const S n2 = j.normSquared();  // (p ∨ ℓ)(p ∨ ℓ)*
  return sqrt(n2) / (abs(p.weight()) * l.direction().norm());
}

template <class S> S distance(const Point<S>& a, const Point<S>& b) {
  using std::abs;
  using std::sqrt;
  detail::requireFinitePoint(a, "pga::distance(point, point)");
  detail::requireFinitePoint(b, "pga::distance(point, point)");
  const auto j = shuffle(a.element(), b.element());
  const S q = -(j | j).scalarPart();
  return sqrt(q > S(0) ? q : S(0)) / abs(a.weight() * b.weight());
}

template <class S> S distance(const Line<S>& a, const Line<S>& b) {
  using std::abs;
  detail::requireProperLine(a, "pga::distance(line, line)");
  detail::requireProperLine(b, "pga::distance(line, line)");
  const Vec3<S> va = a.direction(), vb = b.direction();
  const S cross = va.cross(vb).norm();
  if (cross > Tolerance<S>::sqrtEpsilon() * va.norm() * vb.norm()) return abs(shuffle(a, b)) / cross;
  return distance(Point<S>(a.pointNearestOrigin()), b);
}

}  // namespace soma::pga
