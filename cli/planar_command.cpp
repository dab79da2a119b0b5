// `soma planar SCENE.json [--json] [--png FILE]`: planar kinematics on the user's own data.
//  * {"positions": [{"x", "y", "angle"}, ...], "angles": "degrees"|"radians"} with 3–5 positions of
//    a moving frame: poles; for 3 positions the centre of each given "circle_points" entry; for 4
//    the centre-point and circle-point cubics; for 5 the Burmester pairs and every 4-bar made
//    from two of them, driven through the positions (errors, one circuit or not, Grashof class).
//  * {"fourbar": {"ground": [[x, y], [x, y]], "crank", "coupler", "rocker", "coupler_point": [u, v]},
//     "crank_angle", "mode": ±1, "crank_rates": [ω₁, ω̇₁, ω̈₁, ω⃛₁], "angles"}: Grashof class,
//    circuits, the pose, and the instantaneous invariants of the coupler motion (GF §5.3–5.4).
// Runs in double. Bad input → InvalidInput (the caller prints it and exits 2).
#include "command.hpp"
#include "json_output.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/geometry/planar/burmester_synthesis.hpp"
#include "soma/io/planar_scene_file.hpp"
#include "soma/render/plot.hpp"

#include <chrono>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <iostream>

namespace soma::cli {

namespace {

using json = nlohmann::json;
using namespace soma::planar;
using V2 = Vec2<double>;

json vec(const V2& v) { return json::array({v(0), v(1)}); }
std::string txt(const V2& v) { return fmt::format("({:.12g}, {:.12g})", v(0), v(1)); }

// A point [x, y] of this command's own JSON output (the plot reads the invariants back).
V2 point(const json& j) { return V2(j[0].get<double>(), j[1].get<double>()); }

struct Output {
  json j = json::object();
  std::string text;
  void line(const std::string& s) { text += s + "\n"; }
};

void plotCurve(render::Plot& plot, const std::string& name, const std::vector<V2>& pts, render::Color col, bool markers, double r = 2) {
  std::vector<double> xs, ys;
  for (const V2& p : pts) {
    xs.push_back(p(0));
    ys.push_back(p(1));
  }
  auto& s = plot.add(name, xs, ys, col);
  s.line = !markers;
  s.markers = markers;
  s.markerRadius = r;
}

void positionsScene(const io::PlanarScene& in, Output& o, const std::string& png) {
  std::vector<SE2<double>> pos;
  for (const io::PlanarPosition& p : in.positions) pos.push_back(SE2<double>(p.angle, V2(p.x, p.y)));
  if (pos.size() < 3 || pos.size() > 5)
    throw InvalidInput("\"positions\": need 3, 4 or 5 positions for Burmester synthesis, got " + std::to_string(pos.size()));
  const BurmesterSynthesis<double> bs(pos);
  const int n = bs.size();
  o.j["count"] = n;
  o.line(fmt::format("{} positions (scale {:.6g})", n, bs.scale()));
  json poles = json::array();
  for (int i = 1; i <= n; ++i)
    for (int k = i + 1; k <= n; ++k) {
      try {
        const V2 p = bs.pole(i, k);
        poles.push_back({{"i", i}, {"j", k}, {"pole", vec(p)}});
        o.line(fmt::format("  pole P{}{} = {}", i, k, txt(p)));
      } catch (const InvalidInput&) {
        poles.push_back({{"i", i}, {"j", k}, {"pole", nullptr}, {"note", "pure translation: pole at infinity"}});
        o.line(fmt::format("  pole P{}{} at infinity (pure translation)", i, k));
      }
    }
  o.j["poles"] = poles;
  render::Plot plot;
  plot.equalAspect = true;
  plot.x.label = "x";
  plot.y.label = "y";
  std::vector<V2> traj;
  for (const auto& p : pos) traj.push_back(p.translation());
  V2 mn = traj[0], mx = traj[0];
  for (const V2& p : traj) {
    mn = mn.cwiseMin(p);
    mx = mx.cwiseMax(p);
  }
  if (n == 3) {
    json out = json::array();
    if (in.hasCirclePoints) {
      for (const V2& z : in.circlePoints) {
        const auto m = bs.centreForCirclePoint(z);
        if (!m) {
          out.push_back({{"circle_point", vec(z)}, {"centre", nullptr}, {"note", "its three positions are collinear"}});
          o.line(fmt::format("  circle point {}: positions collinear, no centre", txt(z)));
        } else {
          out.push_back({{"circle_point", vec(z)}, {"centre", vec(*m)}, {"residual", bs.residual(*m, z)}});
          o.line(fmt::format("  circle point {} → centre point {} (residual {:.2e})", txt(z), txt(*m), bs.residual(*m, z)));
        }
      }
    } else {
      o.line("  (3 positions: every moving point has a centre; give \"circle_points\" to compute them)");
    }
    o.j["dyads"] = out;
    plot.title = "Three positions";
  } else if (n == 4) {
    const Poly2<double> F = bs.centrePointCurve(), C = bs.circlePointCurve();
    auto coeffs = [](const Poly2<double>& p) {
      json a = json::array();
      for (int i = 0; i <= 3; ++i)
        for (int j = 0; i + j <= 3; ++j) a.push_back({{"x", i}, {"y", j}, {"c", p.at(i, j)}});
      return a;
    };
    o.j["centre_point_curve"] = coeffs(F);
    o.j["circle_point_curve"] = coeffs(C);
    o.line("  centre-point curve: a circular cubic through the six poles (coefficients in --json)");
    const V2 mid = 0.5 * (mn + mx);
    const double half = 0.5 * (mx - mn).maxCoeff() + 3;
    plotCurve(plot, "centre-point curve", sampleCurve(F, mid(0) - half, mid(0) + half, mid(1) - half, mid(1) + half, 400),
              render::palette::blue, true);
    plot.x.min = mid(0) - half;
    plot.x.max = mid(0) + half;
    plot.y.min = mid(1) - half;
    plot.y.max = mid(1) + half;
    plot.title = "Four positions: centre-point curve";
  } else {
    int cc = 0;
    double lead = 0, pd = 0;
    const auto pairs = bs.burmesterPairs(&cc, &lead, &pd);
    o.j["expected_count"] = 4;
    o.j["real_pairs"] = int(pairs.size());
    o.j["complex_pairs"] = cc;
    o.line(fmt::format("  Burmester pairs: {} real, {} complex (of 4)", pairs.size(), cc));
    json jp = json::array();
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto& p = pairs[k];
      jp.push_back({{"centre", vec(p.centre)}, {"circle_point", vec(p.circle)}, {"radius", p.radius}, {"residual", p.residual}});
      o.line(fmt::format("  [{}] centre point {}  circle point (moving frame) {}  radius {:.12g}  residual {:.2e}", k, txt(p.centre),
                         txt(p.circle), p.radius, p.residual));
    }
    o.j["pairs"] = jp;
    json links = json::array();
    int best = -1, bestB = -1;
    for (std::size_t a = 0; a < pairs.size(); ++a)
      for (std::size_t b = 0; b < pairs.size(); ++b) {
        if (a == b) continue;
        try {
          const FourBar<double> fb = bs.fourBar(pairs[a], pairs[b]);
          const DriveCheck<double> dc = bs.drive(pairs[a], pairs[b]);
          const std::string cls = grashofName(fb.classify().type);
          links.push_back({{"crank_pair", a}, {"rocker_pair", b}, {"grashof", cls}, {"reaches_all", dc.reached},
                           {"one_circuit", dc.sameCircuit}, {"worst_translation_error", dc.worstTranslation},
                           {"worst_angle_error", dc.worstAngle}, {"modes", dc.modes}});
          o.line(fmt::format("  4-bar crank [{}] rocker [{}]: {}, {}; pose error {:.2e} (relative), {:.2e} rad", a, b, cls,
                             !dc.reached ? "cannot reach every position" : (dc.sameCircuit ? "one circuit" : "needs two circuits (branch defect)"),
                             dc.worstTranslation, dc.worstAngle));
          if (best < 0 && dc.reached && dc.sameCircuit) {
            best = int(a);
            bestB = int(b);
          }
        } catch (const InvalidInput& e) {
          links.push_back({{"crank_pair", a}, {"rocker_pair", b}, {"error", e.what()}});
        }
      }
    o.j["linkages"] = links;
    std::vector<V2> cen;
    for (const auto& p : pairs) cen.push_back(p.centre);
    const V2 mid = 0.5 * (mn + mx);
    const double half = 0.5 * (mx - mn).maxCoeff() + 3;
    plot.x.min = mid(0) - half;
    plot.x.max = mid(0) + half;
    plot.y.min = mid(1) - half;
    plot.y.max = mid(1) + half;
    plotCurve(plot, "centre-point curve {1,2,3,4}", sampleCurve(bs.centrePointCurve(4), mid(0) - half, mid(0) + half, mid(1) - half, mid(1) + half, 400),
              render::palette::skyBlue, true, 1.5);
    plotCurve(plot, "Burmester centre points", cen, render::palette::vermillion, true, 9);
    if (best >= 0) {
      const FourBar<double> fb = bs.fourBar(pairs[best], pairs[bestB]);
      const DriveCheck<double> dc = bs.drive(pairs[best], pairs[bestB]);
      std::vector<V2> curve;
      for (const auto& q : fb.traceCircuit(dc.circuits.at(0), 720)) curve.push_back(fb.couplerPointWorld(q));
      plotCurve(plot, "coupler curve of a working 4-bar", curve, render::palette::blue, false);
      for (int i = 0; i < n; ++i) {
        const SE2<double>& M = pos[i];
        const V2 a2 = M.act(pairs[best].circle), b3 = M.act(pairs[bestB].circle);
        plotCurve(plot, i == 0 ? "linkage at the positions" : "", {pairs[best].centre, a2, b3, pairs[bestB].centre},
                  render::palette::cycle(i), false);
      }
    }
    plot.title = "Five positions: Burmester points and a synthesized 4-bar";
  }
  plotCurve(plot, "positions", traj, render::palette::black, true, 6);
  if (!png.empty()) render::renderPlotPng(plot, png, 1000, 1000);
}

void fourbarScene(const io::PlanarScene& in, Output& o, const std::string& png) {
  const io::PlanarFourBarInput& f = *in.fourbar;
  const double angleUnit = in.angleUnit;
  const FourBar<double> fb(f.c1, f.c4, f.crank, f.coupler, f.rocker, f.couplerPoint);
  const GrashofClass<double> g = fb.classify();
  o.j["grashof"] = grashofName(g.type);
  o.j["grashof_margin"] = g.margin;
  o.j["circuits"] = fb.circuitCount();
  o.line(fmt::format("4-bar: {} (margin p + q − s − l = {:.6g}){}{}; {} circuit(s)", grashofName(g.type), g.margin,
                     g.parallelogram ? ", parallelogram" : "", g.deltoid ? ", deltoid" : "", fb.circuitCount()));
  json iv = json::array();
  for (const auto& r : fb.crankIntervals()) iv.push_back({r.first / angleUnit, r.second / angleUnit});
  o.j["crank_intervals"] = iv;
  if (iv.empty()) o.line("  the crank turns fully");
  else
    for (const auto& r : fb.crankIntervals()) o.line(fmt::format("  crank range [{:.10g}, {:.10g}]", r.first / angleUnit, r.second / angleUnit));
  const double th = f.crankAngle;
  const int mode = f.mode;
  const std::array<double, 5> law{th, f.crankRates[0], f.crankRates[1], f.crankRates[2], f.crankRates[3]};
  const auto pose = fb.solve(th, mode);
  if (!pose) throw InvalidInput(fmt::format("the 4-bar cannot be assembled at crank angle {:.10g}", th / angleUnit));
  const V2 P = fb.couplerPointWorld(*pose);
  o.j["pose"] = {{"c2", vec(pose->c2)}, {"c3", vec(pose->c3)}, {"coupler_point", vec(P)}, {"coupler_angle", pose->psi / angleUnit}};
  o.line(fmt::format("  at θ₁ = {:.10g}, mode {}: c2 = {}, c3 = {}, coupler point {}", th / angleUnit, mode, txt(pose->c2), txt(pose->c3), txt(P)));
  const MotionJet<double> jet = fb.couplerJet(th, mode, law);
  json inv = json::object();
  try {
    const InstantInvariants<double> I = InstantInvariants<double>::fromJet(jet);
    const Circle<double> ci = I.inflectionCircle();
    inv["pole"] = vec(I.pole());
    inv["omega"] = json::array({I.omega(0), I.omega(1), I.omega(2), I.omega(3)});
    inv["r_derivatives"] = json::array({vec(I.r(1)), vec(I.r(2)), vec(I.r(3))});
    inv["inflection_circle"] = {{"centre", vec(ci.centre)}, {"radius", ci.radius}};
    inv["inflection_pole"] = vec(I.inflectionPole());
    o.line(fmt::format("  pole r = {}; ω, ω̇, ω̈, ω⃛ = {:.12g}, {:.12g}, {:.12g}, {:.12g}", txt(I.pole()), I.omega(0), I.omega(1), I.omega(2),
                       I.omega(3)));
    o.line(fmt::format("  inflection circle: centre {}, radius {:.12g}; inflection pole {}", txt(ci.centre), ci.radius, txt(I.inflectionPole())));
    try {
      inv["ball_point"] = vec(I.ballPoint());
      o.line(fmt::format("  Ball's point {}", txt(I.ballPoint())));
      const CubicNormalForm<double> nf = I.cubicNormalForm();
      inv["cubic_normal_form"] = {{"inv_mu", nf.invMu}, {"inv_nu", nf.invNu}};
      o.line(fmt::format("  cubic of stationary curvature, normal form: 1/μ = {:.12g}, 1/ν = {:.12g}", nf.invMu, nf.invNu));
      const BurmesterPoints<double> bp = burmesterPoints(jet);
      json pts = json::array();
      for (std::size_t k = 0; k < bp.x.size(); ++k)
        pts.push_back({{"x", {bp.x[k].re, bp.x[k].im}}, {"y", {bp.y[k].re, bp.y[k].im}}, {"real", bool(bp.isReal[k])}});
      inv["burmester_points"] = pts;
      inv["burmester_real_count"] = bp.realCount;
      o.line(fmt::format("  Burmester points: {} real of 4", bp.realCount));
      for (std::size_t k = 0; k < bp.x.size(); ++k)
        if (bp.isReal[k]) o.line(fmt::format("    ({:.12g}, {:.12g})", bp.x[k].re, bp.y[k].re));
    } catch (const InvalidInput& e) {
      inv["note"] = e.what();
      o.line(std::string("  ") + e.what());
    }
  } catch (const InvalidInput& e) {
    inv["pole"] = nullptr;
    inv["note"] = e.what();
    o.line(std::string("  ") + e.what());
  }
  o.j["invariants"] = inv;
  const Poly2<double> sextic = fb.couplerCurve();
  o.j["coupler_curve_degree"] = sextic.degree(1e-12);
  if (png.empty()) return;
  render::Plot plot;
  plot.title = "4-bar, coupler curve and instantaneous invariants";
  plot.equalAspect = true;
  plot.x.label = "x";
  plot.y.label = "y";
  for (int k = 0; k < fb.circuitCount(); ++k) {
    std::vector<V2> curve;
    for (const auto& q : fb.traceCircuit(k, 720)) curve.push_back(fb.couplerPointWorld(q));
    plotCurve(plot, k == 0 ? "coupler curve" : "", curve, render::palette::cycle(k), false);
  }
  plotCurve(plot, "4-bar", {fb.c1(), pose->c2, pose->c3, fb.c4()}, render::palette::black, false);
  if (inv.contains("inflection_circle")) {
    const V2 cc = point(inv["inflection_circle"]["centre"]);
    const double r = inv["inflection_circle"]["radius"].get<double>();
    std::vector<V2> circ;
    for (int k = 0; k < 240; ++k) circ.push_back(cc + r * V2(std::cos(k * 6.283185307 / 240), std::sin(k * 6.283185307 / 240)));
    plotCurve(plot, "inflection circle", circ, render::palette::bluishGreen, false);
    plotCurve(plot, "pole", {point(inv["pole"])}, render::palette::vermillion, true, 8);
    if (inv.contains("ball_point")) plotCurve(plot, "Ball's point", {point(inv["ball_point"])}, render::palette::reddishPurple, true, 8);
  }
  render::renderPlotPng(plot, png, 1000, 1000);
}


int planarCommand(const std::filesystem::path& file, bool asJson, const std::string& png, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const io::PlanarScene in = io::readPlanarScene(file);
  Output o;
  o.j["input"] = file.string();
  o.j["scalar"] = "double";
  o.j["angles"] = in.degrees ? "degrees" : "radians";
  if (!in.fourbar) {
    o.j["method"] = "Burmester synthesis (bilinear circle equations; 5 positions: resultant of two centre-point cubics, Newton polish)";
    positionsScene(in, o, png);
  } else {
    o.j["method"] = "closed-form position analysis; coupler-motion jet by Taylor arithmetic; GF §5.3 invariants";
    fourbarScene(in, o, png);
  }
  o.j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!png.empty()) o.j["png"] = png;
  if (asJson) out << jsonText(o.j) << "\n";
  else out << o.text << (png.empty() ? "" : "figure: " + png + "\n");
  return 0;
}

class PlanarCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "planar";
    spec.help = "planar kinematics of a scene: Burmester synthesis of 3-5 positions {x, y, angle}, or a "
                "4-bar's Grashof class, circuits and GF 5.3 invariants of its coupler motion";
    spec.add("file", file_, "scene JSON: {\"positions\": [{\"x\", \"y\", \"angle\"}, ...]} or "
                            "{\"fourbar\": {...}, \"crank_angle\"}")
        .mustBeGiven();
    spec.flag("--json", json_, "print one JSON object");
    spec.add("--png", png_, "write a figure to this PNG file");
  }
  int run(const Spec&, const Invocation&) override { return planarCommand(file_, json_, png_, std::cout); }

 private:
  std::string file_, png_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(PlanarCommand, 80);

}  // namespace soma::cli
