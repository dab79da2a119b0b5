// Explicit instantiation of mobility (GF ch. 15) for mpfr::mpreal (one scalar per TU: compile time).
#include "mobility_impl.hpp"

namespace soma {
SOMA_MOBILITY_INST(mpfr::mpreal)
}  // namespace soma
