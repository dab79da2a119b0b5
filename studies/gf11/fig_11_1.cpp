// GF Fig. 11.1, "A General Stewart Platform" (§11.5.4): base and platform joined by six hydraulic
// legs with ball joints at both ends, the joint centres not coplanar. Drawn for the general
// platform of studies/platforms/general.json in one of its real assembly modes; what the figure
// shows is checked against independent values: the joint centres are off a plane, every drawn leg
// has its file length, and the real assembly modes soma finds are the real solutions PHCpack finds
// for the same platform. Double (PHCpack's).
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/study.hpp"
#include "platform_plate.hpp"
#include "stewart_phc.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>

#include <random>

namespace soma::studies::gf11fig1::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
constexpr const char* kChapter = "GF 11 — The Study quadric";
constexpr const char* kWhyDouble = "PHCpack, the independent solver, works in double";
namespace rd = soma::render;

/// Smallest singular value over the largest of the centred points: 0 iff they are coplanar.
double planarity(const std::array<Vec3<S>, 6>& pts) {
  Vec3<S> m = Vec3<S>::Zero();
  for (const auto& p : pts) m += p / 6.0;
  Eigen::Matrix<double, 6, 3> A;
  for (int i = 0; i < 6; ++i) A.row(i) = (pts[std::size_t(i)] - m).transpose();
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix<double, 6, 3>>(A).singularValues();
  return sv(2) / sv(0);
}

void drawFigure(Context& c, const StewartPlatform<S>& P, const StewartForwardSolution<S>& s, std::size_t shown,
                const std::string& file) {
  rd::Scene scene;
  scene.title = "GF Fig. 11.1: a general Stewart platform";
  std::vector<Eigen::Vector3d> base, top;
  for (int i = 0; i < 6; ++i) {
    base.push_back(P.base[std::size_t(i)]);
    top.push_back(s.postures[shown].act(P.platform[std::size_t(i)]));
  }
  gf11::addPlate(scene, base, rd::palette::darkGrey, 0.012, rd::palette::lightGrey);
  gf11::addPlate(scene, top, rd::palette::darkGrey, 0.012, rd::palette::orange.withAlpha(0.75f));
  for (int i = 0; i < 6; ++i) {
    // a hydraulic leg: the cylinder on the base joint, the thinner piston rod to the platform joint
    const Eigen::Vector3d a = base[std::size_t(i)], b = top[std::size_t(i)];
    rd::Tube cyl;
    cyl.p = {a, a + 0.58 * (b - a)};
    cyl.radius = 0.035;
    cyl.c = rd::palette::blue;
    scene.add(cyl);
    rd::Tube rod;
    rod.p = {a + 0.5 * (b - a), b};
    rod.radius = 0.018;
    rod.c = rd::palette::skyBlue;
    scene.add(rod);
    rd::Label l;
    l.at = a;
    l.text = fmt::format("{}", i + 1);
    l.pixelHeight = 20;
    l.offset = Eigen::Vector2d(8, 14);
    l.vAlign = rd::VAlign::Top;
    scene.add(l);
  }
  scene.add(rd::Points{base, rd::palette::darkGrey, 0.045});  // ball joints
  scene.add(rd::Points{top, rd::palette::vermillion, 0.045});
  rd::FitOptions fo;
  fo.width = 1200;
  fo.height = 1000;
  rd::renderPng(scene, Eigen::Vector3d(-0.55, 1.0, -0.22), fo, c.figurePath(file));
  c.figure(file, fmt::format("GF Fig. 11.1 redrawn: the general 6-6 platform of studies/platforms/general.json (joint "
                             "centres off a plane) in one of its {} real assembly modes for the same six leg lengths; "
                             "legs as cylinder and piston rod, ball joints as spheres, numbered at the base.",
                             s.count()));
}

void figure111(Context& c) {
  const auto P = io::readPlatform<S>(sourceRoot() / "studies/platforms/general.json");
  // The figure's claim "not necessarily coplanar": this platform's joints are off a plane.
  c.recordIn("base joint centres not coplanar: σ₃/σ₁ of the centred points", "> 1e-3", fmt::format("{:.3g}", planarity(P.base)),
             planarity(P.base), 1e-3, planarity(P.base) > 1e-3);
  c.recordIn("platform joint centres not coplanar: σ₃/σ₁", "> 1e-3", fmt::format("{:.3g}", planarity(P.platform)),
             planarity(P.platform), 1e-3, planarity(P.platform) > 1e-3);
  const auto s = solveStewartForward<S>(P);
  c.checkEqual("soma's forward kinematics: complex solutions (GF §11.5.4: 40)", 40, s.complexCount());
  // The drawn legs have the file's lengths (every real mode).
  double worstLeg = 0;
  for (const auto& g : s.postures)
    for (int i = 0; i < 6; ++i)
      worstLeg = std::max(worstLeg, std::abs((g.act(P.platform[std::size_t(i)]) - P.base[std::size_t(i)]).norm() - P.legs[std::size_t(i)]));
  c.checkResidual("every drawn leg |R qᵢ + t − pᵢ| has its file length Lᵢ (all real modes, 64ε·L)", worstLeg,
                  64 * Tolerance<S>::epsilon() * 2);
  // Independent: PHCpack on the same platform (six leg quadrics, the Study quadric, a random chart),
  // its real regular solutions off the exceptional plane a = 0.
  const PhcResult run = solveWithPhc(stewart_phc::equations(P, stewart_phc::randomChart(111)), stewart_phc::studyNames(), "fig111");
  const auto phc = stewart_phc::classify(run);
  c.note(fmt::format("PHCpack: {} paths, {} regular finite solutions, {} real; {:.1f} s.", run.paths, phc.finite, phc.real.size(), run.seconds));
  c.checkEqual("PHCpack: regular finite solutions (independent count, 40)", 40, phc.finite);
  c.checkEqual("real assembly modes drawn (soma) = PHCpack's real solutions", static_cast<long long>(phc.real.size()),
               static_cast<long long>(s.count()));
  c.checkResidual("every drawn mode is one of PHCpack's real solutions (1 − cos² in PR⁷)", stewart_phc::worstMatch(s.postures, phc.real), 1e-12);
  if (c.makeFigures() && s.count() > 0) {
    // Show the mode whose platform sits highest above the base (the figure's upright pose).
    std::size_t shown = 0;
    for (std::size_t k = 1; k < s.count(); ++k)
      if (s.postures[k].translation().z() > s.postures[shown].translation().z()) shown = k;
    drawFigure(c, P, s, shown, "GF-11-fig-11.1.png");
  }
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-11-fig-11.1", "Fig. 11.1: a general Stewart platform, its real assembly modes checked by PHCpack", "GF §11.5.4",
                  figure111);

}  // namespace soma::studies::gf11fig1::SOMA_UNITY_ID
