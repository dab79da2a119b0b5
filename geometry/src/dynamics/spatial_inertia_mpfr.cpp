// Explicit instantiation of the 6×6 screw formulation for mpfr::mpreal (one scalar per TU: compile time).
#include "soma/geometry/dynamics/spatial_inertia.hpp"

namespace soma {
template class SpatialInertia<mpfr::mpreal>;
template SE3Tangent<mpfr::mpreal> rigidBodyAcceleration<mpfr::mpreal>(const Mat6<mpfr::mpreal>&, const SE3Tangent<mpfr::mpreal>&, const Vec6<mpfr::mpreal>&);
}  // namespace soma
