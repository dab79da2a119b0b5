#pragma once
// Meets (intersections) by the exterior product, GF §10.2.2: the exterior product of the
// elements, then normalised. When the normalising factor vanishes the meet lies at infinity:
// parallel planes meet in a line at infinity (v = 0), a line parallel to a plane meets it in a
// point at infinity (a free vector), three planes whose normals are coplanar meet in a point at
// infinity. "Vanishes" is decided against the scale of the products' terms with
// Tolerance<S>::rank(); the returned element at infinity has its weight set to exactly 0 (never a
// division by a tiny number). Where no meet exists (coincident planes, a line lying in the
// plane, three planes through one line) InvalidInput is thrown.
#include "soma/geometry/pga/line.hpp"
#include "soma/geometry/pga/plane.hpp"
#include "soma/geometry/pga/point.hpp"

namespace soma::pga {

/// π1 ∧ π2 (unnormalised): direction n1 × n2, moment d2 n1 − d1 n2. GF §10.2.2, GF-10.2.2-meet-two-planes
template <class S> Line<S> wedge(const Plane<S>& a, const Plane<S>& b) {
  return Line<S>(a.element() ^ b.element());
}
/// ℓ ∧ π (unnormalised): weight n·v, bulk n × u + d v. GF §10.2.2, GF-10.2.2-meet-line-plane
template <class S> Point<S> wedge(const Line<S>& l, const Plane<S>& p) {
  return Point<S>(l.element() ^ p.element());
}
/// π1 ∧ π2 ∧ π3 (unnormalised): weight det(n1, n2, n3). GF §10.2.2, GF-10.2.2-meet-three-planes
template <class S> Point<S> wedge(const Plane<S>& a, const Plane<S>& b, const Plane<S>& c) {
  return Point<S>((a.element() ^ b.element()) ^ c.element());
}

/// The line where two planes meet, normalised (|v| = 1): ℓ = π1∧π2/√((π1∧π2)(π1∧π2)*).
/// Parallel planes (|n1 × n2| ≤ rank·|n1||n2|): the line at infinity, v = 0, |u| = 1.
/// Coincident planes (either orientation): InvalidInput. GF §10.2.2, GF-10.2.2-meet-two-planes
template <class S> Line<S> meet(const Plane<S>& a, const Plane<S>& b);
/// The point where a line meets a plane, weight +1 (the book's sign choice of ±√):
/// p = ℓ∧π/±√((ℓ∧π)(ℓ∧π)*). Line parallel to the plane (|n·v| ≤ rank·|n||v|): the point at
/// infinity (the free vector ±v/|v|). Line lying in the plane: InvalidInput.
// GF §10.2.2, GF-10.2.2-meet-line-plane
template <class S> Point<S> meet(const Line<S>& l, const Plane<S>& p);
/// The point where three planes meet, weight +1. Normals coplanar (|det| ≤ rank·|n1||n2||n3|):
/// the point at infinity in the common direction of the pairwise meets; three planes through one
/// line, or all parallel: InvalidInput. GF §10.2.2, GF-10.2.2-meet-three-planes
template <class S> Point<S> meet(const Plane<S>& a, const Plane<S>& b, const Plane<S>& c);

#define SOMA_PGA_MEET_EXTERN(S)                                                      \
  extern template Line<S> meet(const Plane<S>&, const Plane<S>&);                    \
  extern template Point<S> meet(const Line<S>&, const Plane<S>&);                    \
  extern template Point<S> meet(const Plane<S>&, const Plane<S>&, const Plane<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_MEET_EXTERN)
#undef SOMA_PGA_MEET_EXTERN

// ---------------------------------------------------------------------------------------------

namespace detail {
/// A point of weight +1 from a raw (w, X), or the unit free vector X/|X| when |w| ≤ wTol;
/// InvalidInput (with `what`) when X is also within xTol of 0.
template <class S>
Point<S> pointOrInfinity(const Point<S>& raw, const S& wTol, const S& xTol, const char* what) {
  using std::abs;
  const S w = raw.weight();
  const Vec3<S> X = raw.bulk();
  if (abs(w) > wTol) return Point<S>(Vec3<S>(X / w));
  if (!(X.norm() > xTol)) throw InvalidInput(what);
  return Point<S>::freeVector(Vec3<S>(X / X.norm()));
}
}  // namespace detail

template <class S> Line<S> meet(const Plane<S>& a, const Plane<S>& b) {
  using std::abs;
  const Line<S> raw = wedge(a, b);
  const Vec3<S> v = raw.direction(), u = raw.moment();
  const S na = a.normal().norm(), nb = b.normal().norm();
  const S r = Tolerance<S>::rank();
  if (v.norm() > r * na * nb) return Line<S>(Grade2<S>(raw.element() / v.norm()));
  const S uScale = abs(a.distance()) * nb + abs(b.distance()) * na;
  if (!(u.norm() > r * uScale))
    throw InvalidInput("pga::meet(plane, plane): the planes coincide (π1 ∧ π2 = 0), so they "
                       "meet in a plane, not a line");
  return Line<S>(Vec3<S>::Zero(), Vec3<S>(u / u.norm()));
}

template <class S> Point<S> meet(const Line<S>& l, const Plane<S>& p) {
  using std::abs;
  const Point<S> raw = wedge(l, p);
  const S nv = l.direction().norm(), nu = l.moment().norm(), nn = p.normal().norm();
  const S r = Tolerance<S>::rank();
  return detail::pointOrInfinity(raw, r * nn * nv, r * (nn * nu + abs(p.distance()) * nv),
                                 "pga::meet(line, plane): the line lies in the plane (ℓ ∧ π = 0), "
                                 "so they meet in a line, not a point");
}

template <class S> Point<S> meet(const Plane<S>& a, const Plane<S>& b, const Plane<S>& c) {
  using std::abs;
  const Point<S> raw = wedge(a, b, c);
  const S n1 = a.normal().norm(), n2 = b.normal().norm(), n3 = c.normal().norm();
  const S d1 = abs(a.distance()), d2 = abs(b.distance()), d3 = abs(c.distance());
  const S r = Tolerance<S>::rank();
  return detail::pointOrInfinity(raw, r * n1 * n2 * n3, r * (d1 * n2 * n3 + d2 * n1 * n3 + d3 * n1 * n2),
                                 "pga::meet(plane, plane, plane): π1 ∧ π2 ∧ π3 = 0 — the planes share "
                                 "a line (or are parallel), so they do not meet in one point");
}

}  // namespace soma::pga
