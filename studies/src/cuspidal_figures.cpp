// Figures of the cuspidality analysis (cuspidal_figures.hpp), used by `soma cuspidal` and the GF §5.2.3 studies.
#include "soma/studies/cuspidal_figures.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace soma::studies {

namespace {

constexpr double kPi = 3.14159265358979323846;

render::Color aspectColor(int label, int sign) {
  // Light tints: positive det J in blues/greens, negative in oranges/pinks.
  static const render::Color pos[] = {render::Color::hex(0xB9D7EA), render::Color::hex(0xBFE3D3),
                                      render::Color::hex(0xD6E9F5), render::Color::hex(0xA8D5C2)};
  static const render::Color neg[] = {render::Color::hex(0xF6D5B3), render::Color::hex(0xEBC6DA),
                                      render::Color::hex(0xF9E6C8), render::Color::hex(0xF0B9A8)};
  return sign > 0 ? pos[label % 4] : neg[label % 4];
}

/// Split an unwrapped joint polyline into pieces inside [−π, π)² for drawing.
void addJointCurve(render::Plot& plot, const std::vector<Eigen::Vector2d>& pts, render::Color c,
                   const std::string& name, double width) {
  std::vector<double> xs, ys;
  auto flush = [&](const std::string& nm) {
    if (xs.size() > 1) {
      auto& s = plot.add(nm, xs, ys, c);
      s.width = width;
    }
    xs.clear();
    ys.clear();
  };
  bool first = true;
  Eigen::Vector2d prev(0, 0);
  for (const auto& p : pts) {
    const Eigen::Vector2d w(std::remainder(p(0), 2 * kPi), std::remainder(p(1), 2 * kPi));
    if (!first && (std::abs(w(0) - prev(0)) > kPi || std::abs(w(1) - prev(1)) > kPi)) flush(first ? name : "");
    xs.push_back(w(0));
    ys.push_back(w(1));
    prev = w;
    first = false;
  }
  flush(name);
}

void addAspectCells(render::Plot& plot, const CuspidalAnalysis& r) {
  const AspectMap& m = r.aspectMap;
  render::PlotCells cells;
  cells.x0 = -kPi;
  cells.x1 = kPi;
  cells.y0 = -kPi;
  cells.y1 = kPi;
  cells.nx = cells.ny = m.n;
  cells.cells.resize(std::size_t(m.n) * m.n);
  for (int j = 0; j < m.n; ++j)
    for (int i = 0; i < m.n; ++i) {
      const int lab = m.label[std::size_t(j) * m.n + i];
      cells.cells[std::size_t(j) * m.n + i] = lab < 0 ? render::palette::white : aspectColor(lab, m.sign[lab]);
    }
  plot.cells.push_back(cells);
}

render::PlotAxis angleAxis(const std::string& label) {
  render::PlotAxis a;
  a.label = label;
  a.min = -kPi;
  a.max = kPi;
  a.ticks = {-3, -2, -1, 0, 1, 2, 3};
  return a;
}

/// The (θ2, θ3) plane: the aspect cells and the singular curves det J = 0 in `colour`.
render::Plot aspectPlot(const CuspidalAnalysis& r, const std::string& title, render::Color colour, double width) {
  render::Plot plot;
  plot.title = title;
  plot.x = angleAxis("θ2 (rad)");
  plot.y = angleAxis("θ3 (rad)");
  plot.equalAspect = true;
  plot.grid = false;
  plot.legend = render::LegendCorner::BottomLeft;
  addAspectCells(plot, r);
  bool first = true;
  for (const auto& b : r.branches) {
    addJointCurve(plot, b.joints, colour, first ? "det J = 0" : "", width);
    first = false;
  }
  return plot;
}

}  // namespace

void plotJointSpace(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png) {
  render::Plot plot = aspectPlot(r, title, render::palette::black, 3);
  if (!r.cusps.cusps.empty()) {
    std::vector<double> xs, ys;
    for (const auto& c : r.cusps.cusps) {
      xs.push_back(std::remainder(c.posture(1), 2 * kPi));
      ys.push_back(std::remainder(c.posture(2), 2 * kPi));
    }
    auto& s = plot.add("cusp postures (triple roots)", xs, ys, render::palette::vermillion);
    s.line = false;
    s.markers = true;
    s.markerRadius = 9;
  }
  for (int a = 0; a < r.aspectMap.count(); ++a)
    plot.legendSwatches.emplace_back(fmt::format("aspect {} (det J {})", a + 1, r.aspectMap.sign[a] > 0 ? "> 0" : "< 0"),
                                     aspectColor(a, r.aspectMap.sign[a]));
  render::renderPlot(plot, png, 1100, 1000);
}

void plotSection(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "ρ = √(x² + y²)";
  plot.y.label = "z";
  plot.equalAspect = true;
  // Legend top right, in a strip to the right of the section (the curves fill the other corners).
  plot.legend = render::LegendCorner::TopRight;
  {
    double rmax = 0;
    for (const auto& b : r.branches)
      for (const auto& s : b.section) rmax = std::max(rmax, s(0));
    plot.x.min = -0.05 * rmax;
    plot.x.max = 1.9 * rmax;
  }
  bool first = true;
  for (const auto& b : r.branches) {
    std::vector<double> xs, ys;
    for (const auto& s : b.section) {
      xs.push_back(s(0));
      ys.push_back(s(1));
    }
    if (b.closed && !xs.empty()) {
      xs.push_back(xs.front());
      ys.push_back(ys.front());
    }
    auto& s = plot.add(first ? "images of det J = 0" : "", xs, ys, render::palette::blue);
    s.width = 3;
    first = false;
  }
  if (!r.cusps.cusps.empty()) {
    std::vector<double> xs, ys;
    for (const auto& c : r.cusps.cusps) {
      xs.push_back(c.rho);
      ys.push_back(c.z);
    }
    auto& s = plot.add(fmt::format("cusp points ({}, algebraic)", r.cusps.cusps.size()), xs, ys,
                       render::palette::vermillion);
    s.line = false;
    s.markers = true;
    s.markerRadius = 9;
  }
  if (!r.reversals.empty()) {
    std::vector<double> xs, ys;
    for (const auto& v : r.reversals) {
      xs.push_back(v(0));
      ys.push_back(v(1));
    }
    auto& s = plot.add(fmt::format("image turns back ({}, traced)", r.reversals.size()), xs, ys,
                       render::palette::black);
    s.line = false;
    s.markers = true;
    s.markerRadius = 4;
  }
  if (r.witness.found) {
    auto& s = plot.add("witness target", {r.witness.rho}, {r.witness.z}, render::palette::bluishGreen);
    s.line = false;
    s.markers = true;
    s.markerRadius = 7;
  }
  render::renderPlot(plot, png, 1100, 1000);
}

void plotWitness(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png) {
  render::Plot plot = aspectPlot(r, title, render::palette::darkGrey, 2);
  const WitnessPath& w = r.witness;
  if (w.found) {
    std::vector<Eigen::Vector2d> pts;
    for (const auto& s : w.path) {
      // Unwrap consecutive states so the polyline follows the shortest arcs OMPL used.
      Eigen::Vector2d p(s(1), s(2));
      if (!pts.empty()) {
        p(0) = pts.back()(0) + std::remainder(p(0) - pts.back()(0), 2 * kPi);
        p(1) = pts.back()(1) + std::remainder(p(1) - pts.back()(1), 2 * kPi);
      }
      pts.push_back(p);
    }
    addJointCurve(plot, pts, render::palette::vermillion, "witness path (OMPL RRTConnect)", 4);
    auto& a = plot.add("start posture", {std::remainder(w.start(1), 2 * kPi)}, {std::remainder(w.start(2), 2 * kPi)},
                       render::palette::bluishGreen);
    a.line = false;
    a.markers = true;
    a.markerRadius = 10;
    auto& b = plot.add("goal posture (same point)", {std::remainder(w.goal(1), 2 * kPi)},
                       {std::remainder(w.goal(2), 2 * kPi)}, render::palette::reddishPurple);
    b.line = false;
    b.markers = true;
    b.markerRadius = 10;
  }
  render::renderPlot(plot, png, 1100, 1000);
}

void plotWitness6R(const SerialRobot<double>& robot, const Witness6R& w, const std::string& title,
                   const std::filesystem::path& png) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "fraction of the path";
  plot.y.label = "joint angle (rad); log10(sign·det J / L³)";
  plot.legend = render::LegendCorner::TopRight;
  if (w.path.size() >= 2) {
    // Unwrapped joint angles, against the cumulated joint-space length.
    std::vector<double> t{0};
    std::vector<JointVector<double>> q{w.path.front()};
    for (std::size_t s = 1; s < w.path.size(); ++s) {
      JointVector<double> d = w.path[s] - w.path[s - 1];
      for (int i = 0; i < d.size(); ++i) d(i) = std::remainder(d(i), 2 * kPi);
      q.push_back(q.back() + d);
      t.push_back(t.back() + d.norm());
    }
    for (double& v : t) v /= std::max(t.back(), 1e-300);
    static const render::Color colours[] = {render::palette::blue,      render::palette::orange,
                                            render::palette::bluishGreen, render::palette::reddishPurple,
                                            render::palette::skyBlue,   render::palette::vermillion};
    for (int i = 0; i < 6; ++i) {
      std::vector<double> ys;
      for (const auto& v : q) ys.push_back(v(i));
      auto& s = plot.add(fmt::format("θ{}", i + 1), t, ys, colours[i]);
      s.width = 2.5;
    }
    // log10 of sign·det J / L³: finite all along (det J never reaches 0), on the angle axis's scale.
    std::vector<double> det;
    for (const auto& v : w.path) det.push_back(std::log10(std::max(w.sign * jacobianDet6(robot, v), 1e-300)));
    auto& s = plot.add(fmt::format("log10(sign·det J / L³), min {:.3g}", std::log10(w.minSignedDet)), t, det,
                       render::palette::black);
    s.width = 3.5;
  }
  render::renderPlotPng(plot, png, 1200, 800);
}

render::Color cuspCountColor(int count) {
  // Discrete classes: 0 light grey, 2 blue, 4 orange, 6 green, 8+ purple; odd counts (an arm on a
  // boundary, where two cusps merge) black.
  if (count <= 0) return render::Color::hex(0xDDDDDD);
  if (count % 2 == 1) return render::palette::black;
  switch (count) {
    case 2: return render::palette::skyBlue;
    case 4: return render::palette::orange;
    case 6: return render::palette::bluishGreen;
    default: return render::palette::reddishPurple;
  }
}

void plotCuspMap(const CuspMap& m, const std::string& title, const std::filesystem::path& png,
                 const std::vector<MapCheckPoint>& checks) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = m.x.name;
  plot.y.label = m.y.name;
  plot.grid = false;
  plot.legend = render::LegendCorner::TopRight;
  const double hx = (m.x.max - m.x.min) / (m.x.n - 1) / 2, hy = (m.y.max - m.y.min) / (m.y.n - 1) / 2;
  render::PlotCells cells;
  cells.x0 = m.x.min - hx;
  cells.x1 = m.x.max + hx;
  cells.y0 = m.y.min - hy;
  cells.y1 = m.y.max + hy;
  cells.nx = m.x.n;
  cells.ny = m.y.n;
  for (int c : m.counts) cells.cells.push_back(cuspCountColor(c));
  const std::vector<int> seen = m.histogram();
  const int maxCount = int(seen.size()) - 1;
  plot.cells.push_back(cells);
  plot.x.min = cells.x0;
  plot.x.max = cells.x1;
  plot.y.min = cells.y0;
  plot.y.max = cells.y1 + 0.36 * (cells.y1 - cells.y0);  // a free strip for the legend
  for (int c = 0; c <= maxCount; ++c)
    if (seen[std::size_t(c)] > 0)
      plot.legendSwatches.emplace_back(fmt::format("{} cusp{} ({} arms{})", c, c == 1 ? "" : "s", seen[std::size_t(c)],
                                                   c % 2 == 1 ? ", on a boundary" : ""),
                                       cuspCountColor(c));
  if (!checks.empty()) {
    std::vector<double> ax, ay, bx, by;
    for (const auto& k : checks) {
      (k.algebraic == k.traced ? ax : bx).push_back(k.x);
      (k.algebraic == k.traced ? ay : by).push_back(k.y);
      render::PlotText t;
      t.x = k.x;
      t.y = k.y;
      t.text = std::to_string(k.traced);
      t.pixelHeight = 22;
      plot.texts.push_back(t);
    }
    if (!ax.empty()) {
      auto& s = plot.add("traced count agrees", ax, ay, render::palette::black);
      s.line = false;
      s.markers = true;
      s.markerRadius = 6;
    }
    if (!bx.empty()) {
      auto& s = plot.add("traced count differs", bx, by, render::palette::vermillion);
      s.line = false;
      s.markers = true;
      s.markerRadius = 8;
    }
  }
  render::renderPlot(plot, png, 1100, 950);
}

}  // namespace soma::studies
