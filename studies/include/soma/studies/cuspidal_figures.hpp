#pragma once
// Figures of the cuspidality analysis (analyseCuspidality, soma/geometry/cuspidal/cuspidality.hpp):
// the joint space, the workspace section, the witness path, and the cusp-count map. Each writes
// `png` as PNG, or as SVG when its extension is ".svg" (render::renderPlot).
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/parameter_map.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace soma::studies {

/// Figures: joint space (aspects coloured, singular curves, cusp postures), the workspace section
/// (singular images and cusp points), the witness path in joint space.
void plotJointSpace(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png);
void plotSection(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png);
void plotWitness(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png);
/// A 6R witness: the six joint angles along the path (against the fraction of the path) and
/// log10(sign·det J / L³) along it (its minimum said in the legend).
void plotWitness6R(const SerialRobot<double>& robot, const Witness6R& w, const std::string& title,
                   const std::filesystem::path& png);

/// The cusp-count map as coloured cells (one colour per count, legend swatches), optional
/// check points (x, y, traced count) marked on top.
struct MapCheckPoint {
  double x = 0, y = 0;
  int algebraic = 0, traced = 0;
};
void plotCuspMap(const CuspMap& m, const std::string& title, const std::filesystem::path& png,
                 const std::vector<MapCheckPoint>& checks = {});

}  // namespace soma::studies
