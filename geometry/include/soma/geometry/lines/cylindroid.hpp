#pragma once
// The cylindroid (Plücker's conoid, GF §6.5.2): the axes of the screws of a 2-system (pencil)
// s(μ, λ) = μ s₁ + λ s₂. Canonical frame: the principal screws (extreme pitches h₁ ≥ h₂) have
// perpendicular axes meeting at the centre c along x, y; z = x × y is the nodal line. The screw
// at angle θ from x has direction (cos θ, sin θ, 0), pitch h(θ) = h₁cos²θ + h₂sin²θ and its axis
// meets the z-axis at z(θ) = ½(h₂ − h₁) sin 2θ; the surface is z(x² + y²) = (h₂ − h₁)xy.
// Pencils containing an infinite-pitch screw (ω₁ ∥ ω₂) are not cylindroids (screw systems, ch. 8).
#include "soma/geometry/lines/screw_axis.hpp"

namespace soma {

template <class S> class Cylindroid {
 public:
  /// From two screws spanning the pencil. Throws for a NaN, dependent screws, or a pencil whose
  /// directions are parallel (|ω₁ × ω₂| ≤ √ε|ω₁||ω₂| after reduction: it contains a screw of
  /// infinite pitch to working precision).
  // GF §6.5.2, GF-6.5.2-cylindroid-two-lines
  Cylindroid(const Vec6<S>& s1, const Vec6<S>& s2);

  /// The principal pitches h₁ ≥ h₂. GF §6.5.2, GF-6.5.2-cylindroid-principal-form
  S pitchMax() const { return h1_; }
  S pitchMin() const { return h2_; }
  /// Principal screws (unit ω, pitch h₁ resp. h₂); their axes meet at right angles at centre().
  Vec6<S> principal(int i) const { return screw(i == 1 ? S(0) : pi<S>() / S(2)); }
  const Vec3<S>& centre() const { return c_; }
  /// Canonical frame: rotation columns x (principal h₁), y (principal h₂), z = nodal line.
  const Mat3<S>& frame() const { return r_; }
  SE3<S> pose() const { return SE3<S>(SO3<S>::fromMatrix(r_), c_); }

  /// The unit-ω screw at angle θ from the first principal screw. GF §6.5.2
  Vec6<S> screw(const S& theta) const;
  /// Pitch distribution h(θ) = h₁cos²θ + h₂sin²θ. GF §6.5.2, GF-6.5.2-cylindroid-principal-form
  S pitch(const S& theta) const {
    using std::cos;
    using std::sin;
    const S c = cos(theta), s = sin(theta);
    return h1_ * c * c + h2_ * s * s;
  }
  /// Height of the axis at θ on the nodal line (from the centre): ½(h₂ − h₁) sin 2θ.
  S height(const S& theta) const {
    using std::sin;
    return (h2_ - h1_) * sin(S(2) * theta) / S(2);
  }
  /// The axis of screw(θ) as a unit line.
  PluckerLine<S> axis(const S& theta) const { return screwAxis(screw(theta)).axis; }
  /// The cubic z(x² + y²) − (h₂ − h₁)xy at a world point (zero on the surface).
  S implicit(const Vec3<S>& x) const {
    const Vec3<S> y = r_.transpose() * (x - c_);
    return y(2) * (y(0) * y(0) + y(1) * y(1)) - (h2_ - h1_) * y(0) * y(1);
  }
  /// Angle θ ∈ (−π/2, π/2] of a screw of the pencil (its ω direction in the frame).
  S angleOf(const Vec6<S>& s) const {
    using std::atan2;
    const Vec3<S> w = r_.transpose() * s.template head<3>();
    S t = atan2(w(1), w(0));
    if (t > pi<S>() / S(2)) t -= pi<S>();
    if (t <= -pi<S>() / S(2)) t += pi<S>();
    return t;
  }

 private:
  S h1_{0}, h2_{0};
  Vec3<S> c_{Vec3<S>::Zero()};
  Mat3<S> r_{Mat3<S>::Identity()};
};

template <class S> Cylindroid<S>::Cylindroid(const Vec6<S>& s1, const Vec6<S>& s2) {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (!allFinite(s1) || !allFinite(s2)) throw InvalidInput("Cylindroid: a screw has a NaN or infinite coordinate");
  const Vec3<S> w1 = s1.template head<3>(), w2 = s2.template head<3>();
  const S g11 = w1.squaredNorm(), g22 = w2.squaredNorm(), g12 = w1.dot(w2);
  const S det = g11 * g22 - g12 * g12;  // |ω₁ × ω₂|²
  if (!(det > Tolerance<S>::epsilon() * g11 * g22))
    throw InvalidInput("Cylindroid: the screws' directions are parallel (the pencil contains an "
                       "infinite-pitch screw: not a cylindroid)");
  // Gram–Schmidt on ω: e_a = s₁/|ω₁|, e_b = (s₂ − (g12/g11)s₁)/|…| have orthonormal ω parts.
  const Vec6<S> ea = s1 / sqrt(g11);
  Vec6<S> eb = s2 - (g12 / g11) * s1;
  eb /= sqrt(eb.template head<3>().squaredNorm());
  // Pitch form on the orthonormal-ω basis: A = [ω_i·v_j] symmetrised.
  const S a11 = kleinValue(ea), a22 = kleinValue(eb), a12 = reciprocalProduct(ea, eb) / S(2);
  // Rotate by φ to diagonalise: tan 2φ = 2a12/(a11 − a22) (atan2: no branch at a11 = a22).
  const S phi = atan2(S(2) * a12, a11 - a22) / S(2);
  const S c = cos(phi), s = sin(phi);
  const Vec6<S> p1 = c * ea + s * eb, p2 = -s * ea + c * eb;
  h1_ = kleinValue(p1);
  h2_ = kleinValue(p2);
  // Centre: the two principal axes meet (at right angles); take the midpoint of their common
  // perpendicular (they are exactly perpendicular, never parallel).
  const PluckerLine<S> ax1 = screwAxis(p1).axis, ax2 = screwAxis(p2).axis;
  const LineRelation<S> rel = relation(ax1, ax2);
  c_ = (rel.footA + rel.footB) / S(2);
  const Vec3<S> x = ax1.direction(), y = ax2.direction();
  r_.col(0) = x;
  r_.col(1) = y - y.dot(x) * x;
  r_.col(1).normalize();
  r_.col(2) = x.cross(Vec3<S>(r_.col(1)));
}

template <class S> Vec6<S> Cylindroid<S>::screw(const S& theta) const {
  using std::cos;
  using std::sin;
  const S c = cos(theta), s = sin(theta);
  const Vec3<S> w = c * r_.col(0) + s * r_.col(1);
  const Vec3<S> q = c_ + height(theta) * r_.col(2);
  Vec6<S> out;
  out << w, Vec3<S>(q.cross(w) + pitch(theta) * w);
  return out;
}

extern template class Cylindroid<float>;
extern template class Cylindroid<double>;
extern template class Cylindroid<long double>;
extern template class Cylindroid<__float128>;
extern template class Cylindroid<mpfr::mpreal>;

}  // namespace soma
