// Explicit instantiations of the Cl(0,3,1) elements Plane, Point, Line (GF §10.1) for the five
// scalars (DESIGN §2).
#include "soma/geometry/pga/line.hpp"
#include "soma/geometry/pga/plane.hpp"
#include "soma/geometry/pga/point.hpp"

namespace soma::pga {
#define SOMA_PGA_ELEMENTS(S) \
  template class Plane<S>;   \
  template class Point<S>;   \
  template class Line<S>;
SOMA_FOR_EACH_SCALAR(SOMA_PGA_ELEMENTS)
#undef SOMA_PGA_ELEMENTS
}  // namespace soma::pga
