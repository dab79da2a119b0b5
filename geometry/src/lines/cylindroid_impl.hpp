// Explicit instantiations of Cylindroid for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/geometry/lines/cylindroid.hpp"

namespace soma {
#define SOMA_INSTANTIATE_CYLINDROID(S) template class Cylindroid<S>;
}  // namespace soma
