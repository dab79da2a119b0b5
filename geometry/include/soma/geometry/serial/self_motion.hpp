#pragma once
// Robots that cannot be solved for a finite set of postures: their joint screws span fewer than
// six dimensions at every configuration (every axis through one point, every axis parallel, two
// axes on one line, ...). Such a robot moves on a submanifold of SE(3) of dimension r, its generic
// Jacobian rank, and every pose it reaches has a self-motion of dimension n − r: a continuum of
// postures, not a count. GF §4.5 (the spatial Jacobian), GF §5.2 (the closed forms' singular cases).
#include "soma/geometry/serial/ik_solution.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <vector>

namespace soma {

/// The rank of the robot's spatial Jacobian (linear rows divided by its length scale) at a
/// generic configuration: the largest rank over the home and `samples` seeded random
/// configurations. A deficiency at all of them is a property of the robot, not of a posture (a
/// rank drop on a measure-zero singular set is missed by random samples with probability 1).
template <class S> int genericJacobianRank(const SerialRobot<S>& robot, int samples = 8);

struct SelfMotionOptions {
  int starts = 16;               ///< seeded random starts (the home is tried first)
  unsigned long long seed = 1;   ///< seed of the starts
  int iterations = 200;          ///< damped Gauss–Newton steps per start
};

/// Points on the self-motion of `robot` over `target`: one representative per connected
/// component that was told apart (two points are joined when a joint path between them can be
/// followed on the self-motion), each with its pose residual. Empty when no start reached the
/// pose: `closest` is then the smallest residual reached.
template <class S> struct SelfMotion {
  int rank = 0;                 ///< generic Jacobian rank
  int dimension = 0;            ///< dof − rank: the dimension of the self-motion
  std::vector<JointVector<S>> representatives;
  std::vector<S> residuals;
  int starts = 0;               ///< starts tried
  int converged = 0;            ///< starts that reached the pose
  S closest = S(0);             ///< smallest residual reached (all starts)
  double seconds = 0;
};

/// Damped (Levenberg–Marquardt) Gauss–Newton from the home and seeded random starts in double,
/// each point that reaches the pose polished in S by minimum-norm Newton steps; the points then
/// merged into components (SelfMotion). Throws InvalidInput for a NaN pose.
template <class S>
SelfMotion<S> solveSelfMotion(const SerialRobot<S>& robot, const SE3<S>& target, int rank,
                              const SelfMotionOptions& options = {});

#define SOMA_SELF_MOTION_EXTERN(S)                                                               \
  extern template int genericJacobianRank<S>(const SerialRobot<S>&, int);                        \
  extern template SelfMotion<S> solveSelfMotion<S>(const SerialRobot<S>&, const SE3<S>&, int, \
                                                   const SelfMotionOptions&);
SOMA_FOR_EACH_SCALAR(SOMA_SELF_MOTION_EXTERN)
#undef SOMA_SELF_MOTION_EXTERN

}  // namespace soma
