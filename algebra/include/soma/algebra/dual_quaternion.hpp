#pragma once
// Dual quaternions ȟ = a + εc ∈ H ⊗ D (ε² = 0, ε central) and dual numbers (GF §9.3).
//
// CONVENTION (the book's, GF §9.3, seed lines 5657–5730). The rigid motion p ↦ R p + t, with R
// the rotation of the unit quaternion a (R p = a p a*, GF §2.2.2), is the unit dual quaternion
//
//     ȟ = a + ε c,   c = ½ t a      (t = t_x i + t_y j + t_z k; t multiplies a on the LEFT),
//
// the image of the Clifford element g + ½ t g e under e2e3 ↦ i, e3e1 ↦ j, e1e2 ↦ k,
// −e1e2e3e ↦ ε. The book's expansion (seed 5696) reads c0 = −½(a1 t1 + a2 t2 + a3 t3),
// c1 = ½(a0 t1 − a2 t3 + a3 t2), …, i.e. c = ½ t a; equivalently h1 h0* = −h0 h1* = t/2
// (seed 5728), so t = 2 c a* (also GF §11.5.4: t = 2 h1 h0*, seed 7274).
// The 8 Study parameters of ȟ are (a0:a1:a2:a3:c0:c1:c2:c3) (study_parameters.hpp).
//
// Three conjugates: conjugate() = a* + εc* (the book's "dual-quaternionic conjugate" ȟ*, used
// in ȟȟ* = 1 and in the adjoint action on dual vectors), dualConjugate() = a − εc, and
// fullConjugate() = a* − εc* (both at once, used in the action on points 1 + εx).
// The Lie algebra: the twist (ω; v) of se3.hpp (moment v = q × ω) is the pure dual quaternion
// ½ω + ε½v (GF §9.3, seed 5742), and exp of that pure dual quaternion is the dual quaternion of
// SE3Tangent::exp() — the book's dual-angle exponential with v0 = ω/θ, v1 = (v − pω̂)/θ.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/quaternion.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <string>

namespace soma {

// ---------------------------------------------------------------------------------------------
// Dual numbers

/// A dual number x + εy with ε² = 0 (used for the norm and the dual angle of §9.3).
// GF §7.6, GF-7.6-transference
template <class S> struct DualNumber {
  S re{0};  ///< real part
  S du{0};  ///< dual part (coefficient of ε)

  DualNumber() = default;
  DualNumber(const S& r, const S& d = S(0)) : re(r), du(d) {}

  DualNumber operator+(const DualNumber& o) const { return {re + o.re, du + o.du}; }
  DualNumber operator-(const DualNumber& o) const { return {re - o.re, du - o.du}; }
  DualNumber operator-() const { return {-re, -du}; }
  /// (x + εy)(u + εw) = xu + ε(xw + yu). GF §7.6, GF-7.6-transference
  DualNumber operator*(const DualNumber& o) const { return {re * o.re, re * o.du + du * o.re}; }
  DualNumber operator*(const S& k) const { return {re * k, du * k}; }
  /// (x + εy)/(u + εw) = x/u + ε(yu − xw)/u²; throws InvalidInput for u = 0 (a zero divisor).
  // GF §7.6, GF-7.6-transference (extreme: zero divisors)
  DualNumber operator/(const DualNumber& o) const {
    if (o.re == S(0)) throw InvalidInput("DualNumber: division by a pure dual number (real part 0)");
    return {re / o.re, (du * o.re - re * o.du) / (o.re * o.re)};
  }
  bool isApprox(const DualNumber& o, const S& tol) const {
    using std::abs;
    return abs(re - o.re) <= tol && abs(du - o.du) <= tol;
  }
  /// √(x + εy) = √x + ε y/(2√x), x > 0; throws InvalidInput for x ≤ 0.
  // GF §7.6, GF-7.6-transference (f(a + εb) = f(a) + εb f'(a))
  DualNumber sqrt() const {
    using std::sqrt;
    if (!(re > S(0)))
      throw InvalidInput("DualNumber::sqrt: real part must be positive, got " + toString(re, 6));
    const S r = sqrt(re);
    return {r, du / (S(2) * r)};
  }
  /// cos and sin of a dual angle θ + εd: cos θ − ε d sin θ and sin θ + ε d cos θ.
  // GF §7.6, GF-7.6-dual-killing-and-dual-angle
  DualNumber cos() const {
    using std::cos;
    using std::sin;
    return {cos(re), -du * sin(re)};
  }
  DualNumber sin() const {
    using std::cos;
    using std::sin;
    return {sin(re), du * cos(re)};
  }
};

// ---------------------------------------------------------------------------------------------
// Dual quaternions

namespace detail {
template <class S> Quat<S> quatAdd(const Quat<S>& p, const Quat<S>& q) {
  return Quat<S>(Vec4<S>(p.coeffs() + q.coeffs()));
}
template <class S> Quat<S> quatSub(const Quat<S>& p, const Quat<S>& q) {
  return Quat<S>(Vec4<S>(p.coeffs() - q.coeffs()));
}
template <class S> Quat<S> quatScale(const Quat<S>& p, const S& k) {
  return Quat<S>(Vec4<S>(p.coeffs() * k));
}
template <class S> Quat<S> quatConj(const Quat<S>& p) {
  return Quat<S>(p.w(), -p.x(), -p.y(), -p.z());
}
/// (ω; v) as an SE3Tangent, filled block by block (the comma initializer of SE3Tangent(ω, v)
/// triggers a GCC 12 -Warray-bounds false positive for float).
template <class S> SE3Tangent<S> twistOf(const Vec3<S>& w, const Vec3<S>& v) {
  Vec6<S> s;
  s.template head<3>() = w;
  s.template tail<3>() = v;
  return SE3Tangent<S>(s);
}
template <class S> Quat<S> pureQuat(const Vec3<S>& x) { return Quat<S>(S(0), x.x(), x.y(), x.z()); }
/// (w, x, y, z) of a quaternion, the Study order (Eigen stores (x, y, z, w)).
template <class S> Vec4<S> studyOrder(const Quat<S>& q) { return Vec4<S>(q.w(), q.x(), q.y(), q.z()); }
template <class S> Quat<S> fromStudyOrder(const Vec4<S>& v) { return Quat<S>(v(0), v(1), v(2), v(3)); }

/// sin φ/φ and g(φ) = (φ cos φ − sin φ)/φ³ = d/dφ(sin φ/φ)/φ, from φ². Taylor below
/// precision(3) (remainders φ⁴/120 and φ⁴/840 below eps); above, φ cos φ − sin φ is evaluated
/// as (φ − sin φ) − 2φ sin²(φ/2) (no catastrophic cancellation).
template <class S> void sincDerivative(const S& phi2, S& f, S& g) {
  using std::sin;
  using std::sqrt;
  if (phi2 < taylorSwitch2<S>(3)) {
    f = S(1) - phi2 / S(6);
    g = -S(1) / S(3) + phi2 / S(30);
    return;
  }
  const S phi = sqrt(phi2);
  const S sh = sin(phi / S(2));
  f = sin(phi) / phi;
  g = (thetaMinusSin(phi) - S(2) * phi * sh * sh) / (phi2 * phi);
}

/// |a·c| / (|a| |c|), the scale-free Study residual (the cosine of the angle between a and c in
/// R⁴): the Study quadric is invariant under a ↦ αa, c ↦ γc, and so is this. 0 when a = 0 or
/// c = 0 (a·c = 0 holds exactly). Each vector is scaled by its largest entry first, so no square
/// overflows or underflows.
template <class S> S studyDefect(const Vec4<S>& a, const Vec4<S>& c) {
  using std::abs;
  using std::sqrt;
  const S ma = a.cwiseAbs().maxCoeff(), mc = c.cwiseAbs().maxCoeff();
  if (ma == S(0) || mc == S(0)) return S(0);
  const Vec4<S> a1 = a / ma, c1 = c / mc;
  return abs(a1.dot(c1)) / sqrt(a1.squaredNorm() * c1.squaredNorm());
}
}  // namespace detail

template <class S> class DualQuaternion {
 public:
  using Scalar = S;

  /// The identity 1 + ε0.
  DualQuaternion() : a_(S(1), S(0), S(0), S(0)), c_(S(0), S(0), S(0), S(0)) {}
  /// a + εc from its real and dual quaternion parts (no validation: any element of H ⊗ D).
  DualQuaternion(const Quat<S>& real, const Quat<S>& dual) : a_(real), c_(dual) {}
  /// From the 8 Study coordinates (a0, a1, a2, a3, c0, c1, c2, c3) (no validation).
  // GF §9.3, GF-9.3-study-quadric
  explicit DualQuaternion(const Vec8<S>& v)
      : a_(v(0), v(1), v(2), v(3)), c_(v(4), v(5), v(6), v(7)) {}
  static DualQuaternion Identity() { return DualQuaternion(); }

  const Quat<S>& real() const { return a_; }
  const Quat<S>& dual() const { return c_; }
  /// (a0, a1, a2, a3, c0, c1, c2, c3): real part first, each quaternion scalar first.
  Vec8<S> coeffs() const;

  /// (a + εc)(b + εd) = ab + ε(ad + cb) with the book's quaternion product.
  // GF §9.3, GF-9.3-dual-quaternion-isomorphism (and GF-2.1-quaternion-product)
  DualQuaternion operator*(const DualQuaternion& o) const;
  DualQuaternion operator+(const DualQuaternion& o) const {
    return DualQuaternion(detail::quatAdd(a_, o.a_), detail::quatAdd(c_, o.c_));
  }
  DualQuaternion operator-(const DualQuaternion& o) const {
    return DualQuaternion(detail::quatSub(a_, o.a_), detail::quatSub(c_, o.c_));
  }
  DualQuaternion operator-() const { return *this * S(-1); }
  DualQuaternion operator*(const S& k) const {
    return DualQuaternion(detail::quatScale(a_, k), detail::quatScale(c_, k));
  }
  friend DualQuaternion operator*(const S& k, const DualQuaternion& h) { return h * k; }

  /// ȟ* = a* + εc*, the book's dual-quaternionic conjugate. GF §9.3, GF-9.3-study-quadric
  DualQuaternion conjugate() const {
    return DualQuaternion(detail::quatConj(a_), detail::quatConj(c_));
  }
  /// a − εc (conjugation of the dual unit only; with conjugate() it gives the point action's
  /// factor). GF §9.3, GF-9.2-euclidean-group-Cl0n1
  DualQuaternion dualConjugate() const { return DualQuaternion(a_, detail::quatScale(c_, S(-1))); }
  /// a* − εc* (both conjugations), the right factor of the point action.
  // GF §9.3, GF-9.2-euclidean-group-Cl0n1
  DualQuaternion fullConjugate() const {
    return DualQuaternion(detail::quatConj(a_), detail::quatScale(detail::quatConj(c_), S(-1)));
  }

  /// ȟȟ* = aa* + ε(ac* + ca*) = |a|² + ε 2 a·c, a dual number. GF §9.3, GF-9.3-study-quadric
  DualNumber<S> squaredNorm() const;
  /// √(ȟȟ*) = |a| + ε a·c/|a|; throws InvalidInput if a = 0. GF §9.3, GF-9.3-study-quadric
  DualNumber<S> norm() const { return squaredNorm().sqrt(); }
  /// ȟȟ* = 1 within tol: ||a| − 1| ≤ tol and the scale-free Study defect |a·c|/(|a||c|) ≤ tol
  /// (the dual part 2a·c carries the unit of length, so it is compared relative to |c|).
  // GF §9.3, GF-9.3-study-quadric
  bool isUnit(const S& tol = Tolerance<S>::input()) const;
  /// |a·c|/(|a||c|) (0 when a = 0 or c = 0): the unit-free Study residual.
  S studyDefect() const { return detail::studyDefect(detail::studyOrder(a_), detail::studyOrder(c_)); }

  /// General inverse a⁻¹ − ε a⁻¹ c a⁻¹ (= conjugate() for a unit ȟ); throws InvalidInput if
  /// a = 0 (such ȟ are zero divisors). GF §9.3, GF-9.3-dual-quaternion-isomorphism
  DualQuaternion inverse() const;

  /// Action on a point: ȟ(1 + εx)(a* − εc*) = aa* + ε(a x a* + c a* − a c*), returned as the
  /// dual vector divided by aa* (homogeneous in ȟ; the component of c along a drops out).
  /// For ȟ = a + ε½ta with a unit this is R x + t. Throws InvalidInput if a = 0.
  // GF §9.3, GF-9.3-study-quadric (point action, seed 5722)
  Vec3<S> act(const Vec3<S>& x) const;
  Vec3<S> operator*(const Vec3<S>& x) const { return act(x); }
  /// Adjoint action on a twist written as the pure dual quaternion ½ω + ε½v: ȟ(·)ȟ*, giving
  /// (Rω; Rv + t × Rω) = Ad(g)(ω; v). ȟ must be unit (validated).
  // GF §9.3, GF-9.3-lie-algebra-adjoint (corrected, erratum E9.3)
  SE3Tangent<S> adjoint(const SE3Tangent<S>& xi) const;

  /// Translation t = 2 c a* / (aa*) (vector part; the scalar part −2a·c/|a|² is the Study
  /// defect and is dropped). Throws InvalidInput if a = 0. GF §9.3, GF-9.3-study-quadric
  Vec3<S> translation() const;

  /// The book's image of (R, t): a = the quaternion of R, c = ½ t a.
  // GF §9.3, GF-9.3-dual-quaternion-isomorphism
  static DualQuaternion fromSE3(const SE3<S>& g);
  /// The motion of a unit dual quaternion: R from a, t = 2 c a*. Validates: finite, ||a| − 1|
  /// and the Study defect within Tolerance::input(); else InvalidInput (never projects).
  // GF §9.3, GF-9.3-study-quadric
  SE3<S> toSE3() const;
  /// From a 4×4 homogeneous matrix (validated by SE3::fromMatrix). GF §2.5.1, GF-2.5.1-homogeneous
  static DualQuaternion fromMatrix(const Mat4<S>& m) { return fromSE3(SE3<S>::fromMatrix(m)); }
  /// [[R, t], [0, 1]] of a unit dual quaternion (validated as in toSE3).
  Mat4<S> matrix() const { return toSE3().matrix(); }

  /// The twist (ω; v) as the pure dual quaternion ½ω + ε½v. GF §9.3, GF-9.3-lie-algebra-adjoint
  static DualQuaternion hat(const SE3Tangent<S>& xi);
  /// Inverse of hat: (2·vec a; 2·vec c) (scalar parts ignored). GF §9.3, GF-9.3-lie-algebra-adjoint
  SE3Tangent<S> vee() const;
  /// exp(½ω + ε½v) in H ⊗ D, in closed form: with φ = |ω|/2, a = ω/2, b = v/2,
  /// exp = (cos φ + (sin φ/φ) a) + ε(−(sin φ/φ) a·b + (sin φ/φ) b + g(φ)(a·b) a),
  /// g = (φ cos φ − sin φ)/φ³ — the book's cos(θ̌/2) + sin(θ̌/2)v̌ expanded in the dual angle, with
  /// no division by θ (valid for pure translations). Equals fromSE3(xi.exp()) coefficient by
  /// coefficient (SO3Tangent::exp keeps the Spin sign, a0 = cos(θ/2), for every θ).
  // GF §9.3, GF-9.3-exp-log
  static DualQuaternion exp(const SE3Tangent<S>& xi);
  /// Logarithm of a unit dual quaternion (validated), rotation angle in [0, π]: the inverse of
  /// exp's closed form (sign chosen with a0 ≥ 0, φ = atan2(|vec a|, a0), a·b = −c0 φ/sin φ).
  /// Equals SE3::log() of the motion (at θ = π, one of the two logs).
  // GF §9.3, GF-9.3-exp-log
  SE3Tangent<S> log() const;
  /// Screw-linear interpolation a·exp(t·log(a*·b)) of unit dual quaternions (the shortest
  /// screw path): the same motion as SE3::interpolate(a, b, t). GF §9.3, GF-9.3-exp-log
  static DualQuaternion sclerp(const DualQuaternion& a, const DualQuaternion& b, const S& t);

  /// All 8 coefficients within tol (max-norm).
  bool isApprox(const DualQuaternion& o, const S& tol) const {
    return (coeffs() - o.coeffs()).template lpNorm<Eigen::Infinity>() <= tol;
  }
  /// Same rigid motion: coefficients equal up to the sign ȟ ~ −ȟ (the 2-to-1 cover), within tol.
  bool sameMotion(const DualQuaternion& o, const S& tol) const {
    const Vec8<S> p = coeffs(), q = o.coeffs();
    const S d1 = (p - q).template lpNorm<Eigen::Infinity>();
    const S d2 = (p + q).template lpNorm<Eigen::Infinity>();
    return (d1 < d2 ? d1 : d2) <= tol;
  }
  template <class T> DualQuaternion<T> cast() const {
    return DualQuaternion<T>(castMatrix<T>(coeffs()));
  }

 private:
  /// Throws InvalidInput unless finite, ||a| − 1| ≤ input and Study defect ≤ input.
  void requireUnit(const char* who) const;

  Quat<S> a_;
  Quat<S> c_;
};

// ---------------------------------------------------------------------------------------------
// Implementation

template <class S> Vec8<S> DualQuaternion<S>::coeffs() const {
  Vec8<S> v;
  v << a_.w(), a_.x(), a_.y(), a_.z(), c_.w(), c_.x(), c_.y(), c_.z();
  return v;
}

template <class S> DualQuaternion<S> DualQuaternion<S>::operator*(const DualQuaternion& o) const {
  return DualQuaternion(quaternionProduct(a_, o.a_),
                        detail::quatAdd(quaternionProduct(a_, o.c_), quaternionProduct(c_, o.a_)));
}

template <class S> DualNumber<S> DualQuaternion<S>::squaredNorm() const {
  return DualNumber<S>(a_.coeffs().squaredNorm(), S(2) * a_.coeffs().dot(c_.coeffs()));
}

template <class S> bool DualQuaternion<S>::isUnit(const S& tol) const {
  using std::abs;
  using std::sqrt;
  if (!allFinite(coeffs())) return false;
  return abs(sqrt(a_.coeffs().squaredNorm()) - S(1)) <= tol && studyDefect() <= tol;
}

template <class S> void DualQuaternion<S>::requireUnit(const char* who) const {
  using std::abs;
  using std::sqrt;
  const std::string w = std::string("DualQuaternion::") + who + ": ";
  if (!allFinite(coeffs())) throw InvalidInput(w + "dual quaternion has a NaN or infinite component");
  const S n = sqrt(a_.coeffs().squaredNorm());
  const S tol = Tolerance<S>::input();
  if (abs(n - S(1)) > tol)
    throw InvalidInput(w + "real part a is not a unit quaternion (|a| = " + toString(n, 17) +
                       ", accepted defect " + toString(tol, 3) +
                       "); for homogeneous coordinates use StudyParameters");
  const S d = studyDefect();
  if (d > tol)
    throw InvalidInput(w + "off the Study quadric: |a·c|/(|a||c|) = " + toString(d, 3) +
                       " exceeds " + toString(tol, 3) + " (not projected; correct the input)");
}

template <class S> DualQuaternion<S> DualQuaternion<S>::inverse() const {
  const S n2 = a_.coeffs().squaredNorm();
  if (!(n2 > S(0)))
    throw InvalidInput("DualQuaternion::inverse: real part a = 0 (a zero divisor has no inverse)");
  const Quat<S> ai = detail::quatScale(detail::quatConj(a_), S(1) / n2);
  return DualQuaternion(ai, detail::quatScale(quaternionProduct(quaternionProduct(ai, c_), ai), S(-1)));
}

template <class S> Vec3<S> DualQuaternion<S>::act(const Vec3<S>& x) const {
  const S n2 = a_.coeffs().squaredNorm();
  if (!(n2 > S(0))) throw InvalidInput("DualQuaternion::act: real part a = 0 (not a rigid motion)");
  const Quat<S> ac = detail::quatConj(a_);
  const Quat<S> rx = quaternionProduct(quaternionProduct(a_, detail::pureQuat(x)), ac);
  const Quat<S> ca = quaternionProduct(c_, ac);
  const Quat<S> acs = quaternionProduct(a_, detail::quatConj(c_));
  return (rx.vec() + ca.vec() - acs.vec()) / n2;
}

template <class S> SE3Tangent<S> DualQuaternion<S>::adjoint(const SE3Tangent<S>& xi) const {
  requireUnit("adjoint");
  const DualQuaternion r = *this * hat(xi) * conjugate();
  return r.vee();
}

template <class S> Vec3<S> DualQuaternion<S>::translation() const {
  const S n2 = a_.coeffs().squaredNorm();
  if (!(n2 > S(0)))
    throw InvalidInput("DualQuaternion::translation: real part a = 0 (not a rigid motion)");
  return quaternionProduct(c_, detail::quatConj(a_)).vec() * (S(2) / n2);
}

template <class S> DualQuaternion<S> DualQuaternion<S>::fromSE3(const SE3<S>& g) {
  const Quat<S>& a = g.quaternion();
  return DualQuaternion(a, detail::quatScale(quaternionProduct(detail::pureQuat(g.translation()), a),
                                             S(1) / S(2)));
}

template <class S> SE3<S> DualQuaternion<S>::toSE3() const {
  requireUnit("toSE3");
  return SE3<S>(SO3<S>::fromQuaternionUnchecked(a_), translation());
}

template <class S> DualQuaternion<S> DualQuaternion<S>::hat(const SE3Tangent<S>& xi) {
  const S h = S(1) / S(2);
  return DualQuaternion(detail::pureQuat(Vec3<S>(xi.ang() * h)),
                        detail::pureQuat(Vec3<S>(xi.lin() * h)));
}

template <class S> SE3Tangent<S> DualQuaternion<S>::vee() const {
  return detail::twistOf<S>(a_.vec() * S(2), c_.vec() * S(2));
}

template <class S> DualQuaternion<S> DualQuaternion<S>::exp(const SE3Tangent<S>& xi) {
  using std::cos;
  using std::sqrt;
  const Vec3<S> a = xi.ang() / S(2), b = xi.lin() / S(2);
  const S phi2 = a.squaredNorm();
  const S ab = a.dot(b);
  S f, g;
  detail::sincDerivative(phi2, f, g);
  const S cphi = cos(sqrt(phi2));
  const Vec3<S> av = f * a;
  const Vec3<S> cv = f * b + (g * ab) * a;
  return DualQuaternion(Quat<S>(cphi, av.x(), av.y(), av.z()),
                        Quat<S>(-f * ab, cv.x(), cv.y(), cv.z()));
}

template <class S> SE3Tangent<S> DualQuaternion<S>::log() const {
  using std::atan2;
  using std::sqrt;
  requireUnit("log");
  // Scale to |a| = 1 exactly (a defect within Tolerance::input() was accepted) and take the
  // representative with a0 ≥ 0, so the rotation angle θ = 2φ lies in [0, π].
  const S n = sqrt(a_.coeffs().squaredNorm());
  const S s = (a_.w() < S(0) ? S(-1) : S(1)) / n;
  const Quat<S> a = detail::quatScale(a_, s);
  Quat<S> c = detail::quatScale(c_, s);
  // Drop the Study defect (the component of c along a, accepted within tolerance).
  c = detail::quatSub(c, detail::quatScale(a, a.coeffs().dot(c.coeffs())));
  const S w = a.w();
  const S n2 = a.vec().squaredNorm();  // sin²φ
  S k;                                   // φ / sin φ
  if (n2 < detail::taylorSwitch2<S>(3)) {
    k = (S(1) - n2 / (S(3) * w * w)) / w;  // atan(n/w)/n, remainder n⁴/5 < eps
  } else {
    const S sn = sqrt(n2);
    k = atan2(sn, w) / sn;
  }
  const Vec3<S> halfOmega = k * a.vec();  // ω/2 = φ û
  S f, g;
  detail::sincDerivative(halfOmega.squaredNorm(), f, g);
  // From exp: c0 = −f (a·b), vec c = f b + g (a·b) a, with f = sin φ/φ = 1/k.
  const S ab = -c.w() * k;
  const Vec3<S> b = k * (c.vec() - (g * ab) * halfOmega);
  return detail::twistOf<S>(S(2) * halfOmega, S(2) * b);
}

template <class S>
DualQuaternion<S> DualQuaternion<S>::sclerp(const DualQuaternion& a, const DualQuaternion& b,
                                            const S& t) {
  a.requireUnit("sclerp");
  return a * exp((a.conjugate() * b).log() * t);
}

using DualQuaternionf = DualQuaternion<float>;
using DualQuaterniond = DualQuaternion<double>;
using DualQuaternionld = DualQuaternion<long double>;
using DualQuaternionq = DualQuaternion<__float128>;
using DualQuaternionmp = DualQuaternion<mpreal>;

#define SOMA_DQ_EXTERN(S) extern template class DualQuaternion<S>;
SOMA_FOR_EACH_SCALAR(SOMA_DQ_EXTERN)
#undef SOMA_DQ_EXTERN

}  // namespace soma
