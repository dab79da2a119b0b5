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

/// Universal Robots UR5 as a POE robot (the joint axes at q = 0), from the maker's DH d1, a2, a3, d4,
/// d5, d6 (α1 = α4 = 90°, α5 = −90°; other lengths give the same family), as studies/robots/ur5_poe.json.
/// Axes 2, 3, 4 parallel, axes 5, 6 meeting.
template <class S>
SerialRobot<S> ur5Robot(const S& d1 = S(89159) / S(1000000), const S& a2 = S(-425) / S(1000),
                        const S& a3 = S(-39225) / S(100000), const S& d4 = S(10915) / S(100000),
                        const S& d5 = S(9465) / S(100000), const S& d6 = S(823) / S(10000)) {
  const S h = pi<S>() / S(2);
  std::vector<DHRow<S>> rows = {{JointType::Revolute, S(0), h, d1, S(0)},  {JointType::Revolute, a2, S(0), S(0), S(0)},
                                {JointType::Revolute, a3, S(0), S(0), S(0)}, {JointType::Revolute, S(0), h, d4, S(0)},
                                {JointType::Revolute, S(0), -h, d5, S(0)},  {JointType::Revolute, S(0), S(0), d6, S(0)}};
  const SerialRobot<S> dh = SerialRobot<S>::fromDH(rows);
  return SerialRobot<S>::fromPOE(dh.joints(), dh.home(), "UR5");
}

/// KUKA KR 6 R900 sixx in modified DH (a_{i-1}, α_{i-1}, d_i, θ_i), its 400 mm base height as a base
/// transform (studies/robots/kr6_r900_mdh.json, without the joint limits). Axes 4, 5, 6 meet.
template <class S> SerialRobot<S> kr6Robot() {
  const S h = pi<S>() / S(2);
  std::vector<DHRow<S>> rows = {{JointType::Revolute, S(0), S(0), S(0), S(0)},
                                {JointType::Revolute, S(25) / S(1000), -h, S(0), S(0)},
                                {JointType::Revolute, S(455) / S(1000), S(0), S(0), -h},
                                {JointType::Revolute, S(35) / S(1000), -h, S(420) / S(1000), S(0)},
                                {JointType::Revolute, S(0), h, S(0), S(0)},
                                {JointType::Revolute, S(0), -h, S(80) / S(1000), S(0)}};
  return SerialRobot<S>::fromDH(rows, DHConvention::Modified, SE3<S>(SO3<S>(), Vec3<S>(S(0), S(0), S(4) / S(10))),
                                SE3<S>(), "KUKA KR6 R900");
}

/// FANUC CRX-10iA in the modified DH of Abbes & Poisson, Robotics 13(6):91, 2024, Table 2 (metres;
/// joint 3 its own variable), as studies/robots/crx10ia_mdh.json. Not a Pieper robot; reported
/// cuspidal by Salunkhe, Chablat & Wenger (ICRA 2023).
template <class S> SerialRobot<S> crx10iaRobot() {
  const S h = pi<S>() / S(2);
  std::vector<DHRow<S>> rows = {{JointType::Revolute, S(0), S(0), S(0), S(0)},
                                {JointType::Revolute, S(0), -h, S(0), -h},
                                {JointType::Revolute, S(54) / S(100), S(2) * h, S(0), S(0)},
                                {JointType::Revolute, S(0), -h, S(-54) / S(100), S(0)},
                                {JointType::Revolute, S(0), h, S(15) / S(100), S(0)},
                                {JointType::Revolute, S(0), -h, S(-16) / S(100), S(0)}};
  return SerialRobot<S>::fromDH(rows, DHConvention::Modified, SE3<S>(), SE3<S>(), "FANUC CRX-10iA");
}

}  // namespace soma

