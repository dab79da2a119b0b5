// Explicit instantiation of the 6×6 screw formulation for __float128 (one scalar per TU: compile time).
#include "soma/geometry/dynamics/spatial_inertia.hpp"

namespace soma {
template class SpatialInertia<__float128>;
template SE3Tangent<__float128> rigidBodyAcceleration<__float128>(const Mat6<__float128>&, const SE3Tangent<__float128>&, const Vec6<__float128>&);
}  // namespace soma
