// Closed-form IK instantiated for float (see closed_form_ik_impl.hpp).
#include "closed_form_ik_impl.hpp"

namespace soma {
SOMA_CFIK_INSTANTIATE(float)
}  // namespace soma
