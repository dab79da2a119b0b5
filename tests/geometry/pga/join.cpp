// GF §10.2.1–10.2.3: joins by the shuffle product and incidence,
// each against a coordinate computation (a 3×3 linear solve, parametric intersections, cross
// products), with the degenerate cases on both sides of their Tolerance<S>::rank() threshold.
#include "pga_support.hpp"

#include <Eigen/LU>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga joins: against coordinates", "[pga][join]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1202);
  const int trials = 20;
  for (int t = 0; t < trials; ++t) {
    const Vec3<S> x1 = rvec<S>(g), x2 = rvec<S>(g), x3 = rvec<S>(g);
    // Two points: the line from x1 to x2 (GF-10.2.3-join-two-points).
    const Line<S> l = join(Point<S>(x1), Point<S>(x2));
    const Line<S> ref = Line<S>::throughPoint(x1, Vec3<S>((x2 - x1).normalized()));
    CHECK(clifford::maxAbsDiff(l.element(), ref.element()) <= tol<S>(256) / (x2 - x1).norm());
    // Point and line: the plane through x3 and the line, n·x = d for all three points.
    const Plane<S> pl = join(Point<S>(x3), l);
    CHECK(abs(pl.normal().norm() - S(1)) <= tol<S>());
    const Vec3<S> nref = (x2 - x1).cross(x3 - x1);
    const S k = S(1) / nref.norm();
    for (const auto& x : {x1, x2, x3}) CHECK(abs(pl.normal().dot(x) - pl.distance()) <= tol<S>(256) * k * S(4));
    // Three points: the same plane, normal along (x2 − x1) × (x3 − x1) (GF-10.2.3-plane-three-points).
    const Plane<S> p3 = join(Point<S>(x1), Point<S>(x2), Point<S>(x3));
    CHECK(maxDiff<S>(p3.normal(), Vec3<S>(nref * k)) <= tol<S>(256) * k * S(4));
    CHECK(p3.isApprox(pl, tol<S>(256) * k * S(4)));
  }
}

TEMPLATE_TEST_CASE("pga joins: far points and degenerate cases", "[pga][join]", float, double) {
  using S = TestType;
  using std::abs;
  const S r = Tolerance<S>::rank();
  // Far points (1e8 from the origin, 1 apart, float: 1e3): the join passes through both.
  {
    const S far = std::is_same_v<S, float> ? S(1e3) : S(1e8);
    const Vec3<S> a(far, far, -far), b(far + S(1), far, -far);
    const Line<S> l = join(Point<S>(a), Point<S>(b));
    CHECK(maxDiff<S>(l.direction(), Vec3<S>(S(1), S(0), S(0))) <= tol<S>(64));
    CHECK(incidenceResidual(Point<S>(a), l) <= tol<S>(64));
    CHECK(incidenceResidual(Point<S>(b), l) <= tol<S>(64));
  }
  // Coincident points, both sides of the threshold (separation 4·rank·|x| joins, rank/2·|x| throws).
  {
    const Vec3<S> a(S(3), S(-1), S(2));
    const Vec3<S> e(S(0), S(1), S(0));
    CHECK_NOTHROW(join(Point<S>(a), Point<S>(Vec3<S>(a + e * (S(4) * r * a.norm())))));
    CHECK_THROWS_WITH(join(Point<S>(a), Point<S>(Vec3<S>(a + e * (r / S(2) * a.norm())))), Contains("coincide"));
    CHECK_THROWS_WITH(join(Point<S>(a), Point<S>(a)), Contains("coincide"));
    // Points at infinity: a finite point and a direction → the line through it; two directions → at infinity.
    const Line<S> ld = join(Point<S>(a), Point<S>::freeVector(e));
    CHECK(clifford::maxAbsDiff(ld.element(), Line<S>::throughPoint(a, e).element()) <= tol<S>());
    CHECK(join(Point<S>::freeVector(e), Point<S>::freeVector(Vec3<S>(S(1), S(0), S(0)))).isAtInfinity());
    CHECK_THROWS_AS(join(Point<S>::freeVector(e), Point<S>::freeVector(e)), InvalidInput);
  }
  // Point on the line / collinear points (both sides).
  {
    const Vec3<S> q(S(1), S(2), S(3)), v(S(0), S(0), S(1)), off(S(1), S(0), S(0));
    const Line<S> l = Line<S>::throughPoint(q, v);
    CHECK_THROWS_WITH(join(Point<S>(Vec3<S>(q + S(5) * v)), l), Contains("lies on the line"));
    CHECK_NOTHROW(join(Point<S>(Vec3<S>(q + S(4) * r * q.norm() * off)), l));
    CHECK_THROWS_WITH(join(Point<S>(q), Point<S>(Vec3<S>(q + v)), Point<S>(Vec3<S>(q + S(3) * v))),
                      Contains("collinear"));
    CHECK(join(Point<S>::freeVector(off), Line<S>(Vec3<S>::Zero(), off)).isAtInfinity());
    // e_z lies on the line at infinity with moment e_x (the horizon of the planes x = const).
    CHECK_THROWS_AS(join(Point<S>::freeVector(v), Line<S>(Vec3<S>::Zero(), off)), InvalidInput);
  }
}

TEMPLATE_TEST_CASE("pga incidence: residuals against coordinates, both sides of the tolerance",
                   "[pga][incidence]", float, double, __float128) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1203);
  const S r = Tolerance<S>::rank();
  const Plane<S> pi = randomPlane<S>(g);
  const Vec3<S> n = pi.normal(), x0 = n * pi.distance() + n.cross(rvec<S>(g));  // on π
  const S scale = x0.norm() + abs(pi.distance());
  // GF-10.2.1-incidence-plane-point: π ∧ p = (x·n − d) e1e2e3𝐞.
  const Vec3<S> x = rvec<S>(g);
  CHECK(abs(bookCoeff(pi.element() ^ Point<S>(x).element(), basis::e123e) - (x.dot(n) - pi.distance())) <= tol<S>());
  CHECK(incident(Point<S>(x0), pi));
  CHECK_FALSE(incident(Point<S>(Vec3<S>(x0 + n * (S(2) * r * scale))), pi));
  CHECK(incident(Point<S>(Vec3<S>(x0 + n * (r / S(4) * scale))), pi));
  // GF-10.2.1-incidence-plane-line (E10.1): π ∧ ℓ = (n·v) e1e2e3 + (n × u + d v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞).
  const Line<S> l(rvec<S>(g), rvec<S>(g));
  const auto pl = pi.element() ^ l.element();
  const Vec3<S> nu = n.cross(l.moment()) + pi.distance() * l.direction();
  CHECK(abs(bookCoeff(pl, basis::e123) - n.dot(l.direction())) <= tol<S>());
  CHECK(abs(bookCoeff(pl, basis::e23e) - nu.x()) <= tol<S>());
  CHECK(abs(bookCoeff(pl, basis::e31e) - nu.y()) <= tol<S>());
  CHECK(abs(bookCoeff(pl, basis::e12e) - nu.z()) <= tol<S>());
  const Line<S> inPlane = Line<S>::throughPoint(x0, Vec3<S>(n.cross(rvec<S>(g))));
  CHECK(incident(inPlane, pi));
  CHECK_FALSE(incident(Line<S>::throughPoint(Vec3<S>(x0 + n * (S(4) * r * scale)), inPlane.direction()), pi));
  // GF-10.2.1-incidence-point-line: pℓ* + ℓp* = 2(u − x × v) as a free vector.
  const auto pll = Point<S>(x).element() * l.element().conjugate() + l.element() * Point<S>(x).element();
  const Vec3<S> ref = S(2) * (l.moment() - x.cross(l.direction()));
  CHECK(maxDiff<S>(Point<S>(pll.template grade<3>()).bulk(), ref) <= tol<S>());
  CHECK(abs(Point<S>(pll.template grade<3>()).weight()) <= tol<S>());
  const Line<S> through = Line<S>::throughPoint(x, unitVec3<S>(g));
  CHECK(incident(Point<S>(x), through));
  // GF-10.2.3: coplanar lines and points.
  CHECK(coplanarityResidual(inPlane, Line<S>::throughPoint(x0, Vec3<S>(n.cross(rvec<S>(g))))) <= tol<S>(64));
  CHECK(coplanarityResidual(through, Line<S>::throughPoint(Vec3<S>(x + S(1) / S(3) * through.direction()), rvec<S>(g))) <= tol<S>(64));
  const Vec3<S> y1 = x0 + n.cross(rvec<S>(g)), y2 = x0 + n.cross(rvec<S>(g)), y3 = x0 + n.cross(rvec<S>(g));
  CHECK(coplanarityResidual(Point<S>(x0), Point<S>(y1), Point<S>(y2), Point<S>(y3)) <= tol<S>(64));
  CHECK(coplanarityResidual(Point<S>(x0), Point<S>(y1), Point<S>(y2), Point<S>(x)) > S(1e-3));
  CHECK(collinearityResidual(Point<S>(x0), Point<S>(y1), Point<S>(Vec3<S>(S(3) * y1 - S(2) * x0))) <= tol<S>(64));
}

}  // namespace SOMA_UNITY_ID
