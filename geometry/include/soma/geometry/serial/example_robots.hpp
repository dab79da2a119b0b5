#pragma once
// Example robots defined once, for the studies, the tests and a library user (the robot files in
// studies/robots/ hold the same data for the command line).
#include "soma/geometry/serial/serial_robot.hpp"

#include <vector>

namespace soma {

/// PUMA 560, standard DH (a, α, d, θ offset) in metres times `scale`, as studies/robots/puma560.json;
/// `wristOffset`·scale is a5 (0: axes 4–6 meet, a Pieper robot; studies/robots/puma560_wrist_offset.json). GF §5.2.1
template <class S> SerialRobot<S> puma560Robot(const S& scale = S(1), const S& wristOffset = S(0)) {
  std::vector<DHRow<S>> rows(6);
  const S h = pi<S>() / S(2);
  rows[0] = {JointType::Revolute, S(0), h, S(0), S(0)};
  rows[1] = {JointType::Revolute, S(4318) / S(10000) * scale, S(0), S(0), S(0)};
  rows[2] = {JointType::Revolute, S(203) / S(10000) * scale, -h, S(15005) / S(100000) * scale, S(0)};
  rows[3] = {JointType::Revolute, S(0), h, S(4318) / S(10000) * scale, S(0)};
  rows[4] = {JointType::Revolute, wristOffset * scale, -h, S(0), S(0)};
  rows[5] = {JointType::Revolute, S(0), S(0), S(5625) / S(100000) * scale, S(0)};
  return SerialRobot<S>::fromDH(rows, DHConvention::Standard, SE3<S>(), SE3<S>(), "PUMA 560");
}

/// The T³-like robot of GF §10.3.2 (Fig. 10.2): joints 2, 3, 4 parallel (links l1, l2, l3), a
/// wrist on the tool axis; POE with the home pose along z (studies/robots/t3.json).
template <class S>
SerialRobot<S> t3Robot(const S& l1 = S(9) / S(10), const S& l2 = S(7) / S(10), const S& l3 = S(1) / S(4)) {
  std::vector<SerialJoint<S>> js(6);
  const Vec3<S> i = Vec3<S>::UnitX(), j = Vec3<S>::UnitY(), k = Vec3<S>::UnitZ();
  js[0].axis = k;
  js[1].axis = i;
  js[2].axis = i, js[2].point = l1 * k;
  js[3].axis = i, js[3].point = (l1 + l2) * k;
  js[4].axis = j, js[4].point = (l1 + l2 + l3) * k;
  js[5].axis = k, js[5].point = (l1 + l2 + l3) * k;  // on the tool axis (the same line as through 0)
  return SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), Vec3<S>((l1 + l2 + l3) * k)), "T3");
}

/// A cuspidal 6R by construction: Wenger's orthogonal 3R arm (d2, d3, d4, r2, r3) = (1, 2, 1.5, 1, 0)
/// and a spherical wrist at its tool point, standard DH (studies/robots/cusp6r_orthogonal_wrist.json).
template <class S> SerialRobot<S> orthogonalWristRobot() {
  const S h = pi<S>() / S(2);
  std::vector<DHRow<S>> rows(6);
  rows[0] = {JointType::Revolute, S(1), -h, S(0), S(0)};
  rows[1] = {JointType::Revolute, S(2), h, S(1), S(0)};
  rows[2] = {JointType::Revolute, S(3) / S(2), S(0), S(0), S(0)};
  rows[3] = {JointType::Revolute, S(0), -h, S(0), S(0)};
  rows[4] = {JointType::Revolute, S(0), h, S(0), S(0)};
  rows[5] = {JointType::Revolute, S(0), S(0), S(3) / S(10), S(0)};
  return SerialRobot<S>::fromDH(rows, DHConvention::Standard, SE3<S>(), SE3<S>(), "orthogonal arm + spherical wrist");
}

}  // namespace soma
