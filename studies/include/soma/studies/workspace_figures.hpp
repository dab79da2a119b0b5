#pragma once
// Figures of the workspace analysis (analyseWorkspace, soma/geometry/cuspidal/workspace_analysis.hpp):
// reachability and dexterity maps (with colour bars) and the singular boundary, σmin along a plan.
// Each writes `png` as PNG, or as SVG when its extension is ".svg" (render::renderPlot).
#include "soma/geometry/cuspidal/workspace_analysis.hpp"

#include <filesystem>
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

}  // namespace soma::studies
