// Explicit instantiation of ConstrainedTree (GF §14.2–14.3) for long double (one scalar per TU: compile time).
#include "soma/geometry/dynamics/constrained_tree_impl.hpp"

namespace soma {
template class ConstrainedTree<long double>;
template DynVector<long double> minimumNormSolve<long double>(const DynMatrix<long double>&, const DynVector<long double>&, int*);
template DynMatrix<long double> nullSpace<long double>(const DynMatrix<long double>&);
}  // namespace soma
