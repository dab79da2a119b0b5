// Explicit instantiation of geodesic_control (GF ch. 15) for long double (one scalar per TU: compile time).
#include "geodesic_control_impl.hpp"

namespace soma {
SOMA_GEODESIC_CONTROL_INST(long double)
}  // namespace soma
