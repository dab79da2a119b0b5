#pragma once
// The shuffle product of Grassmann–Cayley algebra as GF §10.2.3 defines it (GF-10.2.3-shuffle-
// definition, corrected by erratum E10.11): for blades a = a_1∧…∧a_j, b = b_1∧…∧b_k of the
// n = 4 generators e1, e2, e3, 𝐞 (𝐞 taken as "e4"), j + k ≥ n,
//
//   a ∨ b = 1/((n−k)!(j+k−n)!) Σ_σ sign(σ) det(a_σ(1), …, a_σ(n−k), b_1, …, b_k)
//                                           a_σ(n−k+1) ∧ … ∧ a_σ(j),
//
// σ over all permutations of {1, …, j}; extended bilinearly. The book prints a_σ(4−k+1), calls n
// "the dimension of the algebra" (it is the dimension of the generator space) and lists the last
// determinant column as b_σ(k)i (it is b_ki): E10.11. The grade of a ∨ b is j + k − n.
//
// This is implemented literally, blade by blade, from permutations; it does not use the
// regressive product of multivector.hpp (a Poincaré-duality definition), so the two can be
// compared (tests/geometry/pga/shuffle.cpp, study GF-10.2.3-shuffle-definition).
#include "soma/geometry/pga/basis.hpp"

#include <algorithm>
#include <array>

namespace soma::pga {

namespace detail {

constexpr int factorial(int m) { return m <= 1 ? 1 : m * factorial(m - 1); }

/// Sign of the permutation taking the list to increasing order; 0 if two entries repeat.
template <std::size_t N> constexpr int permutationSign(std::array<int, N> v, int len) {
  int s = 1;
  for (int i = 0; i < len; ++i)
    for (int j = i + 1; j < len; ++j) {
      if (v[std::size_t(i)] == v[std::size_t(j)]) return 0;
      if (v[std::size_t(i)] > v[std::size_t(j)]) s = -s;
    }
  return s;
}

/// Coefficient c with blade(a) ∨ blade(b) = c · blade(a & b) by the book's formula (n = 4);
/// 0 when j + k < n. The sum divided by the factorials is an integer (−1, 0 or 1; checked by
/// the static_assert in shuffleTable).
constexpr int bookShuffleCoefficient(Blade a, Blade b) {
  constexpr int n = 4;
  std::array<int, 4> af{}, bf{};
  int j = 0, k = 0;
  for (int g = 0; g < n; ++g) {
    if (a & (Blade(1) << g)) af[std::size_t(j++)] = g;
    if (b & (Blade(1) << g)) bf[std::size_t(k++)] = g;
  }
  if (j + k < n) return 0;
  std::array<int, 4> perm{0, 1, 2, 3};  // σ as indices into af
  int sum = 0;
  do {
    // sign(σ)
    const int sgn = permutationSign(perm, j);
    // det(a_σ(1), …, a_σ(n−k), b_1, …, b_k) of basis vectors: the sign of the column list.
    std::array<int, 4> cols{};
    for (int i = 0; i < n - k; ++i) cols[std::size_t(i)] = af[std::size_t(perm[std::size_t(i)])];
    for (int i = 0; i < k; ++i) cols[std::size_t(n - k + i)] = bf[std::size_t(i)];
    const int det = permutationSign(cols, n);
    if (det != 0) {
      // a_σ(n−k+1) ∧ … ∧ a_σ(j): the sign of sorting the remaining factors.
      std::array<int, 4> rest{};
      for (int i = n - k; i < j; ++i) rest[std::size_t(i - (n - k))] = af[std::size_t(perm[std::size_t(i)])];
      sum += sgn * det * permutationSign(rest, j + k - n);
    }
  } while (std::next_permutation(perm.begin(), perm.begin() + j));
  return sum / (factorial(n - k) * factorial(j + k - n));
}

constexpr std::array<std::int8_t, 256> shuffleTable() {
  std::array<std::int8_t, 256> t{};
  for (Blade a = 0; a < 16; ++a)
    for (Blade b = 0; b < 16; ++b) t[a * 16 + b] = std::int8_t(bookShuffleCoefficient(a, b));
  return t;
}
inline constexpr std::array<std::int8_t, 256> kShuffle = shuffleTable();

/// Grades reached by the shuffle of grade masks A and B (j + k − 4 for j + k ≥ 4).
constexpr clifford::GradeMask shuffleGrades(clifford::GradeMask A, clifford::GradeMask B) {
  clifford::GradeMask m = 0;
  for (int j = 0; j <= 4; ++j)
    for (int k = 0; k <= 4; ++k)
      if ((A & gradeBit(j)) && (B & gradeBit(k)) && j + k >= 4) m |= gradeBit(j + k - 4);
  return m;
}

}  // namespace detail

/// The book's coefficient of blade(a) ∨ blade(b) (result blade a & b), from the permutation sum.
constexpr int shuffleCoefficient(Blade a, Blade b) { return detail::kShuffle[a * 16 + b]; }

/// a ∨ b, the shuffle (join) product of GF §10.2.3, extended bilinearly; GF-10.2.3-shuffle-definition
/// (corrected, erratum E10.11).
template <class S, clifford::GradeMask A, clifford::GradeMask B>
auto shuffle(const clifford::Multivector<Cl031, S, A>& a, const clifford::Multivector<Cl031, S, B>& b) {
  constexpr clifford::GradeMask R = detail::shuffleGrades(A, B);
  static_assert(R != 0, "pga::shuffle: the grades add up to less than 4, so a ∨ b is 0");
  clifford::Multivector<Cl031, S, R> out;
  for (int i = 0; i < a.size; ++i)
    for (int j = 0; j < b.size; ++j) {
      const int c = shuffleCoefficient(a.blade(i), b.blade(j));
      if (c == 0) continue;
      const Blade r = a.blade(i) & b.blade(j);
      const S v = out.coeff(r);
      out.setCoeff(r, c > 0 ? S(v + a[i] * b[j]) : S(v - a[i] * b[j]));
    }
  return out;
}

}  // namespace soma::pga
