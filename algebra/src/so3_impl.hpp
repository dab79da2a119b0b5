// Explicit instantiations of SO3Tangent / SO3 for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/algebra/so3.hpp"

namespace soma {
#define SOMA_INSTANTIATE_SO3(S)      \
  template class SO3Tangent<S>;      \
  template class SO3<S>;
}  // namespace soma
