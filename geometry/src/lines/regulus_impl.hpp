// Explicit instantiations of Regulus for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/geometry/lines/regulus.hpp"

namespace soma {
#define SOMA_INSTANTIATE_REGULUS(S) template class Regulus<S>;
}  // namespace soma
