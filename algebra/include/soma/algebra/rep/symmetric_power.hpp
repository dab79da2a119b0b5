#pragma once
// The symmetric power Sym^n V ⊂ V^{⊗n} (GF §7.2): spanned by the symmetrised products
// v_i v_j ⋯ v_k (i ≤ j ≤ … ≤ k), one per multiset of n indices, so dim Sym^n V = C(n + d − 1, n).
// Sym^n of a representation is the tensor power (algebraTensorPower) restricted to this invariant
// subspace (restrictToSubspace). Sym^k V* are the degree-k homogeneous polynomials on V.
#include "soma/algebra/rep/tensor_product.hpp"

#include <algorithm>
#include <map>

namespace soma::rep {

/// C(n + d − 1, n), the dimension of Sym^n of a d-dimensional space. GF §7.2, GF-7.2-dual-sum-tensor
inline long long symmetricPowerDimension(int d, int n) {
  long long c = 1;  // C(n + d − 1, n) = Π_{k=1..n} (d − 1 + k)/k, exact at every step
  for (int k = 1; k <= n; ++k) c = c * (d - 1 + k) / k;
  return c;
}

/// The basis of Sym^n V inside V^{⊗n} as the columns of a d^n × C(n+d−1, n) matrix: column m is
/// the sum of the basis tensors whose factor indices are a rearrangement of the m-th multiset
/// (multisets in lexicographic order of their sorted indices). Columns are orthogonal.
// GF §7.2, GF-7.2-dual-sum-tensor
template <class T> Matrix<T> symmetricPowerBasis(int d, int n) {
  const long long size = detail::tensorPowerSize(d, n);
  std::map<std::vector<int>, long long> column;
  for (long long t = 0; t < size; ++t) {
    std::vector<int> idx = detail::tensorIndexDigits(t, d, n);
    std::sort(idx.begin(), idx.end());
    column.emplace(idx, 0);
  }
  long long m = 0;
  for (auto& [key, col] : column) col = m++;
  Matrix<T> basis = Matrix<T>::Zero(size, m);
  for (long long t = 0; t < size; ++t) {
    std::vector<int> idx = detail::tensorIndexDigits(t, d, n);
    std::sort(idx.begin(), idx.end());
    basis(t, column.at(idx)) = T(1);
  }
  return basis;
}

/// The symmetriser (1/n!) Σ_σ σ on V^{⊗n}: the orthogonal projector onto Sym^n V (rank
/// C(n + d − 1, n)), built by averaging over the n! permutations of the factors.
// GF §7.2, GF-7.2-dual-sum-tensor
template <class T> Matrix<T> symmetriser(int d, int n) { return detail::permutationAverage<T>(d, n, false); }

}  // namespace soma::rep
