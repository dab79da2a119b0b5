// Explicit instantiations of Line and the two-line relations for one scalar (soma_instantiate) (DESIGN §2).
#pragma once
#include "soma/geometry/lines/line.hpp"

namespace soma {
#define SOMA_INSTANTIATE_LINE(S)                                          \
  template class Line<S>;                                                 \
  template LineRelation<S> relation<S>(const Line<S>&, const Line<S>&);   \
  template S distance<S>(const Line<S>&, const Line<S>&);                 \
  template S angle<S>(const Line<S>&, const Line<S>&);                    \
  template bool meet<S>(const Line<S>&, const Line<S>&, const S&);
}  // namespace soma
