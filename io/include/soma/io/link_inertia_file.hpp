#pragma once
// Link inertial data of a serial robot (GF §13.2): the "links" array that a robot JSON file
// (studies/robots/*.json) may carry, one object per moving link, in the link's own frame (the DH
// frame F_i of link i for a DH robot, the joint frame for a POE robot, at the home configuration):
//   {"mass": m, "com": [x, y, z], "inertia": [Ixx, Iyy, Izz, Ixy, Iyz, Ixz]}
// with the inertia tensor about the centre of mass, axes parallel to the link frame (kg·m², SI).
// Read in double through the one number reader (number.hpp); serialDynamicsOf
// (geometry/dynamics/robot_dynamics.hpp) turns them and a SerialRobot into a SerialDynamics model.
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace soma::io {

/// The "links" array of a robot JSON file. InvalidInput if the file cannot be read, has no "links",
/// or a link has a missing field, a non-positive mass, or an inertia that is not positive definite.
std::vector<SpatialInertia<double>> readLinkInertias(const std::filesystem::path& file);
std::vector<SpatialInertia<double>> parseLinkInertias(const std::string& jsonText, const std::string& origin);
/// The "links" of a parsed robot document `robot` (the robot-file reader calls it).
std::vector<SpatialInertia<double>> linkInertiasFromJson(const nlohmann::json& robot, const std::string& origin);

}  // namespace soma::io
