#pragma once
// `soma workspace ROBOT.json [--samples N] [--grid N] [--png FILE] [--from Q --to Q [--margin M]
// [--seconds T]] [--json]` (issue 9, GF §5.2.3): reachability and dexterity maps of the tool point
// in the section (ρ, z) about axis 1 from OMPL's state sampler within the joint limits; for a 3R
// arm the workspace boundary from the singular curves (images of det J = 0); with --from/--to a
// plan between two postures keeping σ_min ≥ margin (OMPL RRTConnect). --png FILE writes the
// reachability map to FILE, the dexterity map to STEM_dexterity.png and, with a plan,
// σ_min along the path to STEM_path.png. Bad input → InvalidInput (the caller exits 2).
#include "soma/geometry/cuspidal/workspace_analysis.hpp"

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace soma::studies {

void plotReachability(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                      const std::string& title, const std::filesystem::path& png);
void plotDexterity(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                   const std::vector<Eigen::Vector2d>& pathTrace, const std::string& title,
                   const std::filesystem::path& png);
void plotPathSigma(const SerialRobot<double>& robot, const SafePath& p, const std::string& title,
                   const std::filesystem::path& png);

/// The command line's options (the analysis takes WorkspaceOptions, workspace_analysis.hpp).
struct WorkspaceCommandOptions {
  int samples = 200000;
  int grid = 120;
  std::string png;
  std::string from, to;
  double margin = 0.05;
  double seconds = 2.0;
  bool json = false;
};

int workspaceCommand(const std::filesystem::path& robot, const WorkspaceCommandOptions& o, std::ostream& out);

}  // namespace soma::studies
