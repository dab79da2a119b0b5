// Relative position of two Plücker lines (GF §6.1, §6.4, §9.4): angle, distance, common
// perpendicular, parallel / intersecting thresholds on both sides, far and tiny lines.
#include "soma/geometry/lines/line.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
template <class S> S tol(int ulps = 512) { return Tolerance<S>::identity(ulps); }
}  // namespace

TEMPLATE_TEST_CASE("Two lines: angle, distance, common perpendicular (GF-6.1, 6.4, 9.4)", "[lines][relation]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(15);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 8 : 100;
  for (int k = 0; k < n; ++k) {
    const PluckerLine<S> a = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g, -2, 2), uniformVec<S, 3>(g));
    const PluckerLine<S> b = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g, -2, 2), uniformVec<S, 3>(g));
    const LineRelation<S> r = relation(a, b);
    REQUIRE(r.kind == LineRelationKind::Skew);
    REQUIRE(a.contains(r.footA, tol<S>(4096)));
    REQUIRE(b.contains(r.footB, tol<S>(4096)));
    const Vec3<S> p = r.footB - r.footA;
    REQUIRE(abs(p.dot(a.unitDirection())) <= tol<S>(8192));
    REQUIRE(abs(p.dot(b.unitDirection())) <= tol<S>(8192));
    REQUIRE(abs(p.norm() - r.distance) <= tol<S>(8192));
    REQUIRE(abs(p.dot(r.perpendicularDirection) - r.signedDistance) <= tol<S>(8192));
    // ⟨â, b̂⟩ = −d sin α (GF-6.4-reciprocal-product-example).
    using std::sin;
    REQUIRE(abs(reciprocalProduct(a.normalized().coords(), b.normalized().coords()) + r.signedDistance * sin(r.angle)) <= tol<S>(4096));
    // Invariance under a rigid motion.
    const SE3<S> x = SE3Tangent<S>(uniformVec<S, 6>(g)).exp();
    const LineRelation<S> rx = relation(a.transformed(x), b.transformed(x));
    REQUIRE(abs(rx.signedDistance - r.signedDistance) <= tol<S>(8192));
    REQUIRE(abs(rx.angle - r.angle) <= tol<S>(8192));
    // A line through a point of a meets it (exact intersecting case).
    const PluckerLine<S> c = PluckerLine<S>::pointDirection(a.pointAt(uniform<S>(g)), uniformVec<S, 3>(g));
    REQUIRE(meet(a, c, tol<S>(1024)));
    REQUIRE(relation(a, c).kind == LineRelationKind::Intersecting);
    REQUIRE_FALSE(meet(a, b, tol<S>(1024)));
  }
}

TEMPLATE_TEST_CASE("Two lines: book example ⟨s₁,s₂⟩ = −l sin φ and the extremes", "[lines][relation]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  const S l = S(17) / S(10), phi = S(9) / S(10);
  Vec6<S> s1, s2;
  s1 << S(1), S(0), S(0), S(0), S(0), S(0);
  s2 << cos(phi), sin(phi), S(0), -l * sin(phi), l * cos(phi), S(0);
  REQUIRE(abs(reciprocalProduct(s1, s2) + l * sin(phi)) <= tol<S>());
  const LineRelation<S> r = relation(PluckerLine<S>(s1), PluckerLine<S>(s2));
  REQUIRE(abs(r.signedDistance - l) <= tol<S>(64));
  REQUIRE(abs(r.angle - phi) <= tol<S>(64));
  REQUIRE(r.footA.norm() <= tol<S>(64));
  REQUIRE((r.footB - Vec3<S>(S(0), S(0), l)).norm() <= tol<S>(64));
  REQUIRE((relation(PluckerLine<S>(s1), PluckerLine<S>(s2)).commonPerpendicular().unitDirection() - Vec3<S>::UnitZ()).norm() <= tol<S>(64));
  // Parallel threshold sin α ≤ √ε, both sides, distance right on both.
  const S se = Tolerance<S>::sqrtEpsilon();
  for (const S& a : {se / S(4), S(4) * se}) {
    Vec6<S> t;
    t << cos(a), sin(a), S(0), -l * sin(a), l * cos(a), S(0);
    const LineRelation<S> ra = relation(PluckerLine<S>(s1), PluckerLine<S>(t));
    REQUIRE(ra.kind == (a < se ? LineRelationKind::Parallel : LineRelationKind::Skew));
    REQUIRE(abs(ra.distance - l) <= tol<S>(4096) * S(4) / a * se);
  }
  // Exactly parallel and antiparallel: reciprocal product 0 for any distance; coincident lines.
  Vec6<S> p;
  p << S(-1), S(0), S(0), S(0), -l, S(0);  // through (0, 0, l) along −x
  REQUIRE(reciprocalProduct(s1, p) == S(0));
  REQUIRE(meet(PluckerLine<S>(s1), PluckerLine<S>(p)));
  const LineRelation<S> rp = relation(PluckerLine<S>(s1), PluckerLine<S>(p));
  REQUIRE(rp.kind == LineRelationKind::Parallel);
  REQUIRE(abs(rp.distance - l) <= tol<S>());
  REQUIRE(abs(rp.angle - pi<S>()) <= tol<S>());
  REQUIRE(relation(PluckerLine<S>(s1), PluckerLine<S>(Vec6<S>(S(-2) * s1))).kind == LineRelationKind::Coincident);
  // l = 0: lines through the origin intersect; a line at infinity.
  Vec6<S> o;
  o << cos(phi), sin(phi), S(0), S(0), S(0), S(0);
  REQUIRE(relation(PluckerLine<S>(s1), PluckerLine<S>(o)).kind == LineRelationKind::Intersecting);
  REQUIRE(relation(PluckerLine<S>(s1), PluckerLine<S>::atInfinity(Vec3<S>::UnitZ())).kind == LineRelationKind::AtInfinity);
  REQUIRE_THROWS_AS(distance(PluckerLine<S>(s1), PluckerLine<S>::atInfinity(Vec3<S>::UnitZ())), InvalidInput);
  // Intersecting threshold, both sides: b offset by δ along z at distance ~1 from the origin.
  for (const S& d : {Tolerance<S>::epsilon(), S(1) / S(1000)}) {
    const PluckerLine<S> a = PluckerLine<S>::pointDirection(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), S(1), S(0)));
    const PluckerLine<S> b = PluckerLine<S>::pointDirection(Vec3<S>(S(1), S(0), d), Vec3<S>(S(1), S(1), S(0)));
    REQUIRE(relation(a, b).kind == (d < S(1) / S(1000) ? LineRelationKind::Intersecting : LineRelationKind::Skew));
  }
}

TEMPLATE_TEST_CASE("Lines far away and tiny (lengths 1e8, 1e-8)", "[lines][relation]", SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  auto& g = rng(16);
  for (const S& sc : {S(1) / S(100000000), S(100000000)}) {
    for (int k = 0; k < 20; ++k) {
      const Vec3<S> c = sc * unitVec3<S>(g);  // lines near a point at distance sc
      const Vec3<S> ua = unitVec3<S>(g), ub = unitVec3<S>(g);
      const Vec3<S> nrm = ua.cross(ub).normalized();
      const S d = sc / S(1000) * (S(1) + uniform<S>(g, 0, 1));
      const PluckerLine<S> a = PluckerLine<S>::pointDirection(c, ua), b = PluckerLine<S>::pointDirection(Vec3<S>(c + d * nrm), ub);
      const LineRelation<S> r = relation(a, b);
      // Relative error of the distance: ε·|c|/(d sin α) — the conditioning of a far-off pair.
      REQUIRE(abs(r.distance - d) <= tol<S>(4096) * sc / nrm.cross(ua).norm() * S(1000) / ua.cross(ub).norm());
      REQUIRE((r.footA - c).norm() <= tol<S>(4096) * sc * S(1000) / ua.cross(ub).squaredNorm());
    }
  }
}

}  // namespace SOMA_UNITY_ID
