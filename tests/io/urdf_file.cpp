// URDF import of serial chains (io/urdf_file.hpp): the PUMA 560 written as a URDF from its
// DH table has the forward kinematics, the Jacobian and the limits of the DH robot; fixed joints
// fold in, a tip picks one chain of a tree, and every defect is an InvalidInput naming it.
#include "soma/io/urdf_file.hpp"

#include "support/repo_file.hpp"
#include "support/scalars.hpp"

#include <filesystem>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;

namespace {
using soma::test::repoFile;
}  // namespace

TEMPLATE_TEST_CASE("URDF PUMA 560 = DH PUMA 560: FK, Jacobian, limits at random joints", "[urdf]", double,
                   long double) {
  using S = TestType;
  using std::abs;
  using std::max;
  const RobotFile<S> urdf = readAnyRobot<S>(repoFile("studies/robots/puma560.urdf"));
  const RobotFile<S> dh = readAnyRobot<S>(repoFile("studies/robots/puma560.json"));
  REQUIRE(urdf.robot.dof() == 6);
  CHECK(urdf.robot.convention() == DHConvention::POE);
  CHECK(urdf.robot.name() == "PUMA 560");
  CHECK_FALSE(urdf.degrees);
  // urdfdom reads the numbers in double (and turns rpy into a quaternion in double): the URDF
  // robot is exact to double's rounding, so the comparison is at double's identity tolerance
  // also in long double. Lengths are below 1 m, so absolute = relative here.
  const S tol = scalarCast<S>(Tolerance<double>::identity());
  for (int i = 0; i < 6; ++i) {
    CHECK(abs(urdf.robot.joints()[i].lower - dh.robot.joints()[i].lower) <= tol);
    CHECK(abs(urdf.robot.joints()[i].upper - dh.robot.joints()[i].upper) <= tol);
  }
  auto& g = test::rng(7);
  S worst = S(0);
  for (int k = 0; k < 200; ++k) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = test::uniform<S>(g, -3.2, 3.2);
    const SE3<S> a = urdf.robot.fk(q), b = dh.robot.fk(q);
    const S e = max(S((a.rotation() - b.rotation()).norm()), S((a.translation() - b.translation()).norm()));
    const S ej = S((urdf.robot.spatialJacobian(q) - dh.robot.spatialJacobian(q)).norm());
    worst = max(worst, max(e, ej));
  }
  INFO("worst FK/Jacobian difference " << toDouble(worst));
  CHECK(worst <= tol);
}

TEST_CASE("URDF: fixed joints fold in, --tip picks one chain of a tree", "[urdf]") {
  using S = double;
  const auto file = repoFile("tests/io/urdf/branching.urdf");
  CHECK_THROWS_WITH(readAnyRobot<S>(file), Contains("tree branches") && Contains("left_upper") &&
                                               Contains("right_tool") && Contains("--tip"));
  const RobotFile<S> rf = readAnyRobot<S>(file, "right_tool");
  REQUIRE(rf.robot.dof() == 2);
  CHECK(rf.robot.joints()[0].type == JointType::Revolute);
  CHECK(rf.robot.joints()[1].type == JointType::Prismatic);
  // continuous: no limits; prismatic: its <limit>.
  CHECK(std::isinf(rf.robot.joints()[0].upper));
  CHECK(rf.robot.joints()[1].lower == 0.0);
  CHECK(rf.robot.joints()[1].upper == 0.4);
  JointVector<S> q(2);
  q << pi<S>() / 2, 0.25;
  // Rz(π/2)·(0.5 + 0.25 + 0.1, 0, 0) + (0, 0, 0.3)
  CHECK(rf.robot.fk(q).translation().isApprox(Vec3<S>(0, 0.85, 0.3), Tolerance<S>::identity()));
  CHECK(rf.robot.fk(q).translation().x() == Approx(0).margin(Tolerance<S>::identity()));
  // The other chain, and a tip that is not a link.
  CHECK(readAnyRobot<S>(file, "left_upper").robot.dof() == 1);
  CHECK_THROWS_WITH(readAnyRobot<S>(file, "nope"), Contains("no link named \"nope\""));
  // --tip with a JSON robot is refused.
  CHECK_THROWS_WITH(readAnyRobot<S>(repoFile("studies/robots/puma560.json"), "link6"),
                    Contains("--tip names a URDF link"));
}

TEST_CASE("URDF: every defect is named", "[urdf]") {
  using S = double;
  const auto dir = repoFile("tests/io/urdf");
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "does_not_exist.urdf"), Contains("cannot open the robot file"));
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "not_xml.urdf"), Contains("not a valid URDF"));
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "single_link.urdf"), Contains("no chain"));
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "floating.urdf"),
                    Contains("joint \"six_dof\" is floating") && Contains("serial chain"));
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "planar.urdf"), Contains("joint \"table\" is planar"));
  // An axis that is not a unit vector, and a chain of fixed joints only.
  const std::string head = R"(<robot name="r"><link name="a"/><link name="b"/>)";
  CHECK_THROWS_WITH(parseUrdf<S>(head + R"(<joint name="j" type="continuous"><parent link="a"/>
      <child link="b"/><axis xyz="0 0 2"/></joint></robot>)", "x.urdf"),
                    Contains("x.urdf: joint \"j\" axis is not a unit vector"));
  CHECK_THROWS_WITH(parseUrdf<S>(head + R"(<joint name="j" type="fixed"><parent link="a"/>
      <child link="b"/></joint></robot>)", "x.urdf"),
                    Contains("no chain: no revolute, continuous or prismatic joint"));
  // A mimic joint is not a joint of its own.
  CHECK_THROWS_WITH(parseUrdf<S>(R"(<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
      <joint name="j1" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint>
      <joint name="j2" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
      <mimic joint="j1"/></joint></robot>)", "m.urdf"),
                    Contains("joint \"j2\" mimics joint \"j1\""));
}

}  // namespace SOMA_UNITY_ID
