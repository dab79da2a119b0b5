// One scalar per translation unit (they compile in parallel): parallel/stewart.hpp for float.
#include "stewart_impl.hpp"

namespace soma {
SOMA_STEWART_INSTANTIATE(float)
}  // namespace soma
