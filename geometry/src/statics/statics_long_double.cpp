// Explicit instantiation of the statics sub-area (GF ch. 12) for long double: one scalar per TU
// (compile time; the templates live in the *_impl.hpp files of this directory).
#include "grasp_impl.hpp"
#include "linear_program_impl.hpp"
#include "robot_statics_impl.hpp"
#include "wrist_sensor_impl.hpp"

namespace soma {
template class Wrench<long double>;
SOMA_STATICS_SENSOR_INST(long double)
SOMA_STATICS_ROBOT_INST(long double)
SOMA_STATICS_LP_INST(long double)
SOMA_STATICS_GRASP_INST(long double)
}  // namespace soma
