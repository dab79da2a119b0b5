#pragma once
// The direct sum of representations (GF §7.2): (L₁ ⊕ L₂)(X) = diag(L₁(X), L₂(X)) on V ⊕ W, whose
// eigenvalues are those of L₁(X) together with those of L₂(X). The same block form serves groups.
#include "soma/algebra/rep/tensor_product.hpp"

namespace soma::rep {

/// diag(A, B). GF §7.2, GF-7.2-dual-sum-tensor
template <class A, class B> Matrix<typename A::Scalar> directSum(const Eigen::MatrixBase<A>& a,
                                                                const Eigen::MatrixBase<B>& b) {
  using T = typename A::Scalar;
  Matrix<T> out = Matrix<T>::Zero(a.rows() + b.rows(), a.cols() + b.cols());
  out.topLeftCorner(a.rows(), a.cols()) = a;
  out.bottomRightCorner(b.rows(), b.cols()) = b;
  return out;
}

}  // namespace soma::rep
