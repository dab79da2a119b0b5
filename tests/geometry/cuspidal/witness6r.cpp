// 6R witness search (GF §5.2.3): a known non-cuspidal robot (PUMA 560: det J factors, none found —
// which is not a proof, and the answer says so), a cuspidal one by construction (Wenger's
// cuspidal orthogonal arm + a spherical wrist: a witness is found and re-checked here — the
// decomposition's verdict, decomposition.cpp, by an independent method), and the FANUC CRX-10iA
// (not a Pieper robot, modified DH: the general-6R solver on its standard-DH rewrite) found cuspidal.
#include "soma/geometry/cuspidal/witness6r.hpp"
#include "soma/geometry/serial/example_robots.hpp"

#include "soma/algebra/errors.hpp"
#include "support/scalars.hpp"

#include <cmath>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

TEST_CASE("6R witness: PUMA 560 (not cuspidal) — none found, not a proof", "[cuspidal][ompl][6r]") {
  Witness6ROptions o;
  o.poses = 1;
  o.secondsPerPair = 0.1;
  int reports = 0;
  o.progress = [&](const Witness6RProgress& p) {
    ++reports;
    CHECK(p.posesTried == 1);
  };
  const Witness6R w = findWitness6R(puma560Robot<double>(), o);
  CHECK_FALSE(w.found);
  CHECK(w.ikMethod == "pieper");
  CHECK(w.posesTried == 1);
  CHECK(w.posturesSeen == 8);
  CHECK(w.straightTried == 12);  // 8 postures, 4 of each sign of det J: 2 × C(4, 2)
  CHECK(w.pairsTried == 12);     // no straight path joins two of them: all planned
  CHECK(reports >= 1);
  CHECK(w.note.find("not a proof") != std::string::npos);
}

TEST_CASE("6R witness: orthogonal cuspidal arm + spherical wrist — found and re-checked", "[cuspidal][ompl][6r]") {
  const SerialRobot<double> robot = orthogonalWristRobot<double>();
  Witness6ROptions o;
  o.poses = 8;
  const Witness6R w = findWitness6R(robot, o);
  REQUIRE(w.found);
  // Both ends reach the same pose and are different postures.
  CHECK(poseResidual(robot.fk(w.start), w.pose, robot.lengthScale()) <= Tolerance<double>::sqrtEpsilon());
  CHECK(poseResidual(robot.fk(w.goal), w.pose, robot.lengthScale()) <= Tolerance<double>::sqrtEpsilon());
  double apart = 0;
  for (int i = 0; i < 6; ++i) apart = std::max(apart, std::abs(std::remainder(w.start(i) - w.goal(i), 2 * 3.14159265358979)));
  CHECK(apart > 0.1);
  // det J keeps its sign along the path (independent re-check at the states and midpoints).
  REQUIRE(w.path.size() >= 2);
  for (std::size_t k = 0; k < w.path.size(); ++k) CHECK(w.sign * jacobianDet6(robot, w.path[k]) > 0);
  CHECK(w.minSignedDet > 0);
  CHECK(w.sign * jacobianDet6(robot, w.start) > 0);
  CHECK(w.sign * jacobianDet6(robot, w.goal) > 0);
}

TEST_CASE("6R witness: bad input", "[cuspidal][6r]") {
  DHRow<double> r;
  r.a = 1;
  CHECK_THROWS_WITH(findWitness6R(SerialRobot<double>::fromDH({r, r, r, r})), Catch::Contains("has 4 joints"));
  Witness6ROptions o;
  o.poses = 0;
  CHECK_THROWS_WITH(findWitness6R(puma560Robot<double>(), o), Catch::Contains("at least 1"));
  o.poses = 1;
  o.budget = -1;
  CHECK_THROWS_WITH(findWitness6R(puma560Robot<double>(), o), Catch::Contains("budget"));
}

TEST_CASE("6R witness: the budget stops the search", "[cuspidal][ompl][6r]") {
  Witness6ROptions o;
  o.poses = 10000;
  o.secondsPerPair = 0.05;
  o.budget = 0.3;
  const Witness6R w = findWitness6R(puma560Robot<double>(), o);
  CHECK_FALSE(w.found);
  CHECK(w.budgetExhausted);
  CHECK(w.posesTried < 10000);
  CHECK(w.note.find("budget") != std::string::npos);
}

TEST_CASE("6R witness: the FANUC CRX-10iA (modified DH, non-Pieper) is cuspidal", "[cuspidal][ompl][6r]") {
  const SerialRobot<double> robot = crx10iaRobot<double>();  // Abbes & Poisson 2024 (example_robots.hpp)
  Witness6ROptions o;
  o.poses = 40;
  o.secondsPerPair = 0.3;
  o.budget = 30;
  const Witness6R w = findWitness6R(robot, o);
  CHECK(w.ikMethod == "general6r");
  REQUIRE(w.found);
  CHECK(poseResidual(robot.fk(w.start), w.pose, robot.lengthScale()) <= Tolerance<double>::sqrtEpsilon());
  CHECK(poseResidual(robot.fk(w.goal), w.pose, robot.lengthScale()) <= Tolerance<double>::sqrtEpsilon());
  for (const auto& q : w.path) CHECK(w.sign * jacobianDet6(robot, q) > 0);
}

}  // namespace SOMA_UNITY_ID
