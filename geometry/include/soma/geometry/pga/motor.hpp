#pragma once
// Rigid motions as even elements of Cl(0,3,1): h = g + ½ t g 𝐞 with g ∈ Spin(3), hh* = 1
// (GF §9.2–9.3, GF-9.2-euclidean-group-Cl0n1, GF-9.3-dual-quaternion-isomorphism). One sandwich
// x ↦ h x h* moves planes, points and lines (GF §10.1, GF-10.1.1-planes, GF-10.1.2-…, GF-10.1.3-lines).
//
// The bridge to the dual quaternions of dual_quaternion.hpp is the book's isomorphism
// e2e3 ↦ i, e3e1 ↦ j, e1e2 ↦ k, −e1e2e3𝐞 ↦ ε (so e1𝐞 ↦ iε, e2𝐞 ↦ jε, e3𝐞 ↦ kε):
//   h = a0 + a1 e2e3 + a2 e3e1 + a3 e1e2 + c1 e1𝐞 + c2 e2𝐞 + c3 e3𝐞 − c0 e1e2e3𝐞  ↔  ȟ = a + εc,
// and the Study parameters are (a0:…:a3:c0:…:c3). Twists are grade-2 elements: the twist
// (ω; v) is the bivector B(ξ) = ω_x e2e3 + … + v_x e1𝐞 + … (Line::fromTwist) and
// exp(ξ) = exp(½B(ξ)) (GF §9.3: the Lie algebra basis ½e2e3, …, ½e3𝐞).
#include "soma/algebra/study_parameters.hpp"
#include "soma/geometry/pga/line.hpp"
#include "soma/geometry/pga/plane.hpp"
#include "soma/geometry/pga/point.hpp"

namespace soma::pga {

template <class S> class Motor {
 public:
  using Scalar = S;

  /// The identity 1.
  Motor() : e_(S(1)) {}
  /// Any even element (unchecked; isUnit tells whether it is a motion).
  explicit Motor(const EvenElement<S>& e) : e_(e) {}

  /// The image of a dual quaternion under the book's isomorphism (no validation).
  // GF §9.3, GF-9.3-dual-quaternion-isomorphism
  static Motor fromDualQuaternion(const DualQuaternion<S>& h);
  /// The unit dual quaternion of a unit motor (validated by DualQuaternion: |a| = 1 and the
  /// Study condition within Tolerance::input()). GF §9.3, GF-9.3-dual-quaternion-isomorphism
  DualQuaternion<S> toDualQuaternion() const;
  /// Homogeneous: from any Study point representing a motion (validated, scaled to |a| = 1).
  // GF §9.3, GF-9.3-study-quadric
  static Motor fromStudyParameters(const StudyParameters<S>& p) {
    return fromDualQuaternion(p.toDualQuaternion());
  }
  /// The 8 Study parameters (a0:a1:a2:a3:c0:c1:c2:c3) of the element (any even element).
  StudyParameters<S> toStudyParameters() const;
  /// h = g + ½ t g 𝐞 for the motion x ↦ R x + t. GF §9.2, GF-9.2-euclidean-group-Cl0n1
  static Motor fromSE3(const SE3<S>& g) { return fromDualQuaternion(DualQuaternion<S>::fromSE3(g)); }
  /// The motion (validated as toDualQuaternion).
  SE3<S> toSE3() const { return toDualQuaternion().toSE3(); }
  /// Pure translation 1 + ½ t 𝐞 (t as a grade-1 element times 𝐞). GF §9.2
  static Motor translation(const Vec3<S>& t);
  /// Rotation by θ about the unit line ℓ: cos(θ/2) + sin(θ/2) ℓ (GF §10.3.1, a_i = e^{θ_i ℓ_i/2}).
  /// Throws InvalidInput unless ℓ is a unit line (ℓℓ* = 1 within Tolerance::input()).
  static Motor rotationAbout(const Line<S>& l, const S& theta);

  /// exp(½ B(ξ)) through clifford::exp (the closed form for Cl(0,3,1) bivectors). GF §9.3, GF-9.3-exp-log
  static Motor exp(const SE3Tangent<S>& xi);
  /// exp(B) of any bivector B (a screw times half its angle).
  static Motor exp(const Line<S>& B);
  /// The twist ξ with exp(ξ) = ±h, rotation angle in [0, π] (through DualQuaternion::log;
  /// validated unit). GF §9.3, GF-9.3-exp-log
  SE3Tangent<S> log() const { return toDualQuaternion().log(); }

  const EvenElement<S>& element() const { return e_; }
  /// Geometric product: (h1 h2) x (h1 h2)* = h1 (h2 x h2*) h1*, the motion h2 then h1.
  Motor operator*(const Motor& o) const { return Motor(EvenElement<S>(e_ * o.e_)); }
  Motor operator-() const { return Motor(EvenElement<S>(-e_)); }
  /// h* (Clifford conjugation, = reverse on even elements); the inverse of a unit motor.
  Motor conjugate() const { return Motor(e_.conjugate()); }
  /// hh* as (scalar, e1e2e3𝐞 coefficient): (|a|², −2 a·c). GF §9.3, GF-9.3-study-quadric
  std::pair<S, S> normSquared() const;
  /// hh* = 1: ||a| − 1| ≤ tol and the scale-free Study defect ≤ tol (as DualQuaternion::isUnit).
  bool isUnit(const S& tol = Tolerance<S>::input()) const;

  /// h π h*. GF §10.1.1, GF-10.1.1-planes
  Plane<S> operator()(const Plane<S>& x) const;
  /// h p h* (a free vector is only rotated). GF §10.1.2, GF-10.1.2-points-and-free-vectors
  Point<S> operator()(const Point<S>& x) const;
  /// h ℓ h* (also the adjoint action on screws/twists). GF §10.1.3, GF-10.1.3-lines
  Line<S> operator()(const Line<S>& x) const;

  /// Same motion: coefficients equal up to the sign h ~ −h, within tol (max-norm).
  bool sameMotion(const Motor& o, const S& tol) const;
  bool isApprox(const Motor& o, const S& tol) const { return clifford::maxAbsDiff(e_, o.e_) <= tol; }

 private:
  EvenElement<S> e_;
};

#define SOMA_PGA_MOTOR_EXTERN(S) extern template class Motor<S>;
SOMA_FOR_EACH_SCALAR(SOMA_PGA_MOTOR_EXTERN)
#undef SOMA_PGA_MOTOR_EXTERN

// ---------------------------------------------------------------------------------------------

template <class S> Motor<S> Motor<S>::fromDualQuaternion(const DualQuaternion<S>& h) {
  const Vec8<S> c = h.coeffs();
  EvenElement<S> e;
  e.setCoeff(0, c(0));
  setBookCoeff(e, basis::e23, c(1));
  setBookCoeff(e, basis::e31, c(2));
  setBookCoeff(e, basis::e12, c(3));
  setBookCoeff(e, basis::e123e, S(-c(4)));
  setBookCoeff(e, basis::e1e, c(5));
  setBookCoeff(e, basis::e2e, c(6));
  setBookCoeff(e, basis::e3e, c(7));
  return Motor(e);
}

template <class S> StudyParameters<S> Motor<S>::toStudyParameters() const {
  Vec8<S> c;
  c << e_.scalarPart(), bookCoeff(e_, basis::e23), bookCoeff(e_, basis::e31), bookCoeff(e_, basis::e12),
      S(-bookCoeff(e_, basis::e123e)), bookCoeff(e_, basis::e1e), bookCoeff(e_, basis::e2e),
      bookCoeff(e_, basis::e3e);
  return StudyParameters<S>(c);
}

template <class S> DualQuaternion<S> Motor<S>::toDualQuaternion() const {
  const DualQuaternion<S> h(toStudyParameters().coeffs());
  if (!h.isUnit())
    throw InvalidInput("pga::Motor: hh* ≠ 1 (|a| = " + toString(normSquared().first, 6) +
                       "², scale-free Study defect " + toString(h.studyDefect(), 3) +
                       "); not a unit motor (use toStudyParameters for homogeneous coordinates)");
  return h;
}

template <class S> Motor<S> Motor<S>::translation(const Vec3<S>& t) {
  requireFiniteInput(t, "pga::Motor::translation", "translation t");
  EvenElement<S> e(S(1));
  setBookCoeff(e, basis::e1e, S(t.x() / S(2)));
  setBookCoeff(e, basis::e2e, S(t.y() / S(2)));
  setBookCoeff(e, basis::e3e, S(t.z() / S(2)));
  return Motor(e);
}

template <class S> Motor<S> Motor<S>::rotationAbout(const Line<S>& l, const S& theta) {
  using std::abs;
  using std::cos;
  using std::sin;
  const auto [n0, n4] = l.normSquared();
  const S tol = Tolerance<S>::input();
  if (!(abs(n0 - S(1)) <= tol) || !(l.kleinDefect() <= tol))
    throw InvalidInput("pga::Motor::rotationAbout: the axis is not a unit line (ℓℓ* = " +
                       toString(n0, 6) + " + " + toString(n4, 3) + " e1e2e3𝐞, expected 1)");
  if (!isFinite(theta)) throw InvalidInput("pga::Motor::rotationAbout: angle θ is NaN or infinite");
  EvenElement<S> e(l.element() * sin(theta / S(2)));
  e += EvenElement<S>(cos(theta / S(2)));
  return Motor(e);
}

template <class S> Motor<S> Motor<S>::exp(const Line<S>& B) { return Motor(clifford::exp(B.element())); }

template <class S> Motor<S> Motor<S>::exp(const SE3Tangent<S>& xi) {
  requireFiniteInput(xi.coeffs(), "pga::Motor::exp", "twist ξ");
  return exp(Line<S>::fromTwist(xi) * (S(1) / S(2)));
}

template <class S> std::pair<S, S> Motor<S>::normSquared() const {
  const auto n = e_ * e_.conjugate();
  return {n.scalarPart(), bookCoeff(n, basis::e123e)};
}

template <class S> bool Motor<S>::isUnit(const S& tol) const {
  return DualQuaternion<S>(toStudyParameters().coeffs()).isUnit(tol);
}

template <class S> Plane<S> Motor<S>::operator()(const Plane<S>& x) const {
  return Plane<S>((e_ * x.element() * e_.conjugate()).template grade<1>());
}
template <class S> Point<S> Motor<S>::operator()(const Point<S>& x) const {
  return Point<S>((e_ * x.element() * e_.conjugate()).template grade<3>());
}
template <class S> Line<S> Motor<S>::operator()(const Line<S>& x) const {
  return Line<S>((e_ * x.element() * e_.conjugate()).template grade<2>());
}

template <class S> bool Motor<S>::sameMotion(const Motor& o, const S& tol) const {
  const S d1 = clifford::maxAbsDiff(e_, o.e_), d2 = clifford::maxAbsDiff(e_, EvenElement<S>(-o.e_));
  return (d1 < d2 ? d1 : d2) <= tol;
}

}  // namespace soma::pga
