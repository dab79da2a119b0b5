// GF §11.5.1 (GF-11.5.1-6R-sixteen): the count 16 of the general 6R is reached by real postures.
// GF cites Manseur & Doty (IJRR 8(5), 1989) for a 6R with 16 real postures but gives no
// parameters; the ones used here are Manocha & Canny's (IEEE T-RA 10(5), 1994, Table I: problem 6
// of Wampler & Morgan 1991, "a slight variation" of the Manseur–Doty arm, twists 90°, 1°, 90°,
// 1°, 90°, 1°), with their hand pose A_hand and their 16 postures (Table III, degrees, 2 decimals)
// as the reference. The same robot and pose are studies/robots/manseur_doty{,_pose}.json.
// Runs in the asked scalar (--scalar; the solver escalates a short float answer itself); the
// cross-check against another rung, the Ceres alternative and the figure run in double.
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/geometry/serial/serial_robot.hpp"
#include "soma/geometry/study/intersection_ring.hpp"
#include "soma/render/render.hpp"
#include "soma/render/scene_js.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
namespace rd = soma::render;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

template <class T> Robot6R<T> manseurDoty() {
  // a, alpha (degrees), d; theta offsets 0 (Manocha & Canny Table I, standard DH).
  const double rows[6][3] = {{0.3, 90, 0}, {1.0, 1, 0}, {0, 90, 0.2}, {1.5, 1, 0}, {0, 90, 0}, {0, 1, 0}};
  Robot6R<T> r;
  for (int i = 0; i < 6; ++i)
    r[i] = {JointType::Revolute, scalarCast<T>(rows[i][0]), scalarCast<T>(rows[i][1]) * pi<T>() / T(180),
            scalarCast<T>(rows[i][2]), T(0)};
  return r;
}

// Manocha & Canny's A_hand (4 digits; signs as the forward kinematics of their Table III gives
// them), projected onto SO(3) by the polar iteration R ← (R + R⁻ᵀ)/2 (defect of the printed
// matrix 2.4e-4): the same numbers as studies/robots/manseur_doty_pose.json.
template <class T> SE3<T> manseurDotyPose() {
  // Wider than double: the double pose converted exactly (the 17-digit matrix is orthogonal to
  // double's precision only, and SO3::fromMatrix in long double/float128/mpfr rightly refuses it).
  if constexpr (!std::is_same_v<T, float> && !std::is_same_v<T, double>)
    return manseurDotyPose<double>().template cast<T>();
  Mat3<T> R;
  R << scalarCast<T>(-0.7601416939437986), scalarCast<T>(-0.6416653151941663), scalarCast<T>(0.10222635866068862),
      scalarCast<T>(0.13328325043221534), scalarCast<T>(2.149749638863032e-07), scalarCast<T>(0.991077986413873),
      scalarCast<T>(-0.6359403905103651), scalarCast<T>(0.7669847607851965), scalarCast<T>(0.08552307548725724);
  return SE3<T>(SO3<T>::fromMatrix(R), Vec3<T>(scalarCast<T>(-1.1401), T(0), T(0)));
}

// Manocha & Canny Table III: the 16 postures (degrees, rounded to 0.01°).
constexpr double kTable3[16][6] = {
    {-96.28, -6.27, 179.96, 38.48, 52.55, -39.40},     {-120.78, 172.33, -179.07, 31.33, -146.71, 142.82},
    {88.67, -176.72, -176.72, -63.24, 157.19, 140.43},  {113.84, 5.30, -177.74, -55.92, -62.98, -43.37},
    {-178.12, 108.19, -147.73, -5.69, -164.67, 179.58}, {168.32, -103.89, 146.60, -17.24, -171.87, 98.16},
    {-12.94, -105.09, -114.97, 3.02, 7.41, -79.42},     {2.51, 108.07, 112.04, -10.52, 0.00, -0.10},
    {2.51, 108.07, -67.95, -169.47, 179.99, 179.89},    {-12.94, -105.09, 65.02, 176.97, 172.58, 100.57},
    {168.32, -103.89, -33.39, -162.75, -8.12, -81.83},  {-178.12, 108.19, 32.26, -174.30, -15.32, -0.41},
    {88.67, -176.72, 3.27, -116.75, 22.80, -39.56},     {-96.28, -6.27, -0.03, 141.51, 127.44, 140.59},
    {-120.78, 172.33, 0.92, 148.66, -33.28, -37.17},    {113.84, 5.30, 2.25, -124.07, -117.01, 136.62}};

// Largest joint difference in degrees, angles compared on the circle.
template <class T> double angleGap(const std::array<double, 6>& degrees, const JointVector<T>& q) {
  double g = 0;
  for (int i = 0; i < 6; ++i) {
    const double d = std::remainder(degrees[i] - toDouble(q(i)) / kDeg, 360.0);
    g = std::max(g, std::abs(d));
  }
  return g;
}

// The arm at q drawn from its DH frames: the link polyline o_{i-1} → o_{i-1} + d_i z_{i-1} → o_i
// (the offset along joint i's axis, then the common normal a_i), and a short bar along every
// joint axis, so that the two wrist postures with the same links still differ on the page.
void addArm(rd::Scene& scene, const SerialRobot<S>& arm, const Robot6R<S>& rows, const JointVector<S>& q,
            rd::Color linkColour) {
  const auto F = arm.frames(q);
  rd::Tube links;
  links.c = linkColour;
  links.radius = 0.035;
  for (int i = 0; i < 6; ++i) {
    const Vec3<S> o = F[i].translation(), z = F[i].rotation().col(2);
    links.p.push_back(o);
    links.p.push_back(o + rows[i].d * z);
  }
  links.p.push_back(F[6].translation());
  scene.add(links);
  for (int i = 0; i < 6; ++i) {
    const Vec3<S> z = F[i].rotation().col(2), at = F[i].translation() + rows[i].d * z;
    rd::Tube axis;
    axis.c = rd::palette::grey;
    axis.radius = 0.04;
    axis.p = {at - 0.16 * z, at + 0.16 * z};
    scene.add(axis);
  }
  scene.add(rd::Frame{F[6].matrix(), 0.35});
}

// GF §11.5.1 (proposed render (d) of the catalogue): the 16 real postures, a 4 × 4 grid, one
// camera for every panel.
void drawPostures(Context& c, const Robot6R<S>& rows, const SE3<S>& T, const General6RSolution<S>& sol) {
  std::vector<DHRow<S>> table(rows.begin(), rows.end());
  const auto arm = SerialRobot<S>::fromDH(table, DHConvention::Standard);
  // Postures in order of (θ1, θ2, θ3): the pairs that share θ1, θ2 sit side by side.
  std::vector<JointVector<S>> qs = sol.postures;
  std::sort(qs.begin(), qs.end(), [](const JointVector<S>& a, const JointVector<S>& b) {
    for (int i = 0; i < 3; ++i)
      if (std::abs(a(i) - b(i)) > 1e-9) return a(i) < b(i);
    return false;
  });
  const int pw = 420, ph = 440, cols = 4, banner = 56;
  const Eigen::Vector3d view(-0.35, -1.0, -0.45);
  rd::Scene all;
  for (const auto& q : qs) addArm(all, arm, rows, q, rd::palette::blue);
  rd::FitOptions fo;
  fo.width = pw;
  fo.height = ph;
  fo.margin = 0.02;
  const rd::Camera cam = rd::Camera::fit(all, view, fo);
  const rd::Color colours[8] = {rd::palette::blue,          rd::palette::vermillion, rd::palette::bluishGreen,
                                rd::palette::orange,        rd::palette::reddishPurple, rd::palette::skyBlue,
                                rd::Color::hex(0x8C564B), rd::Color::hex(0x6A3D9A)};
  rd::Image grid;
  grid.width = cols * pw;
  grid.height = banner + int((qs.size() + cols - 1) / cols) * ph;
  grid.rgba.assign(std::size_t(grid.width) * grid.height * 4, 255);
  auto blit = [&](const rd::Image& im, int x0, int y0) {
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) std::copy_n(im.pixel(x, y), 4, grid.pixel(x0 + x, y0 + y));
  };
  {
    rd::Scene head;
    head.title = fmt::format("{} real postures of one 6R for one tool pose (Manseur–Doty arm, Wampler–Morgan "
                             "variant; pose of Manocha & Canny 1994)", qs.size());
    head.titlePixelHeight = 22;
    rd::RenderOptions o;
    o.width = grid.width;
    o.height = banner;
    o.camera = rd::Camera::lookAt({0, -5, 0}, {0, 0, 0});
    blit(rd::render(head, o), 0, 0);
  }
  std::vector<std::pair<std::string, rd::Scene>> views;  // the postures together, for the 3-D viewer
  for (std::size_t k = 0; k < qs.size(); ++k) {
    rd::Scene s;
    addArm(s, arm, rows, qs[k], colours[(k / 2) % 8]);
    s.add(rd::Frame{Mat4<S>::Identity(), 0.35});
    rd::Label tool;
    tool.at = T.translation();
    tool.text = "tool";
    tool.pixelHeight = 15;
    s.add(tool);
    s.title = fmt::format("{}: ({:.1f}, {:.1f}, {:.1f}, {:.1f}, {:.1f}, {:.1f})°", k + 1, qs[k](0) / kDeg,
                          qs[k](1) / kDeg, qs[k](2) / kDeg, qs[k](3) / kDeg, qs[k](4) / kDeg, qs[k](5) / kDeg);
    s.titlePixelHeight = 16;
    views.emplace_back(s.title, s);
    rd::RenderOptions o;
    o.width = pw;
    o.height = ph;
    o.camera = cam;
    blit(rd::render(s, o), int(k % cols) * pw, banner + int(k / cols) * ph);
  }
  // Thin separating lines between the panels.
  for (int x = 0; x < grid.width; ++x)
    for (int r = 1; r < (grid.height - banner) / ph; ++r) std::fill_n(grid.pixel(x, banner + r * ph), 3, 200);
  for (int y = banner; y < grid.height; ++y)
    for (int col = 1; col < cols; ++col) std::fill_n(grid.pixel(col * pw, y), 3, 200);
  const std::string file = "GF-11.5.1-6R-sixteen.png";
  rd::writePng(grid, c.figurePath(file));
  rd::writeSceneJs(rd::sceneJs(views, fmt::format("The {} real postures of the Manseur–Doty arm for one tool pose", qs.size())),
                   c.figurePath("GF-11.5.1-6R-sixteen.scene.js"));
  c.figure(file, "The 16 real postures of the Manseur–Doty arm (Wampler–Morgan variant: a = (0.3, 1, 0, 1.5, 0, 0), "
                 "d = (0, 0, 0.2, 0, 0, 0), α = (90°, 1°, 90°, 1°, 90°, 1°)) reaching Manocha & Canny's hand pose, "
                 "seen by one camera: links as tubes (offset d along each joint axis, then the common normal a), "
                 "joint axes as grey bars, the base frame and the tool frame (red x, green y, blue z). Panels in order "
                 "of (θ1, θ2, θ3); the two postures of a pair share θ1, θ2 and a colour.");
}

/// Largest joint difference (rad, on the circle) from each posture of a to its nearest in b.
template <class A, class B> double worstNearest(const General6RSolution<A>& a, const General6RSolution<B>& b) {
  double agree = 0;
  for (std::size_t m = 0; m < a.count(); ++m) {
    double best = 1e300;
    for (std::size_t n = 0; n < b.count(); ++n) {
      double d = 0;
      for (int i = 0; i < 6; ++i)
        d = std::max(d, std::abs(std::remainder(toDouble(b.postures[n](i)) - toDouble(a.postures[m](i)), 2 * pi<double>())));
      best = std::min(best, d);
    }
    agree = std::max(agree, best);
  }
  return agree;
}

// GF §11.5.1, GF-11.5.1-6R-sixteen (16 = (2σ_A + 4σ_B)², reached by 16 real postures), in the
// scalar W asked for.
template <class W> void sixteen(Context& c) {
  using C = StudyClass;
  c.checkEqual("the count: (2σ_A + 4σ_B)² on the Study quadric", 16, (2 * C::sigmaA() + 4 * C::sigmaB()).pow(2).degree());
  const Robot6R<W> robot = manseurDoty<W>();
  const SE3<W> T = manseurDotyPose<W>();
  const General6RSolution<W> sol = solveGeneral6R<W>(robot, T);
  c.checkEqual("complex solutions of the eigenproblem", 16, sol.complex_count);
  c.checkEqual("real postures (Manseur–Doty arm, Wampler–Morgan variant, Manocha–Canny pose)", 16, int(sol.count()));
  // Residual max(‖R − R*‖_F, ‖t − t*‖/L) of each posture after the Newton polish: rounding of the
  // forward chain, a few ulps per link.
  c.checkResidual("worst pose residual of the 16 postures", sol.worstResidual(), Tolerance<W>::identity(256));
  c.note(fmt::format("solved in {}: eigenproblem solved in {}; leading-matrix rcond {:.3g}; smallest relative gap "
                     "between real x3 = tan(θ3/2) values {:.3g}; {:.3g} ms", scalarName<W>(),
                     sol.solved_in, sol.leading_rcond, sol.min_gap, 1e3 * sol.seconds));
  for (const auto& n : sol.notes) c.note("solver: " + n);

  // The reference: every posture of Table III is one of soma's, each matched once. The table is
  // rounded to 0.01° and the pose to 4 digits; the rounded pose moves the postures by at most
  // cond·5e-5 rad — measured below as the FK defect of the table's postures — so the match
  // tolerance is 0.05° (≈ 1e-3 rad, a tenth of the smallest distance between two postures).
  std::array<int, 16> matchedBy;
  matchedBy.fill(-1);
  double worstGap = 0, tableDefect = 0;
  int matched = 0;
  for (int k = 0; k < 16; ++k) {
    std::array<double, 6> ref;
    std::copy(std::begin(kTable3[k]), std::end(kTable3[k]), ref.begin());
    std::array<W, 6> qr;
    for (int i = 0; i < 6; ++i) qr[i] = scalarCast<W>(ref[i] * kDeg);
    tableDefect = std::max(tableDefect, toDouble(general6rResidual<W>(robot, T, qr)));
    int best = -1;
    double bestGap = 1e300;
    for (std::size_t m = 0; m < sol.count(); ++m) {
      const double g = angleGap(ref, sol.postures[m]);
      if (g < bestGap) bestGap = g, best = int(m);
    }
    if (best >= 0 && bestGap <= 0.05 && std::count(matchedBy.begin(), matchedBy.end(), best) == 0) {
      matchedBy[k] = best;
      ++matched;
    }
    worstGap = std::max(worstGap, bestGap);
  }
  c.checkEqual("Manocha–Canny Table III postures matched one-to-one by soma's (≤ 0.05°)", 16, matched);
  c.checkResidual("largest joint difference to Table III (degrees; table rounded to 0.01°)", worstGap, 0.05);
  c.checkResidual("pose defect of Table III's rounded postures (the data's own precision)", tableDefect, 1e-3);
  double minDist = 1e300;
  for (std::size_t a = 0; a < sol.count(); ++a)
    for (std::size_t b = a + 1; b < sol.count(); ++b) {
      double d = 0;
      for (int i = 0; i < 6; ++i)
        d = std::max(d, std::abs(std::remainder(toDouble(sol.postures[a](i)) - toDouble(sol.postures[b](i)), 2 * pi<S>())));
      minDist = std::min(minDist, d);
    }
  c.note(fmt::format("smallest distance between two of the 16 postures: {:.4f} rad ({:.2f}°)", minDist, minDist / kDeg));
  c.record("the 16 postures are distinct: smallest joint distance between two", "> 0.01 rad",
           fmt::format("{:.4f} rad", minDist), 0, 0.01, minDist > 0.01);

  // The same 16 in another rung: for float and double the next one (long double), for the wider
  // rungs double; the postures agree to the conditioning of the problem in the narrower scalar.
  using Other = std::conditional_t<(std::is_same_v<W, float> || std::is_same_v<W, double>), long double, double>;
  using Narrow = std::conditional_t<std::is_same_v<W, float>, float, double>;
  const auto sl = solveGeneral6R<Other>(manseurDoty<Other>(), manseurDotyPose<Other>());
  c.checkEqual(std::string("real postures in ") + std::string(scalarName<Other>()), 16, int(sl.count()));
  c.checkResidual(fmt::format("{} vs {} postures (largest joint difference, rad)", scalarName<W>(), scalarName<Other>()),
                  worstNearest(sol, sl), toDouble(Tolerance<Narrow>::sqrtEpsilon()));

  // Ceres and the figure work in double.
  const Robot6R<S> robotD = manseurDoty<S>();
  const SE3<S> TD = manseurDotyPose<S>();
  General6RSolution<S> solD;
  if constexpr (std::is_same_v<W, S>) solD = sol;
  else solD = solveGeneral6R<S>(robotD, TD);
  // The numerical alternative (Ceres, 64 random starts) on the same problem: every posture it
  // returns is one of the 16, and how many of them it finds.
  const auto ce = solveGeneral6RCeres(robotD, TD);
  int ceresKnown = 0;
  for (const auto& p : ce.postures) {
    bool known = false;
    for (const auto& q : solD.postures) {
      double d = 0;
      for (int i = 0; i < 6; ++i) d = std::max(d, std::abs(std::remainder(p(i) - q(i), 2 * pi<S>())));
      known = known || d <= Tolerance<S>::sqrtEpsilon();
    }
    ceresKnown += known;
  }
  c.checkEqual("every Ceres posture (64 starts) is one of the 16", int(ce.count()), ceresKnown);
  c.note(fmt::format("Ceres multi-start (64 starts, seed 1) finds {} of the 16 real postures", ce.count()));

  if (!c.makeFigures()) return;
  drawPostures(c, robotD, TD, solD);
}

const std::string kChapter = "GF 11 — The Study quadric";

SOMA_STUDY({.id = "GF-11.5.1-6R-sixteen",
            .title = "16 real postures of a 6R: the Manseur–Doty arm (Wampler–Morgan variant) by the eigenproblem",
            .source = "GF §11.5.1", .chapter = kChapter, .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class W>() { sixteen<W>(c); }); }});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
