// The regulus through three skew lines (lines/three_line_regulus.hpp, GF §6.5.1): against the
// book's reguli of x² + y² − z² = 1 and against Regulus (a generator swept about an axis).
#include "soma/geometry/lines/regulus.hpp"
#include "soma/geometry/lines/three_line_regulus.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;

namespace {
template <class S> S tol(int ulps = 4096) { return Tolerance<S>::identity(ulps); }
// |a − λb| for the best λ: zero iff a and b are the same line (a Plücker line and its negative,
// or any multiple, are one line).
template <class S> S lineGap(const Vec6<S>& a, const Vec6<S>& b) {
  const Vec6<S> u = a / a.norm(), v = b / b.norm();
  return std::min(S((u - v).norm()), S((u + v).norm()));
}
}  // namespace

TEMPLATE_TEST_CASE("Three lines of the book's family 1 give family 1 of x²+y²−z²=1 (GF-6.5.1)", "[lines][regulus]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const Vec6<S> l1 = bookRegulusLine(1, S(3) / S(10)), l2 = bookRegulusLine(1, S(14) / S(10)),
                l3 = bookRegulusLine(1, S(26) / S(10));
  const ThreeLineRegulus<S> r{PluckerLine<S>(l1), PluckerLine<S>(l2), PluckerLine<S>(l3)};
  // The given lines at their parameters, up to sign.
  CHECK(lineGap<S>(r.member(r.givenParameter(0)), l1) <= tol<S>());
  CHECK(lineGap<S>(r.member(r.givenParameter(1)), l2) <= tol<S>());
  CHECK(lineGap<S>(r.member(r.givenParameter(2)), l3) <= tol<S>());
  for (int k = 0; k < 12; ++k) {
    const S t = S(k) * pi<S>() / S(12);
    const Vec6<S> m = r.member(t);
    REQUIRE(abs(kleinValue(m)) <= tol<S>());
    // Family 1: p01 − p23 = p02 − p31 = p03 + p12 = 0 (linear, so any multiple).
    REQUIRE(abs(m(0) - m(3)) + abs(m(1) - m(4)) + abs(m(2) + m(5)) <= tol<S>());
    // It meets every line of the other family.
    for (const S& th : {S(0), S(1), S(-2)}) REQUIRE(abs(reciprocalProduct(m, bookRegulusLine(2, th))) <= tol<S>());
    // Its points lie on the hyperboloid.
    const PluckerLine<S> l(m);
    for (const S& mu : {S(-1), S(0), S(2)}) {
      const Vec3<S> p = l.pointAt(mu);
      REQUIRE(abs(p(0) * p(0) + p(1) * p(1) - p(2) * p(2) - S(1)) <= tol<S>(16384));
    }
    REQUIRE(r.contains(m));
  }
  CHECK(r.contains(bookRegulusLine(1, S(-1))));
  CHECK_FALSE(r.contains(bookRegulusLine(2, S(-1))));  // a line of the other family is not a member
}

TEMPLATE_TEST_CASE("Three generators of a swept regulus give that regulus (GF-6.5.1)", "[lines][regulus]", double,
                   long double) {
  using S = TestType;
  auto& g = rng(61);
  for (int k = 0; k < 10; ++k) {
    const PluckerLine<S> axis = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g), uniformVec<S, 3>(g));
    const PluckerLine<S> l0 = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g), uniformVec<S, 3>(g));
    const Regulus<S> swept(axis, l0);
    const ThreeLineRegulus<S> r(swept.generator(S(0)), swept.generator(S(2)), swept.generator(S(4)));
    for (int j = 0; j < 8; ++j) {
      const S t = uniform<S>(g, 0, 3);
      const PluckerLine<S> m(r.member(t));
      if (m.isAtInfinity()) continue;
      for (const S& mu : {S(-1), S(1)}) {
        const Vec3<S> p = m.pointAt(mu);
        REQUIRE(abs(swept.implicit(p)) <= tol<S>(1 << 16) * (S(1) + p.squaredNorm()));
      }
      REQUIRE(r.contains(swept.generator(uniform<S>(g, -3, 3)).coords()));
    }
  }
}

TEST_CASE("Three lines that meet or are parallel are not a regulus", "[lines][regulus]") {
  const auto x = PluckerLine<double>::pointDirection({0, 0, 0}, {1, 0, 0});
  const auto y = PluckerLine<double>::pointDirection({0, 0, 0}, {0, 1, 0});
  const auto z = PluckerLine<double>::pointDirection({0, 0, 5}, {1, 1, 0});
  const auto xp = PluckerLine<double>::pointDirection({0, 3, 1}, {1, 0, 0});
  CHECK_THROWS_WITH(ThreeLineRegulus<double>(x, y, z), Catch::Contains("lines 1 and 2 meet or are parallel"));
  CHECK_THROWS_WITH(ThreeLineRegulus<double>(x, z, xp), Catch::Contains("lines 1 and 3 meet or are parallel"));
}

}  // namespace SOMA_UNITY_ID
