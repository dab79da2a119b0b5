// Cl(p,q,r) (GF §9.1, §9.3): general and versor inverses with their errors, norms, and the
// exponential of bivectors — closed forms (simple bivectors, Cl(0,3,1) with its nilpotent
// pseudoscalar part) against power series and products of commuting exponentials.
#include "soma/algebra/clifford/multivector.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::clifford;
using namespace soma::test;
using Catch::Matchers::Contains;

namespace {
template <class Sig, class S, GradeMask M> Multivector<Sig, S, M> randomMV(std::mt19937_64& g) {
  Multivector<Sig, S, M> a;
  for (int i = 0; i < a.size; ++i) a[i] = uniform<S>(g);
  return a;
}
}  // namespace

TEMPLATE_TEST_CASE("clifford inverses, norms and bivector exponentials", "[clifford]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::cos;
  using std::sin;
  auto& g = rng(99);
  const S tol = Tolerance<S>::identity(64);
  // General inverse in a non-degenerate algebra: a a⁻¹ = a⁻¹ a = 1.
  {
    using G = Signature<2, 1, 0>;
    const auto a = randomMV<G, S, G::allGrades>(g);
    const auto ai = inverse(a);
    const S sc = S(1) + ai.maxAbs();
    CHECK(maxAbsDiff(a * ai, Dense<G, S>(S(1))) <= S(G::dim) * sc * tol);
    CHECK(maxAbsDiff(ai * a, Dense<G, S>(S(1))) <= S(G::dim) * sc * tol);
  }
  // GF-9.1-pin-spin: rotation about e3 by θ in Cl(0,3,0): g = exp(θ/2 e1e2),
  // g e1 g* = cos θ e1 + sin θ e2, g e2 g* = −sin θ e1 + cos θ e2, g e3 g* = e3.
  {
    using G = Signature<0, 3, 0>;
    const S th = S(7) / S(10);
    Bivector<G, S> B;
    B.setCoeff(0b011, th / S(2));
    const auto r = exp(B);
    CHECK(abs(r.coeff(0) - cos(th / S(2))) <= tol);
    CHECK(abs(r.coeff(0b011) - sin(th / S(2))) <= tol);
    const auto e1 = Vector<G, S>::generator(0), e2 = Vector<G, S>::generator(1),
               e3 = Vector<G, S>::generator(2);
    CHECK(maxAbsDiff(r * e1 * r.conjugate(), e1 * cos(th) + e2 * sin(th)) <= tol);
    CHECK(maxAbsDiff(r * e2 * r.conjugate(), e1 * (-sin(th)) + e2 * cos(th)) <= tol);
    CHECK(maxAbsDiff(r * e3 * r.conjugate(), e3) <= tol);
    CHECK(abs(norm(r) - S(1)) <= tol);
    CHECK(maxAbsDiff(versorInverse(r), r.reverse()) <= tol);
    // θ = 2π gives −1 (double cover).
    Bivector<G, S> B2;
    B2.setCoeff(0b011, pi<S>());
    CHECK(maxAbsDiff(exp(B2), Even<G, S>(S(-1))) <= S(4) * tol);
  }
  // Cl(0,3,1) bivectors (GF-9.3-exp-log): closed form with the nilpotent grade-4 part vs the
  // Taylor series summed here, and the motor is unit: g g̃ = 1.
  {
    using G = Signature<0, 3, 1>;
    for (int t = 0; t < 4; ++t) {
      auto B = randomMV<G, S, gradeBit(2)>(g);
      if (t == 3) B *= S(1) / S(1000);  // small-angle branch
      const auto m = exp(B);
      Even<G, S> sum(S(1)), term(S(1));
      for (int k = 1; k < 60; ++k) {
        term = Even<G, S>(term * B) / S(k);
        sum += term;
      }
      CHECK(maxAbsDiff(m, sum) <= S(8) * tol);
      CHECK(maxAbsDiff(m * m.reverse(), Even<G, S>(S(1))) <= S(8) * tol);
      CHECK(m.coeff(0b1111) != S(0));  // the pseudoscalar (dual) part is present
    }
  }
  // Non-simple bivector of Cl(4,0,0) (series path): B = a e01 + b e23, two commuting planes,
  // exp B = exp(a e01) exp(b e23) = (cos a + sin a e01)(cos b + sin b e23).
  {
    using G = Signature<4, 0, 0>;
    const S a = S(13) / S(10), b = S(-7) / S(10);
    Bivector<G, S> B;
    B.setCoeff(0b0011, a);
    B.setCoeff(0b1100, b);
    Even<G, S> A(S(cos(a))), C(S(cos(b)));
    A.setCoeff(0b0011, sin(a));
    C.setCoeff(0b1100, sin(b));
    CHECK(maxAbsDiff(exp(B), A * C) <= S(8) * tol);
  }
  // Simple hyperbolic bivector of Cl(1,1,0): (e0e1)² = +1, exp(φ e01) = cosh φ + sinh φ e01.
  {
    using G = Signature<1, 1, 0>;
    using std::cosh;
    using std::sinh;
    const S phi = S(3) / S(4);
    Bivector<G, S> B;
    B.setCoeff(0b11, phi);
    const auto m = exp(B);
    CHECK(abs(m.coeff(0) - cosh(phi)) <= tol);
    CHECK(abs(m.coeff(0b11) - sinh(phi)) <= tol);
  }
  // Null vector of Cl(0,3,1) has no inverse; the versor inverse names the defect.
  {
    using G = Signature<0, 3, 1>;
    const auto e = Vector<G, S>::generator(3);
    CHECK_THROWS_WITH(versorInverse(e), Contains("not a nonzero scalar"));
    CHECK_THROWS_AS(inverse(e), InvalidInput);
    using V = Vector<G, S>;
    CHECK_THROWS_WITH(V::generator(4), Contains("outside [0, 4)"));
    CHECK_THROWS_WITH(V::basisBlade(0b11), Contains("not stored"));
  }
}

}  // namespace SOMA_UNITY_ID
