// Explicit instantiation of SE(2) for one scalar (soma_instantiate) (extern template in se2.hpp).
#pragma once
#include "soma/algebra/se2.hpp"

namespace soma {
#define SOMA_INSTANTIATE_SE2(T)      \
  template class SE2Tangent<T>;      \
  template class SE2<T>;
}  // namespace soma
