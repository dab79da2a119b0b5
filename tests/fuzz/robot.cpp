// libFuzzer harness: the robot JSON reader (io::parseRobot, DH / MDH / POE, limits, base, tool,
// home, link inertias), and the --joints reader on the robot it returns.
#include "harness.hpp"

#include "soma/io/robot_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The input's first line, when it starts with '#', is a --joints text for the robot.
  std::string body = soma::fuzz::text(data, size), joints;
  if (!body.empty() && body[0] == '#') {
    const std::size_t nl = body.find('\n');
    joints = body.substr(1, nl == std::string::npos ? std::string::npos : nl - 1);
    body = nl == std::string::npos ? std::string() : body.substr(nl + 1);
  }
  soma::fuzz::expectReadOrInvalidInput("robot", [&] {
    const auto robot = soma::io::parseRobot<double>(body, "fuzz.json");
    if (!joints.empty()) (void)soma::io::parseJoints<double>(joints, robot);
  });
  return 0;
}
