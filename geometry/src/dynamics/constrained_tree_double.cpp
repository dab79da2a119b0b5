// Explicit instantiation of ConstrainedTree (GF §14.2–14.3) for double (one scalar per TU: compile time).
#include "soma/geometry/dynamics/constrained_tree_impl.hpp"

namespace soma {
template class ConstrainedTree<double>;
template DynVector<double> minimumNormSolve<double>(const DynMatrix<double>&, const DynVector<double>&, int*);
template DynMatrix<double> nullSpace<double>(const DynMatrix<double>&);
}  // namespace soma
