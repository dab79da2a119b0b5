// Explicit instantiations of the Euclidean operations by contraction (GF §10.2.4): perpendiculars,
// angles, distances, projections, reflections and the common perpendicular.
#pragma once
#include "soma/geometry/pga/angle.hpp"
#include "soma/geometry/pga/common_perpendicular.hpp"
#include "soma/geometry/pga/distance.hpp"
#include "soma/geometry/pga/projection.hpp"
#include "soma/geometry/pga/reflection.hpp"

namespace soma::pga {
#define SOMA_INSTANTIATE_METRIC(S) namespace pga { \
  template Plane<S> perpendicularPlane(const Plane<S>&, const Line<S>&); \
  template Line<S> perpendicularLine(const Plane<S>&, const Point<S>&);  \
  template Plane<S> perpendicularPlane(const Line<S>&, const Point<S>&); \
  template S angle(const Plane<S>&, const Plane<S>&);                    \
  template S angle(const Line<S>&, const Line<S>&);                      \
  template S angle(const Line<S>&, const Plane<S>&);                     \
  template S signedDistance(const Point<S>&, const Plane<S>&);           \
  template S distance(const Point<S>&, const Line<S>&);                  \
  template S distance(const Point<S>&, const Point<S>&);                 \
  template S distance(const Line<S>&, const Line<S>&);                   \
  template Point<S> project(const Point<S>&, const Plane<S>&);           \
  template Point<S> project(const Point<S>&, const Line<S>&);            \
  template Line<S> project(const Line<S>&, const Plane<S>&);             \
  template Plane<S> reflect(const Plane<S>&, const Plane<S>&);           \
  template Point<S> reflect(const Point<S>&, const Plane<S>&);           \
  template Line<S> reflect(const Line<S>&, const Plane<S>&);             \
  template Line<S> commonPerpendicular(const Line<S>&, const Line<S>&); }
}  // namespace soma::pga
