#pragma once
// The principle of transference (GF §7.6): se(3) ≅ so(3) ⊗ 𝔻 = so(3, 𝔻), 𝔻 = ℝ[ε]/ε² (DualNumber,
// dual_quaternion.hpp). A twist (ω; v) is the dual 3-vector ω + εv and the skew dual matrix
// Š = Ω + εV; a motion g = (R, t) is the SO(3, 𝔻) matrix Ř = R + εTR (T = hat(t)); the dual
// cross product is the Lie bracket, the dual dot product ω₁·ω₂ + ε(ω₁·v₂ + v₁·ω₂) the Killing
// form of so(3) with the reciprocal product. Every representation L of so(3) becomes one of se(3)
// when tensored with 𝔻: D(ω_a) = I₂ ⊗ L(X_a), D(v_a) = E ⊗ L(X_a), E = [[0, 0], [1, 0]] (the
// book's partitioned matrices [[L, 0], [0, L]] and [[0, 0], [L, 0]]; it writes L ⊗ I₂, L ⊗ E, the
// same up to a permutation similarity). With L the 3×3 representation D is the adjoint.
#include "soma/algebra/dual_quaternion.hpp"
#include "soma/algebra/rep/se3_representations.hpp"

#include <limits>

namespace soma::rep {

/// The se(3) representation L ⊗ 𝔻 from the three generators L(X), L(Y), L(Z) of so(3).
// GF §7.6, GF-7.6-transference
template <class T> Se3Generators<T> transference(const std::array<Matrix<T>, 3>& so3) {
  Matrix<T> i2 = Matrix<T>::Identity(2, 2), e = Matrix<T>::Zero(2, 2);
  e(1, 0) = T(1);
  Se3Generators<T> g;
  for (std::size_t a = 0; a < 3; ++a) {
    g[a] = groupTensor(i2, so3[a]);
    g[a + 3] = groupTensor(e, so3[a]);
  }
  return g;
}

/// A 3×3 matrix with dual entries, re + ε du (an element of so(3, 𝔻) or SO(3, 𝔻)).
// GF §7.6, GF-7.6-transference
template <class S> struct DualMat3 {
  Mat3<S> re{Mat3<S>::Zero()}, du{Mat3<S>::Zero()};
  DualMat3 operator*(const DualMat3& o) const { return {Mat3<S>(re * o.re), Mat3<S>(re * o.du + du * o.re)}; }
  DualMat3 operator+(const DualMat3& o) const { return {Mat3<S>(re + o.re), Mat3<S>(du + o.du)}; }
  DualMat3 operator-(const DualMat3& o) const { return {Mat3<S>(re - o.re), Mat3<S>(du - o.du)}; }
  DualMat3 transpose() const { return {Mat3<S>(re.transpose()), Mat3<S>(du.transpose())}; }
  DualNumber<S> trace() const { return {re.trace(), du.trace()}; }
};

/// Š = Ω + εV for the twist (ω; v). GF §7.6, GF-7.6-transference
template <class S> DualMat3<S> dualSkew(const SE3Tangent<S>& s) { return {skew(s.ang()), skew(s.lin())}; }

/// Ř = R + εTR for the motion (R, t). GF §7.6, GF-7.6-dual-killing-and-dual-angle
template <class S> DualMat3<S> dualRotation(const SE3<S>& g) {
  const Mat3<S> r = g.rotation();
  return {r, Mat3<S>(skew(g.translation()) * r)};
}

/// The dual Killing form Tr(Š₁Š₂) = Tr(Ω₁Ω₂) + ε Tr(Ω₁V₂ + V₁Ω₂) = −2ω₁·ω₂ − 2ε(ω₁·v₂ + v₁·ω₂):
/// the Killing form of so(3) with the reciprocal product as its dual part.
// GF §7.6, GF-7.6-dual-killing-and-dual-angle
template <class S> DualNumber<S> dualKillingForm(const SE3Tangent<S>& s1, const SE3Tangent<S>& s2) {
  return (dualSkew(s1) * dualSkew(s2)).trace();
}

/// The pitch of a twist as the ratio of its two invariant forms (GF §7.5: "the pitch of a single
/// element is given by the ratio of these two forms"): with Tr(ŠŠ) = k + εr, pitch = r/(2k) =
/// ω·v/ω·ω per radian; +∞ for a pure translation; throws for the zero twist.
// GF §7.5, GF-7.5-casimirs-and-pitch (corrected, erratum E7.6: not Tr(X P_t X)/Tr(X J_t X))
template <class S> S pitchFromInvariantForms(const SE3Tangent<S>& s) {
  const DualNumber<S> k = dualKillingForm(s, s);
  // k.re = −2ω·ω is 0 exactly when ω = 0 (infinite pitch); a tiny ω has a large, finite pitch
  // (as screwPitch in geometry/lines), so this is the definition, not a threshold.
  if (k.re == S(0)) {
    if (s.lin().squaredNorm() == S(0)) throw InvalidInput("pitchFromInvariantForms: the zero twist has no pitch");
    return std::numeric_limits<S>::infinity();
  }
  return k.du / (S(2) * k.re);
}

}  // namespace soma::rep
