// Explicit instantiation of the statics sub-area (GF ch. 12) for one scalar (the rule:
// cmake/SomaInstantiate.cmake; the templates live in the other *_impl.hpp files of this directory).
#pragma once
#include "grasp_impl.hpp"
#include "linear_program_impl.hpp"
#include "robot_statics_impl.hpp"
#include "wrist_sensor_impl.hpp"

#define SOMA_INSTANTIATE_STATICS(S) \
  template class Wrench<S>;         \
  SOMA_STATICS_SENSOR_INST(S)       \
  SOMA_STATICS_ROBOT_INST(S)        \
  SOMA_STATICS_LP_INST(S)           \
  SOMA_STATICS_GRASP_INST(S)
