// Explicit instantiations of ScrewSystem and its set operations for __float128 and mpreal (DESIGN §2).
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
SOMA_SCREW_SYSTEM_INSTANTIATE(__float128)
SOMA_SCREW_SYSTEM_INSTANTIATE(mpfr::mpreal)
#undef SOMA_SCREW_SYSTEM_INSTANTIATE
}  // namespace soma
