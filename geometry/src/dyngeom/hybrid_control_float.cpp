// Explicit instantiation of hybrid_control (GF ch. 15) for float (one scalar per TU: compile time).
#include "hybrid_control_impl.hpp"

namespace soma {
SOMA_HYBRID_CONTROL_INST(float)
}  // namespace soma
