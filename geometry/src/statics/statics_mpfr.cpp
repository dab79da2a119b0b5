// Explicit instantiation of the statics sub-area (GF ch. 12) for mpfr::mpreal: one scalar per TU
// (compile time; the templates live in the *_impl.hpp files of this directory).
#include "grasp_impl.hpp"
#include "linear_program_impl.hpp"
#include "robot_statics_impl.hpp"
#include "wrist_sensor_impl.hpp"

namespace soma {
template class Wrench<mpfr::mpreal>;
SOMA_STATICS_SENSOR_INST(mpfr::mpreal)
SOMA_STATICS_ROBOT_INST(mpfr::mpreal)
SOMA_STATICS_LP_INST(mpfr::mpreal)
SOMA_STATICS_GRASP_INST(mpfr::mpreal)
}  // namespace soma
