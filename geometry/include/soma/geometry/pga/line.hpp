#pragma once
// Lines (and screws) of R³ as grade-2 elements of Cl(0,3,1) (GF §10.1.3, GF-10.1.3-lines):
//   ℓ = v_x e2e3 + v_y e3e1 + v_z e1e2 + u_x e1𝐞 + u_y e2𝐞 + u_z e3𝐞,
// direction v and moment u = r × v (r any point of the line; the catalogue's convention A, the
// same as a twist (ω; v) with v = q × ω). ℓℓ* = |v|² − 2(v·u) e1e2e3𝐞, so ℓℓ* = 1 ⇔ |v| = 1 and
// the Klein condition v·u = 0. A grade-2 element with v·u ≠ 0 is a screw (a Lie algebra element,
// GF §9.3) of pitch v·u/|v|²; v = 0 is a line at infinity. −ℓ is the line with opposite direction.
#include "soma/algebra/dual_quaternion.hpp"  // detail::twistOf, SE3Tangent
#include "soma/geometry/pga/basis.hpp"

namespace soma::pga {

template <class S> class Line {
 public:
  using Scalar = S;

  /// The zero element (not a line; a placeholder).
  Line() = default;
  /// Any grade-2 element (a line, a screw or a line at infinity; unchecked).
  explicit Line(const Grade2<S>& e) : e_(e) {}
  /// ℓ from direction v and moment u (not checked against the Klein condition: a screw if
  /// v·u ≠ 0). Throws InvalidInput for a NaN or infinite coordinate. GF §10.1.3, GF-10.1.3-lines
  Line(const Vec3<S>& v, const Vec3<S>& u);
  /// The line through q with direction v: (v, q × v). GF §10.1.3, GF-10.1.3-lines
  static Line throughPoint(const Vec3<S>& q, const Vec3<S>& v) { return Line(v, Vec3<S>(q.cross(v))); }
  /// The twist (ω; v) as the grade-2 element ω_x e2e3 + … + v_x e1𝐞 + … (a screw; the
  /// rotation by θ about a unit line ℓ is the twist θℓ). GF §9.3, GF-9.3-lie-algebra-adjoint
  static Line fromTwist(const SE3Tangent<S>& xi) { return Line(xi.ang(), xi.lin()); }
  SE3Tangent<S> toTwist() const;

  const Grade2<S>& element() const { return e_; }
  /// v: the coefficients of e2e3, e3e1, e1e2.
  Vec3<S> direction() const;
  /// u: the coefficients of e1𝐞, e2𝐞, e3𝐞.
  Vec3<S> moment() const;

  /// ℓℓ* = |v|² − 2(v·u) e1e2e3𝐞 as (scalar, e1e2e3𝐞 coefficient). GF-10.1.3-lines
  std::pair<S, S> normSquared() const;
  /// v·u (the Klein condition of GF §6.4 is v·u = 0).
  S kleinForm() const { return direction().dot(moment()); }
  /// |v·u|/(|v||u|), scale-free (0 if v = 0 or u = 0).
  S kleinDefect() const;
  /// kleinDefect() ≤ tol: a line (or a line at infinity), not a screw of non-zero pitch.
  bool isLine(const S& tol = Tolerance<S>::input()) const { return kleinDefect() <= tol; }
  /// v = 0 exactly: a line at infinity (only the moment, the normal of its planes).
  bool isAtInfinity() const { return direction().squaredNorm() == S(0); }
  /// Pitch v·u/|v|² of the screw (0 for a line). Throws InvalidInput for v = 0.
  S pitch() const;
  /// The point of the axis nearest the origin, v × u/|v|² (for a screw, of its axis).
  /// Throws InvalidInput for v = 0.
  Vec3<S> pointNearestOrigin() const;
  /// ℓ/|v| (unit direction); a line at infinity is scaled to |u| = 1. Throws InvalidInput for
  /// the zero element. (For a line this gives ℓℓ* = 1.)
  Line normalized() const;
  Line operator-() const { return Line(Grade2<S>(-e_)); }
  Line operator*(const S& k) const { return Line(Grade2<S>(e_ * k)); }
  bool isApprox(const Line& o, const S& tol) const { return clifford::maxAbsDiff(e_, o.e_) <= tol; }

 private:
  Grade2<S> e_;
};

#define SOMA_PGA_LINE_EXTERN(S) extern template class Line<S>;
SOMA_FOR_EACH_SCALAR(SOMA_PGA_LINE_EXTERN)
#undef SOMA_PGA_LINE_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Line<S>::Line(const Vec3<S>& v, const Vec3<S>& u) {
  requireFiniteInput(v, "pga::Line", "direction v");
  requireFiniteInput(u, "pga::Line", "moment u");
  setBookCoeff(e_, basis::e23, v.x());
  setBookCoeff(e_, basis::e31, v.y());
  setBookCoeff(e_, basis::e12, v.z());
  setBookCoeff(e_, basis::e1e, u.x());
  setBookCoeff(e_, basis::e2e, u.y());
  setBookCoeff(e_, basis::e3e, u.z());
}

template <class S> Vec3<S> Line<S>::direction() const {
  return Vec3<S>(bookCoeff(e_, basis::e23), bookCoeff(e_, basis::e31), bookCoeff(e_, basis::e12));
}
template <class S> Vec3<S> Line<S>::moment() const {
  return Vec3<S>(bookCoeff(e_, basis::e1e), bookCoeff(e_, basis::e2e), bookCoeff(e_, basis::e3e));
}
template <class S> SE3Tangent<S> Line<S>::toTwist() const {
  return soma::detail::twistOf<S>(direction(), moment());
}

template <class S> std::pair<S, S> Line<S>::normSquared() const {
  const auto n = e_ * e_.conjugate();
  return {n.scalarPart(), bookCoeff(n, basis::e123e)};
}

template <class S> S Line<S>::kleinDefect() const {
  using std::abs;
  using std::sqrt;
  const Vec3<S> v = direction(), u = moment();
  const S mv = maxAbs3(v), mu = maxAbs3(u);
  if (!(mv > S(0)) || !(mu > S(0))) return S(0);
  const Vec3<S> v1 = v / mv, u1 = u / mu;
  return abs(v1.dot(u1)) / sqrt(v1.squaredNorm() * u1.squaredNorm());
}

template <class S> S Line<S>::pitch() const {
  const Vec3<S> v = direction();
  if (v.squaredNorm() == S(0))
    throw InvalidInput("pga::Line::pitch: direction v = 0 (a line at infinity has no pitch)");
  return v.dot(moment()) / v.squaredNorm();
}

template <class S> Vec3<S> Line<S>::pointNearestOrigin() const {
  const Vec3<S> v = direction();
  if (v.squaredNorm() == S(0))
    throw InvalidInput("pga::Line::pointNearestOrigin: direction v = 0 (a line at infinity)");
  return v.cross(moment()) / v.squaredNorm();
}

template <class S> Line<S> Line<S>::normalized() const {
  using std::sqrt;
  Vec3<S> x = direction();
  if (maxAbs3(x) == S(0)) x = moment();
  const S m = maxAbs3(x);
  if (!(m > S(0))) throw InvalidInput("pga::Line::normalized: the zero element is not a line");
  const Vec3<S> xs = x / m;
  return Line(Grade2<S>(e_ / (m * sqrt(xs.squaredNorm()))));
}

}  // namespace soma::pga
