// Classification of Stewart–Gough platforms (stewart_class.hpp): coincident, collinear and
// coplanar joints decided at tol = √eps · size, each threshold tested on both sides; the class's
// complex count from the literature (Faugère & Lazard 1995).
#include "soma/geometry/parallel/stewart_class.hpp"

#include "support/scalars.hpp"

#include <random>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
template <class S> StewartPlatform<S> randomGeneral(std::mt19937_64& g, bool planar) {
  StewartPlatform<S> P;
  for (int i = 0; i < 6; ++i) {
    P.base[i] = Vec3<S>(test::uniform<S>(g), test::uniform<S>(g), planar ? S(0) : test::uniform<S>(g, -0.3, 0.3));
    P.platform[i] = Vec3<S>(test::uniform<S>(g, -0.6, 0.6), test::uniform<S>(g, -0.6, 0.6),
                            planar ? S(0) : test::uniform<S>(g, -0.2, 0.2));
    P.legs[i] = S(1);
  }
  return P;
}
template <class S> S tolOf(const StewartPlatform<S>& P) { return Tolerance<S>::sqrtEpsilon() * stewartScale<S>(P); }
}  // namespace

TEMPLATE_TEST_CASE("Stewart class: 6-6 general and planar, 40 — planarity decided at tol on both sides",
                   "[stewart][stewart_class]", float, double, long double) {
  using S = TestType;
  std::mt19937_64 g(21);
  for (int trial = 0; trial < 5; ++trial) {
    const auto G = randomGeneral<S>(g, false);
    const auto c = classifyStewart<S>(G);
    CHECK(c.name == "6-6");
    CHECK(!c.base_planar);
    CHECK(!c.platform_planar);
    CHECK(c.expected_count == 40);
    CHECK(c.singular_reason.empty());

    auto P = randomGeneral<S>(g, true);
    const auto cp = classifyStewart<S>(P);
    CHECK(cp.base_planar);
    CHECK(cp.platform_planar);
    CHECK(!cp.similar);
    CHECK(cp.expected_count == 40);
    const S tol = tolOf<S>(P);
    auto in = P, out = P;
    in.base[3].z() = S(0.1) * tol;
    out.base[3].z() = S(10) * tol;
    in.platform[4].z() = S(-0.1) * tol;
    out.platform[4].z() = S(-10) * tol;
    const auto ci = classifyStewart<S>(in), co = classifyStewart<S>(out);
    CHECK(ci.base_planar);
    CHECK(ci.platform_planar);
    CHECK(!co.base_planar);
    CHECK(!co.platform_planar);
  }
}

TEMPLATE_TEST_CASE("Stewart class: 6-3 and 3-6 have 16 — coincidence decided at tol on both sides",
                   "[stewart][stewart_class]", float, double, long double) {
  using S = TestType;
  std::mt19937_64 g(63);
  const auto R = randomGeneral<S>(g, false);
  auto P = R;
  for (int i = 0; i < 6; ++i) P.platform[i] = R.platform[((i + 1) / 2) % 3];  // legs (1, 2), (3, 4), (5, 0) share
  const auto c = classifyStewart<S>(P);
  CHECK(c.name == "6-3");
  CHECK(c.platform_distinct == 3);
  CHECK(c.expected_count == 16);

  StewartPlatform<S> M = P;  // the mirror: 3-6
  std::swap(M.base, M.platform);
  const auto cm = classifyStewart<S>(M);
  CHECK(cm.name == "3-6");
  CHECK(cm.expected_count == 16);

  const S tol = tolOf<S>(P);
  auto in = P, out = P;
  in.platform[2].x() += S(0.5) * tol;  // joint 2 shares with joint 1
  out.platform[2].x() += S(10) * tol;
  CHECK(classifyStewart<S>(in).name == "6-3");
  const auto co = classifyStewart<S>(out);
  CHECK(co.name == "6-4");
  CHECK(co.expected_count == 32);  // 6-4 with two pairs (SOMA-11.5-stewart-classes: homotopy and PHCpack)
}

TEMPLATE_TEST_CASE("Stewart class: 3-3 octahedral has 16 — a 3-3 with two legs on one joint pair is singular",
                   "[stewart][stewart_class]", float, double, long double) {
  using S = TestType;
  std::mt19937_64 g(33);
  const auto R = randomGeneral<S>(g, false);
  StewartPlatform<S> P = R;
  const int b[6] = {0, 0, 1, 1, 2, 2}, q[6] = {0, 1, 1, 2, 2, 0};  // octahedron: each base joint meets two
  for (int i = 0; i < 6; ++i) P.base[i] = R.base[b[i]], P.platform[i] = R.platform[q[i]];
  const auto c = classifyStewart<S>(P);
  CHECK(c.name == "3-3 octahedral");
  CHECK(c.expected_count == 16);
  for (int i = 0; i < 6; ++i) P.platform[i] = R.platform[b[i]];  // legs 0 and 1 both join base 0 to platform 0
  const auto d = classifyStewart<S>(P);
  CHECK(d.name == "3-3");
  CHECK(!d.expected_count);
  CHECK_THAT(d.singular_reason, Catch::Matchers::Contains("a repeated leg"));
}

TEMPLATE_TEST_CASE("Stewart class: collinear joints are architecturally singular (a self-motion), both sides of tol",
                   "[stewart][stewart_class]", float, double, long double) {
  using S = TestType;
  std::mt19937_64 g(7);
  auto P = randomGeneral<S>(g, false);
  const Vec3<S> a(S(0.1), S(-0.2), S(0.05)), u = Vec3<S>(S(1), S(2), S(-0.5)).normalized();
  for (int i = 0; i < 6; ++i) P.platform[i] = a + S(0.2 * (i - 2.5)) * u;
  const auto c = classifyStewart<S>(P);
  CHECK(c.platform_collinear);
  CHECK(!c.singular_reason.empty());
  CHECK(!c.expected_count);
  // The self-motion itself: turning the platform about its line keeps every leg length.
  SE3<S> g0;
  const auto L0 = stewartLegLengths<S>(P, g0);
  // Twist (ω, v) of a pure rotation about the line through a along u: v = a × ω.
  const SE3<S> turn = SE3Tangent<S>(Vec3<S>(S(0.7) * u), Vec3<S>(S(0.7) * a.cross(u))).exp();
  const auto L1 = stewartLegLengths<S>(P, turn);
  using std::abs;
  for (int i = 0; i < 6; ++i) CHECK(abs(L1[i] - L0[i]) <= S(50) * Tolerance<S>::epsilon());

  const S tol = tolOf<S>(P);
  auto in = P, out = P;
  const Vec3<S> off = u.cross(Vec3<S>(S(0), S(0), S(1))).normalized();
  in.platform[3] += S(0.1) * tol * off;
  out.platform[3] += S(10) * tol * off;
  CHECK(classifyStewart<S>(in).platform_collinear);
  CHECK(!classifyStewart<S>(out).platform_collinear);
  CHECK(classifyStewart<S>(out).singular_reason.empty());
}

TEMPLATE_TEST_CASE("Stewart class: similar planar base and platform are flagged and get no count",
                   "[stewart][stewart_class]", float, double, long double) {
  using S = TestType;
  std::mt19937_64 g(5);
  auto P = randomGeneral<S>(g, true);
  const S ct = S(0.6), st = S(0.8);
  for (int i = 0; i < 6; ++i)  // platform = ½ · rotation · base, shifted
    P.platform[i] = Vec3<S>(S(0.5) * (ct * P.base[i].x() - st * P.base[i].y()) + S(0.1),
                            S(0.5) * (st * P.base[i].x() + ct * P.base[i].y()), S(0));
  const auto c = classifyStewart<S>(P);
  CHECK(c.similar);
  CHECK(!c.expected_count);
  P.platform[2].x() += S(10) * tolOf<S>(P);
  CHECK(!classifyStewart<S>(P).similar);
}

}  // namespace SOMA_UNITY_ID
