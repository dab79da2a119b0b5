// Cusp points of 3R arms (GF §5.2.3): the algebraic triple-root computation, checked by the
// triple-root identities in five scalars, by a second method (tracing det J = 0 and counting where
// its image turns back) on literature arms and on random arms, and on degenerate arms.
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"

#include "soma/algebra/errors.hpp"
#include "robots.hpp"
#include "support/scalars.hpp"

#include <cmath>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
constexpr double kHalfPi = 1.57079632679489661923;

/// Orthogonal arm in Wenger's notation (d2, d3, d4, r2, r3) = standard DH (d2, −90°, 0),
/// (d3, 90°, r2), (d4, 0, r3).
template <class S> SerialRobot<S> orthogonal(double d2, double d3, double d4, double r2, double r3) {
  auto row = [](double a, S al, double d) {
    DHRow<S> r;
    r.a = scalarCast<S>(a);
    r.alpha = al;
    r.d = scalarCast<S>(d);
    return r;
  };
  // α = ∓π/2 exactly in S, so that the z ↦ −z symmetry holds to S's precision.
  return SerialRobot<S>::fromDH({row(d2, -pi<S>() / S(2), 0), row(d3, pi<S>() / S(2), r2), row(d4, S(0), r3)},
                                DHConvention::Standard, SE3<S>(), SE3<S>(), "orthogonal");
}
}  // namespace

TEMPLATE_TEST_CASE("cusps: orthogonal arm (1, 2, 1.5, 1, 0) has four cusps, each a triple root", "[cuspidal]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const SerialRobot<S> robot = orthogonal<S>(1, 2, 1.5, 1, 0);
  const CuspAnalysis<S> c = findCusps(robot);
  REQUIRE_FALSE(c.frame.decoupled);
  REQUIRE(c.cusps.size() == 4);
  const S L = c.frame.scale;
  for (const auto& k : c.cusps) {
    const Vec3<S> f = ikFunction(c.frame, k.rho, k.z, S(k.posture(2) + robot.joints()[2].offset));
    // f, f′, f″ vanish to round-off of the degree-4 IK function (values of size L⁴).
    CHECK(f.cwiseAbs().maxCoeff() / (L * L * L * L) <= Tolerance<S>::sqrtEpsilon());
    CHECK(k.residual <= Tolerance<S>::identity(256));
    const Vec2<S> ws = workspaceSection(c.frame, robot, k.posture);
    CHECK(abs(ws(0) - k.rho) / L <= Tolerance<S>::identity(256));
    CHECK(abs(ws(1) - k.z) / L <= Tolerance<S>::identity(256));
  }
  // c1 = cos(−90°) ≈ 0: the section is symmetric under z ↦ −z (cusps sorted by z).
  CHECK(abs(c.cusps[0].z + c.cusps[3].z) / L <= Tolerance<S>::sqrtEpsilon());
  CHECK(abs(c.cusps[0].rho - c.cusps[3].rho) / L <= Tolerance<S>::sqrtEpsilon());
}

TEST_CASE("cusps: the second method (traced image reversals) agrees on literature arms", "[cuspidal]") {
  struct Case {
    const char* name;
    SerialRobot<double> robot;
    std::size_t cusps;
  };
  const Case cases[] = {
      // Verheye, 'Cuspidal robots: a true double-edged sword' (2021): four cusps on the inner boundary.
      {"Verheye a=(1, 1.5, 1), d2 = 0.7", test::dh3r<double>(1, -kHalfPi, 0, 1.5, kHalfPi, 0.7, 1, 0, 0), 4},
      {"orthogonal (1, 2, 1.5, 1, 0)", orthogonal<double>(1, 2, 1.5, 1, 0), 4},
  };
  for (const auto& cs : cases) {
    INFO(cs.name);
    const CuspAnalysis<double> c = findCusps(cs.robot);
    const DetJSeries dj = detJSeries(cs.robot);
    const auto rev = imageReversals(traceSingularCurves(cs.robot, dj));
    CHECK(c.cusps.size() == cs.cusps);
    REQUIRE(rev.size() == c.cusps.size());
    for (const auto& k : c.cusps) {
      double best = 1e300;
      for (const auto& v : rev) best = std::min(best, std::hypot(v(0) - k.rho, v(1) - k.z));
      CHECK(best / c.frame.scale < 0.02);  // within a few continuation steps
    }
  }
}

TEST_CASE("cusps: tracing crosses a line of det J ≡ 0 (orthogonal arms with r3 = 0, a3 > a2) instead of following it",
          "[cuspidal]") {
  // With r3 = 0 and a3 > a2, det J vanishes along two lines θ3 = ±c; the traced branches cross
  // them. A step past a crossing was corrected onto the line, and the branch ran along it for its
  // whole step budget (31,416 steps, ~5,300 false reversals): at (1, 1.2, 1.85) and (1, 1.6, 1.65)
  // with a corrector along ∇det J, at (1, 0.4, 0.45) with one across the tangent; (1, 1.2, 1.65)
  // was traced right by both. The branches are now traced on det J divided by the lines' factor.
  struct Case {
    double d3, d4;
  };
  for (const Case cs : {Case{1.2, 1.85}, Case{1.6, 1.65}, Case{0.4, 0.45}, Case{1.2, 1.65}}) {
    INFO("(1, " << cs.d3 << ", " << cs.d4 << ", 1, 0)");
    const auto robot = orthogonal<double>(1, cs.d3, cs.d4, 1, 0);
    const CuspAnalysis<double> c = findCusps(robot);
    const DetJSeries dj = detJSeries(robot);
    const auto branches = traceSingularCurves(robot, dj);
    int lines = 0;
    for (const auto& b : branches) {
      CHECK(b.closed);
      // Every branch closes within one turn of the torus: at most 2π of θ2 and of θ3 (plus a step).
      double t2 = 0, t3 = 0;
      for (std::size_t i = 1; i < b.joints.size(); ++i) {
        t2 += std::abs(b.joints[i](0) - b.joints[i - 1](0));
        t3 += std::abs(b.joints[i](1) - b.joints[i - 1](1));
      }
      CHECK(std::min(t2, t3) <= 2 * M_PI + 0.01);
      lines += dj.vanishesAlongTheta2(b.joints.front()(1));
    }
    CHECK(lines == 2);  // the two lines θ3 = ±c are traced as branches of their own
    CHECK(imageReversals(branches).size() == c.cusps.size());
  }
}

TEST_CASE("cusps: random 3R arms, algebraic count = traced count", "[cuspidal]") {
  auto& g = test::rng(905);
  int cuspidal = 0, plain = 0;
  for (int k = 0; k < 40; ++k) {
    const double a1 = test::uniform<double>(g, 0.2, 2), al1 = test::uniform<double>(g, 0.3, 2.8);
    const double a2 = test::uniform<double>(g, 0.2, 2), al2 = test::uniform<double>(g, 0.3, 2.8);
    const double d2 = test::uniform<double>(g, -1, 1), a3 = test::uniform<double>(g, 0.2, 2);
    const double d3 = test::uniform<double>(g, -1, 1);
    const auto robot = test::dh3r<double>(a1, al1, 0, a2, al2, d2, a3, 0, d3);
    const CuspAnalysis<double> c = findCusps(robot);
    const DetJSeries dj = detJSeries(robot);
    const auto branches = traceSingularCurves(robot, dj);
    const auto rev = imageReversals(branches);
    INFO("arm " << k << ": a1 " << a1 << " al1 " << al1 << " a2 " << a2 << " al2 " << al2 << " d2 " << d2 << " a3 "
                << a3 << " d3 " << d3);
    bool allClosed = true;
    for (const auto& b : branches) allClosed = allClosed && b.closed;
    CHECK(allClosed);
    CHECK(rev.size() == c.cusps.size());
    // The posture is rebuilt from (ρ, ψ, z) through the 2-D Newton solution: consistent to its
    // conditioning (the triple-root identities are the accuracy check, in the first test case).
    for (const auto& q : c.cusps) CHECK(q.residual <= Tolerance<double>::sqrtEpsilon());
    (c.cusps.empty() ? plain : cuspidal) += 1;
  }
  // Both verdicts occur among the draws (the test exercises both sides).
  CHECK(cuspidal > 0);
  CHECK(plain > 0);
}

TEST_CASE("cusps: decoupled arms have none (PUMA arm — axes 1, 2 meeting or parallel)", "[cuspidal]") {
  // PUMA 560 joints 1–3, tool point at the wrist centre: axes 1, 2 meet.
  const auto puma = test::dh3r<double>(0, kHalfPi, 0, 0.4318, 0, 0, 0.0203, -kHalfPi, 0.15005);
  const CuspAnalysis<double> c = findCusps(puma);
  CHECK(c.frame.decoupled);
  CHECK(c.frame.reason == "axes 1 and 2 meet");
  CHECK(c.cusps.empty());
  // Axes 1, 2 parallel (a planar first pair).
  const auto par = test::dh3r<double>(1, 0, 0, 1, kHalfPi, 0.5, 1, 0, 0);
  CHECK(findCusps(par).frame.reason == "axes 1 and 2 are parallel");
  // Axes 2, 3 parallel with a1 ≠ 0: E = 0.
  const auto e0 = test::dh3r<double>(1, -kHalfPi, 0, 1, 0, 0.5, 1, 0, 0);
  CHECK(findCusps(e0).frame.reason.find("axes 2 and 3") != std::string::npos);
  // The tracing finds no reversal either.
  const DetJSeries dj = detJSeries(puma);
  CHECK(imageReversals(traceSingularCurves(puma, dj)).empty());
}

TEST_CASE("cusps: near-degenerate arms, both sides of the decoupling threshold", "[cuspidal]") {
  // a1 = 0 exactly: decoupled. a1 = 1e-8 L and 1e-2 L: generic, and the algebra still gives cusps
  // that are triple roots and that the posture reaches.
  CHECK(findCusps(orthogonal<double>(0, 2, 1.5, 1, 0)).frame.decoupled);
  for (double a1 : {1e-2, 1e-3, 1e-4, 1e-6, 1e-8}) {
    INFO("a1 = " << a1);
    const auto robot = orthogonal<double>(a1, 2, 1.5, 1, 0);
    // findCuspsAdaptive: double, or float128 / mpfr when the cusp polynomial's roots cluster
    // (near_degenerate.cpp); the count stays that of the a1 → 0+ limit, 4.
    const CuspAnalysis<double> c = findCuspsAdaptive(robot);
    CHECK_FALSE(c.frame.decoupled);
    CHECK(c.cusps.size() == 4);
    for (const auto& k : c.cusps) CHECK(k.residual <= Tolerance<double>::sqrtEpsilon());
    const DetJSeries dj = detJSeries(robot);
    const auto rev = imageReversals(traceSingularCurves(robot, dj));
    for (const auto& k : c.cusps) {
      const Vec3<double> f = ikFunction(c.frame, k.rho, k.z, k.posture(2));
      CHECK(std::abs(f(0)) / std::pow(c.frame.scale, 4) <= Tolerance<double>::sqrtEpsilon());
    }
    WARN("a1 = " << a1 << ": " << c.cusps.size() << " cusps (algebraic), " << rev.size() << " traced reversals");
    if (a1 >= 1e-2) CHECK(rev.size() == c.cusps.size());  // the tracer resolves ~0.004 rad
  }
  // A small last link: the tool point 1e-2 and 1e-8 off axis 3 (E → 0).
  for (double d4 : {1e-2, 1e-8}) {
    INFO("d4 = " << d4);
    const auto robot = orthogonal<double>(1, 2, d4, 1, 0);
    const CuspAnalysis<double> c = findCusps(robot);
    for (const auto& k : c.cusps) CHECK(k.residual <= Tolerance<double>::sqrtEpsilon());
    const DetJSeries dj = detJSeries(robot);
    const auto rev = imageReversals(traceSingularCurves(robot, dj));
    WARN("d4 = " << d4 << ": " << c.cusps.size() << " cusps (algebraic), " << rev.size() << " traced reversals");
    if (d4 >= 1e-2) CHECK(rev.size() == c.cusps.size());
  }
}

TEST_CASE("cusps: bad input names the defect", "[cuspidal]") {
  DHRow<double> r;
  r.a = 1;
  const auto two = SerialRobot<double>::fromDH({r, r});
  CHECK_THROWS_WITH(findCusps(two), Catch::Contains("has 2 joints"));
  DHRow<double> p = r;
  p.type = JointType::Prismatic;
  const auto rpr = SerialRobot<double>::fromDH({r, p, r});
  CHECK_THROWS_AS(findCusps(rpr), InvalidInput);
  CHECK_THROWS_WITH(findCusps(rpr), Catch::Contains("joint 2") && Catch::Contains("prismatic"));
}

TEST_CASE("singular set: the Fourier series of det J is exact", "[cuspidal]") {
  auto& g = test::rng(906);
  for (int k = 0; k < 10; ++k) {
    const auto robot = test::dh3r<double>(test::uniform<double>(g, 0.1, 2), test::uniform<double>(g, -3, 3), 0.3,
                                          test::uniform<double>(g, 0.1, 2), test::uniform<double>(g, -3, 3),
                                          test::uniform<double>(g, -1, 1), test::uniform<double>(g, 0.1, 2),
                                          test::uniform<double>(g, -3, 3), test::uniform<double>(g, -1, 1));
    const DetJSeries dj = detJSeries(robot);
    for (int i = 0; i < 20; ++i) {
      JointVector<double> q(3);
      q << test::uniform<double>(g, -3, 3), test::uniform<double>(g, -3, 3), test::uniform<double>(g, -3, 3);
      CHECK(std::abs(dj.value(q(1), q(2)) - toolPointJacobianDet(robot, q)) <= Tolerance<double>::identity(256) * dj.scale);
    }
    // Roots along a line are roots.
    for (double t3 : {-2.0, 0.5, 3.0})
      for (double t2 : dj.rootsInTheta2(t3))
        CHECK(std::abs(dj.value(t2, t3)) <= Tolerance<double>::sqrtEpsilon() * dj.scale);
  }
}

TEST_CASE("aspects: PUMA arm has 4, the cuspidal orthogonal arm 2", "[cuspidal]") {
  const auto puma = test::dh3r<double>(0, kHalfPi, 0, 0.4318, 0, 0, 0.0203, -kHalfPi, 0.15005);
  const AspectMap pm = aspects(detJSeries(puma), 128);
  CHECK(pm.count() == 4);
  const AspectMap om = aspects(detJSeries(orthogonal<double>(1, 2, 1.5, 1, 0)), 128);
  CHECK(om.count() == 2);
  int pos = 0;
  for (int s : om.sign) pos += s > 0;
  CHECK(pos == 1);
}

}  // namespace SOMA_UNITY_ID
