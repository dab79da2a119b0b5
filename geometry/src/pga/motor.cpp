// Explicit instantiation of pga::Motor (GF §9.2–9.3) for the five scalars.
#include "soma/geometry/pga/motor.hpp"

namespace soma::pga {
#define SOMA_PGA_MOTOR(S) template class Motor<S>;
SOMA_FOR_EACH_SCALAR(SOMA_PGA_MOTOR)
#undef SOMA_PGA_MOTOR
}  // namespace soma::pga
