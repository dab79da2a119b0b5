// GF §10.1: the elements' norms and conjugates, normalisation, elements at infinity.
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga elements: conjugates and norms (GF §10.1)", "[pga][elements]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1101);
  const Vec3<S> n = rvec<S>(g), x = rvec<S>(g), v = rvec<S>(g), u = rvec<S>(g);
  const S d = uniform<S>(g), w = uniform<S>(g, 0.5, 2);
  const Plane<S> pi(n, d);
  const Point<S> p(w, x);
  const Line<S> l(v, u);
  // π* = −π, p* = p, ℓ* = −ℓ (GF §10.2.1).
  CHECK(clifford::maxAbsDiff(pi.element().conjugate(), Grade1<S>(-pi.element())) == S(0));
  CHECK(clifford::maxAbsDiff(p.element().conjugate(), p.element()) == S(0));
  CHECK(clifford::maxAbsDiff(l.element().conjugate(), Grade2<S>(-l.element())) == S(0));
  // ππ* = |n|², pp* = w², ℓℓ* = |v|² − 2(v·u) e1e2e3𝐞.
  CHECK(abs(pi.normSquared() - n.squaredNorm()) <= tol<S>());
  CHECK(abs(p.normSquared() - w * w) <= tol<S>());
  CHECK(abs(l.normSquared().first - v.squaredNorm()) <= tol<S>());
  CHECK(abs(l.normSquared().second + S(2) * v.dot(u)) <= tol<S>());
  // Normalisation.
  CHECK(pi.normalized().isNormalized(tol<S>()));
  CHECK(abs(p.normalized().weight() - S(1)) <= tol<S>());
  CHECK(maxDiff<S>(p.normalized().position(), Vec3<S>(x / w)) <= tol<S>());
  CHECK(maxDiff<S>((-p).position(), Vec3<S>(x / w)) <= tol<S>());  // a negative point, same place
  CHECK(abs((-p).normalized().weight() - S(1)) <= tol<S>());
  const Line<S> ln = Line<S>::throughPoint(x, v).normalized();
  CHECK(abs(ln.normSquared().first - S(1)) <= tol<S>());
  CHECK(abs(ln.normSquared().second) <= tol<S>());
  CHECK(ln.isLine(tol<S>()));
  CHECK_FALSE(Line<S>(v, Vec3<S>(u + v)).isLine());  // a screw: v·u ≠ 0 in general
  CHECK(maxDiff<S>(Line<S>::throughPoint(x, v).pointNearestOrigin(),
                   Vec3<S>(x - v * (x.dot(v) / v.squaredNorm()))) <= tol<S>(1024));
  // Elements at infinity.
  CHECK_THROWS_WITH(Plane<S>::atInfinity().normalized(), Contains("plane at infinity"));
  CHECK_THROWS_WITH(Point<S>::freeVector(x).position(), Contains("free vector"));
  CHECK(abs(Point<S>::freeVector(x).normalized().bulk().norm() - S(1)) <= tol<S>());
  CHECK_THROWS_AS(Point<S>(S(1), Vec3<S>(S(0), std::numeric_limits<S>::quiet_NaN(), S(0))), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
