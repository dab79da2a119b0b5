#pragma once
// A small dense linear program (two-phase simplex, Bland's rule): minimise cᵀx subject to
// A x = b, x ≥ 0. Used by the grasp tests of GF §12.5–12.6 (positive spanning, form closure),
// which are linear programs of a few dozen variables. Thresholds from Tolerance::rank() scaled by
// the largest entry of the data.
#include "soma/algebra/scalar.hpp"

#include <Eigen/Core>

namespace soma {

template <class S> struct LinearProgramResult {
  enum class Status { Optimal, Infeasible, Unbounded };
  Status status = Status::Infeasible;
  S value = S(0);                                ///< cᵀx at the optimum
  Eigen::Matrix<S, Eigen::Dynamic, 1> x;         ///< an optimal vertex
  int pivots = 0;
};

/// GF §12.6 (the polyhedral approximation turns grasping into linear programs),
/// GF-12.6-polyhedral-approximation. InvalidInput on mismatched sizes or non-finite data.
template <class S>
LinearProgramResult<S> minimiseLinearProgram(const Eigen::Matrix<S, Eigen::Dynamic, 1>& c,
                                             const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>& A,
                                             const Eigen::Matrix<S, Eigen::Dynamic, 1>& b);

}  // namespace soma
