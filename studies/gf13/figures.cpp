// GF chapter 13 has no figures; the catalogue item GF-13-figures proposes derived ones. This study
// draws the principal screws of inertia of a rigid body (GF §13.1): six screws on the three
// principal axes through the centre of mass, pitches ±√(d_i/m), each shown as a helix of its pitch
// (right-handed for +, left-handed for −), computed from the generalised eigenproblem N s = λQ₀s of
// the body's 6×6 inertia in a general pose (not from the principal frame). The energy-per-integrator
// plot and K(θ₂) are drawn by GF-13.4-lagrangian-energies and GF-13.6.3-gaussian-curvature-2R.
#include "gf13/common.hpp"

#include "soma/render/render.hpp"

#include <Eigen/Eigenvalues>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

void figures(Context& ctx) {
  // a 2 kg box 0.6 × 0.4 × 0.2 m in a general pose
  const double m = 2, a = 0.6, b = 0.4, c = 0.2;
  const V3 d(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
  auto g = std::mt19937_64(1370);
  const SE3<double> pose(SO3<double>::Random(g), V3(0.3, -0.2, 0.5));
  const SpatialInertia<double> body = SpatialInertia<double>::diagonal(m, d).transformed(pose);
  const M6 N = body.matrix();
  const Eigen::EigenSolver<M6> es(q0() * N);
  const M3 R = pose.rotation();
  double pitchErr = 0, axisErr = 0, dirErr = 0;
  struct Drawn {
    V3 axis;
    double pitch;
  };
  std::vector<Drawn> screws;
  for (int k = 0; k < 6; ++k) {
    const V6 s = es.eigenvectors().col(k).real();
    const V3 w = s.head<3>(), v = s.tail<3>();
    const double p = w.dot(v) / w.squaredNorm();
    const V3 u = w.normalized();
    // which principal axis: the closest column of R
    int best = 0;
    for (int i = 1; i < 3; ++i)
      if (abs(u.dot(R.col(i))) > abs(u.dot(R.col(best)))) best = i;
    dirErr = std::max(dirErr, 1 - abs(u.dot(R.col(best))));
    pitchErr = std::max(pitchErr, abs(abs(p) - std::sqrt(d(best) / m)));
    axisErr = std::max(axisErr, (v - body.centreOfMass().cross(w) - p * w).norm() / w.norm());
    screws.push_back({u, p});
  }
  ctx.checkResidual("the six eigen-screws lie along the principal axes (1 − |cos|)", dirErr, 1e-12);
  ctx.checkResidual("their axes pass through the c.o.m.", axisErr, 1e-12);
  ctx.checkResidual("their pitches are ±√(d_i/m)", pitchErr, 1e-12);
  std::string list;
  for (int i = 0; i < 3; ++i) list += (i ? ", " : "") + toString(std::sqrt(d(i) / m), 4);
  ctx.note("Box 0.6 × 0.4 × 0.2 m, 2 kg: principal moments " + toString(d(0), 4) + ", " + toString(d(1), 4) + ", " +
           toString(d(2), 4) + " kg·m²; pitches ±" + list + " m.");
  if (!ctx.makeFigures()) return;
  rd::Scene s;
  s.title = "Principal screws of inertia of a box: six helices of pitch ±√(d_i/m) through the c.o.m.";
  const V3 cm = body.centreOfMass();
  const V3 half(a / 2, b / 2, c / 2);
  s.add(rd::parametricSurface(
      [&](double th, double ph) {
        const V3 q(half(0) * std::cos(ph) * std::cos(th), half(1) * std::cos(ph) * std::sin(th), half(2) * std::sin(ph));
        return V3(R * q + cm);
      },
      {-pi<double>(), pi<double>()}, {-pi<double>() / 2, pi<double>() / 2}, 64, 32, rd::palette::skyBlue.withAlpha(0.45f)));
  const rd::Color cols[3] = {rd::palette::blue, rd::palette::vermillion, rd::palette::bluishGreen};
  for (const Drawn& x : screws) {
    int i = 0;
    for (int k = 1; k < 3; ++k)
      if (abs(x.axis.dot(R.col(k))) > abs(x.axis.dot(R.col(i)))) i = k;
    const V3 u = R.col(i);  // orient along +x_i for the drawing
    rd::Polyline axis;
    axis.p = {V3(cm - 0.55 * u), V3(cm + 0.55 * u)};
    axis.c = rd::palette::darkGrey;
    axis.dashed = true;
    s.add(axis);
    // helix of pitch p about the axis: point = c + (p φ) u + r (cos φ e₁ + sin φ e₂), φ ∈ [0, 0.5/|p|]
    const V3 e1 = R.col((i + 1) % 3), e2 = R.col((i + 2) % 3);
    const double r = x.pitch > 0 ? 0.07 : 0.12, len = 0.5;
    rd::Tube t;
    for (int k = 0; k <= 400; ++k) {
      const double z = -len + 2 * len * k / 400, phi = z / x.pitch;
      t.p.push_back(cm + z * u + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
    t.radius = 0.006;
    t.c = x.pitch > 0 ? cols[i] : cols[i].lighter(0.45f);
    s.add(t);
    rd::Label l;
    l.at = cm + (len + 0.08) * u * (x.pitch > 0 ? 1 : -1);
    l.text = std::string(x.pitch > 0 ? "+" : "−") + toString(abs(x.pitch), 3) + " m";
    l.c = cols[i];
    l.pixelHeight = 22;
    s.add(l);
  }
  s.add(rd::Points{{cm}, rd::palette::black, 0.02});
  const std::string file = "GF-13-principal-screws-of-inertia.png";
  rd::renderPng(s, V3(R * V3(1, 0.75, 0.55)), {1200, 950}, ctx.figurePath(file));  // oblique to all three principal axes
  ctx.figure(file, "The six principal screws of inertia of a 0.6 × 0.4 × 0.2 m box (equivalent ellipsoid shown): on each "
                   "principal axis through the c.o.m. a right-handed helix of pitch +√(d_i/m) (dark) and a left-handed one "
                   "of pitch −√(d_i/m) (light); computed from N s = λQ₀s in a general pose.");
}

}  // namespace

SOMA_STUDY({.id = "GF-13-figures", .title = "Derived figure: the principal screws of inertia of a box (the chapter has none)",
            .source = "GF §13.1", .chapter = kChapter, .scalarGeneric = false, .run = figures, .whyDouble = "a figure: soma::render draws double geometry"});

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
