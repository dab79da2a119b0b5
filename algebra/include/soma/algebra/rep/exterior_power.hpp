#pragma once
// The exterior power ⋀^n V ⊂ V^{⊗n} (GF §7.2): spanned by v_i ∧ v_j ∧ ⋯ ∧ v_k = Σ_σ sign(σ) v_σ(i)
// ⊗ ⋯ (i < j < … < k), so dim ⋀^n V = C(d, n). ⋀^n of a representation is the tensor power
// restricted to it (restrictToSubspace); the Grassmannian G(n, m) sits in ⋀^n ℝ^m.
#include "soma/algebra/rep/tensor_product.hpp"

#include <algorithm>
#include <map>

namespace soma::rep {

/// C(d, n), the dimension of ⋀^n of a d-dimensional space (0 for n > d). GF §7.2, GF-7.2-dual-sum-tensor
inline long long exteriorPowerDimension(int d, int n) {
  if (n < 0 || n > d) return 0;
  long long c = 1;
  for (int k = 1; k <= n; ++k) c = c * (d - n + k) / k;
  return c;
}

/// The basis of ⋀^n V inside V^{⊗n} as columns (d^n × C(d, n)): column m is Σ_σ sign(σ) e_σ over
/// the arrangements of the m-th increasing index set (lexicographic order). Columns are orthogonal.
// GF §7.2, GF-7.2-dual-sum-tensor
template <class T> Matrix<T> exteriorPowerBasis(int d, int n) {
  const long long size = detail::tensorPowerSize(d, n);
  std::map<std::vector<int>, long long> column;
  auto sortWithSign = [](std::vector<int>& idx) {  // bubble sort; the sign of the permutation, 0 on a repeat
    int sign = 1;
    for (std::size_t a = 0; a < idx.size(); ++a)
      for (std::size_t b = 0; b + 1 < idx.size() - a; ++b)
        if (idx[b] > idx[b + 1]) std::swap(idx[b], idx[b + 1]), sign = -sign;
    for (std::size_t a = 0; a + 1 < idx.size(); ++a)
      if (idx[a] == idx[a + 1]) return 0;
    return sign;
  };
  for (long long t = 0; t < size; ++t) {
    std::vector<int> idx = detail::tensorIndexDigits(t, d, n);
    if (sortWithSign(idx) != 0) column.emplace(idx, 0);
  }
  long long m = 0;
  for (auto& [key, col] : column) col = m++;
  Matrix<T> basis = Matrix<T>::Zero(size, m);
  for (long long t = 0; t < size; ++t) {
    std::vector<int> idx = detail::tensorIndexDigits(t, d, n);
    const int sign = sortWithSign(idx);
    if (sign != 0) basis(t, column.at(idx)) = T(double(sign));
  }
  return basis;
}

/// The antisymmetriser (1/n!) Σ_σ sign(σ) σ on V^{⊗n}: the orthogonal projector onto ⋀^n V.
// GF §7.2, GF-7.2-dual-sum-tensor
template <class T> Matrix<T> antisymmetriser(int d, int n) { return detail::permutationAverage<T>(d, n, true); }

}  // namespace soma::rep
