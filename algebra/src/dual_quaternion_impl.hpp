// Explicit instantiations of DualQuaternion and StudyParameters for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/algebra/study_parameters.hpp"

namespace soma {
#define SOMA_INSTANTIATE_DUAL_QUATERNION(S)        \
  template class DualQuaternion<S>;   \
  template class StudyParameters<S>;
}  // namespace soma
