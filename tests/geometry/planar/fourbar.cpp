// GF §5.4: the planar 4-bar — classification, circuits, coupler curves, the book's formulas.
#include "soma/geometry/planar/fourbar.hpp"
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
template <class S> S tolFor(double k) { return scalarCast<S>(k) * Tolerance<S>::epsilon(); }
template <class S> S num(const char* s) { return fromString<S>(s); }

/// Catalogue test instance (GF-5.4-fourbar-instant-centre): c1 = (0,0), c4 = (3,0), crank 1.2,
/// coupler 2.5, rocker 2.0, θ1 = 1, ω1 = 1, ω̇1 = 0.3, ω̈1 = −0.2, upper branch (mode +1).
template <class S> FourBar<S> catalogueBar(const Vec2<S>& pc = Vec2<S>::Zero()) {
  return FourBar<S>(Vec2<S>(S(0), S(0)), Vec2<S>(S(3), S(0)), num<S>("1.2"), num<S>("2.5"), S(2), pc);
}
template <class S> std::array<S, 5> catalogueLaw() { return {S(1), S(1), num<S>("0.3"), num<S>("-0.2"), S(0)}; }

/// Max distance between consecutive poses of a traced circuit (c2 and c3), closing the loop.
template <class S> S maxStep(const std::vector<FourBarPose<S>>& t) {
  S m(0);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const auto& a = t[k];
    const auto& b = t[(k + 1) % t.size()];
    m = std::max<S>(m, std::max<S>((a.c2 - b.c2).norm(), (a.c3 - b.c3).norm()));
  }
  return m;
}
template <class S> S loopResidual(const FourBar<S>& fb, const std::vector<FourBarPose<S>>& t) {
  using std::abs;
  S m(0);
  for (const auto& p : t) {
    m = std::max<S>(m, abs((p.c2 - fb.c1()).norm() - fb.crank()));
    m = std::max<S>(m, abs((p.c3 - p.c2).norm() - fb.coupler()));
    m = std::max<S>(m, abs((p.c3 - fb.c4()).norm() - fb.rocker()));
  }
  return m;
}
}  // namespace

TEMPLATE_TEST_CASE("catalogue 4-bar: ω, ω4, ω̇ and the book's §5.4 formulas", "[planar][fourbar]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const FourBar<S> fb = catalogueBar<S>();
  const auto pose = fb.solve(S(1), 1);
  REQUIRE(pose);
  const MotionJet<S> jet = fb.couplerJet(S(1), 1, catalogueLaw<S>());
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
  const S tol = std::max<S>(tolFor<S>(1 << 12), num<S>("1e-12"));
  CHECK(abs(inv.omega() - num<S>("-0.291174739311")) <= tol * S(10));
  CHECK(abs(inv.omega(1) - num<S>("0.261021037565")) <= tol * S(10));
  const Vec2<S> c1 = fb.c1(), c2 = pose->c2, c3 = pose->c3, c4 = fb.c4();
  const auto ratios = FourBar<S>::velocityRatios(c1, c2, c3, c4);
  CHECK(abs(ratios.first - inv.omega()) <= tolFor<S>(1 << 12));
  CHECK(abs(ratios.second - num<S>("0.360970565066")) <= tol * S(10));
  // ω4 from the jet: the rocker pin c3 = body point (l2, 0)
  const auto d3 = jet.bodyPointDerivatives(Vec2<S>(fb.coupler(), S(0)));
  CHECK(abs(cross2<S>(c3 - c4, d3[1]) / (c3 - c4).squaredNorm() - ratios.second) <= tolFor<S>(1 << 12));
  // instant centre = pole; both book expressions for r
  const Vec3<S> ic = FourBar<S>::instantCentre(c1, c2, c3, c4);
  CHECK((Vec2<S>(ic(0) / ic(2), ic(1) / ic(2)) - inv.pole()).norm() <= tolFor<S>(1 << 12));
  CHECK((c2 + (S(1) / inv.omega()) * (c1 - c2) - inv.pole()).norm() <= tolFor<S>(1 << 12));
  CHECK((c3 + (ratios.second / inv.omega()) * (c4 - c3) - inv.pole()).norm() <= tolFor<S>(1 << 12));
  // ω̇ formula and the pole velocity from both sides (with the book's ṙ, E5.9)
  CHECK(abs(FourBar<S>::omegaDot(c1, c2, c3, c4, S(1), num<S>("0.3")) - inv.omega(1)) <= tolFor<S>(1 << 12));
  const S w4dot = [&] {  // ω̇4 from the jet: d/dt of det[c3 − c4, ċ3]/|c3 − c4|²
    const Vec2<S> u = c3 - c4;
    const S n2 = u.squaredNorm();
    const S w4 = cross2<S>(u, d3[1]) / n2;
    return cross2<S>(u, d3[2]) / n2 - S(2) * w4 * u.dot(d3[1]) / n2;
  }();
  const Vec2<S> rd1 = FourBar<S>::poleVelocity(c1, c2, inv.omega(), inv.omega(1), S(1), num<S>("0.3"));
  const Vec2<S> rd4 = FourBar<S>::poleVelocity(c4, c3, inv.omega(), inv.omega(1), ratios.second, w4dot);
  CHECK((rd1 - inv.r(1)).norm() <= tolFor<S>(1 << 13));
  CHECK((rd4 - inv.r(1)).norm() <= tolFor<S>(1 << 13));
  // c2 and c3 move on circles: they lie on the cubic of stationary curvature
  const S cs = stationaryCurvatureCurve(jet).magnitude(c2(0), c2(1));
  CHECK(abs(inv.stationaryCurvatureCubic(c2)) <= tolFor<S>(1 << 14) * cs);
  CHECK(abs(inv.stationaryCurvatureCubic(c3)) <= tolFor<S>(1 << 14) * cs);
}

TEMPLATE_TEST_CASE("catalogue 4-bar: inflection circle and Burmester points (catalogue values)", "[planar][fourbar][burmester]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const FourBar<S> fb = catalogueBar<S>();
  const MotionJet<S> jet = fb.couplerJet(S(1), 1, catalogueLaw<S>());
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
  const Circle<S> ci = inv.inflectionCircle();
  const S tol = std::max<S>(tolFor<S>(1 << 16), num<S>("1e-8"));
  CHECK(abs(ci.centre(0) - num<S>("-9.186780624")) <= tol * S(10));
  CHECK(abs(ci.centre(1) - num<S>("1.363498014")) <= tol * S(10));
  CHECK(abs(ci.radius - num<S>("12.45738492")) <= tol * S(10));
  const BurmesterPoints<S> bp = burmesterPoints(jet);
  CHECK(bp.realCount == 2);
  const auto pose = fb.solve(S(1), 1);
  // the two real ones are the moving pivots c2, c3 (GF §5.4)
  for (const Vec2<S>& pin : {pose->c2, pose->c3}) {
    S best(1e9);
    for (int k = 0; k < 4; ++k)
      if (bp.isReal[k]) best = std::min<S>(best, (Vec2<S>(bp.x[k].re, bp.y[k].re) - pin).norm());
    CHECK(best <= std::max<S>(tolFor<S>(1 << 20), num<S>("1e-10")));
  }
  // the complex pair, in the normal frame: (−2.61127 ∓ 15.911875i, −12.962441 ∓ 1.276809i)
  const NormalFrame<S> fr = inv.normalFrame();
  for (int k = 0; k < 4; ++k) {
    if (bp.isReal[k]) continue;
    const Cx<S> X = (bp.x[k] - Cx<S>(fr.origin(0))) * fr.ex(0) + (bp.y[k] - Cx<S>(fr.origin(1))) * fr.ex(1);
    const Cx<S> Y = (bp.x[k] - Cx<S>(fr.origin(0))) * fr.ey(0) + (bp.y[k] - Cx<S>(fr.origin(1))) * fr.ey(1);
    const S t = std::max<S>(tolFor<S>(1 << 20), num<S>("2e-6"));
    CHECK(abs(X.re - num<S>("-2.61127")) <= S(1e-5) + t);
    CHECK(abs(abs(X.im) - num<S>("15.911875")) <= S(1e-5) + t);
    CHECK(abs(Y.re - num<S>("-12.962441")) <= S(1e-5) + t);
    CHECK(abs(abs(Y.im) - num<S>("1.276809")) <= S(1e-5) + t);
  }
}

TEST_CASE("Grashof classification, both sides of the boundary and the change point", "[planar][fourbar][grashof]") {
  using S = double;
  const Vec2<S> o(0, 0);
  auto cls = [&](double g, double a, double b, double c) { return FourBar<S>(o, Vec2<S>(g, 0), a, b, c).classify(); };
  CHECK(cls(3, 1.2, 2.5, 2.0).type == GrashofType::CrankRocker);
  CHECK(cls(1, 2.5, 2.2, 2.8).type == GrashofType::DoubleCrank);
  CHECK(cls(2.5, 2.2, 1, 2.8).type == GrashofType::DoubleRocker);
  CHECK(cls(2.5, 2.2, 2.8, 1).type == GrashofType::RockerCrank);
  CHECK(cls(3, 2, 2.5, 2.2).type == GrashofType::TripleRocker);
  // s + l = p + q exactly: change point; δ = ±1e-9 of the sum on either side
  CHECK(cls(3, 1, 2.5, 1.5).type == GrashofType::ChangePoint);
  for (double d : {1e-9, 1e-6, 1e-3}) {
    const auto g1 = cls(3, 1, 2.5, 1.5 + d), g2 = cls(3, 1, 2.5, 1.5 - d);
    CHECK(g1.type == GrashofType::CrankRocker);
    CHECK(g1.margin > 0);
    CHECK(g2.type == GrashofType::TripleRocker);
    CHECK(g2.margin < 0);
  }
  const auto par = cls(3, 1, 3, 1);
  CHECK(par.type == GrashofType::ChangePoint);
  CHECK(par.parallelogram);
  const auto kite = cls(1, 1, 3, 3);
  CHECK(kite.type == GrashofType::ChangePoint);
  CHECK(kite.deltoid);
  CHECK_THROWS_AS(FourBar<S>(o, Vec2<S>(10, 0), 1, 2, 3), InvalidInput);  // cannot be assembled
  CHECK_THROWS_AS(FourBar<S>(o, Vec2<S>(3, 0), -1, 2, 3), InvalidInput);
  CHECK_THROWS_AS(FourBar<S>(o, o, 1, 2, 3), InvalidInput);
}

TEMPLATE_TEST_CASE("circuits: one branch through a full cycle, continuous and closed", "[planar][fourbar][circuits]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  const Vec2<S> o(S(0), S(0));
  struct Case {
    double g, a, b, c;
    int circuits;
  };
  const Case cases[] = {{3, 1.2, 2.5, 2.0, 2}, {1, 2.5, 2.2, 2.8, 2}, {2.5, 2.2, 1, 2.8, 2}, {3, 2, 2.5, 2.2, 1},
                        {3, 1, 2.5, 1.5, 1},   {3, 1, 3, 1, 2},       {3, 1, 2.5, 1.5 + 1e-2, 2}, {3, 1, 2.5, 1.5 - 1e-2, 1},
                        {3, 0.5, 1, 2.5, 1} /* change point, crank interval through 0 */};
  const int n = 720;
  for (const Case& c : cases) {
    const FourBar<S> fb(o, Vec2<S>(scalarCast<S>(c.g), S(0)), scalarCast<S>(c.a), scalarCast<S>(c.b), scalarCast<S>(c.c));
    INFO("lengths " << c.g << " " << c.a << " " << c.b << " " << c.c);
    REQUIRE(fb.circuitCount() == c.circuits);
    for (int k = 0; k < fb.circuitCount(); ++k) {
      const auto t = fb.traceCircuit(k, n);
      CHECK(loopResidual(fb, t) <= std::max<S>(tolFor<S>(1 << 10), S(1e-12)) * S(10));
      // continuity: consecutive samples are close (a jump to the other branch would be O(1))
      const S step = scalarCast<S>(4 * 3.2 * (c.a + c.b + c.c) / n) * (fb.circuitPeriod(k) / (S(2) * pi<S>()));
      CHECK(maxStep(t) <= step);
      // (at a change-point node both circuits meet: the pose belongs to both)
      for (const auto& p : t)
        if (abs(p.h) > S(1e-3)) CHECK(fb.circuitOf(p) == k);
    }
  }
}

TEST_CASE("crank-rocker keeps its assembly mode — triple-rocker flips it only at the crank limits", "[planar][fourbar][circuits]") {
  using S = double;
  const FourBar<S> cr(Vec2<S>(0, 0), Vec2<S>(3, 0), 1.2, 2.5, 2.0);
  CHECK(cr.classify().crankRotates);
  CHECK(cr.crankIntervals().empty());
  for (int k = 0; k < 2; ++k)
    for (const auto& p : cr.traceCircuit(k, 360)) CHECK(p.mode == (k == 0 ? 1 : -1));
  const FourBar<S> tr(Vec2<S>(0, 0), Vec2<S>(3, 0), 2, 2.5, 2.2);
  REQUIRE(tr.crankIntervals().size() == 1);
  const auto iv = tr.crankIntervals()[0];
  const auto t = tr.traceCircuit(0, 1000);
  int flips = 0, last = 0;
  for (std::size_t k = 0; k <= t.size(); ++k) {
    const int m = t[k % t.size()].mode;
    if (m == 0) continue;  // exactly at a turning point
    if (last != 0 && m != last) ++flips;
    last = m;
  }
  CHECK(flips == 2);
  // branch points: beyond a limit no assembly; at it the two modes coincide; the jet throws
  const double lim = iv.second;
  CHECK_FALSE(tr.solve(lim + 1e-6, 1));
  REQUIRE(tr.solve(lim - 1e-9, 1));
  CHECK((tr.solve(lim - 1e-9, 1)->c3 - tr.solve(lim - 1e-9, -1)->c3).norm() < 1e-3);
  CHECK_THROWS_AS(tr.couplerJet(lim, 1, {lim, 1, 0, 0, 0}), InvalidInput);
  CHECK_NOTHROW(tr.couplerJet(lim - 1e-3, 1, {lim, 1, 0, 0, 0}));
}

TEST_CASE("change-point and folding linkages: the smooth branch through the node", "[planar][fourbar][extremes]") {
  using S = double;
  // parallelogram: one circuit keeps the coupler parallel to the ground through both flat poses
  const FourBar<S> par(Vec2<S>(0, 0), Vec2<S>(3, 0), 1, 3, 1);
  REQUIRE(par.circuitCount() == 2);
  int parallelCircuit = -1;
  for (int k = 0; k < 2; ++k) {
    double worst = 0;
    for (const auto& p : par.traceCircuit(k, 720)) worst = std::max(worst, std::abs(std::sin(p.psi)));
    if (worst < 1e-9) parallelCircuit = k;
  }
  CHECK(parallelCircuit >= 0);
  // the antiparallelogram circuit is a different motion
  const auto anti = par.traceCircuit(1 - parallelCircuit, 720);
  double maxPsi = 0;
  for (const auto& p : anti) maxPsi = std::max(maxPsi, std::abs(std::sin(p.psi)));
  CHECK(maxPsi > 0.1);
  // general change point (figure eight: period 4π) — c3 is smooth across the node: the
  // second difference stays O(h²) everywhere (a kink would make it O(h))
  const FourBar<S> cp(Vec2<S>(0, 0), Vec2<S>(3, 0), 1, 2.5, 1.5);
  REQUIRE(cp.circuitCount() == 1);
  const int n = 4000;
  const auto t = cp.traceCircuit(0, n);
  const double h = 4 * 3.14159265358979 / n;
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    const auto& a = t[(k + n - 1) % n];
    const auto& b = t[k];
    const auto& c = t[(k + 1) % n];
    worst = std::max(worst, (a.c3 - 2 * b.c3 + c.c3).norm() / (h * h));
  }
  CHECK(worst < 50);  // bounded second derivative (a corner gives ~ 1/h ≈ 300)
}

TEMPLATE_TEST_CASE("coupler curve: the sextic vanishes on both circuits, is tricircular, and not elsewhere",
                   "[planar][fourbar][coupler-curve]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const Vec2<S> pc(num<S>("0.8"), num<S>("1.1"));
  const FourBar<S> fb = catalogueBar<S>(pc);
  const Poly2<S> cc = fb.couplerCurve();
  CHECK(cc.degree(tolFor<S>(1 << 10)) == 6);
  const S top = cc.at(6, 0);
  CHECK(abs(cc.at(4, 2) - S(3) * top) <= tolFor<S>(1 << 10) * abs(top));
  CHECK(abs(cc.at(2, 4) - S(3) * top) <= tolFor<S>(1 << 10) * abs(top));
  CHECK(abs(cc.at(0, 6) - top) <= tolFor<S>(1 << 10) * abs(top));
  CHECK(abs(cc.at(5, 1)) + abs(cc.at(3, 3)) + abs(cc.at(1, 5)) <= tolFor<S>(1 << 10) * abs(top));
  const int n = std::is_same_v<S, mpreal> ? 12 : 90;
  for (int k = 0; k < fb.circuitCount(); ++k)
    for (const auto& p : fb.traceCircuit(k, n)) {
      const Vec2<S> q = fb.couplerPointWorld(p);
      CHECK(abs(cc(q(0), q(1))) <= tolFor<S>(1 << 12) * cc.magnitude(q(0), q(1)));
    }
  const Vec2<S> off(S(5), S(5));
  CHECK(abs(cc(off(0), off(1))) > S(1e-3) * cc.magnitude(off(0), off(1)));
}

TEST_CASE("coupler invariants at every crank angle: Euler–Savary equals the curvature centre of the path", "[planar][fourbar]") {
  using S = double;
  const Vec2<S> pc(0.8, 1.1);
  const FourBar<S> fb(Vec2<S>(0, 0), Vec2<S>(3, 0), 1.2, 2.5, 2.0, pc);
  double worst = 0;
  for (int k = 0; k < 72; ++k) {
    const double th = 2 * 3.14159265358979 * k / 72;
    const MotionJet<S> jet = fb.couplerJet(th, -1, {th, 1, 0, 0, 0});
    const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
    const Vec2<S> p = jet.bodyPointDerivatives(pc)[0];
    const auto d = jet.pointDerivatives(p);
    Vec2<S> c1, c2;
    if (!curvatureCentre(p, d[1], d[2], c1) || !inv.eulerSavaryCentre(p, c2)) continue;
    worst = std::max(worst, (c1 - c2).norm() / (1 + c1.norm()));
    // r, p, c collinear
    CHECK(std::abs(cross2<S>(p - inv.pole(), p - c1)) <= 1e-9 * (1 + (p - c1).squaredNorm() + (p - inv.pole()).squaredNorm()));
  }
  CHECK(worst <= 1e-10);
}

}  // namespace SOMA_UNITY_ID
