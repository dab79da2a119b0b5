// Figures of GF chapter 4 (rendered with soma::render, double only, when the report asks):
// the helix of a screw motion exp(tξ) (§4.4.2) and an SE(3) interpolation (geodesic) between two
// poses. Called from the studies GF-4.4.2-se3-exp-4x4 and GF-4.4.2-se3-log-4x4.
#include "gf04/common.hpp"

#include "soma/render/render.hpp"

namespace soma::studies::gf04 {  // not per-file (SOMA_UNITY_ID): it defines functions other chapter files call

namespace rd = soma::render;

namespace {
Eigen::Matrix4d toPose(const SE3d& x) { return x.matrix(); }
}  // namespace

// GF §4.4.2, GF-4.4.2-se3-exp-4x4: the helix swept by a point under exp(tξ).
void helixFigure(Context& c) {
  // Screw: axis along z through q = (0, 0, 0), pitch h = 0.12 per radian, two turns.
  const Eigen::Vector3d axis(0, 0, 1), q(0, 0, 0);
  const double h = 0.12, turns = 2, tMax = turns * 2 * std::numbers::pi;
  const SE3Tangent<double> xi(axis, Eigen::Vector3d(q.cross(axis) + h * axis));
  const Eigen::Vector3d p0(1, 0, 0);
  rd::Scene scene;
  scene.title = "Screw motion exp(tξ): the helix of a point and the moving frame (GF §4.4.2)";
  rd::Tube helix;
  helix.c = rd::palette::blue;
  helix.radius = 0.012;
  for (int k = 0; k <= 400; ++k) helix.p.push_back((xi * (tMax * k / 400)).exp().act(p0));
  scene.add(helix);
  // The screw axis, dashed, a little beyond the helix.
  rd::Polyline ax;
  ax.p = {Eigen::Vector3d(0, 0, -0.35), Eigen::Vector3d(0, 0, h * tMax + 0.45)};
  ax.c = rd::palette::darkGrey;
  ax.width = 2.5;
  ax.dashed = true;
  scene.add(ax);
  scene.add(rd::Arrow{Eigen::Vector3d(0, 0, h * tMax + 0.3), Eigen::Vector3d(0, 0, h * tMax + 0.55), rd::palette::darkGrey, 0.012});
  // Moving frames: exp(tξ) applied to the frame at p0, every 60°.
  const SE3d home(SO3d::Identity(), p0);
  for (int k = 0; k <= 12; ++k) {
    const double t = tMax * k / 12;
    scene.add(rd::Frame{toPose((xi * t).exp() * home), 0.28});
  }
  // Radius segments at t = 0 and t = 4π show the advance 2π·h per turn.
  for (const double t : {0.0, tMax}) {
    const Eigen::Vector3d p = (xi * t).exp().act(p0);
    rd::Polyline r;
    r.p = {Eigen::Vector3d(0, 0, p.z()), p};
    r.c = rd::palette::grey;
    r.width = 1.5;
    scene.add(r);
  }
  auto label = [&](const Eigen::Vector3d& at, const std::string& text, rd::HAlign ha = rd::HAlign::Left,
                   Eigen::Vector2d off = {6, -6}) {
    rd::Label l;
    l.at = at;
    l.text = text;
    l.pixelHeight = 22;
    l.hAlign = ha;
    l.offset = off;
    scene.add(l);
  };
  label(Eigen::Vector3d(0, 0, h * tMax + 0.55), "screw axis: ω = e_z through q = 0, pitch h = 0.12 (advance 2πh per turn)",
        rd::HAlign::Center, {0, -10});
  label(p0, "p₀,  t = 0");
  label((xi * tMax).exp().act(p0), "t = 4π");
  label((xi * (tMax * 0.6)).exp().act(p0), "p(t) = exp(tξ) p₀");
  const std::string file = "GF-4.4.2-helix.png";
  rd::renderPng(scene, Eigen::Vector3d(-1.0, -0.55, -0.32), {1200, 1000}, c.figurePath(file));
  c.figure(file,
           "A point p₀ = (1, 0, 0) under the screw motion exp(tξ), ξ = (e_z; h e_z), h = 0.12 per radian, "
           "t ∈ [0, 4π]: the helix (blue), the frame carried along every 60° (x red, y green, z blue) and "
           "the screw axis (dashed).");
}

// GF §4.4.2 (log) with SE3::interpolate: the geodesic a·exp(t log(a⁻¹b)) is a screw motion.
void interpolationFigure(Context& c) {
  const SE3d a(SO3d::fromAxisAngle(Eigen::Vector3d(0, 0, 1), 0.2), Eigen::Vector3d(0, 0, 0));
  const SE3d b(SO3d::fromAxisAngle(Eigen::Vector3d(1, 1, 1).normalized(), 2.4), Eigen::Vector3d(2.2, 1.2, 0.9));
  rd::Scene scene;
  scene.title = "SE(3) interpolation a·exp(t·log(a⁻¹b)): frames at t = 0, ⅛, …, 1";
  rd::Tube path;
  path.c = rd::palette::vermillion;
  path.radius = 0.012;
  for (int k = 0; k <= 200; ++k) path.p.push_back(SE3d::interpolate(a, b, k / 200.0).translation());
  scene.add(path);
  for (int k = 0; k <= 8; ++k) scene.add(rd::Frame{toPose(SE3d::interpolate(a, b, k / 8.0)), k == 0 || k == 8 ? 0.42 : 0.28});
  // The screw axis of the relative motion a⁻¹b, drawn in world coordinates.
  const Screw<double> sc = screwOf(a.between(b));
  const Eigen::Vector3d p = a.act(sc.point), d = a.rotation() * sc.axis;
  const double s0 = (Eigen::Vector3d(0, 0, 0) - p).dot(d) - 0.8, s1 = (b.translation() - p).dot(d) + 0.8;
  rd::Polyline ax;
  ax.p = {p + s0 * d, p + s1 * d};
  ax.c = rd::palette::darkGrey;
  ax.dashed = true;
  ax.width = 3;
  scene.add(ax);
  scene.add(rd::Points{{Eigen::Vector3d(p + s1 * d)}, rd::palette::darkGrey, 0.025});
  auto label = [&](const Eigen::Vector3d& at, const std::string& text, Eigen::Vector2d off = {8, -8},
                   rd::HAlign ha = rd::HAlign::Left) {
    rd::Label l;
    l.at = at;
    l.text = text;
    l.pixelHeight = 22;
    l.offset = off;
    l.hAlign = ha;
    scene.add(l);
  };
  label(a.translation(), "a (t = 0)", {-12, 6}, rd::HAlign::Right);
  label(b.translation(), "b (t = 1)", {12, -34});
  label(p + s1 * d, "screw axis of a⁻¹b", {-12, -12}, rd::HAlign::Right);
  label(SE3d::interpolate(a, b, 0.5).translation(), "path of the origin", {0, 34});
  // Look across the screw axis (perpendicular to it, slightly from above), orthographic.
  const Eigen::Vector3d across = d.cross(Eigen::Vector3d::UnitZ()).normalized();
  rd::FitOptions fit;
  fit.width = 1200;
  fit.height = 950;
  fit.orthographic = true;
  const std::string file = "GF-4.4.2-interpolation.png";
  rd::renderPng(scene, Eigen::Vector3d(-(across + 0.45 * d.cross(across)).normalized()), fit, c.figurePath(file));
  c.figure(file,
           "SE3::interpolate between pose a and pose b (rotation 2.4 rad about (1,1,1)/√3, translation "
           "(2.2, 1.2, 0.9)): frames at t = 0, ⅛, …, 1 and the path of the origin (vermillion), a helix "
           "about the screw axis of a⁻¹b (dashed).");
}

}  // namespace soma::studies::gf04
