// GF §10.2.4: the contraction, perpendiculars, angles, distances, projections, reflections and
// the common perpendicular, each against coordinate geometry; nearly parallel lines on both
// sides of the switch and threshold.
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga common perpendicular: the book's λ construction", "[pga][common-perpendicular]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1303);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 2 : 20;
  for (int t = 0; t < trials; ++t) {
    const Line<S> a = randomLine<S>(g), b = randomLine<S>(g);
    const Line<S> c = commonPerpendicular(a, b);
    const S sn = a.direction().cross(b.direction()).norm();
    // Closest points by coordinates: r1 + s v1, r2 + t v2 with the gap ⟂ both.
    const Vec3<S> r1 = a.pointNearestOrigin(), r2 = b.pointNearestOrigin(), v1 = a.direction(), v2 = b.direction();
    const S k = v1.dot(v2), e1 = v1.dot(r2 - r1), e2 = v2.dot(r2 - r1);
    const S s = (e1 - k * e2) / (S(1) - k * k), u = (k * e1 - e2) / (S(1) - k * k);
    const Vec3<S> c1 = r1 + s * v1, c2 = r2 + u * v2;
    const S tl = tol<S>(1024) / (sn * sn);
    CHECK(abs(c.normSquared().first - S(1)) <= tol<S>(64));
    CHECK(c.isLine(tl));
    CHECK(incidenceResidual(Point<S>(c1), c) <= tl);
    CHECK(incidenceResidual(Point<S>(c2), c) <= tl);
    CHECK(abs((c.element() | a.element()).scalarPart()) <= tl);  // ⟂ both
    CHECK(abs((c.element() | b.element()).scalarPart()) <= tl);
    CHECK(coplanarityResidual(c, a) <= tl);  // meets both
    CHECK(coplanarityResidual(c, b) <= tl);
    CHECK(abs(distance(a, b) - (c1 - c2).norm()) <= tl);
  }
  // Intersecting lines (pitch 0 already): the perpendicular through the intersection point.
  const Vec3<S> o(S(1), S(2), S(3));
  const Line<S> c = commonPerpendicular(Line<S>::throughPoint(o, Vec3<S>(S(1), S(0), S(0))),
                                        Line<S>::throughPoint(o, Vec3<S>(S(0), S(1), S(0))));
  CHECK(clifford::maxAbsDiff(c.element(), Line<S>::throughPoint(o, Vec3<S>(S(0), S(0), S(1))).element()) <= tol<S>(64));
  // Parallel lines: no unique answer; nearly parallel on both sides of rank.
  const S r = Tolerance<S>::rank();
  const Line<S> a = Line<S>::throughPoint(Vec3<S>::Zero(), Vec3<S>(S(1), S(0), S(0)));
  CHECK_THROWS_WITH(commonPerpendicular(a, Line<S>::throughPoint(o, Vec3<S>(S(-1), S(0), S(0)))), Contains("parallel"));
  CHECK_THROWS_AS(commonPerpendicular(a, Line<S>::throughPoint(o, Vec3<S>(S(1), r / S(2), S(0)))), InvalidInput);
  const Line<S> near = commonPerpendicular(a, Line<S>::throughPoint(Vec3<S>(S(0), S(0), S(1)), Vec3<S>(S(1), S(2) * r, S(0))));
  CHECK(maxDiff<S>(near.direction(), Vec3<S>(S(0), S(0), S(1))) <= tol<S>(64));
}

TEMPLATE_TEST_CASE("pga line distance: nearly parallel lines on both sides of the sqrtEpsilon switch",
                   "[pga][metric]", float, double, long double) {
  using S = TestType;
  using std::abs;
  using std::sqrt;
  // ℓ1 = x-axis; ℓ2 through (0, 0, h) with direction (1, s, 0): distance h exactly for every s ≠ 0
  // (the common perpendicular is the z-axis), and h for s = 0.
  const S h = S(3) / S(4);
  const Line<S> a = Line<S>::throughPoint(Vec3<S>::Zero(), Vec3<S>(S(1), S(0), S(0)));
  for (const S f : {S(0), S(1) / S(2), S(2), S(8)}) {
    const S s = f * Tolerance<S>::sqrtEpsilon();
    const Line<S> b = Line<S>::throughPoint(Vec3<S>(S(0), S(0), h), Vec3<S>(S(1), s, S(0)));
    INFO("s = " << toDouble(s));
    CHECK(abs(distance(a, b) - h) <= S(4) * Tolerance<S>::sqrtEpsilon());
  }
  CHECK_THROWS_AS(distance(a, Line<S>(Vec3<S>::Zero(), Vec3<S>(S(1), S(0), S(0)))), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
