// Plücker lines (GF §6.1–6.4): construction, Klein quadric, distances, two-line relation, SE(3)
// action, lines at infinity; five scalars, both sides of every threshold.
#include "soma/geometry/lines/line.hpp"

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

TEMPLATE_TEST_CASE("Line through two points: Klein quadric, foot, distance (GF-6.2)", "[lines][line]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(11);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 8 : 100;
  for (int k = 0; k < n; ++k) {
    const Vec3<S> q1 = uniformVec<S, 3>(g, -3, 3), q2 = uniformVec<S, 3>(g, -3, 3), a = uniformVec<S, 3>(g, -3, 3);
    const PluckerLine<S> l = PluckerLine<S>::throughPoints(q1, q2);
    // Convention A: ω = q₂ − q₁, v = q₁ × q₂ = q₁ × ω (catalogue E6.1).
    REQUIRE((l.direction() - (q2 - q1)).norm() <= tol<S>() * S(4));
    REQUIRE((l.moment() - q1.cross(Vec3<S>(q2 - q1))).norm() <= tol<S>() * S(16));
    REQUIRE(kleinDefect(l.coords()) <= tol<S>());
    REQUIRE(l.contains(q1));
    REQUIRE(l.contains(q2));
    // foot ⟂ ω, on the line, nearest to origin.
    REQUIRE(abs(l.foot().dot(l.unitDirection())) <= tol<S>() * S(8));
    // Distance: Plücker form vs the book's λ-formula (GF §6.1).
    const Vec3<S> w = q2 - q1;
    const S lam = (a - q1).dot(w) / w.squaredNorm();
    const Vec3<S> ql = q1 + lam * w;
    REQUIRE(abs(l.distanceTo(a) - (ql - a).norm()) <= tol<S>() * S(32));
    REQUIRE((l.closestPoint(a) - ql).norm() <= tol<S>() * S(32));
    const Vec3<S> bookResidual = w.cross(Vec3<S>((q1 - a).cross(w))) / w.squaredNorm();
    REQUIRE((bookResidual - (ql - a)).norm() <= tol<S>() * S(32));
    // Same line under scaling by γ < 0 and γ > 0 (GF-6.1-same-line); a moved line is not.
    const PluckerLine<S> m(Vec3<S>(S(-3) * l.direction()), Vec3<S>(S(-3) * l.moment()));
    REQUIRE(l.sameAs(m));
    REQUIRE(l.sameAs(l.reversed()));
    REQUIRE_FALSE(l.sameAs(PluckerLine<S>::pointDirection(Vec3<S>(q1 + S(1) / S(100) * unitVec3<S>(g).cross(w)), w)));
  }
}

TEMPLATE_TEST_CASE("Line: invalid input, Klein quadric membership, lines at infinity", "[lines][line]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const Vec3<S> e1(S(1), S(0), S(0)), e2(S(0), S(1), S(0));
  REQUIRE_THROWS_AS(PluckerLine<S>(e1, e1), InvalidInput);  // ω·v = 1: off the quadric
  REQUIRE_THROWS_AS(PluckerLine<S>(Vec3<S>::Zero(), Vec3<S>::Zero()), InvalidInput);
  REQUIRE_THROWS_AS(PluckerLine<S>::throughPoints(e1, e1), InvalidInput);
  // Nearly coincident points on both sides of ε·|q|: 1e8-far points 1e8·ε·0.25 apart coincide.
  const Vec3<S> far = S(100000000) * e1;
  REQUIRE_THROWS_AS(PluckerLine<S>::throughPoints(far, Vec3<S>(far + Tolerance<S>::epsilon() * S(25000000) * e2)), InvalidInput);
  REQUIRE_NOTHROW(PluckerLine<S>::throughPoints(far, Vec3<S>(far + Tolerance<S>::epsilon() * S(400000000) * e2)));
  // (0; v) is a line: the line at infinity; it throws on every finite query.
  const PluckerLine<S> inf(Vec3<S>::Zero(), e2);
  REQUIRE(inf.isAtInfinity());
  REQUIRE_THROWS_AS(inf.foot(), InvalidInput);
  REQUIRE_THROWS_AS(inf.normalized(), InvalidInput);
  REQUIRE_FALSE(inf.contains(Vec3<S>::Zero()));
  // (ω; 0): a line through the origin; scale invariance at 1e±8.
  for (const S& sc : {S(1) / S(100000000), S(100000000)}) {
    const PluckerLine<S> l(Vec3<S>(sc * e1), Vec3<S>(sc * e2.cross(e1)));
    REQUIRE(l.foot().isApprox(e2, tol<S>()));
    REQUIRE(kleinDefect(l.coords()) == S(0));
  }
  // A random 6-vector is not on the quadric.
  auto& g = rng(12);
  const Vec6<S> r = uniformVec<S, 6>(g);
  REQUIRE(kleinDefect(r) > S(1) / S(1000));
  REQUIRE_THROWS_AS(PluckerLine<S>(r), InvalidInput);
}

TEMPLATE_TEST_CASE("Line from two planes — parallel planes give the line at infinity (GF-6.3)", "[lines][line]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(13);
  for (int k = 0; k < 20; ++k) {
    const Vec3<S> n1 = uniformVec<S, 3>(g), n2 = uniformVec<S, 3>(g);
    const S d1 = uniform<S>(g), d2 = uniform<S>(g);
    const PluckerLine<S> l = PluckerLine<S>::fromPlanes(n1, d1, n2, d2);
    for (const S& t : {S(-2), S(0), S(3)}) {
      const Vec3<S> p = l.pointAt(t);
      REQUIRE(abs(n1.dot(p) + d1) <= tol<S>(4096) * (S(1) + p.norm()) * n1.norm());
      REQUIRE(abs(n2.dot(p) + d2) <= tol<S>(4096) * (S(1) + p.norm()) * n2.norm());
    }
  }
  const Vec3<S> n(S(0), S(0), S(1)), e(S(1), S(0), S(0));
  const S eps = Tolerance<S>::epsilon();
  // Exactly parallel: (0; δ₁n₂ − δ₂n₁) = (0; (1 − 3)·e_z).
  const PluckerLine<S> inf = PluckerLine<S>::fromPlanes(n, S(1), n, S(3));
  REQUIRE(inf.isAtInfinity());
  REQUIRE(inf.moment().isApprox(Vec3<S>(S(0), S(0), S(-2)), tol<S>()));
  // Both sides of the threshold |n₁ × n₂| ≤ ε|n₁||n₂|.
  REQUIRE(PluckerLine<S>::fromPlanes(n, S(1), Vec3<S>(n + eps / S(4) * e), S(3)).isAtInfinity());
  REQUIRE_FALSE(PluckerLine<S>::fromPlanes(n, S(1), Vec3<S>(n + S(4) * eps * e), S(3)).isAtInfinity());
  REQUIRE_THROWS_AS(PluckerLine<S>::fromPlanes(n, S(1), Vec3<S>(S(2) * n), S(2)), InvalidInput);  // same plane
}

TEMPLATE_TEST_CASE("SE(3) acts on lines by Ad = [[R,0],[TR,R]] (GF-6.4-adjoint-on-lines)", "[lines][line]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(14);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 50;
  for (int k = 0; k < n; ++k) {
    const Vec3<S> q = uniformVec<S, 3>(g, -2, 2), w = unitVec3<S>(g);
    const SE3<S> x = SE3Tangent<S>(uniformVec<S, 6>(g, -2, 2)).exp();
    const PluckerLine<S> l = PluckerLine<S>::pointDirection(q, w);
    const PluckerLine<S> m = l.transformed(x);
    const PluckerLine<S> ref = PluckerLine<S>::pointDirection(x.act(q), Vec3<S>(x.so3().act(w)));
    REQUIRE((m.coords() - ref.coords()).norm() <= tol<S>(1024) * S(8));
    REQUIRE((lineAction(x) * l.coords() - ref.coords()).norm() <= tol<S>(1024) * S(8));
    REQUIRE(abs(kleinValue(m.coords())) <= tol<S>(1024));
    // A line at infinity is moved by the rotation only.
    const PluckerLine<S> inf = PluckerLine<S>::atInfinity(w);
    REQUIRE(inf.transformed(x).isAtInfinity());
    REQUIRE(inf.transformed(x).moment().isApprox(x.so3().act(w), tol<S>()));
  }
}

}  // namespace SOMA_UNITY_ID
