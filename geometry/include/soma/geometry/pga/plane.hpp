#pragma once
// Oriented planes of R³ as grade-1 elements of Cl(0,3,1): π = n_x e1 + n_y e2 + n_z e3 + d𝐞,
// the plane n·r = d (GF §10.1.1, GF-10.1.1-planes). (n, d) and (−n, −d) are the two orientations.
// The element is homogeneous: λπ is the same plane for λ > 0; ππ* = |n|² and the book's
// normalisation ππ* = 1 makes n a unit vector. n = 0 with d ≠ 0 is the plane at infinity 𝐞
// (not normalisable).
#include "soma/geometry/pga/basis.hpp"

namespace soma::pga {

template <class S> class Plane {
 public:
  using Scalar = S;

  /// The zero element (not a plane; a placeholder).
  Plane() = default;
  /// Any grade-1 element (unchecked).
  explicit Plane(const Grade1<S>& e) : e_(e) {}
  /// π = n + d𝐞, the plane n·r = d (homogeneous: n need not be unit). Throws InvalidInput for a
  /// NaN or infinite coordinate. GF §10.1.1, GF-10.1.1-planes
  Plane(const Vec3<S>& n, const S& d);
  /// The plane through the point q with normal n (n·r = n·q). GF §10.1.1, GF-10.1.1-planes
  static Plane throughPoint(const Vec3<S>& n, const Vec3<S>& q) { return Plane(n, S(n.dot(q))); }
  /// The plane at infinity 𝐞 (n = 0). GF-10.1.1-planes (extreme)
  static Plane atInfinity() { return Plane(Vec3<S>::Zero(), S(1)); }

  const Grade1<S>& element() const { return e_; }
  /// (n_x, n_y, n_z): the coefficients of e1, e2, e3.
  Vec3<S> normal() const;
  /// d: the coefficient of 𝐞.
  S distance() const { return bookCoeff(e_, basis::e); }

  /// ππ* (a scalar, = |n|²). GF §10.1.1, GF-10.1.1-planes
  S normSquared() const;
  /// n = 0 exactly (the plane at infinity or the zero element).
  bool isAtInfinity() const { return normal().squaredNorm() == S(0); }
  /// |ππ* − 1| ≤ tol.
  bool isNormalized(const S& tol = Tolerance<S>::input()) const;
  /// π/|n| (ππ* = 1). Throws InvalidInput for the plane at infinity or the zero element.
  Plane normalized() const;
  /// The same plane with the opposite orientation.
  Plane operator-() const { return Plane(Grade1<S>(-e_)); }
  Plane operator*(const S& k) const { return Plane(Grade1<S>(e_ * k)); }

  /// Max-norm distance of the coefficients.
  bool isApprox(const Plane& o, const S& tol) const { return clifford::maxAbsDiff(e_, o.e_) <= tol; }

 private:
  Grade1<S> e_;
};

#define SOMA_PGA_PLANE_EXTERN(S) extern template class Plane<S>;
SOMA_FOR_EACH_SCALAR(SOMA_PGA_PLANE_EXTERN)
#undef SOMA_PGA_PLANE_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Plane<S>::Plane(const Vec3<S>& n, const S& d) {
  requireFiniteInput(n, "pga::Plane", "normal n");
  if (!isFinite(d)) throw InvalidInput("pga::Plane: distance d is NaN or infinite");
  setBookCoeff(e_, basis::e1, n.x());
  setBookCoeff(e_, basis::e2, n.y());
  setBookCoeff(e_, basis::e3, n.z());
  setBookCoeff(e_, basis::e, d);
}

template <class S> Vec3<S> Plane<S>::normal() const {
  return Vec3<S>(bookCoeff(e_, basis::e1), bookCoeff(e_, basis::e2), bookCoeff(e_, basis::e3));
}

template <class S> S Plane<S>::normSquared() const {
  return (e_ * e_.conjugate()).scalarPart();
}

template <class S> bool Plane<S>::isNormalized(const S& tol) const {
  using std::abs;
  return abs(normSquared() - S(1)) <= tol;
}

template <class S> Plane<S> Plane<S>::normalized() const {
  using std::sqrt;
  const Vec3<S> n = normal();
  const S m = maxAbs3(n);
  if (!(m > S(0)))
    throw InvalidInput("pga::Plane::normalized: the normal n is 0 (the plane at infinity or the "
                       "zero element has no unit normal)");
  const Vec3<S> ns = n / m;
  return Plane(Grade1<S>(e_ / (m * sqrt(ns.squaredNorm()))));
}

}  // namespace soma::pga
