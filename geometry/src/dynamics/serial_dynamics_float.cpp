// Explicit instantiation of SerialDynamics (GF §13.2–13.5) for float (one scalar per TU: compile time).
#include "soma/geometry/dynamics/serial_dynamics_impl.hpp"

namespace soma {
template class SerialDynamics<float>;
}  // namespace soma
