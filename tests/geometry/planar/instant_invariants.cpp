// GF §5.3: instantaneous invariants of a planar motion, each against a second method.
#include "soma/geometry/planar/fourbar.hpp"
#include "soma/geometry/planar/instant_invariants.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::planar;
using soma::test::rng;
using soma::test::uniform;
using std::abs;
using std::cos;
using std::sin;
using std::sqrt;

namespace {

/// A random motion jet: angle and origin derivatives uniform in [−1, 1], ω bounded away from 0.
template <class S> MotionJet<S> randomJet(std::mt19937_64& g) {
  std::array<S, 5> a;
  std::array<Vec2<S>, 5> d;
  for (int k = 0; k < 5; ++k) {
    a[k] = uniform<S>(g);
    // Drawn y first, then x: explicit, because C++ leaves the order of constructor arguments
    // unspecified (GCC and clang differ) and the fixed-seed cases must not depend on the compiler.
    const S y = uniform<S>(g);
    const S x = uniform<S>(g);
    d[k] = Vec2<S>(x, y);
  }
  a[1] = uniform<S>(g, 0.4, 1.2) * (uniform<S>(g) < S(0) ? S(-1) : S(1));
  return MotionJet<S>::fromDerivatives(a, d);
}

template <class S> S tolFor(double k = 4096) { return scalarCast<S>(k) * Tolerance<S>::epsilon(); }

}  // namespace

TEMPLATE_TEST_CASE("Taylor series arithmetic: sin² + cos² = 1, (√f)² = f, atan2 inverts tan", "[planar][taylor]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(501);
  Series<S> f;
  for (int k = 0; k < 5; ++k) f.a[k] = uniform<S>(g);
  f.a[0] = S(2);
  Series<S> s, c;
  sincos(f, s, c);
  const Series<S> one = s * s + c * c;
  CHECK(abs(one.a[0] - S(1)) <= tolFor<S>(8));
  for (int k = 1; k < 5; ++k) CHECK(abs(one.a[k]) <= tolFor<S>(64));
  const Series<S> r = sqrt(f), back = r * r;
  for (int k = 0; k < 5; ++k) CHECK(abs(back.a[k] - f.a[k]) <= tolFor<S>(64));
  const Series<S> th = atan2(s, c);  // = f (f(0) = 2 is inside (−π, π))
  for (int k = 0; k < 5; ++k) CHECK(abs(th.a[k] - f.a[k]) <= tolFor<S>(256));
  Series<S> z;
  z.a[0] = S(0);
  z.a[1] = S(1);
  CHECK_THROWS_AS(sqrt(z), InvalidInput);  // a branch point
}

TEMPLATE_TEST_CASE("(P1)–(P4) from (ω…, r…) equal the jet's point derivatives (P4 corrected, E5.13)",
                   "[planar][invariants]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(502);
  const int cases = std::is_same_v<S, mpreal> ? 3 : 20;
  for (int c = 0; c < cases; ++c) {
    const MotionJet<S> jet = randomJet<S>(g);
    const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
    const Vec2<S> p(uniform<S>(g, -2, 2), uniform<S>(g, -2, 2));
    const auto direct = jet.pointDerivatives(p);
    const auto book = inv.pointDerivatives(p);
    S scale(1);
    for (int k = 0; k < 5; ++k) scale = std::max<S>(scale, direct[k].norm());
    for (int k = 1; k < 5; ++k) CHECK((direct[k] - book[k]).norm() <= tolFor<S>(1 << 14) * scale * (S(1) + inv.pole().norm()));
    // The pole does not move at t = 0: P1 vanishes there.
    CHECK(jet.pointDerivatives(inv.pole())[1].norm() <= tolFor<S>(1 << 12) * scale);
    // The printed (P4) differs by ω(2ω²E₂ṙ − 3ω̇ṙ − 3ωr̈) (erratum E5.13): nonzero in general.
    const S w = inv.omega(), wd = inv.omega(1);
    const Vec2<S> rd = inv.r(1), rdd = inv.r(2);
    const Vec2<S> diff = w * (S(2) * w * w * Vec2<S>(rd(1), -rd(0)) - S(3) * wd * rd - S(3) * w * rdd);
    CHECK(diff.norm() > S(1e-3) * scale);
  }
}

TEMPLATE_TEST_CASE("inflection circle: det[ṗ, p̈] = ω²·(p − r)ᵀ(ω(p − r) − 2E₂ṙ) — Ball's point is an undulation",
                   "[planar][invariants]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(503);
  const int cases = std::is_same_v<S, mpreal> ? 3 : 20;
  for (int c = 0; c < cases; ++c) {
    const MotionJet<S> jet = randomJet<S>(g);
    const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
    const Poly2<S> infl = inflectionCurve(jet);
    const S w = inv.omega();
    for (int k = 0; k < 4; ++k) {
      const Vec2<S> p(uniform<S>(g, -3, 3), uniform<S>(g, -3, 3));
      CHECK(abs(infl(p(0), p(1)) - w * w * inv.inflectionResidual(p)) <=
            tolFor<S>(1 << 14) * infl.magnitude(p(0), p(1)) * (S(1) + inv.pole().squaredNorm()));
    }
    // points of the book's circle have zero path curvature (direct derivatives)
    const Circle<S> ci = inv.inflectionCircle();
    const S ang = uniform<S>(g, -3, 3);
    const Vec2<S> q = ci.centre + ci.radius * Vec2<S>(cos(ang), sin(ang));
    const auto d = jet.pointDerivatives(q);
    CHECK(abs(cross2<S>(d[1], d[2])) <= tolFor<S>(1 << 14) * d[1].norm() * d[2].norm() * (S(1) + ci.radius));
    CHECK((inv.inflectionPole() - ci.centre).norm() - ci.radius <= tolFor<S>(256) * (S(1) + ci.radius));
    // Ball's point (corrected, E5.10/E5.11): on the circle and det[ṗ, p⃛] = 0
    const Vec2<S> b = inv.ballPoint();
    const auto db = jet.pointDerivatives(b);
    const S sc = db[1].norm() * (db[2].norm() + db[3].norm()) * (S(1) + (b - inv.pole()).squaredNorm());
    CHECK(abs(cross2<S>(db[1], db[2])) <= tolFor<S>(1 << 16) * sc);
    CHECK(abs(cross2<S>(db[1], db[3])) <= tolFor<S>(1 << 16) * sc);
  }
}

TEMPLATE_TEST_CASE("cubic of stationary curvature: book form = determinant form = −12ω⁴v²·normal form (μ corrected, E5.12)",
                   "[planar][invariants]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(504);
  const int cases = std::is_same_v<S, mpreal> ? 3 : 20;
  for (int c = 0; c < cases; ++c) {
    const MotionJet<S> jet = randomJet<S>(g);
    const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
    const Poly2<S> det = stationaryCurvatureCurve(jet), book = inv.stationaryCurvatureCubicPoly();
    const CubicNormalForm<S> nf = inv.cubicNormalForm();
    const S w = inv.omega(), v = nf.frame.v;
    CHECK(det.degree(tolFor<S>(1 << 12)) == 3);
    for (int k = 0; k < 4; ++k) {
      const Vec2<S> p(uniform<S>(g, -3, 3), uniform<S>(g, -3, 3));
      const S m = det.magnitude(p(0), p(1)) * (S(1) + inv.pole().squaredNorm());
      CHECK(abs(det(p(0), p(1)) - inv.stationaryCurvatureCubic(p)) <= tolFor<S>(1 << 14) * m);
      CHECK(abs(book(p(0), p(1)) - inv.stationaryCurvatureCubic(p)) <= tolFor<S>(1 << 14) * m);
      const Vec2<S> l = nf.frame.local(p);
      CHECK(abs(inv.stationaryCurvatureCubic(p) + S(12) * w * w * w * w * v * v * nf(l(0), l(1))) <= tolFor<S>(1 << 14) * m);
    }
    // the second (5-point) cubic: direct determinant = −(book's corrected α…ξ form) (E5.14)
    const Poly2<S> five = fivePointContactCurve(jet);
    const BurmesterCubic<S> bc = inv.burmesterCubic();
    for (int k = 0; k < 3; ++k) {
      const Vec2<S> p(uniform<S>(g, -3, 3), uniform<S>(g, -3, 3));
      const Vec2<S> l = nf.frame.local(p);
      CHECK(abs(five(p(0), p(1)) + bc(l(0), l(1))) <=
            tolFor<S>(1 << 15) * five.magnitude(p(0), p(1)) * (S(1) + inv.pole().squaredNorm()));
    }
  }
}

TEMPLATE_TEST_CASE("Burmester points: the book's count 9 = 2 + 3 + 4, each point has 5-point contact",
                   "[planar][burmester]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(505);
  const int cases = std::is_same_v<S, mpreal> ? 2 : 15;
  int realSeen[5] = {0, 0, 0, 0, 0};
  for (int c = 0; c < cases; ++c) {
    const MotionJet<S> jet = randomJet<S>(g);
    // Well-conditioned instants only: when the inflection circle is tiny (|ṙ|/|ω| < 0.05) the four
    // points crowd into the node at the pole and the intersection is ill-conditioned (the
    // degenerate side, ṙ = 0, is tested in "extremes").
    if (InstantInvariants<S>::fromJet(jet).inflectionCircle().radius < S(1) / S(20)) continue;
    const BurmesterPoints<S> bp = burmesterPoints(jet);
    CHECK(bp.formDegree == 7);
    INFO("case " << c << " real " << bp.realCount);
    CHECK(bp.circularRemainder <= tolFor<S>(1 << 12));
    CHECK(bp.tangentRemainder <= tolFor<S>(1 << 12));
    REQUIRE(bp.x.size() == 4);
    CHECK(bp.realCount % 2 == 0);
    ++realSeen[bp.realCount];
    for (int k = 0; k < 4; ++k) {
      if (!bp.isReal[k]) continue;
      CHECK(bp.residuals[k] <= tolFor<S>(1 << 16));
      // 5-point contact with the osculating circle: (C3), (C4) hold with c from (C1), (C2).
      const Vec2<S> p(bp.x[k].re, bp.y[k].re);
      const auto d = jet.pointDerivatives(p);
      Vec2<S> cc;
      REQUIRE(curvatureCentre(p, d[1], d[2], cc));
      const Vec2<S> u = p - cc;
      const S sc3 = u.norm() * d[3].norm() + S(3) * d[1].norm() * d[2].norm();
      const S sc4 = u.norm() * d[4].norm() + S(4) * d[1].norm() * d[3].norm() + S(3) * d[2].squaredNorm();
      INFO("p = " << toString(p(0)) << ", " << toString(p(1)) << " pole " << toString(InstantInvariants<S>::fromJet(jet).pole()(0))
                  << ", " << toString(InstantInvariants<S>::fromJet(jet).pole()(1)) << " |u| = " << toString(u.norm()));
      CHECK(abs(d[3].dot(u) + S(3) * d[2].dot(d[1])) <= tolFor<S>(1 << 20) * sc3);
      CHECK(abs(d[4].dot(u) + S(4) * d[3].dot(d[1]) + S(3) * d[2].dot(d[2])) <= tolFor<S>(1 << 20) * sc4);
    }
  }
  CHECK(realSeen[1] + realSeen[3] == 0);
}

TEMPLATE_TEST_CASE("classical centrode: q(0) = r, q̇ = 2ṙ, q̈ = 3r̈ − (ω̇/ω)ṙ − ωE₂ṙ (erratum E5.9)", "[planar][centrode]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(506);
  for (int c = 0; c < 6; ++c) {
    const MotionJet<S> jet = randomJet<S>(g);
    const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
    const auto q = fixedCentrode(jet);
    const Vec2<S> q0(q[0].derivative(0), q[1].derivative(0)), q1(q[0].derivative(1), q[1].derivative(1)),
        q2(q[0].derivative(2), q[1].derivative(2));
    const S sc = S(1) + inv.r(0).norm() + inv.r(1).norm() + inv.r(2).norm();
    CHECK((q0 - inv.r(0)).norm() <= tolFor<S>(1 << 12) * sc);
    CHECK((q1 - S(2) * inv.r(1)).norm() <= tolFor<S>(1 << 12) * sc * sc);
    const Vec2<S> rd = inv.r(1);
    const Vec2<S> expect = S(3) * inv.r(2) - inv.omega(1) / inv.omega() * rd - inv.omega() * Vec2<S>(rd(1), -rd(0));
    CHECK((q2 - expect).norm() <= tolFor<S>(1 << 14) * sc * sc * sc);
    // the homogeneous instantaneous centre agrees
    const Vec3<S> h = jet.instantCentreHomogeneous();
    CHECK((Vec2<S>(h(0) / h(2), h(1) / h(2)) - inv.pole()).norm() <= tolFor<S>(1 << 12) * sc);
    // the moving centrode at t = 0 is the pole in body coordinates
    const auto mc = movingCentrode(jet);
    const Vec2<S> body = jet.pose().inverse().act(inv.pole());
    CHECK((Vec2<S>(mc[0].a[0], mc[1].a[0]) - body).norm() <= tolFor<S>(1 << 12) * sc);
  }
}

TEMPLATE_TEST_CASE("time scaling: r is geometric (r^(k) scales as c^k), ω as c", "[planar][invariants]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(507);
  const MotionJet<S> jet = randomJet<S>(g);
  const S c = S(3) / S(2);
  const InstantInvariants<S> a = InstantInvariants<S>::fromJet(jet), b = InstantInvariants<S>::fromJet(jet.timeScaled(c));
  S ck(1);
  for (int k = 0; k < 4; ++k) {
    CHECK((b.r(k) - ck * a.r(k)).norm() <= tolFor<S>(1 << 12) * (S(1) + ck * a.r(k).norm()));
    ck *= c;
  }
  CHECK(abs(b.omega() - c * a.omega()) <= tolFor<S>(64));
  // inflection circle and Ball's point do not depend on the time law
  CHECK((b.inflectionCircle().centre - a.inflectionCircle().centre).norm() <= tolFor<S>(1 << 12) * (S(1) + a.inflectionCircle().radius));
  CHECK((b.ballPoint() - a.ballPoint()).norm() <= tolFor<S>(1 << 14) * (S(1) + a.ballPoint().norm()));
}

TEMPLATE_TEST_CASE("extremes: pole at infinity (translation), near-translation, stationary pole (rotation about a fixed point)",
                   "[planar][extremes]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const SE2<S> g0(S(1) / S(3), Vec2<S>(S(1) / S(2), -S(1) / S(4)));
  // pure translation with a time law: ω ≡ 0
  const MotionJet<S> tr = MotionJet<S>::screw(g0, SE2Tangent<S>(S(0), S(2), S(1)), {S(0), S(1), S(1) / S(2), S(0), S(0)});
  CHECK_THROWS_AS(InstantInvariants<S>::fromJet(tr), InvalidInput);
  CHECK_THROWS_AS(burmesterPoints(tr), InvalidInput);
  const Vec3<S> h = tr.instantCentreHomogeneous();
  CHECK(h(2) == S(0));
  CHECK(abs(Vec2<S>(h(0), h(1)).dot(Vec2<S>(S(2), S(1)))) <= tolFor<S>(16));  // direction ⊥ velocity
  // det[ṗ, p̈] is constant for a translation: every point or none is an inflection
  CHECK(inflectionCurve(tr).degree(tolFor<S>(64)) <= 0);
  // ω = 0 but ω̇ ≠ 0: the inflection "circle" is a line (the circle through the pole at infinity)
  std::array<S, 5> ang{S(0), S(0), S(1), S(0), S(0)};
  std::array<Vec2<S>, 5> org{Vec2<S>(S(0), S(0)), Vec2<S>(S(1), S(0)), Vec2<S>(S(0), S(0)), Vec2<S>(S(0), S(0)), Vec2<S>(S(0), S(0))};
  const MotionJet<S> lin = MotionJet<S>::fromDerivatives(ang, org);
  CHECK(inflectionCurve(lin).degree(tolFor<S>(64)) == 1);
  CHECK_THROWS_AS(InstantInvariants<S>::fromJet(lin), InvalidInput);
  // the other side: ω small but nonzero — the pole is far, along J v / ω
  const S eps = S(1) / S(1000);
  ang[1] = eps;
  const MotionJet<S> near = MotionJet<S>::fromDerivatives(ang, org);
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(near);
  CHECK((inv.pole() - Vec2<S>(S(0), S(1) / eps)).norm() <= tolFor<S>(1 << 12) / eps);
  // rotation about a fixed point with a non-uniform law: r ≡ c, ṙ = r̈ = 0 (the circle shrinks to r)
  const Vec2<S> cen(S(1) / S(5), S(3) / S(7));
  const MotionJet<S> rot = MotionJet<S>::screw(SE2<S>(S(1) / S(2), Vec2<S>(S(1), S(2))), SE2Tangent<S>(S(1), cen(1), -cen(0)),
                                               {S(0), S(1), S(1) / S(3), -S(1) / S(5), S(1) / S(7)});
  const InstantInvariants<S> ir = InstantInvariants<S>::fromJet(rot);
  CHECK((ir.pole() - cen).norm() <= tolFor<S>(256));
  for (int k = 1; k < 4; ++k) CHECK(ir.r(k).norm() <= tolFor<S>(1 << 10));
  CHECK(ir.inflectionCircle().radius <= tolFor<S>(1 << 10));
  CHECK_THROWS_AS(ir.normalFrame(), InvalidInput);
  // every body point moves on a circle about c: its curvature centre is c
  const Vec2<S> p(S(2), -S(1));
  const auto d = rot.pointDerivatives(p);
  Vec2<S> cc;
  REQUIRE(curvatureCentre(p, d[1], d[2], cc));
  CHECK((cc - cen).norm() <= tolFor<S>(1 << 10));
}

TEST_CASE("inflection circle by sampled paths: coupler points whose path curvature vanishes lie on it", "[planar][second-method]") {
  // Catalogue 4-bar instance: c1 = (0,0), c4 = (3,0), crank 1.2, coupler 2.5, rocker 2.0, θ1 = 1.
  using S = double;
  const FourBar<S> fb(Vec2<S>(0, 0), Vec2<S>(3, 0), 1.2, 2.5, 2.0);
  const std::array<S, 5> law{1.0, 1.0, 0.0, 0.0, 0.0};
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(fb.couplerJet(1.0, 1, law));
  const Circle<S> ci = inv.inflectionCircle();
  // along a ray from the pole, find the point where the finite-difference curvature changes sign
  const SE2<S> M0 = fb.solve(1.0, 1)->coupler;
  auto curvatureFD = [&](const Vec2<S>& world) {
    const Vec2<S> body = M0.inverse().act(world);
    const double h = 1e-3;
    Vec2<S> P[5];
    for (int k = -2; k <= 2; ++k) P[k + 2] = fb.solve(1.0 + k * h, 1)->coupler.act(body);
    const Vec2<S> d1 = (P[0] - S(8) * P[1] + S(8) * P[3] - P[4]) / (12 * h);
    const Vec2<S> d2 = (-P[0] + S(16) * P[1] - S(30) * P[2] + S(16) * P[3] - P[4]) / (12 * h * h);
    return cross2<S>(d1, d2) / std::pow(d1.norm(), 3);
  };
  int found = 0;
  for (double ang : {0.3, 1.1, 2.0, 4.0}) {
    const Vec2<S> dir(std::cos(ang), std::sin(ang));
    // the circle meets the ray from the pole at s* = 2 (centre − r)·dir (if positive)
    const double sStar = 2 * (ci.centre - inv.pole()).dot(dir);
    if (sStar <= 0.5) continue;
    double a = 0.5 * sStar, b = 1.5 * sStar;
    double fa = curvatureFD(inv.pole() + a * dir);
    REQUIRE(fa * curvatureFD(inv.pole() + b * dir) < 0);
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b), fm = curvatureFD(inv.pole() + m * dir);
      if (fa * fm <= 0) b = m;
      else {
        a = m;
        fa = fm;
      }
    }
    const Vec2<S> p = inv.pole() + 0.5 * (a + b) * dir;
    CHECK(std::abs((p - ci.centre).norm() - ci.radius) <= 1e-6 * ci.radius);
    ++found;
  }
  CHECK(found >= 2);
}

}  // namespace SOMA_UNITY_ID
