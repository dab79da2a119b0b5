// Cl(p,q,r) (GF §9.1): the book's multiplication tables (ℂ, 𝔻, ℍ), Cl(p,q,r) ≅ Cl⁺(p,q+1,r),
// the zero divisor, conjugation and involution rules, associativity and reversal identities over
// fixed-seed random elements for all five scalars, inverses and errors, bivector exponentials.
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

/// Algebra identities over random elements (GF-9.1-conjugation-involution).
template <class Sig, class S> void checkIdentities(int trials) {
  INFO("Cl(" << Sig::p << "," << Sig::q << "," << Sig::r << ")");
  auto& g = rng(4000 + Sig::p * 100 + Sig::q * 10 + Sig::r);
  const S tol = S(Sig::dim) * Tolerance<S>::identity(16);
  for (int t = 0; t < trials; ++t) {
    const auto a = randomMV<Sig, S, Sig::allGrades>(g);
    const auto b = randomMV<Sig, S, Sig::allGrades>(g);
    const auto c = randomMV<Sig, S, Sig::allGrades>(g);
    CHECK(maxAbsDiff((a * b) * c, a * (b * c)) <= S(4) * tol);        // associativity
    CHECK(maxAbsDiff((a ^ b) ^ c, a ^ (b ^ c)) <= S(4) * tol);        // exterior associative
    CHECK(maxAbsDiff((a & b) & c, a & (b & c)) <= S(4) * tol);        // join associative
    CHECK(maxAbsDiff(~(a * b), ~b * ~a) <= tol);                      // reversal anti-automorphism
    CHECK(maxAbsDiff((a * b).conjugate(), b.conjugate() * a.conjugate()) <= tol);  // (ab)* = b*a*
    CHECK(maxAbsDiff((a * b).involute(), a.involute() * b.involute()) <= tol);     // α homomorphism
    CHECK(maxAbsDiff(a.involute().conjugate(), a.conjugate().involute()) == S(0));
    CHECK(maxAbsDiff(~(a ^ b), ~b ^ ~a) <= tol);
    // a ⌋ (b ⌋ c) = (a ∧ b) ⌋ c
    CHECK(maxAbsDiff(a | (b | c), (a ^ b) | c) <= S(4) * tol);
    // Grade-sparse and dense products agree: Even · Even stays even.
    const auto e = randomMV<Sig, S, Sig::evenGrades>(g);
    const auto f = randomMV<Sig, S, Sig::evenGrades>(g);
    const Dense<Sig, S> ed(e), fd(f);
    const auto ef = e * f;
    STATIC_REQUIRE((std::remove_cvref_t<decltype(ef)>::mask & Sig::oddGrades) == 0);
    CHECK(maxAbsDiff(ef, ed * fd) == S(0));
  }
}

}  // namespace

TEMPLATE_TEST_CASE("clifford algebra identities over random elements", "[clifford]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  if constexpr (std::is_same_v<S, mpfr::mpreal>) {
    checkIdentities<Signature<0, 3, 1>, S>(2);
    checkIdentities<Signature<1, 1, 0>, S>(2);
  } else {
    checkIdentities<Signature<0, 3, 1>, S>(4);
    checkIdentities<Signature<1, 1, 0>, S>(4);
    checkIdentities<Signature<2, 1, 1>, S>(4);
    if constexpr (!std::is_same_v<S, __float128>) checkIdentities<Signature<0, 6, 2>, S>(1);
  }
}

TEMPLATE_TEST_CASE("clifford: the book's small algebras and even subalgebras", "[clifford]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  // GF-9.1-small-algebras: Cl(0,1,0) ≅ ℂ, (x + y e)(w + z e) = (xw − yz) + (xz + yw) e.
  {
    using C = Signature<0, 1, 0>;
    Dense<C, S> u, v;
    u[0] = S(3), u[1] = S(-2), v[0] = S(5), v[1] = S(7);
    const auto uv = u * v;
    CHECK(uv[0] == S(3 * 5 - (-2) * 7));
    CHECK(uv[1] == S(3 * 7 + (-2) * 5));
  }
  // Cl(0,0,1) = 𝔻: e² = 0, (x + y e)(w + z e) = xw + (xz + yw) e.
  {
    using D = Signature<0, 0, 1>;
    const auto e = Vector<D, S>::generator(0);
    CHECK((e * e).maxAbs() == S(0));
    Dense<D, S> u, v;
    u[0] = S(3), u[1] = S(-2), v[0] = S(5), v[1] = S(7);
    CHECK(maxAbsDiff(u * v, Dense<D, S>(S(15)) + Vector<D, S>(e * S(21 - 10))) == S(0));
    CHECK_THROWS_WITH(inverse(e), Contains("no inverse"));
  }
  // Cl(0,2,0) ≅ ℍ: i ↦ e1, j ↦ e2, k ↦ e1e2; i² = j² = k² = −1, ij = k, jk = i, ki = j, ij = −ji.
  {
    using H = Signature<0, 2, 0>;
    const Dense<H, S> i = Vector<H, S>::generator(0), j = Vector<H, S>::generator(1);
    const Dense<H, S> k = i * j, m1(S(-1));
    CHECK(maxAbsDiff(i * i, m1) == S(0));
    CHECK(maxAbsDiff(j * j, m1) == S(0));
    CHECK(maxAbsDiff(k * k, m1) == S(0));
    CHECK(maxAbsDiff(j * k, i) == S(0));
    CHECK(maxAbsDiff(k * i, j) == S(0));
    CHECK(maxAbsDiff(j * i, -k) == S(0));
    // GF-9.1-conjugation-involution: (a + bi + cj + dk)* = a − bi − cj − dk.
    Dense<H, S> q;
    q[0] = S(1), q[1] = S(2), q[2] = S(3), q[3] = S(4);
    const auto qc = q.conjugate();
    CHECK((qc[0] == S(1) && qc[1] == S(-2) && qc[2] == S(-3) && qc[3] == S(-4)));
    CHECK(maxAbsDiff(q * qc, Dense<H, S>(S(30))) == S(0));
  }
  // Conjugation signs by grade: + − − + + (grades 0..4), xx* = −x₁² … + x_{p+1}² … (GF §9.1).
  {
    using G = Signature<1, 2, 1>;
    const Dense<G, S> all = [] {
      Dense<G, S> d;
      for (int i = 0; i < d.size; ++i) d[i] = S(1);
      return d;
    }();
    const auto c = all.conjugate();
    const int want[5] = {1, -1, -1, 1, 1};
    for (int i = 0; i < c.size; ++i) CHECK(c[i] == S(want[bladeGrade(c.blade(i))]));
    Vector<G, S> x;
    x[0] = S(2), x[1] = S(3), x[2] = S(5), x[3] = S(7);
    CHECK(maxAbsDiff(x * x.conjugate(), Dense<G, S>(S(-4 + 9 + 25)))== S(0));
  }
  // GF-9.1-zero-divisor: in Cl(0,3,0), (e1 + e2e3)(e2 + e1e3) = 0; neither factor is invertible.
  {
    using G = Signature<0, 3, 0>;
    const Dense<G, S> e1 = Vector<G, S>::generator(0), e2 = Vector<G, S>::generator(1),
                      e3 = Vector<G, S>::generator(2);
    const Dense<G, S> a = e1 + e2 * e3, b = e2 + e1 * e3;
    CHECK((a * b).maxAbs() == S(0));
    CHECK_THROWS_AS(inverse(a), InvalidInput);
    CHECK_THROWS_WITH(inverse(b), Contains("zero divisor"));
    CHECK_THROWS_WITH(versorInverse(a), Contains("not an invertible versor"));
  }
  // GF-9.1-grading-even-subalgebra: Cl(p,q,r) ≅ Cl⁺(p,q+1,r) via e_i ↦ e_i e₀, e₀² = −1.
  // The extra generator sits after the q negative ones; images satisfy the original relations
  // and the map on all blades is a homomorphism onto the even subalgebra.
  auto checkEvenIso = []<class Small, class Big>(Small*, Big*) {
    const int e0 = Small::p + Small::q;  // index of the new negative generator in Big
    auto gen = [&](int i) {               // image of generator i of Small
      const int bi = i < e0 ? i : i + 1;
      return Even<Big, S>(Dense<Big, S>(Vector<Big, S>::generator(bi) *
                                        Vector<Big, S>::generator(e0)).template grades<Big::evenGrades>());
    };
    std::vector<Even<Big, S>> img(Small::dim);
    for (int b = 0; b < Small::dim; ++b) {
      Even<Big, S> m(S(1));
      for (int i = 0; i < Small::n; ++i)
        if (b & (1 << i)) m = Even<Big, S>(m * gen(i));
      img[b] = m;
    }
    for (int i = 0; i < Small::n; ++i)
      for (int j = 0; j < Small::n; ++j) {
        const auto ac = gen(i) * gen(j) + gen(j) * gen(i);
        CHECK(maxAbsDiff(ac, Even<Big, S>(S(i == j ? 2 * Small::square(i) : 0))) == S(0));
      }
    auto& g = rng(77);
    auto phi = [&](const Dense<Small, S>& a) {
      Even<Big, S> m;
      for (int i = 0; i < a.size; ++i) m += img[a.blade(i)] * a[i];
      return m;
    };
    const auto a = randomMV<Small, S, Small::allGrades>(g);
    const auto b = randomMV<Small, S, Small::allGrades>(g);
    CHECK(maxAbsDiff(phi(a * b), phi(a) * phi(b)) <= S(Big::dim) * Tolerance<S>::identity(16));
    // dimension count: dim Cl⁺(p,q+1,r) = 2^{p+q+r} = dim Cl(p,q,r), and the images are independent
    int nonzero = 0;
    for (int b2 = 0; b2 < Small::dim; ++b2) nonzero += img[b2].maxAbs() > S(0);
    CHECK(Even<Big, S>::size == Small::dim);
    CHECK(nonzero == Small::dim);
  };
  checkEvenIso((Signature<1, 1, 1>*)nullptr, (Signature<1, 2, 1>*)nullptr);
  checkEvenIso((Signature<0, 2, 0>*)nullptr, (Signature<0, 3, 0>*)nullptr);  // Cl⁺(0,3,0) ≅ ℍ
  checkEvenIso((Signature<0, 2, 1>*)nullptr, (Signature<0, 3, 1>*)nullptr);  // Cl⁺(0,3,1)
}

}  // namespace SOMA_UNITY_ID
