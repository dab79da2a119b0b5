// Studies of GF §5.2.3 (singularities of 3R arms, cusps, cuspidal robots), in double (each study
// says why: OMPL, geometry/cuspidal's double-only det J series and cuspidality analysis): the cusp
// points of an orthogonal arm by two methods, Fig. 5.2 "circling a cusp" reproduced by IK
// continuation, a witness path planned with OMPL, and the bifurcation claim (at det J = 0 two
// roots of the IK equation coalesce).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/witness6r.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/cuspidal_figures.hpp"
#include "soma/studies/workspace_figures.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <Eigen/LU>

#include <cmath>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
const char* kChapter = "GF 5 — A little kinematics";
constexpr double kPi = 3.14159265358979323846;

SerialRobot<S> dhArm(double a1, double d2, double a2, double a3, double d3, const std::string& name) {
  auto row = [](double a, double al, double d) {
    DHRow<S> r;
    r.a = a;
    r.alpha = al;
    r.d = d;
    return r;
  };
  return SerialRobot<S>::fromDH({row(a1, -kPi / 2, 0), row(a2, kPi / 2, d2), row(a3, 0, d3)},
                                DHConvention::Standard, SE3<S>(), SE3<S>(), name);
}

/// Verheye's orthogonal arm a = (1, 1.5, 1), d2 = 0.7.
SerialRobot<S> test3R() { return dhArm(1, 0.7, 1.5, 1, 0, "orthogonal 3R (Verheye)"); }

/// Orthogonal arm (d2, d3, d4, r2, r3) = (1, 2, 1.5, 1, 0) in Wenger's notation.
SerialRobot<S> wengerArm() { return dhArm(1, 1, 2, 1.5, 0, "orthogonal 3R (1, 2, 1.5, 1, 0)"); }

Mat3<S> pointJacobian(const SerialRobot<S>& robot, const JointVector<S>& q) {
  const JacobianMatrix<S> Js = robot.spatialJacobian(q);
  const Vec3<S> p = robot.fk(q).translation();
  Mat3<S> J;
  for (int i = 0; i < 3; ++i) J.col(i) = Vec3<S>(Js.block<3, 1>(3, i)) + Vec3<S>(Js.block<3, 1>(0, i)).cross(p);
  return J;
}

double wrappedDistance(const JointVector<S>& a, const JointVector<S>& b) {
  double d = 0;
  for (int i = 0; i < a.size(); ++i) d = std::max(d, std::abs(std::remainder(a(i) - b(i), 2 * kPi)));
  return d;
}

/// The robot drawn as tubes through its DH frame origins (and tool point) at a few postures of a
/// path: start (green) and goal (purple) solid, ghosts in between light and translucent, the tool
/// point's trace in black. GF §5.2.3 (a witness path as the robot moving).
void renderRobotPath(const SerialRobot<S>& robot, const std::vector<JointVector<S>>& path, int ghosts,
                     const std::string& title, const std::filesystem::path& png, const Eigen::Vector3d& viewDir) {
  namespace rd = soma::render;
  rd::Scene scene;
  scene.title = title;
  const double L = robot.lengthScale();
  auto chain = [&](const JointVector<S>& q) {
    std::vector<Eigen::Vector3d> pts;
    pts.push_back(robot.base().translation());
    for (const auto& f : robot.frames(q)) {
      const Eigen::Vector3d p = f.translation();
      if ((p - pts.back()).norm() > 1e-9 * L) pts.push_back(p);
    }
    const Eigen::Vector3d tool = robot.fk(q).translation();
    if ((tool - pts.back()).norm() > 1e-9 * L) pts.push_back(tool);
    return pts;
  };
  auto draw = [&](const JointVector<S>& q, rd::Color c, double radius) {
    rd::Tube t;
    t.p = chain(q);
    t.radius = radius;
    t.c = c;
    scene.add(t);
    rd::Points j;
    j.p = t.p;
    j.radius = 1.5 * radius;
    j.c = c;
    scene.add(j);
  };
  const std::size_t n = path.size();
  for (int g = 1; g <= ghosts; ++g) {
    const std::size_t k = std::min(n - 1, std::size_t(double(g) / double(ghosts + 1) * double(n - 1)));
    draw(path[k], rd::Color::hex(0x9AA5B1, 0.35f), 0.006 * L);
  }
  draw(path.front(), rd::palette::bluishGreen, 0.009 * L);
  draw(path.back(), rd::palette::reddishPurple, 0.009 * L);
  rd::Polyline trace;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    // Shortest arcs: a path state wrapped at ±π is next to one just across.
    JointVector<S> d = path[k + 1] - path[k];
    for (int i = 0; i < d.size(); ++i) d(i) = std::remainder(d(i), 2 * kPi);
    for (int t = 0; t < 8; ++t) trace.p.push_back(robot.fk(JointVector<S>(path[k] + d * (t / 8.0))).translation());
  }
  trace.p.push_back(robot.fk(path.back()).translation());
  trace.width = 3;
  scene.add(trace);
  rd::Points base;
  base.p = {robot.base().translation()};
  base.radius = 0.02 * L;
  base.c = rd::palette::black;
  scene.add(base);
  rd::renderPng(scene, viewDir, {1200, 1000}, png);
}

// GF §5.2.3, GF-5.2.3-cuspidal-posture-change: cusp points by the triple-root condition and by
// tracing; Fig. 5.2 by continuation around a cusp; a witness path with OMPL.
void cuspidalPostureChange(Context& c) {
  const SerialRobot<S> robot = wengerArm();
  const CuspidalAnalysis r = analyseCuspidality(robot);
  const auto& cusps = r.cusps.cusps;
  const double L = r.cusps.frame.scale;
  c.checkEqual("cusp points of the orthogonal arm (1, 2, 1.5, 1, 0): triple root of the IK equation", 4,
               (long long)cusps.size());
  c.checkEqual("cusp points by a second method: the traced image of det J = 0 turns back", (long long)cusps.size(),
               (long long)r.reversals.size());
  double worstMatch = 0;
  for (const auto& k : cusps) {
    double best = 1e300;
    for (const auto& v : r.reversals) best = std::min(best, std::hypot(v(0) - k.rho, v(1) - k.z));
    worstMatch = std::max(worstMatch, best);
  }
  // The traced reversal is located to within a step of the continuation (0.004 rad in joints).
  c.checkResidual("each traced reversal lies at an algebraic cusp point (max distance / L)", worstMatch / L, 0.02);
  double worstTriple = 0, worstPosture = 0;
  for (const auto& k : cusps) {
    const Vec3<S> f = ikFunction(r.cusps.frame, k.rho, k.z, k.posture(2) + robot.joints()[2].offset);
    worstTriple = std::max(worstTriple, f.cwiseAbs().maxCoeff() / std::pow(L, 4));
    worstPosture = std::max(worstPosture, k.residual);
  }
  c.checkResidual("f = f′ = f″ = 0 at every cusp (IK equation in θ3, / L⁴)", worstTriple, Tolerance<S>::identity(4096));
  c.checkResidual("the triple-root posture reaches its cusp point (/ L)", worstPosture, Tolerance<S>::identity());
  c.checkEqual("the z ↦ −z symmetry of an arm with c1 = 0: cusps in ± pairs", 1,
               cusps.size() == 4 && std::abs(cusps[0].z + cusps[3].z) < 1e-9 * L && std::abs(cusps[1].z + cusps[2].z) < 1e-9 * L);
  c.checkEqual("aspects (components of det J ≠ 0 in (θ2, θ3))", 2, r.aspectMap.count());
  c.note(fmt::format("verdict in {:.3f} ms (cusp polynomial of degree {}, {} real candidates)", 1e3 * r.verdictSeconds,
                     int(r.cusps.polynomial.size()) - 1, r.cusps.candidates));

  // Fig. 5.2: circle of radius 0.02 L about the upper cusp, started inside the 4-posture wedge.
  const auto& k = cusps.back();
  const Arm3RFrame<S>& fr = r.cusps.frame;
  const double rad = 0.02 * L;
  auto pointAt = [&](double s) {
    return Vec3<S>(fr.c + (k.rho + rad * std::cos(s)) * fr.ex + (k.z + rad * std::sin(s)) * fr.ez);
  };
  const int N = 4000;
  int runStart = -1, runLen = 0, bestStart = -1, bestLen = 0;
  for (int i = 0; i < 2 * N; ++i) {
    const int count = int(solveArm3R<S>(robot, SE3<S>(SO3<S>(), pointAt(2 * kPi * (i % N) / N))).count());
    if (count == 4) {
      if (runStart < 0) runStart = i, runLen = 0;
      ++runLen;
      if (runLen > bestLen && runLen < N) bestLen = runLen, bestStart = runStart;
    } else {
      runStart = -1;
    }
  }
  c.checkEqual("the circle about the cusp meets the 4-posture wedge", 1, bestLen > 0);
  if (bestLen == 0) return;
  const double s0 = 2 * kPi * (bestStart + bestLen / 2.0) / N;
  const Solution<S> start = solveArm3R<S>(robot, SE3<S>(SO3<S>(), pointAt(s0)));
  // Continue each start posture around the circle in both directions (Newton on the position).
  int changed = 0, folded = 0;
  std::vector<Eigen::Vector2d> liftedJoints;
  std::vector<Eigen::Vector2d> circle;
  for (int i = 0; i <= 400; ++i) {
    const Vec3<S> p = pointAt(2 * kPi * i / 400);
    circle.emplace_back(std::hypot((p - fr.c).dot(fr.ex), (p - fr.c).dot(fr.ey)), (p - fr.c).dot(fr.ez));
  }
  for (std::size_t i = 0; i < start.count(); ++i)
    for (int dir : {1, -1}) {
      JointVector<S> q = start.postures[i];
      const double sign0 = pointJacobian(robot, q).determinant() > 0 ? 1 : -1;
      bool ok = true;
      std::vector<Eigen::Vector2d> lift;
      for (int step = 1; step <= N && ok; ++step) {
        const Vec3<S> target = pointAt(s0 + dir * 2 * kPi * step / N);
        for (int it = 0; it < 20; ++it) {
          const Vec3<S> e = target - robot.fk(q).translation();
          if (e.norm() <= 1e-13 * L) break;
          const Mat3<S> J = pointJacobian(robot, q);
          q += J.partialPivLu().solve(e);
        }
        const double det = pointJacobian(robot, q).determinant();
        ok = (robot.fk(q).translation() - target).norm() <= 1e-10 * L && det * sign0 > 0;
        lift.emplace_back(q(1), q(2));
      }
      if (!ok) {
        ++folded;
        continue;
      }
      bool isSolution = false;
      for (const auto& qs : start.postures) isSolution = isSolution || wrappedDistance(qs, q) < 1e-7;
      if (isSolution && wrappedDistance(start.postures[i], q) > 1e-3) {
        ++changed;
        if (liftedJoints.empty()) liftedJoints = lift;
      }
    }
  c.checkEqual("GF Fig. 5.2: postures that return to the start point in ANOTHER posture, det J of one sign", 2,
               changed);
  c.note(fmt::format("{} of 8 continuations (4 postures × 2 directions) met a fold (det J → 0) and stopped", folded));

  // The witness path planned with OMPL.
  const WitnessPath& w = r.witness;
  c.checkEqual("OMPL found a witness path (two postures of one point, det J of one sign)", 1, w.found);
  if (w.found) {
    c.checkResidual("witness: both ends reach the target (/ L)", std::max(w.startResidual, w.goalResidual),
                    Tolerance<S>::sqrtEpsilon());
    c.checkEqual("witness: sign·det J > 0 at every checked point, certified between them", 1,
                 w.minSignedDet > 0 && w.certified);
    c.checkEqual("witness: the two postures differ", 1, wrappedDistance(w.start, w.goal) > 1e-3);
    c.note(fmt::format("witness: {} path states, {} checked points, min |det J| {:.3g}, OMPL {:.2f} s", w.path.size(),
                       w.checkedPoints, w.minSignedDet, w.seconds));
  }

  if (c.makeFigures()) {
    const std::string name = robot.name();
    for (const std::string f : {"gf05_cusp_joint.png", "gf05_cusp_joint.svg"})
      plotJointSpace(r, "Aspects and det J = 0 of the orthogonal arm (1, 2, 1.5, 1, 0)", c.figurePath(f));
    c.figure("gf05_cusp_joint.png",
             "Joint space (θ2, θ3): the two aspects (det J > 0 blue, < 0 orange), the singular curves and the four "
             "triple-root postures (red).");
    for (const std::string f : {"gf05_cusp_section.png", "gf05_cusp_section.svg"})
      plotSection(r, "Workspace section of the orthogonal arm: four cusps", c.figurePath(f));
    c.figure("gf05_cusp_section.png",
             "Images of det J = 0 in (ρ, z): the four cusp points from the degree-12 cusp polynomial (red) and "
             "where the traced image turns back (black dots).");
    if (w.found) {
      for (const std::string f : {"gf05_cusp_witness.png", "gf05_cusp_witness.svg"})
        plotWitness(r, "A posture change without singularity (OMPL RRTConnect)", c.figurePath(f));
      c.figure("gf05_cusp_witness.png",
               "The witness: two postures of one point joined inside one aspect; det J keeps its sign.");
      std::vector<JointVector<S>> path;
      for (const auto& x : w.path) path.push_back(JointVector<S>(x));
      renderRobotPath(robot, path, 5, "The witness as the arm moving: same tool point, another posture, det J ≠ 0",
                      c.figurePath("gf05_cusp_witness_robot.png"), Eigen::Vector3d(-0.35, -1.0, -0.3));
      c.figure("gf05_cusp_witness_robot.png",
               "The witness path as the arm moving: start posture (green), goal posture (purple) at the same tool "
               "point, five translucent ghosts in between, the tool point's trace (black); det J keeps its sign.");
    }
    // Fig. 5.2: the circle about the cusp and the lifted posture path.
    render::Plot plot;
    plot.title = "GF Fig. 5.2: circling a cusp changes the posture";
    plot.x.label = "ρ";
    plot.y.label = "z";
    plot.equalAspect = true;
    plot.legend = render::LegendCorner::BottomLeft;
    bool first = true;
    for (const auto& b : r.branches) {
      std::vector<double> xs, ys;
      for (const auto& s : b.section)
        if (std::hypot(s(0) - k.rho, s(1) - k.z) < 3 * rad) {
          xs.push_back(s(0));
          ys.push_back(s(1));
        } else if (!xs.empty()) {
          plot.add(first ? "det J = 0 (image)" : "", xs, ys, render::palette::blue).width = 3;
          first = false;
          xs.clear();
          ys.clear();
        }
      if (!xs.empty()) {
        plot.add(first ? "det J = 0 (image)" : "", xs, ys, render::palette::blue).width = 3;
        first = false;
      }
    }
    std::vector<double> cx, cy;
    for (const auto& p : circle) cx.push_back(p(0)), cy.push_back(p(1));
    plot.add("the circle about the cusp", cx, cy, render::palette::vermillion).width = 3;
    auto& m = plot.add("cusp", {k.rho}, {k.z}, render::palette::black);
    m.line = false;
    m.markers = true;
    m.markerRadius = 8;
    const Vec3<S> ps = pointAt(s0);
    auto& st = plot.add("start and end point (4 postures)", {std::hypot((ps - fr.c).dot(fr.ex), (ps - fr.c).dot(fr.ey))},
                        {(ps - fr.c).dot(fr.ez)}, render::palette::bluishGreen);
    st.line = false;
    st.markers = true;
    st.markerRadius = 8;
    render::renderPlotPngAndSvg(plot, c.figurePath("gf05_cusp_circling.png"), 1000, 1000);
    c.figure("gf05_cusp_circling.png",
             "GF Fig. 5.2: a circle of radius 0.02 L about a cusp; a posture continued once around it returns to "
             "the start point in another posture with det J of one sign.");
  }
}

// GF §5.2.3, GF-5.2.3-bifurcation-factorisation: at a configuration with det J = 0 two roots of
// the IK equation coalesce (f = f′ = 0 at the posture's θ3), and not at a regular one.
void bifurcation(Context& c) {
  const SerialRobot<S> robot = wengerArm();
  const CuspAnalysis<S> cusps = findCusps(robot);
  const DetJSeries dj = detJSeries(robot);
  const auto branches = traceSingularCurves(robot, dj, 0.05, 8);
  double worst = 0, regularMin = 1e300;
  int n = 0;
  const double L4 = std::pow(cusps.frame.scale, 4);
  for (const auto& b : branches)
    for (std::size_t i = 0; i < b.joints.size(); i += 7) {
      const double th3 = b.joints[i](1) + robot.joints()[2].offset;
      const Vec3<S> f = ikFunction(cusps.frame, b.section[i](0), b.section[i](1), th3);
      worst = std::max(worst, std::max(std::abs(f(0)) / L4, std::abs(f(1)) / L4));
      ++n;
      // A regular configuration nearby (0.3 rad off in θ2): a simple root, f′ ≠ 0.
      JointVector<S> q(3);
      q << 0, b.joints[i](0) + 0.3, b.joints[i](1);
      if (std::abs(dj.value(q(1), q(2))) > 0.05 * dj.scale) {
        const Vec2<S> ws = workspaceSection(cusps.frame, robot, q);
        const Vec3<S> g = ikFunction(cusps.frame, ws(0), ws(1), S(q(2) + robot.joints()[2].offset));
        regularMin = std::min(regularMin, std::abs(g(1)) / L4);
      }
    }
  c.checkResidual(fmt::format("f = f′ = 0 (a double root) at {} traced singular configurations (/ L⁴)", n), worst,
                  Tolerance<S>::identity(4096));
  c.checkEqual("at regular configurations f′ ≠ 0 (a simple root)", 1, regularMin > Tolerance<S>::sqrtEpsilon());
  c.note(fmt::format("smallest |f′|/L⁴ at the regular configurations: {:.3g}", regularMin));
}

// Parameter-space map of orthogonal 3R arms (Baili, Wenger, Chablat 2004): cusp counts over
// (a2, a3) = (d3, d4) in Wenger's notation with d2 = 1, r2 = 1, r3 = 0, in parallel (TBB), and
// the traced second method at sample points of every region.
void cuspMapStudy(Context& c) {
  const SerialRobot<S> base = wengerArm();
  const ParameterAxis x = parseParameterAxis("a2:0.2:4:100"), y = parseParameterAxis("a3:0.2:3:100");
  const CuspMap m = cuspMap(base, x, y, 2);
  std::vector<int> hist(32, 0);
  for (int k : m.counts) ++hist[std::size_t(std::min(k, 31))];
  // Baili, Wenger, Chablat 2004: an orthogonal 3R arm has 0, 2 or 4 cusps (odd counts only on the
  // measure-zero boundaries where two merge); a count outside 0…4 would be a failed classification.
  long long outside = 0;
  for (int k : m.counts) outside += k < 0 || k > 4;
  c.checkEqual(fmt::format("arms of the {} × {} map with a cusp count outside 0…4 (at most 4: Baili–Wenger–Chablat 2004)",
                           x.n, y.n),
               0, outside);
  c.checkEqual("the literature arm (1, 2, 1.5, 1, 0): 4 cusps", 4,
               (long long)findCuspsAdaptive(mapArm(base, x, 2.0, y, 1.5)).cusps.size());
  c.note(fmt::format("counts: 0 cusps {} arms, 2 cusps {}, 4 cusps {}, other {} (arms on a boundary where two cusps merge); "
                     "{} escalated to float128/mpfr; {:.2f} s on {} TBB threads",
                     hist[0], hist[2], hist[4], 10000 - hist[0] - hist[2] - hist[4], m.escalated, m.seconds, m.threads));
  // Second method at a 4 × 4 grid of sample arms.
  std::vector<MapCheckPoint> checks;
  int agree = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const int i = 6 + a * 29, j = 6 + b * 29;
      const SerialRobot<S> arm = mapArm(base, x, x.value(i), y, y.value(j));
      const auto rev = imageReversals(traceSingularCurves(arm, detJSeries(arm)));
      MapCheckPoint k{x.value(i), y.value(j), m.count(i, j), int(rev.size())};
      agree += k.algebraic == k.traced;
      checks.push_back(k);
    }
  c.checkEqual("traced count (image reversals) = map count at 16 sample arms", 16, agree);
  if (c.makeFigures()) {
    for (const std::string f : {"gf05_cusp_map.png", "gf05_cusp_map.svg"})
      plotCuspMap(m, "Cusp points of orthogonal 3R arms over (a2, a3) = (d3, d4)", c.figurePath(f), checks);
    c.figure("gf05_cusp_map.png",
             "Number of cusp points of the orthogonal arms (d2, d3, d4, r2, r3) = (1, a2, a3, 1, 0), 100 × 100 arms "
             "(algebraic, TBB); the numbers are the traced count at 16 sample arms (black dots: it agrees).");
  }
}

// Workspace probing with OMPL: reachability and dexterity from the state sampler, the boundary
// from the singular curves, a plan that keeps σmin ≥ margin between the witness postures.
void workspaceStudy(Context& c) {
  const SerialRobot<S> robot = test3R();
  const WorkspaceMaps m = sampleWorkspace(robot, 200000, 120);
  const auto boundary = singularImages(robot);
  double singularMax = 0, sampledMax = 0;
  for (const auto& b : boundary)
    for (const auto& p : b) singularMax = std::max(singularMax, p.norm());
  for (const auto& p : m.points) sampledMax = std::max(sampledMax, p.norm());
  c.checkEqual("farthest sampled reach ≤ farthest point of the singular images (the outer boundary is singular)", 1,
               sampledMax <= singularMax * (1 + Tolerance<S>::sqrtEpsilon()));
  c.checkResidual("… and the samples come within 1 % of it", std::max(0.0, 1 - sampledMax / singularMax), 0.01);
  c.note(fmt::format("{} OMPL samples in {:.2f} s; {:.1f} % of the bounding grid reached; mean σmin/σmax {:.3f}", m.samples,
                     m.seconds, 100 * m.reachedFraction, m.meanDexterity));
  const CuspidalAnalysis r = analyseCuspidality(robot);
  SafePath plan;
  if (r.witness.found) {
    const double margin = 0.5 * std::min(dexteritySingularValues(robot, r.witness.start)(0),
                                         dexteritySingularValues(robot, r.witness.goal)(0));
    plan = planAwayFromSingularities(robot, r.witness.start, r.witness.goal, margin, 3.0);
    c.checkEqual("a plan between the witness postures keeping σmin ≥ ½ min(σmin at the ends)", 1, plan.found);
    if (plan.found)
      c.note(fmt::format("plan: {} states, min σmin {:.4f} ≥ margin {:.4f} over a dense check, {:.2f} s", plan.path.size(),
                         plan.minSigma, plan.margin, plan.seconds));
  }
  if (c.makeFigures()) {
    for (const std::string f : {"gf05_workspace_reach.png", "gf05_workspace_reach.svg"})
      plotReachability(m, boundary, "Reachability of the Verheye arm (OMPL samples per cell)", c.figurePath(f));
    c.figure("gf05_workspace_reach.png",
             "Samples per (ρ, z) cell from OMPL's uniform state sampler (log colour), and the images of det J = 0: "
             "they bound the workspace and the 4-posture region (denser: four postures map there).");
    std::vector<Eigen::Vector2d> trace;
    if (plan.found) {
      const Arm3RFrame<S>& f = r.cusps.frame;
      for (const auto& q : plan.path) trace.push_back(workspaceSection(f, robot, q));
    }
    for (const std::string f : {"gf05_workspace_dexterity.png", "gf05_workspace_dexterity.svg"})
      plotDexterity(m, boundary, trace, "Dexterity of the Verheye arm (best σmin/σmax per cell)", c.figurePath(f));
    c.figure("gf05_workspace_dexterity.png",
             "Best inverse condition number of the point Jacobian per cell; black: the tool point along the plan.");
    if (plan.found) {
      for (const std::string f : {"gf05_workspace_plan.png", "gf05_workspace_plan.svg"})
        plotPathSigma(robot, plan, "σmin along the plan (OMPL RRTConnect)", c.figurePath(f));
      c.figure("gf05_workspace_plan.png", "Distance from the singularities along the plan, and the margin asked.");
    }
  }
}

// 6R witness search: PUMA 560 (not cuspidal, det J factors) and a cuspidal 6R (the orthogonal
// arm + spherical wrist, the IRB 6400C architecture) — the search, compared with the decomposition.
void witness6RStudy(Context& c) {
  const SerialRobot<S> puma = puma560Robot<S>();
  Witness6ROptions po;
  po.poses = 2;
  po.secondsPerPair = 0.1;
  const Witness6R wp = findWitness6R(puma, po);
  c.checkEqual("PUMA 560: no witness after 2 poses (it is not cuspidal; the search says 'not a proof')", 1,
               !wp.found && wp.note.find("not a proof") != std::string::npos);
  c.note(fmt::format("PUMA: {} postures, {} same-sign pairs planned, {:.1f} s", wp.posturesSeen, wp.pairsTried, wp.seconds));
  const SerialRobot<S> cusp6 = orthogonalWristRobot<S>();
  Witness6ROptions co;
  co.poses = 8;
  const Witness6R w = findWitness6R(cusp6, co);
  c.checkEqual("orthogonal arm (1, 2, 1.5, 1, 0) + spherical wrist: a witness found", 1, w.found);
  if (!w.found) return;
  c.checkResidual("both ends reach the pose", std::max(w.startResidual, w.goalResidual), Tolerance<S>::sqrtEpsilon());
  c.checkEqual("sign·det J > 0 over the dense check of the path", 1, w.minSignedDet > 0);
  c.note(fmt::format("witness ({}) after {} poses, {} pairs: {} path states, min sign·det J / L³ {:.3g} (margin {:.3g}), {:.1f} s",
                     w.planner, w.posesTried, w.straightTried, w.path.size(), w.minSignedDet, w.margin, w.seconds));
  if (c.makeFigures()) {
    renderRobotPath(cusp6, w.path, 5, "A cuspidal 6R changes posture without a singularity",
                    c.figurePath("gf05_cusp_witness_6r.png"), Eigen::Vector3d(-0.35, -1.0, -0.3));
    c.figure("gf05_cusp_witness_6r.png",
             "6R witness (joint-space search, det J of one sign): start (green) and goal (purple) "
             "postures reach the same pose; ghosts in between; the tool point's trace in black.");
  }
}

// Decided by decomposition (decomposition.hpp): a spherical wrist gives the positioning arm's
// verdict; three parallel axes next to a meeting pair (UR) are never cuspidal. And a general 6R
// from the literature, the FANUC CRX-10iA (non-Pieper, modified DH), found cuspidal by the search.
void decomposition6RStudy(Context& c) {
  CuspidalOptions o;
  o.aspectGrid = 128;
  const SerialRobot<S> cusp6 = orthogonalWristRobot<S>();
  const CuspidalAnalysis a = analyseCuspidality(cusp6, o);
  c.checkEqual("orthogonal arm + wrist: decomposed by its spherical wrist", 1,
               a.decomposition.kind == CuspidalDecompositionKind::SphericalWrist);
  c.checkEqual("orthogonal arm + wrist: cuspidal (exact: the arm's 4 cusp points)", 4, (long long)a.cusps.cusps.size());
  c.checkEqual("orthogonal arm + wrist: the arm's witness lifted to the 6R (orientation held)", 1, a.witness6r.found);
  if (a.witness6r.found)
    c.note(fmt::format("lifted witness: {} states, min sign·det J / L³ {:.3g}, {:.2f} s in all (the search above: the same "
                       "verdict by an independent method)",
                       a.witness6r.path.size(), a.witness6r.minSignedDet, a.seconds));
  for (const SerialRobot<S>& robot : {puma560Robot<S>(), kr6Robot<S>(), ur5Robot<S>()}) {
    const CuspidalAnalysis r = analyseCuspidality(robot, o);
    c.checkEqual(robot.name() + ": not cuspidal, exactly, by " +
                     (r.decomposition.kind == CuspidalDecompositionKind::ParallelChain ? "the parallel chain (axes " + r.decomposition.axes + ")"
                                                                                      : "its spherical wrist (axes " + r.decomposition.axes + ")"),
                 1, r.decided && !r.cuspidal && r.decomposition.kind != CuspidalDecompositionKind::None);
    c.note(fmt::format("{}: {:.3f} s", robot.name(), r.seconds));
  }
  // The CRX-10iA: no decomposition; the search (budget 60 s).
  const SerialRobot<S> crx = crx10iaRobot<S>();
  CuspidalOptions so;
  so.poses = 200;
  so.secondsPerPair = 0.3;
  so.budget = 60;
  const CuspidalAnalysis r = analyseCuspidality(crx, so);
  const Witness6R& w = r.witness6r;
  c.checkEqual("FANUC CRX-10iA: no decomposition applies", 1, r.decomposition.kind == CuspidalDecompositionKind::None);
  c.checkEqual("FANUC CRX-10iA: a witness found within 60 s (cuspidal, as Salunkhe, Chablat & Wenger 2023 report)", 1,
               w.found);
  c.note(fmt::format("CRX-10iA search: {} poses, {} postures, {} same-sign pairs, {} planned with OMPL, {:.1f} s", w.posesTried,
                     w.posturesSeen, w.straightTried, w.pairsTried, w.seconds));
  if (!w.found) return;
  c.checkResidual("CRX-10iA: both ends reach the pose", poseResidual(crx.fk(w.goal), crx.fk(w.start), crx.lengthScale()),
                  Tolerance<S>::sqrtEpsilon());
  double minDet = std::numeric_limits<double>::infinity();
  for (const auto& q : w.path) minDet = std::min(minDet, w.sign * jacobianDet6(crx, q));
  c.checkEqual("CRX-10iA: sign·det J > 0 at every path state", 1, minDet > 0);
  c.note(fmt::format("CRX-10iA witness ({}): {} states, min |det J| / L³ = {:.3g} over the dense check", w.planner,
                     w.path.size(), w.minSignedDet));
  if (c.makeFigures()) {
    renderRobotPath(crx, w.path, 5, "FANUC CRX-10iA changes posture without a singularity",
                    c.figurePath("gf05_crx_witness.png"), Eigen::Vector3d(-0.5, -1.0, -0.35));
    c.figure("gf05_crx_witness.png",
             "FANUC CRX-10iA witness (search): start (green) and goal (purple) postures reach the same pose (drawn through the DH frame origins, the goal hides most of the start here); "
             "ghosts in between; the flange point's trace in black.");
    plotWitness6R(crx, w, "FANUC CRX-10iA: joint angles and det J along the witness", c.figurePath("gf05_crx_witness_joints.png"));
    c.figure("gf05_crx_witness_joints.png", "The six joint angles along the witness and log10(sign·det J / L³): finite all along, det J never 0.");
  }
}

SOMA_STUDY({.id = "GF-5.2.3-cuspidal-posture-change",
            .title = "Cuspidal 3R arm: cusp points (two methods), circling a cusp (Fig. 5.2), an OMPL witness",
            .source = "GF §5.2.3", .chapter = kChapter, .run = cuspidalPostureChange,
            .whyDouble = "its witness path is planned with OMPL, which works in double"});
SOMA_STUDY({.id = "GF-5.2.3-bifurcation-factorisation",
            .title = "At det J = 0 two roots of the 3R IK equation coalesce",
            .source = "GF §5.2.3", .chapter = kChapter, .run = bifurcation,
            .whyDouble = "its singular configurations are traced by geometry/cuspidal's det J series (detJSeries, "
                         "traceSingularCurves), written in double"});
SOMA_STUDY({.id = "SOMA-5.2.3-cusp-map",
            .title = "Parameter-space map of orthogonal 3R arms by number of cusps (TBB), traced cross-check",
            .source = "GF §5.2.3; Baili, Wenger, Chablat 2004", .chapter = kChapter, .run = cuspMapStudy,
            .whyDouble = "a parameter map: findCusps escalates per cell itself (float128, mpfr), the map is drawn in double"});
SOMA_STUDY({.id = "SOMA-5.2.3-workspace-ompl",
            .title = "Workspace probing with OMPL: reachability, dexterity, singular boundary, a plan away from det J = 0",
            .source = "GF §5.2.3", .chapter = kChapter, .run = workspaceStudy,
            .whyDouble = "OMPL plans in double"});
SOMA_STUDY({.id = "SOMA-5.2.3-witness-6r",
            .title = "6R witness search: PUMA 560 none found (not a proof), a cuspidal 6R found",
            .source = "GF §5.2.3; Wenger", .chapter = kChapter, .run = witness6RStudy,
            .whyDouble = "findWitness6R (geometry/cuspidal) searches in double: its paths are planned with OMPL"});
SOMA_STUDY({.id = "SOMA-5.2.3-decomposition-6r",
            .title = "6R cuspidality decided by decomposition (wrist + arm, UR chain), the CRX-10iA found cuspidal",
            .source = "GF §5.2.3; Baili, Wenger, Chablat 2004; Salunkhe, Chablat, Wenger 2023", .chapter = kChapter,
            .run = decomposition6RStudy,
            .whyDouble = "analyseCuspidality (geometry/cuspidal) runs in double: its witness searches plan with OMPL"});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
