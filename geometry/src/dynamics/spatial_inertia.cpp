// Explicit instantiations of the 6×6 screw formulation for the five scalars (DESIGN §2).
#include "soma/geometry/dynamics/spatial_inertia.hpp"

namespace soma {
#define SOMA_SPATIAL_INERTIA_INSTANTIATE(S) \
  template class SpatialInertia<S>;         \
  template SE3Tangent<S> rigidBodyAcceleration<S>(const Mat6<S>&, const SE3Tangent<S>&, const Vec6<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_SPATIAL_INERTIA_INSTANTIATE)
#undef SOMA_SPATIAL_INERTIA_INSTANTIATE
}  // namespace soma
