#include "soma/studies/cuspidal_command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/render/plot.hpp"
#include "soma/studies/robot_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

std::string fmtNum(double v) { return fmt::format("{:.6g}", v); }

}  // namespace

void plotJointSpace(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png) {
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
    addJointCurve(plot, b.joints, render::palette::black, first ? "det J = 0" : "", 3);
    first = false;
  }
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
  render::renderPlotPng(plot, png, 1100, 1000);
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
  render::renderPlotPng(plot, png, 1100, 1000);
}

void plotWitness(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png) {
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
    addJointCurve(plot, b.joints, render::palette::darkGrey, first ? "det J = 0" : "", 2);
    first = false;
  }
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
  render::renderPlotPng(plot, png, 1100, 1000);
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
  render::renderPlotPng(plot, png, 1100, 950);
}

int cuspidalMapCommand(const std::filesystem::path& file, const std::string& map, int threads, bool json,
                       const std::string& png, std::ostream& out) {
  const std::size_t comma = map.find(',');
  if (comma == std::string::npos)
    throw InvalidInput("--map '" + map + "': expected two axes X,Y, e.g. a2:0.5:4:100,a3:0.2:3:100");
  const ParameterAxis x = parseParameterAxis(map.substr(0, comma)), y = parseParameterAxis(map.substr(comma + 1));
  const RobotFile<double> rf = readRobot<double>(file);
  const CuspMap m = cuspMap(rf.robot, x, y, threads);
  const std::vector<int> hist = m.histogram();
  const std::string name = rf.robot.name().empty() ? file.stem().string() : rf.robot.name();
  if (!png.empty())
    plotCuspMap(m, fmt::format("number of cusp points over ({}, {})", x.name, y.name), png);
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = rf.robot.name();
    j["x"] = {{"name", x.name}, {"min", x.min}, {"max", x.max}, {"n", x.n}};
    j["y"] = {{"name", y.name}, {"min", y.min}, {"max", y.max}, {"n", y.n}};
    j["counts"] = m.counts;
    nlohmann::json h = nlohmann::json::object();
    for (std::size_t c = 0; c < hist.size(); ++c)
      if (hist[c] > 0) h[std::to_string(c)] = hist[c];
    j["histogram"] = h;
    j["escalated"] = m.escalated;
    j["decoupled"] = m.decoupled;
    j["threads"] = m.threads;
    j["seconds"] = m.seconds;
    out << j.dump(2) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} (3R arm), map over {} ∈ [{}, {}] ({} values) × {} ∈ [{}, {}] ({} values)\n", name,
                     x.name, fmtNum(x.min), fmtNum(x.max), x.n, y.name, fmtNum(y.min), fmtNum(y.max), y.n);
  for (std::size_t c = 0; c < hist.size(); ++c)
    if (hist[c] > 0) out << fmt::format("  {} cusps: {} arms\n", c, hist[c]);
  out << fmt::format("decoupled arms (IK splits into quadratics): {}; re-solved in float128/mpfr: {}\n", m.decoupled,
                     m.escalated);
  out << fmt::format("{} arms in {:.3f} s on {} thread(s) (TBB)\n", m.counts.size(), m.seconds, m.threads);
  return 0;
}

int cuspidal6RCommand(const RobotFile<double>& rf, const std::filesystem::path& file, const CuspidalAnalysis& a,
                      bool json, std::ostream& out) {
  const SerialRobot<double>& robot = rf.robot;
  const Witness6R& w = a.witness6r;
  const double unit = rf.degrees ? 180.0 / kPi : 1.0;
  auto jointsOut = [&](const JointVector<double>& q) {
    std::vector<double> v;
    for (int i = 0; i < q.size(); ++i) v.push_back(q(i) * unit);
    return v;
  };
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["method"] = a.method;
    j["ik_method"] = w.ikMethod;
    j["poses_tried"] = w.posesTried;
    j["pairs_tried"] = w.pairsTried;
    j["postures_seen"] = w.posturesSeen;
    j["witness_found"] = w.found;
    j["cuspidal"] = w.found ? nlohmann::json(true) : nlohmann::json("unknown");
    if (w.found) {
      j["start"] = jointsOut(w.start);
      j["goal"] = jointsOut(w.goal);
      j["det_sign"] = w.sign;
      j["margin"] = w.margin;
      j["min_signed_det"] = w.minSignedDet;
      nlohmann::json path = nlohmann::json::array();
      for (const auto& q : w.path) path.push_back(jointsOut(q));
      j["path"] = path;
    } else {
      j["note"] = w.note;
    }
    j["seconds"] = w.seconds;
    out << j.dump(2) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} (6R, IK by {})\n", robot.name().empty() ? file.string() : robot.name(), w.ikMethod);
  out << fmt::format("poses tried: {}, postures {}, same-sign pairs planned: {} ({:.2f} s)\n", w.posesTried,
                     w.posturesSeen, w.pairsTried, w.seconds);
  if (w.found) {
    out << fmt::format("witness found: two postures of one pose joined by a path of {} states along which det J {} 0 "
                       "(min sign·det J / L³ = {} over a dense check)\n",
                       w.path.size(), w.sign > 0 ? ">" : "<", fmtNum(w.minSignedDet));
    out << "verdict: CUSPIDAL (witness)\n";
  } else {
    out << "witness: " << w.note << "\n";
    out << "verdict: unknown (no witness; not a proof of non-cuspidality)\n";
  }
  return 0;
}

int cuspidalCommand(const std::filesystem::path& file, bool json, const std::string& png, std::ostream& out,
                    int poses, double secondsPerPair) {
  const RobotFile<double> rf = readRobot<double>(file);
  const SerialRobot<double>& robot = rf.robot;
  CuspidalOptions options;
  options.poses = poses;
  options.secondsPerPair = secondsPerPair;
  const CuspidalAnalysis r = analyseCuspidality(robot, options);
  if (r.sixR) return cuspidal6RCommand(rf, file, r, json, out);
  const Arm3RFrame<double>& f = r.cusps.frame;
  const WitnessPath& w = r.witness;
  if (!png.empty()) {
    const std::filesystem::path p(png);
    const std::filesystem::path stem = p.parent_path() / p.stem();
    const std::string name = robot.name().empty() ? file.stem().string() : robot.name();
    plotJointSpace(r, name + ": aspects and det J = 0 in joint space", p);
    plotSection(r, name + ": singular curves in the workspace section", stem.string() + "_section.png");
    if (w.found) plotWitness(r, name + ": a posture change without singularity", stem.string() + "_witness.png");
  }
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["method"] = r.method;
    j["scalar"] = r.cusps.scalar;
    if (!r.cusps.conditioning.empty()) j["conditioning"] = r.cusps.conditioning;
    j["seconds"] = r.seconds;
    j["verdict_seconds"] = r.verdictSeconds;
    j["cuspidal"] = r.cuspidal;
    j["decoupled"] = f.decoupled;
    if (f.decoupled) j["decoupled_reason"] = f.reason;
    nlohmann::json cs = nlohmann::json::array();
    for (const auto& c : r.cusps.cusps)
      cs.push_back({{"rho", c.rho}, {"z", c.z}, {"posture", {c.posture(0), c.posture(1), c.posture(2)}},
                    {"residual", c.residual}});
    j["cusps"] = cs;
    j["count"] = r.cusps.cusps.size();
    j["traced_reversals"] = r.reversals.size();
    j["aspects"] = r.aspectMap.count();
    nlohmann::json signs = nlohmann::json::array();
    for (int s : r.aspectMap.sign) signs.push_back(s);
    j["aspect_signs"] = signs;
    j["singular_branches"] = r.branches.size();
    if (r.cuspidal) {
      nlohmann::json jw;
      jw["found"] = w.found;
      if (w.found) {
        jw["target"] = {w.target(0), w.target(1), w.target(2)};
        jw["rho"] = w.rho;
        jw["z"] = w.z;
        jw["start"] = {w.start(0), w.start(1), w.start(2)};
        jw["goal"] = {w.goal(0), w.goal(1), w.goal(2)};
        jw["start_residual"] = w.startResidual;
        jw["goal_residual"] = w.goalResidual;
        jw["det_sign"] = w.sign;
        jw["margin"] = w.margin;
        jw["min_signed_det"] = w.minSignedDet;
        jw["certified"] = w.certified;
        jw["checked_points"] = w.checkedPoints;
        jw["aspect"] = w.aspectStart;
        nlohmann::json path = nlohmann::json::array();
        for (const auto& s : w.path) path.push_back({s(0), s(1), s(2)});
        jw["path"] = path;
        jw["planner"] = "OMPL RRTConnect on SO(2)^3";
      } else {
        jw["note"] = w.note;
      }
      jw["seconds"] = w.seconds;
      j["witness"] = jw;
    }
    out << j.dump(2) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} (3R arm)\n", robot.name().empty() ? file.string() : robot.name());
  out << fmt::format("axes 1–2: common normal {}  twist sin {} cos {}\n", fmtNum(f.a1), fmtNum(f.s1), fmtNum(f.c1));
  if (f.decoupled)
    out << fmt::format("the IK equation splits into quadratics ({}): no cusp point\n", f.reason);
  if (!r.cusps.conditioning.empty()) out << "near-degenerate: " << r.cusps.conditioning << "\n";
  out << fmt::format("cusp points (algebraic, triple root of the IK equation, in {}): {}\n", r.cusps.scalar,
                     r.cusps.cusps.size());
  for (const auto& c : r.cusps.cusps)
    out << fmt::format("  ρ = {:>12}  z = {:>12}   posture ({}, {}, {})\n", fmtNum(c.rho), fmtNum(c.z),
                       fmtNum(c.posture(0)), fmtNum(c.posture(1)), fmtNum(c.posture(2)));
  out << fmt::format("image of det J = 0 turns back (traced): {} times on {} branch(es)\n", r.reversals.size(),
                     r.branches.size());
  out << fmt::format("aspects (components of det J ≠ 0 in (θ2, θ3)): {}\n", r.aspectMap.count());
  out << fmt::format("verdict: {} ({:.3f} ms for the cusp points)\n", r.cuspidal ? "CUSPIDAL" : "not cuspidal",
                     1e3 * r.verdictSeconds);
  if (r.cuspidal) {
    if (w.found) {
      out << fmt::format("witness: target ρ = {}, z = {}; postures ({}, {}, {}) → ({}, {}, {}); det J {} 0 along "
                         "{} path states, min |det J| {} over {} checked points{}\n",
                         fmtNum(w.rho), fmtNum(w.z), fmtNum(w.start(0)), fmtNum(w.start(1)), fmtNum(w.start(2)),
                         fmtNum(w.goal(0)), fmtNum(w.goal(1)), fmtNum(w.goal(2)), w.sign > 0 ? ">" : "<",
                         w.path.size(), fmtNum(w.minSignedDet), w.checkedPoints,
                         w.certified ? " (certified)" : "");
    } else {
      out << "witness: " << w.note << "\n";
    }
  }
  return 0;
}

}  // namespace soma::studies
