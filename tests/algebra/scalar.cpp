// The scalar ladder itself: names, casts that keep every bit, text round trips, π, tolerances.
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

TEST_CASE("scalar names parse and print", "[scalar]") {
  for (auto name : {"float", "double", "long-double", "float128", "mpfr"}) {
    const auto k = parseScalarKind(name);
    REQUIRE(k.has_value());
    CHECK(scalarName(*k) == name);
  }
  CHECK_FALSE(parseScalarKind("quad").has_value());
  CHECK_FALSE(parseScalarKind("").has_value());
}

TEMPLATE_TEST_CASE("scalar ladder: epsilon, π and text round trip", "[scalar]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const S eps = Tolerance<S>::epsilon();
  CHECK(S(1) + eps != S(1));
  CHECK(S(1) + eps / S(4) == S(1));
  // sin(π) is the rounding error of π in S: at most one ulp of π.
  using std::sin;
  using std::abs;
  CHECK(abs(sin(pi<S>())) <= S(4) * eps);
  // Text round trip keeps every bit.
  const S x = S(1) / S(3);
  CHECK(fromString<S>(toString(x)) == x);
  // A Taylor switch lies between eps and 1 and shrinks with eps.
  const S p3 = Tolerance<S>::precision(3);
  CHECK(p3 > eps);
  CHECK(p3 < S(1));
  using std::pow;
  CHECK(abs(pow(p3, 4) - eps) <= S(16) * eps * eps);
}

TEST_CASE("scalarCast keeps the bits of the narrower type", "[scalar]") {
  const __float128 third = __float128(1) / 3;
  const mpreal m = scalarCast<mpreal>(third);
  CHECK(scalarCast<__float128>(m) == third);
  // mpreal 1/3 to float128 rounds to the float128 1/3.
  CHECK(scalarCast<__float128>(mpreal(1) / 3) == third);
  CHECK(scalarCast<double>(mpreal(1) / 3) == 1.0 / 3.0);
  CHECK(toDouble(third) == 1.0 / 3.0);
}

TEST_CASE("withScalar dispatches on the kind", "[scalar]") {
  for (auto k : {ScalarKind::Float, ScalarKind::Double, ScalarKind::LongDouble,
                 ScalarKind::Float128, ScalarKind::Mpfr}) {
    const int digits = withScalar(k, []<class S>() { return soma::digits<S>(); });
    const int expected[] = {24, 53, 64, 113, 256};
    CHECK(digits == expected[int(k)]);
  }
}

TEST_CASE("mpfr precision is settable and validated", "[scalar]") {
  setMpfrBits(512);
  CHECK(soma::digits<mpreal>() == 512);
  CHECK(Tolerance<mpreal>::epsilon() < mpreal("1e-150"));
  setMpfrBits(256);
  CHECK_THROWS_AS(setMpfrBits(0), std::invalid_argument);
}

}  // namespace SOMA_UNITY_ID
