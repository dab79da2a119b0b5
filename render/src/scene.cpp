// Scene bounds and validation.
#include "soma/render/scene.hpp"

#include "detail.hpp"

#include <cmath>

namespace soma::render {

namespace {
// Bounding box of the geometry's defining points (no radii, no automatic sizes).
Eigen::AlignedBox3d coreBounds(const Scene& s) {
  Eigen::AlignedBox3d b;
  for (const auto& x : s.points) for (const auto& p : x.p) b.extend(p);
  for (const auto& x : s.polylines) for (const auto& p : x.p) b.extend(p);
  for (const auto& x : s.tubes) for (const auto& p : x.p) b.extend(p);
  for (const auto& x : s.meshes) for (const auto& p : x.v) b.extend(p);
  for (const auto& x : s.fills) for (const auto& p : x.v) b.extend(p);
  for (const auto& x : s.frames) {
    b.extend(Eigen::Vector3d(x.pose.block<3, 1>(0, 3)));
    if (x.scale > 0)
      for (int k = 0; k < 3; ++k) b.extend(Eigen::Vector3d(x.pose.block<3, 1>(0, 3) + x.scale * x.pose.block<3, 1>(0, k)));
  }
  for (const auto& x : s.arrows) { b.extend(x.from); b.extend(x.to); }
  for (const auto& x : s.labels) b.extend(x.at);
  if (s.axes) {
    b.extend(Eigen::Vector3d::Zero());
    if (s.axesLength > 0) b.extend(Eigen::Vector3d::Constant(s.axesLength));
  }
  return b;
}
void extendBall(Eigen::AlignedBox3d& b, const Eigen::Vector3d& c, double r) {
  b.extend(c - Eigen::Vector3d::Constant(r));
  b.extend(c + Eigen::Vector3d::Constant(r));
}
}  // namespace

double Scene::characteristicLength() const {
  const auto b = coreBounds(*this);
  if (b.isEmpty()) return 1.0;
  const double d = b.diagonal().norm();
  return d > 0 && std::isfinite(d) ? d : 1.0;
}

Eigen::AlignedBox3d Scene::bounds() const {
  Eigen::AlignedBox3d b = coreBounds(*this);
  if (b.isEmpty()) return b;
  const double L = characteristicLength();
  for (const auto& x : points) for (const auto& p : x.p) extendBall(b, p, detail::pointRadius(x, L));
  for (const auto& x : tubes) for (const auto& p : x.p) extendBall(b, p, detail::tubeRadius(x, L));
  for (const auto& x : arrows) {
    const double r = 2.5 * detail::arrowRadius(x, L);  // the head is wider than the shaft
    extendBall(b, x.from, r);
    extendBall(b, x.to, r);
  }
  for (const auto& x : frames) {
    const double s = detail::frameScale(x, L);
    const Eigen::Vector3d o = x.pose.block<3, 1>(0, 3);
    for (int k = 0; k < 3; ++k) extendBall(b, o + s * x.pose.block<3, 1>(0, k), 2.5 * detail::frameArrowRadius * s);
    extendBall(b, o, 2.5 * detail::frameArrowRadius * s);
  }
  if (axes) {
    const double a = detail::axesLength(*this, L);
    for (int k = 0; k < 3; ++k) extendBall(b, a * Eigen::Vector3d::Unit(k), 0.05 * a);
  }
  return b;
}

std::vector<Eigen::Vector3d> detail::outlinePoints(const Scene& sc, const Eigen::Vector3d& s, const Eigen::Vector3d& u) {
  std::vector<Eigen::Vector3d> out;
  const double L = sc.characteristicLength();
  auto ball = [&](const Eigen::Vector3d& c, double r) {
    out.push_back(c);
    for (const Eigen::Vector3d& d : {s, u}) {
      out.push_back(c + r * d);
      out.push_back(c - r * d);
    }
  };
  for (const auto& x : sc.points) for (const auto& p : x.p) ball(p, detail::pointRadius(x, L));
  for (const auto& x : sc.polylines) for (const auto& p : x.p) out.push_back(p);
  for (const auto& x : sc.tubes) for (const auto& p : x.p) ball(p, detail::tubeRadius(x, L));
  for (const auto& x : sc.meshes) for (const auto& p : x.v) out.push_back(p);
  for (const auto& x : sc.fills) for (const auto& p : x.v) out.push_back(p);
  for (const auto& x : sc.frames) {
    const double f = detail::frameScale(x, L);
    const Eigen::Vector3d o = x.pose.block<3, 1>(0, 3);
    ball(o, 1.6 * detail::frameArrowRadius * f);
    for (int k = 0; k < 3; ++k) ball(o + f * x.pose.block<3, 1>(0, k), 2.6 * detail::frameArrowRadius * f);
  }
  for (const auto& x : sc.arrows) {
    const double r = detail::arrowRadius(x, L);
    ball(x.from, r);
    ball(x.to, 2.6 * r);
  }
  for (const auto& x : sc.labels) out.push_back(x.at);
  if (sc.axes) {
    const double a = detail::axesLength(sc, L);
    out.push_back(Eigen::Vector3d::Zero());
    for (int k = 0; k < 3; ++k) ball(a * Eigen::Vector3d::Unit(k), 2.6 * detail::worldAxisRadius(a, L));
  }
  return out;
}

namespace {
using detail::invalid;
void checkColor(const Color& c, const std::string& who) {
  for (float v : {c.r, c.g, c.b, c.a})
    if (!(v >= 0.0f && v <= 1.0f))
      invalid(who + " has a colour component " + std::to_string(v) + " outside [0, 1]");
}
void checkPoints(const std::vector<Eigen::Vector3d>& ps, const std::string& who) {
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (!detail::finite(ps[i]))
      invalid(who + ".p[" + std::to_string(i) + "] has a non-finite coordinate " + detail::str(ps[i]));
}
void checkSize(double v, const std::string& who, bool allowZero) {
  if (!std::isfinite(v) || v < 0 || (!allowZero && v == 0))
    invalid(who + " is " + std::to_string(v) + "; it must be finite and " + (allowZero ? "non-negative (0 = automatic)" : "positive"));
}
std::string at(const char* kind, std::size_t i) { return std::string(kind) + "[" + std::to_string(i) + "]"; }
}  // namespace

void Scene::validate() const {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& x = points[i];
    checkPoints(x.p, at("Points", i));
    checkColor(x.c, at("Points", i));
    checkSize(x.radius, at("Points", i) + ".radius", true);
  }
  for (std::size_t i = 0; i < polylines.size(); ++i) {
    const auto& x = polylines[i];
    checkPoints(x.p, at("Polyline", i));
    checkColor(x.c, at("Polyline", i));
    checkSize(x.width, at("Polyline", i) + ".width", false);
    if (x.dashed) checkSize(x.dashLength, at("Polyline", i) + ".dashLength", false);
  }
  for (std::size_t i = 0; i < tubes.size(); ++i) {
    const auto& x = tubes[i];
    checkPoints(x.p, at("Tube", i));
    checkColor(x.c, at("Tube", i));
    checkSize(x.radius, at("Tube", i) + ".radius", true);
  }
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const auto& x = meshes[i];
    const std::string who = at("Mesh", i);
    for (std::size_t k = 0; k < x.v.size(); ++k)
      if (!detail::finite(x.v[k])) invalid(who + ".v[" + std::to_string(k) + "] has a non-finite coordinate " + detail::str(x.v[k]));
    if (!x.n.empty() && x.n.size() != x.v.size())
      invalid(who + " has " + std::to_string(x.n.size()) + " normals for " + std::to_string(x.v.size()) +
              " vertices (give one per vertex, or none to compute them)");
    for (std::size_t k = 0; k < x.n.size(); ++k)
      if (!detail::finite(x.n[k])) invalid(who + ".n[" + std::to_string(k) + "] has a non-finite coordinate " + detail::str(x.n[k]));
    for (std::size_t k = 0; k < x.tri.size(); ++k)
      for (int j = 0; j < 3; ++j)
        if (x.tri[k][j] < 0 || std::size_t(x.tri[k][j]) >= x.v.size())
          invalid(who + ".tri[" + std::to_string(k) + "] refers to vertex " + std::to_string(x.tri[k][j]) + " of " +
                  std::to_string(x.v.size()));
    checkColor(x.c, who);
  }
  for (std::size_t i = 0; i < fills.size(); ++i) {
    const auto& x = fills[i];
    const std::string who = at("Fill", i);
    for (std::size_t k = 0; k < x.v.size(); ++k)
      if (!detail::finite(x.v[k])) invalid(who + ".v[" + std::to_string(k) + "] has a non-finite coordinate " + detail::str(x.v[k]));
    if (!x.vc.empty() && x.vc.size() != x.v.size())
      invalid(who + " has " + std::to_string(x.vc.size()) + " vertex colours for " + std::to_string(x.v.size()) +
              " vertices (give one per vertex, or none to use c)");
    for (std::size_t k = 0; k < x.tri.size(); ++k)
      for (int j = 0; j < 3; ++j)
        if (x.tri[k][j] < 0 || std::size_t(x.tri[k][j]) >= x.v.size())
          invalid(who + ".tri[" + std::to_string(k) + "] refers to vertex " + std::to_string(x.tri[k][j]) + " of " +
                  std::to_string(x.v.size()));
    checkColor(x.c, who);
    for (std::size_t k = 0; k < x.vc.size(); ++k) checkColor(x.vc[k], who + ".vc[" + std::to_string(k) + "]");
  }
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& x = frames[i];
    if (!x.pose.allFinite()) invalid(at("Frame", i) + ".pose has a non-finite entry");
    checkSize(x.scale, at("Frame", i) + ".scale", true);
  }
  for (std::size_t i = 0; i < arrows.size(); ++i) {
    const auto& x = arrows[i];
    if (!detail::finite(x.from)) invalid(at("Arrow", i) + ".from has a non-finite coordinate " + detail::str(x.from));
    if (!detail::finite(x.to)) invalid(at("Arrow", i) + ".to has a non-finite coordinate " + detail::str(x.to));
    checkColor(x.c, at("Arrow", i));
    checkSize(x.radius, at("Arrow", i) + ".radius", true);
  }
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto& x = labels[i];
    if (!detail::finite(x.at)) invalid(at("Label", i) + " (\"" + x.text + "\").at has a non-finite coordinate " + detail::str(x.at));
    if (!x.offset.allFinite()) invalid(at("Label", i) + ".offset is not finite");
    checkColor(x.c, at("Label", i));
    if (!(x.pixelHeight >= 1 && x.pixelHeight <= 1000))
      invalid(at("Label", i) + ".pixelHeight is " + std::to_string(x.pixelHeight) + "; it must be in [1, 1000]");
  }
  checkColor(background, "Scene.background");
  if (!title.empty() && !(titlePixelHeight >= 1 && titlePixelHeight <= 1000))
    invalid("Scene.titlePixelHeight is " + std::to_string(titlePixelHeight) + "; it must be in [1, 1000]");
  checkSize(axesLength, "Scene.axesLength", true);
}

}  // namespace soma::render
