// Workspace probing with OMPL (issue 9): sampled reachability and dexterity, the outer boundary
// from the singular curves, and plans that keep away from singularities.
#include "soma/geometry/cuspidal/workspace.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"
#include "soma/geometry/cuspidal/witness.hpp"

#include "soma/algebra/errors.hpp"
#include "robots.hpp"
#include "support/scalars.hpp"

#include <cmath>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
SerialRobot<double> verheye() { return test::dh3r<double>(1, -kHalfPi, 0, 1.5, kHalfPi, 0.7, 1, 0, 0); }
}  // namespace

TEST_CASE("workspace: samples, dexterity, and the outer boundary is a singular image", "[cuspidal][workspace]") {
  const SerialRobot<double> robot = verheye();
  const WorkspaceMaps m = sampleWorkspace(robot, 40000, 64);
  CHECK(m.samples == 40000);
  int total = 0;
  for (int h : m.hits) total += h;
  CHECK(total == 40000);
  CHECK(m.reachedFraction > 0.2);
  CHECK(m.reachedFraction < 1.0);
  for (double d : m.dexterity) CHECK(d <= 1.0 + Tolerance<double>::sqrtEpsilon());
  CHECK(m.meanDexterity > 0);
  // The farthest reach (max distance of the tool point from the section's origin) is attained on
  // det J = 0: the sampled maximum approaches the maximum over the traced singular images from below.
  const DetJSeries dj = detJSeries(robot);
  double singularMax = 0;
  for (const auto& b : traceSingularCurves(robot, dj))
    for (const auto& p : b.section) singularMax = std::max(singularMax, p.norm());
  double sampledMax = 0;
  for (const auto& p : m.points) sampledMax = std::max(sampledMax, p.norm());
  CHECK(sampledMax <= singularMax * (1 + Tolerance<double>::sqrtEpsilon()));
  CHECK(sampledMax >= 0.97 * singularMax);
  // Dexterity at a singular posture is 0 (to round-off), at a generic one positive.
  const auto r = dj.rootsInTheta3(0.4);
  REQUIRE_FALSE(r.empty());
  JointVector<double> q(3);
  q << 0.2, 0.4, r[0];
  const Eigen::Vector2d sv = dexteritySingularValues(robot, q);
  CHECK(sv(0) / sv(1) <= Tolerance<double>::sqrtEpsilon());
  q << 0.2, 0.4, r[0] + 0.3;
  CHECK(dexteritySingularValues(robot, q)(0) > 0.01);
}

TEST_CASE("workspace: joint limits shrink the sampled workspace", "[cuspidal][workspace]") {
  const SerialRobot<double> robot = verheye();
  const SerialRobot<double> limited = robot.withLimits({-3.0, -0.5, -0.5}, {3.0, 0.5, 0.5});
  const WorkspaceMaps a = sampleWorkspace(robot, 20000, 48), b = sampleWorkspace(limited, 20000, 48);
  int ca = 0, cb = 0;
  for (int h : a.hits) ca += h > 0;
  for (int h : b.hits) cb += h > 0;
  CHECK(cb < ca);
  CHECK_THROWS_WITH(sampleWorkspace(robot, 0), Catch::Contains("samples"));
  CHECK_THROWS_WITH(sampleWorkspace(robot, 10, 4), Catch::Contains("grid size"));
}

TEST_CASE("workspace: a plan keeping σmin ≥ margin between two postures of one point", "[cuspidal][workspace][ompl]") {
  const SerialRobot<double> robot = verheye();
  const CuspAnalysis<double> c = findCusps(robot);
  const DetJSeries dj = detJSeries(robot);
  const WitnessPath w = findWitness(robot, c, dj, aspects(dj, 128), 2.0);
  REQUIRE(w.found);
  const double margin = 0.5 * std::min(dexteritySingularValues(robot, w.start)(0), dexteritySingularValues(robot, w.goal)(0));
  const SafePath p = planAwayFromSingularities(robot, w.start, w.goal, margin, 3.0);
  REQUIRE(p.found);
  CHECK(p.minSigma >= margin);
  CHECK(p.startSign == p.goalSign);
  CHECK((p.path.front() - w.start).cwiseAbs().maxCoeff() <= 1e-9);
  // The same path certified by the det J sign check of the witness module.
  std::vector<Eigen::Vector3d> pts;
  for (const auto& q : p.path) pts.emplace_back(q(0), q(1), q(2));
  CHECK(checkPathSign(dj, pts, p.startSign).minSignedDet > 0);
}

TEST_CASE("workspace: postures on opposite sides of det J = 0, bad input", "[cuspidal][workspace]") {
  const SerialRobot<double> robot = verheye();
  const DetJSeries dj = detJSeries(robot);
  const auto r = dj.rootsInTheta3(0.4);
  REQUIRE(r.size() >= 2);
  JointVector<double> a(3), b(3);
  a << 0, 0.4, r[0] - 0.2;
  b << 0, 0.4, r[0] + 0.2;
  REQUIRE(dj.value(0.4, r[0] - 0.2) * dj.value(0.4, r[0] + 0.2) < 0);
  const SafePath p = planAwayFromSingularities(robot, a, b, 1e-3, 0.5);
  CHECK_FALSE(p.found);
  CHECK(p.note.find("opposite signs") != std::string::npos);
  JointVector<double> two(2);
  two << 0, 0;
  CHECK_THROWS_WITH(planAwayFromSingularities(robot, two, b, 1e-3), Catch::Contains("start posture has 2"));
  JointVector<double> s(3);
  s << 0, 0.4, r[0];  // singular
  CHECK_THROWS_WITH(planAwayFromSingularities(robot, s, b, 1e-3), Catch::Contains("closer to a singularity"));
  const SerialRobot<double> limited = robot.withLimits({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
  JointVector<double> out(3);
  out << 2, 0, 0;
  CHECK_THROWS_WITH(planAwayFromSingularities(limited, out, out, 0), Catch::Contains("outside the joint limits"));
}

}  // namespace SOMA_UNITY_ID
