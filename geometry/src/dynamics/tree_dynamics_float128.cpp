// Explicit instantiation of TreeDynamics (GF §14.1) for __float128 (one scalar per TU: compile time).
#include "soma/geometry/dynamics/tree_dynamics_impl.hpp"

namespace soma {
template class TreeDynamics<__float128>;
template Eigen::Matrix<__float128, 3, 3> planarInertia<__float128>(const __float128&, const __float128&, const __float128&, const __float128&);
template Mat6<__float128> planarBodyInertia<__float128>(const __float128&, const __float128&, const __float128&, const __float128&);
}  // namespace soma
