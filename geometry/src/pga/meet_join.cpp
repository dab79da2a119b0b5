// Explicit instantiations of the meets, joins and incidence tests (GF §10.2.1–10.2.3).
#include "soma/geometry/pga/incidence.hpp"

namespace soma::pga {
#define SOMA_PGA_MEET_JOIN(S)                                                              \
  template Line<S> meet(const Plane<S>&, const Plane<S>&);                                 \
  template Point<S> meet(const Line<S>&, const Plane<S>&);                                 \
  template Point<S> meet(const Plane<S>&, const Plane<S>&, const Plane<S>&);               \
  template Line<S> join(const Point<S>&, const Point<S>&);                                 \
  template Plane<S> join(const Point<S>&, const Line<S>&);                                 \
  template Plane<S> join(const Point<S>&, const Point<S>&, const Point<S>&);               \
  template S incidenceResidual(const Point<S>&, const Plane<S>&);                          \
  template S incidenceResidual(const Line<S>&, const Plane<S>&);                           \
  template S incidenceResidual(const Point<S>&, const Line<S>&);                           \
  template S coplanarityResidual(const Line<S>&, const Line<S>&);                          \
  template S collinearityResidual(const Point<S>&, const Point<S>&, const Point<S>&);      \
  template S coplanarityResidual(const Point<S>&, const Point<S>&, const Point<S>&, const Point<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_PGA_MEET_JOIN)
#undef SOMA_PGA_MEET_JOIN
}  // namespace soma::pga
