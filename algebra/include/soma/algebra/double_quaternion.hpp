#pragma once
// Double quaternions h = h0 + h1 σ, σ central with σ² = s (GF §11.1). s = 1: Cl⁺(0,4,0) =
// H ⊗ Cl(1,0,0), Spin(4) and SO(4); s = 1/r²: the Saletan contraction of SO(4) (the symmetries
// of the 3-sphere of radius r) towards SE(3); s = 0: the dual quaternions of GF §9.3.
// Header-only and light (quaternion arithmetic only), so every scalar instantiates it on use.
#include "soma/algebra/dual_quaternion.hpp"
#include "soma/algebra/errors.hpp"
#include "soma/algebra/quaternion.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

namespace soma {

template <class S> class DoubleQuaternion {
 public:
  /// h0 + h1 σ with σ² = sigma2 (1 for the double quaternions of Spin(4)).
  DoubleQuaternion(const Quat<S>& h0, const Quat<S>& h1, const S& sigma2 = S(1)) : h0_(h0), h1_(h1), s_(sigma2) {}

  /// ½(g1 + g2) + ½(g1 − g2)σ: Spin(4) = Spin(3) × Spin(3) (σ² = 1).
  // GF §11.1, GF-11.1-spin3xspin3
  static DoubleQuaternion fromSpin3Pair(const Quat<S>& g1, const Quat<S>& g2) {
    const S h = S(1) / S(2);
    return DoubleQuaternion(detail::quatScale(detail::quatAdd(g1, g2), h),
                            detail::quatScale(detail::quatSub(g1, g2), h), S(1));
  }

  const Quat<S>& h0() const { return h0_; }
  const Quat<S>& h1() const { return h1_; }
  const S& sigma2() const { return s_; }

  /// (a + cσ)(b + dσ) = (ab + σ² cd) + (ad + cb)σ, σ central. Both factors need the same σ².
  // GF §11.1, GF-11.1-double-quaternions (and GF-11.1-saletan-contraction for σ² ≠ 1)
  DoubleQuaternion operator*(const DoubleQuaternion& o) const {
    if (!(s_ == o.s_)) throw InvalidInput("DoubleQuaternion product: the factors have different σ²");
    const Quat<S> re = detail::quatAdd(quaternionProduct(h0_, o.h0_), detail::quatScale(quaternionProduct(h1_, o.h1_), s_));
    const Quat<S> si = detail::quatAdd(quaternionProduct(h0_, o.h1_), quaternionProduct(h1_, o.h0_));
    return DoubleQuaternion(re, si, s_);
  }

  /// h* = h0* + h1* σ (quaternion conjugation, σ* = σ).
  DoubleQuaternion conjugate() const { return DoubleQuaternion(detail::quatConj(h0_), detail::quatConj(h1_), s_); }
  /// h0* − h1* σ: the right-hand factor of the action on R⁴.
  DoubleQuaternion actionInverse() const {
    return DoubleQuaternion(detail::quatConj(h0_), detail::quatScale(detail::quatConj(h1_), S(-1)), s_);
  }

  /// The two Spin(4) conditions, as reals: h0h0* + σ²h1h1* − 1 and h0h1* + h1h0* (a real
  /// quaternion, = 2 h0·h1 — the book prints it equal to a·c, erratum 6: a factor 2).
  // GF §11.1, GF-11.1-spin4-conditions
  S normDefect() const { return h0_.coeffs().squaredNorm() + s_ * h1_.coeffs().squaredNorm() - S(1); }
  S studyForm() const { return S(2) * h0_.coeffs().dot(h1_.coeffs()); }

  /// x ↦ x' with x' = h x (h0* − h1*σ), x = x0 + (x1 i + x2 j + x3 k)σ. The σ-free vector part
  /// and the scalar σ part of the product must vanish; they are returned in *offForm (the
  /// largest absolute entry) for the caller to check.
  // GF §11.1, GF-11.1-double-quaternions (the action on R⁴)
  Vec4<S> act(const Vec4<S>& x, S* offForm = nullptr) const {
    using std::abs;
    const DoubleQuaternion X(Quat<S>(x(0), S(0), S(0), S(0)), Quat<S>(S(0), x(1), x(2), x(3)), s_);
    const DoubleQuaternion Y = *this * X * actionInverse();
    if (offForm) {
      S m = abs(Y.h1_.w());
      m = std::max<S>(m, std::max<S>(abs(Y.h0_.x()), std::max<S>(abs(Y.h0_.y()), abs(Y.h0_.z()))));
      *offForm = m;
    }
    return Vec4<S>(Y.h0_.w(), Y.h1_.x(), Y.h1_.y(), Y.h1_.z());
  }

  /// The 4 × 4 matrix of act (columns: the images of the unit vectors).
  Mat4<S> matrix() const {
    Mat4<S> m;
    for (int k = 0; k < 4; ++k) m.col(k) = act(Vec4<S>::Unit(k));
    return m;
  }

  /// (h0 : h1) as a point of PR⁷ in Study's order (a0..a3, c0..c3).
  Vec8<S> studyPoint() const {
    Vec8<S> v;
    v << detail::studyOrder(h0_), detail::studyOrder(h1_);
    return v;
  }

  /// The Spin(4) element (up to sign) of a rotation M ∈ SO(4): M q = g1 q g2* on quaternions
  /// q = x0 + x1 i + x2 j + x3 k, so u = M·1 = g1 g2* and q ↦ (M q) u* = g1 q g1* is a rotation
  /// of the pure quaternions, which gives g1 (Shepperd), then g2 = u* g1.
  // GF §11.1, GF-11.1-SO4-is-whole-study-quadric
  static DoubleQuaternion fromSO4(const Mat4<S>& M) {
    if (!allFinite(M)) throw InvalidInput("DoubleQuaternion::fromSO4: the matrix has a NaN or infinite entry");
    const S defect = (M.transpose() * M - Mat4<S>::Identity()).cwiseAbs().maxCoeff();
    if (defect > Tolerance<S>::input())
      throw InvalidInput("DoubleQuaternion::fromSO4: the matrix is not orthogonal (max |MᵀM − I| = " + toString(defect, 3) + ")");
    if (!(M.determinant() > S(0))) throw InvalidInput("DoubleQuaternion::fromSO4: det M = −1 (not a rotation)");
    auto quatOf = [](const Vec4<S>& v) { return Quat<S>(v(0), v(1), v(2), v(3)); };
    const Quat<S> u = quatOf(M.col(0));
    Mat3<S> R;
    for (int k = 0; k < 3; ++k) {
      const Quat<S> img = quaternionProduct(quatOf(M.col(k + 1)), detail::quatConj(u));
      R.col(k) = Vec3<S>(img.x(), img.y(), img.z());
    }
    const Quat<S> g1 = quaternionFromRotation(R);
    const Quat<S> g2 = quaternionProduct(detail::quatConj(u), g1);
    return fromSpin3Pair(g1, g2);
  }

 private:
  Quat<S> h0_, h1_;
  S s_;
};

}  // namespace soma
