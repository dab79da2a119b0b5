#pragma once
// Instantaneous invariants of a planar motion (GF §5.3.1–5.3.5): the pole, ω and its
// derivatives, the book's pole curve r(t) and its derivatives, the point-path derivatives
// (P1)–(P4), Euler–Savary, the inflection circle, Ball's point (undulation), the cubic of
// stationary curvature and its normal form, the Burmester cubic and the Burmester points.
//
// CONVENTION (catalogue ch05, erratum E5.9): r(t) is the centre of the FINITE displacement
// M(t)M(0)⁻¹ from the reference instant, not the locus q(t) of instantaneous centres (the
// classical fixed centrode, q̇ = 2ṙ). The book's formulas hold with this r(t) only; soma computes
// its derivatives exactly from the motion jet: r(t) = ½ t_A + ½ cot(θ/2) J t_A.
//
// Two methods everywhere: the book's closed forms in terms of (ω…, r…) (corrected where the
// catalogue lists an erratum) and "direct" polynomials built from the jet's point derivatives
// p^(k) = R_k p + t_k (e.g. the inflection curve det[ṗ, p̈] = 0), which also cover the pole at
// infinity (pure translation) where the book's chart fails.
#include "soma/geometry/planar/motion_jet.hpp"

#include <optional>
#include <vector>

namespace soma::planar {

template <class S> struct Circle {
  Vec2<S> centre = Vec2<S>::Zero();
  S radius{0};
};

/// Normal frame of GF §5.3.4: origin r, x along ṙ, y along −E₂ṙ = Jṙ; v = |ṙ|, a = |r̈|,
/// r̈·ṙ = a v cos θ, r̈ᵀE₂ṙ = −a v sin θ, r⃛ = b(cos φ, sin φ) in the frame.
template <class S> struct NormalFrame {
  Vec2<S> origin = Vec2<S>::Zero(), ex = Vec2<S>::UnitX(), ey = Vec2<S>::UnitY();
  S v{0}, a{0}, cosTheta{1}, sinTheta{0}, b{0}, cosPhi{1}, sinPhi{0};
  /// World point → frame coordinates and back.
  Vec2<S> local(const Vec2<S>& p) const { return Vec2<S>((p - origin).dot(ex), (p - origin).dot(ey)); }
  Vec2<S> world(const Vec2<S>& q) const { return origin + q(0) * ex + q(1) * ey; }
};

/// Cubic of stationary curvature in normal form (x² + y²)(x/μ + y/ν) − xy = 0 (GF §5.3.4,
/// corrected μ, erratum E5.12). Stored as 1/μ, 1/ν so that μ = ∞ (a term drops) is representable.
template <class S> struct CubicNormalForm {
  NormalFrame<S> frame;
  S invMu{0}, invNu{0};
  S operator()(const S& x, const S& y) const { return (x * x + y * y) * (x * invMu + y * invNu) - x * y; }
};

/// Coefficients of the second (5-point contact) cubic in the normal frame,
/// (x² + y²)(αx + βy + γ) + y(ηx + ζy + ξ) = 0 (GF §5.3.5, corrected set, erratum E5.14).
template <class S> struct BurmesterCubic {
  S alpha{0}, beta{0}, gamma{0}, eta{0}, zeta{0}, xi{0};
  S operator()(const S& x, const S& y) const {
    return (x * x + y * y) * (alpha * x + beta * y + gamma) + y * (eta * x + zeta * y + xi);
  }
};

/// The four Burmester points of GF §5.3.5 and the book's count (9 = 2 circular points + 3 at
/// the pole + 4). Directions through the pole are the roots of a binary form of degree 7 that
/// factors as (c² + s²)·G₁·Q₄: (c² + s²) are the circular points at infinity, G₁ the tangent of
/// the second cubic at the pole (the pole's extra intersection), Q₄ the four Burmester points.
template <class S> struct BurmesterPoints {
  std::vector<Cx<S>> x, y;     ///< world coordinates, complex in general (conjugate pairs)
  std::vector<bool> isReal;    ///< |imaginary part| ≤ tolerance (relative to the scale)
  int realCount = 0;
  int formDegree = 0;          ///< degree of the binary form before removing spurious factors (7)
  S circularRemainder{0};      ///< remainder of the division by c² + s² (relative; ≈ 0)
  S tangentRemainder{0};       ///< remainder of the division by G₁ (relative; ≈ 0)
  std::vector<S> residuals;    ///< per point: max(|F|, |G|)/magnitude at the (real part of the) point
};

template <class S> class InstantInvariants {
 public:
  /// From a motion jet. Throws InvalidInput when the pole is at infinity (|ω| ≤ rank tolerance
  /// relative to the translational speed over the scale): the book's chart fails there; use the
  /// direct polynomials of the jet instead.
  static InstantInvariants fromJet(const MotionJet<S>& jet);
  /// From values directly (ω^(k), r^(k), k = 0..3).
  InstantInvariants(const std::array<S, 4>& omega, const std::array<Vec2<S>, 4>& r) : w_(omega), r_(r) {}

  S omega(int k = 0) const { return w_[k]; }  ///< ω, ω̇, ω̈, ω⃛
  const Vec2<S>& r(int k = 0) const { return r_[k]; }  ///< r, ṙ, r̈, r⃛ (book's finite-pole curve)
  const Vec2<S>& pole() const { return r_[0]; }

  /// (P1)–(P4) (GF §5.3.1, §5.3.3, §5.3.5; P4 corrected, erratum E5.13): p, ṗ, p̈, p⃛, p⁗.
  std::array<Vec2<S>, 5> pointDerivatives(const Vec2<S>& p) const;

  /// Centre of curvature of the path of p by Euler–Savary (GF §5.3.1, GF-5.3.1-euler-savary):
  /// c = r + λ(p − r), λ = 2uᵀE₂ṙ/(2uᵀE₂ṙ − ω|u|²). Returns false at an inflection (c at ∞).
  bool eulerSavaryCentre(const Vec2<S>& p, Vec2<S>& c) const;

  /// Inflection circle (GF §5.3.2): centre r + E₂ṙ/ω, radius |ṙ|/|ω|.
  Circle<S> inflectionCircle() const;
  /// Inflection pole r + 2E₂ṙ/ω (diametrically opposite r).
  Vec2<S> inflectionPole() const;
  /// (p − r)ᵀ(ω(p − r) − 2E₂ṙ): zero on the inflection circle.
  S inflectionResidual(const Vec2<S>& p) const;

  /// x = ω²ṙ − ω̇E₂ṙ + ωE₂r̈ (corrected, erratum E5.11): the undulation line is (p − r)·x = 0.
  Vec2<S> undulationVector() const;
  /// Ball's point r + λE₂x, λ = 2 x·ṙ/(ω x·x) (GF §5.3.3 corrected, errata E5.10, E5.11).
  /// Throws InvalidInput when x = 0 (undetermined).
  Vec2<S> ballPoint() const;

  /// Book's cubic of stationary curvature at p (GF §5.3.4; printed form, correct).
  S stationaryCurvatureCubic(const Vec2<S>& p) const;
  /// The same cubic as a polynomial in world (x, y).
  Poly2<S> stationaryCurvatureCubicPoly() const;
  /// Normal frame (GF §5.3.4). Throws InvalidInput when ṙ = 0 (the frame is undefined).
  NormalFrame<S> normalFrame() const;
  /// Normal form with corrected μ = 4v²/(a sin θ − ωv) and ν = 4ωv²/(ω̇v − ωa cos θ) (E5.12).
  CubicNormalForm<S> cubicNormalForm() const;
  /// Corrected α…ξ of the Burmester cubic (erratum E5.14).
  BurmesterCubic<S> burmesterCubic() const;

 private:
  InstantInvariants() = default;
  std::array<S, 4> w_;
  std::array<Vec2<S>, 4> r_;
};

// ---- direct polynomials from the jet (second method; valid for the pole at infinity) ----------

/// det[ṗ, p̈] as a polynomial in world (x, y): ω³(x² + y²) + … (a line when ω = 0). GF §5.3.2
template <class S> Poly2<S> inflectionCurve(const MotionJet<S>& jet);
/// (ṗ·ṗ) det[ṗ, p⃛] − 3(p̈·ṗ) det[ṗ, p̈] (the quartic terms cancel: a circular cubic). GF §5.3.4
template <class S> Poly2<S> stationaryCurvatureCurve(const MotionJet<S>& jet);
/// (ṗ·ṗ) det[ṗ, p⁗] − (4p⃛·ṗ + 3p̈·p̈) det[ṗ, p̈]: the second cubic of 5-point contact. GF §5.3.5
template <class S> Poly2<S> fivePointContactCurve(const MotionJet<S>& jet);
/// det[ṗ, p⃛] (the undulation condition, together with det[ṗ, p̈] = 0). GF §5.3.3
template <class S> Poly2<S> undulationCurve(const MotionJet<S>& jet);

/// Burmester points of the motion at t = 0 (GF §5.3.5, GF-5.3.5-burmester-count), from the
/// direct cubics intersected through their common node at the pole. Throws InvalidInput for a
/// pole at infinity or a degenerate cubic (ṙ = 0).
template <class S> BurmesterPoints<S> burmesterPoints(const MotionJet<S>& jet);

/// The classical fixed centrode q(t) (locus of instantaneous centres) near t = 0 as series:
/// q = d + Jḋ/ω (one order lost: q, q̇, q̈, q⃛ valid). Throws InvalidInput for ω = 0.
template <class S> std::array<Series<S>, 2> fixedCentrode(const MotionJet<S>& jet);
/// The moving centrode: the instantaneous centre in body coordinates, R(φ)ᵀ J ḋ/ω, as series.
template <class S> std::array<Series<S>, 2> movingCentrode(const MotionJet<S>& jet);

}  // namespace soma::planar
