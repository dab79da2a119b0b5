#pragma once
// Link inertial data for a serial robot and the SerialDynamics model of a SerialRobot (GF §13.2).
//
// Robot files (studies/robots/*.json) may carry an additive "links" array, one object per moving
// link, in the link's own frame (the DH frame F_i of link i for a DH robot, the joint frame for a
// POE robot, at the home configuration θ = 0):
//   {"mass": m, "com": [x, y, z], "inertia": [Ixx, Iyy, Izz, Ixy, Iyz, Ixz]}
// with the inertia tensor about the centre of mass, axes parallel to the link frame (kg·m², SI).
// readLinkInertias parses it (double; InvalidInput names the link and the defect, e.g. mass ≤ 0).
//
// serialDynamicsOf is header-only (it is instantiated where a SerialRobot is at hand, in studies
// and tests, so soma_geometry_dynamics does not link soma_geometry_serial). The dynamics variable
// is θ_i = q_i + offset_i: the twists of SerialRobot::joints() are the home screws s_i⁰.
#include "soma/geometry/dynamics/serial_dynamics.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <filesystem>
#include <vector>

namespace soma {

/// The "links" array of a robot JSON file. InvalidInput if the file cannot be read, has no "links",
/// or a link has a missing field, a non-positive mass, or an inertia that is not positive definite.
std::vector<SpatialInertia<double>> readLinkInertias(const std::filesystem::path& file);
std::vector<SpatialInertia<double>> parseLinkInertias(const std::string& jsonText, const std::string& origin);

/// The SerialDynamics model of `robot` with link i's inertia given in its own home frame
/// (robot.frames(−offsets)[i + 1]) and gravity g along −z of the base frame. GF §13.2.2
template <class S>
SerialDynamics<S> serialDynamicsOf(const SerialRobot<S>& robot, const std::vector<SpatialInertia<S>>& linkInertias,
                                   const S& gravity) {
  const int n = robot.dof();
  if (int(linkInertias.size()) != n)
    throw InvalidInput("serialDynamicsOf: " + std::to_string(linkInertias.size()) + " link inertias for a robot with " +
                       std::to_string(n) + " joints");
  JointVector<S> q0(n);
  for (int i = 0; i < n; ++i) q0(i) = -robot.joints()[std::size_t(i)].offset;
  const std::vector<SE3<S>> F = robot.frames(q0);
  std::vector<SE3Tangent<S>> screws;
  std::vector<SpatialInertia<S>> links;
  for (int i = 0; i < n; ++i) {
    screws.push_back(robot.joints()[std::size_t(i)].twist());
    links.push_back(linkInertias[std::size_t(i)].transformed(F[std::size_t(i + 1)]));
  }
  return SerialDynamics<S>(screws, links, gravity);
}

}  // namespace soma
