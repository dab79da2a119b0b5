#pragma once
// Perpendiculars by the left contraction, GF §10.2.4 (x⌋c = ½(xc − α(c)x) for a vector x,
// extended by (c1 ∧ c2)⌋c3 = c1⌋(c2⌋c3): clifford::leftContraction, operator |).
#include "soma/geometry/pga/meet.hpp"

namespace soma::pga {

/// The plane containing ℓ and perpendicular to π: π⌋ℓ = (n × v) − (n·u)𝐞, normalised (|n'| = 1,
/// normal along n × v). ℓ ⟂ π (|n × v| ≤ rank·|n||v|): every plane through ℓ is perpendicular
/// to π — InvalidInput. GF §10.2.4, GF-10.2.4-plane-line-perpendicular-plane
template <class S> Plane<S> perpendicularPlane(const Plane<S>& pi, const Line<S>& l);
/// The line through p perpendicular to π, directed along n, |v| = 1: −(π⌋p)/(w|n|) (the book's
/// π⌋p is anti-parallel to n). InvalidInput for a point at infinity or the plane at infinity.
// GF §10.2.4, GF-10.2.4-plane-point-perpendicular-line
template <class S> Line<S> perpendicularLine(const Plane<S>& pi, const Point<S>& p);
/// The plane through p perpendicular to ℓ, normal along v, |n| = 1: −(ℓ⌋p)/(w|v|) = v − (x·v)𝐞
/// (sign flipped from the book's ℓ⌋p so the normal agrees with ℓ). InvalidInput for a point at
/// infinity or a line at infinity. GF §10.2.4, GF-10.2.4-line-point-perpendicular-plane
template <class S> Plane<S> perpendicularPlane(const Line<S>& l, const Point<S>& p);

#define SOMA_PGA_PERP_EXTERN(S)                                                  \
  extern template Plane<S> perpendicularPlane(const Plane<S>&, const Line<S>&);  \
  extern template Line<S> perpendicularLine(const Plane<S>&, const Point<S>&);   \
  extern template Plane<S> perpendicularPlane(const Line<S>&, const Point<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_PERP_EXTERN)
#undef SOMA_PGA_PERP_EXTERN

// ---------------------------------------------------------------------------------------------

namespace detail {
template <class S> void requireFinitePoint(const Point<S>& p, const char* who) {
  if (p.weight() == S(0))
    throw InvalidInput(std::string(who) + ": the point is at infinity (weight 0)");
}
template <class S> void requireProperPlane(const Plane<S>& pi, const char* who) {
  if (pi.normal().squaredNorm() == S(0))
    throw InvalidInput(std::string(who) + ": the plane has normal n = 0 (the plane at infinity)");
}
template <class S> void requireProperLine(const Line<S>& l, const char* who) {
  if (l.direction().squaredNorm() == S(0))
    throw InvalidInput(std::string(who) + ": the line has direction v = 0 (a line at infinity)");
}
}  // namespace detail

template <class S> Plane<S> perpendicularPlane(const Plane<S>& pi, const Line<S>& l) {
  const Plane<S> raw((pi.element() | l.element()).template grade<1>());
  const S nn = raw.normal().norm();
  if (!(nn > Tolerance<S>::rank() * pi.normal().norm() * l.direction().norm()))
    throw InvalidInput("pga::perpendicularPlane(plane, line): the line is perpendicular to the "
                       "plane (π⌋ℓ = 0), so every plane through it is perpendicular to π");
  return Plane<S>(Grade1<S>(raw.element() / nn));
}

template <class S> Line<S> perpendicularLine(const Plane<S>& pi, const Point<S>& p) {
  detail::requireFinitePoint(p, "pga::perpendicularLine(plane, point)");
  detail::requireProperPlane(pi, "pga::perpendicularLine(plane, point)");
  const Line<S> raw((pi.element() | p.element()).template grade<2>());
  return Line<S>(Grade2<S>(raw.element() / (-p.weight() * pi.normal().norm())));
}

template <class S> Plane<S> perpendicularPlane(const Line<S>& l, const Point<S>& p) {
  detail::requireFinitePoint(p, "pga::perpendicularPlane(line, point)");
  detail::requireProperLine(l, "pga::perpendicularPlane(line, point)");
  const Plane<S> raw((l.element() | p.element()).template grade<1>());
  return Plane<S>(Grade1<S>(raw.element() / (-p.weight() * l.direction().norm())));
}

}  // namespace soma::pga
