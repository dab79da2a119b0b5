#pragma once
// Incidence relations, GF §10.2.1 and §10.2.3: a product of the elements vanishes. Each test
// returns a scale-free residual (the product divided by the sum of the magnitudes of its terms,
// so rounding gives ~ε whatever the units or the distance from the origin) and a bool that
// compares it with a tolerance (default Tolerance<S>::rank()).
#include "soma/geometry/pga/join.hpp"
#include "soma/geometry/pga/meet.hpp"

namespace soma::pga {

/// |π ∧ p|/scale; π ∧ p = ½(πp − pπ) = (x·n − d) e1e2e3𝐞 for w = 1. GF §10.2.1, GF-10.2.1-incidence-plane-point
template <class S> S incidenceResidual(const Point<S>& p, const Plane<S>& pi);
/// |π ∧ ℓ|/scale; π ∧ ℓ = (n·v) e1e2e3 + (n × u + d v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞) (E10.1: the last
/// coefficient is n_x u_y − n_y u_x + d v_z). GF §10.2.1, GF-10.2.1-incidence-plane-line
template <class S> S incidenceResidual(const Line<S>& l, const Plane<S>& pi);
/// |pℓ* + ℓp*|/scale; pℓ* + ℓp* = 2(u − x × v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞) for w = 1.
// GF §10.2.1, GF-10.2.1-incidence-point-line
template <class S> S incidenceResidual(const Point<S>& p, const Line<S>& l);
/// |ℓ1 ∨ ℓ2|/scale (coplanar lines ⇔ 0). GF §10.2.3, GF-10.2.3-line-line-shuffle
template <class S> S coplanarityResidual(const Line<S>& a, const Line<S>& b);
/// |p1 ∨ p2 ∨ p3|/scale (collinear ⇔ 0). GF §10.2.3, GF-10.2.3-plane-three-points
template <class S> S collinearityResidual(const Point<S>& a, const Point<S>& b, const Point<S>& c);
/// |p1 ∨ p2 ∨ p3 ∨ p4|/scale (coplanar ⇔ 0). GF §10.2.3, GF-10.2.3-point-plane-and-coplanarity
template <class S>
S coplanarityResidual(const Point<S>& a, const Point<S>& b, const Point<S>& c, const Point<S>& d);

template <class S> bool incident(const Point<S>& p, const Plane<S>& pi, const S& tol = Tolerance<S>::rank()) {
  return incidenceResidual(p, pi) <= tol;
}
template <class S> bool incident(const Line<S>& l, const Plane<S>& pi, const S& tol = Tolerance<S>::rank()) {
  return incidenceResidual(l, pi) <= tol;
}
template <class S> bool incident(const Point<S>& p, const Line<S>& l, const S& tol = Tolerance<S>::rank()) {
  return incidenceResidual(p, l) <= tol;
}

#define SOMA_PGA_INCIDENCE_EXTERN(S)                                                              \
  extern template S incidenceResidual(const Point<S>&, const Plane<S>&);                          \
  extern template S incidenceResidual(const Line<S>&, const Plane<S>&);                           \
  extern template S incidenceResidual(const Point<S>&, const Line<S>&);                           \
  extern template S coplanarityResidual(const Line<S>&, const Line<S>&);                          \
  extern template S collinearityResidual(const Point<S>&, const Point<S>&, const Point<S>&);      \
  extern template S coplanarityResidual(const Point<S>&, const Point<S>&, const Point<S>&,        \
                                        const Point<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_INCIDENCE_EXTERN)
#undef SOMA_PGA_INCIDENCE_EXTERN

// ---------------------------------------------------------------------------------------------

namespace detail {
template <class S> S ratio(const S& num, const S& scale) {
  return scale > S(0) ? S(num / scale) : S(0);
}
}  // namespace detail

template <class S> S incidenceResidual(const Point<S>& p, const Plane<S>& pi) {
  using std::abs;
  const auto w = pi.element() ^ p.element();
  return detail::ratio(S(abs(bookCoeff(w, basis::e123e))),
                       S(p.bulk().norm() * pi.normal().norm() + abs(p.weight() * pi.distance())));
}

template <class S> S incidenceResidual(const Line<S>& l, const Plane<S>& pi) {
  using std::abs;
  const auto w = pi.element() ^ l.element();
  const S n = pi.normal().norm(), v = l.direction().norm(), u = l.moment().norm();
  return detail::ratio(w.maxAbs(), S(n * (v + u) + abs(pi.distance()) * v));
}

template <class S> S incidenceResidual(const Point<S>& p, const Line<S>& l) {
  using std::abs;
  const auto r = p.element() * l.element().conjugate() + l.element() * p.element().conjugate();
  return detail::ratio(S(r.maxAbs() / S(2)),
                       S(abs(p.weight()) * l.moment().norm() + p.bulk().norm() * l.direction().norm()));
}

template <class S> S coplanarityResidual(const Line<S>& a, const Line<S>& b) {
  using std::abs;
  return detail::ratio(S(abs(shuffle(a, b))), S(a.direction().norm() * b.moment().norm() +
                                                a.moment().norm() * b.direction().norm()));
}

template <class S> S collinearityResidual(const Point<S>& a, const Point<S>& b, const Point<S>& c) {
  using std::abs;
  const auto r = shuffle(shuffle(a.element(), b.element()), c.element());
  const S w1 = abs(a.weight()), w2 = abs(b.weight()), w3 = abs(c.weight());
  const S x1 = a.bulk().norm(), x2 = b.bulk().norm(), x3 = c.bulk().norm();
  return detail::ratio(r.maxAbs(), S((w1 * x2 + w2 * x1) * x3 + x1 * x2 * w3 + x1 * x2 * x3));
}

template <class S>
S coplanarityResidual(const Point<S>& a, const Point<S>& b, const Point<S>& c, const Point<S>& d) {
  using std::abs;
  const auto r = shuffle(shuffle(shuffle(a.element(), b.element()), c.element()), d.element());
  const S w1 = abs(a.weight()), w2 = abs(b.weight()), w3 = abs(c.weight()), w4 = abs(d.weight());
  const S x1 = a.bulk().norm(), x2 = b.bulk().norm(), x3 = c.bulk().norm(), x4 = d.bulk().norm();
  return detail::ratio(S(abs(r.scalarPart())),
                       S(w1 * x2 * x3 * x4 + x1 * w2 * x3 * x4 + x1 * x2 * w3 * x4 + x1 * x2 * x3 * w4));
}

}  // namespace soma::pga
