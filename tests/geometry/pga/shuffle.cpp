// GF §10.2.3: the shuffle product as the book defines it (permutation sum, corrected E10.11)
// against the regressive product of multivector.hpp (Poincaré duality), on every pair of basis
// blades and on random elements; the book's worked example and its coordinate formulas.
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;

TEST_CASE("pga shuffle: the book's example e1e2e3 ∨ e2e3𝐞 = e2e3", "[pga][shuffle]") {
  // GF-10.2.3-shuffle-definition: blades 0b0111 ∨ 0b1110 = +1 · 0b0110.
  CHECK(shuffleCoefficient(7, 14) == 1);
  // j + k < n gives nothing; the pseudoscalar is the identity of ∨ on either side.
  CHECK(shuffleCoefficient(1, 2) == 0);
  for (Blade b = 0; b < 16; ++b) {
    CHECK(shuffleCoefficient(15, b) == 1);
    CHECK(shuffleCoefficient(b, 15) == 1);
  }
}

TEST_CASE("pga shuffle: the book's definition equals the regressive product on all 256 blade pairs",
          "[pga][shuffle]") {
  int nonzero = 0;
  for (Blade a = 0; a < 16; ++a)
    for (Blade b = 0; b < 16; ++b) {
      INFO("a = " << a << ", b = " << b);
      CHECK(shuffleCoefficient(a, b) == Cl031::regressiveSign(a, b));
      if (shuffleCoefficient(a, b) != 0) ++nonzero;
    }
  // Pairs with a | b = all four generators: Σ_j C(4,j) 2^j = 81.
  CHECK(nonzero == 81);
}

TEMPLATE_TEST_CASE("pga shuffle: random elements, and the book's coordinate formulas", "[pga][shuffle]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1001);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 2 : 10;
  for (int t = 0; t < trials; ++t) {
    DenseElement<S> a, b;
    for (int i = 0; i < a.size; ++i) a[i] = uniform<S>(g), b[i] = uniform<S>(g);
    CHECK(clifford::maxAbsDiff(shuffle(a, b), a & b) <= tol<S>(64));
    const Vec3<S> x1 = rvec<S>(g), x2 = rvec<S>(g), x = rvec<S>(g), n = rvec<S>(g);
    const S d = uniform<S>(g);
    // GF-10.2.3-join-two-points: direction x2 − x1, moment x1 × x2.
    const Line<S> l = shuffle(Point<S>(x1), Point<S>(x2));
    CHECK(maxDiff<S>(l.direction(), x2 - x1) <= tol<S>());
    CHECK(maxDiff<S>(l.moment(), x1.cross(x2)) <= tol<S>());
    // GF-10.2.3-join-point-line: (x·u)𝐞 + (u − x × v)·(e1, e2, e3).
    const Vec3<S> v = rvec<S>(g), u = rvec<S>(g);
    const Plane<S> pl = shuffle(Point<S>(x), Line<S>(v, u));
    CHECK(maxDiff<S>(pl.normal(), Vec3<S>(u - x.cross(v))) <= tol<S>());
    CHECK(abs(pl.distance() - x.dot(u)) <= tol<S>());
    // GF-10.2.3-point-plane-and-coplanarity: p ∨ π = d − x·n.
    CHECK(abs(shuffle(Point<S>(x), Plane<S>(n, d)) - (d - x.dot(n))) <= tol<S>());
    // GF-10.2.3-line-line-shuffle: ℓ1 ∨ ℓ2 = v·μ + u·w (the reciprocal product).
    const Vec3<S> w = rvec<S>(g), mu = rvec<S>(g);
    CHECK(abs(shuffle(Line<S>(v, u), Line<S>(w, mu)) - (v.dot(mu) + u.dot(w))) <= tol<S>());
  }
}

}  // namespace SOMA_UNITY_ID
