#pragma once
// A representation restricted to an invariant subspace U ⊂ V (GF §7.2): given a basis of U as
// the columns of B, the restricted matrix of A is the A_U with A B = B A_U, found by least
// squares, A_U = (BᵀB)⁻¹ Bᵀ A B; the residual ‖A B − B A_U‖ says whether U is invariant.
// Sym^n and ⋀^n of a representation are the tensor power restricted to symmetricPowerBasis /
// exteriorPowerBasis; an irreducible summand is the span of a ladder chain.
#include "soma/algebra/rep/tensor_product.hpp"

#include <Eigen/LU>

namespace soma::rep {

/// A_U with A B = B A_U (exact when the span of B's columns is invariant under A; B full rank).
// GF §7.2, GF-7.2-dual-sum-tensor
template <class A, class B> Matrix<typename A::Scalar> restrictToSubspace(const Eigen::MatrixBase<A>& a,
                                                                         const Eigen::MatrixBase<B>& basis) {
  using T = typename A::Scalar;
  const Matrix<T> b = basis.template cast<T>();
  const Matrix<T> bt = b.adjoint();
  const Matrix<T> gram = bt * b;
  return Eigen::FullPivLU<Matrix<T>>(gram).solve(Matrix<T>(bt * a * b));
}

}  // namespace soma::rep
