#pragma once
// The SerialDynamics model of a SerialRobot and its links' inertias (GF §13.2). The inertias of
// a robot file's "links" array are read by soma::io::readLinkInertias (io/link_inertia_file.hpp),
// each in its link's own home frame.
//
// serialDynamicsOf is header-only (it is instantiated where a SerialRobot is at hand, in studies
// and tests, so soma_geometry_dynamics does not link soma_geometry_serial). The dynamics variable
// is θ_i = q_i + offset_i: the twists of SerialRobot::joints() are the home screws s_i⁰.
#include "soma/geometry/dynamics/serial_dynamics.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <vector>

namespace soma {

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
