// Ruled surfaces, reguli, cylindroids, curvature axes, dual-vector lines (GF §6.5, §9.4).
#include "soma/geometry/lines/curvature_axes.hpp"
#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/lines/regulus.hpp"

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

TEMPLATE_TEST_CASE("Book reguli of x²+y²−z²=1: Klein, 2-planes, families meet (GF-6.5.1)", "[lines][regulus]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(31);
  for (int k = 0; k < 10; ++k) {
    const S t1 = uniform<S>(g, -3, 3), t2 = uniform<S>(g, -3, 3);
    const Vec6<S> a = bookRegulusLine(1, t1), b = bookRegulusLine(2, t2), a2 = bookRegulusLine(1, t2);
    REQUIRE(abs(kleinValue(a)) <= tol<S>());
    // Family 1: p01 − p23 = p02 − p31 = p03 + p12 = 0; family 2 with the opposite signs.
    REQUIRE(abs(a(0) - a(3)) + abs(a(1) - a(4)) + abs(a(2) + a(5)) <= tol<S>());
    REQUIRE(abs(b(0) + b(3)) + abs(b(1) + b(4)) + abs(b(2) - b(5)) <= tol<S>());
    REQUIRE(abs(reciprocalProduct(a, b)) <= tol<S>());           // different families meet
    REQUIRE(abs(reciprocalProduct(a, a2)) > S(1) / S(100000));  // same family: skew
    // Points on the lines lie on the hyperboloid; det(A + B T(t)) = −(x² + y² − z² − 1).
    const PluckerLine<S> l(a);
    const Mat3<S> A = Mat3<S>::Identity(), B = Vec3<S>(S(-1), S(-1), S(1)).asDiagonal();
    for (const S& mu : {S(-2), S(0), S(1)}) {
      const Vec3<S> p = l.pointAt(mu);
      REQUIRE(abs(p(0) * p(0) + p(1) * p(1) - p(2) * p(2) - S(1)) <= tol<S>(1024));
      const Vec3<S> q = uniformVec<S, 3>(g);
      REQUIRE(abs(twoPlaneQuadric(A, B, q) + (q(0) * q(0) + q(1) * q(1) - q(2) * q(2) - S(1))) <= tol<S>());
    }
  }
}

TEMPLATE_TEST_CASE("Swept regulus: implicit quadric, throat circle, distribution parameter (GF-9.4)", "[lines][regulus]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  // Axis z, generator through (d, 0, 0) with direction (0, sin α, cos α) (GF-9.4 example).
  const S d = S(4) / S(5), al = S(3) / S(5);
  const PluckerLine<S> axis = PluckerLine<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitZ());
  const PluckerLine<S> l0 = PluckerLine<S>::pointDirection(Vec3<S>(d, S(0), S(0)), Vec3<S>(S(0), sin(al), cos(al)));
  const Regulus<S> r(axis, l0);
  REQUIRE(abs(r.distance() - d) <= tol<S>());
  REQUIRE(abs(r.angle() - al) <= tol<S>());
  const Regulus<S> o = r.opposite();
  for (const S& th : {S(0), S(1), S(-2), S(3)}) {
    const PluckerLine<S> gth = r.generator(th), oth = o.generator(S(1) / S(2) - th);
    for (const S& mu : {S(-3), S(0), S(2)}) {
      REQUIRE(abs(r.implicit(gth.pointAt(mu))) <= tol<S>(2048));
      REQUIRE(abs(r.implicit(oth.pointAt(mu))) <= tol<S>(2048));  // same quadric
    }
    REQUIRE(meet(gth, oth, tol<S>(2048)));  // other family meets
    const Vec3<S> s = r.surface().strictionPoint(th);
    REQUIRE(abs(s(2)) <= tol<S>(1024));                       // throat circle at z = 0
    REQUIRE(abs(s.norm() - d) <= tol<S>(1024));               // of radius d
    const RuledFrame<S> f = r.surface().frame(th);
    REQUIRE(abs(f.kappa0 - sin(al)) <= tol<S>(1024));         // κ₀ = sin α
    REQUIRE(abs(abs(f.kappa1) - d * cos(al)) <= tol<S>(1024));  // |κ₁| = d cos α
    REQUIRE(abs(f.distributionParameter - r.surface().distributionParameter(th)) <= tol<S>(1024));  // two methods
    REQUIRE((f.striction - s).norm() <= tol<S>(4096));
    REQUIRE(abs(abs(f.distributionParameter) - d * cos(al) / sin(al)) <= tol<S>(1024));  // d cot α
    // Frame: ň ⟂ l̂ meeting it, ť = l̂ × ň.
    REQUIRE(meet(f.l, f.n, tol<S>(1024)));
    REQUIRE(abs(f.l.direction().dot(f.n.direction())) <= tol<S>(64));
    REQUIRE(meet(f.t, f.n, tol<S>(1024)));
  }
  // Extremes: α = π/2 (plane: κ₁ = 0), d = 0 (cone: κ₁ = 0), α = 0 (cylinder: no striction).
  const Regulus<S> pl(axis, PluckerLine<S>::pointDirection(Vec3<S>(d, S(0), S(0)), Vec3<S>::UnitY()));
  REQUIRE(abs(pl.surface().frame(S(1)).kappa1) <= tol<S>());
  const Regulus<S> cone(axis, PluckerLine<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>(S(0), sin(al), cos(al))));
  REQUIRE(abs(cone.surface().frame(S(1)).kappa1) <= tol<S>());
  const Regulus<S> cyl(axis, PluckerLine<S>::pointDirection(Vec3<S>(d, S(0), S(0)), Vec3<S>::UnitZ()));
  REQUIRE(cyl.surface().isCylindrical(S(1)));
  REQUIRE_THROWS_AS(cyl.surface().strictionPoint(S(1)), InvalidInput);
  // Nearly cylindrical, both sides of |u'| ≤ √ε|l̂'|.
  const S se = Tolerance<S>::sqrtEpsilon();
  for (const S& a : {se / S(8), S(8) * se}) {
    const Regulus<S> nc(axis, PluckerLine<S>::pointDirection(Vec3<S>(d, S(0), S(0)), Vec3<S>(S(0), sin(a), cos(a))));
    REQUIRE(nc.surface().isCylindrical(S(0)) == (a < se));
  }
}

TEMPLATE_TEST_CASE("Ruled helicoid: κ₀ = sin α, κ₁/κ₀ = p − d cot α, helical striction (GF-9.4-ruled-helicoid)", "[lines][regulus]", SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::cos;
  using std::sin;
  const S d = S(4) / S(5), al = S(3) / S(5), p = S(1) / S(3);
  Vec6<S> xi;
  xi << S(0), S(0), S(1), S(0), S(0), p;
  const PluckerLine<S> l0 = PluckerLine<S>::pointDirection(Vec3<S>(d, S(0), S(0)), Vec3<S>(S(0), sin(al), cos(al)));
  const RuledSurface<S> h = RuledSurface<S>::sweep(xi, l0);
  for (const S& th : {S(0), S(2)}) {
    const RuledFrame<S> f = h.frame(th);
    REQUIRE(abs(f.kappa0 - sin(al)) <= tol<S>(1024));
    // After reparametrising to κ₀ = 1 (λ' = λ sin α, E9.6): κ₁/κ₀ = p − d cot α for this hand
    // (generator leaning towards +y seen from +x); the book's p + d cot α is the mirror hand.
    REQUIRE(abs(f.distributionParameter - (p - d * cos(al) / sin(al))) <= tol<S>(1024));
    // The striction curve is a helix: radius d, height p θ.
    REQUIRE(abs(f.striction(2) - p * th) <= tol<S>(1024));
  }
}

TEMPLATE_TEST_CASE("Dual angle and common perpendicular by dual vectors agree with Plücker (GF-9.4)", "[lines][dual]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(32);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 50;
  for (int k = 0; k < n; ++k) {
    const PluckerLine<S> a = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g, -2, 2), uniformVec<S, 3>(g));
    const PluckerLine<S> b = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g, -2, 2), uniformVec<S, 3>(g));
    const DualNumber<S> da = dualAngle(a, b);
    const LineRelation<S> r = relation(a, b);
    REQUIRE(abs(da.re - r.angle) <= tol<S>(1024));
    REQUIRE(abs(da.du - r.signedDistance) <= tol<S>(1 << 14));
    const PluckerLine<S> cp = commonPerpendicularDual(a, b);
    REQUIRE(cp.sameAs(r.commonPerpendicular(), tol<S>(1 << 14)));
    // ň is a unit line meeting both at right angles: l_i · ň = 0 (dual).
    const DualVec3<S> nn = DualVec3<S>::of(cp);
    REQUIRE(abs(DualVec3<S>::of(a).dot(nn).re) + abs(DualVec3<S>::of(a).dot(nn).du) <= tol<S>(1 << 12));
    REQUIRE(abs(DualVec3<S>::of(b).dot(nn).re) + abs(DualVec3<S>::of(b).dot(nn).du) <= tol<S>(1 << 12));
  }
  // Parallel: pure dual sine, distance; common perpendicular undefined.
  const PluckerLine<S> x = PluckerLine<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitX());
  const PluckerLine<S> y = PluckerLine<S>::pointDirection(Vec3<S>(S(0), S(0), S(2)), Vec3<S>::UnitX());
  REQUIRE(abs(dualAngle(x, y).du - S(2)) <= tol<S>());
  REQUIRE(dualAngle(x, y).re == S(0));
  REQUIRE_THROWS_AS(commonPerpendicularDual(x, y), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
