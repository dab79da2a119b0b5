#pragma once
// Lie-algebra tools over any tangent type with ad() (SO3Tangent, SE3Tangent, SE2Tangent…):
// the bracket, the Killing form, the Campbell–Baker–Hausdorff series and the dexp series.
// They are series and matrix traces, meant for studies and checks, not for inner loops.
#include "soma/algebra/se3.hpp"
#include "soma/algebra/so3.hpp"

namespace soma {

/// [a, b] = ad(a) b. For so(3): a × b; for se(3): (ω₁ × ω₂; ω₁ × v₂ − ω₂ × v₁).
// GF §4.3, GF-4.3-bracket-structure-constants, GF-4.3-se3-commutators-ad
template <class Tangent> Tangent bracket(const Tangent& a, const Tangent& b) {
  return Tangent(typename Tangent::DataType(a.ad() * b.coeffs()));
}

/// The matrix of the Killing form ⟨X, Y⟩ = Tr(ad X ad Y) on the coordinate basis.
/// so(3): −2 I₃; se(3): diag(−4 I₃, 0) (the book prints −2 for se(3), erratum E4.10).
// GF §4.7, GF-4.7-killing-so3, GF-4.7-killing-se3 (corrected, erratum E4.10)
template <class Tangent>
Eigen::Matrix<typename Tangent::Scalar, Tangent::DoF, Tangent::DoF> killingForm() {
  using S = typename Tangent::Scalar;
  constexpr int n = Tangent::DoF;
  using Data = typename Tangent::DataType;
  using AdMat = Eigen::Matrix<S, n, n>;
  AdMat ads[n];
  for (int i = 0; i < n; ++i) ads[i] = Tangent(Data(Data::Unit(i))).ad();
  AdMat k;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) k(i, j) = (ads[i] * ads[j]).trace();
  return k;
}

/// Campbell–Baker–Hausdorff: log(exp X exp Y) to the given order (1..4):
/// X + Y + ½[X,Y] + (1/12)([X,[X,Y]] + [Y,[Y,X]]) − (1/24)[Y,[X,[X,Y]]].
// GF §4.8, GF-4.8-cbh-series (the book stops at order 3; order 4 is the standard next term)
template <class Tangent> Tangent bch(const Tangent& x, const Tangent& y, int order) {
  using S = typename Tangent::Scalar;
  if (order < 1 || order > 4)
    throw InvalidInput("bch: order must be 1, 2, 3 or 4, got " + std::to_string(order));
  Tangent z = x + y;
  if (order >= 2) {
    const Tangent xy = bracket(x, y);
    z = z + xy * (S(1) / S(2));
    if (order >= 3) {
      const Tangent xxy = bracket(x, xy);
      z = z + (xxy + bracket(y, bracket(y, x))) * (S(1) / S(12));
      if (order >= 4) z = z - bracket(y, xxy) * (S(1) / S(24));
    }
  }
  return z;
}

/// Σ_{k=0}^{terms−1} ad(x)^k/(k+1)! — the spatial (left-trivialised) dexp of the Hausdorff
/// formula, the series of ljac(); with `body = true`, Σ (−1)^k ad^k/(k+1)!, the series of rjac().
// GF §4.5.2, GF-4.5.2-dexp-hausdorff (corrected 4th term, erratum E4.9; the study computes the
// printed ad²/4! and shows it failing)
template <class Tangent>
Eigen::Matrix<typename Tangent::Scalar, Tangent::DoF, Tangent::DoF> dexpSeries(
    const Tangent& x, int terms, bool body = false) {
  using S = typename Tangent::Scalar;
  using M = Eigen::Matrix<S, Tangent::DoF, Tangent::DoF>;
  const M a = body ? M(-x.ad()) : M(x.ad());
  // term_k = ad^k/(k+1)!, updated as term_k = term_{k−1}·ad/(k+1): no separate factorial, which
  // overflows float at (35)! and turned the sum into NaN.
  M term = M::Identity(), sum = M::Identity();
  for (int k = 1; k < terms; ++k) {
    term = (term * a / S(k + 1)).eval();
    sum += term;
  }
  return sum;
}

}  // namespace soma
