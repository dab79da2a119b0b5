#pragma once
// Quaternion multiplication as 4×4 matrices on Study-ordered coefficients (w, x, y, z), and the
// left/right actions of a dual quaternion on PR⁷ as 8×8 matrices (GF §9.3, §11.2): the tools
// that turn statements about Study parameters into linear algebra.
#include "soma/algebra/dual_quaternion.hpp"

namespace soma {

/// L(p) with L(p)·q = p q (coefficients in Study order w, x, y, z). GF §9.3
template <class S> Mat4<S> quaternionLeftMatrix(const Vec4<S>& p) {
  Mat4<S> m;
  m << p(0), -p(1), -p(2), -p(3),  //
      p(1), p(0), -p(3), p(2),     //
      p(2), p(3), p(0), -p(1),     //
      p(3), -p(2), p(1), p(0);
  return m;
}

/// R(q) with R(q)·p = p q (coefficients in Study order w, x, y, z). GF §9.3
template <class S> Mat4<S> quaternionRightMatrix(const Vec4<S>& q) {
  Mat4<S> m;
  m << q(0), -q(1), -q(2), -q(3),  //
      q(1), q(0), q(3), -q(2),     //
      q(2), -q(3), q(0), q(1),     //
      q(3), q(2), -q(1), q(0);
  return m;
}

/// The linear map x ↦ g x of PR⁷ (left multiplication by the dual quaternion g = a + εc):
/// (a', c') = (a_g a, a_g c + c_g a). GF §11.2.2, GF-11.2.2-A-plane-cosets
template <class S> Eigen::Matrix<S, 8, 8> dualQuaternionLeftMatrix(const DualQuaternion<S>& g) {
  const Vec8<S> v = g.coeffs();
  const Mat4<S> La = quaternionLeftMatrix<S>(v.template head<4>()), Lc = quaternionLeftMatrix<S>(v.template tail<4>());
  Eigen::Matrix<S, 8, 8> m = Eigen::Matrix<S, 8, 8>::Zero();
  m.template topLeftCorner<4, 4>() = La;
  m.template bottomLeftCorner<4, 4>() = Lc;
  m.template bottomRightCorner<4, 4>() = La;
  return m;
}

/// The linear map x ↦ x g (right multiplication): (a', c') = (a a_g, c a_g + a c_g). GF §11.2.2
template <class S> Eigen::Matrix<S, 8, 8> dualQuaternionRightMatrix(const DualQuaternion<S>& g) {
  const Vec8<S> v = g.coeffs();
  const Mat4<S> Ra = quaternionRightMatrix<S>(v.template head<4>()), Rc = quaternionRightMatrix<S>(v.template tail<4>());
  Eigen::Matrix<S, 8, 8> m = Eigen::Matrix<S, 8, 8>::Zero();
  m.template topLeftCorner<4, 4>() = Ra;
  m.template bottomLeftCorner<4, 4>() = Rc;
  m.template bottomRightCorner<4, 4>() = Ra;
  return m;
}

}  // namespace soma
