// Explicit instantiations of RuledSurface and the dual-vector line helpers (DESIGN §2).
#include "soma/geometry/lines/ruled_surface.hpp"

namespace soma {
#define SOMA_RULED_INSTANTIATE(S)                                          \
  template class RuledSurface<S>;                                          \
  template DualNumber<S> dualAngle<S>(const Line<S>&, const Line<S>&);     \
  template Line<S> commonPerpendicularDual<S>(const Line<S>&, const Line<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_RULED_INSTANTIATE)
#undef SOMA_RULED_INSTANTIATE
}  // namespace soma
