// Explicit instantiations of Line and the two-line relations for the five scalars (DESIGN §2).
#include "soma/geometry/lines/line.hpp"

namespace soma {
#define SOMA_LINE_INSTANTIATE(S)                                          \
  template class Line<S>;                                                 \
  template LineRelation<S> relation<S>(const Line<S>&, const Line<S>&);   \
  template S distance<S>(const Line<S>&, const Line<S>&);                 \
  template S angle<S>(const Line<S>&, const Line<S>&);                    \
  template bool meet<S>(const Line<S>&, const Line<S>&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_LINE_INSTANTIATE)
#undef SOMA_LINE_INSTANTIATE
}  // namespace soma
