// Explicit instantiation of hybrid_control (GF ch. 15) for long double (one scalar per TU: compile time).
#include "hybrid_control_impl.hpp"

namespace soma {
SOMA_HYBRID_CONTROL_INST(long double)
}  // namespace soma
