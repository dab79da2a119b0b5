#pragma once
// The answer of an inverse-kinematics solver (DESIGN §3): every posture found, each with the
// residual it reached, the wall time, the method, and how many postures the method's class
// expects in general (an upper bound: 2 for a 3R wrist, 4 for a 3R arm, 8 for a Pieper robot,
// 16 for a general 6R). A solver that finds fewer real postures than `expected_count` is not
// wrong — real counts are even and ≤ the complex count — but it must say what it did (`notes`).
#include "soma/algebra/scalar.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace soma {

/// A joint vector of any length (3 for a wrist or arm, 6 for a 6R robot).
template <class S> using JointVector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

template <class S> struct Solution {
  /// Real postures, one joint vector each (radians for revolute joints, lengths for prismatic).
  std::vector<JointVector<S>> postures;
  /// Residual of each posture: for a full pose, max(|R(q) − R*|_F, |t(q) − t*| / scale) where
  /// scale = max(1, robot length scale); the solver documents its own definition.
  std::vector<S> residuals;
  /// Wall-clock seconds spent by the solver.
  double seconds = 0;
  /// Method name as given to `soma ik --method` ("wrist3r", "arm3r", "pieper", "general6r", ...).
  std::string method;
  /// Number of complex postures of the class in general (the bound on the real count).
  int expected_count = 0;
  /// What the solver did beyond the plain path (re-solve in higher precision, degenerate branch,
  /// singular configuration: a continuum of postures of which one representative is returned).
  std::vector<std::string> notes;
  /// True when the pose lies on a singularity with a continuum of postures (e.g. the gimbal
  /// singularity of a wrist): `postures` then holds representatives, not all postures.
  bool continuum = false;

  std::size_t count() const { return postures.size(); }
  /// Largest residual over the postures (0 when there are none).
  S worstResidual() const {
    S w = S(0);
    for (const auto& r : residuals)
      if (r > w) w = r;
    return w;
  }
};

}  // namespace soma
