#pragma once
// Small dense decompositions (a handful of rows and columns: screw systems, Jacobians, Study
// 3-planes): one-sided Jacobi SVD, singular values, numerical rank, cyclic Jacobi symmetric
// eigen-decomposition, pivoted Gram–Schmidt completion, an LU determinant and a small solve. Hand-written
// because Eigen's JacobiSVD/SelfAdjointEigenSolver for the five scalars cost minutes of compile
// time (measured: > 3 min CPU, 2.6 GB for one TU). Include it from .cpp/_impl files only.
#include "soma/algebra/tolerance.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <utility>
#include <vector>

namespace soma::detail {

template <class S> using SmallMat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// Thin SVD A = U diag(σ) Vᵀ by one-sided Jacobi (Hestenes); σ descending. Accurate small σ
/// (relative to ‖A‖), which the rank decisions need.
template <class S>
void smallSvd(const SmallMat<S>& a, SmallMat<S>& u, std::vector<S>& sig, SmallMat<S>& v) {
  using std::abs;
  using std::sqrt;
  const Eigen::Index m = a.rows(), n = a.cols();
  SmallMat<S> w = a;
  v = SmallMat<S>::Identity(n, n);
  const S eps = Tolerance<S>::epsilon();
  for (int sweep = 0; sweep < 60; ++sweep) {
    bool rotated = false;
    for (Eigen::Index p = 0; p < n; ++p)
      for (Eigen::Index q = p + 1; q < n; ++q) {
        const S alpha = w.col(p).squaredNorm(), beta = w.col(q).squaredNorm();
        const S gamma = w.col(p).dot(w.col(q));
        if (!(abs(gamma) > eps * sqrt(alpha * beta)) || gamma == S(0)) continue;
        rotated = true;
        const S zeta = (beta - alpha) / (S(2) * gamma);
        const S t = (zeta >= S(0) ? S(1) : S(-1)) / (abs(zeta) + sqrt(S(1) + zeta * zeta));
        const S c = S(1) / sqrt(S(1) + t * t), s = c * t;
        for (Eigen::Index i = 0; i < m; ++i) {
          const S x = w(i, p), y = w(i, q);
          w(i, p) = c * x - s * y;
          w(i, q) = s * x + c * y;
        }
        for (Eigen::Index i = 0; i < n; ++i) {
          const S x = v(i, p), y = v(i, q);
          v(i, p) = c * x - s * y;
          v(i, q) = s * x + c * y;
        }
      }
    if (!rotated) break;
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::vector<S> norms(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) {
    order[std::size_t(j)] = j;
    norms[std::size_t(j)] = sqrt(w.col(j).squaredNorm());
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index x, Eigen::Index y) { return norms[std::size_t(y)] < norms[std::size_t(x)]; });
  u.resize(m, n);
  SmallMat<S> vs(n, n);
  sig.assign(std::size_t(n), S(0));
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index j = order[std::size_t(k)];
    sig[std::size_t(k)] = norms[std::size_t(j)];
    vs.col(k) = v.col(j);
    if (norms[std::size_t(j)] > S(0)) u.col(k) = w.col(j) / norms[std::size_t(j)];
    else u.col(k).setZero();
  }
  v = vs;
}

/// Singular values of A, descending (one-sided Jacobi: accurate relative to ‖A‖).
template <class S> std::vector<S> smallSingularValues(const SmallMat<S>& a) {
  SmallMat<S> u, v;
  std::vector<S> sig;
  smallSvd<S>(a, u, sig, v);
  return sig;
}

/// Numerical rank: the singular values above Tolerance::rank × the largest (0 for the zero
/// matrix, and for a matrix with a NaN).
template <class S> int smallNumericalRank(const SmallMat<S>& a) {
  const std::vector<S> sig = smallSingularValues<S>(a);
  if (sig.empty() || !(sig[0] > S(0))) return 0;
  int r = 0;
  for (const S& s : sig)
    if (s > Tolerance<S>::rank() * sig[0]) ++r;
  return r;
}

/// Symmetric eigen-decomposition by cyclic Jacobi; eigenvalues descending, orthonormal vectors.
template <class S> void smallSymEigen(const SmallMat<S>& a0, std::vector<S>& vals, SmallMat<S>& vecs) {
  using std::abs;
  using std::sqrt;
  const Eigen::Index n = a0.rows();
  SmallMat<S> a = (a0 + a0.transpose()) / S(2);
  vecs = SmallMat<S>::Identity(n, n);
  const S eps = Tolerance<S>::epsilon();
  for (int sweep = 0; sweep < 60; ++sweep) {
    S off(0);
    for (Eigen::Index p = 0; p < n; ++p)
      for (Eigen::Index q = p + 1; q < n; ++q) off += a(p, q) * a(p, q);
    if (!(off > eps * eps * a.squaredNorm())) break;
    for (Eigen::Index p = 0; p < n; ++p)
      for (Eigen::Index q = p + 1; q < n; ++q) {
        if (a(p, q) == S(0)) continue;
        const S theta = (a(q, q) - a(p, p)) / (S(2) * a(p, q));
        const S t = (theta >= S(0) ? S(1) : S(-1)) / (abs(theta) + sqrt(S(1) + theta * theta));
        const S c = S(1) / sqrt(S(1) + t * t), s = t * c;
        for (Eigen::Index k = 0; k < n; ++k) {  // A ← A J
          const S x = a(k, p), y = a(k, q);
          a(k, p) = c * x - s * y;
          a(k, q) = s * x + c * y;
        }
        for (Eigen::Index k = 0; k < n; ++k) {  // A ← Jᵀ A
          const S x = a(p, k), y = a(q, k);
          a(p, k) = c * x - s * y;
          a(q, k) = s * x + c * y;
        }
        for (Eigen::Index k = 0; k < n; ++k) {
          const S x = vecs(k, p), y = vecs(k, q);
          vecs(k, p) = c * x - s * y;
          vecs(k, q) = s * x + c * y;
        }
      }
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) order[std::size_t(j)] = j;
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index x, Eigen::Index y) { return a(y, y) < a(x, x); });
  SmallMat<S> vs(n, n);
  vals.assign(std::size_t(n), S(0));
  for (Eigen::Index k = 0; k < n; ++k) {
    vals[std::size_t(k)] = a(order[std::size_t(k)], order[std::size_t(k)]);
    vs.col(k) = vecs.col(order[std::size_t(k)]);
  }
  vecs = vs;
}

/// Orthonormal completion: columns orthonormal to the orthonormal columns of b, spanning the
/// complement in R^m (pivoted Gram–Schmidt on the unit vectors, twice for stability).
template <class S> SmallMat<S> smallComplement(const SmallMat<S>& b) {
  using std::sqrt;
  const Eigen::Index m = b.rows(), k = b.cols();
  SmallMat<S> q(m, m);
  q.leftCols(k) = b;
  std::vector<bool> used(std::size_t(m), false);
  for (Eigen::Index c = k; c < m; ++c) {
    Eigen::Index best = -1;
    S bestNorm(-1);
    Eigen::Matrix<S, Eigen::Dynamic, 1> bestVec;
    for (Eigen::Index e = 0; e < m; ++e) {
      if (used[std::size_t(e)]) continue;
      Eigen::Matrix<S, Eigen::Dynamic, 1> x = Eigen::Matrix<S, Eigen::Dynamic, 1>::Unit(m, e);
      for (int pass = 0; pass < 2; ++pass)
        for (Eigen::Index j = 0; j < c; ++j) x -= q.col(j) * q.col(j).dot(x);
      const S nx = x.squaredNorm();
      if (nx > bestNorm) {
        bestNorm = nx;
        best = e;
        bestVec = x;
      }
    }
    used[std::size_t(best)] = true;
    q.col(c) = bestVec / sqrt(bestNorm);
  }
  return q.rightCols(m - k);
}

/// Determinant by Gaussian elimination with partial pivoting.
template <class S> S smallDeterminant(SmallMat<S> a) {
  using std::abs;
  const Eigen::Index n = a.rows();
  S det(1);
  for (Eigen::Index c = 0; c < n; ++c) {
    Eigen::Index p = c;
    for (Eigen::Index r = c + 1; r < n; ++r)
      if (abs(a(r, c)) > abs(a(p, c))) p = r;
    if (a(p, c) == S(0)) return S(0);
    if (p != c) {
      a.row(p).swap(a.row(c));
      det = -det;
    }
    det *= a(c, c);
    for (Eigen::Index r = c + 1; r < n; ++r) {
      const S f = a(r, c) / a(c, c);
      a.row(r).tail(n - c) -= f * a.row(c).tail(n - c);
    }
  }
  return det;
}

/// Solves a x = b (square a) by Gaussian elimination with partial pivoting; b ← x. Returns the
/// ratio smallest/largest pivot modulus (0 when a is singular, b then unchanged in meaning): a
/// cheap conditioning indicator for the caller's threshold.
template <class S, int N>
S smallSolveInPlace(Eigen::Matrix<S, N, N> a, Eigen::Matrix<S, N, 1>& b) {
  using std::abs;
  const Eigen::Index n = a.rows();
  S pmin(0), pmax(0);
  for (Eigen::Index c = 0; c < n; ++c) {
    Eigen::Index p = c;
    for (Eigen::Index r = c + 1; r < n; ++r)
      if (abs(a(r, c)) > abs(a(p, c))) p = r;
    const S piv = abs(a(p, c));
    if (piv == S(0)) return S(0);
    if (c == 0 || piv < pmin) pmin = piv;
    if (piv > pmax) pmax = piv;
    if (p != c) {
      a.row(p).swap(a.row(c));
      std::swap(b(p), b(c));
    }
    for (Eigen::Index r = c + 1; r < n; ++r) {
      const S f = a(r, c) / a(c, c);
      a.row(r).tail(n - c) -= f * a.row(c).tail(n - c);
      b(r) -= f * b(c);
    }
  }
  for (Eigen::Index c = n - 1; c >= 0; --c) {
    S v = b(c);
    for (Eigen::Index k = c + 1; k < n; ++k) v -= a(c, k) * b(k);
    b(c) = v / a(c, c);
  }
  return pmin / pmax;
}

}  // namespace soma::detail
