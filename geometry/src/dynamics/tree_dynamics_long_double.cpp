// Explicit instantiation of TreeDynamics (GF §14.1) for long double (one scalar per TU: compile time).
#include "soma/geometry/dynamics/tree_dynamics_impl.hpp"

namespace soma {
template class TreeDynamics<long double>;
template Eigen::Matrix<long double, 3, 3> planarInertia<long double>(const long double&, const long double&, const long double&, const long double&);
template Mat6<long double> planarBodyInertia<long double>(const long double&, const long double&, const long double&, const long double&);
}  // namespace soma
