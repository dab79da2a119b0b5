#pragma once
// Two-phase dense simplex with Bland's rule (no cycling). GF §12.6, GF-12.6-polyhedral-approximation
#include "soma/geometry/statics/linear_program.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"

#include <algorithm>
#include <vector>

namespace soma {
namespace {

template <class S> using LpMat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

template <class S> void pivot(LpMat<S>& T, std::vector<Eigen::Index>& basis, Eigen::Index r, Eigen::Index e) {
  T.row(r) /= T(r, e);
  for (Eigen::Index i = 0; i < T.rows(); ++i)
    if (i != r && T(i, e) != S(0)) T.row(i) -= T(i, e) * T.row(r);
  basis[std::size_t(r)] = e;
}

/// Bland's rule on the columns [0, ncols); the objective row is the last; returns false when
/// unbounded.
template <class S> bool runSimplex(LpMat<S>& T, std::vector<Eigen::Index>& basis, Eigen::Index ncols,
                                   const S& tol, int& pivots) {
  const Eigen::Index m = T.rows() - 1, last = T.cols() - 1;
  const int maxPivots = 64 * int(T.cols() + T.rows());
  while (pivots < maxPivots) {
    Eigen::Index e = -1;
    for (Eigen::Index j = 0; j < ncols; ++j)
      if (T(m, j) < -tol) {
        e = j;
        break;
      }
    if (e < 0) return true;
    // Ratio test on the entries above a relative pivot tolerance (√ε × the column's largest: a
    // tinier pivot blows the tableau up); among ratios tied within tol, the largest pivot.
    using std::abs;
    using std::max;
    S colMax(0);
    for (Eigen::Index i = 0; i < m; ++i) colMax = max(colMax, S(abs(T(i, e))));
    const S pivTol = max(tol, S(Tolerance<S>::sqrtEpsilon() * colMax));
    Eigen::Index r = -1;
    S best(0);
    for (Eigen::Index i = 0; i < m; ++i) {
      if (!(T(i, e) > pivTol)) continue;
      const S ratio = max(S(0), S(T(i, last))) / T(i, e);
      if (r < 0 || ratio < best - tol || (!(ratio > best + tol) && T(i, e) > T(r, e))) {
        r = i;
        best = ratio;
      }
    }
    if (r < 0) return false;
    pivot(T, basis, r, e);
    ++pivots;
  }
  throw InvalidInput("minimiseLinearProgram: no optimum after " + std::to_string(maxPivots) +
                     " pivots (degenerate data)");
}

}  // namespace

template <class S>
LinearProgramResult<S> minimiseLinearProgram(const Eigen::Matrix<S, Eigen::Dynamic, 1>& c,
                                             const LpMat<S>& A, const Eigen::Matrix<S, Eigen::Dynamic, 1>& b) {
  using std::abs;
  using std::max;
  const Eigen::Index m = A.rows(), n = A.cols();
  if (c.size() != n || b.size() != m)
    throw InvalidInput("minimiseLinearProgram: sizes of c (" + std::to_string(c.size()) + "), A (" +
                       std::to_string(m) + "×" + std::to_string(n) + ") and b (" + std::to_string(b.size()) +
                       ") do not match");
  if (!allFinite(A) || !allFinite(b) || !allFinite(c))
    throw InvalidInput("minimiseLinearProgram: NaN or infinite entry in c, A or b");
  S scale(1);
  if (A.size()) scale = max(scale, S(A.cwiseAbs().maxCoeff()));
  if (b.size()) scale = max(scale, S(b.cwiseAbs().maxCoeff()));
  if (c.size()) scale = max(scale, S(c.cwiseAbs().maxCoeff()));
  const S tol = Tolerance<S>::rank() * scale;

  // Tableau [A | I | b] with artificial basis; last row the reduced costs and −z.
  LpMat<S> T = LpMat<S>::Zero(m + 1, n + m + 1);
  std::vector<Eigen::Index> basis(static_cast<std::size_t>(m));
  for (Eigen::Index i = 0; i < m; ++i) {
    const S sg = b(i) < S(0) ? S(-1) : S(1);
    T.row(i).head(n) = sg * A.row(i);
    T(i, n + i) = S(1);
    T(i, n + m) = sg * b(i);
    basis[std::size_t(i)] = n + i;
  }
  for (Eigen::Index j = 0; j < n; ++j) T(m, j) = -T.col(j).head(m).sum();
  T(m, n + m) = -T.col(n + m).head(m).sum();
  LinearProgramResult<S> res;
  runSimplex<S>(T, basis, n + m, tol, res.pivots);  // phase 1 is bounded below by 0
  if (-T(m, n + m) > tol) {
    res.status = LinearProgramResult<S>::Status::Infeasible;
    return res;
  }
  // Drive the artificials out of the basis (rows with no pivot left are redundant).
  for (Eigen::Index i = 0; i < m; ++i) {
    if (basis[std::size_t(i)] < n) continue;
    for (Eigen::Index j = 0; j < n; ++j)
      if (abs(T(i, j)) > tol) {
        pivot(T, basis, i, j);
        ++res.pivots;
        break;
      }
  }
  // Phase 2: reduced costs of c; artificial columns may not enter.
  T.row(m).setZero();
  for (Eigen::Index j = 0; j < n; ++j) T(m, j) = c(j);
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index bj = basis[std::size_t(i)];
    const S cb = bj < n ? c(bj) : S(0);
    if (cb != S(0)) T.row(m) -= cb * T.row(i);
  }
  if (!runSimplex<S>(T, basis, n, tol, res.pivots)) {
    res.status = LinearProgramResult<S>::Status::Unbounded;
    return res;
  }
  res.status = LinearProgramResult<S>::Status::Optimal;
  res.x = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(n);
  for (Eigen::Index i = 0; i < m; ++i)
    if (basis[std::size_t(i)] < n) res.x(basis[std::size_t(i)]) = T(i, n + m);
  res.value = c.dot(res.x);
  return res;
}

#define SOMA_STATICS_LP_INST(S)                                                                  \
  template LinearProgramResult<S> minimiseLinearProgram<S>(const Eigen::Matrix<S, Eigen::Dynamic, 1>&, \
                                                           const LpMat<S>&,                        \
                                                           const Eigen::Matrix<S, Eigen::Dynamic, 1>&);

}  // namespace soma
