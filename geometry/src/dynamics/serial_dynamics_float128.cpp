// Explicit instantiation of SerialDynamics (GF §13.2–13.5) for __float128 (one scalar per TU: compile time).
#include "soma/geometry/dynamics/serial_dynamics_impl.hpp"

namespace soma {
template class SerialDynamics<__float128>;
}  // namespace soma
