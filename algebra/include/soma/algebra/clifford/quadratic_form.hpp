#pragma once
// Clifford algebras of a non-diagonal quadratic form (GF §9.1, GF-9.1-clifford-definition-signature).
//
// The book defines Cℓ(Q) by generators x_1 … x_n with x_i x_j + x_j x_i = 2 Q_ij for any
// symmetric Q, then changes generators, e_i = Σ_j m_ij x_j, so that e_i e_j + e_j e_i =
// 2 (M Q Mᵀ)_ij, and by Sylvester's law of inertia picks M with M Q Mᵀ = diag(1…1, −1…−1, 0…0):
// every Cℓ(Q) IS a Cℓ(p,q,r) written in another basis (seed 5317–5338; the book's double sum
// "Σ_k Σ_j m_ik m_jl" is a typo for Σ_k Σ_l). soma therefore computes only with diagonal
// signatures — the blade tables of signature.hpp need orthogonal generators — and this header
// is the change of basis that lets a user start from a non-diagonal Q:
//
//   FormBasis<Signature<p,q,r>, S> fb(Q);      // InvalidInput unless Q has inertia (p,q,r)
//   auto u = fb.vector(ux);                      // Σ u_j x_j as a Cl(p,q,r) vector
//   auto w = u * v;                              // products in the diagonal algebra
//   auto wx = fb.toFormBasis(Dense(w));          // coefficients on the x-blades x_{j1}∧…∧x_{jk}
//
// Blades in the form basis are the exterior products of the x_j (metric-free, so the map between
// the two bases is the outermorphism of the linear change of generators; this is the Chevalley
// identification Cℓ ≅ Λ, natural under isometries). tests/algebra/clifford_form.cpp checks the
// products against a direct evaluation of x_i · (x_J) = x_i ∧ x_J + x_i ⌋_Q x_J in the
// x-basis that never diagonalises Q.
#include "soma/algebra/clifford/multivector.hpp"

#include <Eigen/Eigenvalues>
#include <string>

namespace soma::clifford {

template <class S> using FormMatrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// Sylvester's law of inertia by an orthogonal eigen-decomposition: Q = V Λ Vᵀ, then
/// M = |Λ'|^{-1/2} Vᵀ (rows ordered: positive, negative, zero eigenvalues; |λ| below
/// Tolerance<S>::rank()·max|λ| counts as zero and keeps scale 1). M Q Mᵀ = diag(+1, −1, 0).
template <class S> struct Congruence {
  int p = 0, q = 0, r = 0;
  FormMatrix<S> M;  ///< e = M x (generators of the diagonal algebra in terms of the x_j)
  FormMatrix<S> N;  ///< M⁻¹: x_j = Σ_i N_ji e_i
};

// GF §9.1, GF-9.1-clifford-definition-signature (Sylvester; double sum corrected to Σ_k Σ_l)
template <class S> Congruence<S> congruence(const FormMatrix<S>& Q) {
  using std::abs;
  using std::sqrt;
  const Eigen::Index n = Q.rows();
  if (n < 1 || n > 8 || Q.cols() != n)
    throw InvalidInput("clifford quadratic form Q must be square with 1..8 rows, got " +
                       std::to_string(Q.rows()) + "x" + std::to_string(Q.cols()));
  const S scale = Q.cwiseAbs().maxCoeff();
  if (!((Q - Q.transpose()).cwiseAbs().maxCoeff() <= Tolerance<S>::input() * (S(1) + scale)))
    throw InvalidInput("clifford quadratic form Q is not symmetric");
  const FormMatrix<S> Qs = (Q + Q.transpose()) / S(2);
  Eigen::SelfAdjointEigenSolver<FormMatrix<S>> es(Qs);
  if (es.info() != Eigen::Success)
    throw InvalidInput("clifford quadratic form: eigen-decomposition of Q failed");
  const auto& lam = es.eigenvalues();
  const S zero = Tolerance<S>::rank() * (scale > S(0) ? scale : S(1));
  std::vector<int> pos, neg, nul;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (lam(i) > zero) pos.push_back(int(i));
    else if (lam(i) < -zero) neg.push_back(int(i));
    else nul.push_back(int(i));
  }
  Congruence<S> c;
  c.p = int(pos.size()), c.q = int(neg.size()), c.r = int(nul.size());
  c.M.resize(n, n);
  c.N.resize(n, n);
  int row = 0;
  for (const auto* group : {&pos, &neg, &nul})
    for (int i : *group) {
      const S s = (group == &nul) ? S(1) : sqrt(abs(lam(i)));
      c.M.row(row) = es.eigenvectors().col(i).transpose() / s;
      c.N.col(row) = es.eigenvectors().col(i) * s;
      ++row;
    }
  return c;
}

/// Cℓ(Q) for a symmetric n×n Q of inertia (p,q,r) = Sig, computed in Cl(p,q,r).
template <class Sig, class S> class FormBasis {
 public:
  using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1>;

  explicit FormBasis(const FormMatrix<S>& Q) : c_(clifford::congruence<S>(Q)), Q_(Q) {
    if (Q.rows() != Sig::n || c_.p != Sig::p || c_.q != Sig::q || c_.r != Sig::r)
      throw InvalidInput("clifford FormBasis: Q (" + std::to_string(Q.rows()) +
                         " generators) has inertia (p,q,r) = (" + std::to_string(c_.p) + "," +
                         std::to_string(c_.q) + "," + std::to_string(c_.r) +
                         ") but the algebra is Cl(" + std::to_string(Sig::p) + "," +
                         std::to_string(Sig::q) + "," + std::to_string(Sig::r) + ")");
    for (Blade b = 0; b < Blade(Sig::dim); ++b) {
      toE_.push_back(outermorphism(c_.N.transpose(), b));  // x_j = Σ_i N_ji e_i
      toX_.push_back(outermorphism(c_.M.transpose(), b));  // e_i = Σ_j M_ij x_j
    }
  }
  const Congruence<S>& congruence() const { return c_; }
  const FormMatrix<S>& form() const { return Q_; }

  /// Σ_j v_j x_j as a vector of Cl(p,q,r): coefficient of e_i is Σ_j v_j N_ji.
  Vector<Sig, S> vector(const Vec& v) const {
    if (v.size() != Sig::n)
      throw InvalidInput("clifford FormBasis::vector: expected " + std::to_string(Sig::n) +
                         " coordinates, got " + std::to_string(v.size()));
    Vector<Sig, S> out;
    const Vec e = c_.N.transpose() * v;
    for (int i = 0; i < Sig::n; ++i) out.setCoeff(Blade(1) << i, e(i));
    return out;
  }
  /// The x-generator x_j.
  Vector<Sig, S> generator(int j) const {
    Vec v = Vec::Zero(Sig::n);
    v(j) = S(1);
    return vector(v);
  }
  /// Element with coefficients w on the x-blades x_{j1} ∧ … ∧ x_{jk} (w indexed by bitmask).
  Dense<Sig, S> fromFormBasis(const std::array<S, Sig::dim>& w) const {
    Dense<Sig, S> out;
    for (int b = 0; b < Sig::dim; ++b)
      if (w[std::size_t(b)] != S(0)) out += toE_[std::size_t(b)] * w[std::size_t(b)];
    return out;
  }
  /// Coefficients on the x-blades (inverse of fromFormBasis).
  std::array<S, Sig::dim> toFormBasis(const Dense<Sig, S>& a) const {
    std::array<S, Sig::dim> w{};
    for (int i = 0; i < a.size; ++i) {
      if (a[i] == S(0)) continue;
      const auto& img = toX_[std::size_t(a.blade(i))];
      for (int k = 0; k < img.size; ++k) w[std::size_t(img.blade(k))] += a[i] * img[k];
    }
    return w;
  }

 private:
  /// Outermorphism of the linear map with matrix T (column j = image of generator j) on
  /// blade b: the exterior product of the images of its generators, in increasing order.
  static Dense<Sig, S> outermorphism(const FormMatrix<S>& T, Blade b) {
    Dense<Sig, S> out(S(1));
    for (int j = 0; j < Sig::n; ++j)
      if (b & (Blade(1) << j)) {
        Vector<Sig, S> v;
        for (int i = 0; i < Sig::n; ++i) v.setCoeff(Blade(1) << i, T(i, j));
        out = Dense<Sig, S>(out ^ v);
      }
    return out;
  }
  Congruence<S> c_;
  FormMatrix<S> Q_;
  std::vector<Dense<Sig, S>> toE_, toX_;
};

}  // namespace soma::clifford
