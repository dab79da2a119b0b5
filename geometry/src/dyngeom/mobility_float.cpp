// Explicit instantiation of mobility (GF ch. 15) for float (one scalar per TU: compile time).
#include "mobility_impl.hpp"

namespace soma {
SOMA_MOBILITY_INST(float)
}  // namespace soma
