// Explicit instantiations of DualQuaternion and StudyParameters for the five scalars (DESIGN §2).
#include "soma/algebra/study_parameters.hpp"

namespace soma {
#define SOMA_DQ_INSTANTIATE(S)        \
  template class DualQuaternion<S>;   \
  template class StudyParameters<S>;
SOMA_FOR_EACH_SCALAR(SOMA_DQ_INSTANTIATE)
#undef SOMA_DQ_INSTANTIATE
}  // namespace soma
