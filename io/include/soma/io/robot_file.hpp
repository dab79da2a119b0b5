#pragma once
// Reading a robot file (DESIGN §6):
//   {"name": "...", "angles": "degrees"|"radians", "convention": "dh"|"mdh"|"poe",
//    "joints": [...], "base": POSE, "tool": POSE, "home": POSE}
// DH / MDH joints: {"type": "R"|"P", "a", "alpha", "d", "theta", "limits": [lo, hi]}
// (standard A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); modified: a, alpha of the previous link).
// POE joints: {"type", "axis": [x,y,z], "point": [x,y,z], "offset", "limits"} and the tool's
// home pose "home" (required for poe). "base"/"tool" (dh, mdh) are optional poses, parsed like
// pose files. Numbers may be JSON numbers or decimal strings (exact in mpfr/float128), read by the
// one number reader (number.hpp). An optional "links" array carries the links' inertial data
// (link_inertia_file.hpp), read into RobotFile::links.
// Angles (alpha, theta, revolute offsets and limits) are in the file's unit. Every defect is an
// InvalidInput naming the file, the joint and the field.
#include "soma/geometry/dynamics/spatial_inertia.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace soma::io {

template <class S> struct RobotFile {
  SerialRobot<S> robot;
  bool degrees = false;  ///< joint angles in and out of the CLI are in degrees
  /// The file's "links" (GF ch. 13 inertial data, double), empty when it has none.
  std::vector<SpatialInertia<double>> links;
};

template <class S> RobotFile<S> parseRobot(const std::string& text, const std::string& origin);
template <class S> RobotFile<S> readRobot(const std::filesystem::path& file);

/// Parse "q1,q2,..." (decimal numbers exact in S, spaces around an entry allowed); the robot's
/// angle unit applies to revolute joints. Throws InvalidInput naming the bad entry.
template <class S> JointVector<S> parseJoints(const std::string& text, const RobotFile<S>& robot);
/// The values of "q1,q2,..." as written (degrees when the robot file says so), exact in S: what a
/// command echoes. The same checks and messages as parseJoints.
template <class S> std::vector<S> parseJointValues(const std::string& text, const RobotFile<S>& robot);

#define SOMA_ROBOT_FILE_EXTERN(S)                                                              \
  extern template RobotFile<S> parseRobot<S>(const std::string&, const std::string&);          \
  extern template RobotFile<S> readRobot<S>(const std::filesystem::path&);                     \
  extern template JointVector<S> parseJoints<S>(const std::string&, const RobotFile<S>&);      \
  extern template std::vector<S> parseJointValues<S>(const std::string&, const RobotFile<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_ROBOT_FILE_EXTERN)
#undef SOMA_ROBOT_FILE_EXTERN

}  // namespace soma::io
