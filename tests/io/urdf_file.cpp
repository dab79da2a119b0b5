// URDF import of serial chains (io/urdf_file.hpp): the PUMA 560 written as a URDF from its
// DH table has the forward kinematics, the Jacobian and the limits of the DH robot; fixed joints
// fold in, a tip picks one chain of a tree, and every defect is an InvalidInput naming it.
#include "soma/io/input_limits.hpp"
#include "soma/io/urdf_file.hpp"

#include "support/repo_file.hpp"
#include "support/scalars.hpp"

#include <filesystem>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;
using Catch::StartsWith;

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

TEST_CASE("URDF: the joint graph is checked before it is walked (issue 24)", "[urdf]") {
  using S = double;
  const auto dir = repoFile("tests/io/urdf");
  // A cycle apart from the root's tree, and a self loop: both looped forever (with --tip in them).
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "cycle.urdf", "d"),
                    Contains("cycle.urdf: not a valid URDF robot: the joints form a cycle (\"c\" → \"d\" → \"c\")"));
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "self_loop.urdf", "b"),
                    Contains("self_loop.urdf: not a valid URDF robot: joint \"j2\": link \"b\" is its own parent (a self loop)"));
  auto robot = [](const std::string& links, const std::string& joints) {
    std::string s = "<robot name=\"r\">";
    for (const char l : links) s += "<link name=\"" + std::string(1, l) + "\"/>";
    for (std::size_t k = 0; k + 1 < joints.size(); k += 2)
      s += "<joint name=\"j" + std::to_string(k / 2) + "\" type=\"continuous\"><parent link=\"" + std::string(1, joints[k]) +
           "\"/><child link=\"" + std::string(1, joints[k + 1]) + "\"/><axis xyz=\"0 0 1\"/></joint>";
    return s + "</robot>";
  };
  CHECK(parseUrdf<S>(robot("abc", "abbc"), "t.urdf").robot.dof() == 2);
  CHECK_THROWS_WITH(parseUrdf<S>(robot("abc", "abcb"), "t.urdf"),
                    "t.urdf: not a valid URDF robot: link \"b\" is the child of joints \"j0\" and \"j1\" (a link has one parent joint)");
  CHECK_THROWS_WITH(parseUrdf<S>(robot("abc", "ab"), "t.urdf"), Contains("links \"a\" and \"c\" are both roots"));
  CHECK_THROWS_WITH(parseUrdf<S>(robot("ab", "abba"), "t.urdf"),
                    Contains("the joints form a cycle (\"a\" → \"b\" → \"a\"): a link is its own ancestor"));
  CHECK_THROWS_WITH(parseUrdf<S>(robot("ab", "ax"), "t.urdf"), Contains("joint \"j0\": its child link \"x\" is not defined"));
  CHECK_THROWS_WITH(parseUrdf<S>(robot("ab", "xb"), "t.urdf"), Contains("joint \"j0\": its parent link \"x\" is not defined"));
  CHECK_THROWS_WITH(parseUrdf<S>(robot("aba", "ab"), "t.urdf"), Contains("link \"a\" is defined twice"));
  CHECK_THROWS_WITH(parseUrdf<S>(R"(<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="fixed">
      <parent link="a"/></joint></robot>)", "t.urdf"), Contains("joint \"j\": no <child link="));
  // The joint count: limits::maxJoints joints are read, one more is refused (a 200,000-joint chain
  // crashed urdfdom's recursive destruction of its link tree).
  auto chain = [](std::size_t joints) {
    std::string s = "<robot name=\"long\"><link name=\"l0\"/>";
    for (std::size_t k = 0; k < joints; ++k)
      s += "<link name=\"l" + std::to_string(k + 1) + "\"/><joint name=\"j" + std::to_string(k) +
           "\" type=\"continuous\"><parent link=\"l" + std::to_string(k) + "\"/><child link=\"l" + std::to_string(k + 1) +
           "\"/><axis xyz=\"0 0 1\"/></joint>";
    return s + "</robot>";
  };
  CHECK(parseUrdf<S>(chain(limits::maxJoints), "c.urdf").robot.dof() == int(limits::maxJoints));
  CHECK_THROWS_WITH(parseUrdf<S>(chain(limits::maxJoints + 1), "c.urdf"),
                    Contains("c.urdf: not a valid URDF: line 1: more than 1000 joints (the most soma reads)"));
}

TEST_CASE("URDF: the text is checked before TinyXML sees it (issue 24)", "[urdf]") {
  using S = double;
  const auto dir = repoFile("tests/io/urdf");
  const std::string two = R"(<link name="a"/><link name="b"/><joint name="j" type="continuous"><parent link="a"/>)"
                          R"(<child link="b"/><axis xyz="0 0 1"/></joint>)";
  const std::string ok = "<robot name=\"r\">" + two + "</robot>";
  REQUIRE(parseUrdf<S>(ok, "t.urdf").robot.dof() == 1);
  // Nesting: maxDepth levels are read, one more is refused (10^5 levels crashed TinyXML's recursion).
  auto nested = [&](std::size_t depth) {  // robot > link > visual^(depth-2)
    return "<robot name=\"r\">" + two + "<link name=\"x\">" + [&] {
      std::string s;
      for (std::size_t k = 2; k < depth; ++k) s += "<visual>";
      for (std::size_t k = 2; k < depth; ++k) s += "</visual>";
      return s;
    }() + "</link><joint name=\"jx\" type=\"fixed\"><parent link=\"b\"/><child link=\"x\"/></joint></robot>";
  };
  CHECK(parseUrdf<S>(nested(limits::maxDepth), "t.urdf").robot.dof() == 1);
  CHECK_THROWS_WITH(parseUrdf<S>(nested(limits::maxDepth + 1), "t.urdf"),
                    "t.urdf: not a valid URDF: line 1: elements nested deeper than 64 levels (the most soma reads)");
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "nested.urdf"), Contains("nested deeper than 64 levels"));
  // Bytes that are not UTF-8 of XML characters: TinyXML 2.6.2 read past its buffer on a UTF-8
  // sequence cut short; NUL and control characters are not XML.
  CHECK_THROWS_WITH(parseUrdf<S>(ok + "\xF0", "t.urdf"), Contains("a UTF-8 sequence cut short at the end of the text"));
  CHECK_THROWS_WITH(parseUrdf<S>(ok + "\xF0\x9F", "t.urdf"), Contains("cut short"));
  CHECK_THROWS_WITH(parseUrdf<S>("<robot name=\"\xC3\x28\">" + two + "</robot>", "t.urdf"), Contains("cut short at offset 13"));
  CHECK_THROWS_WITH(parseUrdf<S>("<robot name=\"\xC0\xAF\">" + two + "</robot>", "t.urdf"), Contains("byte 0xC0 at offset 13 is not UTF-8"));
  CHECK_THROWS_WITH(parseUrdf<S>("<robot name=\"\xED\xA0\x80\">" + two + "</robot>", "t.urdf"), Contains("an invalid UTF-8 sequence"));
  CHECK_THROWS_WITH(parseUrdf<S>(std::string("<robot name=\"r\">") + '\0' + two + "</robot>", "t.urdf"), Contains("a NUL byte at offset 16"));
  CHECK_THROWS_WITH(parseUrdf<S>("<robot name=\"\x01\">" + two + "</robot>", "t.urdf"), Contains("the character U+01"));
  CHECK_THROWS_WITH(parseUrdf<S>("<robot name=\"\xEF\xBF\xBE\">" + two + "</robot>", "t.urdf"), Contains("the character U+FFFE"));
  CHECK(parseUrdf<S>("\xEF\xBB\xBF<robot name=\"r\xC3\xA9\">" + two + "</robot>", "t.urdf").robot.name() == "r\xC3\xA9");
  // Entities: XML's five and numeric ones of XML characters.
  CHECK(parseUrdf<S>("<robot name=\"&lt;r&#x41;&#66;&amp;\">" + two + "</robot>", "t.urdf").robot.name() == "<rAB&");
  for (const char* bad : {"&nbsp;", "&#x0;", "&#xD800;", "&#x110000;", "&#;", "&#x;", "&", "&#99999999;", "&#x41"})
    CHECK_THROWS_WITH(parseUrdf<S>("<robot name=\"" + std::string(bad) + "\">" + two + "</robot>", "t.urdf"),
                      Contains("entity reference") || Contains("starts no entity"));
  // Tags.
  for (const char* bad : {"<robot name=\"r\">", "<robot name=\"r\"></link></robot>", "<robot name=r></robot>",
                          "<robot name=\"r\"/><robot name=\"s\"/>", "<!DOCTYPE r [<!ENTITY e \"x\">]><robot/>",
                          "<robot name=\"r\" name=\"s\"/>", "<robot name=\"a<b\"/>", "<robot><!-- </robot>", "x<robot/>",
                          "<robot name=\"r\"><1/></robot>", "", "<robot name=\"r\"x=\"1\"/>"})
    CHECK_THROWS_WITH(parseUrdf<S>(bad, "t.urdf"), StartsWith("t.urdf: not a valid URDF: line 1: "));
  // Numbers go through the one number reader, in double (urdfdom's precision).
  CHECK_THROWS_WITH(readAnyRobot<S>(dir / "hex_limit.urdf"),
                    Contains("hex_limit.urdf: joint \"j1\" > limit@upper: \"0x10\" is not a decimal number (hexadecimal)"));
  auto withAxis = [&](const std::string& xyz) {
    return R"(<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="continuous"><parent link="a"/>)"
           R"(<child link="b"/><axis xyz=")" + xyz + R"("/></joint></robot>)";
  };
  CHECK(parseUrdf<S>(withAxis("0 0 1e0"), "t.urdf").robot.dof() == 1);
  CHECK_THROWS_WITH(parseUrdf<S>(withAxis("0 0 nan"), "t.urdf"), "t.urdf: joint \"j\" > axis@xyz[2]: \"nan\" is not a decimal number (NaN and infinity are not numbers soma reads)");
  CHECK_THROWS_WITH(parseUrdf<S>(withAxis("0 0 1e999"), "t.urdf"), StartsWith("t.urdf: joint \"j\" > axis@xyz[2]: \"1e999\" is outside the range of double"));
  CHECK_THROWS_WITH(parseUrdf<S>(withAxis("0 1"), "t.urdf"), "t.urdf: joint \"j\" > axis@xyz: \"0 1\" has 2 numbers, 3 expected");
  CHECK_THROWS_WITH(parseUrdf<S>(R"(<robot name="r"><link name="a"><inertial><mass value="0x1"/></inertial></link></robot>)", "t.urdf"),
                    Contains("link \"a\" > inertial > mass@value: \"0x1\" is not a decimal number"));
  // The file's size: read in bounded pieces.
  CHECK_THROWS_WITH(parseUrdf<S>(std::string(limits::maxFileBytes + 1, ' '), "t.urdf"),
                    "t.urdf: the URDF text is larger than 16 MiB, the largest input soma reads");
}

}  // namespace SOMA_UNITY_ID
