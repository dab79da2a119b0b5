// One scalar per translation unit (they compile in parallel): parallel/stewart.hpp for __float128.
#include "stewart_impl.hpp"

namespace soma {
SOMA_STEWART_INSTANTIATE(__float128)
}  // namespace soma
