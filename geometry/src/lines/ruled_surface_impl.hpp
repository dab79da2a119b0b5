// Explicit instantiations of RuledSurface and the dual-vector line helpers (DESIGN §2).
#pragma once
#include "soma/geometry/lines/ruled_surface.hpp"

namespace soma {
#define SOMA_INSTANTIATE_RULED_SURFACE(S)                                          \
  template class RuledSurface<S>;                                          \
  template DualNumber<S> dualAngle<S>(const PluckerLine<S>&, const PluckerLine<S>&);     \
  template PluckerLine<S> commonPerpendicularDual<S>(const PluckerLine<S>&, const PluckerLine<S>&);
}  // namespace soma
