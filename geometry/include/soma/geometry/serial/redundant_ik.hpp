#pragma once
// Inverse kinematics of a redundant arm (7 or more revolute or prismatic joints): the postures
// reaching a pose form a family of dimension n − 6 (the self-motion, GF §4.5), parametrised here
// by the values of n − 6 chosen joints, the redundancy parameters. With those joints locked, the
// arm is a 6-joint robot (`lockJoints`) that solveIk answers completely: every posture of the
// family for that value, certified where solveIk certifies. A sweep of the first locked joint over
// a list of values traces the family. (The arm angle of SRS arms is not offered: a joint value
// parametrises every arm, SRS or not, such as a Franka-type arm whose wrist axes do not meet.)
#include "soma/geometry/serial/ik.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <vector>

namespace soma {

/// The 6-joint robot obtained by locking joints `joints` (0-based, distinct, ascending not
/// required) of `robot` at `values` (joint values q, offsets and limits as for fk). Joints after a
/// locked one are moved by its constant motion G = exp(ξ_k (v + o_k)): twist Ad(G)ξ_j, home G·M,
/// so that lockJoints(robot).fk(q') = robot.fk(q) with q' = q without the locked entries.
/// Throws InvalidInput for an index out of range or repeated, a NaN value, or a value outside the
/// locked joint's limits.
template <class S>
SerialRobot<S> lockJoints(const SerialRobot<S>& robot, const std::vector<int>& joints, const std::vector<S>& values);

/// The full joint vector of `robot` from a posture q' of lockJoints(robot, joints, values).
template <class S>
JointVector<S> insertLockedJoints(const JointVector<S>& reduced, const std::vector<int>& joints, const std::vector<S>& values);

/// The joints a 7-joint arm is best parametrised by: the one whose locking leaves a robot of
/// generic Jacobian rank 6 with the cheapest certified solver (a closed form before the general 6R
/// eigenproblem), the highest such index on ties: the last joint of a Franka-type arm or of an SRS
/// arm such as a KUKA LBR-type arm (their shoulder axes 1–3 meet, so both lock to a Pieper 6R). Throws InvalidInput for a robot with fewer than 7
/// joints, or when no choice leaves a rank-6 robot.
template <class S> int chooseRedundancyJoint(const SerialRobot<S>& robot);

struct RedundantIkOptions {
  /// The locked joints (0-based), n − 6 of them; empty: chooseRedundancyJoint (7 joints only).
  std::vector<int> joints;
  /// The IK method of each locked 6-joint robot (auto: its class).
  IkOptions ik;
};

/// One value of the redundancy parameters and the postures of the family at it (full joint
/// vectors of the redundant arm; the IkSolution's method, certificate, notes and reason are those
/// of the locked robot's solveIk).
template <class S> struct RedundantIkSlice {
  std::vector<S> values;  ///< the locked joints' values
  IkSolution<S> solution;
};

template <class S> struct RedundantIkSolution {
  std::vector<int> joints;  ///< the locked joints (0-based)
  std::vector<RedundantIkSlice<S>> slices;
  double seconds = 0;
  /// Postures over every slice.
  std::size_t count() const {
    std::size_t n = 0;
    for (const auto& s : slices) n += s.solution.count();
    return n;
  }
};

/// The family of postures of a redundant arm reaching `pose`, at each entry of `values` (each a
/// vector of n − 6 joint values, one per locked joint). Throws InvalidInput for a robot with fewer
/// than 7 joints, a wrong number of locked joints or values, or a value outside the limits.
template <class S>
RedundantIkSolution<S> solveRedundantIk(const SerialRobot<S>& robot, const SE3<S>& pose,
                                        const std::vector<std::vector<S>>& values, const RedundantIkOptions& options = {});

/// `count` values evenly spaced over the joint's range: its limits where they are finite,
/// otherwise (−π, π] for a revolute joint (the end points −π and π are one angle: π only).
/// Throws InvalidInput for count < 1, or a prismatic joint without finite limits.
template <class S> std::vector<S> redundancySweepValues(const SerialRobot<S>& robot, int joint, int count);

#define SOMA_REDUNDANT_IK_EXTERN(S)                                                                             \
  extern template SerialRobot<S> lockJoints<S>(const SerialRobot<S>&, const std::vector<int>&, const std::vector<S>&); \
  extern template JointVector<S> insertLockedJoints<S>(const JointVector<S>&, const std::vector<int>&,               \
                                                       const std::vector<S>&);                                       \
  extern template int chooseRedundancyJoint<S>(const SerialRobot<S>&);                                             \
  extern template RedundantIkSolution<S> solveRedundantIk<S>(const SerialRobot<S>&, const SE3<S>&,                   \
                                                             const std::vector<std::vector<S>>&,                     \
                                                             const RedundantIkOptions&);                             \
  extern template std::vector<S> redundancySweepValues<S>(const SerialRobot<S>&, int, int);
SOMA_FOR_EACH_SCALAR(SOMA_REDUNDANT_IK_EXTERN)
#undef SOMA_REDUNDANT_IK_EXTERN

}  // namespace soma
