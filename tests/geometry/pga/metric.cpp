// GF §10.2.4: the contraction, perpendiculars, angles, distances, projections, reflections and
// the common perpendicular, each against coordinate geometry; nearly parallel lines on both
// sides of the switch and threshold.
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga perpendiculars, angles, distances, projections, reflections", "[pga][metric]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::atan2;
  auto& g = rng(1302);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 2 : 20;
  for (int t = 0; t < trials; ++t) {
    const Plane<S> pi = randomPlane<S>(g);
    const Line<S> l = randomLine<S>(g), m = randomLine<S>(g);
    const Vec3<S> x = rvec<S>(g, 2), y = rvec<S>(g, 2);
    const Vec3<S> n = pi.normal(), v = l.direction(), q = l.pointNearestOrigin();
    // Perpendiculars.
    const Plane<S> pp = perpendicularPlane(pi, l);
    CHECK(incidenceResidual(l, pp) <= tol<S>(256) / (n.cross(v)).norm());
    CHECK(abs(pp.normal().dot(n)) <= tol<S>(64) / (n.cross(v)).norm());
    const Line<S> pl = perpendicularLine(pi, Point<S>(x));
    CHECK(clifford::maxAbsDiff(pl.element(), Line<S>::throughPoint(x, n).element()) <= tol<S>(64));
    const Plane<S> lp = perpendicularPlane(l, Point<S>(x));
    CHECK(lp.isApprox(Plane<S>::throughPoint(v, x), tol<S>(64)));
    // Angles (atan2 of coordinate sines and cosines).
    const Plane<S> pi2 = randomPlane<S>(g);
    CHECK(abs(angle(pi, pi2) - atan2(S(n.cross(pi2.normal()).norm()), S(n.dot(pi2.normal())))) <= tol<S>(64));
    CHECK(abs(angle(l, m) - atan2(S(v.cross(m.direction()).norm()), S(v.dot(m.direction())))) <= tol<S>(64));
    CHECK(abs(angle(l, pi) - atan2(S(n.dot(v)), S(n.cross(v).norm()))) <= tol<S>(64));
    // Distances (GF-10.2.4-distances; E10.10: signedDistance is positive on the normal's side).
    CHECK(abs(signedDistance(Point<S>(x), pi) - (n.dot(x) - pi.distance())) <= tol<S>(64));
    CHECK(abs(signedDistance(Point<S>(S(-3), Vec3<S>(S(-3) * x)), pi) - (n.dot(x) - pi.distance())) <= tol<S>(64));
    CHECK(abs(distance(Point<S>(x), l) - (x - q).cross(v).norm()) <= tol<S>(64));
    CHECK(abs(distance(Point<S>(x), Point<S>(y)) - (x - y).norm()) <= tol<S>(64));
    const Vec3<S> c = v.cross(m.direction());
    CHECK(abs(distance(l, m) - abs((m.pointNearestOrigin() - q).dot(c)) / c.norm()) <= tol<S>(256) / c.norm());
    // Projections (feet of perpendiculars).
    CHECK(maxDiff<S>(project(Point<S>(x), pi).position(), Vec3<S>(x - n * (n.dot(x) - pi.distance()))) <= tol<S>(64));
    const Vec3<S> foot = q + v * v.dot(x - q);
    CHECK(maxDiff<S>(project(Point<S>(x), l).position(), foot) <= tol<S>(64));
    // … equals ½(p − ℓpℓ) (GF §10.3.3) for a unit line.
    const Point<S> half((Point<S>(x).element() - (l.element() * Point<S>(x).element() * l.element()).template grade<3>()) *
                        (S(1) / S(2)));
    CHECK(maxDiff<S>(half.position(), foot) <= tol<S>(64));
    const Line<S> lpi = project(l, pi);
    CHECK(incidenceResidual(lpi, pi) <= tol<S>(256) / (n.cross(v)).norm());
    const Vec3<S> vp = (v - n * n.dot(v)).normalized();
    CHECK(maxDiff<S>(lpi.direction(), vp) <= tol<S>(256) / (n.cross(v)).norm());
    CHECK(incidenceResidual(project(Point<S>(q), pi), lpi) <= tol<S>(256) / (n.cross(v)).norm());
    // Reflections in π: x ↦ x − 2(n·x − d)n; directions v ↦ v − 2(n·v)n.
    auto mirror = [&](const Vec3<S>& z) { return Vec3<S>(z - S(2) * (n.dot(z) - pi.distance()) * n); };
    const Vec3<S> vm = v - S(2) * n.dot(v) * n;
    const Point<S> rp = reflect(Point<S>(x), pi);
    CHECK(abs(rp.weight() - S(1)) <= tol<S>(16));
    CHECK(maxDiff<S>(rp.position(), mirror(x)) <= tol<S>(64));
    CHECK(clifford::maxAbsDiff(reflect(l, pi).element(), Line<S>::throughPoint(mirror(q), vm).element()) <= tol<S>(64));
    const Plane<S> rpl = reflect(pi2, pi);
    const Vec3<S> n2m = pi2.normal() - S(2) * n.dot(pi2.normal()) * n;
    CHECK(rpl.isApprox(Plane<S>::throughPoint(n2m, mirror(Vec3<S>(pi2.normal() * pi2.distance()))), tol<S>(64)));
    CHECK(reflect(reflect(l, pi), pi).isApprox(l, tol<S>(64)));
  }
}

}  // namespace SOMA_UNITY_ID
