// Explicit instantiations of Line and the two-line relations for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/geometry/lines/line.hpp"

namespace soma {
#define SOMA_INSTANTIATE_LINE(S)                                          \
  template class PluckerLine<S>;                                                 \
  template LineRelation<S> relation<S>(const PluckerLine<S>&, const PluckerLine<S>&);   \
  template S distance<S>(const PluckerLine<S>&, const PluckerLine<S>&);                 \
  template S angle<S>(const PluckerLine<S>&, const PluckerLine<S>&);                    \
  template bool meet<S>(const PluckerLine<S>&, const PluckerLine<S>&, const S&);
}  // namespace soma
