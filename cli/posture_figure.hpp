#pragma once
// The figures of `fk`, `ik` and `stewart` (--png FILE, --svg FILE): what the command computed, a
// panel per posture (render/panels.hpp: one camera for every panel), each labelled with its joint
// values (or pose) and its configuration, the robot or platform drawn by the scene layer's
// tessellations (the same primitives `soma render` draws). Written before the answer is printed,
// so that a figure that cannot be written leaves no answer either (exit 2, the file named).
#include "soma/algebra/errors.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/serial/serial_robot.hpp"
#include "soma/render/panels.hpp"
#include "soma/scene/tessellation.hpp"

#include <fmt/format.h>

#include <Eigen/LU>

#include <string>
#include <vector>

namespace soma::cli {

/// The files asked for: --png and --svg (either, both or none).
struct FigureFiles {
  std::string png, svg;
  bool any() const { return !png.empty() || !svg.empty(); }
};

inline void writeFigureFiles(const render::PanelGrid& grid, const FigureFiles& files) {
  for (const std::string* f : {&files.png, &files.svg}) {
    if (f->empty()) continue;
    try {
      render::writePanels(grid, *f);
    } catch (const std::exception& e) {
      throw InvalidInput(std::string(f == &files.png ? "--png " : "--svg ") + *f + ": " + e.what());
    }
  }
}

/// A 6R posture's configuration: the sign of det J (its aspect's side of the singular set).
inline std::string configurationOf(const SerialRobot<double>& robot, const JointVector<double>& q) {
  if (robot.dof() != 6) return "";
  const double d = Eigen::Matrix<double, 6, 6>(robot.spatialJacobian(q)).determinant();
  return d > 0 ? "det J > 0" : d < 0 ? "det J < 0" : "det J = 0";
}

/// The robot at each posture, a panel each: "k: (q1, …, qn)° · det J > 0".
template <class S>
void writeRobotFigures(const SerialRobot<S>& robotS, const std::vector<JointVector<S>>& postures, bool degrees,
                       const std::string& title, const FigureFiles& files) {
  if (!files.any()) return;
  const SerialRobot<double> robot = robotS.template cast<double>();
  render::PanelGrid grid;
  grid.title = title;
  grid.columns = postures.size() <= 4 ? int(std::max<std::size_t>(1, postures.size())) : 4;
  std::vector<JointVector<double>> qs;
  for (const auto& p : postures) qs.push_back(p.unaryExpr([](const S& x) { return toDouble(x); }));
  if (qs.empty()) qs.push_back(JointVector<double>::Zero(robot.dof()));  // no posture: the robot at home
  for (std::size_t k = 0; k < qs.size(); ++k) {
    render::Scene s = scene::robotTessellation(robot, {qs[k]}, {}, "");
    s.labels.clear();
    std::string joints;
    for (int i = 0; i < qs[k].size(); ++i) {
      const bool rev = robot.joints()[std::size_t(i)].type == JointType::Revolute;
      joints += fmt::format("{}{:.1f}", i ? ", " : "", qs[k](i) * (rev && degrees ? 180.0 / pi<double>() : 1.0));
    }
    const std::string conf = configurationOf(robot, qs[k]);
    s.title = postures.empty() ? "home (no posture found)"
                               : fmt::format("{}: ({}){}{}", k + 1, joints, degrees ? "°" : "", conf.empty() ? "" : " · " + conf);
    grid.panels.push_back(std::move(s));
  }
  writeFigureFiles(grid, files);
}

/// The platform at each real posture, a panel each: "k: t = (x, y, z)".
template <class S>
void writePlatformFigures(const StewartPlatform<S>& PS, const std::vector<SE3<S>>& postures, const std::string& title,
                          const FigureFiles& files) {
  if (!files.any()) return;
  const StewartPlatform<double> P = PS.template cast<double>();
  render::PanelGrid grid;
  grid.title = title;
  grid.columns = postures.size() <= 4 ? int(std::max<std::size_t>(1, postures.size())) : 4;
  if (postures.empty()) {
    render::Scene s = scene::platformTessellation(P, {}, "");
    s.labels.clear();
    s.title = "the base (no real posture)";
    grid.panels.push_back(std::move(s));
  }
  for (std::size_t k = 0; k < postures.size(); ++k) {
    const SE3<double> g = postures[k].template cast<double>();
    render::Scene s = scene::platformTessellation(P, {g}, "");
    s.labels.clear();
    s.title = fmt::format("{}: t = ({:.3f}, {:.3f}, {:.3f})", k + 1, g.translation()(0), g.translation()(1), g.translation()(2));
    grid.panels.push_back(std::move(s));
  }
  writeFigureFiles(grid, files);
}

}  // namespace soma::cli
