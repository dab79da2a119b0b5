#pragma once
// Inverse Jacobians by reciprocal screws (GF §6.7): if a line z_i is reciprocal to every joint
// screw but s_i (z_iᵀQ₀s_j = 0, j ≠ i), then W_i = Q₀z_i/(z_iᵀQ₀s_i) is row i of J⁻¹. For the
// PUMA-like arm of Fig. 6.5 (axes 1, 2 through the origin o, 3 ∥ 2 through the elbow x_e, 4, 5, 6
// through the wrist centre x_c) the book gives the six z_i in closed form.
#include "soma/geometry/lines/line.hpp"

#include <array>

namespace soma {

/// Joint screws of the PUMA-like arm: s₁ = (ω₁; 0), s₂ = (ω₂; 0), s₃ = (ω₂; x_e × ω₂),
/// s₄,₅,₆ = (ω_i; x_c × ω_i) (convention A). GF §6.7, GF-6.7-inverse-jacobian-6R
template <class S> struct PumaLikeArm {
  Vec3<S> w1, w2, w4, w5, w6, xe, xc;
  Mat6<S> jacobian() const;  ///< columns s₁ … s₆
};

/// The reciprocal lines z₁ … z₆ of the book (z₄ from α, β solving z₄ᵀQ₀s₅ = z₄ᵀQ₀s₆ = 0).
// GF §6.7, GF-6.7-inverse-jacobian-6R
template <class S> std::array<Vec6<S>, 6> pumaLikeReciprocalLines(const PumaLikeArm<S>& arm);

/// J⁻¹ with rows W_i = Q₀z_i/(z_iᵀQ₀s_i); throws near a singularity, when some
/// |z_iᵀQ₀s_i| ≤ Tolerance::rank()·|z_i||s_i|. GF §6.7, GF-6.7-inverse-jacobian-6R
template <class S> Mat6<S> inverseJacobianFromReciprocals(const Mat6<S>& j, const std::array<Vec6<S>, 6>& z);

template <class S> Mat6<S> PumaLikeArm<S>::jacobian() const {
  Mat6<S> j;
  auto col = [](const Vec3<S>& w, const Vec3<S>& q) {
    Vec6<S> s;
    s << w, Vec3<S>(q.cross(w));
    return s;
  };
  j.col(0) = col(w1, Vec3<S>::Zero());
  j.col(1) = col(w2, Vec3<S>::Zero());
  j.col(2) = col(w2, xe);
  j.col(3) = col(w4, xc);
  j.col(4) = col(w5, xc);
  j.col(5) = col(w6, xc);
  return j;
}

template <class S> std::array<Vec6<S>, 6> pumaLikeReciprocalLines(const PumaLikeArm<S>& a) {
  const Mat6<S> j = a.jacobian();
  auto six = [](const Vec3<S>& w, const Vec3<S>& v) {
    Vec6<S> s;
    s << w, v;
    return s;
  };
  std::array<Vec6<S>, 6> z;
  z[0] = six(a.w2, a.xc.cross(a.w2));
  z[1] = j.col(3);
  z[2] = six(a.xc, Vec3<S>::Zero());
  const Vec6<S> za = six(a.xe, Vec3<S>::Zero());
  const Vec3<S> w12 = a.w1.cross(a.w2);
  const Vec6<S> zb = six(Vec3<S>(a.w2 * a.w1.dot(a.w2.cross(a.w4))), Vec3<S>(w12 * a.xe.dot(a.w2.cross(a.w4))));
  const Vec6<S> zg = six(Vec3<S>::Zero(), w12);
  const Vec6<S> s5 = j.col(4), s6 = j.col(5);
  // z₄ = α z_α + β z_β + z_γ with ⟨z₄, s₅⟩ = ⟨z₄, s₆⟩ = 0 (2×2 linear system, Cramer).
  const S a11 = reciprocalProduct(za, s5), a12 = reciprocalProduct(zb, s5), r1 = -reciprocalProduct(zg, s5);
  const S a21 = reciprocalProduct(za, s6), a22 = reciprocalProduct(zb, s6), r2 = -reciprocalProduct(zg, s6);
  const S det = a11 * a22 - a12 * a21;
  if (det == S(0)) throw InvalidInput("pumaLikeReciprocalLines: z₄ system singular (wrist singularity)");
  const S al = (r1 * a22 - a12 * r2) / det, be = (a11 * r2 - r1 * a21) / det;
  z[3] = al * za + be * zb + zg;
  z[4] = za * reciprocalProduct(zb, s6) - zb * reciprocalProduct(za, s6);
  z[5] = za * reciprocalProduct(zb, s5) - zb * reciprocalProduct(za, s5);
  return z;
}

template <class S> Mat6<S> inverseJacobianFromReciprocals(const Mat6<S>& j, const std::array<Vec6<S>, 6>& z) {
  using std::abs;
  using std::sqrt;
  const Mat6<S> q0 = [] {
    Mat6<S> q = Mat6<S>::Zero();
    q.template topRightCorner<3, 3>().setIdentity();
    q.template bottomLeftCorner<3, 3>().setIdentity();
    return q;
  }();
  Mat6<S> w;
  for (int i = 0; i < 6; ++i) {
    const S d = reciprocalProduct(z[i], Vec6<S>(j.col(i)));
    if (abs(d) <= Tolerance<S>::rank() * sqrt(z[i].squaredNorm() * j.col(i).squaredNorm()))
      throw InvalidInput("inverseJacobianFromReciprocals: z_" + std::to_string(i + 1) +
                         "ᵀQ₀s_" + std::to_string(i + 1) + " ≈ 0 (singular configuration)");
    w.row(i) = (q0 * z[i]).transpose() / d;
  }
  return w;
}

#define SOMA_INVJ_EXTERN(S)                                                                         \
  extern template struct PumaLikeArm<S>;                                                           \
  extern template std::array<Vec6<S>, 6> pumaLikeReciprocalLines<S>(const PumaLikeArm<S>&);        \
  extern template Mat6<S> inverseJacobianFromReciprocals<S>(const Mat6<S>&, const std::array<Vec6<S>, 6>&);
SOMA_FOR_EACH_SCALAR(SOMA_INVJ_EXTERN)
#undef SOMA_INVJ_EXTERN

}  // namespace soma
