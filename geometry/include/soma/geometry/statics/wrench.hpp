#pragma once
// Co-screws and wrenches (GF §12.1–12.2). A co-screw is a linear functional on se(3); a wrench
// 𝒲 = (M, F) — moment about the origin first, then force — pairs with a twist s = (ω, v) to give
// the power 𝒲(s) = M·ω + F·v. Wrench and SE3Tangent are different types with no conversion: a
// twist moves by the adjoint [[R, 0], [T R, R]], a wrench by the coadjoint [[R, T R], [0, R]]
// = Ad(g)⁻ᵀ, which keeps the pairing invariant.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/so3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <string>

namespace soma {

/// Pitch and axis of a wrench (GF §12.2, GF-12.2-wrench-pitch-axis).
template <class S> struct WrenchAxis {
  bool pureTorque = false;          ///< F = 0 (to Tolerance::rank): pitch infinite by convention
  S pitch = S(0);                   ///< p = τ·F / F·F (finite wrenches)
  Vec3<S> point = Vec3<S>::Zero();  ///< r₀ = F × τ / |F|², the point of the axis nearest the origin
  Vec3<S> direction = Vec3<S>::Zero();  ///< F/|F|, or τ/|τ| for a pure torque
};

template <class S> class Wrench {
 public:
  Wrench() : w_(Vec6<S>::Zero()) {}
  explicit Wrench(const Vec6<S>& coeffs) : w_(coeffs) {}
  Wrench(const Vec3<S>& moment, const Vec3<S>& force) {
    w_.template head<3>() = moment;
    w_.template tail<3>() = force;
  }
  static Wrench Zero() { return Wrench(); }
  /// A force F acting along the line through r: 𝒲 = (r × F, F). GF §12.2, GF-12.2-wrench-of-a-force
  static Wrench ofForce(const Vec3<S>& point, const Vec3<S>& force) {
    return Wrench(Vec3<S>(point.cross(force)), force);
  }
  /// A pure torque (couple) τ: 𝒲 = (τ, 0). GF §12.2, GF-12.2-couple-pure-torque
  static Wrench couple(const Vec3<S>& torque) { return Wrench(torque, Vec3<S>::Zero()); }
  /// A pitch-p wrench on the line through r along F: 𝒲 = (r × F + p F, F). GF §12.2,
  /// GF-12.2-wrench-pitch-axis
  static Wrench ofPitch(const Vec3<S>& point, const Vec3<S>& force, const S& pitch) {
    return Wrench(Vec3<S>(point.cross(force) + pitch * force), force);
  }

  Vec3<S> moment() const { return w_.template head<3>(); }
  Vec3<S> force() const { return w_.template tail<3>(); }
  const Vec6<S>& coeffs() const { return w_; }

  /// The evaluation map 𝒲(s) = Mᵀω + pᵀv (the power). GF §12.1, GF-12.1-coscrew-pairing
  S operator()(const SE3Tangent<S>& s) const { return w_.dot(s.coeffs()); }
  /// The wrench after the rigid motion g: 𝒲' = [[R, T R], [0, R]] 𝒲 (coadjoint representation).
  /// GF §12.1, GF-12.1-coadjoint-representation
  Wrench transformed(const SE3<S>& g) const {
    const Mat3<S> R = g.rotation();
    const Vec3<S> Rf = R * force();
    return Wrench(Vec3<S>(R * moment() + g.translation().cross(Rf)), Rf);
  }
  /// Pitch and axis; InvalidInput for the zero wrench (no axis). GF §12.2, GF-12.2-wrench-pitch-axis
  WrenchAxis<S> axis() const;

  Wrench operator+(const Wrench& o) const { return Wrench(Vec6<S>(w_ + o.w_)); }
  Wrench operator-(const Wrench& o) const { return Wrench(Vec6<S>(w_ - o.w_)); }
  Wrench operator-() const { return Wrench(Vec6<S>(-w_)); }
  Wrench operator*(const S& k) const { return Wrench(Vec6<S>(w_ * k)); }
  Wrench& operator+=(const Wrench& o) {
    w_ += o.w_;
    return *this;
  }
  template <class T> Wrench<T> cast() const { return Wrench<T>(castMatrix<T>(w_)); }

 private:
  Vec6<S> w_;
};

/// The coadjoint matrix [[R, T R], [0, R]] (T = ad(t)) of g = (R, t): it equals Ad(g)⁻ᵀ.
/// GF §12.1, GF-12.1-coadjoint-representation
template <class S> Mat6<S> coadjointMatrix(const SE3<S>& g) {
  const Mat3<S> R = g.rotation();
  Mat6<S> m = Mat6<S>::Zero();
  m.template topLeftCorner<3, 3>() = R;
  m.template topRightCorner<3, 3>() = skew(g.translation()) * R;
  m.template bottomRightCorner<3, 3>() = R;
  return m;
}

template <class S> WrenchAxis<S> Wrench<S>::axis() const {
  using std::sqrt;
  if (!allFinite(w_)) throw InvalidInput("Wrench::axis: the wrench has a NaN or infinite entry");
  const Vec3<S> tau = moment(), F = force();
  const S ff = F.squaredNorm(), tt = tau.squaredNorm();
  if (!(ff > S(0)) && !(tt > S(0)))
    throw InvalidInput("Wrench::axis: the zero wrench has no axis");
  WrenchAxis<S> a;
  // F counts as zero when the axis would lie further than 1/Tolerance::rank() (in the units of
  // the moment arm) from the origin or the pitch would exceed that: |F|² ≤ rank² |τ|².
  const S rk = Tolerance<S>::rank();
  if (ff <= rk * rk * tt) {
    a.pureTorque = true;
    a.direction = tau / sqrt(tt);
    return a;
  }
  a.pitch = tau.dot(F) / ff;
  a.point = F.cross(tau) / ff;
  a.direction = F / sqrt(ff);
  return a;
}

#define SOMA_STATICS_WRENCH_EXTERN(S) extern template class Wrench<S>;
SOMA_FOR_EACH_SCALAR(SOMA_STATICS_WRENCH_EXTERN)
#undef SOMA_STATICS_WRENCH_EXTERN

}  // namespace soma
