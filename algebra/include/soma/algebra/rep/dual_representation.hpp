#pragma once
// The dual (contragredient) representation on V* (GF §7.2): the evaluation f(v) is left
// unchanged, (R*_g f)(R_g v) = f(v), so R*_g = R_{g⁻¹}ᵀ; for the Lie algebra
// (L*_X f)(v) + f(L_X v) = 0, so L*_X = −L_Xᵀ (eigenvalues change sign). For se(3) the dual of
// the adjoint representation is the coadjoint representation (wrenches).
#include "soma/algebra/scalar.hpp"

namespace soma::rep {

/// R*_g = R_{g⁻¹}ᵀ, given the matrix of g⁻¹. GF §7.2, GF-7.2-dual-sum-tensor
template <class A> auto dualOfGroup(const Eigen::MatrixBase<A>& rInverse) { return rInverse.transpose().eval(); }

/// L*_X = −L_Xᵀ. GF §7.2, GF-7.2-dual-sum-tensor
template <class A> auto dualOfAlgebra(const Eigen::MatrixBase<A>& l) { return (-l.transpose()).eval(); }

}  // namespace soma::rep
