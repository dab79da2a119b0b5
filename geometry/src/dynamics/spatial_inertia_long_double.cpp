// Explicit instantiation of the 6×6 screw formulation for long double (one scalar per TU: compile time).
#include "soma/geometry/dynamics/spatial_inertia.hpp"

namespace soma {
template class SpatialInertia<long double>;
template SE3Tangent<long double> rigidBodyAcceleration<long double>(const Mat6<long double>&, const SE3Tangent<long double>&, const Vec6<long double>&);
}  // namespace soma
