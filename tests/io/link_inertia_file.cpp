// Link inertias (io/link_inertia_file.hpp): the PUMA 560 data of studies/robots/puma560_dynamics.json
// (Armstrong, Khatib & Burdick 1986, via Corke's mdl_puma560), read on their own and by the robot
// reader; bad data is an InvalidInput naming the link.
#include "soma/io/link_inertia_file.hpp"
#include "soma/io/robot_file.hpp"

#include "support/repo_file.hpp"
#include "support/scalars.hpp"

#include <filesystem>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;

namespace {
std::filesystem::path pumaDynamics() {
  return soma::test::repoFile("studies/robots/puma560_dynamics.json");
}
}  // namespace

TEST_CASE("link inertia file: the PUMA 560 data parse — bad data is InvalidInput", "[io][dynamics][edge]") {
  const auto links = readLinkInertias(pumaDynamics());
  REQUIRE(links.size() == 6);
  CHECK(links[1].mass() == 17.4);  // link 2 of the PUMA 560: 17.4 kg (Armstrong et al. 1986)
  CHECK_THROWS_WITH(parseLinkInertias(R"({"links": [{"mass": 0, "com": [0,0,0], "inertia": [1,1,1,0,0,0]}]})", "t"),
                    Contains("t: link 1: mass 0 is not positive"));
  CHECK_THROWS_WITH(parseLinkInertias(R"({"links": [{"mass": 1, "com": [0,0], "inertia": [1,1,1,0,0,0]}]})", "t"),
                    Contains("t: link 1: \"com\" must be an array of 3 numbers"));
  CHECK_THROWS_AS(parseLinkInertias(R"({"links": [{"mass": 1, "com": [0,0,0], "inertia": [1,1,-1,0,0,0]}]})", "t"),
                  InvalidInput);
  CHECK_THROWS_WITH(parseLinkInertias(R"({"joints": []})", "t"), Contains("no \"links\" array"));
  // Numbers through the one number reader: its errors, with the key path.
  CHECK_THROWS_WITH(parseLinkInertias(R"({"links": [{"mass": 1, "com": [0,0,0], "inertia": [1,1,1,0,0,0]},
                                                    {"mass": "0x10", "com": [0,0,0], "inertia": [1,1,1,0,0,0]}]})", "t"),
                    Contains("t: links[1].mass: \"0x10\" is not a decimal number (hexadecimal)"));
  CHECK_THROWS_WITH(parseLinkInertias(R"({"links": [{"mass": 1, "com": [0,"nan",0], "inertia": [1,1,1,0,0,0]}]})", "t"),
                    Contains("t: links[0].com[1]: \"nan\" is not a decimal number"));
  CHECK_THROWS_WITH(readLinkInertias("/nonexistent/robot.json"), Contains("cannot open"));
}

TEST_CASE("the robot reader reads a robot file's links", "[io][dynamics]") {
  const RobotFile<double> rf = readRobot<double>(pumaDynamics());
  REQUIRE(rf.robot.dof() == 6);
  const auto links = readLinkInertias(pumaDynamics());
  REQUIRE(rf.links.size() == links.size());
  for (std::size_t i = 0; i < links.size(); ++i) {
    CHECK(rf.links[i].mass() == links[i].mass());
    CHECK(rf.links[i].matrix() == links[i].matrix());
  }
  // A robot without "links" has none.
  CHECK(readRobot<double>(soma::test::repoFile("studies/robots/puma560.json")).links.empty());
}

}  // namespace SOMA_UNITY_ID
