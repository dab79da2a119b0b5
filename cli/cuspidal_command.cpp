// `soma cuspidal ROBOT.json|ROBOT.urdf [--json] [--png FILE]` (DESIGN §6): is a 3R arm cuspidal? The cusp
// points of its workspace section (algebraically, from the triple root of the IK equation), the
// singular curves det J = 0 in (θ2, θ3) and their images in (ρ, z), the aspects, the verdict
// (generic 3R: cuspidal ⇔ a cusp point exists — Salunkhe, Spartalis, Capco, Chablat, Wenger 2022),
// and for a cuspidal arm a witness path planned with OMPL. --png FILE writes the joint-space
// figure to FILE, the workspace section to FILE's stem + "_section.png" and the witness path to
// stem + "_witness.png". Runs in double (near-degenerate arms: float128 / mpfr, said in the
// output). A 6R robot (DH, MDH, POE or URDF, as given): decided by decomposition when it has a
// spherical wrist at either end or three parallel axes next to a meeting pair (decomposition.hpp),
// else a witness search within --budget seconds, progress on stderr (witness6r.hpp).
// With --map: a parameter-space map of cusp counts (parameter_map.hpp). Bad input →
// InvalidInput (the caller exits 2).
#include "command.hpp"
#include "json_output.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/studies/cuspidal_figures.hpp"
#include "soma/io/robot_file.hpp"
#include "soma/io/urdf_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace soma::cli {

namespace {

using namespace soma::studies;

constexpr double kPi = 3.14159265358979323846;

std::string fmtNum(double v) { return fmt::format("{:.6g}", v); }

int cuspidalMapCommand(const std::filesystem::path& file, const std::string& map, int threads, bool json,
                       const std::string& png, std::ostream& out) {
  const std::size_t comma = map.find(',');
  if (comma == std::string::npos)
    throw InvalidInput("--map '" + map + "': expected two axes X,Y, e.g. a2:0.5:4:100,a3:0.2:3:100");
  const ParameterAxis x = parseParameterAxis(map.substr(0, comma)), y = parseParameterAxis(map.substr(comma + 1));
  const io::RobotFile<double> rf = io::readRobot<double>(file);
  const CuspMap m = cuspMap(rf.robot, x, y, threads);
  const std::vector<int> hist = m.histogram();
  const std::string name = rf.robot.name().empty() ? file.stem().string() : rf.robot.name();
  if (!png.empty())
    plotCuspMap(m, fmt::format("number of cusp points over ({}, {})", x.name, y.name), png);
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = rf.robot.name();
    j["x"] = {{"name", x.name}, {"min", x.min}, {"max", x.max}, {"n", x.n}};
    j["y"] = {{"name", y.name}, {"min", y.min}, {"max", y.max}, {"n", y.n}};
    j["counts"] = m.counts;
    nlohmann::json h = nlohmann::json::object();
    for (std::size_t c = 0; c < hist.size(); ++c)
      if (hist[c] > 0) h[std::to_string(c)] = hist[c];
    j["histogram"] = h;
    j["escalated"] = m.escalated;
    j["decoupled"] = m.decoupled;
    j["threads"] = m.threads;
    j["seconds"] = m.seconds;
    out << jsonText(j) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} (3R arm), map over {} ∈ [{}, {}] ({} values) × {} ∈ [{}, {}] ({} values)\n", name,
                     x.name, fmtNum(x.min), fmtNum(x.max), x.n, y.name, fmtNum(y.min), fmtNum(y.max), y.n);
  for (std::size_t c = 0; c < hist.size(); ++c)
    if (hist[c] > 0) out << fmt::format("  {} cusps: {} arms\n", c, hist[c]);
  out << fmt::format("decoupled arms (IK splits into quadratics): {}; re-solved in float128/mpfr: {}\n", m.decoupled,
                     m.escalated);
  out << fmt::format("{} arms in {:.3f} s on {} thread(s) (TBB)\n", m.counts.size(), m.seconds, m.threads);
  return 0;
}

std::string decompositionKind(CuspidalDecompositionKind k) {
  switch (k) {
    case CuspidalDecompositionKind::SphericalWrist: return "spherical_wrist";
    case CuspidalDecompositionKind::ParallelChain: return "parallel_chain";
    default: return "none";
  }
}

int cuspidal6RCommand(const io::RobotFile<double>& rf, const std::filesystem::path& file, const CuspidalAnalysis& a,
                      bool json, const std::string& png, std::ostream& out) {
  const SerialRobot<double>& robot = rf.robot;
  const Witness6R& w = a.witness6r;
  const CuspidalDecomposition& d = a.decomposition;
  const bool wrist = d.kind == CuspidalDecompositionKind::SphericalWrist;
  const bool searched = d.kind == CuspidalDecompositionKind::None;
  const double unit = rf.degrees ? 180.0 / kPi : 1.0;
  const std::string name = robot.name().empty() ? file.stem().string() : robot.name();
  auto jointsOut = [&](const JointVector<double>& q) {
    std::vector<double> v;
    for (int i = 0; i < q.size(); ++i) v.push_back(q(i) * unit);
    return v;
  };
  auto jointsText = [&](const JointVector<double>& q) {
    std::string t;
    for (int i = 0; i < q.size(); ++i) t += (i ? ", " : "") + fmtNum(q(i) * unit);
    return "(" + t + ")";
  };
  if (!png.empty()) {
    // PNG: the 6R witness (joint angles and det J along the path); STEM_arm.png and
    // STEM_arm_witness.png: the positioning arm's joint space and witness (spherical wrist).
    const std::filesystem::path p(png);
    const std::string stem = (p.parent_path() / p.stem()).string();
    if (w.found) plotWitness6R(robot, w, "a posture change without singularity (" + w.planner + ")", p);
    if (wrist) {
      plotJointSpace(a, name + ", positioning arm: aspects and det J = 0", stem + "_arm.png");
      if (a.witness.found) plotWitness(a, name + ", positioning arm: the witness", stem + "_arm_witness.png");
    }
  }
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["method"] = a.method;
    j["decomposition"] = {{"kind", decompositionKind(d.kind)}, {"reversed", d.reversed}, {"axes", d.axes},
                          {"reason", d.reason}};
    j["exact"] = a.decided && !searched;
    j["cuspidal"] = a.decided ? nlohmann::json(a.cuspidal) : nlohmann::json("unknown");
    if (wrist) {
      nlohmann::json cs = nlohmann::json::array();
      for (const auto& c : a.cusps.cusps)
        cs.push_back({{"rho", c.rho}, {"z", c.z}, {"posture", {c.posture(0), c.posture(1), c.posture(2)}}});
      j["arm"] = {{"cusps", cs}, {"count", a.cusps.cusps.size()}, {"aspects", a.aspectMap.count()},
                  {"traced_reversals", a.reversals.size()}, {"scalar", a.cusps.scalar},
                  {"decoupled", a.cusps.frame.decoupled}, {"verdict_seconds", a.verdictSeconds}};
      j["aspects"] = 2 * a.aspectMap.count();
    }
    if (searched) {
      j["ik_method"] = w.ikMethod;
      j["poses_tried"] = w.posesTried;
      j["pairs_tried"] = w.straightTried;
      j["pairs_planned"] = w.pairsTried;
      j["postures_seen"] = w.posturesSeen;
      j["budget_exhausted"] = w.budgetExhausted;
    }
    if (wrist || searched) j["witness_found"] = w.found;
    if (w.found) {
      j["planner"] = w.planner;
      j["start"] = jointsOut(w.start);
      j["goal"] = jointsOut(w.goal);
      j["det_sign"] = w.sign;
      j["margin"] = w.margin;
      j["min_signed_det"] = w.minSignedDet;
      j["min_abs_det"] = w.minSignedDet;
      j["residual"] = std::max(w.startResidual, w.goalResidual);
      nlohmann::json path = nlohmann::json::array();
      for (const auto& q : w.path) path.push_back(jointsOut(q));
      j["path"] = path;
    } else if (!w.note.empty()) {
      j["note"] = w.note;
    }
    j["seconds"] = a.seconds;
    out << jsonText(j) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} (6R)\n", name);
  if (!searched) out << "decomposition: " << d.reason << "\n";
  if (wrist) {
    const Arm3RFrame<double>& f = a.cusps.frame;
    if (f.decoupled) out << fmt::format("positioning arm: its IK equation splits into quadratics ({}): no cusp point\n", f.reason);
    out << fmt::format("positioning arm: cusp points (algebraic, in {}): {}\n", a.cusps.scalar, a.cusps.cusps.size());
    for (const auto& c : a.cusps.cusps)
      out << fmt::format("  wrist centre at ρ = {:>12}  z = {:>12}   arm posture ({}, {}, {})\n", fmtNum(c.rho),
                         fmtNum(c.z), fmtNum(c.posture(0)), fmtNum(c.posture(1)), fmtNum(c.posture(2)));
    out << fmt::format("aspects: {} of the arm × 2 of the wrist (sign of w(θ5)) = {}\n", a.aspectMap.count(),
                       2 * a.aspectMap.count());
  }
  if (searched)
    out << fmt::format("search: IK by {}; poses tried: {}, postures {}, same-sign pairs {} (straight joint paths), "
                       "{} planned with OMPL ({:.2f} s{})\n",
                       w.ikMethod, w.posesTried, w.posturesSeen, w.straightTried, w.pairsTried, w.seconds,
                       w.budgetExhausted ? ", budget spent" : "");
  if (w.found) {
    out << fmt::format("witness ({}): postures {} → {} of one pose (residual {}), joined by {} path states along "
                       "which det J {} 0, min |det J| / L³ = {} over a dense check (≤ 0.002 rad)\n",
                       w.planner, jointsText(w.start), jointsText(w.goal),
                       fmtNum(std::max(w.startResidual, w.goalResidual)), w.path.size(), w.sign > 0 ? ">" : "<",
                       fmtNum(w.minSignedDet));
  } else if (!w.note.empty()) {
    out << "witness: " << w.note << "\n";
  }
  if (!a.decided) out << "verdict: unknown (no witness; not a proof of non-cuspidality)\n";
  else out << fmt::format("verdict: {} ({}, {:.3f} s)\n", a.cuspidal ? "CUSPIDAL" : "not cuspidal",
                          searched ? "witness" : "exact, by the decomposition", a.seconds);
  return 0;
}

int cuspidalCommand(const std::filesystem::path& file, const std::string& tip, bool json, const std::string& png,
                    std::ostream& out, int poses, double secondsPerPair, double budget, bool search) {
  const io::RobotFile<double> rf = io::readAnyRobot<double>(file, tip);
  const SerialRobot<double>& robot = rf.robot;
  CuspidalOptions options;
  options.poses = poses;
  options.secondsPerPair = secondsPerPair;
  options.budget = budget;
  options.forceSearch = search;
  options.progress = [](const Witness6RProgress& p) {
    std::cerr << fmt::format("cuspidal: {} poses, {} postures, {} pairs planned, {:.1f} s\n", p.posesTried,
                             p.posturesSeen, p.pairsTried, p.seconds);
  };
  const CuspidalAnalysis r = analyseCuspidality(robot, options);
  if (r.sixR) return cuspidal6RCommand(rf, file, r, json, png, out);
  const Arm3RFrame<double>& f = r.cusps.frame;
  const WitnessPath& w = r.witness;
  if (!png.empty()) {
    const std::filesystem::path p(png);
    const std::filesystem::path stem = p.parent_path() / p.stem();
    const std::string name = robot.name().empty() ? file.stem().string() : robot.name();
    plotJointSpace(r, name + ": aspects and det J = 0 in joint space", p);
    plotSection(r, name + ": singular curves in the workspace section", stem.string() + "_section.png");
    if (w.found) plotWitness(r, name + ": a posture change without singularity", stem.string() + "_witness.png");
  }
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["method"] = r.method;
    j["scalar"] = r.cusps.scalar;
    if (!r.cusps.conditioning.empty()) j["conditioning"] = r.cusps.conditioning;
    j["seconds"] = r.seconds;
    j["verdict_seconds"] = r.verdictSeconds;
    j["cuspidal"] = r.cuspidal;
    j["decoupled"] = f.decoupled;
    if (f.decoupled) j["decoupled_reason"] = f.reason;
    nlohmann::json cs = nlohmann::json::array();
    for (const auto& c : r.cusps.cusps)
      cs.push_back({{"rho", c.rho}, {"z", c.z}, {"posture", {c.posture(0), c.posture(1), c.posture(2)}},
                    {"residual", c.residual}});
    j["cusps"] = cs;
    j["count"] = r.cusps.cusps.size();
    j["traced_reversals"] = r.reversals.size();
    j["aspects"] = r.aspectMap.count();
    nlohmann::json signs = nlohmann::json::array();
    for (int s : r.aspectMap.sign) signs.push_back(s);
    j["aspect_signs"] = signs;
    j["singular_branches"] = r.branches.size();
    if (r.cuspidal) {
      nlohmann::json jw;
      jw["found"] = w.found;
      if (w.found) {
        jw["target"] = {w.target(0), w.target(1), w.target(2)};
        jw["rho"] = w.rho;
        jw["z"] = w.z;
        jw["start"] = {w.start(0), w.start(1), w.start(2)};
        jw["goal"] = {w.goal(0), w.goal(1), w.goal(2)};
        jw["start_residual"] = w.startResidual;
        jw["goal_residual"] = w.goalResidual;
        jw["det_sign"] = w.sign;
        jw["margin"] = w.margin;
        jw["min_signed_det"] = w.minSignedDet;
        jw["certified"] = w.certified;
        jw["checked_points"] = w.checkedPoints;
        jw["aspect"] = w.aspectStart;
        nlohmann::json path = nlohmann::json::array();
        for (const auto& s : w.path) path.push_back({s(0), s(1), s(2)});
        jw["path"] = path;
        jw["planner"] = "OMPL RRTConnect on SO(2)^3";
      } else {
        jw["note"] = w.note;
      }
      jw["seconds"] = w.seconds;
      j["witness"] = jw;
    }
    out << jsonText(j) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} (3R arm)\n", robot.name().empty() ? file.string() : robot.name());
  out << fmt::format("axes 1–2: common normal {}  twist sin {} cos {}\n", fmtNum(f.a1), fmtNum(f.s1), fmtNum(f.c1));
  if (f.decoupled)
    out << fmt::format("the IK equation splits into quadratics ({}): no cusp point\n", f.reason);
  if (!r.cusps.conditioning.empty()) out << "near-degenerate: " << r.cusps.conditioning << "\n";
  out << fmt::format("cusp points (algebraic, triple root of the IK equation, in {}): {}\n", r.cusps.scalar,
                     r.cusps.cusps.size());
  for (const auto& c : r.cusps.cusps)
    out << fmt::format("  ρ = {:>12}  z = {:>12}   posture ({}, {}, {})\n", fmtNum(c.rho), fmtNum(c.z),
                       fmtNum(c.posture(0)), fmtNum(c.posture(1)), fmtNum(c.posture(2)));
  out << fmt::format("image of det J = 0 turns back (traced): {} times on {} branch(es)\n", r.reversals.size(),
                     r.branches.size());
  out << fmt::format("aspects (components of det J ≠ 0 in (θ2, θ3)): {}\n", r.aspectMap.count());
  out << fmt::format("verdict: {} ({:.3f} ms for the cusp points)\n", r.cuspidal ? "CUSPIDAL" : "not cuspidal",
                     1e3 * r.verdictSeconds);
  if (r.cuspidal) {
    if (w.found) {
      out << fmt::format("witness: target ρ = {}, z = {}; postures ({}, {}, {}) → ({}, {}, {}); det J {} 0 along "
                         "{} path states, min |det J| {} over {} checked points{}\n",
                         fmtNum(w.rho), fmtNum(w.z), fmtNum(w.start(0)), fmtNum(w.start(1)), fmtNum(w.start(2)),
                         fmtNum(w.goal(0)), fmtNum(w.goal(1)), fmtNum(w.goal(2)), w.sign > 0 ? ">" : "<",
                         w.path.size(), fmtNum(w.minSignedDet), w.checkedPoints,
                         w.certified ? " (certified)" : "");
    } else {
      out << "witness: " << w.note << "\n";
    }
  }
  return 0;
}

class CuspidalCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "cuspidal";
    spec.help = "is a 3R arm or a 6R robot cuspidal? cusp points, aspects, a witness path (6R: by decomposition, "
                "else a witness search)";
    spec.add("robot", robot_, "robot JSON (DESIGN §6) or URDF (.urdf: a serial chain) with 3 or 6 revolute joints")
        .mustBeGiven();
    spec.add("--tip", tip_, "URDF only: the chain's tip link (default: the only leaf link)");
    spec.flag("--json", json_, "print one JSON object");
    spec.add("--png", png_, "joint-space figure (also STEM_section.png, STEM_witness.png)");
    spec.add("--map", map_, "cusp-count map over two DH lengths of the robot: X,Y with each NAME:MIN:MAX:N "
                            "(NAME a1..a3, d1..d3), e.g. a2:0.5:4:100,a3:0.2:3:100");
    spec.add("--threads", threads_, "--map: TBB threads (default 0: all cores)").within(0, 1024);
    spec.add("--poses", poses_, "6R search: random poses to try at most (fixed seed; the budget usually stops first)")
        .within(1, 10000)
        .withDefault();
    spec.add("--pair-seconds", pairSeconds_, "6R: OMPL time per same-sign posture pair").within(0.001, 3600).withDefault();
    spec.add("--budget", budget_, "6R search: total seconds (0: no limit)").within(0, 86400).withDefault();
    spec.flag("--search", search_, "6R: search for a witness even when a decomposition decides");
  }
  int run(const Spec&, const Invocation&) override {
    if (!map_.empty()) return cuspidalMapCommand(robot_, map_, threads_, json_, png_, std::cout);
    return cuspidalCommand(robot_, tip_, json_, png_, std::cout, poses_, pairSeconds_, budget_, search_);
  }

 private:
  std::string robot_, png_, map_, tip_;
  bool json_ = false, search_ = false;
  int threads_ = 0, poses_ = 1000;
  double pairSeconds_ = 0.5, budget_ = 20;
};

}  // namespace

SOMA_CLI_COMMAND(CuspidalCommand, 60);

}  // namespace soma::cli
