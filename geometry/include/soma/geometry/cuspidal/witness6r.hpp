#pragma once
// Witness search for cuspidal 6R robots (GF §5.2.3, after Wenger: a robot is cuspidal when it can
// change posture without meeting a singularity). Poses are sampled (fixed seed), every IK posture
// is computed by solveIk (ik.hpp: the closed forms, or the general-6R eigenproblem on the robot
// rewritten in standard DH with base and tool transforms — POE, MDH and URDF robots as given), and
// pairs of postures with the same sign of det J are joined first by the straight joint path (the
// shortest arc of every unlimited joint), then with OMPL (RRTConnect in joint space, validity
// sign·det J ≥ margin and the joint limits), margin = ¼ of the smaller |det J| of the pair. A
// candidate is re-checked densely (≤ 0.002 rad between points): sign·det J ≥ margin along a
// straight path, ≥ margin / 2 along an OMPL path. The margin is what makes the check sound in
// practice: positivity at sample points alone is fooled by an even-order zero of det J (two of its
// factors vanishing at one point, as on the straight path between mirror postures of a PUMA). A found path is a witness that the robot is cuspidal; none found is NOT a proof that
// it is not (the planner is not complete). OMPL stays in geometry/src/cuspidal/witness6r_ompl.cpp.
// Runs in double.
#include "soma/geometry/serial/serial_robot.hpp"

#include <functional>
#include <string>
#include <vector>

namespace soma {

/// What the search has done so far (for progress lines).
struct Witness6RProgress {
  int posesTried = 0, pairsTried = 0, posturesSeen = 0;
  double seconds = 0;
};

struct Witness6ROptions {
  /// Poses to try at most (fixed seed); the budget may stop the search earlier.
  int poses = 4;
  /// OMPL RRTConnect seconds per same-sign posture pair (after the straight path fails).
  double secondsPerPair = 0.5;
  /// Total seconds for the whole search (0: no limit). Checked before every pose and pair; a
  /// pair's OMPL time is cut to what is left.
  double budget = 0;
  unsigned long long seed = 20261130;
  /// Called after every pose (and at most once a second between pairs).
  std::function<void(const Witness6RProgress&)> progress;
};

struct Witness6R {
  bool found = false;
  int posesTried = 0, pairsTried = 0, posturesSeen = 0;
  int straightTried = 0;                   ///< pairs whose straight joint path was checked
  bool budgetExhausted = false;            ///< the budget stopped the search
  SE3<double> pose;                        ///< the pose reached at both ends
  JointVector<double> start, goal;         ///< two IK postures of it
  std::vector<JointVector<double>> path;   ///< the witness path (straight or OMPL, interpolated)
  std::string planner;                     ///< "straight joint path", "OMPL RRTConnect" or "decomposition"
  int sign = 0;                            ///< sign of det J along the path
  double margin = 0;                       ///< sign·det J / L³ ≥ margin asked of the path
  double minSignedDet = 0;                 ///< min of sign·det J / L³ over the dense check
  double startResidual = 0, goalResidual = 0;
  std::string ikMethod;
  double seconds = 0;
  std::string note;
};

/// det of the 6 × 6 spatial Jacobian at q divided by L³ (frame-independent, dimensionless).
double jacobianDet6(const SerialRobot<double>& robot, const JointVector<double>& q);

/// Sample poses, solve every posture, try same-sign pairs (straight path, then OMPL) until a
/// witness is found, `poses` poses are done or the budget is spent. Throws InvalidInput unless
/// the robot has 6 revolute joints, or for poses < 1, secondsPerPair ≤ 0 or budget < 0.
// GF §5.2.3 (cuspidal robots; the 6R case after Parenti-Castelli & Innocenti 1988, Wenger)
Witness6R findWitness6R(const SerialRobot<double>& robot, const Witness6ROptions& options = {});

}  // namespace soma
