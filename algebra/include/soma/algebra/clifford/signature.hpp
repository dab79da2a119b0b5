#pragma once
// Clifford algebra Cl(p,q,r): signature, basis blades as bitmasks, and the sign of the product of
// two basis blades (GF §9.1, GF-9.1-clifford-definition-signature).
//
// Generators e_0 … e_{n-1}, n = p+q+r ≤ 8, ordered as the book orders them: the first p square
// to +1, the next q to −1, the last r to 0 (degenerate). So Cl(0,1,0) ≅ ℂ, Cl(0,0,1) = 𝔻,
// Cl(0,2,0) ≅ ℍ, Cl(0,3,1) is the algebra of GF §9.2 with the null generator 𝐞 = e_3.
// A basis blade is a bitmask: bit i set ⇔ e_i is a factor, factors in increasing index order
// (e.g. 0b101 = e_0 e_2). The algebra has dimension 2^n (GF-9.1-clifford-definition-signature).
//
// Everything here is constexpr: the product tables of multivector.hpp are built from these
// functions at compile time, once per (signature, operand grades, product) that is used.
#include <array>
#include <bit>
#include <cstdint>

namespace soma::clifford {

/// Set of grades as a bitmask: bit k set ⇔ grade k present. Grades 0 … 8.
using GradeMask = std::uint32_t;
using Blade = std::uint32_t;

constexpr GradeMask gradeBit(int k) { return GradeMask(1) << k; }
/// Grade of a basis blade = number of generator factors.
constexpr int bladeGrade(Blade b) { return std::popcount(b); }

/// Sign (+1/−1) of moving the factors of blade b past those of blade a to sort a·b into
/// increasing index order, ignoring the metric: (−1)^{#pairs (i∈a, j∈b) with i > j}.
constexpr int reorderSign(Blade a, Blade b) {
  int swaps = 0;
  for (a >>= 1; a != 0; a >>= 1) swaps += std::popcount(a & b);
  return (swaps & 1) ? -1 : 1;
}

template <int P, int Q, int R> struct Signature {
  static_assert(P >= 0 && Q >= 0 && R >= 0, "Signature<p,q,r>: counts must be non-negative");
  static_assert(P + Q + R >= 1 && P + Q + R <= 8, "Signature<p,q,r>: need 1 <= p+q+r <= 8");
  static constexpr int p = P, q = Q, r = R;
  static constexpr int n = P + Q + R;
  /// Dimension of the algebra, 2^n (GF §9.1).
  static constexpr int dim = 1 << n;
  /// The pseudoscalar e_0 e_1 … e_{n-1}.
  static constexpr Blade pseudoscalar = Blade(dim - 1);
  /// Generators that square to 0.
  static constexpr Blade nullMask = Blade(((1 << R) - 1) << (P + Q));
  static constexpr Blade negativeMask = Blade(((1 << Q) - 1) << P);
  static constexpr GradeMask allGrades = (GradeMask(1) << (n + 1)) - 1;
  static constexpr GradeMask evenGrades = allGrades & GradeMask(0x155);  // grades 0,2,4,6,8
  static constexpr GradeMask oddGrades = allGrades & GradeMask(0xAA);    // grades 1,3,5,7

  /// e_i² ∈ {+1, −1, 0} (GF §9.1: Sylvester's law gives generators of these three kinds).
  static constexpr int square(int i) { return i < P ? 1 : (i < P + Q ? -1 : 0); }

  /// Sign s ∈ {+1, −1, 0} with (blade a)(blade b) = s · blade(a xor b): the reordering sign
  /// times the squares of the shared generators (0 when a shared generator is null).
  static constexpr int productSign(Blade a, Blade b) {
    const Blade common = a & b;
    if (common & nullMask) return 0;
    int s = reorderSign(a, b);
    if (std::popcount(common & negativeMask) & 1) s = -s;
    return s;
  }

  /// Sign of the exterior (Grassmann) product a ∧ b: 0 if they share a factor, else the
  /// reordering sign; independent of the metric (GF-9.1-exterior-product).
  static constexpr int outerSign(Blade a, Blade b) { return (a & b) ? 0 : reorderSign(a, b); }

  /// Right complement (Poincaré duality on the basis, no metric): rc(a) = c·(I xor a) with
  /// a ∧ rc(a) = I. Returns c.
  static constexpr int rightComplementSign(Blade a) { return reorderSign(a, pseudoscalar ^ a); }
  /// Left complement: lc(a) = c·(I xor a) with lc(a) ∧ a = I. Returns c. lc(rc(a)) = a.
  static constexpr int leftComplementSign(Blade a) { return reorderSign(pseudoscalar ^ a, a); }

  /// Sign of the regressive (join) product a ∨ b = lc(rc(a) ∧ rc(b)) of two blades; the result
  /// blade is a & b, nonzero only if a | b = I. Metric-free, so valid for degenerate signatures.
  static constexpr int regressiveSign(Blade a, Blade b) {
    if ((a | b) != pseudoscalar) return 0;
    const Blade ca = pseudoscalar ^ a, cb = pseudoscalar ^ b;
    int s = rightComplementSign(a) * rightComplementSign(b) * reorderSign(ca, cb);
    return s * leftComplementSign(ca | cb);
  }

  /// The full dim×dim table of productSign, row a, column b (row-major), for callers that want
  /// a lookup rather than the function; built at compile time on first use.
  static constexpr std::array<std::int8_t, std::size_t(dim) * dim> productSignTable() {
    std::array<std::int8_t, std::size_t(dim) * dim> t{};
    for (Blade a = 0; a < Blade(dim); ++a)
      for (Blade b = 0; b < Blade(dim); ++b)
        t[std::size_t(a) * dim + b] = std::int8_t(productSign(a, b));
    return t;
  }
};

/// Sign of the reverse of a grade-k blade: (−1)^{k(k−1)/2} (grades 0..4: + + − − +).
constexpr int reverseSign(int k) { return ((k * (k - 1) / 2) & 1) ? -1 : 1; }
/// Sign of the grade (main) involution α on grade k: (−1)^k (GF §9.1).
constexpr int involutionSign(int k) { return (k & 1) ? -1 : 1; }
/// Sign of Clifford conjugation c* = α(c̃) on grade k: (−1)^k (−1)^{k(k−1)/2}
/// (GF-9.1-conjugation-involution; grades 0..4: + − − + +).
constexpr int conjugationSign(int k) { return reverseSign(k) * involutionSign(k); }

}  // namespace soma::clifford
