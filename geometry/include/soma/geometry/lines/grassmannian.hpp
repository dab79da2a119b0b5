#pragma once
// Grassmannians G(n, m) of n-planes in R^m (GF §6.8): the Plücker embedding by the n×n minors
// into P^(C(m,n) − 1), the quadratic Plücker relations of G(2, m), and dim G(n, m) = n(m − n).
// G(2, 4) is the Klein quadric (one relation, the Pfaffian of (p_ij)).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"

#include <Eigen/LU>
#include <vector>

namespace soma {

/// dim G(n, m) = ½m(m−1) − ½n(n−1) − ½(m−n)(m−n−1) = n(m − n) (O(m)/(O(n) × O(m−n))).
// GF §6.8, GF-6.8-grassmannian-homogeneous (G(1, m) = PR^(m−1), erratum E6.7)
inline int grassmannianDimension(int n, int m) {
  if (n < 0 || m < n) throw InvalidInput("grassmannianDimension: need 0 ≤ n ≤ m");
  return m * (m - 1) / 2 - n * (n - 1) / 2 - (m - n) * (m - n - 1) / 2;
}

/// Index sets i₁ < … < i_n of {0 … m−1} in lexicographic order (the Plücker coordinates' order).
std::vector<std::vector<int>> pluckerIndexSets(int n, int m);

/// Plücker coordinates of the span of the n columns of `basis` (m × n): all n×n minors in
/// lexicographic order of the row sets. GF §6.8, GF-6.8-grassmannian-embedding
template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerEmbedding(const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>& basis) {
  const int m = int(basis.rows()), n = int(basis.cols());
  const auto sets = pluckerIndexSets(n, m);
  Eigen::Matrix<S, Eigen::Dynamic, 1> p(sets.size());
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> minor(n, n);
  for (std::size_t k = 0; k < sets.size(); ++k) {
    for (int r = 0; r < n; ++r) minor.row(r) = basis.row(sets[k][r]);
    p(Eigen::Index(k)) = minor.determinant();
  }
  return p;
}

/// The quadratic Plücker relations of G(2, m): p_ij p_kl − p_ik p_jl + p_il p_jk for every
/// i < j < k < l (C(m, 4) of them; 1 for m = 4 — the Klein quadric — 5 for m = 5, 15 for m = 6).
/// p is indexed as pluckerIndexSets(2, m). GF §6.8, GF-6.8-grassmannian-embedding
template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerRelationsG2(const Eigen::Matrix<S, Eigen::Dynamic, 1>& p, int m) {
  auto idx = [m](int i, int j) { return i * m - i * (i + 1) / 2 + (j - i - 1); };  // lexicographic pair index
  if (p.size() != m * (m - 1) / 2) throw InvalidInput("pluckerRelationsG2: p must have C(m, 2) entries");
  std::vector<S> out;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        for (int l = k + 1; l < m; ++l)
          out.push_back(p(idx(i, j)) * p(idx(k, l)) - p(idx(i, k)) * p(idx(j, l)) + p(idx(i, l)) * p(idx(j, k)));
  Eigen::Matrix<S, Eigen::Dynamic, 1> r(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) r(Eigen::Index(k)) = out[k];
  return r;
}

#define SOMA_GRASS_EXTERN(S)                                                                                   \
  extern template Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerEmbedding<S>(const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>&); \
  extern template Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerRelationsG2<S>(const Eigen::Matrix<S, Eigen::Dynamic, 1>&, int);
SOMA_FOR_EACH_SCALAR(SOMA_GRASS_EXTERN)
#undef SOMA_GRASS_EXTERN

}  // namespace soma
