// Explicit instantiation of TreeDynamics (GF §14.1) for float (one scalar per TU: compile time).
#include "soma/geometry/dynamics/tree_dynamics_impl.hpp"

namespace soma {
template class TreeDynamics<float>;
template Eigen::Matrix<float, 3, 3> planarInertia<float>(const float&, const float&, const float&, const float&);
template Mat6<float> planarBodyInertia<float>(const float&, const float&, const float&, const float&);
}  // namespace soma
