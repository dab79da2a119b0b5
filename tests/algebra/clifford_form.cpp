// Clifford algebras of non-diagonal quadratic forms (GF §9.1, GF-9.1-clifford-definition-signature):
// soma computes in Cl(p,q,r) after Sylvester's congruence (quadratic_form.hpp). Checked here
// against a direct evaluation in the basis of the original generators x_j that never
// diagonalises Q: x_i · x_J = x_i ∧ x_J + x_i ⌋_Q x_J (Chevalley), and x_J = x_{j1} ∧ x_{J'} =
// x_{j1} x_{J'} − x_{j1} ⌋_Q x_{J'} for the left multiplication by a blade.
// double and long double only: the eigen-decomposition for three scalars costs ~70 s of compile.
#include "soma/algebra/clifford/quadratic_form.hpp"
#include "support/scalars.hpp"

#include <bit>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::clifford;
using namespace soma::test;
using Catch::Matchers::Contains;

namespace {

template <class S, int D> using Coeffs = std::array<S, D>;

/// x_i · a in the x-basis (a on x-blades by bitmask), Q the bilinear form.
template <class S, int D>
Coeffs<S, D> vecTimes(const FormMatrix<S>& Q, int i, const Coeffs<S, D>& a) {
  Coeffs<S, D> out{};
  for (int J = 0; J < D; ++J) {
    if (a[std::size_t(J)] == S(0)) continue;
    const int below = std::popcount(unsigned(J) & ((1u << i) - 1u));
    if (!(J & (1 << i)))  // x_i ∧ x_J
      out[std::size_t(J | (1 << i))] += (below & 1 ? -a[std::size_t(J)] : a[std::size_t(J)]);
    int m = 0;  // x_i ⌋ x_J = Σ_m (−1)^m Q(i, j_m) x_{J∖j_m}
    for (int j = 0; (1 << j) <= J; ++j)
      if (J & (1 << j)) {
        const S t = Q(i, j) * a[std::size_t(J)];
        out[std::size_t(J & ~(1 << j))] += (m & 1) ? -t : t;
        ++m;
      }
  }
  return out;
}
/// x_J · b (J a bitmask of x-generators).
template <class S, int D>
Coeffs<S, D> bladeTimes(const FormMatrix<S>& Q, int J, const Coeffs<S, D>& b) {
  if (J == 0) return b;
  const int j1 = std::countr_zero(unsigned(J));
  const int rest = J & ~(1 << j1);
  Coeffs<S, D> out = vecTimes<S, D>(Q, j1, bladeTimes<S, D>(Q, rest, b));
  int m = 0;
  for (int j = 0; (1 << j) <= rest; ++j)
    if (rest & (1 << j)) {
      const Coeffs<S, D> t = bladeTimes<S, D>(Q, rest & ~(1 << j), b);
      const S f = (m & 1) ? -Q(j1, j) : Q(j1, j);
      for (int k = 0; k < D; ++k) out[std::size_t(k)] -= f * t[std::size_t(k)];
      ++m;
    }
  return out;
}
template <class S, int D>
Coeffs<S, D> directProduct(const FormMatrix<S>& Q, const Coeffs<S, D>& a, const Coeffs<S, D>& b) {
  Coeffs<S, D> out{};
  for (int J = 0; J < D; ++J) {
    if (a[std::size_t(J)] == S(0)) continue;
    const Coeffs<S, D> t = bladeTimes<S, D>(Q, J, b);
    for (int k = 0; k < D; ++k) out[std::size_t(k)] += a[std::size_t(J)] * t[std::size_t(k)];
  }
  return out;
}

/// Q = A diag(d) Aᵀ with A random (well conditioned: I + 0.3·uniform) → known inertia.
template <class S> FormMatrix<S> randomForm(std::mt19937_64& g, const std::vector<int>& d) {
  const int n = int(d.size());
  FormMatrix<S> A = FormMatrix<S>::Identity(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) += S(3) / S(10) * uniform<S>(g);
  FormMatrix<S> Dm = FormMatrix<S>::Zero(n, n);
  for (int i = 0; i < n; ++i) Dm(i, i) = S(d[std::size_t(i)]);
  return A * Dm * A.transpose();
}

template <class Sig, class S> void checkForm(const std::vector<int>& d, int trials) {
  INFO("Cl(" << Sig::p << "," << Sig::q << "," << Sig::r << ")");
  constexpr int D = Sig::dim;
  auto& g = rng(5000 + Sig::p * 100 + Sig::q * 10 + Sig::r);
  const FormMatrix<S> Q = randomForm<S>(g, d);
  const FormBasis<Sig, S> fb(Q);
  const auto& c = fb.congruence();
  // Sylvester: M Q Mᵀ = diag(1…, −1…, 0…) and M N = I.
  FormMatrix<S> want = FormMatrix<S>::Zero(Sig::n, Sig::n);
  for (int i = 0; i < Sig::n; ++i) want(i, i) = S(Sig::square(i));
  const S tol = S(64) * Tolerance<S>::identity(64);
  CHECK((c.M * Q * c.M.transpose() - want).cwiseAbs().maxCoeff() <= tol);
  CHECK((c.M * c.N - FormMatrix<S>::Identity(Sig::n, Sig::n)).cwiseAbs().maxCoeff() <= tol);
  // The book's defining relations, evaluated in Cl(p,q,r): x_i x_j + x_j x_i = 2 Q_ij.
  for (int i = 0; i < Sig::n; ++i)
    for (int j = 0; j < Sig::n; ++j) {
      const auto xi = fb.generator(i), xj = fb.generator(j);
      const auto ac = Dense<Sig, S>(xi * xj + xj * xi);
      CHECK(abs(ac.scalarPart() - S(2) * Q(i, j)) <= tol);
      CHECK(ac.template grades<gradeBit(2)>().maxAbs() <= tol);
    }
  // General products: diagonal algebra + change of basis = direct evaluation in the x-basis.
  for (int t = 0; t < trials; ++t) {
    Coeffs<S, D> a{}, b{};
    for (auto& v : a) v = uniform<S>(g);
    for (auto& v : b) v = uniform<S>(g);
    // round trip of the basis change
    const auto ra = fb.toFormBasis(fb.fromFormBasis(a));
    S err(0);
    for (int k = 0; k < D; ++k) err = std::max<S>(err, abs(ra[std::size_t(k)] - a[std::size_t(k)]));
    CHECK(err <= tol);
    const auto viaDiag = fb.toFormBasis(Dense<Sig, S>(fb.fromFormBasis(a) * fb.fromFormBasis(b)));
    const auto direct = directProduct<S, D>(Q, a, b);
    err = S(0);
    for (int k = 0; k < D; ++k)
      err = std::max<S>(err, abs(viaDiag[std::size_t(k)] - direct[std::size_t(k)]));
    CHECK(err <= S(D) * tol);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("clifford algebra of a non-diagonal quadratic form via Sylvester's congruence",
                   "[clifford]", double, long double) {
  using S = TestType;
  checkForm<Signature<2, 1, 0>, S>({1, -1, 1}, 4);
  checkForm<Signature<1, 2, 1>, S>({-1, 0, 1, -1}, 4);
  checkForm<Signature<0, 3, 1>, S>({0, -1, -1, -1}, 4);  // degenerate, as in GF §9.2
  // Wrong inertia or a non-symmetric Q: InvalidInput naming the defect.
  FormMatrix<S> Q = FormMatrix<S>::Identity(3, 3);
  CHECK_THROWS_WITH((FormBasis<Signature<2, 1, 0>, S>(Q)), Contains("inertia (p,q,r) = (3,0,0)"));
  Q(0, 1) = S(1);
  CHECK_THROWS_WITH((FormBasis<Signature<2, 1, 0>, S>(Q)), Contains("not symmetric"));
}

}  // namespace SOMA_UNITY_ID
