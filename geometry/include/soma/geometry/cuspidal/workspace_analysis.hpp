#pragma once
// The workspace of a serial robot in one call (issue 9, GF §5.2.3; DESIGN §3): the reachability
// and dexterity maps of the tool point in the section (ρ, z) about axis 1 from OMPL's state
// sampler (workspace.hpp), for a 3R arm the workspace boundary from the singular curves (images of
// det J = 0, singular_set.hpp), and optionally a plan between two postures keeping σ_min ≥ margin
// with the tool point traced along it. Runs in double.
#include "soma/geometry/cuspidal/workspace.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace soma {

/// The 3R singular curves' images in (ρ, z), each closed curve closed (its first point repeated);
/// empty unless the robot is a 3R arm. GF §5.2.3
std::vector<std::vector<Eigen::Vector2d>> singularImages(const SerialRobot<double>& robot);

struct WorkspaceOptions {
  int samples = 200000;  ///< postures sampled within the joint limits
  int grid = 120;        ///< cells per side of the (ρ, z) maps
  /// A plan from .first to .second (joint vectors in radians / lengths), when given.
  std::optional<std::pair<JointVector<double>, JointVector<double>>> plan;
  double margin = 0.05;  ///< σ_min ≥ margin along the plan (dimensionless)
  double seconds = 2.0;  ///< planning time limit
};

struct WorkspaceAnalysis {
  WorkspaceMaps maps;
  std::vector<std::vector<Eigen::Vector2d>> boundary;  ///< singularImages (3R only)
  std::optional<SafePath> plan;                        ///< when options.plan was given
  /// The tool point in (ρ, z) along a plan found, 8 points per path segment (for figures).
  std::vector<Eigen::Vector2d> planTrace;
};

/// Throws InvalidInput as sampleWorkspace and planAwayFromSingularities do.
// GF §5.2.3 (the workspace and its singular boundary)
WorkspaceAnalysis analyseWorkspace(const SerialRobot<double>& robot, const WorkspaceOptions& options = {});

}  // namespace soma
