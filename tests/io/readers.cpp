// The robot, platform and planar scene readers: values read as written (decimal strings exact in S),
// and the number reader's errors reported with the file and the key path of the value.
#include "soma/io/input_limits.hpp"
#include "soma/io/planar_scene_file.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/io/robot_file.hpp"

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
// A 2R planar arm, standard DH, with one field replaced by `alpha2`.
std::string twoR(const std::string& alpha2) {
  return R"({"convention": "dh", "joints": [{"a": 1, "alpha": 0, "d": 0, "theta": 0},
                                           {"a": "0.1", "alpha": )" + alpha2 + R"(, "d": 0, "theta": 0}]})";
}
}  // namespace

TEMPLATE_TEST_CASE("robot file: decimal strings exact in S, number errors with the key path", "[io][robot]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const RobotFile<S> rf = parseRobot<S>(twoR("0"), "robot.json");
  REQUIRE(rf.robot.dof() == 2);
  // The DH length "0.1" is S's own 0.1 (not the double's).
  CHECK(rf.robot.dhRows()[1].a == fromString<S>("0.1"));
  CHECK(rf.robot.dhRows()[0].a == S(1));
  CHECK_THROWS_WITH(parseRobot<S>(twoR("\"0x10\""), "robot.json"),
                    "robot.json: joints[1].alpha: \"0x10\" is not a decimal number (hexadecimal)");
  CHECK_THROWS_WITH(parseRobot<S>(twoR("\"inf\""), "robot.json"), Contains("joints[1].alpha: \"inf\" is not a decimal number"));
  CHECK_THROWS_WITH(parseRobot<S>(twoR("\"1e999999999\""), "robot.json"), Contains("joints[1].alpha: \"1e999999999\" is outside the range"));
  CHECK_THROWS_WITH(parseRobot<S>(twoR("1e400"), "robot.json"), Contains("robot.json: joints[1].alpha: 1e400 is outside the range of a JSON number"));
  CHECK_THROWS_WITH(parseRobot<S>(twoR("true"), "robot.json"), "robot.json: joints[1].alpha: expected a number, got boolean");
  // --joints: the same reader; spaces around an entry belong to the list, not to the number.
  const JointVector<S> q = parseJoints<S>("0.5, -0.25", rf);
  CHECK(q(0) == fromString<S>("0.5"));
  CHECK(q(1) == fromString<S>("-0.25"));
  CHECK_THROWS_WITH(parseJoints<S>("0x10,0", rf), "--joints value 1: \"0x10\" is not a decimal number (hexadecimal)");
  CHECK_THROWS_WITH(parseJoints<S>("0,nan", rf), Contains("--joints value 2: \"nan\" is not a decimal number"));
  // Every comma separates two entries: a trailing comma is an empty entry, not the end of the list.
  CHECK_THROWS_WITH(parseJoints<S>("0,", rf), "--joints value 2: empty (a trailing comma?)");
  CHECK_THROWS_WITH(parseJoints<S>("0,0,", rf), "--joints value 3: empty (a trailing comma?)");
  CHECK_THROWS_WITH(parseJoints<S>(",0", rf), "--joints value 1: empty");
  CHECK_THROWS_WITH(parseJoints<S>("0,,0", rf), "--joints value 2: empty");
  CHECK_THROWS_WITH(parseJoints<S>("", rf), "--joints value 1: empty");
  CHECK_THROWS_WITH(parseJoints<S>("0", rf), "--joints: 1 values given, the robot has 2 joints");
  // In degrees: parseJointValues keeps the values as written (what fk echoes), parseJoints turns
  // the revolute ones into radians.
  std::string deg = twoR("0");
  deg.insert(1, R"("angles": "degrees", )");
  const RobotFile<S> rd = parseRobot<S>(deg, "robot.json");
  const std::vector<S> v = parseJointValues<S>("10, -35.5", rd);
  CHECK(v == std::vector<S>{S(10), S(-35.5)});
  CHECK(parseJoints<S>("10, -35.5", rd)(1) == S(-35.5) * (pi<S>() / S(180)));
  CHECK_THROWS_WITH(parseJointValues<S>("0", rd), "--joints: 1 values given, the robot has 2 joints");
}

TEMPLATE_TEST_CASE("robot file: a POE axis is judged at double's tolerance in every scalar, then normalised",
                   "[io][robot]", SOMA_TEST_SCALARS) {
  // Found by the differential fuzz harness (tests/fuzz/corpus/differential/robot_poe_near_unit_axis.json):
  // judged at S's own tolerance, float took a 1e-3 off-unit axis that double refused and __float128
  // and mpfr refused an axis written to 8 digits that double took.
  using S = TestType;
  using std::abs;
  auto robot = [](const std::string& axis) {
    return R"({"convention": "poe", "joints": [{"axis": )" + axis + R"(, "point": [0, 0, 0]}],
               "home": {"quaternion": [1, 0, 0, 0], "translation": [1, 0, 0]}})";
  };
  const auto r = parseRobot<S>(robot("[0, 0, 1.00000001]"), "r.json");
  const Vec3<S> a = r.robot.joints()[0].axis;
  CHECK(abs(a.squaredNorm() - S(1)) <= S(8) * Tolerance<S>::epsilon());
  CHECK(abs(a(2) - S(1)) <= S(8) * Tolerance<S>::epsilon());
  CHECK(parseRobot<S>(robot(R"(["0.6", "0.8", 0])"), "r.json").robot.joints()[0].axis(0) > S(0.59));
  CHECK_THROWS_WITH(parseRobot<S>(robot("[0, 0, 1.001]"), "r.json"),
                    Contains("r.json: joint 1 axis is not a unit vector"));
}

TEST_CASE("robot file: 3.5e38 is a length in double, not in float", "[io][robot]") {
  CHECK(parseRobot<double>(twoR("0").replace(twoR("0").find("\"a\": 1"), 6, "\"a\": \"3.5e38\""), "r").robot.dof() == 2);
  CHECK_THROWS_WITH(parseRobot<float>(twoR("0").replace(twoR("0").find("\"a\": 1"), 6, "\"a\": \"3.5e38\""), "r"),
                    StartsWith("r: joints[0].a: \"3.5e38\" is outside the range of float (it overflows to infinity"));
}

TEST_CASE("robot file: the joint count is bounded (limits::maxJoints), unknown keys everywhere", "[io][robot]") {
  auto robot = [](std::size_t joints) {
    std::string s = R"({"convention": "dh", "joints": [)";
    for (std::size_t k = 0; k < joints; ++k) s += std::string(k ? "," : "") + R"({"a": 1, "alpha": 0, "d": 0, "theta": 0})";
    return s + "]}";
  };
  CHECK(parseRobot<double>(robot(limits::maxJoints), "r.json").robot.dof() == int(limits::maxJoints));
  CHECK_THROWS_WITH(parseRobot<double>(robot(limits::maxJoints + 1), "r.json"),
                    "r.json: joints: 1001 joints, more than the 1000 soma reads");
  // A POE joint and a link of inertial data name their unknown keys too.
  CHECK_THROWS_WITH(parseRobot<double>(R"({"convention": "poe", "home": {"rotation": [[1,0,0],[0,1,0],[0,0,1]],
      "translation": [0,0,0]}, "joints": [{"type": "R", "axis": [0,0,1], "point": [0,0,0], "pont": 1}]})", "p.json"),
                    "p.json: joint 1: unknown field \"pont\" (a poe joint has type, axis, point, offset, limits)");
  CHECK_THROWS_WITH(parseRobot<double>(R"({"convention": "dh", "joints": [{"a": 1, "alpha": 0, "d": 0, "theta": 0}],
      "links": [{"mass": 1, "com": [0,0,0], "inertia": [1,1,1,0,0,0], "colour": 1}]})", "l.json"),
                    "l.json: link 1: unknown field \"colour\" (a link has mass, com, inertia)");
}

TEMPLATE_TEST_CASE("platform file: the general platform — number errors with the key path", "[io][platform]",
                   double, mpfr::mpreal) {
  using S = TestType;
  const StewartPlatform<S> P = readPlatform<S>(repoFile("studies/platforms/general.json"));
  CHECK(P.base[0](0) == scalarCast<S>(0.854648));  // the file's first base coordinate, a JSON double
  const std::string pts = "[[1,0,0],[0,1,0],[-1,0,0],[0,-1,0],[1,1,0.5],[-1,1,0.2]]";
  auto platform = [&](const std::string& legs) {
    return R"({"base": )" + pts + R"(, "platform": )" + pts + R"(, "leg_lengths": )" + legs + "}";
  };
  const StewartPlatform<S> Q = parsePlatform<S>(platform(R"([1, 1, 1, 1, 1, "1.1"])"), "p.json");
  CHECK(Q.legs[5] == fromString<S>("1.1"));
  CHECK_THROWS_WITH(parsePlatform<S>(platform(R"([1, 1, 1, 1, 1, "0x10"])"), "p.json"),
                    "p.json: leg_lengths[5]: \"0x10\" is not a decimal number (hexadecimal)");
  CHECK_THROWS_WITH(parsePlatform<S>(platform("[1, 1, 1, 1, 1]"), "p.json"),
                    "p.json: leg_lengths: expected an array of 6 numbers");
  CHECK_THROWS_WITH(parsePlatform<S>(R"({"base": [[1,0,0],[0,1,0],[-1,0,0],[0,-1,0],[1,1,0.5],[-1,1," 0"]], "platform": )" + pts +
                                         R"(, "leg_lengths": [1,1,1,1,1,1]})", "p.json"),
                    "p.json: base[5][2]: \" 0\" is not a decimal number (leading or trailing space)");
  CHECK_THROWS_WITH(parsePlatform<S>(platform("[1,1,1,1,1,1], \"legs\": 1"), "p.json"),
                    "p.json: unknown field \"legs\" (expected base, platform, leg_lengths)");
}

TEST_CASE("planar scene file: positions, circle points and a 4-bar, in radians", "[io][planar]") {
  const auto dir = repoFile("tests/geometry/planar/scenes");
  const PlanarScene three = readPlanarScene(dir / "three_positions.json");
  REQUIRE(three.positions.size() == 3);
  CHECK(three.positions[1].x == 1);
  CHECK(three.positions[2].angle == 0.7);
  REQUIRE(three.hasCirclePoints);
  REQUIRE(three.circlePoints.size() == 2);
  CHECK(three.circlePoints[0] == Vec2<double>(0.5, -0.2));
  CHECK(!three.fourbar);
  const PlanarScene fb = readPlanarScene(dir / "fourbar.json");
  REQUIRE(fb.fourbar);
  CHECK(fb.fourbar->c4 == Vec2<double>(3, 0));
  CHECK(fb.fourbar->coupler == 2.5);
  CHECK(fb.fourbar->couplerPoint == Vec2<double>(0.8, 1.1));
  CHECK(fb.fourbar->crankAngle == 1.0);
  CHECK(fb.fourbar->crankRates == std::array<double, 4>{1.0, 0.3, -0.2, 0});  // the rate not given is 0
  CHECK(fb.fourbar->mode == 1);
  CHECK_THROWS_WITH(readPlanarScene(dir / "bad_field.json"), (dir / "bad_field.json").string() + ": position 1: missing \"angle\"");
  CHECK_THROWS_WITH(readPlanarScene(dir / "does_not_exist.json"), Contains("cannot read scene file"));
}

TEST_CASE("planar scene file: unknown keys, and the mode read as the integer written", "[io][planar]") {
  const std::string fourbar = R"("fourbar": {"ground": [[0, 0], [3, 0]], "crank": 1.2, "coupler": 2.5, "rocker": 2.0})";
  CHECK(parsePlanarScene("{" + fourbar + R"(, "mode": -1})", "s.json").fourbar->mode == -1);
  // 4294967297 = 2^32 + 1 was taken as 1 (issue 24): the integer is read as written.
  CHECK_THROWS_WITH(parsePlanarScene("{" + fourbar + R"(, "mode": 4294967297})", "s.json"),
                    "\"mode\" must be 1 or -1 (assembly mode), got 4294967297");
  CHECK_THROWS_WITH(parsePlanarScene("{" + fourbar + R"(, "mode": 0.5})", "s.json"), "mode: 0.5 is not an integer");
  CHECK_THROWS_WITH(parsePlanarScene("{" + fourbar + R"(, "bogus": 1})", "s.json"),
                    "scene: unknown field \"bogus\" (a 4-bar scene has fourbar, crank_angle, mode, crank_rates, angles)");
  CHECK_THROWS_WITH(parsePlanarScene(R"({"fourbar": {"ground": [[0, 0], [3, 0]], "crank": 1, "coupler": 2, "rocker": 2,
      "coupler": 3}})", "s.json"), "s.json: fourbar.coupler: the key \"coupler\" is given twice in one object");
  CHECK_THROWS_WITH(parsePlanarScene(R"({"fourbar": {"ground": [[0, 0], [3, 0]], "crank": 1, "coupler": 2, "rocker": 2,
      "coupler_pt": [0, 0]}})", "s.json"), Contains("fourbar: unknown field \"coupler_pt\""));
  CHECK_THROWS_WITH(parsePlanarScene(R"({"positions": [{"x": 0, "y": 0, "angle": 0, "z": 1}]})", "s.json"),
                    "positions[0]: unknown field \"z\" (a position has x, y, angle)");
  CHECK_THROWS_WITH(parsePlanarScene(R"({"positions": [], "fourbar": {}})", "s.json"), Contains("not both"));
}

}  // namespace SOMA_UNITY_ID
