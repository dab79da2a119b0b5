// One scalar per translation unit (they compile in parallel): parallel/stewart.hpp for long double.
#include "stewart_impl.hpp"

namespace soma {
SOMA_STEWART_INSTANTIATE(long double)
}  // namespace soma
