#pragma once
// The quadratic elements of se(3) in a representation (GF §7.5): with J_a = L(ω_a), P_a = L(v_a),
//   P_t = Σ P_a J_a  (the book's P₃J₃ + ½P₊J₋ + ½P₋J₊)  and  Σ P_a²  commute with every L(s):
//   the two Casimirs of se(3);
//   J_t = Σ J_a²     (the book's J₃² + ½J₊J₋ + ½J₋J₊) is the Casimir of so(3) only: it commutes
//   with the translations in the adjoint representation (J_t = −2·1) but not in the 4×4 one.
// The book says both J_t and P_t commute with all of se(3) and that Tr(X P_t Y) is the reciprocal
// product (erratum E7.6: in the 4×4 and adjoint representations Tr(X P_t Y) ≡ 0); the invariant
// forms that do work are in se3_invariant_forms.hpp.
#include "soma/algebra/rep/se3_representations.hpp"

namespace soma::rep {

template <class T> struct Se3QuadraticElements {
  Matrix<T> mixed;              ///< P_t = Σ P_a J_a (Casimir)
  Matrix<T> translationSquare;  ///< Σ P_a² (Casimir)
  Matrix<T> rotationSquare;     ///< J_t = Σ J_a² (so(3) Casimir; not an se(3) Casimir in general)
};

/// P_t, Σ P_a², J_t of a representation given by its generators.
// GF §7.5, GF-7.5-casimirs-and-pitch (corrected, erratum E7.6)
template <class T> Se3QuadraticElements<T> se3QuadraticElements(const Se3Generators<T>& gen) {
  const Eigen::Index n = gen[0].rows();
  Se3QuadraticElements<T> q{Matrix<T>::Zero(n, n), Matrix<T>::Zero(n, n), Matrix<T>::Zero(n, n)};
  for (std::size_t a = 0; a < 3; ++a) {
    q.mixed += gen[a + 3] * gen[a];
    q.translationSquare += gen[a + 3] * gen[a + 3];
    q.rotationSquare += gen[a] * gen[a];
  }
  return q;
}

}  // namespace soma::rep
