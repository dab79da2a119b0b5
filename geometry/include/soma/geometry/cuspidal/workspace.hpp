#pragma once
// Workspace probing of serial robots with OMPL (GF §5.2.3 singularities; issue 9): reachability
// and dexterity maps of the tool point in the section (ρ, z) about axis 1, from OMPL's uniform
// state sampler over the joint space with its limits; and planning between two postures that keeps
// a minimum distance from the singularities (OMPL RRTConnect, validity σ_min ≥ margin). OMPL stays
// in geometry/src/cuspidal/workspace_ompl.cpp (no OMPL type here). Runs in double.
//
// Dexterity: the inverse condition number σ_min/σ_max of the tool point's 3 × n Jacobian for a
// 3-joint arm; for more joints, of the 6 × n Jacobian [ω; (v + ω × p)/L] (L the robot's length
// scale). The distance to the singularities in planning is σ_min of the same matrix divided by L
// for a 3-joint arm (dimensionless), σ_min of the scaled 6 × n matrix otherwise.
#include "soma/geometry/serial/serial_robot.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace soma {

/// (σ_min, σ_max) of the dexterity matrix described above at q (dimensionless).
Eigen::Vector2d dexteritySingularValues(const SerialRobot<double>& robot, const JointVector<double>& q);

struct WorkspaceMaps {
  int samples = 0;
  int nRho = 0, nZ = 0;
  double rhoMax = 0, zMin = 0, zMax = 0;  ///< the grid covers [0, rhoMax] × [zMin, zMax]
  std::vector<int> hits;                  ///< samples per cell, [j * nRho + i] (i along ρ, j along z)
  std::vector<double> dexterity;          ///< best σ_min/σ_max per cell (−1 where no sample fell)
  std::vector<Eigen::Vector2d> points;    ///< (ρ, z) of the first few thousand samples (for figures)
  double meanDexterity = 0;               ///< over all samples
  double reachedFraction = 0;             ///< cells hit / cells in the bounding grid
  double seconds = 0;
};

/// Sample `samples` postures uniformly within the joint limits (OMPL's default sampler; SO(2) for
/// an unlimited revolute joint, an interval otherwise; seeded, reproducible) and bin the tool point
/// into an n × n grid of the section about axis 1. Throws InvalidInput for a prismatic joint without
/// limits, or samples < 1, n < 8.
// GF §5.2.3 (the workspace and its singular boundary)
WorkspaceMaps sampleWorkspace(const SerialRobot<double>& robot, int samples, int n = 120);

struct SafePath {
  bool found = false;
  std::vector<JointVector<double>> path;  ///< from start to goal (OMPL solution, interpolated)
  double margin = 0;                      ///< σ_min ≥ margin asked of every state
  double minSigma = 0;                    ///< min σ_min over a dense check (≤ 0.002 rad apart)
  double startSigma = 0, goalSigma = 0;
  int startSign = 0, goalSign = 0;        ///< sign of det J (square Jacobians; 0 otherwise)
  double seconds = 0;
  std::string note;                       ///< why none was found
};

/// Plan from `start` to `goal` with σ_min ≥ margin along the way, within the joint limits (OMPL
/// RRTConnect, `seconds` of planning at most, then shortcut and interpolated). Throws InvalidInput
/// when start or goal has the wrong size, is outside the limits or violates the margin itself.
// GF §5.2.3 (a posture change that keeps away from det J = 0)
SafePath planAwayFromSingularities(const SerialRobot<double>& robot, const JointVector<double>& start,
                                   const JointVector<double>& goal, double margin, double seconds = 2.0);

}  // namespace soma
