#pragma once
// Finite-position (Burmester) synthesis of planar 4-bars, beyond GF §5.3.5 (the book treats
// the infinitesimal case only). Positions M_i = (R_i, d_i) of a moving body, i = 1..n. A body
// point z (circle point) stays on a circle about a fixed point m (centre point) iff
//   e_i(m, z) = |M_i z − m|² − |M_1 z − m|² = 0,  i = 2..n,
// bilinear in (m, z): linear in z for fixed m and linear in m for fixed z.
//  * 3 positions: any z has its centre (circumcentre), any m its circle point.
//  * 4 positions: the centre points form a circular cubic (the centre-point curve, through the
//    six poles P_ij), the circle points another (the circle-point curve).
//  * 5 positions: the centre-point curves of {1,2,3,4} and {1,2,3,5} meet in 9 points: the 2
//    circular points at infinity, the poles P12, P13, P23 (spurious), and up to 4 Burmester
//    points. Two real Burmester pairs make a 4-bar whose coupler passes through all five.
#include "soma/geometry/planar/fourbar.hpp"

#include <optional>
#include <string>
#include <vector>

namespace soma::planar {

template <class S> struct BurmesterPair {
  Vec2<S> centre = Vec2<S>::Zero();  ///< fixed pivot (world)
  Vec2<S> circle = Vec2<S>::Zero();  ///< moving pivot (body coordinates of the moving frame)
  S radius{0};                       ///< link length |M_1 z − m|
  S residual{0};                     ///< max_i |e_i| / ρ², ρ = max(scale, |circle|, |centre − centroid|), after polishing
};

/// Result of driving a 4-bar through the prescribed positions.
template <class S> struct DriveCheck {
  std::vector<S> translationErrors, angleErrors;  ///< per position, relative to the data scale / radians
  S worstTranslation{0}, worstAngle{0};
  std::vector<int> modes;     ///< assembly mode of the linkage at each position
  std::vector<int> circuits;  ///< circuit index of each position
  bool sameCircuit = true;    ///< every position on one circuit (no disassembly needed)
  bool reached = true;        ///< every crank angle assemblable
};

template <class S> class BurmesterSynthesis {
 public:
  /// 2 to 5 positions of the moving frame. Throws InvalidInput for fewer than 2 or more than 5
  /// positions, NaN, or two positions that coincide (within Tolerance::input() of the scale).
  explicit BurmesterSynthesis(std::vector<SE2<S>> positions);
  const std::vector<SE2<S>>& positions() const { return pos_; }
  int size() const { return int(pos_.size()); }
  /// A length scale of the data (for reporting relative errors).
  S scale() const { return scale_; }

  /// e_i(m, z), i = 2..n (index i is 1-based as in the text).
  S equation(int i, const Vec2<S>& m, const Vec2<S>& z) const;
  /// max_{i ≥ 2} |e_i(m, z)| / ρ², ρ = max(scale, |z|, |m − centroid of the translations|): relative
  /// to the size of the terms of e_i (a pair far from the data has rounding floor eps·|z|·r, not eps·scale²).
  S residual(const Vec2<S>& m, const Vec2<S>& z) const;
  /// Pole P_ij of the displacement from position i to j (1-based). Throws for a translation.
  Vec2<S> pole(int i, int j) const;

  /// Three positions: the centre of the circle through M_1 z, M_2 z, M_3 z (empty if collinear).
  std::optional<Vec2<S>> centreForCirclePoint(const Vec2<S>& z) const;
  /// Three positions: the circle point whose three positions lie on a circle about m.
  /// Four or five positions: the least-squares z (exact when m is on the centre-point curve).
  std::optional<Vec2<S>> circlePointForCentre(const Vec2<S>& m) const;

  /// Four (or more) positions: det[a_i(m) | b_i(m)] over rows (2, 3, k): the centre-point curve
  /// of positions {1, 2, 3, k} (k = 4 by default), a circular cubic in world (x, y).
  Poly2<S> centrePointCurve(int k = 4) const;
  /// The circle-point curve of {1, 2, 3, k}, a cubic in body coordinates.
  Poly2<S> circlePointCurve(int k = 4) const;

  /// Five positions: the real Burmester pairs (up to four). The five circle conditions
  /// |M_i z − m|² = r² are linear in (1, K, m, z, m·z, m×z) with K = |z|² + |m|² − r²; their
  /// null space is a projective plane on which m·z and m×z cut two conics meeting in exactly
  /// four points (no spurious poles or circular points to remove). The conics are intersected
  /// through a degenerate member of their pencil (a line pair, from a 3×3 symmetric eigen-
  /// decomposition); every solution is polished by complex Newton, the real ones then by Newton
  /// on e_2..e_5 in S. `complexCount` receives the number of non-real solutions (0, 2, 4),
  /// `complexResidual` the largest max_i |e_i| / scale² among them (they are genuine solutions),
  /// `algebraicResidual` the largest residual of the four solutions before any Newton step,
  /// `notes` how it was solved (float: the conic intersection runs in double, the pairs are
  /// polished in float) and any solution at infinity (a slider dyad, not counted).
  /// `escalateFloat` (float only): false solves the conic intersection in float too, the float
  /// rung alone (SOMA-burmester-speed-accuracy measures what it loses).
  std::vector<BurmesterPair<S>> burmesterPairs(int* complexCount = nullptr, S* complexResidual = nullptr,
                                               S* algebraicResidual = nullptr, std::string* notes = nullptr,
                                               bool escalateFloat = true) const;

  /// A 4-bar from two pairs (a: crank c1 = a.centre, b: rocker c4 = b.centre); the coupler
  /// point is the moving frame's origin. Its coupler frame relates to the moving frame by
  /// `bodyToCoupler` (moving = coupler·bodyToCoupler⁻¹ ... see drive()).
  FourBar<S> fourBar(const BurmesterPair<S>& a, const BurmesterPair<S>& b) const;
  /// Drive that 4-bar through every position (crank angle from the prescribed crank pin) and
  /// compare the coupler pose with the prescribed one.
  DriveCheck<S> drive(const BurmesterPair<S>& a, const BurmesterPair<S>& b) const;

 private:
  /// Row i (1-based, ≥ 2) of the system in z for fixed m: a_i(m)·z + b_i(m) = 0, as affine polys in m.
  void rowInZ(int i, Poly2<S>& ax, Poly2<S>& ay, Poly2<S>& b) const;
  /// Row i of the system in m for fixed z: c_i(z)·m + f_i(z) = 0, as affine polys in z.
  void rowInM(int i, Poly2<S>& cx, Poly2<S>& cy, Poly2<S>& f) const;
  std::vector<SE2<S>> pos_;
  S scale_{1};
  Vec2<S> centroid_ = Vec2<S>::Zero();
};

/// Real points of an algebraic curve p(x, y) = 0 in the box [x0, x1] × [y0, y1] (for drawing):
/// roots in y along n vertical lines and roots in x along n horizontal lines.
template <class S> std::vector<Vec2<S>> sampleCurve(const Poly2<S>& p, const S& x0, const S& x1, const S& y0, const S& y1, int n);

}  // namespace soma::planar
