// Figures of GF chapter 12 (rendered with soma::render, double only): Fig. 12.2 (the four-beam wrist
// force sensor with its eight gauge forces) and Fig. 12.4 (fingers on a rigid body: a seven-finger
// push-only grasp of an ellipsoid with its contact normals, and three fingers with friction cones).
#include "soma/geometry/statics/grasp.hpp"
#include "soma/geometry/statics/wrist_sensor.hpp"
#include "soma/geometry/statics/robot_statics.hpp"
#include "soma/render/render.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <random>

namespace soma::studies::gf12::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

constexpr const char* kChapter = "GF 12 — Statics";
constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";
namespace rd = soma::render;
using V3 = Eigen::Vector3d;
using V6 = Vec6<double>;
using WS = WrenchSet<double>;
using std::cos;
using std::sin;

void label(rd::Scene& s, const V3& at, const std::string& text, Eigen::Vector2d off = {8, -8}, double px = 24,
           rd::Color col = rd::palette::black) {
  rd::Label l;
  l.at = at;
  l.text = text;
  l.offset = off;
  l.pixelHeight = px;
  l.c = col;
  s.add(l);
}
void draw(Context& c, rd::Scene& scene, const V3& view, const std::string& file, const std::string& caption) {
  rd::renderPng(scene, view, {1200, 950}, c.figurePath(file));
  c.figure(file, caption);
}

// GF Fig. 12.2, GF-12-fig-12.2
void fig122(Context& c) {
  const double l = 1.0;
  const auto gauges = wristSensorGauges<double>(l);
  // the drawn geometry is the one whose wrenches sum to the corrected resolved force matrix
  Vec8<double> w;
  w << 1, 2, 3, 4, 5, 6, 7, 8;
  Wrench<double> tot;
  for (const auto& x : wristSensorWrenches<double>(l, w)) tot += x;
  c.checkResidual("the drawn gauges reproduce the corrected resolved force matrix (w = 1…8)",
                  (resolvedForceMatrix<double>(l) * w - tot.coeffs()).cwiseAbs().maxCoeff(), 1e-14);
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 12.2: the four-beam wrist force sensor — eight gauge forces w₁ … w₈";
  s.axes = true;
  s.axesLength = 0.45;
  for (const V3& e : {V3(1, 0, 0), V3(0, 1, 0), V3(-1, 0, 0), V3(0, -1, 0)}) {
    rd::Tube t;
    t.p = {V3(0.18 * e), V3(l * e)};
    t.radius = 0.05;
    t.c = rd::palette::lightGrey.darker(0.15f);
    s.add(t);
  }
  s.add(rd::sphere(V3::Zero(), 0.2, rd::palette::lightGrey.darker(0.3f)));
  for (int i = 0; i < 8; ++i) {
    const auto& gi = gauges[std::size_t(i)];
    const V3 from = gi.point + 0.09 * gi.direction, to = gi.point + 0.5 * gi.direction;
    const rd::Color col = gi.direction.z() > 0.5 ? rd::palette::blue : rd::palette::vermillion;
    s.add(rd::Arrow{from, to, col, 0.022});
    label(s, to, "w" + std::string(i == 0 ? "₁" : i == 1 ? "₂" : i == 2 ? "₃" : i == 3 ? "₄" : i == 4 ? "₅" : i == 5 ? "₆" : i == 6 ? "₇" : "₈"),
          {8, -4}, 28, col);
  }
  label(s, V3(l, 0, 0), "(l, 0, 0)", {10, 22}, 20, rd::palette::darkGrey);
  label(s, V3(0, l, 0), "(0, l, 0)", {10, 22}, 20, rd::palette::darkGrey);
  draw(c, s, V3(-0.55, -1.0, -0.75), "GF-12-fig-12.2-wrist-sensor.png",
       "The four-beam wrist force sensor of Fig. 12.2, read off the eight printed wrenches: beams of length l to (±l, 0, 0) "
       "and (0, ±l, 0); in-plane gauge forces (vermillion) w₁, w₅ ∥ y, w₃, w₇ ∥ x, and vertical forces (blue) w₂, w₄, w₆, w₈. "
       "Their wrenches sum to the corrected resolved force matrix (row 2 = (0, −l, 0, 0, 0, +l, 0, 0), erratum E12.1).");
}

V3 ellPoint(double a, double b, double cc, double th, double ph) {
  return V3(a * cos(ph) * cos(th), b * cos(ph) * sin(th), cc * sin(ph));
}

// GF Fig. 12.4, GF-12-fig-12.4
void fig124(Context& c) {
  const double a = 1.5, b = 1.0, cc = 0.7;
  auto g = std::mt19937_64(1240);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<V3> pts, nrm;
  PositiveSpan<double> ps;
  int tries = 0;
  for (; tries < 50000; ++tries) {
    pts.clear();
    nrm.clear();
    for (int i = 0; i < 7; ++i) {
      const V3 x = ellPoint(a, b, cc, 3.14159 * u(g), 1.45 * u(g));
      pts.push_back(x);
      nrm.push_back(V3(-x.x() / (a * a), -x.y() / (b * b), -x.z() / (cc * cc)).normalized());
    }
    ps = positiveSpan<double>(contactNormalWrenches<double>(pts, nrm));
    if (ps.spans && ps.margin > 0.02) break;  // a well-conditioned example for the picture
  }
  c.checkEqual("the drawn 7-finger grasp is force closed (positive span)", "yes", ps.spans ? "yes" : "no");
  c.checkEqual("and form closed (dual LP)", "yes", formClosure<double>(contactNormalWrenches<double>(pts, nrm)).closed ? "yes" : "no");
  // three fingers with friction on a sphere
  const double mu = 0.5;
  WS E(6, 24);
  std::vector<V3> q3;
  for (int i = 0; i < 3; ++i) {
    const double th = 2 * pi<double>() * i / 3 + 0.3;
    q3.push_back(V3(cos(th), sin(th), 0.15).normalized());
    E.middleCols(8 * i, 8) = frictionConeEdges<double>(q3.back(), V3(-q3.back()), mu, 8);
  }
  c.checkEqual("the drawn three-finger friction grasp (μ = 0.5, 8-edge cones) is force closed", "yes",
               positiveSpan<double>(E).spans ? "yes" : "no");
  if (!c.makeFigures()) return;
  {
    rd::Scene s;
    s.title = "Fig. 12.4: seven push-only fingers force-close an ellipsoid";
    s.add(rd::parametricSurface([&](double th, double ph) { return ellPoint(a, b, cc, th, ph); }, {-pi<double>(), pi<double>()},
                                {-pi<double>() / 2, pi<double>() / 2}, 64, 32, rd::palette::skyBlue.withAlpha(0.55f)));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      s.add(rd::Arrow{V3(pts[i] - 0.75 * nrm[i]), pts[i], rd::palette::vermillion, 0.025});
      rd::Polyline line;  // the normal line through the body
      line.p = {pts[i], V3(pts[i] + 0.6 * nrm[i])};
      line.c = rd::palette::darkGrey;
      line.dashed = true;
      line.width = 1.5;
      s.add(line);
      label(s, V3(pts[i] - 0.75 * nrm[i]), std::to_string(i + 1), {6, -6}, 26, rd::palette::vermillion);
    }
    s.add(rd::Points{pts, rd::palette::black, 0.035});
    draw(c, s, V3(-0.7, -1.0, -0.6), "GF-12-fig-12.4-seven-fingers.png",
         "Several fingers acting on a rigid body (Fig. 12.4): seven frictionless push-only fingers (arrows along the inward "
         "contact normals, dashed: the normal lines continued) on the ellipsoid with semi-axes (1.5, 1, 0.7). The seven "
         "normal wrenches positively span se*(3) (LP margin " + toString(ps.margin, 3) + "), so the grasp is force and form "
         "closed; six fingers never are (GF-12.5-positive-grasp-seven).");
  }
  {
    rd::Scene s;
    s.title = "Three fingers with friction (μ = 0.5): friction cones and their 8-edge pyramids";
    s.add(rd::sphere(V3::Zero(), 1.0, rd::palette::skyBlue.withAlpha(0.5f), 48, 24));
    for (int i = 0; i < 3; ++i) {
      const V3 p = q3[std::size_t(i)], n = -p;
      // the cone of forces, drawn on the finger side: apex at p, opening outward along −f
      V3 t1 = n.cross(V3::UnitZ()).normalized(), t2 = n.cross(t1);
      const double h = 0.9;
      s.add(rd::parametricSurface(
          [&](double phi, double r) { return V3(p - r * h * (n + mu * (cos(phi) * t1 + sin(phi) * t2))); }, {0, 2 * pi<double>()},
          {0, 1}, 48, 4, rd::palette::orange.withAlpha(0.35f)));
      const WS Ei = frictionConeEdges<double>(p, n, mu, 8);
      for (int j = 0; j < 8; ++j) {
        const V3 f = V6(Ei.col(j)).tail<3>();
        rd::Polyline e;
        e.p = {p, V3(p - h * f)};
        e.c = rd::palette::darkGrey;
        e.width = 1.5;
        s.add(e);
      }
      s.add(rd::Arrow{V3(p - 1.1 * n), V3(p - 0.02 * n), rd::palette::vermillion, 0.02});
    }
    s.add(rd::Points{q3, rd::palette::black, 0.035});
    draw(c, s, V3(-0.5, -0.8, -0.9), "GF-12-fig-12.6-friction-cones.png",
         "Three fingers on a unit sphere near its equator with Coulomb friction μ = 0.5: each friction cone (orange, semi-angle "
         "atan μ, apex at the contact, drawn on the finger side) and its inscribed 8-edge pyramid (grey lines) used by the "
         "linear program. The 24 edge wrenches positively span se*(3): the grasp is force closed; two such cones never are "
         "(no torque about the line joining the contacts).");
  }
}


// GF Fig. 12.1, GF-12-fig-12.1: a force F acting along the line through r on a rigid body, 𝒲 = (r × F, F)
void fig121(Context& c) {
  const V3 r(0.5, 0.3, 0.25), F(-0.2, 0.35, 0.45);
  const Wrench<double> W = Wrench<double>::ofForce(r, F);
  double slide = 0;
  for (double lam : {-1.0, 0.5, 2.0}) slide = std::max(slide, (Wrench<double>::ofForce(V3(r + lam * F), F).coeffs() - W.coeffs()).cwiseAbs().maxCoeff());
  c.checkResidual("𝒲 = (r × F, F) is unchanged when r slides along the line of action (λ = −1, ½, 2)", slide, 1e-15);
  c.checkResidual("the moment r × F is perpendicular to F (pitch 0: a pure force)", abs(W.coeffs().head<3>().dot(F)), 1e-16);
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 12.1: a force F on a rigid body along the line through r: W = (r × F, F)";
  s.axes = true;
  s.axesLength = 0.3;
  const V3 ctr(0.55, 0.25, 0.05);
  s.add(rd::parametricSurface(
      [&](double th, double ph) { return V3(ctr + V3(0.3 * std::cos(ph) * std::cos(th), 0.22 * std::cos(ph) * std::sin(th), 0.2 * std::sin(ph))); },
      {-pi<double>(), pi<double>()}, {-pi<double>() / 2, pi<double>() / 2}, 64, 32, rd::palette::skyBlue.withAlpha(0.5f)));
  rd::Polyline line;
  line.p = {V3(r - 0.9 * F), V3(r + 1.6 * F)};
  line.c = rd::palette::darkGrey;
  line.dashed = true;
  s.add(line);
  s.add(rd::Arrow{r, V3(r + F), rd::palette::vermillion, 0.02});
  s.add(rd::Arrow{V3::Zero(), r, rd::palette::blue, 0.012});
  s.add(rd::sphere(r, 0.02, rd::palette::black));
  label(s, V3(r + F), "F", {8, -8}, 28, rd::palette::vermillion);
  label(s, V3(0.5 * r), "r", {8, -8}, 28, rd::palette::blue);
  label(s, V3(r + 1.6 * F), "line of action", {8, -8}, 22, rd::palette::darkGrey);
  label(s, V3::Zero(), "O", {-24, 16}, 26);
  draw(c, s, V3(1.0, -1.4, 0.7), "GF-12-fig-12.1-force-on-body.png",
       "Fig. 12.1 redrawn: a force F on a rigid body acts along the line through r (dashed); its wrench about the origin O is "
       "𝒲 = (r × F, F), unchanged when r slides along the line.");
}

// GF Fig. 12.3, GF-12-fig-12.3: the wrenches on the links of a robot; the joint torques w_i = 𝒲_totᵀs_i
void fig123(Context& c) {
  const SerialRobot<double> robot = puma560Robot<double>();
  JointVector<double> q(6);
  q << 0.3, -0.7, 0.5, 0.4, 0.8, -0.3;
  const auto J = robot.spatialJacobian(q);
  const SE3<double> T = robot.fk(q);
  const V3 tip = T.translation(), Ftip(0, 0, -20);  // a 20 N load hanging at the tool point
  const Wrench<double> Wtot = Wrench<double>::ofForce(tip, Ftip);
  const auto w = jointEfforts<double>(J, Wtot);
  auto g = std::mt19937_64(1230);
  double vw = 0;
  for (int t = 0; t < 5; ++t) {
    Eigen::Matrix<double, 6, 1> qd;
    for (int i = 0; i < 6; ++i) qd(i) = std::uniform_real_distribution<double>(-1, 1)(g);
    vw = std::max(vw, abs(Wtot.coeffs().dot(J * qd) - w.dot(qd)));
  }
  c.checkResidual("virtual work: 𝒲_totᵀ(Jθ̇) = Σ w_iθ̇_i with w_i = 𝒲_totᵀs_i (5 random θ̇)", vw, 1e-12);
  // and back: 𝒲_tot = J⁻ᵀw (line 7448) recovers the load
  c.checkResidual("𝒲_tot = J⁻ᵀ(w₁, …, w₆) recovers the 20 N load", (J.transpose().partialPivLu().solve(w) - Wtot.coeffs()).cwiseAbs().maxCoeff(), 1e-11);
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 12.3: joint torques w_i = W_totᵀs_i holding a 20 N load";
  s.axes = true;
  s.axesLength = 0.25;
  const auto F = robot.frames(q);
  std::vector<V3> pts;
  for (const auto& f : F) pts.push_back(f.translation());
  pts.push_back(tip);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    if ((pts[i + 1] - pts[i]).norm() < 1e-9) continue;
    rd::Tube t;
    t.p = {pts[i], pts[i + 1]};
    t.radius = 0.025;
    t.c = rd::palette::lightGrey.darker(0.2f);
    s.add(t);
  }
  // The load passes through the wrist centre, on axes 4–6 of the PUMA: w₆ is zero up to rounding
  // (8.9e-16 N·m); the labels print such a torque as 0.
  const auto wShown = w.unaryExpr([&](double v) { return abs(v) < 1e-12 * w.cwiseAbs().maxCoeff() ? 0.0 : v; }).eval();
  for (int i = 0; i < 6; ++i) {
    const V3 o = F[std::size_t(i)].translation(), z = F[std::size_t(i)].rotation().col(2);
    rd::Tube ax;
    ax.p = {V3(o - 0.07 * z), V3(o + 0.07 * z)};
    ax.radius = 0.04;
    ax.c = rd::palette::blue;
    s.add(ax);
    label(s, V3(o + 0.08 * z), "w" + std::string(i == 0 ? "₁" : i == 1 ? "₂" : i == 2 ? "₃" : i == 3 ? "₄" : i == 4 ? "₅" : "₆") + " = " +
                                  toString(wShown(i), 3) + " N·m",
          {10, -6 - 18.0 * (i % 2)}, 20, rd::palette::blue);
  }
  s.add(rd::Arrow{tip, V3(tip + 0.02 * Ftip), rd::palette::vermillion, 0.015});
  s.add(rd::sphere(tip, 0.03, rd::palette::vermillion));
  label(s, V3(tip + 0.02 * Ftip), "W_tot: 20 N load", {8, 8}, 22, rd::palette::vermillion);
  draw(c, s, V3(1.6, 1.2, 0.7), "GF-12-fig-12.3-link-wrenches.png",  // across the forearm: the hanging load stays in view
       "Fig. 12.3 redrawn: the PUMA 560 at q = (0.3, −0.7, 0.5, 0.4, 0.8, −0.3) holding a 20 N load; at each joint the motor "
       "wrench 𝒲_i and the reaction ℛ_i sum to 𝒲_tot, so the joint torque is w_i = 𝒲_totᵀs_i (labels, N·m).");
}
}  // namespace

SOMA_STUDY_DOUBLE("GF-12-fig-12.1", "Fig. 12.1: a force acting on a rigid body", "GF §12.2", fig121);
SOMA_STUDY_DOUBLE("GF-12-fig-12.3", "Fig. 12.3: the wrenches acting on the links of a robot", "GF §12.4", fig123);
SOMA_STUDY_DOUBLE("GF-12-fig-12.2", "Fig. 12.2: the four-beam wrist force sensor", "GF §12.3", fig122);
SOMA_STUDY_DOUBLE("GF-12-fig-12.4", "Fig. 12.4: fingers on a rigid body — normals, and friction cones", "GF §12.5–12.6", fig124);

}  // namespace soma::studies::gf12::SOMA_UNITY_ID
