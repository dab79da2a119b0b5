#pragma once
// The regulus through three pairwise skew lines (GF §6.5.1, GF-6.5.1-conic-to-quadric): the lines
// l₁, l₂, l₃ span a 2-plane of PR⁵ that meets the Klein quadric in a conic, and that conic is the
// regulus containing them. A point x = a l₁ + b l₂ + c l₃ of the plane is a line iff
//   ab K₁₂ + ac K₁₃ + bc K₂₃ = 0,   K_ij = ⟨l_i, l_j⟩ (the reciprocal product, ≠ 0 for skew lines);
// with (α, β, γ) = (1/a, 1/b, 1/c) this is the straight line K₁₂ γ + K₁₃ β + K₂₃ α = 0, so the
// conic is parametrised by (α, β, γ)(t) = cos t (K₁₃, −K₂₃, 0) + sin t (0, K₁₂, −K₁₃), t ∈ [0, π),
// and x(t) = βγ l₁ + αγ l₂ + αβ l₃ (t = 0 gives l₃, t = π/2 gives l₁).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/reciprocal_product.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/lines/line.hpp"

#include <Eigen/QR>
#include <array>
#include <string>

namespace soma {

template <class S> class ThreeLineRegulus {
 public:
  /// The regulus through l₁, l₂, l₃ (finite lines). InvalidInput when two of them meet or are
  /// parallel (⟨l_i, l_j⟩ ≈ 0 relative to |l_i||l_j|): three lines of a regulus are pairwise skew.
  // GF §6.5.1, GF-6.5.1-conic-to-quadric
  ThreeLineRegulus(const PluckerLine<S>& l1, const PluckerLine<S>& l2, const PluckerLine<S>& l3)
      : lines_{l1.normalized().coords(), l2.normalized().coords(), l3.normalized().coords()} {
    using std::abs;
    const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int k = 0; k < 3; ++k) {
      const int i = pairs[k][0], j = pairs[k][1];
      k_[std::size_t(k)] = reciprocalProduct(lines_[std::size_t(i)], lines_[std::size_t(j)]);
      const S scale = lines_[std::size_t(i)].norm() * lines_[std::size_t(j)].norm();
      if (abs(k_[std::size_t(k)]) <= Tolerance<S>::input() * scale)
        throw InvalidInput("ThreeLineRegulus: lines " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                           " meet or are parallel (the three lines of a regulus are pairwise skew)");
    }
  }

  /// The given lines (unit directions).
  const Vec6<S>& given(int i) const { return lines_.at(std::size_t(i)); }
  /// The member at t (period π), scaled to |x| = 1 (a line at infinity, ω = 0, for a paraboloid's
  /// regulus at one t). GF §6.5.1
  Vec6<S> member(const S& t) const {
    using std::cos;
    using std::sin;
    const S c = cos(t), s = sin(t);
    const S alpha = c * k_[1], beta = -c * k_[2] + s * k_[0], gamma = -s * k_[1];
    const Vec6<S> x = beta * gamma * lines_[0] + alpha * gamma * lines_[1] + alpha * beta * lines_[2];
    return x / x.norm();
  }
  /// The parameter of given line i: π/2 (l₁), atan2(K₂₃, K₁₂) mod π (l₂), 0 (l₃).
  S givenParameter(int i) const {
    using std::atan2;
    if (i == 0) return pi<S>() / S(2);
    if (i == 2) return S(0);
    S t = atan2(k_[2], k_[0]);
    if (t < S(0)) t += pi<S>();
    return t;
  }
  /// Whether the 6-vector x is a line of the regulus: in the span of the three lines (relative
  /// least-squares residual) and on the Klein quadric (kleinDefect), both within tol.
  bool contains(const Vec6<S>& x, const S& tol = Tolerance<S>::sqrtEpsilon()) const {
    Eigen::Matrix<S, 6, 3> a;
    for (int i = 0; i < 3; ++i) a.col(i) = lines_[std::size_t(i)];
    const Eigen::Matrix<S, 3, 1> c = a.colPivHouseholderQr().solve(x);
    return (a * c - x).norm() <= tol * x.norm() && kleinDefect(x) <= tol;
  }

 private:
  std::array<Vec6<S>, 3> lines_;
  std::array<S, 3> k_{};  // K₁₂, K₁₃, K₂₃
};

}  // namespace soma
