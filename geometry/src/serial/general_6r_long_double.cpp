// Explicit instantiation of the general-6R solver for long double (GF §11.5). One TU per scalar:
// the eigen solvers are the heaviest templates of soma/geometry.
#include "soma/geometry/serial/general_6r_impl.hpp"

namespace soma {
SOMA_GENERAL6R_INSTANTIATE(long double)
}  // namespace soma
