#pragma once
// Reading a serial chain out of a URDF file (issue 7 item 1, parsed by Debian's urdfdom) into a
// product-of-exponentials SerialRobot (GF §4.5): the chain runs from the URDF's root link to a
// tip link (the unique leaf of the tree unless a tip is named). Revolute, continuous and
// prismatic joints become POE joints (axis and a point of it at the home configuration, in root
// coordinates; limits from <limit>, none for continuous); fixed joints are folded into the next
// transform; the tip link's frame at q = 0 is the home pose M. Angles are radians (URDF's unit).
// urdfdom reads numbers in double: a URDF robot is exact to double's rounding in every scalar.
// Every defect (no file, not URDF, no chain, a floating/planar/mimic joint, a branching tree
// without a tip, a non-unit axis) is an InvalidInput naming the file, the joint or link.
#include "soma/io/robot_file.hpp"

#include <filesystem>
#include <string>

namespace soma::io {

/// Parse URDF text; `tip` empty = the unique leaf link.
template <class S>
RobotFile<S> parseUrdf(const std::string& xml, const std::string& origin, const std::string& tip = "");
template <class S> RobotFile<S> readUrdf(const std::filesystem::path& file, const std::string& tip = "");

/// A robot file of either kind, by its extension: ".urdf" → readUrdf, anything else → the
/// DESIGN §6 JSON (readRobot; a `tip` is then refused: it names a URDF link).
template <class S>
RobotFile<S> readAnyRobot(const std::filesystem::path& file, const std::string& tip = "");

#define SOMA_URDF_FILE_EXTERN(S)                                                                 \
  extern template RobotFile<S> parseUrdf<S>(const std::string&, const std::string&,              \
                                            const std::string&);                                 \
  extern template RobotFile<S> readUrdf<S>(const std::filesystem::path&, const std::string&);    \
  extern template RobotFile<S> readAnyRobot<S>(const std::filesystem::path&, const std::string&);
SOMA_FOR_EACH_SCALAR(SOMA_URDF_FILE_EXTERN)
#undef SOMA_URDF_FILE_EXTERN

}  // namespace soma::io
