// Explicit instantiation of pga::Motor (GF §9.2–9.3) for one scalar (soma_instantiate).
#pragma once
#include "soma/geometry/pga/motor.hpp"

namespace soma::pga {
#define SOMA_INSTANTIATE_MOTOR(S) namespace pga { template class Motor<S>; }
}  // namespace soma::pga
