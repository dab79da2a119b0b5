#pragma once
// The inverse kinematics of a serial robot, one entry point for every method (DESIGN §3):
//   auto       the class of the robot (classifyRobot): wrist3r, arm3r, pieper or general6r;
//   wrist3r, arm3r, pieper   the closed forms (closed_form_ik.hpp; GF §5.1, §5.2, §10.3);
//   general6r  the Raghavan–Roth / Manocha–Canny eigenproblem (general_6r.hpp; GF §11.5), in the
//              working scalar, completed numerically when its answer may be short;
//   ceres, nlopt   multi-start searches in double, each posture Newton-polished in the working
//              scalar (numeric_polish.hpp).
// A robot that is not in standard DH form (POE, URDF, modified DH) is rewritten in standard DH
// for the general-6R methods (standard_dh.hpp). The robot's joint limits apply to every method.
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/ik_solution.hpp"
#include "soma/geometry/serial/self_motion.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <string>

namespace soma {

struct IkOptions {
  /// Auto picks the class of the robot (classifyRobot); Ceres and Nlopt are general-6R methods.
  IkMethod method = IkMethod::Auto;
  /// general6r: when the eigenproblem's answer may be short (not 16 complex solutions, an odd
  /// real count, or the solver says so), add the postures a Ceres multi-start search finds.
  bool complete = true;
  /// Random starts of that completion search (in double).
  int completionStarts = 128;
};

/// The answer of solveIk: Solution<S> plus whether its count is certified complete.
template <class S> struct IkSolution : Solution<S> {
  /// True for the closed forms and for an eigenproblem answer that is complete (16 complex
  /// solutions, nothing added numerically); false for ceres and nlopt and for an answer that a
  /// numerical search completed (no certificate that every posture was found).
  bool certified = false;
  /// general6r: complex solutions of the eigenproblem (−1 for the other methods).
  int complex_count = -1;
  /// general6r: the scalar the eigenproblem was finally solved in (empty for the other methods).
  std::string solved_in;
  /// general6r: the elimination used ("theta3 last", or another joint on a relabelled or
  /// reversed loop; General6RSolution::elimination), empty for the other methods.
  std::string elimination;
  /// Why there is no posture (empty when there is one): "out of reach: …" or "joint limits: …".
  std::string reason;
  /// A robot whose joint screws span fewer than 6 dimensions at every configuration (every axis
  /// through one point, every axis parallel, two axes on one line): the dimension of the
  /// self-motion over every pose it reaches (0 for a robot with finitely many postures); its
  /// postures are then representatives, one per component told apart (self_motion.hpp), and
  /// `continuum` is true, `expected_count` 0 (there is no finite count).
  int self_motion_dimension = 0;
  /// The robot's generic Jacobian rank (genericJacobianRank; 6 for a 6R robot that is not degenerate).
  int generic_rank = -1;
};

/// Every real posture of `robot` reaching `pose`. A 6R robot of generic Jacobian rank below 6 is
/// answered by its self-motion whatever the method (self_motion.hpp). (the tool pose in the base frame), each with its
/// residual (Solution<S>), postures outside the robot's joint limits dropped (a note says how
/// many for the general-6R methods; the closed forms drop them as they solve). Throws InvalidInput
/// when the method does not apply to the robot (e.g. general6r for a robot that is not 6R).
template <class S> IkSolution<S> solveIk(const SerialRobot<S>& robot, const SE3<S>& pose, const IkOptions& options = {});

#define SOMA_SOLVE_IK_EXTERN(S) \
  extern template IkSolution<S> solveIk<S>(const SerialRobot<S>&, const SE3<S>&, const IkOptions&);
SOMA_FOR_EACH_SCALAR(SOMA_SOLVE_IK_EXTERN)
#undef SOMA_SOLVE_IK_EXTERN

}  // namespace soma
