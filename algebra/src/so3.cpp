// Explicit instantiations of SO3Tangent / SO3 for the five scalars (DESIGN §2).
#include "soma/algebra/so3.hpp"

namespace soma {
#define SOMA_SO3_INSTANTIATE(S)      \
  template class SO3Tangent<S>;      \
  template class SO3<S>;
SOMA_FOR_EACH_SCALAR(SOMA_SO3_INSTANTIATE)
#undef SOMA_SO3_INSTANTIATE
}  // namespace soma
