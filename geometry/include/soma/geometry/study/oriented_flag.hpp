#pragma once
// Study's somas as oriented (1,2,3) flags in R⁴ (GF §11.1): the stereographic projection onto
// w = 1 from (0,0,0,−1), the frame of a flag, and the flag's SO(4) matrix.
// Header-only and light (fixed 3- and 4-vectors), so every scalar instantiates it on use.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"

namespace soma {

/// pr(x, y, z, w) = (2x, 2y, 2z)/(1 + w) (the point (…, 1) of the 3-plane w = 1, returned as its
/// first three coordinates). Undefined at w = −1: InvalidInput.
// GF §11.1, GF-11.1-stereographic-projection
template <class S> Vec3<S> stereographicProjection(const Vec4<S>& p) {
  if (!allFinite(p)) throw InvalidInput("stereographicProjection: the point has a NaN or infinite coordinate");
  const S den = S(1) + p(3);
  if (den == S(0)) throw InvalidInput("stereographicProjection: w = −1 is the centre of projection (no image)");
  return Vec3<S>(S(2) * p.template head<3>() / den);
}

/// The inverse on the unit 3-sphere: u ↦ (4u, 4 − |u|²)/(4 + |u|²) (pr of it is u; never w = −1).
template <class S> Vec4<S> inverseStereographicProjection(const Vec3<S>& u) {
  if (!allFinite(u)) throw InvalidInput("inverseStereographicProjection: the point has a NaN or infinite coordinate");
  const S n = u.squaredNorm();
  Vec4<S> p;
  p << S(4) * u / (S(4) + n), (S(4) - n) / (S(4) + n);
  return p;
}

/// e4 = e1 ∧ e2 ∧ e3 as a vector: (e4)_l = ε_{ijkl} e1_i e2_j e3_k, so det[e1 e2 e3 e4] = |e4|².
// GF §11.1, GF-11.1-flag-SO4-matrix
template <class S> Vec4<S> generalizedCrossProduct(const Vec4<S>& a, const Vec4<S>& b, const Vec4<S>& c) {
  Vec4<S> e;
  for (int l = 0; l < 4; ++l) {
    Mat3<S> minor;
    for (int r = 0, rr = 0; r < 4; ++r) {
      if (r == l) continue;
      minor.row(rr++) = Vec3<S>(a(r), b(r), c(r));
    }
    e(l) = ((l % 2 == 1) ? S(1) : S(-1)) * minor.determinant();  // cofactor of (l, 4) in [a b c ·]
  }
  return e;
}

/// An oriented (1,2,3) flag of R⁴, given by orthonormal e1, e2, e3 (line, 2-plane, 3-plane).
template <class S> class OrientedFlag {
 public:
  /// Throws InvalidInput unless e1, e2, e3 are orthonormal to Tolerance::input.
  OrientedFlag(const Vec4<S>& e1, const Vec4<S>& e2, const Vec4<S>& e3) : e_{e1, e2, e3} {
    for (int i = 0; i < 3; ++i) {
      if (!allFinite(e_[i])) throw InvalidInput("OrientedFlag: e" + std::to_string(i + 1) + " has a NaN or infinite entry");
      for (int j = i; j < 3; ++j) {
        const S d = e_[i].dot(e_[j]) - (i == j ? S(1) : S(0));
        using std::abs;
        if (abs(d) > Tolerance<S>::input())
          throw InvalidInput("OrientedFlag: e1, e2, e3 are not orthonormal (e" + std::to_string(i + 1) + "·e" +
                             std::to_string(j + 1) + " off by " + toString(d, 3) + ")");
      }
    }
  }
  /// The flag of the columns 1–3 of an SO(4) matrix (F⁺(1,2,3;4) ≅ SO(4)).
  static OrientedFlag fromSO4(const Mat4<S>& M) { return OrientedFlag(M.col(0), M.col(1), M.col(2)); }

  const Vec4<S>& e(int i) const { return e_[i - 1]; }
  /// [e1 e2 e3 e4] with e4 = e1 ∧ e2 ∧ e3: the SO(4) matrix of the flag (det = +1).
  // GF §11.1, GF-11.1-flag-SO4-matrix
  Mat4<S> so4() const {
    Mat4<S> m;
    m << e_[0], e_[1], e_[2], generalizedCrossProduct<S>(e_[0], e_[1], e_[2]);
    return m;
  }

  /// 1 + w at or below which a unit vector counts as the centre of projection −w: 16 ulps, the
  /// rounding error of a w computed from unit-scale data (its image would lie beyond 1/(16 eps)).
  static S poleThreshold() { return Tolerance<S>::identity(16); }
  /// True when the flag gives a soma: e1 is not −w (the centre of projection).
  bool isSoma() const { return S(1) + e_[0](3) > poleThreshold(); }

  /// The soma (a right-handed frame in R³) of the flag: origin pr(e1); x-axis from the origin
  /// towards pr(e2); z-axis along (pr(e2) − pr(e1)) × (pr(e3) − pr(e1)); y = z × x. Differences
  /// are taken as (1 + w_k)(pr(e_k) − pr(e1)) = 2x_k − (1 + w_k) pr(e1), positive multiples, so
  /// e2 or e3 near −w costs no accuracy. When e_k is −w (1 + w_k ≤ poleThreshold) its projection
  /// is at infinity and, as the book says, the linear space is projected instead: the great
  /// circle through e1 and e_k then projects to a line, and pr((e1 + e_k)/√2) lies on its ray
  /// towards pr(e_k). This rule is not the limit of the general one (the chord towards a far
  /// pr(e_k) turns with the direction of approach): the map is discontinuous at such flags.
  /// Throws InvalidInput when e1 = −w (no soma).
  // GF §11.1, GF-11.1-flag-to-soma
  SE3<S> soma() const {
    using std::sqrt;
    if (!isSoma()) throw InvalidInput("OrientedFlag::soma: e1 = (0, 0, 0, −1) is the centre of projection: this flag is not a soma");
    const Vec3<S> o = stereographicProjection<S>(e_[0]);
    auto towards = [&](const Vec4<S>& ek) {
      Vec4<S> p = ek;
      if (!(S(1) + ek(3) > poleThreshold())) p = (e_[0] + ek) / sqrt(S(2));
      return Vec3<S>(S(2) * p.template head<3>() - (S(1) + p(3)) * o);
    };
    const Vec3<S> d2 = towards(e_[1]), d3 = towards(e_[2]);
    const Vec3<S> x = d2.normalized();
    const Vec3<S> z = d2.cross(d3).normalized();
    Mat3<S> R;
    R << x, z.cross(x), z;
    return SE3<S>(SO3<S>::fromMatrix(R), o);
  }

 private:
  Vec4<S> e_[3];
};

}  // namespace soma
