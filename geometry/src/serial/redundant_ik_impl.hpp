#pragma once
// Definitions of redundant_ik.hpp: locked joints, the parameter's choice and the family's slices.
// Instantiated for the five scalars (redundant_ik in geometry/CMakeLists.txt).
#include "soma/geometry/serial/redundant_ik.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/self_motion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace soma {

namespace redundant {

inline std::string jointLabel(int k) { return "joint " + std::to_string(k + 1); }

inline void checkJointList(int dof, const std::vector<int>& joints) {
  for (std::size_t a = 0; a < joints.size(); ++a) {
    if (joints[a] < 0 || joints[a] >= dof)
      throw InvalidInput("redundancy parameter: joint " + std::to_string(joints[a] + 1) + " does not exist (the robot has " +
                         std::to_string(dof) + " joints)");
    for (std::size_t b = 0; b < a; ++b)
      if (joints[a] == joints[b]) throw InvalidInput("redundancy parameter: " + jointLabel(joints[a]) + " is locked twice");
  }
}

/// A value inside the joint's range that no design makes special (not 0, not a multiple of π/2).
template <class S> S genericValue(const SerialJoint<S>& j) {
  const S t = S(37) / S(100);
  if (isFinite(j.lower) && isFinite(j.upper)) return j.lower + t * (j.upper - j.lower);
  if (isFinite(j.lower)) return j.lower + t;
  if (isFinite(j.upper)) return j.upper - t;
  return t;
}

}  // namespace redundant

template <class S>
SerialRobot<S> lockJoints(const SerialRobot<S>& robot, const std::vector<int>& joints, const std::vector<S>& values) {
  redundant::checkJointList(robot.dof(), joints);
  if (values.size() != joints.size())
    throw InvalidInput("redundancy parameter: " + std::to_string(joints.size()) + " locked joint(s) but " +
                       std::to_string(values.size()) + " value(s)");
  std::vector<int> lockedAt(robot.dof(), -1);
  for (std::size_t a = 0; a < joints.size(); ++a) {
    const auto& j = robot.joints()[joints[a]];
    if (!isFinite(values[a])) throw InvalidInput("redundancy parameter: " + redundant::jointLabel(joints[a]) + " value is NaN or infinite");
    if (values[a] < j.lower || values[a] > j.upper)
      throw InvalidInput("redundancy parameter: " + redundant::jointLabel(joints[a]) + " value " + toString(values[a], 6) +
                         " is outside its limits [" + toString(j.lower, 6) + ", " + toString(j.upper, 6) + "]");
    lockedAt[joints[a]] = int(a);
  }
  // T(q) = Π_i exp(ξ_i θ_i) · M. Walking the chain, G accumulates the locked joints' constant
  // motions met so far; a free joint after them is Ad(G)ξ (axis R_G a, point G·p), so that
  // Π exp(ξ_i θ_i) = Π_free exp(Ad(G_i)ξ_i θ_i) · G_n with G_n the product of every locked motion.
  SE3<S> G;
  std::vector<SerialJoint<S>> free;
  for (int i = 0; i < robot.dof(); ++i) {
    const auto& j = robot.joints()[i];
    if (lockedAt[i] >= 0) {
      G = G * j.motion(values[lockedAt[i]] + j.offset);
      continue;
    }
    SerialJoint<S> k = j;
    k.axis = G.so3().act(j.axis);
    k.point = G.act(j.point);
    free.push_back(k);
  }
  std::string name = robot.name();
  for (std::size_t a = 0; a < joints.size(); ++a)
    name += (a == 0 ? " with " : ", ") + redundant::jointLabel(joints[a]) + " = " + toString(values[a], 6);
  return SerialRobot<S>::fromPOE(std::move(free), G * robot.home(), name);
}

template <class S>
JointVector<S> insertLockedJoints(const JointVector<S>& reduced, const std::vector<int>& joints, const std::vector<S>& values) {
  const int n = int(reduced.size() + joints.size());
  JointVector<S> q(n);
  std::vector<int> lockedAt(n, -1);
  for (std::size_t a = 0; a < joints.size(); ++a) lockedAt[joints[a]] = int(a);
  int r = 0;
  for (int i = 0; i < n; ++i) q(i) = lockedAt[i] >= 0 ? values[lockedAt[i]] : reduced(r++);
  return q;
}

template <class S> int chooseRedundancyJoint(const SerialRobot<S>& robot) {
  if (robot.dof() < 7)
    throw InvalidInput("redundancy parameter: the robot has " + std::to_string(robot.dof()) + " joints (a redundant arm has 7 or more)");
  if (robot.dof() > 7)
    throw InvalidInput("redundancy parameter: a " + std::to_string(robot.dof()) + "-joint robot needs " + std::to_string(robot.dof() - 6) +
                       " locked joints: name them");
  // Cost rank of the locked robot's class: a closed form (certified, microseconds) before the
  // general-6R eigenproblem; a robot that is not 6R or has a self-motion is no choice at all.
  int best = -1, bestCost = 1 << 20;
  for (int k = 0; k < robot.dof(); ++k) {
    const SerialRobot<S> locked = lockJoints<S>(robot, {k}, {redundant::genericValue(robot.joints()[k])});
    if (!locked.allRevolute() || genericJacobianRank(locked) < 6) continue;
    const IkMethod m = classifyRobot(locked);
    const int cost = m == IkMethod::Pieper ? 0 : 1;
    if (cost <= bestCost) best = k, bestCost = cost;
  }
  if (best < 0)
    throw InvalidInput("redundancy parameter: no joint of " + robot.name() +
                       " leaves a 6R robot of generic Jacobian rank 6 when locked (the arm has a larger self-motion)");
  return best;
}

template <class S>
RedundantIkSolution<S> solveRedundantIk(const SerialRobot<S>& robot, const SE3<S>& pose, const std::vector<std::vector<S>>& values,
                                        const RedundantIkOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (robot.dof() < 7)
    throw InvalidInput("redundant IK: the robot has " + std::to_string(robot.dof()) + " joints (a redundant arm has 7 or more)");
  RedundantIkSolution<S> out;
  out.joints = options.joints.empty() ? std::vector<int>{chooseRedundancyJoint(robot)} : options.joints;
  if (int(out.joints.size()) != robot.dof() - 6)
    throw InvalidInput("redundancy parameter: a " + std::to_string(robot.dof()) + "-joint robot needs " + std::to_string(robot.dof() - 6) +
                       " locked joint(s), " + std::to_string(out.joints.size()) + " given");
  redundant::checkJointList(robot.dof(), out.joints);
  if (values.empty()) throw InvalidInput("redundant IK: no value of the redundancy parameter given");
  for (const auto& v : values) {
    RedundantIkSlice<S> slice;
    slice.values = v;
    const SerialRobot<S> locked = lockJoints<S>(robot, out.joints, v);
    slice.solution = solveIk<S>(locked, pose, options.ik);
    // The postures as the redundant arm's joint vectors; their residuals measured on the arm
    // itself (its length scale), not on the locked robot.
    for (std::size_t p = 0; p < slice.solution.postures.size(); ++p) {
      slice.solution.postures[p] = insertLockedJoints<S>(slice.solution.postures[p], out.joints, v);
      slice.solution.residuals[p] = poseResidual<S>(robot.fk(slice.solution.postures[p]), pose, robot.lengthScale());
    }
    out.slices.push_back(std::move(slice));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

template <class S> std::vector<S> redundancySweepValues(const SerialRobot<S>& robot, int joint, int count) {
  redundant::checkJointList(robot.dof(), {joint});
  if (count < 1) throw InvalidInput("redundancy sweep: the number of values must be at least 1 (got " + std::to_string(count) + ")");
  const auto& j = robot.joints()[joint];
  std::vector<S> v;
  if (isFinite(j.lower) && isFinite(j.upper)) {
    if (count == 1) return {(j.lower + j.upper) / S(2)};
    for (int i = 0; i < count; ++i) v.push_back(j.lower + (j.upper - j.lower) * S(i) / S(count - 1));
    return v;
  }
  if (j.type != JointType::Revolute)
    throw InvalidInput("redundancy sweep: " + redundant::jointLabel(joint) + " is prismatic without finite limits (give the values)");
  // (−π, π]: count values −π + 2π k / count, k = 1..count (π itself last; −π is the same angle).
  for (int i = 1; i <= count; ++i) v.push_back(-pi<S>() + S(2) * pi<S>() * S(i) / S(count));
  return v;
}

#define SOMA_INSTANTIATE_REDUNDANT_IK(S)                                                                      \
  template SerialRobot<S> lockJoints<S>(const SerialRobot<S>&, const std::vector<int>&, const std::vector<S>&); \
  template JointVector<S> insertLockedJoints<S>(const JointVector<S>&, const std::vector<int>&, const std::vector<S>&); \
  template int chooseRedundancyJoint<S>(const SerialRobot<S>&);                                              \
  template RedundantIkSolution<S> solveRedundantIk<S>(const SerialRobot<S>&, const SE3<S>&,                    \
                                                      const std::vector<std::vector<S>>&, const RedundantIkOptions&); \
  template std::vector<S> redundancySweepValues<S>(const SerialRobot<S>&, int, int);

}  // namespace soma
