#pragma once
// A posture within the robot's joint limits: a revolute joint's angle is defined modulo 2π, so
// a solver's angle in (−π, π] stands for every θ + 2πk. A joint whose limits do not contain
// (−π, π] (the Franka-type arm's joint 6 in [−1°, 215°], a KUKA arm's joint 2 in [−190°, 45°])
// reaches the posture at θ + 2πk when that lies within them; dropping it would lose a posture.
#include "soma/geometry/serial/serial_robot.hpp"

#include <cmath>
#include <optional>

namespace soma {

/// q with each revolute angle moved by a multiple of 2π into the joint's limits (the angle itself
/// when it lies within them, else the nearest such multiple); nullopt when some joint cannot be
/// (a prismatic value outside, or no θ + 2πk within an angular range narrower than 2π). Limits
/// wider than 2π hold several such angles: the one nearest q's is returned (one posture per pose
/// branch, as the solvers count them).
template <class S, class Vec> bool shiftIntoLimitsInPlace(const SerialRobot<S>& robot, Vec& out);

template <class S> std::optional<JointVector<S>> shiftIntoLimits(const SerialRobot<S>& robot, const JointVector<S>& q) {
  JointVector<S> out = q;
  if (!shiftIntoLimitsInPlace(robot, out)) return std::nullopt;
  return out;
}

/// shiftIntoLimits applied to `out` itself (any Eigen vector; its first min(dof, size) entries), without
/// a copy: false when some joint cannot be shifted into its limits (`out` is then partly shifted).
template <class S, class Vec> bool shiftIntoLimitsInPlace(const SerialRobot<S>& robot, Vec& out) {
  using std::ceil;
  const S twoPi = S(2) * pi<S>();
  for (int i = 0; i < robot.dof() && i < int(out.size()); ++i) {
    const auto& j = robot.joints()[i];
    if (out(i) >= j.lower && out(i) <= j.upper) continue;
    if (j.type != JointType::Revolute) return false;
    // The multiple of 2π that takes θ just above the lower limit, or just below the upper one.
    const S up = out(i) + twoPi * ceil((j.lower - out(i)) / twoPi);
    const S down = out(i) - twoPi * ceil((out(i) - j.upper) / twoPi);
    if (out(i) < j.lower && up <= j.upper) out(i) = up;
    else if (out(i) > j.upper && down >= j.lower) out(i) = down;
    else return false;
  }
  return true;
}

}  // namespace soma
