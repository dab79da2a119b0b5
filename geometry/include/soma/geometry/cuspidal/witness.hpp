#pragma once
// A witness of cuspidality (GF §5.2.3, Fig. 5.2: "the robot can change posture without passing
// through a singularity by circling a cusp"): one target point, two of its IK postures, and a
// joint-space path between them along which det J keeps its sign — planned with OMPL
// (RRTConnect on SO(2)³, validity: sign(det J) fixed and |det J| ≥ margin), then checked densely
// with a certificate: between consecutive checked points det J cannot vanish because its value
// exceeds a Lipschitz bound of the trigonometric series times the half-spacing. OMPL stays in
// geometry/src/cuspidal/witness_ompl.cpp (no OMPL type in this header). Runs in double.
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace soma {

struct WitnessPath {
  bool found = false;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< world point reached at both ends
  double rho = 0, z = 0;                             ///< its workspace section
  JointVector<double> start, goal;                   ///< two IK postures of the target
  std::vector<Eigen::Vector3d> path;                 ///< joint states (OMPL solution, interpolated)
  int sign = 0;                                      ///< sign of det J along the path
  double margin = 0;                                 ///< |det J| ≥ margin asked of the planner
  double minSignedDet = 0;                           ///< min of sign·det J over the dense check
  bool certified = false;                            ///< no root of det J between checked points
  int checkedPoints = 0;
  double startResidual = 0, goalResidual = 0;        ///< |p(q) − target| / L of the two postures
  int aspectStart = -1, aspectGoal = -1;             ///< grid aspect labels (AspectMap)
  int targetsTried = 0, pairsTried = 0;
  double seconds = 0;
  std::string note;                                  ///< why none was found
};

/// Look for a witness near each cusp point: targets inside the 4-posture side of the cusp, every
/// pair of postures with the same sign of det J, OMPL RRTConnect for at most `secondsPerPair`.
// GF §5.2.3, GF-5.2.3-cuspidal-posture-change
WitnessPath findWitness(const SerialRobot<double>& robot, const CuspAnalysis<double>& cusps,
                        const DetJSeries& dj, const AspectMap& aspectMap, double secondsPerPair = 1.0);

/// Dense check of a path of joint states (shortest arcs between states): min of sign·det J over
/// points at most `spacing` apart, and whether a Lipschitz bound certifies no root in between.
struct PathCheck {
  double minSignedDet = 0;
  bool certified = false;
  int points = 0;
};
PathCheck checkPathSign(const DetJSeries& dj, const std::vector<Eigen::Vector3d>& path, int sign,
                        double spacing = 1e-3);

}  // namespace soma
