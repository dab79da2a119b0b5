// Closed-form IK instantiated for mpfr::mpreal (see closed_form_ik_impl.hpp).
#include "closed_form_ik_impl.hpp"

namespace soma {
SOMA_CFIK_INSTANTIATE(mpfr::mpreal)
}  // namespace soma
