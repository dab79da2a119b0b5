// Explicit instantiation of hybrid_control (GF ch. 15) for __float128 (one scalar per TU: compile time).
#include "hybrid_control_impl.hpp"

namespace soma {
SOMA_HYBRID_CONTROL_INST(__float128)
}  // namespace soma
