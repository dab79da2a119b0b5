// Explicit instantiation of ConstrainedTree (GF §14.2–14.3) for float (one scalar per TU: compile time).
#include "soma/geometry/dynamics/constrained_tree_impl.hpp"

namespace soma {
template class ConstrainedTree<float>;
template DynVector<float> minimumNormSolve<float>(const DynMatrix<float>&, const DynVector<float>&, int*);
template DynMatrix<float> nullSpace<float>(const DynMatrix<float>&);
}  // namespace soma
