// Explicit instantiations of the meets, joins and incidence tests (GF §10.2.1–10.2.3).
#pragma once
#include "soma/geometry/pga/incidence.hpp"

namespace soma::pga {
#define SOMA_INSTANTIATE_MEET_JOIN(S) namespace pga { \
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
  template S coplanarityResidual(const Point<S>&, const Point<S>&, const Point<S>&, const Point<S>&); }
}  // namespace soma::pga
