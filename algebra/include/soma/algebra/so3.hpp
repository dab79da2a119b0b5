#pragma once
// SO(3) and its Lie algebra so(3) (GF §2.2.2, §4.1, §4.4.1, §4.5.3), manif/Sophus style:
// the group SO3<S> stores a unit quaternion, the tangent SO3Tangent<S> a 3-vector ω.
// Jacobians are right Jacobians unless named otherwise (manif): exp(ω ⊕ δ) ≈ exp(ω)·exp(Jr δ).
// The book's dexp (GF §4.5.2, spatial, (d/dt e^X) e^{−X}) is the LEFT Jacobian ljac().
#include "soma/algebra/errors.hpp"
#include "soma/algebra/quaternion.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/taylor.hpp"
#include "soma/algebra/tolerance.hpp"

#include <random>
#include <string>

// The few-line helpers of the inline maps below: GCC's heuristics sometimes keep them out of
// line once a translation unit calls them from several places, which costs more than they do.
#if defined(__GNUC__)
#define SOMA_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define SOMA_ALWAYS_INLINE inline
#endif

namespace soma {


/// Skew matrix of ω: hat(ω) x = ω × x.
// GF §4.1, GF-4.1-hat-map (the book's ε-formula has the opposite sign, erratum E4.2)
template <class S> Mat3<S> skew(const Vec3<S>& w) {
  Mat3<S> m;
  m << S(0), -w.z(), w.y(), w.z(), S(0), -w.x(), -w.y(), w.x(), S(0);
  return m;
}

template <class S> class SO3;

/// Element ω of so(3) (axis × angle).
template <class S> class SO3Tangent {
 public:
  using Scalar = S;
  using Group = SO3<S>;
  static constexpr int DoF = 3;
  using DataType = Vec3<S>;
  using Jacobian = Mat3<S>;
  using LieAlg = Mat3<S>;

  SO3Tangent() : w_(Vec3<S>::Zero()) {}
  explicit SO3Tangent(const Vec3<S>& w) : w_(w) {}
  static SO3Tangent Zero() { return SO3Tangent(); }

  const Vec3<S>& coeffs() const { return w_; }
  Vec3<S>& coeffs() { return w_; }
  /// Rotation angle |ω|.
  S angle() const;

  /// hat(ω): 3×3 skew matrix with hat(ω)x = ω × x. GF §4.1, GF-4.1-hat-map
  Mat3<S> hat() const { return skew(w_); }
  /// Inverse of hat (reads the three independent entries; no check of skewness).
  static SO3Tangent vee(const Mat3<S>& m) { return SO3Tangent(Vec3<S>(m(2, 1), m(0, 2), m(1, 0))); }

  /// Exponential map (Rodrigues via the half-angle quaternion); J_out = right Jacobian.
  // GF §4.4.1, GF-4.4.1-rodrigues
  SO3<S> exp(Mat3<S>* J_out = nullptr) const;

  /// Right Jacobian Jr(ω) = I − (1−cos θ)/θ² Ω + (θ−sin θ)/θ³ Ω² (body-fixed dexp).
  Mat3<S> rjac() const;
  /// Left Jacobian Jl(ω) = Σ ad^k/(k+1)! = I + (1−cos θ)/θ² Ω + (θ−sin θ)/θ³ Ω².
  // GF §4.5.3, GF-4.5.3-so3-dexp-and-inverse
  Mat3<S> ljac() const;
  /// Jr⁻¹ = I + ½Ω + (1/θ² − cot(θ/2)/(2θ)) Ω² (singular at θ = 2π).
  Mat3<S> rjacinv() const;
  /// Jl⁻¹ = I − ½Ω + (1/θ² − cot(θ/2)/(2θ)) Ω². GF §4.5.3, GF-4.5.3-so3-dexp-and-inverse
  Mat3<S> ljacinv() const;
  /// ad(ω) = Ω. GF §4.3, GF-4.3-so3-su2-commutators
  Mat3<S> ad() const { return hat(); }

  SO3Tangent operator+(const SO3Tangent& o) const { return SO3Tangent(w_ + o.w_); }
  SO3Tangent operator-(const SO3Tangent& o) const { return SO3Tangent(w_ - o.w_); }
  SO3Tangent operator-() const { return SO3Tangent(-w_); }
  SO3Tangent operator*(const S& s) const { return SO3Tangent(w_ * s); }
  friend SO3Tangent operator*(const S& s, const SO3Tangent& t) { return SO3Tangent(t.w_ * s); }
  bool isApprox(const SO3Tangent& o, const S& tol) const {
    return (w_ - o.w_).template lpNorm<Eigen::Infinity>() <= tol;
  }
  template <class T> SO3Tangent<T> cast() const { return SO3Tangent<T>(castMatrix<T>(w_)); }

 private:
  Vec3<S> w_;
};

/// A rotation, stored as a unit quaternion.
template <class S> class SO3 {
 public:
  using Scalar = S;
  using Tangent = SO3Tangent<S>;
  static constexpr int DoF = 3;
  static constexpr int Dim = 3;  // dimension of the space it acts on
  using Jacobian = Mat3<S>;
  using Point = Vec3<S>;
  using Transformation = Mat3<S>;

  /// The identity.
  SO3() : q_(S(1), S(0), S(0), S(0)) {}
  static SO3 Identity() { return SO3(); }

  /// From a quaternion with ||q| − 1| ≤ Tolerance::input(); normalised. Throws InvalidInput.
  static SO3 fromQuaternion(const Quat<S>& q);
  /// From a rotation matrix: finite, |RᵀR − I|∞ ≤ Tolerance::input(), det > 0. Throws.
  // GF §2.2.2, GF-2.2.2-SO3-to-quaternion-charts
  static SO3 fromMatrix(const Mat3<S>& r);
  /// Rotation by θ about a unit axis (||axis| − 1| ≤ Tolerance::input()). Throws.
  static SO3 fromAxisAngle(const Vec3<S>& axis, const S& theta);
  /// Uniform random rotation (normalised Gaussian quaternion drawn in double, cast to S).
  static SO3 Random(std::mt19937_64& g);

  const Quat<S>& quaternion() const { return q_; }
  /// R by the book's 1/Δ formula. GF §2.2.2, GF-2.2.2-SO3-from-quaternion
  Mat3<S> matrix() const { return rotationFromQuaternion(q_); }

  /// Inverse; J_out = d(X⁻¹)/dX = −Ad(X) = −R.
  SO3 inverse(Mat3<S>* J_out = nullptr) const;
  /// Composition this·b; J_out_self = Ad(b)⁻¹ = R_bᵀ, J_out_b = I.
  SO3 compose(const SO3& b, Mat3<S>* J_out_self = nullptr, Mat3<S>* J_out_b = nullptr) const;
  SO3 operator*(const SO3& b) const { return compose(b); }
  /// Active rotation of a point: R p; J_out_self = −R hat(p), J_out_p = R.
  Vec3<S> act(const Vec3<S>& p, Mat3<S>* J_out_self = nullptr, Mat3<S>* J_out_p = nullptr) const;
  Vec3<S> operator*(const Vec3<S>& p) const { return act(p); }
  /// Ad(R) = R (Ad(R)ω = Rω). GF §4.2, GF-4.2-adjoint-SO3
  Mat3<S> adjoint() const { return matrix(); }

  /// Logarithm: angle by atan2(|v|, w) on the quaternion (w ≥ 0), θ ∈ [0, π]; exact at θ = π
  /// (returns one of the two logs ±πâ). J_out = Jr⁻¹(log).
  // GF §4.4.1, GF-4.4.1-so3-log-trace (computed from the quaternion, not the trace)
  Tangent log(Mat3<S>* J_out = nullptr) const;

  /// X ⊕ τ = X·exp(τ).
  SO3 rplus(const Tangent& t) const { return compose(t.exp()); }
  /// τ ⊕ X = exp(τ)·X.
  SO3 lplus(const Tangent& t) const { return t.exp().compose(*this); }
  /// X ⊖ Y = log(Y⁻¹·X).
  Tangent rminus(const SO3& y) const { return y.inverse().compose(*this).log(); }
  /// X ⊖ Y (left) = log(X·Y⁻¹).
  Tangent lminus(const SO3& y) const { return compose(y.inverse()).log(); }
  /// X⁻¹·Y.
  SO3 between(const SO3& y) const { return inverse().compose(y); }
  /// Geodesic a·exp(t·log(a⁻¹b)): t = 0 gives a, t = 1 gives b.
  static SO3 interpolate(const SO3& a, const SO3& b, const S& t) {
    return a.rplus(b.rminus(a) * t);
  }

  /// Same rotation, quaternion up to sign, within tol (max-norm of the difference).
  bool isApprox(const SO3& o, const S& tol) const;
  template <class T> SO3<T> cast() const {
    return SO3<T>::fromQuaternionUnchecked(Quat<T>(castMatrix<T>(q_.coeffs())));
  }
  /// No validation: q must already be unit (used by exp, products and casts). Normalises.
  static SO3 fromQuaternionUnchecked(const Quat<S>& q) {
    SO3 r;
    r.q_ = q;
    r.q_.coeffs() /= q.coeffs().norm();
    return r;
  }
  /// No validation, no normalisation: q must be unit to a few ulps (exp's cos/sin pair, a
  /// conjugate). The hot paths use it to skip the sqrt and four divisions.
  static SO3 fromUnitQuaternion(const Quat<S>& q) {
    SO3 r;
    r.q_ = q;
    return r;
  }
  /// Product of two unit quaternions, renormalised by one Newton step for 1/√n², n²=|q|²:
  /// q·(3 − n²)/2. The product's |n² − 1| is a few ulps, so the step leaves a defect of
  /// (3/4)(n² − 1)² (far below an ulp) at the cost of 5 multiplies, no sqrt or division.
  static SO3 fromUnitProduct(const Quat<S>& q) {
    // Written per component: a packed squaredNorm over the four scalars just computed makes
    // GCC store them and reload them as pairs (a store-forwarding stall, ~2× the whole compose).
    const S n2 = q.w() * q.w() + q.x() * q.x() + q.y() * q.y() + q.z() * q.z();
    const S k = (S(3) - n2) / S(2);
    SO3 r;
    r.q_ = Quat<S>(k * q.w(), k * q.x(), k * q.y(), k * q.z());
    return r;
  }

 private:
  // The Jacobian outputs of compose and act, out of line (compiled once per scalar in
  // algebra/src) so that the inline maps stay small enough to be inlined.
  void composeJacobians(const SO3& b, Mat3<S>* J_out_self, Mat3<S>* J_out_b) const;
  void actJacobians(const Vec3<S>& p, Mat3<S>* J_out_self, Mat3<S>* J_out_p) const;

  Quat<S> q_;
};

// ---------------------------------------------------------------------------------------------
// Implementation

namespace detail {
/// Coefficients B = (1−cos θ)/θ², C = (θ−sin θ)/θ³ of Jl, Jr (Taylor below precision(3)).
template <class S> void so3JacobianCoefficients(const S& theta2, S& B, S& C) {
  using std::sin;
  using std::sqrt;
  if (theta2 < taylorSwitch2<S>(3)) {  // series to θ², remainder θ⁴/720 < eps
    B = S(1) / S(2) - theta2 / S(24);
    C = S(1) / S(6) - theta2 / S(120);
    return;
  }
  const S theta = sqrt(theta2);
  const S s = sin(theta / S(2));
  B = S(2) * s * s / theta2;  // 1 − cos θ = 2 sin²(θ/2): no cancellation
  C = theta2 <= S(1) ? thetaMinusSinOverCube(theta2) : thetaMinusSin(theta) / (theta2 * theta);
}
/// D = 1/θ² − cot(θ/2)/(2θ) = 1/θ² − (1+cos θ)/(2θ sin θ) of Jl⁻¹, Jr⁻¹ (Taylor below
/// precision(3)).
template <class S> S so3InverseJacobianCoefficient(const S& theta2) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta2 < taylorSwitch2<S>(3)) return S(1) / S(12) + theta2 / S(720);
  const S theta = sqrt(theta2);
  return S(1) / theta2 - cos(theta / S(2)) / (S(2) * theta * sin(theta / S(2)));
}
}  // namespace detail

template <class S> S SO3Tangent<S>::angle() const {
  using std::sqrt;
  return sqrt(w_.squaredNorm());
}

namespace detail {
/// The half-angle quaternion of exp(ω): w = cos(θ/2), k = sin(θ/2)/θ (q = (w, kω)), and
/// sh = sin(θ/2), for θ² = |ω|². Taylor for k below precision(3) (remainder θ⁴/3840 < eps).
template <class S> struct So3HalfAngle {
  S theta, w, k, sh;
};
template <class S> SOMA_ALWAYS_INLINE So3HalfAngle<S> so3HalfAngle(const S& theta2) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  So3HalfAngle<S> h;
  h.theta = sqrt(theta2);
  const S half = h.theta / S(2);
  h.sh = sin(half);  // sin and cos of one argument: GCC emits one sincos call
  h.w = cos(half);
  h.k = theta2 < taylorSwitch2<S>(3) ? S(1) / S(2) - theta2 / S(48) : h.sh / h.theta;
  return h;
}
/// Unit quaternion q = (w, v) rotating p: p + w u + v × u with u = 2 v × p (15 multiplies, no
/// 3×3 matrix, no division). For |q| = 1 it is R(q) p.
template <class S> SOMA_ALWAYS_INLINE Vec3<S> rotateByUnitQuaternion(const Quat<S>& q, const Vec3<S>& p) {
  // Scalars, not Eigen's cross(): in a large translation unit GCC may leave Eigen's cross out
  // of line (a call and a round trip through memory for every product).
  const S ux = S(2) * (q.y() * p.z() - q.z() * p.y());
  const S uy = S(2) * (q.z() * p.x() - q.x() * p.z());
  const S uz = S(2) * (q.x() * p.y() - q.y() * p.x());
  return Vec3<S>(p.x() + q.w() * ux + (q.y() * uz - q.z() * uy),
                 p.y() + q.w() * uy + (q.z() * ux - q.x() * uz),
                 p.z() + q.w() * uz + (q.x() * uy - q.y() * ux));
}
}  // namespace detail

// exp, log, compose, act and inverse are `inline` (the rest of the class is compiled once per
// scalar in algebra/src): an explicit instantiation declaration does not stop the compiler from
// inlining inline members, so a caller's tight loop sees these few-nanosecond maps whole
// (Sophus's are header-only), and the J_out == nullptr branches fold away.
template <class S> inline SO3<S> SO3Tangent<S>::exp(Mat3<S>* J_out) const {
  if (!allFinite(w_)) throw InvalidInput("so(3) exp: tangent ω has a NaN or infinite component");
  const auto h = detail::so3HalfAngle(w_.squaredNorm());
  const Quat<S> q(h.w, h.k * w_.x(), h.k * w_.y(), h.k * w_.z());
  if (J_out) *J_out = rjac();
  // cos²(θ/2) + k²θ² = 1 to a few ulps: no renormalisation (its sqrt and 4 divisions).
  return SO3<S>::fromUnitQuaternion(q);
}

template <class S> Mat3<S> SO3Tangent<S>::rjac() const {
  S B, C;
  detail::so3JacobianCoefficients(w_.squaredNorm(), B, C);
  const Mat3<S> W = hat();
  return Mat3<S>::Identity() - B * W + C * W * W;
}
template <class S> Mat3<S> SO3Tangent<S>::ljac() const {
  S B, C;
  detail::so3JacobianCoefficients(w_.squaredNorm(), B, C);
  const Mat3<S> W = hat();
  return Mat3<S>::Identity() + B * W + C * W * W;
}
template <class S> Mat3<S> SO3Tangent<S>::rjacinv() const {
  const S D = detail::so3InverseJacobianCoefficient(w_.squaredNorm());
  const Mat3<S> W = hat();
  return Mat3<S>::Identity() + W / S(2) + D * W * W;
}
template <class S> Mat3<S> SO3Tangent<S>::ljacinv() const {
  const S D = detail::so3InverseJacobianCoefficient(w_.squaredNorm());
  const Mat3<S> W = hat();
  return Mat3<S>::Identity() - W / S(2) + D * W * W;
}

template <class S> SO3<S> SO3<S>::fromQuaternion(const Quat<S>& q) {
  using std::abs;
  using std::sqrt;
  if (!allFinite(q.coeffs()))
    throw InvalidInput("SO3::fromQuaternion: quaternion has a NaN or infinite component");
  const S n = sqrt(q.coeffs().squaredNorm());
  if (abs(n - S(1)) > Tolerance<S>::input())
    throw InvalidInput("SO3::fromQuaternion: quaternion is not unit (|q| = " + toString(n, 17) +
                       ", accepted defect " + toString(Tolerance<S>::input(), 3) + ")");
  return fromQuaternionUnchecked(q);
}

template <class S> SO3<S> SO3<S>::fromMatrix(const Mat3<S>& r) {
  if (!allFinite(r)) throw InvalidInput("SO3::fromMatrix: matrix has a NaN or infinite entry");
  const S defect =
      (r.transpose() * r - Mat3<S>::Identity()).template lpNorm<Eigen::Infinity>();
  if (defect > Tolerance<S>::input())
    throw InvalidInput("SO3::fromMatrix: matrix is not orthogonal (|RᵀR − I| = " +
                       toString(defect, 3) + ", accepted " + toString(Tolerance<S>::input(), 3) +
                       ")");
  if (r.determinant() < S(0))
    throw InvalidInput("SO3::fromMatrix: matrix has det = −1 (a reflection, not a rotation)");
  return fromQuaternionUnchecked(quaternionFromRotation(r));
}

template <class S> SO3<S> SO3<S>::fromAxisAngle(const Vec3<S>& axis, const S& theta) {
  using std::abs;
  using std::sqrt;
  if (!allFinite(axis) || !isFinite(theta))
    throw InvalidInput("SO3::fromAxisAngle: axis or angle has a NaN or infinite component");
  const S n = sqrt(axis.squaredNorm());
  if (abs(n - S(1)) > Tolerance<S>::input())
    throw InvalidInput("SO3::fromAxisAngle: axis is not a unit vector (|axis| = " +
                       toString(n, 17) + ")");
  return Tangent(axis * (theta / n)).exp();
}

template <class S> SO3<S> SO3<S>::Random(std::mt19937_64& g) {
  std::normal_distribution<double> nd;
  Quat<S> q;
  do {
    q = Quat<S>(scalarCast<S>(nd(g)), scalarCast<S>(nd(g)), scalarCast<S>(nd(g)),
                scalarCast<S>(nd(g)));
  } while (q.coeffs().squaredNorm() < S(1) / S(1000000));
  return fromQuaternionUnchecked(q);
}

template <class S> SOMA_ALWAYS_INLINE SO3<S> SO3<S>::inverse(Mat3<S>* J_out) const {
  if (J_out) *J_out = -matrix();
  return fromUnitQuaternion(q_.conjugate());  // the conjugate of a unit quaternion is unit
}

template <class S>
void SO3<S>::composeJacobians(const SO3& b, Mat3<S>* J_out_self, Mat3<S>* J_out_b) const {
  if (J_out_self) *J_out_self = b.matrix().transpose();
  if (J_out_b) *J_out_b = Mat3<S>::Identity();
}
template <class S>
SOMA_ALWAYS_INLINE SO3<S> SO3<S>::compose(const SO3& b, Mat3<S>* J_out_self, Mat3<S>* J_out_b) const {
  if (J_out_self || J_out_b) composeJacobians(b, J_out_self, J_out_b);
  if constexpr (std::is_same_v<S, float> || std::is_same_v<S, double>)
    return fromUnitProduct(q_ * b.q_);  // Eigen's SSE kernel for the same Hamilton product
  else
    return fromUnitProduct(quaternionProduct(q_, b.q_));
}

template <class S>
void SO3<S>::actJacobians(const Vec3<S>& p, Mat3<S>* J_out_self, Mat3<S>* J_out_p) const {
  const Mat3<S> r = matrix();
  if (J_out_self) *J_out_self = -r * skew(p);
  if (J_out_p) *J_out_p = r;
}
template <class S>
SOMA_ALWAYS_INLINE Vec3<S> SO3<S>::act(const Vec3<S>& p, Mat3<S>* J_out_self, Mat3<S>* J_out_p) const {
  if (J_out_self || J_out_p) actJacobians(p, J_out_self, J_out_p);
  return detail::rotateByUnitQuaternion(q_, p);
}

template <class S> inline SO3Tangent<S> SO3<S>::log(Mat3<S>* J_out) const {
  using std::atan2;
  using std::sqrt;
  const S sign = q_.w() < S(0) ? S(-1) : S(1);  // w ≥ 0: θ ∈ [0, π]
  const S w = sign * q_.w();
  const Vec3<S> v = sign * q_.vec();
  const S n2 = v.squaredNorm();
  S k;  // θ / |v| with θ = 2 atan2(|v|, w)
  if (n2 < detail::taylorSwitch2<S>(3)) {
    // 2 atan(n/w)/n = (2/w)(1 − n²/(3w²) + …), remainder n⁴/5 < eps (w ≈ 1 here)
    k = S(2) / w * (S(1) - n2 / (S(3) * w * w));
  } else {
    const S n = sqrt(n2);
    k = S(2) * atan2(n, w) / n;
  }
  const Tangent t(k * v);
  if (J_out) *J_out = t.rjacinv();
  return t;
}

template <class S> bool SO3<S>::isApprox(const SO3& o, const S& tol) const {
  const S a = (q_.coeffs() - o.q_.coeffs()).template lpNorm<Eigen::Infinity>();
  const S b = (q_.coeffs() + o.q_.coeffs()).template lpNorm<Eigen::Infinity>();
  return (a < b ? a : b) <= tol;
}

using SO3f = SO3<float>;
using SO3d = SO3<double>;
using SO3ld = SO3<long double>;
using SO3q = SO3<__float128>;
using SO3mp = SO3<mpreal>;

#define SOMA_SO3_EXTERN(S)                  \
  extern template class SO3Tangent<S>;      \
  extern template class SO3<S>;
SOMA_FOR_EACH_SCALAR(SOMA_SO3_EXTERN)
#undef SOMA_SO3_EXTERN

}  // namespace soma
