// Explicit instantiations of SE3Tangent / SE3 for the five scalars (DESIGN §2).
#include "soma/algebra/se3.hpp"

namespace soma {
#define SOMA_SE3_INSTANTIATE(S)      \
  template class SE3Tangent<S>;      \
  template class SE3<S>;
SOMA_FOR_EACH_SCALAR(SOMA_SE3_INSTANTIATE)
#undef SOMA_SE3_INSTANTIATE
}  // namespace soma
