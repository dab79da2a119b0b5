// Explicit instantiations of Cylindroid for the five scalars (DESIGN §2).
#include "soma/geometry/lines/cylindroid.hpp"

namespace soma {
template class Cylindroid<float>;
template class Cylindroid<double>;
template class Cylindroid<long double>;
template class Cylindroid<__float128>;
template class Cylindroid<mpfr::mpreal>;
}  // namespace soma
