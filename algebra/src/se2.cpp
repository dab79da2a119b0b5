// Explicit instantiation of SE(2) for the five scalars (extern template in se2.hpp).
#include "soma/algebra/se2.hpp"

namespace soma {
#define SOMA_SE2_INSTANTIATE(T)      \
  template class SE2Tangent<T>;      \
  template class SE2<T>;
SOMA_FOR_EACH_SCALAR(SOMA_SE2_INSTANTIATE)
#undef SOMA_SE2_INSTANTIATE
}  // namespace soma
