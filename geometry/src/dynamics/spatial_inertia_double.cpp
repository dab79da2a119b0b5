// Explicit instantiation of the 6×6 screw formulation for double (one scalar per TU: compile time).
#include "soma/geometry/dynamics/spatial_inertia.hpp"

namespace soma {
template class SpatialInertia<double>;
template SE3Tangent<double> rigidBodyAcceleration<double>(const Mat6<double>&, const SE3Tangent<double>&, const Vec6<double>&);
}  // namespace soma
