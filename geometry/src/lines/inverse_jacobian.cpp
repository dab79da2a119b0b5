// Explicit instantiations of the §6.7 reciprocal-screw inverse Jacobian (DESIGN §2).
#include "soma/geometry/lines/inverse_jacobian.hpp"

namespace soma {
#define SOMA_INVJ_INSTANTIATE(S)                                                             \
  template struct PumaLikeArm<S>;                                                           \
  template std::array<Vec6<S>, 6> pumaLikeReciprocalLines<S>(const PumaLikeArm<S>&);        \
  template Mat6<S> inverseJacobianFromReciprocals<S>(const Mat6<S>&, const std::array<Vec6<S>, 6>&);
SOMA_FOR_EACH_SCALAR(SOMA_INVJ_INSTANTIATE)
#undef SOMA_INVJ_INSTANTIATE
}  // namespace soma
