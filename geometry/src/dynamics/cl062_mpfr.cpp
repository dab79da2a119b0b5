// Explicit instantiation of SB's Cl(0,6,2) dynamics for mpfr::mpreal (one scalar per TU: compile time).
#include "soma/geometry/dynamics/cl062_impl.hpp"

namespace soma::cl062 {
SOMA_CL062_INSTANTIATE(mpfr::mpreal)
}  // namespace soma::cl062
