#pragma once
// Points of R³ as grade-3 elements of Cl(0,3,1) (GF §10.1.2, GF-10.1.2-points-and-free-vectors):
//   p = w e1e2e3 + X e2e3𝐞 + Y e3e1𝐞 + Z e1e2𝐞,
// homogeneous: the point is at X/w. The book's points have w = 1 (pp* = 1); w = −1 gives the
// book's "negative points" (−p is the point at the same place with weight −1), and w = 0 the free
// vectors (points at infinity, directions), which motions only rotate: hfh* = gfg*.
#include "soma/geometry/pga/basis.hpp"

namespace soma::pga {

template <class S> class Point {
 public:
  using Scalar = S;

  /// The zero element (not a point; a placeholder).
  Point() = default;
  /// Any grade-3 element (unchecked).
  explicit Point(const Grade3<S>& e) : e_(e) {}
  /// The book's point at x (weight 1). GF §10.1.2, GF-10.1.2-points-and-free-vectors
  explicit Point(const Vec3<S>& x) : Point(S(1), x) {}
  /// Homogeneous: w e1e2e3 + X e2e3𝐞 + … (the point X/w; a free vector if w = 0). Throws
  /// InvalidInput for a NaN or infinite coordinate.
  Point(const S& w, const Vec3<S>& X);
  /// The free vector f = x e2e3𝐞 + y e3e1𝐞 + z e1e2𝐞 (a point at infinity in direction f).
  // GF §10.1.2, GF-10.1.2-points-and-free-vectors
  static Point freeVector(const Vec3<S>& f) { return Point(S(0), f); }

  const Grade3<S>& element() const { return e_; }
  /// w: the coefficient of e1e2e3.
  S weight() const { return bookCoeff(e_, basis::e123); }
  /// (X, Y, Z): the coefficients of e2e3𝐞, e3e1𝐞, e1e2𝐞 (for a free vector, its components).
  Vec3<S> bulk() const;
  /// X/w. Throws InvalidInput for a free vector (w = 0) or when X/w overflows.
  Vec3<S> position() const;
  /// w = 0 exactly: a free vector / point at infinity (meets return exactly 0 when they decide,
  /// with a Tolerance threshold, that the point is at infinity).
  bool isAtInfinity() const { return weight() == S(0); }
  /// pp* (a scalar, = w²). GF §10.1.2, GF-10.1.2-points-and-free-vectors
  S normSquared() const;
  /// Weight +1 (divide by w, so a negative point becomes the positive point at the same place);
  /// a free vector is scaled to unit length. Throws InvalidInput for the zero element.
  Point normalized() const;
  Point operator-() const { return Point(Grade3<S>(-e_)); }
  Point operator*(const S& k) const { return Point(Grade3<S>(e_ * k)); }
  bool isApprox(const Point& o, const S& tol) const { return clifford::maxAbsDiff(e_, o.e_) <= tol; }

 private:
  Grade3<S> e_;
};

#define SOMA_PGA_POINT_EXTERN(S) extern template class Point<S>;
SOMA_FOR_EACH_SCALAR(SOMA_PGA_POINT_EXTERN)
#undef SOMA_PGA_POINT_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Point<S>::Point(const S& w, const Vec3<S>& X) {
  requireFiniteInput(X, "pga::Point", "coordinates (X, Y, Z)");
  if (!isFinite(w)) throw InvalidInput("pga::Point: weight w is NaN or infinite");
  setBookCoeff(e_, basis::e123, w);
  setBookCoeff(e_, basis::e23e, X.x());
  setBookCoeff(e_, basis::e31e, X.y());
  setBookCoeff(e_, basis::e12e, X.z());
}

template <class S> Vec3<S> Point<S>::bulk() const {
  return Vec3<S>(bookCoeff(e_, basis::e23e), bookCoeff(e_, basis::e31e), bookCoeff(e_, basis::e12e));
}

template <class S> Vec3<S> Point<S>::position() const {
  const S w = weight();
  if (w == S(0))
    throw InvalidInput("pga::Point::position: the element is a free vector (weight 0, a point at "
                       "infinity) and has no position");
  const Vec3<S> x = bulk() / w;
  if (!allFinite(x))
    throw InvalidInput("pga::Point::position: X/w overflows (weight " + toString(w, 3) +
                       " too small for the coordinates)");
  return x;
}

template <class S> S Point<S>::normSquared() const { return (e_ * e_.conjugate()).scalarPart(); }

template <class S> Point<S> Point<S>::normalized() const {
  using std::sqrt;
  const S w = weight();
  if (w != S(0)) {
    (void)position();  // throws if X/w overflows
    return Point(Grade3<S>(e_ / w));
  }
  const Vec3<S> f = bulk();
  const S m = maxAbs3(f);
  if (!(m > S(0))) throw InvalidInput("pga::Point::normalized: the zero element is not a point");
  const Vec3<S> fs = f / m;
  return Point(Grade3<S>(e_ / (m * sqrt(fs.squaredNorm()))));
}

}  // namespace soma::pga
