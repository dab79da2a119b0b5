#pragma once
// Example robots used by several studies, defined once (the robot files in studies/robots/ hold
// the same data for the command line).
#include "soma/geometry/serial/serial_robot.hpp"

#include <vector>

namespace soma::studies {

/// PUMA 560, standard DH (a, α, d, θ offset), as studies/robots/puma560.json. GF §5.2.1
template <class S> SerialRobot<S> puma560Robot() {
  std::vector<DHRow<S>> rows(6);
  const S h = pi<S>() / 2;
  rows[0] = {JointType::Revolute, S(0), h, S(0), S(0)};
  rows[1] = {JointType::Revolute, S(0.4318), S(0), S(0), S(0)};
  rows[2] = {JointType::Revolute, S(0.0203), -h, S(0.15005), S(0)};
  rows[3] = {JointType::Revolute, S(0), h, S(0.4318), S(0)};
  rows[4] = {JointType::Revolute, S(0), -h, S(0), S(0)};
  rows[5] = {JointType::Revolute, S(0), S(0), S(0.05625), S(0)};
  return SerialRobot<S>::fromDH(rows, DHConvention::Standard, SE3<S>(), SE3<S>(), "PUMA 560");
}

}  // namespace soma::studies
