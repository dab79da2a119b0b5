#pragma once
// Shared checks of the Cl(p,q,r) products for tests/algebra/clifford_products*.cpp (see there).
#include "soma/algebra/clifford/multivector.hpp"
#include "support/scalars.hpp"

#include <Eigen/LU>
#include <vector>

namespace soma::test::clifford_checks {
using namespace soma::clifford;

template <class S> using MatX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// Complex integer matrices as pairs (re, im) of int matrices.
struct CMat {
  Eigen::MatrixXi re, im;
};
inline CMat kron(const CMat& a, const CMat& b) {
  const int ra = int(a.re.rows()), rb = int(b.re.rows());
  CMat c{Eigen::MatrixXi::Zero(ra * rb, ra * rb), Eigen::MatrixXi::Zero(ra * rb, ra * rb)};
  for (int i = 0; i < ra; ++i)
    for (int j = 0; j < ra; ++j) {
      c.re.block(i * rb, j * rb, rb, rb) = a.re(i, j) * b.re - a.im(i, j) * b.im;
      c.im.block(i * rb, j * rb, rb, rb) = a.re(i, j) * b.im + a.im(i, j) * b.re;
    }
  return c;
}
/// N anticommuting complex matrices squaring to +1 (Jordan–Wigner), faithful for Cl_N(ℂ) ⊇ real.
inline std::vector<CMat> gammas(int N) {
  const Eigen::MatrixXi Z2 = Eigen::MatrixXi::Zero(2, 2);
  Eigen::MatrixXi one(2, 2), x(2, 2), z(2, 2), yim(2, 2);
  one << 1, 0, 0, 1;
  x << 0, 1, 1, 0;
  z << 1, 0, 0, -1;
  yim << 0, -1, 1, 0;  // Y = i·[[0,−1],[1,0]]
  const CMat I{one, Z2}, X{x, Z2}, Zm{z, Z2}, Y{Z2, yim};
  const int m = (N + 1) / 2;
  std::vector<CMat> g;
  for (int k = 0; k < N; ++k) {
    const int q = k / 2;
    CMat mat{Eigen::MatrixXi::Ones(1, 1), Eigen::MatrixXi::Zero(1, 1)};
    for (int t = 0; t < m; ++t) mat = kron(mat, t < q ? Zm : (t == q ? (k % 2 ? Y : X) : I));
    g.push_back(mat);
  }
  return g;
}
template <class S> MatX<S> realForm(const CMat& c) {
  const int d = int(c.re.rows());
  MatX<S> r = MatX<S>::Zero(2 * d, 2 * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      r(2 * i, 2 * j) = S(c.re(i, j));
      r(2 * i, 2 * j + 1) = S(-c.im(i, j));
      r(2 * i + 1, 2 * j) = S(c.im(i, j));
      r(2 * i + 1, 2 * j + 1) = S(c.re(i, j));
    }
  return r;
}

/// Real matrices for the generators of Sig and for every basis blade (dense blade order = bitmask).
template <class Sig, class S> std::vector<MatX<S>> bladeMatrices() {
  const std::vector<CMat> g = gammas(Sig::n + Sig::r);
  const auto d0 = g[0].re.rows();
  const CMat iI{Eigen::MatrixXi::Zero(d0, d0), Eigen::MatrixXi::Identity(d0, d0)};  // i·1
  std::vector<MatX<S>> gen;
  int extra = Sig::n;
  for (int i = 0; i < Sig::n; ++i) {
    const int sq = Sig::square(i);
    if (sq == 1) gen.push_back(realForm<S>(g[i]));
    if (sq == -1) gen.push_back(realForm<S>(g[i]) * realForm<S>(iI));  // (iγ)² = −1
    if (sq == 0) {  // f₊ + f₋ with f₊ = γ_i, f₋ = i γ_extra
      gen.push_back(realForm<S>(g[i]) + realForm<S>(iI) * realForm<S>(g[extra]));
      ++extra;
    }
  }
  const int d = int(gen[0].rows());
  std::vector<MatX<S>> blades(Sig::dim);
  for (int b = 0; b < Sig::dim; ++b) {
    MatX<S> m = MatX<S>::Identity(d, d);
    for (int i = 0; i < Sig::n; ++i)
      if (b & (1 << i)) m = (m * gen[i]).eval();
    blades[b] = m;
  }
  return blades;
}

template <class Sig, class S, GradeMask M>
MatX<S> rep(const std::vector<MatX<S>>& blades, const Multivector<Sig, S, M>& a) {
  MatX<S> m = MatX<S>::Zero(blades[0].rows(), blades[0].cols());
  for (int i = 0; i < a.size; ++i)
    if (a[i] != S(0)) m += a[i] * blades[a.blade(i)];
  return m;
}

template <class Sig, class S, GradeMask M> Multivector<Sig, S, M> randomMV(std::mt19937_64& g) {
  Multivector<Sig, S, M> a;
  for (int i = 0; i < a.size; ++i) a[i] = uniform<S>(g);
  return a;
}

template <class S, class D> S maxAbsM(const Eigen::MatrixBase<D>& m) {
  return m.cwiseAbs().maxCoeff();
}

/// Geometric products of dense and grade-sparse operands agree with the matrix representation.
template <class Sig, class S> void checkAgainstMatrices(int trials) {
  auto& g = rng(1000 + Sig::p * 100 + Sig::q * 10 + Sig::r);
  const auto blades = bladeMatrices<Sig, S>();
  // Faithfulness (double only, cheap): the 2^n blade matrices are linearly independent, so
  // agreement of matrices means agreement of multivectors.
  if constexpr (std::is_same_v<S, double>) {
    MatX<double> stack(blades[0].size(), Sig::dim);
    for (int b = 0; b < Sig::dim; ++b)
      stack.col(b) = Eigen::Map<const Eigen::VectorXd>(blades[b].data(), blades[b].size());
    CHECK(Eigen::FullPivLU<MatX<double>>(stack).rank() == Sig::dim);
  }
  // Generator relations: e_i e_j + e_j e_i = 2 Q_ij (GF §9.1) in the representation.
  for (int i = 0; i < Sig::n; ++i)
    for (int j = 0; j < Sig::n; ++j) {
      const MatX<S> ac = blades[1 << i] * blades[1 << j] + blades[1 << j] * blades[1 << i];
      const MatX<S> want =
          MatX<S>::Identity(ac.rows(), ac.cols()) * S(i == j ? 2 * Sig::square(i) : 0);
      CHECK(maxAbsM<S>(ac - want) == S(0));
    }
  const S tol = S(Sig::dim) * Tolerance<S>::identity(16);
  for (int t = 0; t < trials; ++t) {
    const auto a = randomMV<Sig, S, Sig::allGrades>(g);
    const auto b = randomMV<Sig, S, Sig::allGrades>(g);
    const MatX<S> want = rep(blades, a) * rep(blades, b);
    CHECK(maxAbsM<S>(rep(blades, a * b) - want) <= tol);
    const auto ev = randomMV<Sig, S, Sig::evenGrades>(g);
    const auto bv = randomMV<Sig, S, gradeBit(2) & Sig::allGrades>(g);
    const auto v = randomMV<Sig, S, gradeBit(1)>(g);
    CHECK(maxAbsM<S>(rep(blades, ev * bv) - rep(blades, ev) * rep(blades, bv)) <= tol);
    CHECK(maxAbsM<S>(rep(blades, v * ev) - rep(blades, v) * rep(blades, ev)) <= tol);
    CHECK(maxAbsM<S>(rep(blades, ev * ev) - rep(blades, ev) * rep(blades, ev)) <= tol);
  }
}

/// Outer, contractions and scalar product are the grade projections of the geometric product:
/// ⟨a⟩_r ∧ ⟨b⟩_s = ⟨⟨a⟩_r⟨b⟩_s⟩_{r+s}, ⌋ → grade s−r, ⌊ → grade r−s, scalar → grade 0.
template <class Sig, class S> void checkProjections(int trials) {
  using std::abs;
  auto& g = rng(2000 + Sig::p * 100 + Sig::q * 10 + Sig::r);
  const S tol = S(Sig::dim) * Tolerance<S>::identity(16);
  for (int t = 0; t < trials; ++t) {
    const auto a = randomMV<Sig, S, Sig::allGrades>(g);
    const auto b = randomMV<Sig, S, Sig::allGrades>(g);
    Dense<Sig, S> outerW, lcW, rcW;
    for (int r = 0; r <= Sig::n; ++r)
      for (int s = 0; s <= Sig::n; ++s) {
        const auto ab = a.gradeProject(r) * b.gradeProject(s);
        if (r + s <= Sig::n) outerW += ab.gradeProject(r + s);
        if (s >= r) lcW += ab.gradeProject(s - r);
        if (r >= s) rcW += ab.gradeProject(r - s);
      }
    CHECK(maxAbsDiff(a ^ b, outerW) <= tol);
    CHECK(maxAbsDiff(a | b, lcW) <= tol);
    CHECK(maxAbsDiff(rightContraction(a, b), rcW) <= tol);
    CHECK(abs(scalarProduct(a, b) - (a * b).scalarPart()) <= tol);
  }
}

/// Metric-free products of Sig equal those of the Euclidean algebra of the same dimension, where
/// the exterior product is ⟨ab⟩_{r+s} and the join is I·rev((ã I) ∧ (b̃ I)) (Hodge complements).
template <class Sig, class S> void checkExterior(int trials) {
  using E = Signature<Sig::n, 0, 0>;
  auto& g = rng(3000 + Sig::p * 100 + Sig::q * 10 + Sig::r);
  const S tol = S(Sig::dim) * Tolerance<S>::identity(16);
  const auto I = Dense<E, S>::basisBlade(E::pseudoscalar);
  for (int t = 0; t < trials; ++t) {
    const auto a = randomMV<Sig, S, Sig::allGrades>(g);
    const auto b = randomMV<Sig, S, Sig::allGrades>(g);
    Dense<E, S> ae, be;  // same coefficients, Euclidean metric
    for (int i = 0; i < a.size; ++i) {
      ae[i] = a[i];
      be[i] = b[i];
    }
    Dense<E, S> wedgeE;
    for (int r = 0; r <= Sig::n; ++r)
      for (int s = 0; r + s <= Sig::n; ++s)
        wedgeE += (ae.gradeProject(r) * be.gradeProject(s)).gradeProject(r + s);
    const Dense<E, S> rca = ae.reverse() * I, rcb = be.reverse() * I;  // a ∧ rc(a) = I
    const Dense<E, S> joinE = I * Dense<E, S>(rca ^ rcb).reverse();   // lc(x) = I x̃
    const Dense<Sig, S> w = a ^ b, j = a & b;
    S dw(0), dj(0);
    for (int i = 0; i < w.size; ++i) {
      using std::abs;
      dw = std::max<S>(dw, abs(w[i] - wedgeE[i]));
      dj = std::max<S>(dj, abs(j[i] - joinE[i]));
    }
    CHECK(dw <= tol);
    CHECK(dj <= tol);
    // Duality laws: I ∨ b = b, a ∨ I = a (I the pseudoscalar of Sig).
    const auto Is = Dense<Sig, S>::basisBlade(Sig::pseudoscalar);
    CHECK(maxAbsDiff(Is & b, b) == S(0));
    CHECK(maxAbsDiff(a & Is, a) == S(0));
  }
}

template <class Sig, class S> void checkAll(int trials) {
  INFO("Cl(" << Sig::p << "," << Sig::q << "," << Sig::r << ")");
  checkAgainstMatrices<Sig, S>(trials);
  checkProjections<Sig, S>(trials);
  checkExterior<Sig, S>(trials);
}

}  // namespace soma::test::clifford_checks
