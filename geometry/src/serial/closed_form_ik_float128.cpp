// Closed-form IK instantiated for __float128 (see closed_form_ik_impl.hpp).
#include "closed_form_ik_impl.hpp"

namespace soma {
SOMA_CFIK_INSTANTIATE(__float128)
}  // namespace soma
