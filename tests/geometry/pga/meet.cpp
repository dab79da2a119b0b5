// GF §10.2.1–10.2.3: meets by the exterior product,
// each against a coordinate computation (a 3×3 linear solve, parametric intersections, cross
// products), with the degenerate cases on both sides of their Tolerance<S>::rank() threshold.
#include "pga_support.hpp"

#include <Eigen/LU>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga meets: against linear solves and parametric intersections", "[pga][meet]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1201);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 2 : 20;
  for (int t = 0; t < trials; ++t) {
    const Plane<S> a = randomPlane<S>(g), b = randomPlane<S>(g), c = randomPlane<S>(g);
    // Three planes: π1 ∧ π2 ∧ π3 against the solution of [n1 n2 n3]ᵀ x = d (GF-10.2.2-meet-three-planes).
    Mat3<S> N;
    N.row(0) = a.normal().transpose(), N.row(1) = b.normal().transpose(), N.row(2) = c.normal().transpose();
    // Reject near-singular triples (|det| < 0.1 with unit normals bounds cond(N) by ~30) so one
    // tolerance serves; partial-pivot LU is the independent reference (cheaper to compile than full).
    if (abs(N.determinant()) < S(1) / S(10)) continue;
    const Vec3<S> x = N.partialPivLu().solve(Vec3<S>(a.distance(), b.distance(), c.distance()));
    const S cond(30);
    const Point<S> p = meet(a, b, c);
    CHECK(p.weight() == S(1));
    CHECK(maxDiff<S>(p.position(), x) <= tol<S>(64) * cond * (S(1) + x.norm()));
    // Two planes: the line lies in both, direction n1 × n2 (GF-10.2.2-meet-two-planes).
    const Line<S> l = meet(a, b);
    const Vec3<S> n12 = a.normal().cross(b.normal());
    CHECK(maxDiff<S>(l.direction(), Vec3<S>(n12.normalized())) <= tol<S>(64));
    CHECK(abs(l.normSquared().first - S(1)) <= tol<S>());
    CHECK(incident(l, a, tol<S>(256) * cond));
    CHECK(incident(l, b, tol<S>(256) * cond));
    CHECK(incident(p, l, tol<S>(256) * cond * cond));
    // Line and plane: r + s v with n·(r + s v) = d (GF-10.2.2-meet-line-plane).
    const Vec3<S> r = rvec<S>(g), v = unitVec3<S>(g);
    const Point<S> q = meet(Line<S>::throughPoint(r, v), c);
    const S s = (c.distance() - c.normal().dot(r)) / c.normal().dot(v);
    CHECK(q.weight() == S(1));
    CHECK(maxDiff<S>(q.position(), Vec3<S>(r + s * v)) <= tol<S>(64) * (S(1) + abs(s)) / abs(c.normal().dot(v)));
  }
}

TEMPLATE_TEST_CASE("pga meets: parallel, nearly parallel and coincident cases", "[pga][meet]",
                   float, double) {
  using S = TestType;
  using std::sqrt;
  const S r = Tolerance<S>::rank();
  const Vec3<S> ez(S(0), S(0), S(1));
  auto tilted = [&](const S& sn) { return Vec3<S>(sn, S(0), sqrt(S(1) - sn * sn)); };
  const Plane<S> z0(ez, S(0));
  // Two planes at sin∠ = 2·rank: a finite line (far away, in both planes).
  {
    const Plane<S> p2(tilted(S(2) * r), S(1));
    const Line<S> l = meet(z0, p2);
    CHECK_FALSE(l.isAtInfinity());
    CHECK(incidenceResidual(l, z0) <= tol<S>(64));
    CHECK(incidenceResidual(l, p2) <= tol<S>(64));
  }
  // … at sin∠ = rank/2: the line at infinity, unit moment along the common normal.
  {
    const Line<S> l = meet(z0, Plane<S>(tilted(r / S(2)), S(1)));
    CHECK(l.isAtInfinity());
    CHECK(abs(l.moment().norm() - S(1)) <= tol<S>());
    CHECK(abs(abs(l.moment().z()) - S(1)) <= tol<S>(1024));
    // Exactly parallel, either orientation.
    CHECK(meet(z0, Plane<S>(ez, S(3))).isAtInfinity());
    CHECK(meet(z0, Plane<S>(Vec3<S>(-ez), S(3))).isAtInfinity());
  }
  // Coincident planes (both orientations, through the origin or not): no line.
  CHECK_THROWS_WITH(meet(z0, z0), Contains("coincide"));
  CHECK_THROWS_WITH(meet(Plane<S>(ez, S(2)), Plane<S>(Vec3<S>(-ez), S(-2))), Contains("coincide"));
  // Line and plane at sin∠ = 2·rank: a finite point on both; at rank/2: the free vector ±v.
  {
    const Vec3<S> v(sqrt(S(1) - S(4) * r * r), S(0), S(2) * r);
    const Line<S> l = Line<S>::throughPoint(Vec3<S>(S(0), S(0), S(1)), v);
    const Point<S> p = meet(l, z0);
    CHECK(p.weight() == S(1));
    CHECK(incidenceResidual(p, z0) <= tol<S>(64));
    CHECK(incidenceResidual(p, l) <= tol<S>(64));
    const Vec3<S> v2(sqrt(S(1) - r * r / S(4)), S(0), r / S(2));
    const Point<S> f = meet(Line<S>::throughPoint(Vec3<S>(S(0), S(0), S(1)), v2), z0);
    CHECK(f.isAtInfinity());
    CHECK(abs(abs(f.bulk().x()) - S(1)) <= tol<S>());
  }
  // A line in the plane: no point.
  CHECK_THROWS_WITH(meet(Line<S>::throughPoint(Vec3<S>(S(1), S(2), S(0)), Vec3<S>(S(1), S(1), S(0))), z0),
                    Contains("lies in the plane"));
  // Three planes: a prism (normals coplanar, no common line) meets at infinity along the edges;
  // three planes of a pencil (one common line) do not meet in a point.
  const Plane<S> px(Vec3<S>(S(1), S(0), S(0)), S(0)), pd(Vec3<S>(S(1), S(0), S(1)) / sqrt(S(2)), S(1));
  const Point<S> inf = meet(z0, px, pd);
  CHECK(inf.isAtInfinity());
  CHECK(abs(abs(inf.bulk().y()) - S(1)) <= tol<S>());
  CHECK_THROWS_WITH(meet(z0, px, Plane<S>(Vec3<S>(S(1), S(0), S(1)) / sqrt(S(2)), S(0))),
                    Contains("share a line"));
}

}  // namespace SOMA_UNITY_ID
