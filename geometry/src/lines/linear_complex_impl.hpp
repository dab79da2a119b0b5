// Explicit instantiations of LinearComplex for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/geometry/lines/linear_complex.hpp"

namespace soma {
#define SOMA_INSTANTIATE_LINEAR_COMPLEX(S) template class LinearComplex<S>;
}  // namespace soma
