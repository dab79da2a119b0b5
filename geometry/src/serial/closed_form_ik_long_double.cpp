// Closed-form IK instantiated for long double (see closed_form_ik_impl.hpp).
#include "closed_form_ik_impl.hpp"

namespace soma {
SOMA_CFIK_INSTANTIATE(long double)
}  // namespace soma
