// GF §9.2–9.3, §10.1: the motor sandwich on planes, points, free vectors, lines and screws against
// SE3 in coordinates (SE3::act, SE3::adjoint).
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga motors: the sandwich hxh* against SE3 in coordinates", "[pga][motor]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1102);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 2 : 20;
  for (int t = 0; t < trials; ++t) {
    const double scale = t % 4 == 3 ? 1e3 : 1;  // large translations too
    const SE3<S> m(SO3<S>::Random(g), rvec<S>(g, scale));
    const Motor<S> h = Motor<S>::fromSE3(m);
    const Mat3<S> R = m.rotation();
    const Vec3<S> tr = m.translation();
    REQUIRE(h.isUnit(tol<S>()));
    const S tl = tol<S>(512) * S(scale);
    // Points: hph* = point(Rx + t) (GF-10.1.2).
    const Vec3<S> x = rvec<S>(g, 2);
    CHECK(maxDiff<S>(h(Point<S>(x)).position(), m.act(x)) <= tl);
    // Free vectors: only rotated (hfh* = gfg*).
    const Point<S> f = h(Point<S>::freeVector(x));
    CHECK(f.weight() == S(0));
    CHECK(maxDiff<S>(f.bulk(), Vec3<S>(R * x)) <= tl);
    // Planes: n' = Rn, d' = d + (Rn)·t (GF-10.1.1).
    const Plane<S> pi = randomPlane<S>(g);
    const Plane<S> pi2 = h(pi);
    CHECK(maxDiff<S>(pi2.normal(), Vec3<S>(R * pi.normal())) <= tl);
    CHECK(abs(pi2.distance() - (pi.distance() + (R * pi.normal()).dot(tr))) <= tl * S(4));
    // Lines: through Rq + t with direction Rv (GF-10.1.3).
    const Vec3<S> q = rvec<S>(g), v = unitVec3<S>(g);
    const Line<S> l2 = h(Line<S>::throughPoint(q, v));
    const Line<S> expect = Line<S>::throughPoint(m.act(q), Vec3<S>(R * v));
    CHECK(clifford::maxAbsDiff(l2.element(), expect.element()) <= tl * S(4));
    // Screws transform by the adjoint (SE3::adjoint on the twist (v; u)).
    const SE3Tangent<S> xi(uniformVec<S, 6>(g));
    const Vec6<S> ad = m.adjoint() * xi.coeffs();
    CHECK((h(Line<S>::fromTwist(xi)).toTwist().coeffs() - ad).cwiseAbs().maxCoeff() <= tl * S(4));
  }
}

}  // namespace SOMA_UNITY_ID
