#pragma once
// Example robots of the serial IK tests (standard DH, A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i)); the
// same robots as studies/robots/*.json.
#include "soma/geometry/serial/serial_robot.hpp"

#include <vector>

namespace soma::test {

/// The PUMA 560 (metres; axes 4–6 meet: a Pieper robot), lengths times `scale`.
template <class S> SerialRobot<S> puma560(const S& scale = S(1)) {
  std::vector<DHRow<S>> rows(6);
  const S h = pi<S>() / S(2);
  rows[0] = {JointType::Revolute, S(0), h, S(0), S(0)};
  rows[1] = {JointType::Revolute, S(4318) / S(10000) * scale, S(0), S(0), S(0)};
  rows[2] = {JointType::Revolute, S(203) / S(10000) * scale, -h, S(15005) / S(100000) * scale, S(0)};
  rows[3] = {JointType::Revolute, S(0), h, S(4318) / S(10000) * scale, S(0)};
  rows[4] = {JointType::Revolute, S(0), -h, S(0), S(0)};
  rows[5] = {JointType::Revolute, S(0), S(0), S(5625) / S(100000) * scale, S(0)};
  return SerialRobot<S>::fromDH(rows, DHConvention::Standard, SE3<S>(), SE3<S>(), "PUMA 560");
}

/// The PUMA 560 with the joint limits of studies/robots/puma560.json (degrees there).
template <class S> SerialRobot<S> puma560Limited() {
  const double lo[6] = {-160, -225, -45, -110, -100, -266}, hi[6] = {160, 45, 225, 170, 100, 266};
  std::vector<S> l, u;
  for (int i = 0; i < 6; ++i) {
    l.push_back(scalarCast<S>(lo[i]) * pi<S>() / S(180));
    u.push_back(scalarCast<S>(hi[i]) * pi<S>() / S(180));
  }
  return puma560<S>().withLimits(l, u);
}

/// studies/robots/general6r.json: no three consecutive axes meeting or parallel, 16 complex
/// postures in general (GF §11.5).
template <class S> SerialRobot<S> general6rExample() {
  const double rows[6][3] = {{0.31, 0.83, 0.12}, {0.57, -1.21, -0.23}, {0.18, 1.47, 0.41},
                             {0.44, -0.62, 0.09}, {0.26, 1.05, -0.35}, {0.13, -0.94, 0.27}};
  std::vector<DHRow<S>> dh(6);
  for (int i = 0; i < 6; ++i)
    dh[i] = {JointType::Revolute, fromString<S>(std::to_string(rows[i][0])), fromString<S>(std::to_string(rows[i][1])),
             fromString<S>(std::to_string(rows[i][2])), S(0)};
  return SerialRobot<S>::fromDH(dh, DHConvention::Standard, SE3<S>(), SE3<S>(), "General 6R (random DH)");
}

}  // namespace soma::test
