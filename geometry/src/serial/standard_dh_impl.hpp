#pragma once
// Definitions of toStandardDH (standard_dh.hpp), instantiated for the five scalars by soma_instantiate.
#include "soma/geometry/serial/standard_dh.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace soma {

// GF §3.4: DH frames from the common normals of consecutive axes. Frame i-1 has z along axis i;
// x_i runs along the common normal of axes i and i+1 (for parallel axes: the normal through the
// previous origin, d_i = 0); frame 6 = frame 5 turned by joint 6. Joint offsets go into the θ_i.
// Checked: the DH robot's FK equals the robot's.
template <class S> SerialRobot<S> toStandardDH(const SerialRobot<S>& robot) {
  using std::atan2;
  using std::sqrt;
  if (robot.dof() != 6 || !robot.allRevolute())
    throw InvalidInput("toStandardDH: needs a robot with 6 revolute joints (this one has " +
                       std::to_string(robot.dof()) + " joints" + (robot.allRevolute() ? ")" : ", not all revolute)"));
  const auto& J = robot.joints();
  std::array<Vec3<S>, 7> x, z, o;  // frames 0..6 (x_0 = x_1, frame 6 = frame 5)
  std::vector<DHRow<S>> rows(6);
  const S par = Tolerance<S>::input();
  Vec3<S> prevOrigin = J[0].point;
  for (int i = 0; i < 5; ++i) {
    const Vec3<S> ui = J[i].axis, uj = J[i + 1].axis, w = J[i + 1].point - J[i].point;
    const Vec3<S> n = ui.cross(uj);
    Vec3<S> foot;  // foot of the common normal on axis i (c_i) and on axis i+1 (o_i)
    if (n.squaredNorm() > par * par) {
      x[i + 1] = n / sqrt(n.squaredNorm());
      // c_i = p_i + s u_i, o_i = p_j + t u_j with o_i − c_i ∥ x: (w + t u_j − s u_i)·u_{i,j} = 0.
      const S b = ui.dot(uj), d1 = w.dot(ui), d2 = w.dot(uj), den = S(1) - b * b;
      const S sPar = (d1 - b * d2) / den, tPar = (b * d1 - d2) / den;
      foot = J[i].point + sPar * ui;
      o[i + 1] = J[i + 1].point + tPar * uj;
    } else {
      foot = prevOrigin;  // on axis i already (the previous foot), so d_i = 0 for i > 0
      const Vec3<S> r = J[i + 1].point - foot, perp = r - r.dot(ui) * ui;
      x[i + 1] = perp.squaredNorm() > par * par * robot.lengthScale() * robot.lengthScale()
                     ? Vec3<S>(perp / sqrt(perp.squaredNorm()))
                     : (i == 0 ? Vec3<S>(ui.unitOrthogonal()) : x[i]);
      o[i + 1] = foot + perp.dot(x[i + 1]) * x[i + 1];
    }
    z[i + 1] = uj;
    if (i == 0) {
      x[0] = x[1], z[0] = ui, o[0] = foot;
    }
    DHRow<S>& r = rows[i];
    r.d = (foot - o[i]).dot(z[i]);
    r.theta = atan2(x[i].cross(x[i + 1]).dot(z[i]), x[i].dot(x[i + 1])) + J[i].offset;
    r.a = (o[i + 1] - foot).dot(x[i + 1]);
    r.alpha = atan2(z[i].cross(z[i + 1]).dot(x[i + 1]), z[i].dot(z[i + 1]));
    prevOrigin = o[i + 1];
  }
  rows[5].theta = J[5].offset;
  auto frame = [&](int i) {
    Mat3<S> R;
    R.col(0) = x[i], R.col(1) = z[i].cross(x[i]), R.col(2) = z[i];
    return SE3<S>(SO3<S>::fromMatrix(R), o[i]);
  };
  const SE3<S> base = frame(0), tool = frame(5).inverse() * robot.home();
  SerialRobot<S> dh = SerialRobot<S>::fromDH(rows, DHConvention::Standard, base, tool, robot.name());
  std::vector<S> lo, hi;
  for (const auto& j : J) lo.push_back(j.lower), hi.push_back(j.upper);
  dh = dh.withLimits(lo, hi);
  JointVector<S> q(6);
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 6; ++i) q(i) = S(k + 1) * S(i - 2) / S(3);
    if (!(poseResidual(dh.fk(q), robot.fk(q), robot.lengthScale()) <= Tolerance<S>::identity(4096)))
      throw InvalidInput("ik: the robot's joint axes could not be written as standard DH rows (FK mismatch)");
  }
  return dh;
}

#define SOMA_INSTANTIATE_STANDARD_DH(S) template SerialRobot<S> toStandardDH<S>(const SerialRobot<S>&);

}  // namespace soma
