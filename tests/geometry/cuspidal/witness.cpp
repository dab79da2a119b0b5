// Witness paths (GF §5.2.3, Fig. 5.2): OMPL joins two postures of one point inside one aspect;
// the path is checked densely and certified by a Lipschitz bound on det J.
#include "soma/geometry/cuspidal/witness.hpp"

#include "robots.hpp"
#include "support/scalars.hpp"

#include <cmath>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
double wrapped(const JointVector<double>& a, const JointVector<double>& b) {
  double d = 0;
  for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(std::remainder(a(i) - b(i), 2 * 3.14159265358979323846)));
  return d;
}
}  // namespace

TEST_CASE("witness: a cuspidal orthogonal arm changes posture without a singularity", "[cuspidal][ompl]") {
  const auto robot = test::dh3r<double>(1, -kHalfPi, 0, 1.5, kHalfPi, 0.7, 1, 0, 0);  // Verheye's arm
  const CuspAnalysis<double> c = findCusps(robot);
  REQUIRE(c.cusps.size() == 4);
  const DetJSeries dj = detJSeries(robot);
  const AspectMap am = aspects(dj, 128);
  const WitnessPath w = findWitness(robot, c, dj, am, 2.0);
  REQUIRE(w.found);
  // Both ends are IK postures of the same point, and different postures.
  const double L = c.frame.scale;
  CHECK((robot.fk(w.start).translation() - w.target).norm() / L <= Tolerance<double>::sqrtEpsilon());
  CHECK((robot.fk(w.goal).translation() - w.target).norm() / L <= Tolerance<double>::sqrtEpsilon());
  CHECK(wrapped(w.start, w.goal) > 0.1);
  // The path runs from one to the other with one sign of det J, certified between checked points.
  REQUIRE(w.path.size() >= 2);
  JointVector<double> first = w.path.front(), last = w.path.back();
  CHECK(wrapped(first, w.start) <= 1e-9);
  CHECK(wrapped(last, w.goal) <= 1e-9);
  const PathCheck pc = checkPathSign(dj, w.path, w.sign, 5e-4);
  CHECK(pc.minSignedDet > 0);
  CHECK(pc.certified);
  CHECK(w.aspectStart == w.aspectGoal);
  // The opposite sign fails the check (the test can fail).
  CHECK_FALSE(checkPathSign(dj, w.path, -w.sign).minSignedDet > 0);
}

TEST_CASE("witness: none for an arm without cusps", "[cuspidal][ompl]") {
  const auto puma = test::dh3r<double>(0, kHalfPi, 0, 0.4318, 0, 0, 0.0203, -kHalfPi, 0.15005);
  const CuspAnalysis<double> c = findCusps(puma);
  const DetJSeries dj = detJSeries(puma);
  const WitnessPath w = findWitness(puma, c, dj, aspects(dj, 64), 0.5);
  CHECK_FALSE(w.found);
  CHECK(w.note.find("no cusp") != std::string::npos);
}

TEST_CASE("witness: a straight joint path across det J = 0 is rejected by the check", "[cuspidal]") {
  const auto robot = test::dh3r<double>(1, -kHalfPi, 0, 1.5, kHalfPi, 0.7, 1, 0, 0);
  const DetJSeries dj = detJSeries(robot);
  // θ3 = 0 and θ3 = π on one θ2: the arm stretched/folded in between crosses a singular curve.
  const auto r = dj.rootsInTheta3(0.3);
  REQUIRE(r.size() >= 2);
  std::vector<Eigen::Vector3d> path = {Eigen::Vector3d(0, 0.3, r[0] - 0.05), Eigen::Vector3d(0, 0.3, r[0] + 0.05)};
  const int s = dj.value(0.3, r[0] - 0.05) > 0 ? 1 : -1;
  const PathCheck pc = checkPathSign(dj, path, s);
  CHECK(pc.minSignedDet < 0);
  CHECK_FALSE(pc.certified);
}

}  // namespace SOMA_UNITY_ID
