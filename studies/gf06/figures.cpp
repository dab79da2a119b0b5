// Figures of GF chapter 6 (rendered with soma::render, double only): Fig. 6.1 (a line and its
// Plücker vectors), Fig. 6.2 (the reguli of a hyperboloid), Fig. 6.3 (the cylindroid), Fig. 6.4
// (curvature axes at an elliptic and a hyperbolic point), Fig. 6.5 (joint axes of a 6R arm) and
// the lines of a linear complex through a few points.
#include "gf06/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/render.hpp"
#include "soma/render/scene_js.hpp"

namespace soma::studies::gf06 {  // not per-file (SOMA_UNITY_ID): it defines functions other chapter files call
namespace {

namespace rd = soma::render;

void addLabel(rd::Scene& s, const V3& at, const std::string& text, Eigen::Vector2d off = {8, -8},
              rd::HAlign ha = rd::HAlign::Left, double px = 22, rd::Color col = rd::palette::black) {
  rd::Label l;
  l.at = at;
  l.text = text;
  l.offset = off;
  l.hAlign = ha;
  l.pixelHeight = px;
  l.c = col;
  s.add(l);
}
void addSegment(rd::Scene& s, const V3& a, const V3& b, rd::Color c, double width = 2.5, bool dashed = false) {
  rd::Polyline p;
  p.p = {a, b};
  p.c = c;
  p.width = width;
  p.dashed = dashed;
  s.add(p);
}
void addTube(rd::Scene& s, const V3& a, const V3& b, rd::Color c, double radius) {
  rd::Tube t;
  t.p = {a, b};
  t.c = c;
  t.radius = radius;
  s.add(t);
}
void draw(Context& c, rd::Scene& scene, const V3& view, const std::string& file, const std::string& caption,
            int w = 1200, int h = 950, bool ortho = false) {
  rd::FitOptions fo;
  fo.width = w;
  fo.height = h;
  fo.orthographic = ortho;
  rd::renderPng(scene, view, fo, c.figurePath(file));
  // The same scene for the report's 3-D viewer.
  rd::writeSceneJs(rd::sceneJs(scene), c.figurePath(file.substr(0, file.size() - 4) + ".scene.js"));
  c.figure(file, caption);
}

// GF Fig. 6.1, GF-6.1-fig6.1-line
void fig61(Context& c) {
  const V3 q1(1.6, -0.4, 0.6), q2(0.4, 1.4, 1.5);
  const L l = L::throughPoints(q1, q2);
  const V3 w = l.direction(), v = l.moment(), f = l.foot();
  c.checkResidual("the drawn moment is q₁ × ω = q₂ × ω (convention A)", (q1.cross(w) - v).norm() + (q2.cross(w) - v).norm(), tolId(64));
  c.checkNear("foot ω × v/|ω|² is ⟂ ω", 0.0, f.dot(w), tolId(64));
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 6.1: the line through q₁, q₂ — direction ω = q₂ − q₁, moment v = q₁ × ω";
  s.axes = true;
  s.axesLength = 0.8;
  const V3 a = q1 - 0.6 * w, b = q2 + 0.6 * w;
  addTube(s, a, b, rd::palette::blue, 0.018);
  s.add(rd::Points{{q1, q2}, rd::palette::vermillion, 0.05});
  s.add(rd::Arrow{q1, q2, rd::palette::vermillion, 0.022});
  s.add(rd::Arrow{V3::Zero(), V3(v.normalized() * 1.0), rd::palette::bluishGreen, 0.022});
  addSegment(s, V3::Zero(), f, rd::palette::darkGrey, 2.0, true);
  s.add(rd::Points{{f}, rd::palette::darkGrey, 0.035});
  addSegment(s, V3::Zero(), q1, rd::palette::grey, 1.5, true);
  addLabel(s, q1, "q₁", {10, 10}, rd::HAlign::Left, 26);
  addLabel(s, q2, "q₂", {10, -8}, rd::HAlign::Left, 26);
  addLabel(s, V3((q1 + q2) / 2), "ω = q₂ − q₁", {14, 4}, rd::HAlign::Left, 24, rd::palette::vermillion);
  addLabel(s, V3(v.normalized()), "v = q₁ × ω (unit length)", {14, 4}, rd::HAlign::Left, 22,
           rd::palette::bluishGreen);
  addLabel(s, f, "foot ω × v/|ω|²", {-10, 12}, rd::HAlign::Right, 22);
  addLabel(s, V3::Zero(), "O", {-10, 10}, rd::HAlign::Right, 24);
  draw(c, s, V3(-0.35, -1.0, -0.3), "GF-6.1-fig6.1-line.png",
         "A line in three dimensions (Fig. 6.1) through q₁ = (1.6, −0.4, 0.6) and q₂ = (0.4, 1.4, 1.5): direction ω = q₂ − q₁ "
         "(vermillion), moment v = q₁ × ω (green, normalised; perpendicular to the plane through O and the line), and the "
         "foot of the perpendicular from O (dashed).");
}

// GF Fig. 6.2, GF-6.5.1-fig6.2-regulus
rd::Mesh hyperboloidMesh(double zmax, rd::Color col) {
  rd::Mesh m;
  m.c = col;
  const int nu = 72, nv = 24;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double t = 2 * pi<double>() * i / nu, z = -zmax + 2 * zmax * j / nv, r = std::sqrt(1 + z * z);
      m.v.push_back(V3(r * std::cos(t), r * std::sin(t), z));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * (nu + 1) + i, b = a + 1, cc = a + nu + 1, d = cc + 1;
      m.tri.push_back(Eigen::Vector3i(a, b, d));
      m.tri.push_back(Eigen::Vector3i(a, d, cc));
    }
  return m;
}
// Clip a line to |z| ≤ zmax (the line is not horizontal).
std::pair<V3, V3> clipZ(const L& l, double zmax) {
  const L u = l.normalized();
  const V3 f = u.foot(), d = u.direction();
  return {V3(f + (-zmax - f.z()) / d.z() * d), V3(f + (zmax - f.z()) / d.z() * d)};
}
void fig62(Context& c) {
  // Check first: every drawn family-1 line crosses every drawn family-2 line inside |z| ≤ 2 or at infinity.
  const int n = 16;
  double worst = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      worst = std::max(worst, std::abs(reciprocalProduct(bookRegulusLine(1, 2 * pi<double>() * i / n), bookRegulusLine(2, 2 * pi<double>() * j / n))));
  c.checkResidual("every drawn family-1 line meets every drawn family-2 line (16 × 16)", worst, tolId());
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 6.2: the two reguli of the hyperboloid x² + y² − z² = 1";
  s.add(hyperboloidMesh(2.0, rd::palette::lightGrey.withAlpha(0.35f)));
  for (int i = 0; i < n; ++i) {
    const double th = 2 * pi<double>() * i / n;
    const auto [a1, b1] = clipZ(L(bookRegulusLine(1, th)), 2.0);
    addTube(s, a1, b1, rd::palette::blue, 0.022);
    const auto [a2, b2] = clipZ(L(bookRegulusLine(2, th + pi<double>() / n)), 2.0);
    addTube(s, a2, b2, rd::palette::vermillion, 0.022);
  }
  rd::Polyline throat;
  for (int k = 0; k <= 120; ++k) throat.p.push_back(V3(std::cos(2 * pi<double>() * k / 120), std::sin(2 * pi<double>() * k / 120), 0));
  throat.c = rd::palette::darkGrey;
  throat.width = 2;
  throat.dashed = true;
  s.add(throat);
  addLabel(s, V3(0, 0, 2.4), "blue: family 1 (p₀₁ = p₂₃, p₀₂ = p₃₁, p₀₃ = −p₁₂)     vermillion: family 2", {0, -6}, rd::HAlign::Center, 22);
  draw(c, s, V3(-1.0, -0.4, -0.25), "GF-6.5.1-fig6.2-regulus.png",
         "The regulus of a hyperboloid (Fig. 6.2): 16 lines of each family of x² + y² − z² = 1 from the book's Plücker "
         "coordinates, clipped to |z| ≤ 2; each blue line crosses each vermillion one; dashed: the throat circle.");
}

// GF Fig. 6.3, GF-6.5.2-fig6.3-cylindroid
void fig63(Context& c) {
  const double l = 1.0, phi = pi<double>() / 3;
  const V6 s1 = six(V3(1, 0, 0), V3::Zero());
  const V6 s2 = six(V3(std::cos(phi), std::sin(phi), 0), V3(-l * std::sin(phi), l * std::cos(phi), 0));
  const Cylindroid<double> cy(s1, s2);
  double onCubic = 0;
  for (int k = 0; k < 60; ++k) {
    const L ax = cy.axis(pi<double>() * k / 60);
    for (const double t : {-1.0, 1.0}) {
      const V3 p = ax.pointAt(t);
      onCubic = std::max(onCubic, std::abs(p.z() * (p.x() * p.x() + p.y() * p.y()) - l * (p.y() * p.y() + p.x() * p.y() / std::tan(phi))));
    }
  }
  c.checkResidual("drawn axes lie on z(x² + y²) = l(y² + xy cot φ) (corrected, E6.3)", onCubic, tolId(1024));
  c.checkNear("nodal segment: z from the centre spans h₁ − h₂ = l/sin φ", l / std::sin(phi), cy.pitchMax() - cy.pitchMin(), tolId());
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 6.3: the cylindroid of s₁ and s₂ (l = 1, φ = 60°), axes coloured by pitch";
  const double R = 1.6;
  const double hmin = cy.pitchMin(), hmax = cy.pitchMax();
  // Surface: ρ ∈ [−R, R] along each axis direction, θ ∈ [0, π).
  rd::Mesh m;
  const int nt = 180, nr = 16;
  std::vector<rd::Color> colours;
  for (int i = 0; i <= nt; ++i) {
    const double th = pi<double>() * i / nt;
    const L ax = cy.axis(th);
    const V3 base = cy.centre() + cy.height(th) * cy.frame().col(2), d = ax.direction();
    for (int j = 0; j <= nr; ++j) m.v.push_back(V3(base + (-R + 2 * R * j / nr) * d));
  }
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < nr; ++j) {
      const int a = i * (nr + 1) + j, b = a + 1, cc = a + nr + 1, d = cc + 1;
      m.tri.push_back(Eigen::Vector3i(a, b, d));
      m.tri.push_back(Eigen::Vector3i(a, d, cc));
    }
  m.c = rd::palette::lightGrey.withAlpha(0.45f);
  s.add(m);
  for (int i = 0; i < 24; ++i) {
    const double th = pi<double>() * i / 24;
    const L ax = cy.axis(th);
    const V3 base = cy.centre() + cy.height(th) * cy.frame().col(2), d = ax.direction();
    addTube(s, V3(base - R * d), V3(base + R * d), rd::colorMap((cy.pitch(th) - hmin) / (hmax - hmin)), 0.014);
  }
  // The two generating lines, the nodal line and the bounding cylinder's rims.
  addTube(s, V3(-R, 0, 0), V3(R, 0, 0), rd::palette::vermillion, 0.026);
  const V3 d2(std::cos(phi), std::sin(phi), 0), p2(0, 0, l);
  addTube(s, V3(p2 - R * d2), V3(p2 + R * d2), rd::palette::vermillion, 0.026);
  const V3 zc = cy.centre(), ez = cy.frame().col(2);
  addSegment(s, V3(zc - 1.2 * ez), V3(zc + 1.2 * ez), rd::palette::black, 3.0, true);
  for (const double zz : {cy.height(pi<double>() / 4), cy.height(-pi<double>() / 4)}) {
    rd::Polyline rim;
    for (int k = 0; k <= 120; ++k) {
      const double t = 2 * pi<double>() * k / 120;
      rim.p.push_back(V3(zc + zz * ez + R * (std::cos(t) * cy.frame().col(0) + std::sin(t) * cy.frame().col(1))));
    }
    rim.c = rd::palette::grey;
    rim.width = 1.2;
    s.add(rim);
  }
  addLabel(s, V3(R, 0, 0), "s₁", {8, 8}, rd::HAlign::Left, 26, rd::palette::vermillion);
  addLabel(s, V3(p2 + R * d2), "s₂", {8, -4}, rd::HAlign::Left, 26, rd::palette::vermillion);
  addLabel(s, V3(zc + 1.2 * ez), "nodal line", {8, -4}, rd::HAlign::Left, 22);
  addLabel(s, V3(zc - 1.2 * ez), "pitch: dark blue h₂ = " + num(hmin) + " … yellow h₁ = " + num(hmax), {0, 28}, rd::HAlign::Center, 22);
  draw(c, s, V3(-1.0, -0.8, -0.42), "GF-6.5.2-fig6.3-cylindroid.png",
         "The cylindroid (Plücker's conoid, Fig. 6.3) of the pencil of s₁ = x-axis and s₂ (height l = 1, angle φ = 60°): 24 axes "
         "coloured by pitch (viridis, h₂ = −0.289 … h₁ = 0.866 per radian), the translucent surface z(x² + y²) = l(y² + xy cot φ) "
         "(corrected sign, E6.3) inside a cylinder of radius 1.6, the two generators (vermillion) and the nodal line (dashed).");
}

// GF Fig. 6.4, GF-6.5.3-fig6.4-curvature-axes
void curvaturePanel(rd::Scene& s, double kx, double ky, const V3& offset, double zclip, const std::string& label) {
  // Local quadric patch k_x x² + k_y y² = 2z.
  rd::Mesh m;
  const int n = 30;
  const double r = 0.9;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -r + 2 * r * i / n, y = -r + 2 * r * j / n;
      m.v.push_back(V3(offset + V3(x, y, 0.5 * (kx * x * x + ky * y * y))));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, cc = a + n + 1, d = cc + 1;
      m.tri.push_back(Eigen::Vector3i(a, b, d));
      m.tri.push_back(Eigen::Vector3i(a, d, cc));
    }
  m.c = rd::palette::skyBlue.withAlpha(0.55f);
  s.add(m);
  // Normal at the point and axes of curvature for φ ∈ [0, π).
  addSegment(s, offset, V3(offset + V3(0, 0, zclip)), rd::palette::darkGrey, 2.0, true);
  const int na = 36;
  for (int i = 0; i < na; ++i) {
    const double phi = pi<double>() * i / na;
    const V6 a = curvatureAxis(kx, ky, std::cos(phi), std::sin(phi));
    const L ax(a);
    if (ax.isAtInfinity()) continue;
    const V3 f = ax.foot();
    if (std::abs(f.z()) > zclip) continue;  // beyond the drawn box (near asymptotic directions)
    const V3 d = ax.unitDirection();
    const double len = 0.8;
    addTube(s, V3(offset + f - len * d), V3(offset + f + len * d), rd::colorMap(double(i) / na), 0.012);
  }
  s.add(rd::Points{{offset}, rd::palette::vermillion, 0.04});
  addLabel(s, V3(offset + V3(0, 0, 2.9)), label, {0, -10}, rd::HAlign::Center, 24);
}
void fig64(Context& c) {
  // The axis in direction φ is at height 1/k_φ: check both panels' extremes.
  c.checkNear("elliptic (k_x = 1, k_y = 2.5): highest axis at 1/k_x = 1", 1.0, L(curvatureAxis(1.0, 2.5, 1.0, 0.0)).foot().z(), tolId());
  c.checkNear("… lowest at 1/k_y = 0.4", 0.4, L(curvatureAxis(1.0, 2.5, 0.0, 1.0)).foot().z(), tolId());
  c.checkNear("hyperbolic (k_x = 1, k_y = −1.5): 1/k_y = −0.667 below the point", -1 / 1.5, L(curvatureAxis(1.0, -1.5, 0.0, 1.0)).foot().z(), tolId());
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 6.4: axes of curvature at an elliptic point (left) and a hyperbolic point (right)";
  curvaturePanel(s, 1.0, 2.5, V3(0, 0, 0), 1.1, "k_x = 1, k_y = 2.5 (k_x k_y > 0)");
  curvaturePanel(s, 1.0, -1.5, V3(0, 3.2, 0), 2.6, "k_x = 1, k_y = −1.5 (k_x k_y < 0)");
  draw(c, s, V3(-1.0, -0.12, -0.22), "GF-6.5.3-fig6.4-curvature-axes.png",
         "Lines of curvature axes for two surface points (Fig. 6.4): the local quadric k_x x² + k_y y² = 2z (blue), its normal "
         "(dashed) and the axes s(φ) through (0, 0, 1/k_φ) perpendicular to the direction φ (colour: φ from 0 to π). Left: "
         "elliptic point, the axes fill a segment of the normal between 1/k_y and 1/k_x (a cylindroid-like cubic). Right: "
         "hyperbolic point, the axes go to infinity at the asymptotic directions k_φ = 0 (axes beyond |z| = 2.6 are not drawn).",
         1400, 900, true);
}

// GF Fig. 6.5, GF-6.7-fig6.5-6R-joints
void fig65(Context& c) {
  PumaLikeArm<double> a;
  a.w1 = V3::UnitZ();
  a.w2 = V3(std::cos(0.5), std::sin(0.5), 0);
  const V3 e = a.w1.cross(a.w2);
  a.xe = 0.9 * e + 0.5 * a.w1;
  a.xc = a.xe + 0.9 * (std::cos(-0.6) * e + std::sin(-0.6) * a.w1);
  a.w4 = (a.xc - a.xe).normalized();
  a.w5 = V3(0.3, 0.2, 1.0).normalized().cross(a.w4).normalized();
  a.w6 = (0.5 * a.w4 + 0.8 * a.w5 + 0.3 * a.w4.cross(a.w5)).normalized();
  const Mat6<double> j = a.jacobian();
  const auto z = pumaLikeReciprocalLines(a);
  const Mat6<double> w = inverseJacobianFromReciprocals(j, z);
  c.checkResidual("drawn configuration: W J = I", (w * j - Mat6<double>::Identity()).norm(), 1e-12);
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Fig. 6.5: joint axes of the PUMA-like 6R arm";
  const double len = 0.75;
  const V3 pts[6] = {V3::Zero(), V3::Zero(), a.xe, a.xc, a.xc, a.xc};
  for (int i = 0; i < 6; ++i) {
    const V3 d = j.col(i).head<3>().normalized();
    const V3 mid = (i == 3) ? V3((a.xe + a.xc) / 2) : pts[i];
    const double ext = (i == 3) ? len + 0.45 : len;
    addTube(s, V3(mid - ext * d), V3(mid + ext * d), rd::palette::cycle(i), 0.018);
    addLabel(s, V3(mid + ext * d), std::to_string(i + 1), {6, -6}, rd::HAlign::Left, 28, rd::palette::cycle(i));
  }
  // Links o–x_e–x_c.
  addTube(s, V3::Zero(), a.xe, rd::palette::lightGrey, 0.05);
  addTube(s, a.xe, a.xc, rd::palette::lightGrey, 0.05);
  s.add(rd::Points{{V3::Zero(), a.xe, a.xc}, rd::palette::black, 0.045});
  addLabel(s, V3::Zero(), "O", {-10, 14}, rd::HAlign::Right, 26);
  addLabel(s, a.xe, "x_e", {-10, -6}, rd::HAlign::Right, 26);
  addLabel(s, a.xc, "x_c", {12, 16}, rd::HAlign::Left, 26);
  // Reciprocal line z₁ (through x_c ∥ ω₂) and z₃ (through O and x_c), dashed.
  addSegment(s, V3(a.xc - 0.9 * a.w2), V3(a.xc + 0.9 * a.w2), rd::palette::darkGrey, 2.0, true);
  addLabel(s, V3(a.xc + 0.9 * a.w2), "z₁", {6, -6}, rd::HAlign::Left, 22, rd::palette::darkGrey);
  addSegment(s, V3(-0.3 * a.xc), V3(1.35 * a.xc), rd::palette::darkGrey, 2.0, true);
  addLabel(s, V3(1.35 * a.xc), "z₃", {6, -6}, rd::HAlign::Left, 22, rd::palette::darkGrey);
  draw(c, s, V3(-0.55, -1.0, -0.35), "GF-6.7-fig6.5-6R-joints.png",
         "The arrangement of joints in the 6R arm of §6.7 (Fig. 6.5) in a general configuration: axes 1 and 2 meet at O, "
         "axis 3 is parallel to 2 through the elbow x_e, axis 4 runs from x_e to the wrist centre x_c, axes 5 and 6 pass "
         "through x_c; dashed: the reciprocal lines z₁ (through x_c parallel to axis 2) and z₃ (through O and x_c) that give "
         "rows 1 and 3 of J⁻¹ by inspection.");
}

}  // namespace

// Suggested figure for GF-6.6-linear-complex (called from that study): the pencils of complex
// lines through points.
void complexFigure(Context& c) {
  const double h = 0.35;
  const LinearComplex<double> cc = LinearComplex<double>::fromAxisPitch(L::pointDirection(V3::Zero(), V3::UnitZ()), h);
  // The null planes at points (ρ, 0, 0) tilt by atan(ρ/h) about the radius: check.
  double worst = 0;
  for (const double rho : {0.5, 1.0, 1.5}) {
    const V3 n = cc.nullPlane(V3(rho, 0, 0)).normal();
    worst = std::max(worst, std::abs(std::atan2(std::hypot(n.x(), n.y()), n.z()) - std::atan2(rho, h)));
  }
  c.checkResidual("null plane at distance ρ from the axis is tilted by atan(ρ/h) from horizontal", worst, tolId(64));
  if (!c.makeFigures()) return;
  rd::Scene s;
  s.title = "Linear complex of pitch h = 0.35 about the z-axis: the lines through a few points";
  addSegment(s, V3(0, 0, -1.6), V3(0, 0, 1.9), rd::palette::black, 3.0, true);
  addLabel(s, V3(0, 0, 1.9), "axis (pitch h = 0.35)", {8, -4});
  std::vector<V3> pts;
  for (int k = 0; k < 6; ++k) {
    const double t = 2 * pi<double>() * k / 6;
    pts.push_back(V3(1.2 * std::cos(t), 1.2 * std::sin(t), 0.25 * k - 0.6));
  }
  pts.push_back(V3(0.45, 0.0, 1.2));
  pts.push_back(V3(0, 0, -1.2));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const V3 y = pts[i];
    const rd::Color col = rd::palette::cycle(i);
    const V3 n = cc.nullPlane(y).normal().normalized();
    for (int k = 0; k < 10; ++k) {
      const L l = cc.lineThrough(y, pi<double>() * k / 10);
      const V3 d = l.unitDirection();
      addSegment(s, V3(y - 0.42 * d), V3(y + 0.42 * d), col, 2.2);
    }
    // The null plane as a translucent disc.
    rd::Mesh disc;
    const V3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    disc.v.push_back(y);
    for (int k = 0; k <= 40; ++k) {
      const double t = 2 * pi<double>() * k / 40;
      disc.v.push_back(V3(y + 0.42 * (std::cos(t) * e1 + std::sin(t) * e2)));
      if (k > 0) disc.tri.push_back(Eigen::Vector3i(0, k, k + 1));
    }
    disc.c = col.withAlpha(0.25f);
    s.add(disc);
    s.add(rd::Points{{y}, col, 0.035});
  }
  addLabel(s, pts.back(), "on the axis: null plane normal to the axis", {60, 14});
  draw(c, s, V3(-1.0, -0.6, -0.5), "GF-6.6-linear-complex-pencils.png",
         "The lines of the linear complex with axis z and pitch h = 0.35 through eight points: at each point the complex lines "
         "form a plane pencil in the null plane (disc), which turns about the radius by atan(ρ/h) as the distance ρ from the "
         "axis grows — horizontal on the axis, nearly vertical far from it (the planes twist along helices about the axis).");
}

namespace {

namespace figures_only {  // the reason below is these studies' only
constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";
SOMA_STUDY_DOUBLE("GF-6.1-fig6.1-line", "Fig. 6.1: a line through two points with its Plücker vectors", "GF §6.1", fig61);
SOMA_STUDY_DOUBLE("GF-6.5.1-fig6.2-regulus", "Fig. 6.2: the two reguli of a hyperboloid", "GF §6.5.1", fig62);
SOMA_STUDY_DOUBLE("GF-6.5.2-fig6.3-cylindroid", "Fig. 6.3: the cylindroid", "GF §6.5.2", fig63);
SOMA_STUDY_DOUBLE("GF-6.5.3-fig6.4-curvature-axes", "Fig. 6.4: curvature axes at an elliptic and a hyperbolic point", "GF §6.5.3", fig64);
SOMA_STUDY_DOUBLE("GF-6.7-fig6.5-6R-joints", "Fig. 6.5: joint axes of the PUMA-like 6R arm", "GF §6.7", fig65);
}  // namespace figures_only

}  // namespace
}  // namespace soma::studies::gf06
