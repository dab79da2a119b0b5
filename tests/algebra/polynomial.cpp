// Real roots of polynomials (algebra/polynomial.hpp): products of known factors, double roots,
// complex pairs near the real axis on both sides of the acceptance test, degree drops.
#include "soma/algebra/polynomial.hpp"

#include "soma/algebra/errors.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
template <class S> std::vector<S> product(const std::vector<std::vector<S>>& factors) {
  std::vector<S> p{S(1)};
  for (const auto& f : factors) {
    std::vector<S> r(p.size() + f.size() - 1, S(0));
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < f.size(); ++j) r[i + j] += p[i] * f[j];
    p = r;
  }
  return p;
}
}  // namespace

TEMPLATE_TEST_CASE("polynomial: real roots of products of known factors", "[polynomial]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  // (x − 1)(x − 2)(x + 3)(x² + 1)(x − 1/2): real roots −3, 1/2, 1, 2; one complex pair ±i.
  const auto p = product<S>({{S(-1), S(1)}, {S(-2), S(1)}, {S(3), S(1)}, {S(1), S(0), S(1)}, {S(-1) / S(2), S(1)}});
  const auto r = realRoots(p);
  REQUIRE(r.size() == 4);
  const S expected[4] = {S(-3), S(1) / S(2), S(1), S(2)};
  for (int i = 0; i < 4; ++i) CHECK(abs(r[i] - expected[i]) <= Tolerance<S>::identity(64) * (S(1) + abs(expected[i])));
  CHECK(polynomialRoots(p).size() == 6);
}

TEMPLATE_TEST_CASE("polynomial: a double root is returned twice — a complex pair near the axis is not real",
                   "[polynomial]", SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs;
  using std::sqrt;
  // (x − 0.3)² (x + 2)(x − 5): double root at 0.3.
  const auto d = product<S>({{S(-3) / S(10), S(1)}, {S(-3) / S(10), S(1)}, {S(2), S(1)}, {S(-5), S(1)}});
  const auto r = quarticRealRoots<S>({d[0], d[1], d[2], d[3], d[4]});
  REQUIRE(r.size() == 4);
  CHECK(abs(r[1] - S(3) / S(10)) <= sqrt(Tolerance<S>::epsilon()) * S(16));
  CHECK(abs(r[2] - S(3) / S(10)) <= sqrt(Tolerance<S>::epsilon()) * S(16));
  // (x − 0.3)² + y² with y = 32 √eps (inside the √eps imaginary pre-filter): |p(0.3)| = 10.8 y²
  // is far above round-off, so the pair is complex and rejected.
  const S y = S(32) * sqrt(Tolerance<S>::epsilon());
  const auto c = product<S>({{S(9) / S(100) + y * y, S(-6) / S(10), S(1)}, {S(2), S(1)}, {S(-5), S(1)}});
  CHECK(quarticRealRoots<S>({c[0], c[1], c[2], c[3], c[4]}).size() == 2);
}

TEST_CASE("polynomial: degree drops, quadratic without cancellation, bad input", "[polynomial]") {
  // Leading coefficient 0: the cubic's roots.
  const auto r = quarticRealRoots<double>({-6, 11, -6, 1, 0});
  REQUIRE(r.size() == 3);
  CHECK(r[0] == Approx(1));
  CHECK(r[2] == Approx(3));
  // x² − 1e8 x + 1: the small root 1e-8 keeps full relative accuracy.
  const auto q = quadraticRealRoots<double>(1, -1e8, 1);
  REQUIRE(q.size() == 2);
  CHECK(std::abs(q[0] - 1e-8) <= 1e-8 * 1e-15);
  CHECK(quadraticRealRoots<double>(1, 0, 1).empty());
  CHECK_THROWS_AS(realRoots<double>({0, 0, 0}), InvalidInput);
  CHECK_THROWS_WITH(realRoots<double>({1, std::nan(""), 1}), Catch::Contains("coefficient 1"));
}

}  // namespace SOMA_UNITY_ID
