// Figures of the workspace analysis (workspace_figures.hpp), used by `soma workspace` and the GF §5.2.3 studies.
#include "soma/studies/workspace_figures.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

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

/// The (ρ, z) half-plane of a workspace section: the map's cells (white: no sample), the singular
/// boundary; the legend places itself where it hides neither (render::LegendCorner).
render::Plot sectionPlot(const std::string& title, const WorkspaceMaps& m, render::PlotCells cells,
                         const std::vector<std::vector<Eigen::Vector2d>>& boundary) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "ρ = distance from axis 1";
  plot.y.label = "z along axis 1";
  plot.equalAspect = true;
  plot.legend = render::LegendCorner::BottomRight;
  plot.cells.push_back(std::move(cells));
  plot.x.min = 0;
  plot.x.max = m.rhoMax;
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
  const double top = std::max(2, maxHits);  // the colour bar's upper end (a log scale from 1 sample)
  for (int h : m.hits)
    c.cells.push_back(h == 0 ? render::palette::white : render::colorMap(std::log(double(h)) / std::log(top)));
  render::Plot plot = sectionPlot(title, m, std::move(c), boundary);
  plot.colorBar = render::PlotColorBar{"samples per cell", 1, top, render::AxisScale::Log10};
  render::renderPlot(plot, png, 1100, 1000);
}

void plotDexterity(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                   const std::vector<Eigen::Vector2d>& pathTrace, const std::string& title,
                   const std::filesystem::path& png) {
  render::PlotCells c = cellsOf(m);
  // The colour scale runs from 0 to the best value found (σmin/σmax ≤ 1 but rarely near 1), so the
  // map uses the whole ramp instead of its dark end.
  double best = 0;
  for (double d : m.dexterity) best = std::max(best, d);
  if (!(best > 0)) best = 1;
  for (double d : m.dexterity)
    c.cells.push_back(d < 0 ? render::palette::white : render::colorMap(std::clamp(d / best, 0.0, 1.0)));
  render::Plot plot = sectionPlot(title, m, std::move(c), boundary);
  if (!pathTrace.empty()) {
    std::vector<double> xs, ys;
    for (const auto& p : pathTrace) xs.push_back(p(0)), ys.push_back(p(1));
    auto& s = plot.add("plan (tool point)", xs, ys, render::palette::black);
    s.width = 3;
  }
  plot.colorBar = render::PlotColorBar{"best σmin/σmax", 0, best};
  render::renderPlot(plot, png, 1100, 1000);
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
  render::renderPlot(plot, png, 1100, 700);
}

}  // namespace soma::studies
