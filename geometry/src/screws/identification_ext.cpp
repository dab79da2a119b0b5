// Explicit instantiations of the screw-system identification for __float128 and mpreal.
#define SOMA_SCREW_IDENTIFICATION_IMPL
#include "soma/geometry/screws/identification.hpp"

namespace soma {

#define SOMA_SCREW_ID_INSTANTIATE(S)                                                              \
  template ScrewBasis<S> screwSystemNormalForm<S>(ScrewSystemType, const std::array<S, 3>&);      \
  template ScrewSystemIdentification<S> identifyScrewSystem<S>(const ScrewSystem<S>&);            \
  template struct ScrewSystemIdentification<S>;
SOMA_SCREW_ID_INSTANTIATE(__float128)
SOMA_SCREW_ID_INSTANTIATE(mpfr::mpreal)
#undef SOMA_SCREW_ID_INSTANTIATE

}  // namespace soma
