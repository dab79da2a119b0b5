#pragma once
// A planar motion as a curve in SE(2) known to fourth order at t = 0 (GF §5.3.1): the body →
// world pose M(t) = (R(φ(t)), d(t)) given by the Taylor series of its angle φ and origin d.
// Every instantaneous invariant of GF §5.3 needs at most the 4th derivative (Burmester points).
#include "soma/algebra/se2.hpp"
#include "soma/geometry/planar/polynomials.hpp"
#include "soma/geometry/planar/taylor_series.hpp"

#include <array>

namespace soma::planar {

inline constexpr int kJetSize = 5;  ///< derivatives 0..4
template <class S> using Series = TaylorSeries<S, kJetSize>;

/// J = [[0, −1], [1, 0]] (rotation by +π/2). The book's E₂ = −J, and aᵀE₂b = det[a b].
template <class S> Vec2<S> perp(const Vec2<S>& v) { return Vec2<S>(-v(1), v(0)); }
/// det[a b] = a_x b_y − a_y b_x = aᵀE₂b.
template <class S> S cross2(const Vec2<S>& a, const Vec2<S>& b) { return a(0) * b(1) - a(1) * b(0); }

/// p^(k) = R_k p + t_k: the k-th derivative at t = 0 of the path of the body point that is at
/// the world point p when t = 0 (affine in p; R_k = a I + b J).
template <class S> struct AffineDerivative {
  S a{0}, b{0};  ///< R_k = a I + b J
  Vec2<S> t = Vec2<S>::Zero();
  Vec2<S> operator()(const Vec2<S>& p) const { return a * p + b * perp(p) + t; }
  /// Component i (0 = x, 1 = y) as an affine polynomial in (x, y).
  Poly2<S> poly(int i) const {
    return i == 0 ? Poly2<S>::affine(t(0), a, -b) : Poly2<S>::affine(t(1), b, a);
  }
};

template <class S> class MotionJet {
 public:
  MotionJet() = default;
  /// From the series of the angle φ(t) and the body origin d(t) = (x(t), y(t)).
  MotionJet(const Series<S>& angle, const Series<S>& x, const Series<S>& y);
  /// From derivatives φ^(k)(0) and d^(k)(0), k = 0..4. Throws InvalidInput on NaN/inf.
  static MotionJet fromDerivatives(const std::array<S, kJetSize>& angle, const std::array<Vec2<S>, kJetSize>& origin);
  /// The motion t ↦ exp(t ξ) g of a constant spatial twist ξ = (ω, v) (a rotation about a fixed
  /// point, or a translation when ω = 0) composed with a time law: t ↦ exp(s(t) ξ) g, s(t) = Σ s_k t^k/k!.
  static MotionJet screw(const SE2<S>& g, const SE2Tangent<S>& xi, const std::array<S, kJetSize>& timeLaw);

  const Series<S>& angle() const { return phi_; }
  const Series<S>& x() const { return x_; }
  const Series<S>& y() const { return y_; }
  /// M(0).
  SE2<S> pose() const;
  /// The jet of the same motion with the time rescaled and shifted: t ↦ M(c t) (c ≠ 0).
  MotionJet timeScaled(const S& c) const;

  /// p^(k)(0) = R_k p + t_k for the body point at world p when t = 0, k = 0..4.
  const std::array<AffineDerivative<S>, kJetSize>& pointMaps() const { return maps_; }
  /// p, ṗ, p̈, p⃛, p⁗ of that point (direct: from the jet, no book formula).
  std::array<Vec2<S>, kJetSize> pointDerivatives(const Vec2<S>& p) const;
  /// The same for a point given in body coordinates.
  std::array<Vec2<S>, kJetSize> bodyPointDerivatives(const Vec2<S>& body) const { return pointDerivatives(pose().act(body)); }

  /// Instantaneous centre as a homogeneous point (X, Y, W) = (ω d + J ḋ, ω): W = 0 is the pole at
  /// infinity of an instantaneous translation (direction J ḋ, normal to the velocity). GF §5.3.1
  Vec3<S> instantCentreHomogeneous() const;

  /// Relative motion A(t) = M(t) M(0)⁻¹ (world frame): θ(t) = φ(t) − φ(0), translation t_A(t).
  const Series<S>& relativeAngle() const { return theta_; }
  const Series<S>& relativeX() const { return tx_; }
  const Series<S>& relativeY() const { return ty_; }

 private:
  void build();
  Series<S> phi_, x_, y_;
  Series<S> theta_, tx_, ty_;
  std::array<AffineDerivative<S>, kJetSize> maps_;
};

/// Curvature centre of a path from ṗ, p̈ (GF §5.3, GF-5.3-curvature-centre: (C1) ṗ·(p−c) = 0,
/// (C2) p̈·(p−c) + ṗ·ṗ = 0). Returns false (c untouched) at an inflection or a stationary point,
/// |det[ṗ, p̈]| ≤ Tolerance::rank()·|ṗ|·|p̈|... (the centre is at infinity).
template <class S> bool curvatureCentre(const Vec2<S>& p, const Vec2<S>& pd, const Vec2<S>& pdd, Vec2<S>& c);
/// Signed curvature κ = det[ṗ, p̈]/|ṗ|³ (throws InvalidInput when ṗ = 0: a cusp of the path).
template <class S> S pathCurvature(const Vec2<S>& pd, const Vec2<S>& pdd);

}  // namespace soma::planar
