#pragma once
// The representations of se(3) and SE(3) used in GF ch. 7, as generator matrices on the basis
// ω_i, ω_j, ω_k, v_i, v_j, v_k: the standard 4×4 (P_g = [[R, t], [0, 1]], indecomposable but
// not irreducible: (x, y, z, 0) is invariant), the adjoint 6×6 (Ad_g = [[R, 0], [TR, R]]) and the
// coadjoint −adᵀ (its dual, on wrenches; equivalent to the adjoint through Q₀). A representation
// of se(3) is any array of six matrices with the brackets of se(3) (GF §4.3).
#include "soma/algebra/rep/dual_representation.hpp"
#include "soma/algebra/rep/tensor_product.hpp"
#include "soma/algebra/se3.hpp"

#include <array>

namespace soma::rep {

/// L(ω_i), L(ω_j), L(ω_k), L(v_i), L(v_j), L(v_k).
template <class T> using Se3Generators = std::array<Matrix<T>, 6>;

/// The 4×4 representation: L(s) = hat(s). GF §7.1, GF-7.1-representation-axioms
template <class S> Se3Generators<S> se3StandardGenerators() {
  Se3Generators<S> g;
  for (int a = 0; a < 6; ++a) g[std::size_t(a)] = SE3Tangent<S>(Vec6<S>(Vec6<S>::Unit(a))).hat();
  return g;
}
/// The adjoint representation: L(s) = ad(s). GF §7.1, GF-7.1-representation-axioms
template <class S> Se3Generators<S> se3AdjointGenerators() {
  Se3Generators<S> g;
  for (int a = 0; a < 6; ++a) g[std::size_t(a)] = SE3Tangent<S>(Vec6<S>(Vec6<S>::Unit(a))).ad();
  return g;
}
/// The coadjoint representation: L(s) = −ad(s)ᵀ. GF §7.5, GF-7.5-coadjoint
template <class S> Se3Generators<S> se3CoadjointGenerators() {
  Se3Generators<S> g = se3AdjointGenerators<S>();
  for (auto& m : g) m = dualOfAlgebra(m);
  return g;
}
/// Σ s_a L(e_a): the matrix of the element s = (ω; v).
template <class T, class S> Matrix<T> se3Element(const Se3Generators<T>& gen, const Vec6<S>& s) {
  Matrix<T> m = Matrix<T>::Zero(gen[0].rows(), gen[0].cols());
  for (int a = 0; a < 6; ++a) m += T(s(a)) * gen[std::size_t(a)];
  return m;
}
/// The coadjoint representation of the group: Ad*_g = Ad_{g⁻¹}ᵀ. GF §7.2, GF-7.5-coadjoint
template <class S> Mat6<S> coadjoint(const SE3<S>& g) { return dualOfGroup(g.inverse().adjoint()); }

}  // namespace soma::rep
