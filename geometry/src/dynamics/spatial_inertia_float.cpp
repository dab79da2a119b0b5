// Explicit instantiation of the 6×6 screw formulation for float (one scalar per TU: compile time).
#include "soma/geometry/dynamics/spatial_inertia.hpp"

namespace soma {
template class SpatialInertia<float>;
template SE3Tangent<float> rigidBodyAcceleration<float>(const Mat6<float>&, const SE3Tangent<float>&, const Vec6<float>&);
}  // namespace soma
