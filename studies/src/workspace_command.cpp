#include "soma/studies/workspace_command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/geometry/cuspidal/workspace_analysis.hpp"
#include "soma/render/plot.hpp"
#include "soma/studies/robot_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

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

std::string fmtNum(double v) { return fmt::format("{:.6g}", v); }

}  // namespace

void plotReachability(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                      const std::string& title, const std::filesystem::path& png) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "ρ = distance from axis 1";
  plot.y.label = "z along axis 1";
  plot.equalAspect = true;
  plot.legend = render::LegendCorner::BottomRight;  // the section's outer arc leaves that corner free
  render::PlotCells c = cellsOf(m);
  int maxHits = 1;
  for (int h : m.hits) maxHits = std::max(maxHits, h);
  for (int h : m.hits)
    c.cells.push_back(h == 0 ? render::palette::white
                             : render::colorMap(std::log1p(double(h)) / std::log1p(double(maxHits))));
  plot.cells.push_back(c);
  plot.x.min = 0;
  plot.x.max = 1.3 * m.rhoMax;  // room for the legend right of the outer arc
  plot.y.min = m.zMin;
  plot.y.max = m.zMax;
  addBoundary(plot, boundary);
  plot.legendSwatches.emplace_back("1 sample", render::colorMap(0.0));
  plot.legendSwatches.emplace_back(fmt::format("{} (log scale)", maxHits), render::colorMap(1.0));
  render::renderPlotPng(plot, png, 1000, 1000);
}

void plotDexterity(const WorkspaceMaps& m, const std::vector<std::vector<Eigen::Vector2d>>& boundary,
                   const std::vector<Eigen::Vector2d>& pathTrace, const std::string& title,
                   const std::filesystem::path& png) {
  render::Plot plot;
  plot.title = title;
  plot.x.label = "ρ = distance from axis 1";
  plot.y.label = "z along axis 1";
  plot.equalAspect = true;
  plot.legend = render::LegendCorner::BottomRight;  // the section's outer arc leaves that corner free
  render::PlotCells c = cellsOf(m);
  for (double d : m.dexterity) c.cells.push_back(d < 0 ? render::palette::white : render::colorMap(std::clamp(d, 0.0, 1.0)));
  plot.cells.push_back(c);
  plot.x.min = 0;
  plot.x.max = 1.3 * m.rhoMax;  // room for the legend right of the outer arc
  plot.y.min = m.zMin;
  plot.y.max = m.zMax;
  addBoundary(plot, boundary);
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

int workspaceCommand(const std::filesystem::path& file, const WorkspaceCommandOptions& o, std::ostream& out) {
  const RobotFile<double> rf = readRobot<double>(file);
  const SerialRobot<double>& robot = rf.robot;
  if (o.from.empty() != o.to.empty()) throw InvalidInput("workspace: --from and --to go together");
  WorkspaceOptions options;
  options.samples = o.samples;
  options.grid = o.grid;
  options.margin = o.margin;
  options.seconds = o.seconds;
  if (!o.from.empty()) {
    auto joints = [&](const std::string& text, const char* flag) {
      try {
        return parseJoints<double>(text, rf);
      } catch (const InvalidInput& e) {
        throw InvalidInput(std::string("workspace ") + flag + " '" + text + "': " + e.what());
      }
    };
    options.plan = std::make_pair(joints(o.from, "--from"), joints(o.to, "--to"));
  }
  const WorkspaceAnalysis a = analyseWorkspace(robot, options);
  const WorkspaceMaps& m = a.maps;
  const auto& boundary = a.boundary;
  const std::optional<SafePath>& plan = a.plan;
  const std::vector<Eigen::Vector2d>& trace = a.planTrace;
  const std::string name = robot.name().empty() ? file.stem().string() : robot.name();
  if (!o.png.empty()) {
    const std::filesystem::path p(o.png);
    const std::filesystem::path stem = p.parent_path() / p.stem();
    plotReachability(m, boundary, name + ": reachability (OMPL samples per cell)", p);
    plotDexterity(m, boundary, trace, name + ": dexterity (best inverse condition number)",
                  stem.string() + "_dexterity.png");
    if (plan && plan->found) plotPathSigma(robot, *plan, name + ": distance from the singularities along the plan",
                                           stem.string() + "_path.png");
  }
  const double unit = rf.degrees ? 180.0 / 3.14159265358979323846 : 1.0;
  auto jointsOut = [&](const JointVector<double>& q) {
    std::vector<double> v;
    for (int i = 0; i < q.size(); ++i) v.push_back(q(i) * (robot.joints()[i].type == JointType::Revolute ? unit : 1.0));
    return v;
  };
  if (o.json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["samples"] = m.samples;
    j["grid"] = {m.nRho, m.nZ};
    j["rho_max"] = m.rhoMax;
    j["z_range"] = {m.zMin, m.zMax};
    j["reached_fraction"] = m.reachedFraction;
    j["mean_dexterity"] = m.meanDexterity;
    j["boundary_curves"] = boundary.size();
    j["sampler"] = "OMPL default state sampler (uniform within the joint limits)";
    j["seconds"] = m.seconds;
    if (plan) {
      nlohmann::json p;
      p["found"] = plan->found;
      p["margin"] = plan->margin;
      p["start_sigma"] = plan->startSigma;
      p["goal_sigma"] = plan->goalSigma;
      p["start_det_sign"] = plan->startSign;
      p["goal_det_sign"] = plan->goalSign;
      if (plan->found) {
        p["min_sigma"] = plan->minSigma;
        nlohmann::json path = nlohmann::json::array();
        for (const auto& q : plan->path) path.push_back(jointsOut(q));
        p["path"] = path;
        p["planner"] = "OMPL RRTConnect";
      } else {
        p["note"] = plan->note;
      }
      p["seconds"] = plan->seconds;
      j["plan"] = p;
    }
    out << j.dump(2) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} ({} joints)\n", name, robot.dof());
  out << fmt::format("samples: {} postures within the joint limits (OMPL state sampler), {:.3f} s\n", m.samples, m.seconds);
  out << fmt::format("section about axis 1: ρ ≤ {}, z ∈ [{}, {}]; {} × {} grid, {:.1f} % of its cells reached\n",
                     fmtNum(m.rhoMax), fmtNum(m.zMin), fmtNum(m.zMax), m.nRho, m.nZ, 100 * m.reachedFraction);
  out << fmt::format("dexterity (σmin/σmax): mean {}\n", fmtNum(m.meanDexterity));
  if (!boundary.empty())
    out << fmt::format("workspace boundary: {} singular curve image(s) in (ρ, z)\n", boundary.size());
  else
    out << "workspace boundary: singular curves traced for 3R arms only\n";
  if (plan) {
    out << fmt::format("plan: σmin start {} goal {}, margin {}\n", fmtNum(plan->startSigma), fmtNum(plan->goalSigma),
                       fmtNum(plan->margin));
    if (plan->found)
      out << fmt::format("path found: {} states (OMPL RRTConnect), min σmin {} ≥ margin over a dense check\n",
                         plan->path.size(), fmtNum(plan->minSigma));
    else
      out << "no path: " << plan->note << "\n";
  }
  return 0;
}

}  // namespace soma::studies
