// Explicit instantiation of ConstrainedTree (GF §14.2–14.3) for mpfr::mpreal (one scalar per TU: compile time).
#include "soma/geometry/dynamics/constrained_tree_impl.hpp"

namespace soma {
template class ConstrainedTree<mpfr::mpreal>;
template DynVector<mpfr::mpreal> minimumNormSolve<mpfr::mpreal>(const DynMatrix<mpfr::mpreal>&, const DynVector<mpfr::mpreal>&, int*);
template DynMatrix<mpfr::mpreal> nullSpace<mpfr::mpreal>(const DynMatrix<mpfr::mpreal>&);
}  // namespace soma
