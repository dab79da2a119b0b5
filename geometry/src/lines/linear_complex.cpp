// Explicit instantiations of LinearComplex for the five scalars (DESIGN §2).
#include "soma/geometry/lines/linear_complex.hpp"

namespace soma {
template class LinearComplex<float>;
template class LinearComplex<double>;
template class LinearComplex<long double>;
template class LinearComplex<__float128>;
template class LinearComplex<mpfr::mpreal>;
}  // namespace soma
