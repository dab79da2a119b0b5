// Studies of GF §11.5.2 and §11.5.4: the forward kinematics of Stewart–Gough platforms counted
// numerically — 40 complex postures of a general 6-6 platform, 16 of a 6-3 platform — by the
// homotopy solver of geometry/parallel/stewart.hpp, and the real postures of one platform drawn.
// Double precision (the solver is tested in all five scalars in tests/geometry/parallel).
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <random>

namespace soma::studies::gf11stewart {
namespace {

using S = double;
namespace rd = soma::render;
constexpr const char* kChapter = "GF 11 — The Study quadric";

double uni(std::mt19937_64& g, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }

/// A random general platform (joints not coplanar) and the posture that defines its leg lengths.
StewartPlatform<S> randomPlatform(std::mt19937_64& g, SE3<S>* pose) {
  StewartPlatform<S> P;
  for (int i = 0; i < 6; ++i) {
    P.base[i] = Vec3<S>(uni(g, -1, 1), uni(g, -1, 1), uni(g, -0.2, 0.2));
    P.platform[i] = Vec3<S>(uni(g, -0.6, 0.6), uni(g, -0.6, 0.6), uni(g, -0.1, 0.1));
  }
  Vec6<S> xi;
  xi << uni(g, -0.3, 0.3), uni(g, -0.3, 0.3), uni(g, -0.3, 0.3), uni(g, -0.2, 0.2), uni(g, -0.2, 0.2), uni(g, 0.8, 1.2);
  *pose = SE3Tangent<S>(xi).exp();
  P.legs = stewartLegLengths<S>(P, *pose);
  return P;
}

double nearest(const StewartForwardSolution<S>& s, const SE3<S>& g) {
  double best = 1e300;
  for (const auto& h : s.postures) best = std::min(best, (h.matrix() - g.matrix()).norm());
  return best;
}

/// Non-real solutions whose conjugate is not in the set (0 for a real platform).
int unpairedConjugates(const StewartForwardSolution<S>& s) {
  int n = 0;
  for (const auto& x : s.complex_solutions) {
    double im = 0;
    for (const auto& z : x) im = std::max(im, std::abs(z.imag()));
    if (im > Tolerance<S>::input() && !containsConjugate<S>(s.complex_solutions, x, Tolerance<S>::input())) ++n;
  }
  return n;
}

/// The platform of studies/platforms/general.json (irregular hexagons, joints off a plane).
StewartPlatform<S> examplePlatform() {
  StewartPlatform<S> P;
  const double b[6][3] = {{0.854648, 0.248159, 0.002365},   {0.806715, 0.596192, -0.055343},
                          {-0.668405, 0.732368, 0.056675},  {-0.954569, 0.316566, 0.053623},
                          {-0.19489, -0.936848, -0.052013}, {0.304459, -1.079584, 0.063352}};
  const double q[6][3] = {{0.48443, 0.136726, 0.018518},    {-0.142747, 0.423322, -0.024849},
                          {-0.24425, 0.452013, 0.030514},   {-0.241091, -0.381148, -0.042368},
                          {-0.196986, -0.460494, -0.020788}, {0.485676, -0.026128, 0.020398}};
  const double L[6] = {1.042060141, 1.415693982, 1.051051562, 1.443082953, 0.974698497, 1.427782454};
  for (int i = 0; i < 6; ++i) {
    P.base[i] = Vec3<S>(b[i][0], b[i][1], b[i][2]);
    P.platform[i] = Vec3<S>(q[i][0], q[i][1], q[i][2]);
    P.legs[i] = L[i];
  }
  return P;
}

/// The real postures of P drawn side by side: base (grey), legs (blue), platform (orange).
void postureGrid(Context& c, const StewartPlatform<S>& P, const StewartForwardSolution<S>& s, const std::string& file) {
  rd::Scene scene;
  scene.title = fmt::format("The {} real postures of one general 6-6 platform (of 40 complex solutions) for the same six leg lengths",
                            s.count());
  const int cols = 4;
  const double dx = 3.0, dz = 2.9;
  for (std::size_t k = 0; k < s.count(); ++k) {
    const Eigen::Vector3d o(dx * double(k % cols), 0.0, -dz * double(k / cols));
    std::vector<Eigen::Vector3d> base, top;
    for (int i = 0; i < 6; ++i) {
      base.push_back(P.base[i] + o);
      top.push_back(s.postures[k].act(P.platform[i]) + o);
    }
    rd::Tube bt;
    bt.p = base;
    bt.closed = true;
    bt.radius = 0.025;
    bt.c = rd::palette::darkGrey;
    scene.add(bt);
    rd::Tube pt;
    pt.p = top;
    pt.closed = true;
    pt.radius = 0.03;
    pt.c = rd::palette::orange;
    scene.add(pt);
    rd::Mesh m;  // the platform plate, a fan over its joint centres
    Eigen::Vector3d ctr = Eigen::Vector3d::Zero();
    for (const auto& v : top) ctr += v / 6.0;
    m.v = top;
    m.v.push_back(ctr);
    for (int i = 0; i < 6; ++i) m.tri.push_back(Eigen::Vector3i(6, i, (i + 1) % 6));
    m.c = rd::palette::orange.withAlpha(0.45f);
    scene.add(m);
    for (int i = 0; i < 6; ++i) {
      rd::Tube leg;
      leg.p = {base[i], top[i]};
      leg.radius = 0.018;
      leg.c = rd::palette::blue;
      scene.add(leg);
    }
    scene.add(rd::Points{base, rd::palette::darkGrey, 0.04});
    scene.add(rd::Points{top, rd::palette::vermillion, 0.04});
    rd::Label l;
    l.at = o + Eigen::Vector3d(0, 0, -1.2);
    l.text = fmt::format("{}: residual {:.1e}", k + 1, s.residuals[k]);
    l.hAlign = rd::HAlign::Center;
    l.vAlign = rd::VAlign::Top;
    l.pixelHeight = 20;
    scene.add(l);
  }
  const int w = 1500, h = 1050;
  rd::RenderOptions opt;
  opt.width = w;
  opt.height = h;
  rd::FitOptions fo;
  fo.width = w;
  fo.height = h;
  fo.orthographic = true;
  opt.camera = rd::Camera::fit(scene, Eigen::Vector3d(0.0, 1.0, -0.3), fo);
  rd::renderPng(scene, opt, c.figurePath(file));
  c.figure(file, fmt::format("GF Fig. 11.1 for a real platform: the {} real assembly modes of one general 6-6 "
                             "Stewart platform (studies/platforms/general.json) for the same six leg lengths, "
                             "found with the other {} complex solutions by homotopy continuation; each posture's "
                             "largest leg-length error relative to the platform size is printed under it.",
                             s.count(), s.complexCount() - static_cast<int>(s.count())));
}

// GF §11.5.4, GF-11.5.4-stewart-forty
void stewartForty(Context& c) {
  // The start system: a random complex platform solved by the total-degree homotopy (128 paths).
  const auto start = stewartStartPlatform<S>();
  const auto a = stewartTotalDegreeSolve(start, 1);
  const auto b = stewartTotalDegreeSolve(start, 9);
  c.checkEqual("random complex platform: finite solutions by a 2⁷ = 128-path total-degree homotopy", 40,
               static_cast<long long>(a.size()));
  int same = 0;
  for (const auto& x : b) {
    for (const auto& y : a) {
      double d = 0;
      for (int k = 0; k < 8; ++k) d = std::max(d, std::abs(x[k] - y[k]));
      if (d <= Tolerance<S>::input()) {
        ++same;
        break;
      }
    }
  }
  c.checkEqual("… the same 40 points from another set of gammas", 40, same);
  // The Study quadric's leg form (study/constraint_quadrics.hpp) and the solver's agree.
  {
    std::mt19937_64 g(1154);
    SE3<S> pose;
    const auto P = randomPlatform(g, &pose);
    const Vec8<S> v = StudyParameters<S>::fromSE3(pose).coeffs();
    StudyPointC<S> x;
    Vec8<S> w = v;
    w(5) += 0.1;  // off the variety: both forms must agree there too
    for (int k = 0; k < 8; ++k) x[k] = w(k);
    const auto f = stewartSystem<S>(stewartComplexPlatform<S>(P), x);
    double worst = 0;
    for (int i = 0; i < 6; ++i) {
      const Mat8<S> Q = sphereConstraintQuadric<S>(P.base[i], P.platform[i], P.legs[i]);
      worst = std::max(worst, std::abs(f[i + 1].real() - w.dot(Q * w)));
    }
    c.checkResidual("leg equation u·u − L²a·a = xᵀQx of the S–S sphere quadric (off the variety)", worst,
                    Tolerance<S>::identity(256));
  }
  // Random real general platforms.
  std::mt19937_64 g(2026);
  const int n = 20;
  int forty = 0, found = 0, evenReal = 0, unpaired = 0;
  double worstRes = 0, worstPose = 0;
  for (int t = 0; t < n; ++t) {
    SE3<S> pose;
    const auto P = randomPlatform(g, &pose);
    const auto s = solveStewartForward<S>(P);
    forty += s.complexCount() == 40;
    found += nearest(s, pose) <= Tolerance<S>::sqrtEpsilon();
    evenReal += s.count() % 2 == 0;
    unpaired += unpairedConjugates(s);
    worstRes = std::max(worstRes, s.worstResidual());
    worstPose = std::max(worstPose, nearest(s, pose));
  }
  c.checkEqual(fmt::format("random real 6-6 platforms with 40 complex solutions (of {})", n), n, forty);
  c.checkEqual("… the posture that defined the leg lengths is among the real ones", n, found);
  c.checkResidual("… distance of that posture (|ΔT|, 4×4) at worst", worstPose, Tolerance<S>::identity(1u << 14));
  c.checkResidual("… worst leg-length residual / platform size over all real postures", worstRes,
                  Tolerance<S>::identity(64));
  c.checkEqual("… platforms with an even number of real postures", n, evenReal);
  c.checkEqual("… non-real solutions without their conjugate", 0, unpaired);
  // Extreme: base and platform planar. Still 40; real postures come in mirror pairs M g M.
  {
    std::mt19937_64 g2(41);
    SE3<S> pose;
    auto P = randomPlatform(g2, &pose);
    for (int i = 0; i < 6; ++i) P.base[i](2) = P.platform[i](2) = 0;
    P.legs = stewartLegLengths<S>(P, pose);
    const auto s = solveStewartForward<S>(P);
    c.checkEqual("planar base and planar platform: complex solutions", 40, s.complexCount());
    const Mat3<S> Mz = Vec3<S>(1, 1, -1).asDiagonal();
    double worst = 0;
    for (const auto& h : s.postures) {
      Mat4<S> m = Mat4<S>::Identity();
      m.topLeftCorner<3, 3>() = Mz * h.rotation() * Mz;
      m.topRightCorner<3, 1>() = Mz * h.translation();
      double best = 1e300;
      for (const auto& k : s.postures) best = std::min(best, (k.matrix() - m).norm());
      worst = std::max(worst, best);
    }
    c.checkResidual(fmt::format("… its {} real postures pair up under the mirror in the base plane", s.count()), worst,
                    Tolerance<S>::identity(1u << 14));
  }
  // The example platform, drawn.
  const auto P = examplePlatform();
  const auto s = solveStewartForward<S>(P);
  c.checkEqual("example platform (studies/platforms/general.json): complex solutions", 40, s.complexCount());
  c.checkEqual("… real postures", 8, static_cast<long long>(s.count()));
  if (c.makeFigures() && s.count() > 0) postureGrid(c, P, s, "GF-11.5.4-stewart-postures.png");
}

// GF §11.5.2, GF-11.5.2-6-3-stewart-sixteen
void sixThree(Context& c) {
  std::mt19937_64 g(63);
  const int n = 5;
  int sixteen = 0, found = 0, failed = 0, singular = 0, expected = 0;
  for (int t = 0; t < n; ++t) {
    SE3<S> pose;
    auto P = randomPlatform(g, &pose);
    const std::array<Vec3<S>, 3> t3{P.platform[0], P.platform[2], P.platform[4]};
    for (int i = 0; i < 6; ++i) P.platform[i] = t3[((i + 1) / 2) % 3];
    P.legs = stewartLegLengths<S>(P, pose);
    const auto s = solveStewartForward<S>(P);
    sixteen += s.complexCount() == 16;
    expected += s.expected_count == 16;
    found += nearest(s, pose) <= Tolerance<S>::sqrtEpsilon();
    failed += s.paths_failed;
    singular += 40 - s.complexCount() - s.paths_at_infinity;
  }
  c.checkEqual(fmt::format("random 6-3 platforms with 16 finite nonsingular solutions (of {}), (2σ₄)³ = 16", n), n,
               sixteen);
  c.checkEqual("… recognised as 6-3 (expected_count 16)", n, expected);
  c.checkEqual("… the defining posture found", n, found);
  c.checkEqual("… paths that failed in tracking", 0, failed);
  c.checkEqual("… paths of the 40 that end at singular points of the degenerate system", 24 * n, singular);
}

#define GF11S_STUDY(ID, TITLE, SOURCE, FN) \
  SOMA_STUDY({.id = ID, .title = TITLE, .source = SOURCE, .chapter = kChapter, .scalarGeneric = false, .run = FN})

GF11S_STUDY("GF-11.5.4-stewart-forty",
            "General 6-6 Stewart platform: 40 complex forward-kinematics solutions (homotopy), real postures drawn",
            "GF §11.5.4", stewartForty);
GF11S_STUDY("GF-11.5.2-6-3-stewart-sixteen", "6-3 Stewart platform: 16 postures (the other 24 paths end singular)",
            "GF §11.5.2", sixThree);

}  // namespace
}  // namespace soma::studies::gf11stewart
