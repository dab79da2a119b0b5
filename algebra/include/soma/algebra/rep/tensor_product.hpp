#pragma once
// Tensor products of representations (GF §7.2): the group acts on V ⊗ W by R₁(g) ⊗ R₂(g) (the
// Kronecker product), the Lie algebra by L₁(X) ⊗ 1 + 1 ⊗ L₂(X) (the Kronecker sum), so that
// eigenvalues add. Basis order of V ⊗ W: v_i ⊗ w_j at index i·dim W + j (Eigen's kroneckerProduct).
// The matrices may be real or complex (std::complex<S>), fixed or dynamic size.
#include "soma/algebra/scalar.hpp"

#include <unsupported/Eigen/KroneckerProduct>

#include <algorithm>
#include <vector>

namespace soma::rep {

template <class T> using Matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// R₁(g) ⊗ R₂(g): the tensor product of two group representations. GF §7.2, GF-7.2-dual-sum-tensor
template <class A, class B> Matrix<typename A::Scalar> groupTensor(const Eigen::MatrixBase<A>& r1,
                                                                  const Eigen::MatrixBase<B>& r2) {
  return Matrix<typename A::Scalar>(Eigen::kroneckerProduct(r1.derived(), r2.derived()));
}

/// L₁(X) ⊗ 1 + 1 ⊗ L₂(X): the tensor product of two Lie-algebra representations.
// GF §7.2, GF-7.2-dual-sum-tensor
template <class A, class B> Matrix<typename A::Scalar> algebraTensor(const Eigen::MatrixBase<A>& l1,
                                                                    const Eigen::MatrixBase<B>& l2) {
  using T = typename A::Scalar;
  const Matrix<T> i1 = Matrix<T>::Identity(l1.rows(), l1.cols()), i2 = Matrix<T>::Identity(l2.rows(), l2.cols());
  return Matrix<T>(Matrix<T>(Eigen::kroneckerProduct(l1.derived(), i2)) + Matrix<T>(Eigen::kroneckerProduct(i1, l2.derived())));
}

/// The n-th tensor power of a Lie-algebra representation, Σ_k 1 ⊗ … ⊗ L(X) ⊗ … ⊗ 1 on V^{⊗n}
/// (dim d^n); n = 0 gives the trivial 1×1 zero. GF §7.2, GF-7.2-dual-sum-tensor
template <class A> Matrix<typename A::Scalar> algebraTensorPower(const Eigen::MatrixBase<A>& l, int n) {
  using T = typename A::Scalar;
  Matrix<T> out = Matrix<T>::Zero(1, 1);
  for (int k = 0; k < n; ++k) out = algebraTensor(out, l);
  return out;
}

}  // namespace soma::rep

namespace soma::rep::detail {
/// The n factor indices (i₁, …, i_n) of basis vector `index` of V^{⊗n}, dim V = d (first factor
/// most significant, as in algebraTensorPower).
inline std::vector<int> tensorIndexDigits(long long index, int d, int n) {
  std::vector<int> digits(std::size_t(n), 0);
  for (int k = n - 1; k >= 0; --k) {
    digits[std::size_t(k)] = int(index % d);
    index /= d;
  }
  return digits;
}
inline long long tensorPowerSize(int d, int n) {
  long long size = 1;
  for (int k = 0; k < n; ++k) size *= d;
  return size;
}
/// (1/n!) Σ_σ χ(σ) σ on V^{⊗n} (σ permutes the factors; χ = 1 or the sign of σ): the symmetriser
/// and the antisymmetriser (symmetric_power.hpp, exterior_power.hpp).
template <class T> Matrix<T> permutationAverage(int d, int n, bool signed_) {
  const long long size = tensorPowerSize(d, n);
  std::vector<int> perm(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) perm[std::size_t(k)] = k;
  Matrix<T> p = Matrix<T>::Zero(size, size);
  long long count = 0;
  do {
    ++count;
    int sign = 1;  // the sign of perm by counting inversions
    if (signed_)
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
          if (perm[std::size_t(a)] > perm[std::size_t(b)]) sign = -sign;
    for (long long t = 0; t < size; ++t) {
      const std::vector<int> idx = tensorIndexDigits(t, d, n);
      long long u = 0;
      for (int k = 0; k < n; ++k) u = u * d + idx[std::size_t(perm[std::size_t(k)])];
      p(u, t) += T(double(sign));
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return p / T(double(count));
}
}  // namespace soma::rep::detail
