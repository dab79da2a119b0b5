// Explicit instantiations of the screw-axis helpers for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/geometry/lines/screw_axis.hpp"

namespace soma {
#define SOMA_INSTANTIATE_SCREW_AXIS(S)                            \
  template S screwPitch<S>(const Vec6<S>&);                       \
  template ScrewAxis<S> screwAxis<S>(const Vec6<S>&);             \
  template Vec6<S> screwFromAxis<S>(const PluckerLine<S>&, const S&, const S&);
}  // namespace soma
