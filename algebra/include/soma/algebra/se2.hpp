#pragma once
// SE(2), the group of proper rigid motions of the plane, and its Lie algebra se(2).
// GF §2.5.1 (GF-2.5.1-homogeneous: the 3×3 homogeneous picture on the plane z = 1) and
// GF §5.3 (GF-5.3-se2-rotation-about-point, GF-5.3-se2-algebra-exp-ad, GF-5.3-se2-dexp).
//
// Conventions (fixed for the whole code base):
//  * a tangent ξ = (ω, vx, vy), ω the angular rate, v the linear part, hat(ξ) = [[ωJ, v],[0, 0]]
//    with J = [[0,-1],[1,0]]; exp(ξ) = (R(ω), V(ω) v);
//  * the book's §5.3 coordinates l = (a_x, a_y, θ) relate by θ = ω and v = E₂ a = (a_y, −a_x)
//    (E₂ = [[0,1],[-1,0]]); the book's 3×3 matrix L equals hat(ξ);
//  * right Jacobian:  exp(ξ + δ) ≈ exp(ξ)·exp(Jr(ξ) δ);  left: exp(ξ + δ) ≈ exp(Jl(ξ) δ)·exp(ξ);
//  * the rotation is stored as the unit complex number (c, s) = (cos θ, sin θ).
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/errors.hpp"
#include "soma/algebra/taylor.hpp"
#include "soma/algebra/tolerance.hpp"

#include <random>
#include <string>

namespace soma {

template <class S> class SE2;

namespace detail::se2 {

// The scalar functions of θ that appear in exp, log and the Jacobians. Each has a Taylor branch
// (terms through θ⁶, first omitted term θ⁸: switch at Tolerance::precision(7)) and a direct
// formula written without cancellation where one exists (1 − cos θ = 2 sin²(θ/2)).

/// sin θ / θ
template <class S> S sinc(const S& th) {
  using std::abs;
  using std::sin;
  const S t2 = th * th;
  if (abs(th) < Tolerance<S>::precision(7))
    return S(1) - t2 / S(6) * (S(1) - t2 / S(20) * (S(1) - t2 / S(42)));
  return sin(th) / th;
}
/// (1 − cos θ) / θ²
template <class S> S cosc(const S& th) {
  using std::abs;
  using std::sin;
  const S t2 = th * th;
  if (abs(th) < Tolerance<S>::precision(7))
    return S(1) / S(2) - t2 / S(24) * (S(1) - t2 / S(30) * (S(1) - t2 / S(56)));
  const S h = sin(th / S(2));
  return S(2) * h * h / t2;
}
/// (θ − sin θ) / θ³. Above the switch the numerator comes from detail::thetaMinusSin: the
/// plain difference θ − sin θ cancels (relative error ≈ 6ε/θ², 1e3 ulp at θ = 1e-4 in
/// float128), which is what the dexp/Jacobian checks against a 512-bit series caught.
template <class S> S sincc(const S& th) {
  using std::abs;
  const S t2 = th * th;
  if (abs(th) < Tolerance<S>::precision(7))
    return S(1) / S(6) - t2 / S(120) * (S(1) - t2 / S(42) * (S(1) - t2 / S(72)));
  return thetaMinusSin(th) / (t2 * th);
}
/// (θ/2)·cot(θ/2), evaluated from the half angle (no cancellation near θ = π, where it → 0).
/// Throws when θ/2 is a nonzero multiple of π (V(θ) singular: θ = ±2π, ...).
template <class S> S halfCot(const S& th) {
  using std::abs;
  using std::cos;
  using std::sin;
  const S t2 = th * th;
  // x cot x = 1 − x²/3 − x⁴/45 − 2x⁶/945 with x = θ/2.
  if (abs(th) < Tolerance<S>::precision(7))
    return S(1) - t2 / S(12) * (S(1) + t2 / S(60) * (S(1) + t2 / S(42)));
  const S h = th / S(2);
  const S sh = sin(h);
  if (abs(sh) <= Tolerance<S>::rank() * (S(1) + abs(h)))
    throw InvalidInput("SE(2): V(θ) is singular at θ = " + toString(th) +
                       " (a nonzero multiple of 2π): Jacobian inverse undefined");
  return h * cos(h) / sh;
}

}  // namespace detail::se2

/// Element of se(2): coefficients (ω, vx, vy).
template <class S> class SE2Tangent {
 public:
  using Scalar = S;
  using Coeffs = Vec3<S>;

  SE2Tangent() : x_(Coeffs::Zero()) {}
  explicit SE2Tangent(const Coeffs& x) : x_(x) {}
  SE2Tangent(const S& omega, const Vec2<S>& v) : x_(omega, v(0), v(1)) {}
  SE2Tangent(const S& omega, const S& vx, const S& vy) : x_(omega, vx, vy) {}

  static SE2Tangent Zero() { return SE2Tangent(); }
  /// ω uniform in [−π, π), v uniform in [−1, 1)² (randomness from double).
  template <class G> static SE2Tangent Random(G& g) {
    std::uniform_real_distribution<double> u(-1, 1);
    const double w = std::numbers::pi * u(g);
    const double vx = u(g), vy = u(g);  // sequenced: argument order is unspecified
    return SE2Tangent(scalarCast<S>(w), scalarCast<S>(vx), scalarCast<S>(vy));
  }

  const Coeffs& coeffs() const { return x_; }
  Coeffs& coeffs() { return x_; }
  S angular() const { return x_(0); }
  Vec2<S> linear() const { return Vec2<S>(x_(1), x_(2)); }

  /// The 3×3 matrix [[0,−ω,vx],[ω,0,vy],[0,0,0]]: the book's L of §5.3. GF-5.3-se2-algebra-exp-ad
  Mat3<S> hat() const;
  /// Inverse of hat; validates that the matrix lies in se(2) (finite, skew block, zero last row).
  static SE2Tangent vee(const Mat3<S>& m);

  /// exp: se(2) → SE(2), e^L = I + sinθ/θ·L + (1−cosθ)/θ²·L². GF §5.3, GF-5.3-se2-algebra-exp-ad
  SE2<S> exp() const;

  /// ad(ξ) η = [ξ, η]: [[0,0,0],[vy,0,−ω],[−vx,ω,0]]. GF §5.3, GF-5.3-se2-algebra-exp-ad
  Mat3<S> ad() const;
  /// Lie bracket [this, other].
  SE2Tangent bracket(const SE2Tangent& other) const { return SE2Tangent(ad() * other.x_); }

  /// Right Jacobian: exp(ξ + δ) ≈ exp(ξ) exp(Jr δ).  Jr(ξ) = Jl(−ξ).
  Mat3<S> rjac() const;
  /// Left Jacobian (the book's dexp): Jl = I + (1−cosθ)/θ² ad + (θ−sinθ)/θ³ ad². GF-5.3-se2-dexp
  Mat3<S> ljac() const;
  /// Inverses of the Jacobians (closed form); throw InvalidInput at ω = ±2π, ±4π, ...
  Mat3<S> rjacinv() const;
  Mat3<S> ljacinv() const;

  SE2Tangent operator+(const SE2Tangent& o) const { return SE2Tangent(Coeffs(x_ + o.x_)); }
  SE2Tangent operator-(const SE2Tangent& o) const { return SE2Tangent(Coeffs(x_ - o.x_)); }
  SE2Tangent operator-() const { return SE2Tangent(Coeffs(-x_)); }
  SE2Tangent operator*(const S& k) const { return SE2Tangent(Coeffs(x_ * k)); }
  friend SE2Tangent operator*(const S& k, const SE2Tangent& t) { return t * k; }

  template <class T> SE2Tangent<T> cast() const { return SE2Tangent<T>(castMatrix<T>(x_)); }

 private:
  Coeffs x_;
};

/// Element of SE(2): rotation as a unit complex number (c, s) and a translation t.
template <class S> class SE2 {
 public:
  using Scalar = S;
  using Tangent = SE2Tangent<S>;

  /// Identity.
  SE2() : c_(1), s_(0), t_(Vec2<S>::Zero()) {}
  /// Rotation by `angle` (radians) followed by translation t: x ↦ R x + t. Throws on NaN/inf.
  SE2(const S& angle, const Vec2<S>& t);

  static SE2 Identity() { return SE2(); }
  /// From a unit complex number (c, s) = (cos θ, sin θ); throws InvalidInput when it is not
  /// finite or ||(c,s)| − 1| > Tolerance::input() (accepted input is renormalised).
  static SE2 fromComplex(const S& c, const S& s, const Vec2<S>& t);
  /// From a 3×3 homogeneous matrix [[R, t],[0, 1]] (GF-2.5.1-homogeneous); validates finiteness,
  /// the last row, RᵀR = I and det R = +1 to Tolerance::input(); throws InvalidInput otherwise.
  static SE2 fromMatrix(const Mat3<S>& m);
  /// Rotation by `angle` about the point c: (R, (I − R) c). GF §5.3, GF-5.3-se2-rotation-about-point
  static SE2 rotationAbout(const S& angle, const Vec2<S>& c);
  /// Pure translation.
  static SE2 translation(const Vec2<S>& t) { return SE2(S(0), t); }
  /// Angle uniform in [−π, π), translation uniform in [−1, 1)².
  template <class G> static SE2 Random(G& g) {
    std::uniform_real_distribution<double> u(-1, 1);
    const double th = std::numbers::pi * u(g);
    const double tx = u(g), ty = u(g);
    return SE2(scalarCast<S>(th), Vec2<S>(scalarCast<S>(tx), scalarCast<S>(ty)));
  }

  S real() const { return c_; }
  S imag() const { return s_; }
  /// θ ∈ (−π, π], from atan2.
  S angle() const;
  Mat2<S> rotation() const;
  const Vec2<S>& translation() const { return t_; }
  /// [[c, −s, tx],[s, c, ty],[0, 0, 1]]: acts on the plane z = 1. GF §2.5.1, GF-2.5.1-homogeneous
  Mat3<S> matrix() const;

  /// (R₂, t₂)(R₁, t₁) = (R₂R₁, R₂t₁ + t₂). GF §2.5.1, GF-2.5.1-euclidean-pairs
  SE2 operator*(const SE2& o) const;
  SE2& operator*=(const SE2& o) { return *this = *this * o; }
  /// (Rᵀ, −Rᵀt). GF §2.5.1, GF-2.5.1-homogeneous
  SE2 inverse() const;
  /// x ↦ R x + t.
  Vec2<S> act(const Vec2<S>& x) const;
  Vec2<S> operator*(const Vec2<S>& x) const { return act(x); }

  /// Ad(g) ξ = vee(g hat(ξ) g⁻¹): [[1,0,0],[ty, R],[−tx, R]].
  Mat3<S> adjoint() const;
  /// log: SE(2) → se(2), ω ∈ (−π, π]; v = V⁻¹ t with V⁻¹ = [[k, θ/2],[−θ/2, k]], k = (θ/2)cot(θ/2).
  Tangent log() const;

  /// g ⊕ ξ = g exp(ξ) and g ⊖ h = log(h⁻¹ g) (right-plus / right-minus).
  SE2 plus(const Tangent& xi) const { return *this * xi.exp(); }
  Tangent minus(const SE2& h) const { return (h.inverse() * *this).log(); }
  /// Geodesic a exp(τ log(a⁻¹ b)), τ ∈ [0, 1] (any τ accepted).
  static SE2 interpolate(const SE2& a, const SE2& b, const S& tau);

  /// Centre of the rotation c = (I − Rᵀ) t / (2 − 2cos θ). GF §5.3, GF-5.3-se2-rotation-about-point
  /// Throws InvalidInput for a (near-)pure translation: |θ| ≤ Tolerance::sqrtEpsilon().
  Vec2<S> centre() const;

  /// Same motion within tol (max-norm on the matrix entries, relative to 1 + |t|).
  bool isApprox(const SE2& o, const S& tol = Tolerance<S>::identity()) const;

  /// The same element in another rung: (c, s, t) cast exactly where T can hold them, then
  /// (c, s) normalised in T. No input validation: a unit complex number of S is unit only to
  /// ε_S, which is far outside Tolerance<T>::input() when T is wider (mpfr), so checking it as
  /// user input would reject every up-cast.
  template <class T> SE2<T> cast() const {
    return SE2<T>::fromComplexUnchecked(scalarCast<T>(c_), scalarCast<T>(s_), castMatrix<T>(t_));
  }
  /// No validation: (c, s) must already be a unit complex number up to rounding (casts,
  /// products); it is normalised. User input goes through fromComplex.
  static SE2 fromComplexUnchecked(const S& c, const S& s, const Vec2<S>& t) {
    using std::sqrt;
    const S n = sqrt(c * c + s * s);
    return SE2(Raw{}, c / n, s / n, t);
  }

 private:
  struct Raw {};
  SE2(Raw, const S& c, const S& s, const Vec2<S>& t) : c_(c), s_(s), t_(t) {}
  S c_, s_;
  Vec2<S> t_;
};

// ------------------------------------------------------------------------------------------
// SE2Tangent

template <class S> Mat3<S> SE2Tangent<S>::hat() const {
  Mat3<S> m;
  m << S(0), -x_(0), x_(1), x_(0), S(0), x_(2), S(0), S(0), S(0);
  return m;
}

template <class S> SE2Tangent<S> SE2Tangent<S>::vee(const Mat3<S>& m) {
  using std::abs;
  if (!allFinite(m)) throw InvalidInput("se(2) vee: matrix has a NaN or infinite entry");
  const S scale = S(1) + m.cwiseAbs().maxCoeff();
  const S tol = Tolerance<S>::input() * scale;
  if (abs(m(0, 0)) > tol || abs(m(1, 1)) > tol || abs(m(0, 1) + m(1, 0)) > tol ||
      m.row(2).cwiseAbs().maxCoeff() > tol)
    throw InvalidInput("se(2) vee: matrix is not of the form [[0,-w,vx],[w,0,vy],[0,0,0]]");
  return SE2Tangent((m(1, 0) - m(0, 1)) / S(2), m(0, 2), m(1, 2));
}

template <class S> SE2<S> SE2Tangent<S>::exp() const {
  // GF §5.3, GF-5.3-se2-algebra-exp-ad: t = V v, V = [[A, −B],[B, A]], A = sinθ/θ, B = (1−cosθ)/θ
  using std::cos;
  using std::sin;
  if (!allFinite(x_)) throw InvalidInput("se(2) exp: tangent has a NaN or infinite coefficient");
  const S th = x_(0);
  const S A = detail::se2::sinc(th);
  const S B = th * detail::se2::cosc(th);
  const Vec2<S> t(A * x_(1) - B * x_(2), B * x_(1) + A * x_(2));
  return SE2<S>(th, t);
}

template <class S> Mat3<S> SE2Tangent<S>::ad() const {
  Mat3<S> m;
  m << S(0), S(0), S(0), x_(2), S(0), -x_(0), -x_(1), x_(0), S(0);
  return m;
}

template <class S> Mat3<S> SE2Tangent<S>::ljac() const {
  // GF §5.3, GF-5.3-se2-dexp: Jl = I + (1−cosθ)/θ² ad + (θ−sinθ)/θ³ ad², in closed form:
  // [[1,0,0],[P vx + Q vy, A, −B],[−Q vx + P vy, B, A]] with P = (θ−sinθ)/θ², Q = (1−cosθ)/θ².
  const S th = x_(0);
  const S A = detail::se2::sinc(th);
  const S Q = detail::se2::cosc(th);
  const S B = th * Q;
  const S P = th * detail::se2::sincc(th);
  Mat3<S> J;
  J << S(1), S(0), S(0),                    //
      P * x_(1) + Q * x_(2), A, -B,          //
      -Q * x_(1) + P * x_(2), B, A;
  return J;
}

template <class S> Mat3<S> SE2Tangent<S>::rjac() const { return (-*this).ljac(); }

template <class S> Mat3<S> SE2Tangent<S>::ljacinv() const {
  // J = [[1,0],[w, V]] ⇒ J⁻¹ = [[1,0],[−V⁻¹w, V⁻¹]], V⁻¹ = [[k, θ/2],[−θ/2, k]], k = (θ/2)cot(θ/2).
  const S th = x_(0);
  const S k = detail::se2::halfCot(th);
  const S h = th / S(2);
  Mat2<S> Vi;
  Vi << k, h, -h, k;
  const S Q = detail::se2::cosc(th);
  const S P = th * detail::se2::sincc(th);
  const Vec2<S> w(P * x_(1) + Q * x_(2), -Q * x_(1) + P * x_(2));
  Mat3<S> J = Mat3<S>::Zero();
  J(0, 0) = S(1);
  J.template block<2, 2>(1, 1) = Vi;
  J.template block<2, 1>(1, 0) = -(Vi * w);
  return J;
}

template <class S> Mat3<S> SE2Tangent<S>::rjacinv() const { return (-*this).ljacinv(); }

// ------------------------------------------------------------------------------------------
// SE2

template <class S> SE2<S>::SE2(const S& angle, const Vec2<S>& t) : t_(t) {
  using std::cos;
  using std::sin;
  if (!isFinite(angle) || !allFinite(t))
    throw InvalidInput("SE(2): angle " + toString(angle) + " or translation is not finite");
  c_ = cos(angle);
  s_ = sin(angle);
}

template <class S> SE2<S> SE2<S>::fromComplex(const S& c, const S& s, const Vec2<S>& t) {
  using std::abs;
  using std::sqrt;
  if (!isFinite(c) || !isFinite(s) || !allFinite(t))
    throw InvalidInput("SE(2): rotation (c, s) or translation has a NaN or infinite entry");
  const S n2 = c * c + s * s;
  if (abs(n2 - S(1)) > S(2) * Tolerance<S>::input())
    throw InvalidInput("SE(2): rotation (c, s) = (" + toString(c) + ", " + toString(s) +
                       ") is not a unit complex number (|c+is|² = " + toString(n2) + ")");
  const S n = sqrt(n2);
  return SE2(Raw{}, c / n, s / n, t);
}

template <class S> SE2<S> SE2<S>::fromMatrix(const Mat3<S>& m) {
  using std::abs;
  using std::atan2;
  if (!allFinite(m)) throw InvalidInput("SE(2) fromMatrix: matrix has a NaN or infinite entry");
  const S tol = Tolerance<S>::input();
  if (abs(m(2, 0)) > tol || abs(m(2, 1)) > tol || abs(m(2, 2) - S(1)) > tol)
    throw InvalidInput("SE(2) fromMatrix: last row is not (0, 0, 1)");
  const Mat2<S> R = m.template block<2, 2>(0, 0);
  const Mat2<S> defect = R.transpose() * R - Mat2<S>::Identity();
  if (defect.cwiseAbs().maxCoeff() > tol)
    throw InvalidInput("SE(2) fromMatrix: rotation block is not orthogonal (max |RᵀR − I| = " +
                       toString(defect.cwiseAbs().maxCoeff()) + ")");
  if (R.determinant() < S(0))
    throw InvalidInput("SE(2) fromMatrix: rotation block has det −1 (a reflection)");
  // Nearest rotation to R (polar factor): angle atan2(R10 − R01, R00 + R11).
  const S th = atan2(R(1, 0) - R(0, 1), R(0, 0) + R(1, 1));
  return SE2(th, Vec2<S>(m(0, 2), m(1, 2)));
}

template <class S> SE2<S> SE2<S>::rotationAbout(const S& angle, const Vec2<S>& c) {
  // GF §5.3, GF-5.3-se2-rotation-about-point: [[R, (I − R)c],[0, 1]]
  SE2 r(angle, Vec2<S>::Zero());
  r.t_ = c - r.rotation() * c;
  return r;
}

template <class S> S SE2<S>::angle() const {
  using std::atan2;
  // θ ∈ (−π, π]: only the exact half-turn s = ±0, c < 0 is mapped to +π (atan2(−0, −1) = −π).
  // A tiny negative s is a genuine angle −π + |s|: its correctly rounded value may be −π_S
  // (when π_S > π, as for float and long double) and must keep its sign, so that
  // log(exp(ξ)) follows the principal branch and sign(ω) = sign(s).
  if (s_ == S(0) && c_ < S(0)) return pi<S>();
  return atan2(s_, c_);
}

template <class S> Mat2<S> SE2<S>::rotation() const {
  Mat2<S> R;
  R << c_, -s_, s_, c_;
  return R;
}

template <class S> Mat3<S> SE2<S>::matrix() const {
  Mat3<S> m;
  m << c_, -s_, t_(0), s_, c_, t_(1), S(0), S(0), S(1);
  return m;
}

template <class S> SE2<S> SE2<S>::operator*(const SE2& o) const {
  using std::sqrt;
  S c = c_ * o.c_ - s_ * o.s_;
  S s = s_ * o.c_ + c_ * o.s_;
  // Keep (c, s) on the unit circle against drift from repeated products (not user input).
  const S n = sqrt(c * c + s * s);
  c /= n;
  s /= n;
  return SE2(Raw{}, c, s, Vec2<S>(act(o.t_)));
}

template <class S> SE2<S> SE2<S>::inverse() const {
  const Vec2<S> ti(-(c_ * t_(0) + s_ * t_(1)), -(-s_ * t_(0) + c_ * t_(1)));
  return SE2(Raw{}, c_, -s_, ti);
}

template <class S> Vec2<S> SE2<S>::act(const Vec2<S>& x) const {
  return Vec2<S>(c_ * x(0) - s_ * x(1) + t_(0), s_ * x(0) + c_ * x(1) + t_(1));
}

template <class S> Mat3<S> SE2<S>::adjoint() const {
  Mat3<S> m;
  m << S(1), S(0), S(0), t_(1), c_, -s_, -t_(0), s_, c_;
  return m;
}

template <class S> SE2Tangent<S> SE2<S>::log() const {
  // Inverse of GF-5.3-se2-algebra-exp-ad. θ = atan2(s, c) is accurate at θ ≈ π too (there the
  // rotation is read from s); k = (θ/2)cot(θ/2) comes from the half angle, so near π it has no
  // cancellation (own branch inside halfCot), near 0 it is the Taylor series.
  const S th = angle();
  const S k = detail::se2::halfCot(th);
  const S h = th / S(2);
  return Tangent(th, k * t_(0) + h * t_(1), -h * t_(0) + k * t_(1));
}

template <class S> SE2<S> SE2<S>::interpolate(const SE2& a, const SE2& b, const S& tau) {
  return a * (tau * (a.inverse() * b).log()).exp();
}

template <class S> Vec2<S> SE2<S>::centre() const {
  // GF §5.3, GF-5.3-se2-rotation-about-point: c = (I − Rᵀ)t / Δ, Δ = 2 − 2cosθ = 4 sin²(θ/2).
  // Written as c = ½ (t + cot(θ/2) J t), J t = (−ty, tx): no division by a cancelled Δ.
  using std::abs;
  using std::cos;
  using std::sin;
  const S th = angle();
  if (abs(th) <= Tolerance<S>::sqrtEpsilon())
    throw InvalidInput("SE(2) centre: the motion is a pure translation (θ = " + toString(th) +
                       "); its centre is at infinity");
  const S h = th / S(2);
  const S ct = cos(h) / sin(h);
  return Vec2<S>((t_(0) - ct * t_(1)) / S(2), (t_(1) + ct * t_(0)) / S(2));
}

template <class S> bool SE2<S>::isApprox(const SE2& o, const S& tol) const {
  using std::abs;
  const S scale = S(1) + t_.cwiseAbs().maxCoeff();
  return (matrix() - o.matrix()).cwiseAbs().maxCoeff() <= tol * scale;
}

using SE2f = SE2<float>;
using SE2d = SE2<double>;
using SE2ld = SE2<long double>;
using SE2q = SE2<__float128>;
using SE2mp = SE2<mpreal>;

#define SOMA_SE2_EXTERN(T)                   \
  extern template class SE2Tangent<T>;       \
  extern template class SE2<T>;
SOMA_FOR_EACH_SCALAR(SOMA_SE2_EXTERN)
#undef SOMA_SE2_EXTERN

}  // namespace soma
