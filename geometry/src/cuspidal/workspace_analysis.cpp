// analyseWorkspace and singularImages (workspace_analysis.hpp).
#include "soma/geometry/cuspidal/workspace_analysis.hpp"

#include "soma/geometry/cuspidal/singular_set.hpp"

#include <cmath>

namespace soma {

std::vector<std::vector<Eigen::Vector2d>> singularImages(const SerialRobot<double>& robot) {
  std::vector<std::vector<Eigen::Vector2d>> out;
  if (robot.dof() != 3 || !robot.allRevolute()) return out;
  const DetJSeries dj = detJSeries(robot);
  for (const auto& b : traceSingularCurves(robot, dj)) {
    std::vector<Eigen::Vector2d> pts(b.section.begin(), b.section.end());
    if (b.closed && !pts.empty()) pts.push_back(pts.front());
    out.push_back(std::move(pts));
  }
  return out;
}

WorkspaceAnalysis analyseWorkspace(const SerialRobot<double>& robot, const WorkspaceOptions& o) {
  WorkspaceAnalysis a;
  a.maps = sampleWorkspace(robot, o.samples, o.grid);
  a.boundary = singularImages(robot);
  if (!o.plan) return a;
  a.plan = planAwayFromSingularities(robot, o.plan->first, o.plan->second, o.margin, o.seconds);
  if (!a.plan->found) return a;
  // The tool point in the section about axis 1: ρ from the axis, z along it from the foot of the
  // base origin on the axis.
  const Vec3<double> ez = robot.joints()[0].axis, r1 = robot.joints()[0].point, o0 = robot.base().translation();
  const Vec3<double> c = r1 + ez * ez.dot(o0 - r1);
  const auto& path = a.plan->path;
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    for (int t = 0; t < 8; ++t) {
      const JointVector<double> q = path[k] + (path[k + 1] - path[k]) * (t / 8.0);
      const Vec3<double> d = robot.fk(q).translation() - c;
      const double z = ez.dot(d);
      a.planTrace.emplace_back(std::sqrt((d - ez * z).squaredNorm()), z);
    }
  return a;
}

}  // namespace soma
