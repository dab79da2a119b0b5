#pragma once
// Joins by the shuffle product, GF §10.2.3 (shuffle.hpp implements the book's definition):
// the line through two points, the plane through a point and a line or through three points,
// then normalised. When the normalising factor vanishes the join is at infinity (two points at
// infinity span a line at infinity; a point at infinity and a line at infinity span the plane at
// infinity); where no join exists (coincident points, a point on the line, collinear points)
// InvalidInput is thrown. Decisions use Tolerance<S>::rank() against the scale of the terms.
#include "soma/geometry/pga/line.hpp"
#include "soma/geometry/pga/plane.hpp"
#include "soma/geometry/pga/point.hpp"
#include "soma/geometry/pga/shuffle.hpp"

namespace soma::pga {

/// p1 ∨ p2 (unnormalised): direction w1 X2 − w2 X1, moment X1 × X2. GF §10.2.3, GF-10.2.3-join-two-points
template <class S> Line<S> shuffle(const Point<S>& a, const Point<S>& b) {
  return Line<S>(shuffle(a.element(), b.element()));
}
/// p ∨ ℓ (unnormalised): normal w u − X × v, distance X·u. GF §10.2.3, GF-10.2.3-join-point-line
template <class S> Plane<S> shuffle(const Point<S>& p, const Line<S>& l) {
  return Plane<S>(shuffle(p.element(), l.element()));
}
/// p ∨ π = w d − X·n (a scalar; zero ⇔ p on π). GF §10.2.3, GF-10.2.3-point-plane-and-coplanarity
template <class S> S shuffle(const Point<S>& p, const Plane<S>& pi) {
  return shuffle(p.element(), pi.element()).scalarPart();
}
/// ℓ1 ∨ ℓ2 = v·μ + u·w, the reciprocal product (zero ⇔ coplanar). GF §10.2.3, GF-10.2.3-line-line-shuffle
template <class S> S shuffle(const Line<S>& a, const Line<S>& b) {
  return shuffle(a.element(), b.element()).scalarPart();
}

/// The line through two points, ℓ = p1∨p2/√((p1∨p2)(p1∨p2)*), |v| = 1, directed from p1 to p2
/// (for positive weights). Two points at infinity: the line at infinity (|u| = 1). Coincident
/// points (|p1 ∨ p2| ≤ rank·scale): InvalidInput. GF §10.2.3, GF-10.2.3-join-two-points
template <class S> Line<S> join(const Point<S>& a, const Point<S>& b);
/// The plane through a point and a line, π = p∨ℓ/√((p∨ℓ)(p∨ℓ)*), |n| = 1. A point at infinity
/// and a line at infinity: the plane at infinity. p on ℓ: InvalidInput. GF-10.2.3-join-point-line
template <class S> Plane<S> join(const Point<S>& p, const Line<S>& l);
/// The plane through three points, π = p1∨p2∨p3/√(…), |n| = 1; normal along
/// (x2 − x1) × (x3 − x1) for positive weights. Collinear or coincident points: InvalidInput.
// GF §10.2.3, GF-10.2.3-plane-three-points
template <class S> Plane<S> join(const Point<S>& a, const Point<S>& b, const Point<S>& c);

#define SOMA_PGA_JOIN_EXTERN(S)                                                       \
  extern template Line<S> join(const Point<S>&, const Point<S>&);                     \
  extern template Plane<S> join(const Point<S>&, const Line<S>&);                     \
  extern template Plane<S> join(const Point<S>&, const Point<S>&, const Point<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_JOIN_EXTERN)
#undef SOMA_PGA_JOIN_EXTERN

// ---------------------------------------------------------------------------------------------

namespace detail {
/// Normalise a raw plane (|n| = 1), or return the plane at infinity when |n| ≤ nTol, or throw
/// `what` when d is also within dTol of 0.
template <class S>
Plane<S> planeOrInfinity(const Plane<S>& raw, const S& nTol, const S& dTol, const char* what) {
  using std::abs;
  const S nn = raw.normal().norm();
  if (nn > nTol) return Plane<S>(Grade1<S>(raw.element() / nn));
  if (!(abs(raw.distance()) > dTol)) throw InvalidInput(what);
  return raw.distance() > S(0) ? Plane<S>::atInfinity() : -Plane<S>::atInfinity();
}
}  // namespace detail

template <class S> Line<S> join(const Point<S>& a, const Point<S>& b) {
  using std::abs;
  const Line<S> raw = shuffle(a, b);
  const Vec3<S> v = raw.direction(), u = raw.moment();
  const S x1 = a.bulk().norm(), x2 = b.bulk().norm();
  const S r = Tolerance<S>::rank();
  if (v.norm() > r * (abs(a.weight()) * x2 + abs(b.weight()) * x1))
    return Line<S>(Grade2<S>(raw.element() / v.norm()));
  if (!(u.norm() > r * x1 * x2))
    throw InvalidInput("pga::join(point, point): the points coincide (p1 ∨ p2 = 0), so no unique "
                       "line passes through them");
  return Line<S>(Vec3<S>::Zero(), Vec3<S>(u / u.norm()));
}

template <class S> Plane<S> join(const Point<S>& p, const Line<S>& l) {
  using std::abs;
  const Plane<S> raw = shuffle(p, l);
  const S w = abs(p.weight()), X = p.bulk().norm(), v = l.direction().norm(), u = l.moment().norm();
  const S r = Tolerance<S>::rank();
  return detail::planeOrInfinity(raw, r * (w * u + X * v), r * X * u,
                                 "pga::join(point, line): the point lies on the line (p ∨ ℓ = 0), "
                                 "so no unique plane contains them");
}

template <class S> Plane<S> join(const Point<S>& a, const Point<S>& b, const Point<S>& c) {
  using std::abs;
  const Plane<S> raw(shuffle(shuffle(a.element(), b.element()), c.element()));
  const S w1 = abs(a.weight()), w2 = abs(b.weight()), w3 = abs(c.weight());
  const S x1 = a.bulk().norm(), x2 = b.bulk().norm(), x3 = c.bulk().norm();
  const S r = Tolerance<S>::rank();
  return detail::planeOrInfinity(raw, r * ((w1 * x2 + w2 * x1) * x3 + x1 * x2 * w3), r * x1 * x2 * x3,
                                 "pga::join(point, point, point): the points are collinear or "
                                 "coincide (p1 ∨ p2 ∨ p3 = 0), so no unique plane contains them");
}

}  // namespace soma::pga
