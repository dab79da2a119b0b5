// Cylindroids and curvature-axis surfaces (GF §6.5.2, §6.5.3).
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

TEMPLATE_TEST_CASE("Cylindroid: book two-line pencil, principal pitches, cubic (GF-6.5.2)", "[lines][cylindroid]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  const S l = S(1), phi = S(11) / S(10);
  Vec6<S> s1, s2;
  s1 << S(1), S(0), S(0), S(0), S(0), S(0);
  s2 << cos(phi), sin(phi), S(0), -l * sin(phi), l * cos(phi), S(0);
  const Cylindroid<S> c(s1, s2);
  // Principal pitches l(cos φ ± 1)/(2 sin φ) (GF-8.4.2 cross-check).
  REQUIRE(abs(c.pitchMax() - l * (cos(phi) + S(1)) / (S(2) * sin(phi))) <= tol<S>(256));
  REQUIRE(abs(c.pitchMin() - l * (cos(phi) - S(1)) / (S(2) * sin(phi))) <= tol<S>(256));
  // The book's pitch of μ s₁ + λ s₂: −μλ l sin φ/(μ² + λ² + 2μλ cos φ).
  auto& g = rng(33);
  for (int k = 0; k < 10; ++k) {
    const S mu = uniform<S>(g), la = uniform<S>(g);
    const Vec6<S> s = mu * s1 + la * s2;
    const S book = -mu * la * l * sin(phi) / (mu * mu + la * la + S(2) * mu * la * cos(phi));
    REQUIRE(abs(screwPitch(s) - book) <= tol<S>(1024));
    // Its axis is the cylindroid's axis at its angle, and lies on the cubic.
    const S th = c.angleOf(s);
    REQUIRE(abs(c.pitch(th) - book) <= tol<S>(1024));
    REQUIRE(screwAxis(s).axis.sameAs(c.axis(th), tol<S>(4096)));
    const PluckerLine<S> ax = screwAxis(s).axis;
    for (const S& t : {S(-1), S(1) / S(2)}) REQUIRE(abs(c.implicit(ax.pointAt(t))) <= tol<S>(4096));
    // Corrected cubic of the book frame z(x² + y²) = +l(y² + xy cot φ) (E6.3); printed sign fails.
    const Vec3<S> p = ax.pointAt(S(1) / S(2));
    const S lhs = p(2) * (p(0) * p(0) + p(1) * p(1)), rhs = l * (p(1) * p(1) + p(0) * p(1) * cos(phi) / sin(phi));
    REQUIRE(abs(lhs - rhs) <= tol<S>(4096));
    REQUIRE(abs(lhs + rhs) > S(1) / S(1000000));
  }
  // Principal axes meet at right angles at the centre.
  const PluckerLine<S> a1 = screwAxis(c.principal(1)).axis, a2 = screwAxis(c.principal(2)).axis;
  REQUIRE(relation(a1, a2).kind == LineRelationKind::Intersecting);
  REQUIRE(abs(relation(a1, a2).angle - pi<S>() / S(2)) <= tol<S>(256));
}

TEMPLATE_TEST_CASE("Cylindroid extremes: l = 0, equal pitches, parallel directions both sides", "[lines][cylindroid]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  // Principal form (E6.4 corrected input): lines along x at height r_x and along y at height r_y.
  const S rx = S(1) / S(2), ry = S(-1) / S(2);
  Vec6<S> a, b;
  a << S(1), S(0), S(0), S(0), rx, S(0);   // (0,0,rx) × x = (0, rx, 0)
  b << S(0), S(1), S(0), -ry, S(0), S(0);  // (0,0,ry) × y = (−ry, 0, 0)
  const Cylindroid<S> c(a, b);
  REQUIRE(abs(c.pitchMax() - (rx - ry) / S(2)) <= tol<S>());
  REQUIRE(abs(c.pitchMin() + (rx - ry) / S(2)) <= tol<S>());
  // The line of direction (cos θ, sin θ, 0) in the pencil passes through z = rx cos²θ + ry sin²θ.
  for (const S& th : {S(1) / S(5), S(1), S(2)}) {
    const Vec6<S> s = cos(th) * cos(th) * a + sin(th) * sin(th) * b;  // book's (λ(λ²+μ²)…) scaled
    Vec6<S> sl = cos(th) * a + sin(th) * b;
    const PluckerLine<S> ax = screwAxis(sl).axis;
    const S z = rx * cos(th) * cos(th) + ry * sin(th) * sin(th);
    REQUIRE(ax.distanceTo(Vec3<S>(S(0), S(0), z)) <= tol<S>(1024));
    REQUIRE(abs(screwPitch(sl) - cos(th) * sin(th) * (rx - ry)) <= tol<S>(1024));
    (void)s;
  }
  // l = 0: a pencil through a point, all pitches 0.
  Vec6<S> p2;
  p2 << S(0), S(1), S(0), S(0), S(0), S(0);
  Vec6<S> p1;
  p1 << S(1), S(0), S(0), S(0), S(0), S(0);
  const Cylindroid<S> flat(p1, p2);
  REQUIRE(abs(flat.pitchMax()) + abs(flat.pitchMin()) <= tol<S>());
  REQUIRE(abs(flat.height(S(1) / S(3))) <= tol<S>());
  // Parallel directions: rejected below √ε, accepted above.
  const S se = Tolerance<S>::sqrtEpsilon();
  Vec6<S> q;
  q << S(1), se / S(4), S(0), S(0), S(0), S(1);
  REQUIRE_THROWS_AS(Cylindroid<S>(p1, q), InvalidInput);
  q(1) = S(4) * se;
  REQUIRE_NOTHROW(Cylindroid<S>(p1, q));
}

TEMPLATE_TEST_CASE("Curvature axes: cubic surface, umbilic, saddle at infinity (GF-6.5.3)", "[lines][curvature]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  for (const auto& [kx, ky] : {std::pair<S, S>{S(1), S(3)}, std::pair<S, S>{S(2), S(-1)}, std::pair<S, S>{S(2), S(2)}}) {
    for (const S& phi : {S(0), S(1) / S(3), S(1), S(2)}) {
      const S k = kx * cos(phi) * cos(phi) + ky * sin(phi) * sin(phi);
      const PluckerLine<S> ax(curvatureAxis(kx, ky, S(cos(phi)), S(sin(phi))));
      REQUIRE(ax.contains(Vec3<S>(S(0), S(0), S(1) / k), tol<S>(1024)));
      REQUIRE(abs(ax.unitDirection().dot(Vec3<S>(cos(phi), sin(phi), S(0)))) <= tol<S>());
      for (const S& t : {S(-1), S(2)}) {
        const Vec3<S> p = ax.pointAt(t);
        REQUIRE(abs(curvatureAxesImplicit(kx, ky, p)) <= tol<S>(1024) * (S(1) + p.squaredNorm() * (S(1) + abs(p(2)))));
      }
    }
  }
  // Umbilic: every axis through (0, 0, 1/k).
  const Vec3<S> c(S(0), S(0), S(1) / S(2));
  for (const S& phi : {S(0), S(1), S(2)}) REQUIRE(PluckerLine<S>(curvatureAxis(S(2), S(2), S(cos(phi)), S(sin(phi)))).contains(c));
  // Saddle k_x = 1, k_y = −1: the asymptotic direction λ = μ gives a line at infinity exactly.
  REQUIRE(PluckerLine<S>(curvatureAxis(S(1), S(-1), S(1), S(1))).isAtInfinity());
  REQUIRE_THROWS_AS(curvatureAxis(S(0), S(0), S(1), S(0)), InvalidInput);
  // Derivative of the surface curve agrees with a central difference (double-scale check).
  const RuledSurface<S> rs = curvatureAxesSurface(S(1), S(3));
  const S h = Tolerance<S>::precision(2);
  const Vec6<S> fd = (rs.coords(S(1) + h) - rs.coords(S(1) - h)) / (S(2) * h);
  REQUIRE((fd - rs.derivative(S(1))).norm() <= S(100) * h * h);
}

}  // namespace SOMA_UNITY_ID
