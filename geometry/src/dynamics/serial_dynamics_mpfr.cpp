// Explicit instantiation of SerialDynamics (GF §13.2–13.5) for mpfr::mpreal (one scalar per TU: compile time).
#include "soma/geometry/dynamics/serial_dynamics_impl.hpp"

namespace soma {
template class SerialDynamics<mpfr::mpreal>;
}  // namespace soma
