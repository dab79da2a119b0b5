// The analysis entry points: analyseCuspidality (cuspidality.hpp) and analyseWorkspace
// (workspace_analysis.hpp) — their parts agree with each other and with independent formulas.
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/workspace_analysis.hpp"

#include "soma/algebra/errors.hpp"
#include "robots.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
SerialRobot<double> verheye() { return test::dh3r<double>(1, -kHalfPi, 0, 1.5, kHalfPi, 0.7, 1, 0, 0); }
SerialRobot<double> pumaArm() { return test::dh3r<double>(0, kHalfPi, 0, 0.4318, 0, 0, 0.0203, -kHalfPi, 0.15005); }
}  // namespace

TEST_CASE("analyseCuspidality: Verheye's arm is cuspidal — 4 cusps by both methods, 2 aspects, a certified witness",
          "[cuspidal][entry][ompl]") {
  const SerialRobot<double> robot = verheye();
  CuspidalOptions o;
  o.aspectGrid = 128;
  const CuspidalAnalysis a = analyseCuspidality(robot, o);
  CHECK_FALSE(a.sixR);
  CHECK(a.cuspidal);
  CHECK(a.cusps.cusps.size() == 4);
  CHECK(a.reversals.size() == a.cusps.cusps.size());  // the traced count agrees with the algebraic one
  CHECK(a.aspectMap.count() == 2);
  REQUIRE(a.witness.found);
  CHECK(checkPathSign(a.dj, a.witness.path, a.witness.sign).minSignedDet > 0);
  CHECK(a.verdictSeconds <= a.seconds);
  // Without the witness: the same verdict, no path planned.
  o.witness = false;
  const CuspidalAnalysis b = analyseCuspidality(robot, o);
  CHECK(b.cuspidal);
  CHECK_FALSE(b.witness.found);
  CHECK(b.witness.path.empty());
}

TEST_CASE("analyseCuspidality: the PUMA arm is not cuspidal, nor is the PUMA 560 (decomposed — searched: no witness)",
          "[cuspidal][entry]") {
  const CuspidalAnalysis a = analyseCuspidality(pumaArm());
  CHECK_FALSE(a.cuspidal);
  CHECK(a.cusps.cusps.empty());
  CHECK(a.reversals.empty());
  CHECK(a.aspectMap.count() == 4);
  CHECK_FALSE(a.witness.found);
  // The PUMA 560: the arm above and a spherical wrist.
  std::vector<DHRow<double>> rows = pumaArm().dhRows();
  rows.push_back({JointType::Revolute, 0, kHalfPi, 0.4318, 0});
  rows.push_back({JointType::Revolute, 0, -kHalfPi, 0, 0});
  rows.push_back({JointType::Revolute, 0, 0, 0.05625, 0});
  const CuspidalAnalysis d = analyseCuspidality(SerialRobot<double>::fromDH(rows));
  CHECK(d.sixR);
  CHECK(d.decomposition.kind == CuspidalDecompositionKind::SphericalWrist);
  CHECK(d.decided);
  CHECK_FALSE(d.cuspidal);
  CHECK(d.aspectMap.count() == 4);
  CuspidalOptions o;
  o.poses = 1;
  o.secondsPerPair = 0.1;
  o.forceSearch = true;
  const CuspidalAnalysis b = analyseCuspidality(SerialRobot<double>::fromDH(rows), o);
  CHECK(b.sixR);
  CHECK(b.decomposition.kind == CuspidalDecompositionKind::None);
  CHECK_FALSE(b.decided);
  CHECK_FALSE(b.cuspidal);
  CHECK(b.witness6r.posesTried == 1);
  CHECK(b.witness6r.note.find("not a proof") != std::string::npos);
  // A 4R robot is neither.
  rows.resize(4);
  CHECK_THROWS_AS(analyseCuspidality(SerialRobot<double>::fromDH(rows)), InvalidInput);
}

TEST_CASE("analyseWorkspace: the boundary is the singular images, the plan's trace is the tool point's section",
          "[cuspidal][entry][workspace][ompl]") {
  const SerialRobot<double> robot = verheye();
  CuspidalOptions co;
  co.aspectGrid = 128;
  const CuspidalAnalysis c = analyseCuspidality(robot, co);
  REQUIRE(c.witness.found);
  WorkspaceOptions o;
  o.samples = 20000;
  o.grid = 48;
  o.plan = std::make_pair(c.witness.start, c.witness.goal);
  o.margin = 0.5 * std::min(dexteritySingularValues(robot, c.witness.start)(0),
                            dexteritySingularValues(robot, c.witness.goal)(0));
  o.seconds = 3.0;
  const WorkspaceAnalysis w = analyseWorkspace(robot, o);
  CHECK(w.maps.samples == 20000);
  CHECK(w.boundary.size() == c.branches.size());
  REQUIRE(w.plan);
  REQUIRE(w.plan->found);
  CHECK(w.plan->minSigma >= o.margin);
  const auto& path = w.plan->path;
  REQUIRE(w.planTrace.size() == 8 * (path.size() - 1));
  // Each segment's first trace point is the section (ρ, z) of the path state (cusps.hpp's formula).
  const Arm3RFrame<double> f = arm3RFrame(robot);
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    CHECK((w.planTrace[8 * k] - workspaceSection(f, robot, path[k])).norm() <= Tolerance<double>::identity(64) * f.scale);
  // No plan asked, none made; a robot that is not a 3R arm has no traced boundary.
  WorkspaceOptions small;
  small.samples = 2000;
  small.grid = 16;
  CHECK_FALSE(analyseWorkspace(robot, small).plan);
  std::vector<DHRow<double>> rows = robot.dhRows();
  rows.push_back({JointType::Revolute, 0.3, 0.4, 0.2, 0});
  CHECK(analyseWorkspace(SerialRobot<double>::fromDH(rows), small).boundary.empty());
}

}  // namespace SOMA_UNITY_ID
