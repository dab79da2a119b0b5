// Explicit instantiations of the screw-axis helpers for the five scalars (DESIGN §2).
#include "soma/geometry/lines/screw_axis.hpp"

namespace soma {
#define SOMA_SCREW_AXIS_INSTANTIATE(S)                            \
  template S screwPitch<S>(const Vec6<S>&);                       \
  template ScrewAxis<S> screwAxis<S>(const Vec6<S>&);             \
  template Vec6<S> screwFromAxis<S>(const Line<S>&, const S&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_SCREW_AXIS_INSTANTIATE)
#undef SOMA_SCREW_AXIS_INSTANTIATE
}  // namespace soma
