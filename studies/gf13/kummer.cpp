// GF §13.6.1, the derived figure of the catalogue (ch13 figure 3): the quadratic line complex of a
// decoupled 2R and its Kummer surface. In principal axes (c.o.m. at the origin, principal moments
// d₁, d₂, d₃) the complex is (d₁−d₃)y ω_zω_x + (d₂−d₁)z ω_xω_y + (d₃−d₂)x ω_yω_z = 0; the complex lines
// through a point r form the quadratic cone ωᵀM(r)ω = 0, and the Kummer surface det M = 0 — where the
// cone degenerates into two planes — is the union of the three principal planes (erratum 23: det M
// is 2(d₂−d₁)(d₁−d₃)(d₃−d₂)xyz).
#include "gf13/common.hpp"

#include "soma/render/render.hpp"

#include <Eigen/Eigenvalues>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

// GF §13.6.1 line 8421: the conic matrix of the complex lines through r
M3 conicMatrix(const V3& d, const V3& r) {
  M3 m = M3::Zero();
  m(0, 1) = m(1, 0) = (d(1) - d(0)) * r.z() / 2;
  m(0, 2) = m(2, 0) = (d(0) - d(2)) * r.y() / 2;
  m(1, 2) = m(2, 1) = (d(2) - d(1)) * r.x() / 2;
  return m;
}
double complexEquation(const V3& d, const V3& r, const V3& w) {
  return (d(0) - d(2)) * r.y() * w.z() * w.x() + (d(1) - d(0)) * r.z() * w.x() * w.y() + (d(2) - d(1)) * r.x() * w.y() * w.z();
}
/// Unit directions of the cone ωᵀMω = 0 (M of signature (+, +, −) or (+, −, −)), n samples.
std::vector<V3> coneDirections(const M3& M, int n) {
  const Eigen::SelfAdjointEigenSolver<M3> es(M);
  const V3 l = es.eigenvalues();  // ascending
  const M3 E = es.eigenvectors();
  std::vector<V3> out;
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * pi<double>() * k / n;
    V3 w;
    if (l(1) > 0)  // one negative (l0): ω = e₀ + …
      w = E.col(0) + std::sqrt(-l(0) / l(1)) * std::cos(phi) * E.col(1) + std::sqrt(-l(0) / l(2)) * std::sin(phi) * E.col(2);
    else  // one positive (l2)
      w = E.col(2) + std::sqrt(-l(2) / l(0)) * std::cos(phi) * E.col(0) + std::sqrt(-l(2) / l(1)) * std::sin(phi) * E.col(1);
    out.push_back(w.normalized());
  }
  return out;
}

void kummerFigure(Context& ctx) {
  const V3 d(0.3, 0.5, 0.9);  // principal moments d₁ < d₂ < d₃ (distinct: otherwise the complex degenerates)
  auto g = std::mt19937_64(1361);
  // the cone directions solve the complex equation; det M = ¼ of the printed (d₂−d₁)(d₁−d₃)(d₃−d₂)xyz (×2 for 2M)
  double worst = 0, det = 0;
  for (int t = 0; t < 20; ++t) {
    const V3 r = rv3(g);
    for (const V3& w : coneDirections(conicMatrix(d, r), 12)) worst = std::max(worst, abs(complexEquation(d, r, w)));
    const double printed = (d(1) - d(0)) * (d(0) - d(2)) * (d(2) - d(1)) * r.x() * r.y() * r.z();
    det = std::max(det, abs((2 * conicMatrix(d, r)).determinant() - 2 * printed));
  }
  ctx.checkResidual("sampled cone directions satisfy the complex equation (20 points × 12 lines)", worst, 1e-14);
  ctx.checkResidual("det of the book's conic matrix (= 2M) is 2(d₂−d₁)(d₁−d₃)(d₃−d₂)xyz (erratum 23: the factor 2)", det, 1e-15);
  // on a principal plane (z = 0) the cone degenerates into two planes: ω_z = 0 and (d₁−d₃)yω_x + (d₃−d₂)xω_y = 0
  const V3 r0(0.6, 0.5, 0.0);
  ctx.checkNear("det M = 0 on the principal plane z = 0 (Kummer surface)", 0.0, conicMatrix(d, r0).determinant(), 1e-17);
  if (!ctx.makeFigures()) return;
  rd::Scene s;
  s.title = "Line complex of a decoupled 2R: cones; Kummer surface = principal planes";
  s.axes = true;
  s.axesLength = 0.35;
  const rd::Color planeCols[3] = {rd::palette::vermillion.withAlpha(0.18f), rd::palette::bluishGreen.withAlpha(0.18f),
                                  rd::palette::skyBlue.withAlpha(0.22f)};
  for (int k = 0; k < 3; ++k)
    s.add(rd::parametricSurface(
        [&](double u, double v) {
          V3 p = V3::Zero();
          p((k + 1) % 3) = u;
          p((k + 2) % 3) = v;
          return p;
        },
        {-1.0, 1.0}, {-1.0, 1.0}, 2, 2, planeCols[k]));
  const std::vector<V3> pts = {V3(0.6, 0.5, 0.55), V3(-0.55, 0.6, -0.5), V3(0.55, -0.6, -0.45)};
  const rd::Color coneCol[3] = {rd::palette::blue, rd::palette::reddishPurple, rd::palette::orange};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::vector<V3> dirs = coneDirections(conicMatrix(d, pts[i]), 72);
    rd::Polyline rimA, rimB;  // the two nappes' rims at distance 0.3
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      rimA.p.push_back(V3(pts[i] + 0.3 * dirs[k]));
      rimB.p.push_back(V3(pts[i] - 0.3 * dirs[k]));
      if (k % 4) continue;
      rd::Polyline l;
      l.p = {V3(pts[i] - 0.3 * dirs[k]), V3(pts[i] + 0.3 * dirs[k])};
      l.c = coneCol[i];
      s.add(l);
    }
    rimA.p.push_back(rimA.p.front());
    rimB.p.push_back(rimB.p.front());
    rimA.c = rimB.c = coneCol[i];
    s.add(rimA);
    s.add(rimB);
    s.add(rd::sphere(pts[i], 0.02, coneCol[i]));
  }
  // the degenerate "cone" at r0 on z = 0: the two planes ω_z = 0 and (d₁−d₃)yω_x + (d₃−d₂)xω_y = 0
  const V3 n2 = V3((d(0) - d(2)) * r0.y(), (d(2) - d(1)) * r0.x(), 0).normalized();
  const V3 a2 = n2.cross(V3::UnitZ());
  for (int k = 0; k < 12; ++k) {
    const double phi = pi<double>() * k / 12;
    for (const V3& w : {V3(std::cos(phi), std::sin(phi), 0), V3(std::cos(phi) * a2 + std::sin(phi) * V3::UnitZ())}) {
      rd::Polyline l;
      l.p = {V3(r0 - 0.3 * w), V3(r0 + 0.3 * w)};
      l.c = rd::palette::black;
      s.add(l);
    }
  }
  s.add(rd::sphere(r0, 0.02, rd::palette::black));
  rd::Label lb;
  lb.at = r0;
  lb.text = "on z = 0: two planes";
  lb.offset = {10, 14};
  lb.pixelHeight = 22;
  s.add(lb);
  rd::renderPng(s, V3(1.3, -1.0, 0.8), {1200, 950}, ctx.figurePath("GF-13.6.1-kummer.png"));
  ctx.figure("GF-13.6.1-kummer.png", "The quadratic line complex of a decoupled 2R (principal moments 0.3, 0.5, 0.9): at three points "
                                    "off the principal planes the complex lines form quadratic cones (coloured); at a point of the "
                                    "plane z = 0 the cone splits into two planes (black). The Kummer surface det M = 0 is the union "
                                    "of the three principal planes (tinted).");
}

}  // namespace

SOMA_STUDY({.id = "GF-13-fig-kummer", .title = "Derived figure: the quadratic line complex and its Kummer surface (principal planes)",
            .source = "GF §13.6.1", .chapter = kChapter, .scalarGeneric = false, .run = kummerFigure, .whyDouble = "a figure: soma::render draws double geometry"});

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
