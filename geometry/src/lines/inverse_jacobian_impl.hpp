// Explicit instantiations of the §6.7 reciprocal-screw inverse Jacobian (DESIGN §2).
#pragma once
#include "soma/geometry/lines/inverse_jacobian.hpp"

namespace soma {
#define SOMA_INSTANTIATE_INVERSE_JACOBIAN(S)                                                             \
  template struct PumaLikeArm<S>;                                                           \
  template std::array<Vec6<S>, 6> pumaLikeReciprocalLines<S>(const PumaLikeArm<S>&);        \
  template Mat6<S> inverseJacobianFromReciprocals<S>(const Mat6<S>&, const std::array<Vec6<S>, 6>&);
}  // namespace soma
