// Explicit instantiation of mobility (GF ch. 15) for __float128 (one scalar per TU: compile time).
#include "mobility_impl.hpp"

namespace soma {
SOMA_MOBILITY_INST(__float128)
}  // namespace soma
