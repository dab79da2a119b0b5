// Figures of the workspace analysis (workspace_figures.hpp), used by `soma workspace` and the GF §5.2.3 studies.
#include "soma/studies/workspace_figures.hpp"

#include "soma/render/plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace soma::studies {

namespace {

void addBoundary(render::Plot& plot, const std::vector<std::vector<Eigen::Vector2d>>& boundary) {
  bool first = true;
  for (const auto& b : boundary) {
    std::vector<double> xs, ys;
    for (const auto& p : b) xs.push_back(p(0)), ys.push_back(p(1));
    auto& s = plot.add(first ? "det J = 0 (image)" : "", xs, ys, render::palette::vermillion);
    s.width = 2.5;
    first = false;
  }
}

render::PlotCells cellsOf(const WorkspaceMaps& m) {
  render::PlotCells c;
  c.x0 = 0;
  c.x1 = m.rhoMax;
  c.y0 = m.zMin;
  c.y1 = m.zMax;
  c.nx = m.nRho;
  c.ny = m.nZ;
  return c;
}

/// The (ρ, z) half-plane of a workspace section: the map's cells, the singular boundary, the legend
/// where the outer arc leaves room.
render::Plot sectionPlot(const std::string& title, const WorkspaceMaps& m, render::PlotCells cells,
                         const std::vector<std::vector<Eigen::Vector2d>>& boundary) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "ρ = distance from axis 1";
  plot.y.label = "z along axis 1";
  plot.equalAspect = true;
  plot.legend = render::LegendCorner::BottomRight;  // the section's outer arc leaves that corner free
  plot.cells.push_back(std::move(cells));
  plot.x.min = 0;
  plot.x.max = 1.3 * m.rhoMax;  // room for the legend right of the outer arc
  plot.y.min = m.zMin;
  plot.y.max = m.zMax;
  addBoundary(plot, boundary);
  return plot;
}

}  // namespace

void plotReachability(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                      const std::string& title, const std::filesystem::path& png) {
  render::PlotCells c = cellsOf(m);
  int maxHits = 1;
  for (int h : m.hits) maxHits = std::max(maxHits, h);
  for (int h : m.hits)
    c.cells.push_back(h == 0 ? render::palette::white
                             : render::colorMap(std::log1p(double(h)) / std::log1p(double(maxHits))));
  render::Plot plot = sectionPlot(title, m, std::move(c), boundary);
  plot.legendSwatches.emplace_back("1 sample", render::colorMap(0.0));
  plot.legendSwatches.emplace_back(fmt::format("{} (log scale)", maxHits), render::colorMap(1.0));
  render::renderPlotPng(plot, png, 1000, 1000);
}

void plotDexterity(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                   const std::vector<Eigen::Vector2d>& pathTrace, const std::string& title,
                   const std::filesystem::path& png) {
  render::PlotCells c = cellsOf(m);
  for (double d : m.dexterity) c.cells.push_back(d < 0 ? render::palette::white : render::colorMap(std::clamp(d, 0.0, 1.0)));
  render::Plot plot = sectionPlot(title, m, std::move(c), boundary);
  if (!pathTrace.empty()) {
    std::vector<double> xs, ys;
    for (const auto& p : pathTrace) xs.push_back(p(0)), ys.push_back(p(1));
    auto& s = plot.add("plan (tool point)", xs, ys, render::palette::black);
    s.width = 3;
  }
  plot.legendSwatches.emplace_back("σmin/σmax 0", render::colorMap(0.0));
  plot.legendSwatches.emplace_back("0.5", render::colorMap(0.5));
  plot.legendSwatches.emplace_back("1", render::colorMap(1.0));
  render::renderPlotPng(plot, png, 1000, 1000);
}

void plotPathSigma(const SerialRobot<double>& robot, const SafePath& p, const std::string& title,
                   const std::filesystem::path& png) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "path state";
  plot.y.label = "σmin (distance from the singularities)";
  plot.legend = render::LegendCorner::BottomRight;
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < p.path.size(); ++k) {
    xs.push_back(double(k));
    ys.push_back(dexteritySingularValues(robot, p.path[k])(0));
  }
  if (xs.size() < 2) return;
  plot.add("σmin along the OMPL path", xs, ys, render::palette::blue).width = 3;
  auto& m = plot.add("margin asked", {xs.front(), xs.back()}, {p.margin, p.margin}, render::palette::vermillion);
  m.dashed = true;
  m.width = 2.5;
  plot.y.min = 0;
  render::renderPlotPng(plot, png, 1100, 700);
}

}  // namespace soma::studies
