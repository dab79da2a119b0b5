// Explicit instantiations of SE3Tangent / SE3 for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/algebra/se3.hpp"

namespace soma {
#define SOMA_INSTANTIATE_SE3(S)      \
  template class SE3Tangent<S>;      \
  template class SE3<S>;
}  // namespace soma
