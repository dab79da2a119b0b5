// Explicit instantiation of mobility (GF ch. 15) for long double (one scalar per TU: compile time).
#include "mobility_impl.hpp"

namespace soma {
SOMA_MOBILITY_INST(long double)
}  // namespace soma
