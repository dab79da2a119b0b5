// Explicit instantiation of the 6×6 screw formulation for one scalar (the rule: cmake/SomaInstantiate.cmake).
#pragma once
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#define SOMA_INSTANTIATE_SPATIAL_INERTIA(S) \
  template class SpatialInertia<S>;         \
  template SE3Tangent<S> rigidBodyAcceleration<S>(const Mat6<S>&, const SE3Tangent<S>&, const Vec6<S>&);
