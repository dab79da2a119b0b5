// Explicit instantiations of ScrewSystem and its set operations for float, double, long double
// (__float128 and mpreal in screw_system_ext.cpp: one TU for all five took 56 s).
#define SOMA_SCREW_SYSTEM_IMPL
#include "soma/geometry/screws/screw_system.hpp"

namespace soma {
#define SOMA_SCREW_SYSTEM_INSTANTIATE(S)                                                  \
  template class ScrewSystem<S>;                                                          \
  template ScrewSystem<S> unionOf<S>(const ScrewSystem<S>&, const ScrewSystem<S>&);       \
  template ScrewSystem<S> intersectionOf<S>(const ScrewSystem<S>&, const ScrewSystem<S>&); \
  template ScrewSystem<S> isotropyAlgebra<S>(const ScrewSystem<S>&);                      \
  template ScrewSystem<S> completion<S>(const ScrewSystem<S>&, std::vector<int>*);        \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> wedge<S>(const ScrewMatX<S>&);             \
  template ScrewBasis<S> orthogonalComplement<S>(const ScrewBasis<S>&);
SOMA_SCREW_SYSTEM_INSTANTIATE(float)
SOMA_SCREW_SYSTEM_INSTANTIATE(double)
SOMA_SCREW_SYSTEM_INSTANTIATE(long double)
#undef SOMA_SCREW_SYSTEM_INSTANTIATE
}  // namespace soma
