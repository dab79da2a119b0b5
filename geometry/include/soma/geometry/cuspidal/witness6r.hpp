#pragma once
// Witness search for cuspidal 6R robots (GF §5.2.3, after Wenger: a robot is cuspidal when it can
// change posture without meeting a singularity). Poses are sampled (fixed seed), every IK posture
// is computed (Pieper closed form, or the general-6R eigenproblem), and pairs of postures with the
// same sign of det J are joined with OMPL (RRTConnect in joint space, validity sign·det J ≥ margin
// and the joint limits), then re-checked densely. A found path is a witness that the robot is
// cuspidal; none found after N poses is NOT a proof that it is not (the planner is not complete).
// OMPL stays in geometry/src/cuspidal/witness6r_ompl.cpp. Runs in double.
#include "soma/geometry/serial/serial_robot.hpp"

#include <string>
#include <vector>

namespace soma {

struct Witness6R {
  bool found = false;
  int posesTried = 0, pairsTried = 0, posturesSeen = 0;
  SE3<double> pose;                        ///< the pose reached at both ends
  JointVector<double> start, goal;         ///< two IK postures of it
  std::vector<JointVector<double>> path;   ///< OMPL path, interpolated
  int sign = 0;                            ///< sign of det J along the path
  double margin = 0;                       ///< sign·det J / L³ ≥ margin asked
  double minSignedDet = 0;                 ///< min of sign·det J / L³ over the dense check
  double startResidual = 0, goalResidual = 0;
  std::string ikMethod;
  double seconds = 0;
  std::string note;
};

/// det of the 6 × 6 spatial Jacobian at q divided by L³ (frame-independent, dimensionless).
double jacobianDet6(const SerialRobot<double>& robot, const JointVector<double>& q);

/// Try `poses` random poses (seed): each pose's IK postures, same-sign pairs, OMPL for at most
/// `secondsPerPair` each. Throws InvalidInput unless the robot has 6 revolute joints.
// GF §5.2.3 (cuspidal robots; the 6R case after Parenti-Castelli & Innocenti 1988, Wenger)
Witness6R findWitness6R(const SerialRobot<double>& robot, int poses = 4, double secondsPerPair = 0.5,
                        unsigned long long seed = 20261130);

}  // namespace soma
