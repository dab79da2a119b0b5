// GF §10.2.4: the contraction, perpendiculars, angles, distances, projections, reflections and
// the common perpendicular, each against coordinate geometry; nearly parallel lines on both
// sides of the switch and threshold.
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga contraction: the book's definition x⌋c = ½(xc − α(c)x) and the plane/line/point formulas",
                   "[pga][contraction]", SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1301);
  DenseElement<S> c;
  for (int i = 0; i < c.size; ++i) c[i] = uniform<S>(g);
  const Plane<S> xp = randomPlane<S>(g);
  const DenseElement<S> x(xp.element());
  const DenseElement<S> def((x * c - c.involute() * x) * (S(1) / S(2)));
  CHECK(clifford::maxAbsDiff(DenseElement<S>(x | c), def) <= tol<S>(16));
  CHECK(clifford::maxAbsDiff(DenseElement<S>(x * c), DenseElement<S>((x ^ c) + (x | c))) <= tol<S>(16));
  // π1⌋π2 = −n·m; ℓ1⌋ℓ2 = −v·w; π⌋ℓ = (n × v) − (n·u)𝐞; π⌋p = −n·(e2e3, …) − (x × n)·(e1𝐞, …);
  // ℓ⌋p = −v − (x·v)𝐞 (GF-10.2.4-*).
  const Plane<S> a = randomPlane<S>(g), b = randomPlane<S>(g);
  CHECK(abs((a.element() | b.element()).scalarPart() + a.normal().dot(b.normal())) <= tol<S>());
  const Line<S> l1(rvec<S>(g), rvec<S>(g)), l2(rvec<S>(g), rvec<S>(g));
  CHECK(abs((l1.element() | l2.element()).scalarPart() + l1.direction().dot(l2.direction())) <= tol<S>());
  const Plane<S> pl((a.element() | l1.element()).template grade<1>());
  CHECK(maxDiff<S>(pl.normal(), Vec3<S>(a.normal().cross(l1.direction()))) <= tol<S>());
  CHECK(abs(pl.distance() + a.normal().dot(l1.moment())) <= tol<S>());
  const Vec3<S> x0 = rvec<S>(g);
  const Line<S> lp((a.element() | Point<S>(x0).element()).template grade<2>());
  CHECK(maxDiff<S>(lp.direction(), Vec3<S>(-a.normal())) <= tol<S>());
  CHECK(maxDiff<S>(lp.moment(), Vec3<S>(-x0.cross(a.normal()))) <= tol<S>());
  const Plane<S> pp((l1.element() | Point<S>(x0).element()).template grade<1>());
  CHECK(maxDiff<S>(pp.normal(), Vec3<S>(-l1.direction())) <= tol<S>());
  CHECK(abs(pp.distance() + x0.dot(l1.direction())) <= tol<S>());
}

}  // namespace SOMA_UNITY_ID
