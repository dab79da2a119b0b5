// One scalar per translation unit (they compile in parallel): parallel/stewart.hpp for mpfr::mpreal.
#include "stewart_impl.hpp"

namespace soma {
SOMA_STEWART_INSTANTIATE(mpfr::mpreal)
}  // namespace soma
