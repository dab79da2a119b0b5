// Explicit instantiation of ConstrainedTree (GF §14.2–14.3) for __float128 (one scalar per TU: compile time).
#include "soma/geometry/dynamics/constrained_tree_impl.hpp"

namespace soma {
template class ConstrainedTree<__float128>;
template DynVector<__float128> minimumNormSolve<__float128>(const DynMatrix<__float128>&, const DynVector<__float128>&, int*);
template DynMatrix<__float128> nullSpace<__float128>(const DynMatrix<__float128>&);
}  // namespace soma
