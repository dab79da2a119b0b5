// Explicit instantiations of Regulus for the five scalars (DESIGN §2).
#include "soma/geometry/lines/regulus.hpp"

namespace soma {
template class Regulus<float>;
template class Regulus<double>;
template class Regulus<long double>;
template class Regulus<__float128>;
template class Regulus<mpfr::mpreal>;
}  // namespace soma
