#pragma once
// SE(3) = SO(3) ⋉ R³ and its Lie algebra se(3) (GF §2.5, §4.1–4.5), manif/Sophus style.
// Twists are ordered (ω, v); the moment of a screw through q is v = q × ω (+ pitch·ω), so a
// point moves with ṗ = ω × p + v. ad(s) = [[Ω, 0], [V, Ω]], Ad(R, t) = [[R, 0], [T R, R]].
// Jacobians are right Jacobians (manif); the book's spatial dexp is ljac().
#include "soma/algebra/so3.hpp"

namespace soma {

template <class S> class SE3;

/// Element s = (ω; v) of se(3).
template <class S> class SE3Tangent {
 public:
  using Scalar = S;
  using Group = SE3<S>;
  static constexpr int DoF = 6;
  using DataType = Vec6<S>;
  using Jacobian = Mat6<S>;
  using LieAlg = Mat4<S>;

  SE3Tangent() : s_(Vec6<S>::Zero()) {}
  explicit SE3Tangent(const Vec6<S>& s) : s_(s) {}
  SE3Tangent(const Vec3<S>& w, const Vec3<S>& v) {
    s_.template head<3>() = w;
    s_.template tail<3>() = v;
  }
  static SE3Tangent Zero() { return SE3Tangent(); }

  const Vec6<S>& coeffs() const { return s_; }
  Vec6<S>& coeffs() { return s_; }
  Vec3<S> ang() const { return s_.template head<3>(); }
  Vec3<S> lin() const { return s_.template tail<3>(); }

  /// 4×4 [[Ω, v], [0, 0]]. GF §4.1, GF-4.1-se3-twist-velocity
  Mat4<S> hat() const;
  static SE3Tangent vee(const Mat4<S>& m) {
    return SE3Tangent(Vec3<S>(m(2, 1), m(0, 2), m(1, 0)), Vec3<S>(m(0, 3), m(1, 3), m(2, 3)));
  }

  /// exp: R = exp(Ω), t = Jl_so3(ω) v; J_out = right Jacobian.
  // GF §4.4.2, GF-4.4.2-se3-exp-4x4 (the equivalent (e^Ω, V u) form)
  SE3<S> exp(Mat6<S>* J_out = nullptr) const;

  /// Right Jacobian Jr(s) = Jl(−s).
  Mat6<S> rjac() const;
  /// Left Jacobian Jl(s) = Σ ad(s)^k/(k+1)! = [[Jl, 0], [Q(ω, v), Jl]] (closed-form Q-block).
  // GF §4.5.4, GF-4.5.4-se3-dexp-and-inverse
  Mat6<S> ljac() const;
  Mat6<S> rjacinv() const;
  Mat6<S> ljacinv() const;
  /// ad(s) = [[Ω, 0], [V, Ω]]. GF §4.3, GF-4.3-se3-commutators-ad
  Mat6<S> ad() const;

  SE3Tangent operator+(const SE3Tangent& o) const { return SE3Tangent(Vec6<S>(s_ + o.s_)); }
  SE3Tangent operator-(const SE3Tangent& o) const { return SE3Tangent(Vec6<S>(s_ - o.s_)); }
  SE3Tangent operator-() const { return SE3Tangent(Vec6<S>(-s_)); }
  SE3Tangent operator*(const S& k) const { return SE3Tangent(Vec6<S>(s_ * k)); }
  friend SE3Tangent operator*(const S& k, const SE3Tangent& t) { return t * k; }
  bool isApprox(const SE3Tangent& o, const S& tol) const {
    return (s_ - o.s_).template lpNorm<Eigen::Infinity>() <= tol;
  }
  template <class T> SE3Tangent<T> cast() const { return SE3Tangent<T>(castMatrix<T>(s_)); }

 private:
  Vec6<S> s_;
};

/// A rigid motion p ↦ R p + t (active), stored as (SO3, t).
template <class S> class SE3 {
 public:
  using Scalar = S;
  using Tangent = SE3Tangent<S>;
  static constexpr int DoF = 6;
  static constexpr int Dim = 3;
  using Jacobian = Mat6<S>;
  using Point = Vec3<S>;
  using Transformation = Mat4<S>;

  SE3() : r_(), t_(Vec3<S>::Zero()) {}
  /// From a rotation and a translation; throws InvalidInput when t has a NaN or infinity.
  SE3(const SO3<S>& r, const Vec3<S>& t) : r_(r), t_(t) {
    if (!allFinite(t_)) throw InvalidInput("SE3: translation has a NaN or infinite component");
  }
  static SE3 Identity() { return SE3(); }
  /// From a 4×4 homogeneous matrix: rotation block validated as in SO3::fromMatrix, last row
  /// (0, 0, 0, 1) within Tolerance::input(), finite translation. Throws InvalidInput.
  // GF §2.5.1, GF-2.5.1-homogeneous
  static SE3 fromMatrix(const Mat4<S>& m);
  /// Random rotation and translation uniform in [−1, 1]³.
  static SE3 Random(std::mt19937_64& g);

  /// [[R, t], [0, 1]]. GF §2.5.1, GF-2.5.1-homogeneous
  Mat4<S> matrix() const;
  Mat3<S> rotation() const { return r_.matrix(); }
  const SO3<S>& so3() const { return r_; }
  const Vec3<S>& translation() const { return t_; }
  const Quat<S>& quaternion() const { return r_.quaternion(); }

  /// (Rᵀ, −Rᵀt); J_out = −Ad(X). GF §2.5.1, GF-2.5.1-homogeneous
  SE3 inverse(Mat6<S>* J_out = nullptr) const;
  /// (R_a R_b, R_a t_b + t_a); J_out_self = Ad(b)⁻¹, J_out_b = I. GF §2.5.1, GF-2.5.1-euclidean-pairs
  SE3 compose(const SE3& b, Mat6<S>* J_out_self = nullptr, Mat6<S>* J_out_b = nullptr) const;
  SE3 operator*(const SE3& b) const { return compose(b); }
  /// Active action on a point, R p + t; J_out_self = [−R hat(p), R] (3×6), J_out_p = R.
  Vec3<S> act(const Vec3<S>& p, Eigen::Matrix<S, 3, 6>* J_out_self = nullptr,
              Mat3<S>* J_out_p = nullptr) const;
  Vec3<S> operator*(const Vec3<S>& p) const { return act(p); }
  /// Ad = [[R, 0], [T R, R]], T = hat(t). GF §4.2, GF-4.2-adjoint-SE3
  Mat6<S> adjoint() const;

  /// log: ω = log R (θ ∈ [0, π]), v = Jl_so3(ω)⁻¹ t; J_out = Jr⁻¹(log).
  // GF §4.4.2, GF-4.4.2-se3-log-4x4 (computed as log R and V⁻¹t, the book's advice for small θ)
  Tangent log(Mat6<S>* J_out = nullptr) const;

  SE3 rplus(const Tangent& t) const { return compose(t.exp()); }
  SE3 lplus(const Tangent& t) const { return t.exp().compose(*this); }
  Tangent rminus(const SE3& y) const { return y.inverse().compose(*this).log(); }
  Tangent lminus(const SE3& y) const { return compose(y.inverse()).log(); }
  SE3 between(const SE3& y) const { return inverse().compose(y); }
  /// Geodesic (screw motion) a·exp(t·log(a⁻¹b)).
  static SE3 interpolate(const SE3& a, const SE3& b, const S& t) {
    return a.rplus(b.rminus(a) * t);
  }

  /// Rotations agree (quaternion up to sign) and translations agree, within tol (max-norm).
  bool isApprox(const SE3& o, const S& tol) const {
    return r_.isApprox(o.r_, tol) && (t_ - o.t_).template lpNorm<Eigen::Infinity>() <= tol;
  }
  template <class T> SE3<T> cast() const {
    return SE3<T>(r_.template cast<T>(), castMatrix<T>(t_));
  }

 private:
  struct Unchecked {};
  // For results of maps of valid elements (finite in, finite out): no allFinite test.
  SE3(const SO3<S>& r, const Vec3<S>& t, Unchecked) : r_(r), t_(t) {}
  friend class SE3Tangent<S>;
  // Jacobian outputs of compose and act, out of line (see so3.hpp).
  void composeJacobians(const SE3& b, Mat6<S>* J_out_self, Mat6<S>* J_out_b) const;
  void actJacobians(const Vec3<S>& p, Eigen::Matrix<S, 3, 6>* J_out_self, Mat3<S>* J_out_p) const;

  SO3<S> r_;
  Vec3<S> t_;
};

/// A motion given in a moving frame, expressed in the fixed frame: X = F·X'·F⁻¹ where F is the
/// frame (its rotation and origin in fixed coordinates). Passive change of coordinates of a
/// point is F.inverse().act(p). GF §2.5.3, GF-2.5.3-active-passive
template <class S> SE3<S> changeOfFrame(const SE3<S>& frame, const SE3<S>& motionInFrame) {
  return frame.compose(motionInFrame).compose(frame.inverse());
}

// ---------------------------------------------------------------------------------------------
// Implementation

namespace detail {
/// Q-block of the SE(3) left Jacobian (Barfoot's Q(ρ, φ) with ρ = v, φ = ω):
/// Q = ½V + C(ΩV + VΩ + ΩVΩ) + D(Ω²V + VΩ² − 3ΩVΩ) + E(ΩVΩ² + Ω²VΩ),
/// C = (θ − sin θ)/θ³, D = (θ² + 2cos θ − 2)/(2θ⁴), E = (2θ − 3 sin θ + θ cos θ)/(2θ⁵).
/// Numerators are rewritten without cancellation (θ − sin θ by detail::thetaMinusSin,
/// 2 − 2cos θ = 4 sin²(θ/2)); Taylor branch below precision(5) (remainder θ⁶ < eps).
template <class S> Mat3<S> se3QBlock(const Vec3<S>& w, const Vec3<S>& v) {
  using std::sin;
  using std::sqrt;
  const S theta2 = w.squaredNorm();
  S C, D, E;
  if (theta2 < taylorSwitch2<S>(5)) {
    C = S(1) / S(6) - theta2 / S(120) + theta2 * theta2 / S(5040);
    D = S(1) / S(24) - theta2 / S(720) + theta2 * theta2 / S(40320);
    E = S(1) / S(120) - theta2 / S(2520) + theta2 * theta2 / S(120960);
  } else {
    const S theta = sqrt(theta2);
    const S tms = thetaMinusSin(theta);
    const S sh = sin(theta / S(2));
    const S oneMinusCos = S(2) * sh * sh;
    C = tms / (theta2 * theta);
    D = (theta2 / S(2) - oneMinusCos) / (theta2 * theta2);  // (θ² + 2cos θ − 2)/(2θ⁴)
    // 2θ − 3 sin θ + θ cos θ = 3(θ − sin θ) − θ(1 − cos θ)
    E = (S(3) * tms - theta * oneMinusCos) / (S(2) * theta2 * theta2 * theta);
  }
  const Mat3<S> W = skew(w), V = skew(v);
  const Mat3<S> WV = W * V, VW = V * W, WVW = WV * W;
  return V / S(2) + C * (WV + VW + WVW) + D * (W * WV + VW * W - S(3) * WVW) +
         E * (WVW * W + W * WVW);
}
}  // namespace detail

template <class S> Mat4<S> SE3Tangent<S>::hat() const {
  Mat4<S> m = Mat4<S>::Zero();
  m.template topLeftCorner<3, 3>() = skew(ang());
  m.template topRightCorner<3, 1>() = lin();
  return m;
}

// exp, log, compose, act, inverse are inline and matrix-free (see so3.hpp): the rotation stays a
// quaternion, V(ω)v and V(ω)⁻¹t are written with two cross products each, and exp reuses the
// sin/cos of θ/2 it needs for the quaternion for the coefficients of V.
template <class S> inline SE3<S> SE3Tangent<S>::exp(Mat6<S>* J_out) const {
  if (!allFinite(s_))
    throw InvalidInput("se(3) exp: twist (ω, v) has a NaN or infinite component");
  const Vec3<S> w = ang(), v = lin();
  const S theta2 = w.squaredNorm();
  const auto h = detail::so3HalfAngle(theta2);
  // t = Jl(ω) v = v + B ω×v + C ω×(ω×v), B = (1−cos θ)/θ² = 2 sin²(θ/2)/θ², C = (θ−sin θ)/θ³
  // (Horner series for θ ≤ 1, sin θ = 2 sin(θ/2) cos(θ/2) above).
  S B, C;
  if (theta2 < detail::taylorSwitch2<S>(3)) {
    B = S(1) / S(2) - theta2 / S(24);
    C = S(1) / S(6) - theta2 / S(120);
  } else {
    B = S(2) * h.sh * h.sh / theta2;
    C = theta2 <= S(1) ? detail::thetaMinusSinOverCube(theta2)
                       : (h.theta - S(2) * h.sh * h.w) / (theta2 * h.theta);
  }
  const Vec3<S> wv = w.cross(v);
  const Vec3<S> t = v + B * wv + C * w.cross(wv);
  if (J_out) *J_out = rjac();
  return SE3<S>(SO3<S>::fromUnitQuaternion(Quat<S>(h.w, h.k * w.x(), h.k * w.y(), h.k * w.z())),
                t, typename SE3<S>::Unchecked{});
}

template <class S> Mat6<S> SE3Tangent<S>::ljac() const {
  const Mat3<S> J = SO3Tangent<S>(ang()).ljac();
  Mat6<S> m;
  m << J, Mat3<S>::Zero(), detail::se3QBlock<S>(ang(), lin()), J;
  return m;
}
template <class S> Mat6<S> SE3Tangent<S>::rjac() const { return (-*this).ljac(); }
template <class S> Mat6<S> SE3Tangent<S>::ljacinv() const {
  const Mat3<S> Ji = SO3Tangent<S>(ang()).ljacinv();
  Mat6<S> m;
  m << Ji, Mat3<S>::Zero(), -Ji * detail::se3QBlock<S>(ang(), lin()) * Ji, Ji;
  return m;
}
template <class S> Mat6<S> SE3Tangent<S>::rjacinv() const { return (-*this).ljacinv(); }
template <class S> Mat6<S> SE3Tangent<S>::ad() const {
  const Mat3<S> W = skew(ang());
  Mat6<S> m;
  m << W, Mat3<S>::Zero(), skew(lin()), W;
  return m;
}

template <class S> SE3<S> SE3<S>::fromMatrix(const Mat4<S>& m) {
  using std::abs;
  if (!allFinite(m)) throw InvalidInput("SE3::fromMatrix: matrix has a NaN or infinite entry");
  const S tol = Tolerance<S>::input();
  if (abs(m(3, 0)) > tol || abs(m(3, 1)) > tol || abs(m(3, 2)) > tol || abs(m(3, 3) - S(1)) > tol)
    throw InvalidInput("SE3::fromMatrix: last row is not (0, 0, 0, 1)");
  try {
    return SE3(SO3<S>::fromMatrix(m.template topLeftCorner<3, 3>()),
               m.template topRightCorner<3, 1>());
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string("SE3::fromMatrix: rotation block: ") + e.what());
  }
}

template <class S> SE3<S> SE3<S>::Random(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-1, 1);
  const SO3<S> r = SO3<S>::Random(g);
  const Vec3<S> t(scalarCast<S>(u(g)), scalarCast<S>(u(g)), scalarCast<S>(u(g)));
  return SE3(r, t);
}

template <class S> Mat4<S> SE3<S>::matrix() const {
  Mat4<S> m = Mat4<S>::Identity();
  m.template topLeftCorner<3, 3>() = r_.matrix();
  m.template topRightCorner<3, 1>() = t_;
  return m;
}

template <class S> SOMA_ALWAYS_INLINE SE3<S> SE3<S>::inverse(Mat6<S>* J_out) const {
  if (J_out) *J_out = -adjoint();
  const SO3<S> ri = r_.inverse();
  return SE3(ri, -ri.act(t_), Unchecked{});
}

template <class S>
void SE3<S>::composeJacobians(const SE3& b, Mat6<S>* J_out_self, Mat6<S>* J_out_b) const {
  if (J_out_self) *J_out_self = b.inverse().adjoint();
  if (J_out_b) *J_out_b = Mat6<S>::Identity();
}
template <class S>
SOMA_ALWAYS_INLINE SE3<S> SE3<S>::compose(const SE3& b, Mat6<S>* J_out_self, Mat6<S>* J_out_b) const {
  if (J_out_self || J_out_b) composeJacobians(b, J_out_self, J_out_b);
  return SE3(r_.compose(b.r_), r_.act(b.t_) + t_, Unchecked{});
}

template <class S>
void SE3<S>::actJacobians(const Vec3<S>& p, Eigen::Matrix<S, 3, 6>* J_out_self,
                          Mat3<S>* J_out_p) const {
  const Mat3<S> r = r_.matrix();
  if (J_out_self) {
    J_out_self->template leftCols<3>() = -r * skew(p);
    J_out_self->template rightCols<3>() = r;
  }
  if (J_out_p) *J_out_p = r;
}
template <class S>
SOMA_ALWAYS_INLINE Vec3<S> SE3<S>::act(const Vec3<S>& p, Eigen::Matrix<S, 3, 6>* J_out_self,
                           Mat3<S>* J_out_p) const {
  if (J_out_self || J_out_p) actJacobians(p, J_out_self, J_out_p);
  return r_.act(p) + t_;
}

template <class S> Mat6<S> SE3<S>::adjoint() const {
  const Mat3<S> r = r_.matrix();
  Mat6<S> m;
  m << r, Mat3<S>::Zero(), skew(t_) * r, r;
  return m;
}

template <class S> inline SE3Tangent<S> SE3<S>::log(Mat6<S>* J_out) const {
  using std::atan2;
  using std::sqrt;
  // ω as in SO3::log (θ = 2 atan2(|v|, w), w ≥ 0); then v = Jl(ω)⁻¹ t = t − ½ ω×t + D ω×(ω×t)
  // with D = 1/θ² − cot(θ/2)/(2θ), where cot(θ/2) = w/|v| is read off the quaternion (no trig).
  const Quat<S>& q = r_.quaternion();
  const S sign = q.w() < S(0) ? S(-1) : S(1);
  const S qw = sign * q.w();
  const Vec3<S> qv = sign * q.vec();
  const S n2 = qv.squaredNorm();
  S k, D;  // k = θ/|v|
  if (n2 < detail::taylorSwitch2<S>(3)) {
    // k as in SO3::log; D = 1/12 + θ²/720 (remainder θ⁴/30240 with θ² < 4·precision(3)²)
    k = S(2) / qw * (S(1) - n2 / (S(3) * qw * qw));
    D = S(1) / S(12) + k * k * n2 / S(720);
  } else {
    const S n = sqrt(n2);
    const S theta = S(2) * atan2(n, qw);
    k = theta / n;
    D = S(1) / (theta * theta) - qw / (S(2) * theta * n);
  }
  const Vec3<S> w = k * qv;
  const Vec3<S> wt = w.cross(t_);
  const Tangent s(w, t_ - wt / S(2) + D * w.cross(wt));
  if (J_out) *J_out = s.rjacinv();
  return s;
}

using SE3f = SE3<float>;
using SE3d = SE3<double>;
using SE3ld = SE3<long double>;
using SE3q = SE3<__float128>;
using SE3mp = SE3<mpreal>;

#define SOMA_SE3_EXTERN(S)             \
  extern template class SE3Tangent<S>; \
  extern template class SE3<S>;
SOMA_FOR_EACH_SCALAR(SOMA_SE3_EXTERN)
#undef SOMA_SE3_EXTERN

}  // namespace soma
