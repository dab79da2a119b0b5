#pragma once
// Internal helpers shared by the render sources (not installed, not public API).
#include "soma/render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace soma::render::detail {

inline bool finite(const Eigen::Vector3d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

inline std::string str(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return s.str();
}

[[noreturn]] inline void invalid(const std::string& what) {
  throw std::invalid_argument("soma::render: " + what);
}

/// Sizes after resolving "0 = automatic" against the scene's characteristic length L.
inline double pointRadius(const Points& x, double L) { return x.radius > 0 ? x.radius : autosize::pointRadius * L; }
inline double tubeRadius(const Tube& x, double L) { return x.radius > 0 ? x.radius : autosize::tubeRadius * L; }
inline double arrowRadius(const Arrow& x, double L) { return x.radius > 0 ? x.radius : autosize::arrowRadius * L; }
inline double frameScale(const Frame& x, double L) { return x.scale > 0 ? x.scale : autosize::frameScale * L; }
inline double axesLength(const Scene& s, double L) { return s.axesLength > 0 ? s.axesLength : autosize::axesLength * L; }
/// Shaft radius of a frame's arrows relative to its scale.
inline constexpr double frameArrowRadius = 0.035;
/// Shaft radius of the world axes' arrows: thin (a fraction of the scene's size L), and never
/// more than a fraction of their length a.
inline double worldAxisRadius(double a, double L) { return std::min(0.018 * a, 0.0035 * L); }

/// Points whose projections outline the drawn scene as seen along a view direction with screen
/// axes s (right) and u (up): every defining point, and for round things (spheres, tubes, arrow
/// heads) the points at +-radius along s and u. Used by Camera::fit to frame the geometry tightly.
std::vector<Eigen::Vector3d> outlinePoints(const Scene& scene, const Eigen::Vector3d& s, const Eigen::Vector3d& u);

}  // namespace soma::render::detail
