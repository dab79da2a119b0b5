#pragma once
// The irreducible representations L_j of so(3) (GF §7.3), j = 0, ½, 1, …, dimension 2j + 1, in
// the book's ladder basis: J₃ = Z, J± = Y ± iX ([J₃, J±] = ±iJ±, [J₊, J₋] = 2iJ₃), basis
// e_k = J₋^k e_top (k = 0 … 2j), so J₋ e_k = e_{k+1}, J₃ e_k = i(j − k) e_k and
// J₊ e_k = f(k) e_{k−1} with the book's f(k) = (2in + k − 1)k at top eigenvalue n = ij, i.e.
// f(k) = k(k − 1 − 2j). In this basis J₊, J₋ are real and J₃ = iH with the real weight matrix
// H = diag(j, j − 1, …, −j); so(3)'s real elements are complex matrices (element()).
// Casimir J₃² + ½(J₊J₋ + J₋J₊) = X² + Y² + Z² = −j(j + 1)·1. L_j passes to SO(3) iff j is an integer
// (e^{2πJ₃} = (−1)^{2j}). Clebsch–Gordan: L_m ⊗ L_n = L_{m+n} ⊕ … ⊕ L_{|m−n|}.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/rep/tensor_product.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/LU>

#include <complex>
#include <map>
#include <string>

namespace soma::rep {

/// L_j with j = twoJ/2: H = −iJ₃, J₊, J₋ (all real). GF §7.3, GF-7.3-so3-irreps
template <class S> struct So3Irrep {
  int twoJ = 0;  ///< 2j (the book's m): the dimension is twoJ + 1
  Matrix<S> H;   ///< the weight matrix −iJ₃ = diag(j, j − 1, …, −j)
  Matrix<S> Jp;  ///< J₊ (raising: J₊ e_k = k(k − 1 − 2j) e_{k−1})
  Matrix<S> Jm;  ///< J₋ (lowering: J₋ e_k = e_{k+1})

  int dimension() const { return twoJ + 1; }
  /// J₃ = iH.
  Matrix<std::complex<S>> J3() const { return Matrix<std::complex<S>>(H.template cast<std::complex<S>>() * std::complex<S>(S(0), S(1))); }
  /// J₃² + ½(J₊J₋ + J₋J₊) = −H² + ½(J₊J₋ + J₋J₊) (real; −j(j + 1)·1 on L_j). GF §7.5 (J_t)
  Matrix<S> casimir() const { return Matrix<S>(-H * H + (Jp * Jm + Jm * Jp) / S(2)); }
  /// The matrix of the real element xX + yY + zZ of so(3): X = i(J₋ − J₊)/2, Y = (J₊ + J₋)/2, Z = J₃.
  Matrix<std::complex<S>> element(const Vec3<S>& w) const {
    const Matrix<S> re = w(1) * (Jp + Jm) / S(2);
    const Matrix<S> im = w(0) * (Jm - Jp) / S(2) + w(2) * H;
    Matrix<std::complex<S>> out(re.rows(), re.cols());
    for (Eigen::Index r = 0; r < re.rows(); ++r)
      for (Eigen::Index c = 0; c < re.cols(); ++c) out(r, c) = std::complex<S>(re(r, c), im(r, c));
    return out;
  }
};

/// L_j, twoJ = 2j ≥ 0, built from the ladder with the book's normalisation f(k).
// GF §7.3, GF-7.3-so3-irreps
template <class S> So3Irrep<S> so3Irrep(int twoJ) {
  if (twoJ < 0) throw InvalidInput("so3Irrep: 2j must be ≥ 0, got " + std::to_string(twoJ));
  const int d = twoJ + 1;
  So3Irrep<S> l{twoJ, Matrix<S>::Zero(d, d), Matrix<S>::Zero(d, d), Matrix<S>::Zero(d, d)};
  for (int k = 0; k < d; ++k) {
    l.H(k, k) = S(twoJ - 2 * k) / S(2);
    if (k + 1 < d) l.Jm(k + 1, k) = S(1);
    if (k > 0) l.Jp(k - 1, k) = S(k * (k - 1 - twoJ));
  }
  return l;
}

/// The summands of L_m ⊗ L_n as 2k: 2|m − n|, 2|m − n| + 2, …, 2(m + n). GF §7.4, GF-7.4-clebsch-gordan (corrected, E7.1)
inline std::vector<int> clebschGordan(int twoM, int twoN) {
  std::vector<int> out;
  for (int twoK = std::abs(twoM - twoN); twoK <= twoM + twoN; twoK += 2) out.push_back(twoK);
  return out;
}

/// Decomposition of a representation of so(3) into irreducibles from its weights: the
/// multiplicity of each eigenvalue w of H = −iJ₃ (w ∈ ½ℤ, counted as nullity of H − w, rank at
/// Tolerance::rank()) gives #L_k = mult(k) − mult(k + 1). Returns 2k ↦ number of copies of L_k.
// GF §7.4, GF-7.4-L1xL1 ("from the list of eigenvalues and their multiplicities")
template <class S> std::map<int, int> so3Decomposition(const Matrix<S>& h) {
  const int n = int(h.rows());
  auto mult = [&](int twoW) {
    Eigen::FullPivLU<Matrix<S>> lu(Matrix<S>(h - (S(twoW) / S(2)) * Matrix<S>::Identity(n, n)));
    lu.setThreshold(Tolerance<S>::rank());
    return n - int(lu.rank());
  };
  std::map<int, int> out;
  int total = 0;
  for (int twoK = n - 1; twoK >= 0; --twoK) {
    const int copies = mult(twoK) - mult(twoK + 2);
    if (copies > 0) out[twoK] = copies, total += copies * (twoK + 1);
  }
  if (total != n)
    throw InvalidInput("so3Decomposition: the weights do not form so(3) strings (accounted " + std::to_string(total) +
                       " of " + std::to_string(n) + " dimensions)");
  return out;
}

}  // namespace soma::rep
