#pragma once
// Definitions of screw_system.hpp; included only by the explicit instantiations (soma_instantiate,
// cmake/SomaInstantiate.cmake), so users pay no decomposition instantiations.
#include "soma/geometry/screws/screw_system.hpp"
#include "soma/algebra/small_linalg.hpp"

#include <string>

namespace soma {
namespace detail {

/// Orthonormal range of the columns of a (rows × k) matrix by SVD, rank from
/// Tolerance::rank()·σ_max. Returns the basis; cond = σ_r/σ_1, dropped = σ_{r+1}/σ_1.
template <class S>
ScrewMatX<S> orthonormalRange(const ScrewMatX<S>& a, S* cond = nullptr, S* dropped = nullptr) {
  if (cond) *cond = S(1);
  if (dropped) *dropped = S(0);
  if (a.cols() == 0) return ScrewMatX<S>(a.rows(), 0);
  ScrewMatX<S> u, v;
  std::vector<S> sv;
  smallSvd<S>(a, u, sv, v);
  const int k = int(sv.size());
  if (k == 0 || !(sv[0] > S(0))) return ScrewMatX<S>(a.rows(), 0);
  const S tol = Tolerance<S>::rank() * sv[0];
  int r = 0;
  while (r < k && sv[std::size_t(r)] > tol) ++r;
  if (cond) *cond = sv[std::size_t(r - 1)] / sv[0];
  if (dropped && r < k) *dropped = sv[std::size_t(r)] / sv[0];
  return u.leftCols(r);
}

}  // namespace detail

template <class S> ScrewSystem<S>::ScrewSystem(const ScrewMatX<S>& generators) : basis_(6, 0) {
  using std::sqrt;
  if (generators.rows() != 6)
    throw InvalidInput("ScrewSystem: generators must have 6 rows (ω, v), got " +
                       std::to_string(generators.rows()));
  if (!allFinite(generators))
    throw InvalidInput("ScrewSystem: a generator has a NaN or infinite component");
  ScrewMatX<S> g(6, generators.cols());
  int k = 0;
  for (Eigen::Index j = 0; j < generators.cols(); ++j) {
    const S n2 = generators.col(j).squaredNorm();
    if (n2 > S(0)) g.col(k++) = generators.col(j) / sqrt(n2);
  }
  g.conservativeResize(6, k);
  const ScrewMatX<S> u = detail::orthonormalRange<S>(g, &conditioning_, &dropped_);
  basis_ = u;
}

template <class S> ScrewSystem<S> ScrewSystem<S>::fromOrthonormal(const Basis& b, const S& cond) {
  ScrewSystem s;
  s.basis_ = b;
  s.conditioning_ = cond;
  return s;
}

template <class S> ScrewBasis<S> orthogonalComplement(const ScrewBasis<S>& b) {
  if (b.cols() == 0) return ScrewBasis<S>(Mat6<S>::Identity());
  if (b.cols() >= 6) return ScrewBasis<S>(6, 0);
  return ScrewBasis<S>(detail::smallComplement<S>(ScrewMatX<S>(b)));
}

// GF §8.1, GF-8.1-reciprocal-system: {s : s_iᵀQ₀s = 0}; Q₀ is orthogonal and symmetric, so the
// reciprocal is the orthogonal complement of Q₀Δ.
template <class S> ScrewSystem<S> ScrewSystem<S>::reciprocal() const {
  const Basis q0b = kleinForm<S>() * basis_;
  return fromOrthonormal(orthogonalComplement<S>(q0b));
}

template <class S> ScrewSystem<S> ScrewSystem<S>::transformed(const SE3<S>& g) const {
  return ScrewSystem(ScrewMatX<S>(g.adjoint() * basis_));
}

template <class S> S ScrewSystem<S>::residualOf(const Vec6<S>& s) const {
  using std::sqrt;
  const S n2 = s.squaredNorm();
  if (!(n2 > S(0))) return S(0);
  const Vec6<S> r = s - basis_ * (basis_.transpose() * s);
  return sqrt(r.squaredNorm() / n2);
}

template <class S> S ScrewSystem<S>::distanceTo(const ScrewSystem& o) const {
  using std::sqrt;
  if (o.dimension() != dimension()) return S(1);
  if (dimension() == 0) return S(0);
  // Largest principal-angle sine = ‖(I − P_a) B_b‖₂; bounded by the Frobenius norm, use the
  // spectral norm from the small SVD.
  const ScrewMatX<S> r = ScrewMatX<S>(o.basis_) - ScrewMatX<S>(basis_) * (basis_.transpose() * o.basis_);
  ScrewMatX<S> u, v;
  std::vector<S> sv;
  detail::smallSvd<S>(r, u, sv, v);
  return sv[0];
}

template <class S> bool ScrewSystem<S>::isSubalgebra() const {
  for (int i = 0; i < dimension(); ++i)
    for (int j = i + 1; j < dimension(); ++j) {
      const Vec6<S> b = screwBracket<S>(basis_.col(i), basis_.col(j));
      const Vec6<S> r = b - basis_ * (basis_.transpose() * b);
      if (r.squaredNorm() > Tolerance<S>::rank() * Tolerance<S>::rank()) return false;
    }
  return true;
}

template <class S> ScrewSystem<S> unionOf(const ScrewSystem<S>& a, const ScrewSystem<S>& b) {
  ScrewMatX<S> g(6, a.dimension() + b.dimension());
  g << ScrewMatX<S>(a.basis()), ScrewMatX<S>(b.basis());
  return ScrewSystem<S>(g);
}

template <class S> ScrewSystem<S> intersectionOf(const ScrewSystem<S>& a, const ScrewSystem<S>& b) {
  return unionOf(a.reciprocal(), b.reciprocal()).reciprocal();
}

template <class S> ScrewSystem<S> isotropyAlgebra(const ScrewSystem<S>& d) {
  const int n = d.dimension();
  if (n == 0 || n == 6) return ScrewSystem<S>(ScrewMatX<S>(Mat6<S>::Identity()));
  const ScrewMatX<S> B = d.basis();
  const ScrewMatX<S> comp = ScrewMatX<S>(Mat6<S>::Identity()) - B * B.transpose();
  // [s, b_i] = −ad(b_i) s must lie in Δ: (I − P)(−ad(b_i)) s = 0 for every i.
  ScrewMatX<S> a(6 * n, 6);
  for (int i = 0; i < n; ++i) {
    const SE3Tangent<S> bi{Vec6<S>(B.col(i))};
    a.block(6 * i, 0, 6, 6) = -(comp * ScrewMatX<S>(bi.ad()));
  }
  ScrewMatX<S> u, v;
  std::vector<S> sv;
  detail::smallSvd<S>(a, u, sv, v);
  const S scale = sv[0] > S(1) ? sv[0] : S(1);
  const S tol = Tolerance<S>::rank() * scale;
  int r = 0;
  while (r < 6 && sv[std::size_t(r)] > tol) ++r;
  return ScrewSystem<S>::fromOrthonormal(ScrewBasis<S>(v.rightCols(6 - r)));
}

template <class S> ScrewSystem<S> completion(const ScrewSystem<S>& d, std::vector<int>* dims) {
  if (dims) dims->assign(1, d.dimension());
  ScrewSystem<S> cur = d;
  for (int step = 0; step < 6; ++step) {
    const int n1 = d.dimension(), nc = cur.dimension();
    ScrewMatX<S> g(6, nc + n1 * nc);
    g.leftCols(nc) = cur.basis();
    int k = nc;
    // Brackets of unit basis screws: keep only the part outside Δ_i that is above the rank
    // tolerance (an exactly-zero bracket computed in floating point must not be normalised up).
    for (int i = 0; i < n1; ++i)
      for (int j = 0; j < nc; ++j) {
        const Vec6<S> b = screwBracket<S>(d.basis().col(i), cur.basis().col(j));
        const Vec6<S> r = b - cur.basis() * (cur.basis().transpose() * b);
        if (r.squaredNorm() > Tolerance<S>::rank() * Tolerance<S>::rank()) g.col(k++) = r;
      }
    g.conservativeResize(6, k);
    ScrewSystem<S> next(g);
    if (next.dimension() == cur.dimension()) break;
    cur = next;
    if (dims) dims->push_back(cur.dimension());
  }
  return cur;
}

template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> wedge(const ScrewMatX<S>& g) {
  const int n = int(g.cols());
  if (g.rows() != 6 || n < 1 || n > 6)
    throw InvalidInput("wedge: need a 6 × n matrix with 1 ≤ n ≤ 6");
  std::vector<int> idx(n);
  for (int i = 0; i < n; ++i) idx[i] = i;
  std::vector<S> out;
  while (true) {
    ScrewMatX<S> m(n, n);
    for (int i = 0; i < n; ++i) m.row(i) = g.row(idx[i]);
    out.push_back(detail::smallDeterminant<S>(m));
    int i = n - 1;
    while (i >= 0 && idx[i] == 6 - n + i) --i;
    if (i < 0) break;
    ++idx[i];
    for (int j = i + 1; j < n; ++j) idx[j] = idx[j - 1] + 1;
  }
  Eigen::Matrix<S, Eigen::Dynamic, 1> w(Eigen::Index(out.size()));
  for (std::size_t i = 0; i < out.size(); ++i) w(Eigen::Index(i)) = out[i];
  return w;
}

}  // namespace soma

// Explicit instantiation for one scalar (the rule: cmake/SomaInstantiate.cmake).
#define SOMA_INSTANTIATE_SCREW_SYSTEM(S)                                                  \
  template class ScrewSystem<S>;                                                          \
  template ScrewSystem<S> unionOf<S>(const ScrewSystem<S>&, const ScrewSystem<S>&);       \
  template ScrewSystem<S> intersectionOf<S>(const ScrewSystem<S>&, const ScrewSystem<S>&); \
  template ScrewSystem<S> isotropyAlgebra<S>(const ScrewSystem<S>&);                      \
  template ScrewSystem<S> completion<S>(const ScrewSystem<S>&, std::vector<int>*);        \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> wedge<S>(const ScrewMatX<S>&);             \
  template ScrewBasis<S> orthogonalComplement<S>(const ScrewBasis<S>&);
