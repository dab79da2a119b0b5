// Explicit instantiation of TreeDynamics (GF §14.1) for double (one scalar per TU: compile time).
#include "soma/geometry/dynamics/tree_dynamics_impl.hpp"

namespace soma {
template class TreeDynamics<double>;
template Eigen::Matrix<double, 3, 3> planarInertia<double>(const double&, const double&, const double&, const double&);
template Mat6<double> planarBodyInertia<double>(const double&, const double&, const double&, const double&);
}  // namespace soma
