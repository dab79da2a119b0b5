// Explicit instantiations of the Cl(0,3,1) elements Plane, Point, Line (GF §10.1) for the five
// scalars (DESIGN §2).
#pragma once
#include "soma/geometry/pga/line.hpp"
#include "soma/geometry/pga/plane.hpp"
#include "soma/geometry/pga/point.hpp"

namespace soma::pga {
#define SOMA_INSTANTIATE_ELEMENTS(S) namespace pga { \
  template class Plane<S>;   \
  template class Point<S>;   \
  template class Line<S>; }
}  // namespace soma::pga
