// Near-degenerate 3R arms (GF §5.2.3): axes 1, 2 almost meeting (a1 → 0). The cusp polynomial's
// roots cluster (cusps.hpp); findCuspsAdaptive detects it from Tolerance<double> and re-solves in
// __float128 / mpfr. Checked on both sides of the threshold against the exact a1 → 0+ limit.
#include "soma/geometry/cuspidal/cusps.hpp"

#include "support/scalars.hpp"

#include <cmath>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
SerialRobot<double> orthogonalArm(double d2, double d3, double d4, double r2, double r3) {
  auto row = [](double a, double al, double d) {
    DHRow<double> r;
    r.a = a;
    r.alpha = al;
    r.d = d;
    return r;
  };
  const double h = 1.57079632679489661923;
  return SerialRobot<double>::fromDH({row(d2, -h, 0), row(d3, h, r2), row(d4, 0, r3)}, DHConvention::Standard,
                                     SE3<double>(), SE3<double>(), "orthogonal");
}
}  // namespace

/// Max distance from each cusp to its nearest limit point (counts must agree first).
double distanceToLimit(const std::vector<CuspPoint<double>>& cusps, const std::vector<Vec2<double>>& limit) {
  double worst = 0;
  for (const auto& c : cusps) {
    double best = 1e300;
    for (const auto& v : limit) best = std::min(best, std::hypot(c.rho - v(0), c.z - v(1)));
    worst = std::max(worst, best);
  }
  return worst;
}

TEST_CASE("near-degenerate: the a1 → 0+ limit of the cusp points", "[cuspidal]") {
  // The limit from the local form of G (cusps.hpp): four corners of the decoupled section.
  const auto limit = cuspLimitA1Zero(orthogonalArm(1e-3, 2, 1.5, 1, 0));
  REQUIRE(limit.size() == 4);
  // The same limit from any member of the DH family (W, V do not depend on a1).
  const auto limit2 = cuspLimitA1Zero(orthogonalArm(0.5, 2, 1.5, 1, 0));
  REQUIRE(limit2.size() == 4);
  for (int i = 0; i < 4; ++i) CHECK((limit[i] - limit2[i]).norm() <= Tolerance<double>::identity(64) * 4);
  // z ↦ −z symmetry of the orthogonal arm.
  CHECK(std::abs(limit[0](1) + limit[3](1)) <= Tolerance<double>::identity(64) * 4);
  // Not orthogonal (c1 ≠ 0): no closed form here.
  DHRow<double> r;
  r.a = 1;
  r.alpha = 1.0;
  CHECK(cuspLimitA1Zero(SerialRobot<double>::fromDH({r, r, r})).empty());
}

TEST_CASE("near-degenerate: a1 = 1e-2 (double suffices) and 1e-8 (escalated) against the limit", "[cuspidal]") {
  const auto limit = cuspLimitA1Zero(orthogonalArm(1e-3, 2, 1.5, 1, 0));
  REQUIRE(limit.size() == 4);
  // a1 = 1e-2: min(a, b) = (2a1/L)² ≈ 2.5e-5 > √eps: solved in double.
  {
    const auto robot = orthogonalArm(1e-2, 2, 1.5, 1, 0);
    const CuspAnalysis<double> c = findCuspsAdaptive(robot);
    const double L = c.frame.scale;
    CHECK_FALSE(cuspsIllConditioned(c.frame));
    CHECK(c.scalar == "double");
    CHECK(c.conditioning.empty());
    REQUIRE(c.cusps.size() == limit.size());
    // The cusps approach the limit as w ~ b^{1/3}, i.e. by ~L (a1/L)^{2/3}.
    CHECK(distanceToLimit(c.cusps, limit) <= L * std::pow(1e-2 / L, 2.0 / 3.0));
    CHECK(distanceToLimit(c.cusps, limit) >= L * std::pow(1e-2 / L, 2.0 / 3.0) / 16);  // not yet at the limit
  }
  // a1 = 1e-8: b ≈ 2.5e-17 ≤ √eps of double; double alone finds 2 of the 4 (the finding); float128
  // (√eps ≈ 1.4e-17 < b) resolves them.
  {
    const auto robot = orthogonalArm(1e-8, 2, 1.5, 1, 0);
    const CuspAnalysis<double> plain = findCusps(robot);
    CHECK(cuspsIllConditioned(plain.frame));
    CHECK_FALSE(cuspsIllConditioned(arm3RFrame(robot.cast<__float128>())));
    const CuspAnalysis<double> c = findCuspsAdaptive(robot);
    const double L = c.frame.scale;
    CHECK(c.scalar == "float128");
    CHECK(c.conditioning.find("re-solved in float128") != std::string::npos);
    REQUIRE(c.cusps.size() == limit.size());
    CHECK(distanceToLimit(c.cusps, limit) <= L * std::pow(1e-8 / L, 2.0 / 3.0));
    // Each is a triple root of the double robot's IK equation and reached by its posture.
    for (const auto& k : c.cusps) {
      CHECK(k.residual <= Tolerance<double>::sqrtEpsilon());
      const Vec2<double> ws = workspaceSection(c.frame, robot, k.posture);
      CHECK((ws - Vec2<double>(k.rho, k.z)).norm() / L <= Tolerance<double>::sqrtEpsilon());
    }
    WARN("a1 = 1e-8: double alone " << plain.cusps.size() << " cusps, " << c.scalar << " " << c.cusps.size());
  }
}

TEST_CASE("near-degenerate: a1 = 1e-10 goes on to mpfr, s1 → 0 is detected too", "[cuspidal]") {
  const auto limit = cuspLimitA1Zero(orthogonalArm(1e-3, 2, 1.5, 1, 0));
  const auto robot = orthogonalArm(1e-10, 2, 1.5, 1, 0);
  CHECK(cuspsIllConditioned(arm3RFrame(robot.cast<__float128>())));
  const int bits = mpfrBits();
  const CuspAnalysis<double> c = findCuspsAdaptive(robot);
  CHECK(mpfrBits() == bits);  // restored
  CHECK(c.scalar == "mpfr");
  CHECK(c.conditioning.find("mpfr at") != std::string::npos);
  REQUIRE(c.cusps.size() == limit.size());
  CHECK(distanceToLimit(c.cusps, limit) <= c.frame.scale * std::pow(1e-10 / c.frame.scale, 2.0 / 3.0));
  // Axes 1, 2 nearly parallel (twist 1e-5 rad, s1² = 1e-10 ≤ √eps): ill-conditioned in double.
  DHRow<double> r1, r2, r3;
  r1.a = 1;
  r1.alpha = 1e-5;
  r2.a = 2;
  r2.alpha = 1.57;
  r2.d = 1;
  r3.a = 1.5;
  const auto par = SerialRobot<double>::fromDH({r1, r2, r3});
  CHECK(cuspsIllConditioned(arm3RFrame(par)));
  r1.alpha = 0.1;  // s1² = 0.01: fine
  CHECK_FALSE(cuspsIllConditioned(arm3RFrame(SerialRobot<double>::fromDH({r1, r2, r3}))));
}

}  // namespace SOMA_UNITY_ID
