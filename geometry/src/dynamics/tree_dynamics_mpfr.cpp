// Explicit instantiation of TreeDynamics (GF §14.1) for mpfr::mpreal (one scalar per TU: compile time).
#include "soma/geometry/dynamics/tree_dynamics_impl.hpp"

namespace soma {
template class TreeDynamics<mpfr::mpreal>;
template Eigen::Matrix<mpfr::mpreal, 3, 3> planarInertia<mpfr::mpreal>(const mpfr::mpreal&, const mpfr::mpreal&, const mpfr::mpreal&, const mpfr::mpreal&);
template Mat6<mpfr::mpreal> planarBodyInertia<mpfr::mpreal>(const mpfr::mpreal&, const mpfr::mpreal&, const mpfr::mpreal&, const mpfr::mpreal&);
}  // namespace soma
