// The `soma` command line (DESIGN §6, a contract: keep it stable).
//   soma study list [--json]
//   soma study run ID... [--scalar T] [--bits N] [--out DIR] [--no-figures] [--json]
//   soma report [--out DIR] [--only GLOB]... [--scalar T] [--bits N] [--no-figures]
//   soma pose POSE.json [--scalar T] [--bits N] [--json]
//   soma fk ROBOT.json|ROBOT.urdf [--tip LINK] --joints q1,q2,... [--scalar T] [--json]
//   soma ik ROBOT.json|ROBOT.urdf [--tip LINK] --pose POSE.json [--method M] [--scalar T] [--json]
//   soma planar SCENE.json [--json] [--png FILE]
//   soma stewart PLATFORM.json [--method M] [--scalar T] [--json]
//   soma cuspidal ROBOT.json [--json] [--png FILE] [--map X:MIN:MAX:N,Y:MIN:MAX:N [--threads N]]
//   soma workspace ROBOT.json [--samples N] [--grid N] [--png FILE] [--from Q --to Q [--margin M]] [--json]
// Exit codes: 0 every check passed, 1 a check or study failed, 2 bad input (usage, unknown
// study or scalar, unwritable output).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/studies/planar_command.hpp"
#include "soma/studies/cuspidal_command.hpp"
#include "soma/studies/fk_command.hpp"
#include "soma/studies/ik_command.hpp"
#include "soma/studies/pose_command.hpp"
#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"
#include "soma/studies/stewart_command.hpp"
#include "soma/studies/workspace_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace {

using namespace soma;
using namespace soma::studies;

constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

struct ScalarOptions {
  std::string scalar = "double";
  int bits = 256;
};

void addScalarOptions(CLI::App* app, ScalarOptions& o) {
  app->add_option("--scalar", o.scalar,
                  "scalar type of scalar-generic studies: " + scalarNames())
      ->check(CLI::IsMember({"float", "double", "long-double", "float128", "mpfr"}))
      ->capture_default_str();
  app->add_option("--bits", o.bits, "mpfr precision in bits (with --scalar mpfr)")
      ->check(CLI::Range(16, 100000))
      ->capture_default_str();
}

/// Applies the scalar options; returns the kind (the name was already validated by CLI11).
ScalarKind applyScalar(const ScalarOptions& o) {
  const auto kind = parseScalarKind(o.scalar);
  if (!kind) throw InvalidInput("unknown scalar '" + o.scalar + "' (one of " + scalarNames() + ")");
  setMpfrBits(o.bits);
  return *kind;
}

std::string commandLine(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) {
    if (i) s += ' ';
    s += argv[i];
  }
  return s;
}

bool useColor() { return isatty(STDOUT_FILENO) && std::getenv("NO_COLOR") == nullptr; }

int studyList(bool json) {
  const auto studies = allStudies();
  std::cout << (json ? studyListJson(studies) + "\n" : formatStudyList(studies));
  return 0;
}

int studyRun(const std::vector<std::string>& ids, const ScalarOptions& so,
             const std::string& outDir, bool figures, bool json) {
  const ScalarKind kind = applyScalar(so);
  const auto selected = selectStudies(ids);
  RunOptions opt;
  opt.scalar = kind;
  opt.outDir = outDir;
  opt.makeFigures = figures;
  TextOptions text;
  text.outDir = outDir;
  text.color = useColor();
  const auto results = runStudies(selected, opt, [&](const StudyResult& r, std::size_t, std::size_t) {
    if (!json) std::cout << formatStudyText(r, text) << std::flush;
  });
  const RunSummary sum = summarize(results);
  if (json) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& r : results) arr.push_back(nlohmann::json::parse(studyJson(r)));
    std::cout << arr.dump(2) << "\n";
  } else {
    std::cout << formatSummaryLine(sum) << "\n";
  }
  return sum.allPassed() ? 0 : kExitFailed;
}

int report(const std::vector<std::string>& only, const ScalarOptions& so, const std::string& outDir,
           bool figures, const std::string& command) {
  const ScalarKind kind = applyScalar(so);
  const auto selected = selectStudies(only);
  RunOptions opt;
  opt.scalar = kind;
  opt.outDir = outDir;
  opt.makeFigures = figures;
  const bool color = useColor();
  const auto t0 = std::chrono::steady_clock::now();
  const auto results =
      runStudies(selected, opt, [&](const StudyResult& r, std::size_t k, std::size_t n) {
        const bool ok = r.passed();
        const std::string tag = color ? (ok ? "\033[1;32mPASS\033[0m" : "\033[1;31mFAIL\033[0m")
                                      : (ok ? "PASS" : "FAIL");
        std::cout << fmt::format("[{:>3}/{}] {}  {}  ({})\n", k + 1, n, tag, r.study->id,
                                 formatSeconds(r.seconds))
                  << std::flush;
        if (!ok) {
          TextOptions text;
          text.outDir = outDir;
          text.color = color;
          std::cout << formatStudyText(r, text);
        }
      });
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const ReportInfo info = collectReportInfo(kind, command, secs, figures);
  writeReport(outDir, info, results);
  const RunSummary sum = summarize(results);
  std::cout << formatSummaryLine(sum) << "\n";
  std::cout << "report: " << (std::filesystem::absolute(outDir) / "index.html").string() << "\n";
  return sum.allPassed() ? 0 : kExitFailed;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"soma — geometry of robot kinematics (J.M. Selig, Geometric Fundamentals of Robotics)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(somaVersion()));

  // soma study list | run
  auto* study = app.add_subcommand("study", "list or run the studies (one per catalogue item)");
  study->require_subcommand(1);
  bool listJson = false;
  auto* list = study->add_subcommand("list", "every study: catalogue ID, title, source section");
  list->add_flag("--json", listJson, "print a JSON array");

  std::vector<std::string> runIds;
  ScalarOptions runScalar;
  std::string runOut = "out/report";
  bool runNoFigures = false, runJson = false;
  auto* run = study->add_subcommand("run", "run studies by ID or glob ('GF-4.*'); print every check");
  run->add_option("ids", runIds, "study IDs or shell globs")->required();
  addScalarOptions(run, runScalar);
  run->add_option("--out", runOut, "directory for figures (DIR/figures/)")->capture_default_str();
  run->add_flag("--no-figures", runNoFigures, "skip figures");
  run->add_flag("--json", runJson, "print the results as JSON");

  // soma report
  std::vector<std::string> only;
  ScalarOptions repScalar;
  std::string repOut = "out/report";
  bool repNoFigures = false;
  auto* rep = app.add_subcommand("report", "run studies and write DIR/index.html, report.json, figures");
  rep->add_option("--out", repOut, "output directory")->capture_default_str();
  rep->add_option("--only", only, "only studies matching these IDs or globs (repeatable)");
  addScalarOptions(rep, repScalar);
  rep->add_flag("--no-figures", repNoFigures, "skip figures");

  // soma pose
  std::string poseFile;
  ScalarOptions poseScalar;
  bool poseJson = false;
  auto* pose = app.add_subcommand(
      "pose", "one pose in every representation: matrix, quaternion, dual quaternion, Study "
              "parameters, twist, screw, with round-trip residuals");
  pose->add_option("file", poseFile, "pose JSON: {\"rotation\": [[3x3]] or \"quaternion\": "
                                     "[w,x,y,z], \"translation\": [x,y,z]}")
      ->required();
  addScalarOptions(pose, poseScalar);
  pose->add_flag("--json", poseJson, "print one JSON object");

  // soma fk / soma ik (DESIGN §6)
  std::string fkRobot, fkJoints, fkTip;
  ScalarOptions fkScalar;
  bool fkJson = false;
  auto* fk = app.add_subcommand("fk", "forward kinematics: the tool pose of a robot file at a joint vector");
  fk->add_option("robot", fkRobot, "robot JSON (DESIGN §6: dh, mdh or poe joints) or URDF (.urdf: a serial chain)")->required();
  fk->add_option("--tip", fkTip, "URDF only: the chain's tip link (default: the only leaf link)");
  fk->add_option("--joints", fkJoints, "q1,q2,... (degrees when the robot file says \"angles\": \"degrees\"; --joints=-0.5,... for a leading minus)")
      ->required();
  addScalarOptions(fk, fkScalar);
  fk->add_flag("--json", fkJson, "print one JSON object");
  std::string ikRobot, ikPose, ikMethod = "auto", ikTip;
  ScalarOptions ikScalar;
  bool ikJson = false;
  auto* ik = app.add_subcommand("ik", "inverse kinematics: every real posture of a robot for a pose");
  ik->add_option("robot", ikRobot, "robot JSON (DESIGN §6) or URDF (.urdf: a serial chain)")->required();
  ik->add_option("--tip", ikTip, "URDF only: the chain's tip link (default: the only leaf link)");
  ik->add_option("--pose", ikPose, "pose JSON: {\"rotation\": [[3x3]], \"translation\": [x,y,z]}")->required();
  ik->add_option("--method", ikMethod, "auto wrist3r arm3r pieper general6r (every scalar); ceres nlopt (double, Newton-polished in other scalars)")->capture_default_str();
  addScalarOptions(ik, ikScalar);
  ik->add_flag("--json", ikJson, "print one JSON object");

  // soma cuspidal (GF §5.2.3: cusp points, aspects, witness path)
  std::string cuspRobot, cuspPng;
  bool cuspJson = false;
  auto* cusp = app.add_subcommand("cuspidal", "is a 3R arm cuspidal? cusp points, singular curves, aspects, a witness path (6R: a witness search)");
  cusp->add_option("robot", cuspRobot, "robot JSON with 3 (or 6) revolute joints (DESIGN §6)")->required();
  cusp->add_flag("--json", cuspJson, "print one JSON object");
  cusp->add_option("--png", cuspPng, "joint-space figure (also STEM_section.png, STEM_witness.png)");
  std::string cuspMap;
  int cuspThreads = 0;
  cusp->add_option("--map", cuspMap, "cusp-count map over two DH lengths of the robot: X,Y with each NAME:MIN:MAX:N "
                                     "(NAME a1..a3, d1..d3), e.g. a2:0.5:4:100,a3:0.2:3:100");
  cusp->add_option("--threads", cuspThreads, "--map: TBB threads (default: all cores)");
  int cuspPoses = 4;
  double cuspPairSeconds = 0.5;
  cusp->add_option("--poses", cuspPoses, "6R: random poses to try (fixed seed)")->capture_default_str();
  cusp->add_option("--pair-seconds", cuspPairSeconds, "6R: OMPL time per same-sign posture pair")->capture_default_str();

  // soma workspace (issue 9: OMPL reachability / dexterity maps, singularity-avoiding plans)
  std::string wsRobot;
  WorkspaceCommandOptions wsOpt;
  auto* ws = app.add_subcommand("workspace", "reachability and dexterity maps from OMPL samples, the singular "
                                             "boundary, a plan keeping away from singularities");
  ws->add_option("robot", wsRobot, "robot JSON (DESIGN §6)")->required();
  ws->add_option("--samples", wsOpt.samples, "postures sampled within the joint limits")->capture_default_str();
  ws->add_option("--grid", wsOpt.grid, "cells per side of the (ρ, z) maps")->capture_default_str();
  ws->add_option("--png", wsOpt.png, "reachability map (also STEM_dexterity.png, STEM_path.png)");
  ws->add_option("--from", wsOpt.from, "start posture q1,q2,... (the robot's angle unit)");
  ws->add_option("--to", wsOpt.to, "goal posture q1,q2,...");
  ws->add_option("--margin", wsOpt.margin, "minimum σmin along the plan (dimensionless)")->capture_default_str();
  ws->add_option("--seconds", wsOpt.seconds, "planning time limit")->capture_default_str();
  ws->add_flag("--json", wsOpt.json, "print one JSON object");

  // soma planar
  std::string planarFile, planarPng;
  bool planarJson = false;
  auto* planar = app.add_subcommand(
      "planar", "planar kinematics of a scene: Burmester synthesis of 3-5 positions {x, y, angle}, or a "
                "4-bar's Grashof class, circuits and GF 5.3 invariants of its coupler motion");
  planar->add_option("file", planarFile, "scene JSON: {\"positions\": [{\"x\", \"y\", \"angle\"}, ...]} or "
                                         "{\"fourbar\": {...}, \"crank_angle\"}")
      ->required();
  planar->add_flag("--json", planarJson, "print one JSON object");
  planar->add_option("--png", planarPng, "write a figure to this PNG file");

  // soma stewart (DESIGN §6)
  std::string stewartFile, stewartMethod = "homotopy";
  ScalarOptions stewartScalar;
  bool stewartJson = false;
  auto* stewart = app.add_subcommand(
      "stewart", "forward kinematics of a Stewart-Gough platform: all 40 complex solutions, the real postures");
  stewart->add_option("platform", stewartFile, "platform JSON: {\"base\": [6 points], \"platform\": [6 points], "
                                               "\"leg_lengths\": [6]}")
      ->required();
  stewart->add_option("--method", stewartMethod, "homotopy (all 40 complex solutions, certified count), ceres or nlopt (multi-start, real postures only)")->capture_default_str();
  addScalarOptions(stewart, stewartScalar);
  stewart->add_flag("--json", stewartJson, "print one JSON object");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : kExitBadInput;
  }

  try {
    if (list->parsed()) return studyList(listJson);
    if (run->parsed()) return studyRun(runIds, runScalar, runOut, !runNoFigures, runJson);
    if (rep->parsed()) return report(only, repScalar, repOut, !repNoFigures, commandLine(argc, argv));
    if (pose->parsed()) return poseCommand(poseFile, applyScalar(poseScalar), poseJson, std::cout);
    if (fk->parsed()) return fkCommand(fkRobot, fkJoints, applyScalar(fkScalar), fkJson, std::cout, fkTip);
    if (ik->parsed()) return ikCommand(ikRobot, ikPose, ikMethod, applyScalar(ikScalar), ikJson, std::cout, ikTip);
    if (planar->parsed()) return planarCommand(planarFile, planarJson, planarPng, std::cout);
    if (ws->parsed()) return workspaceCommand(wsRobot, wsOpt, std::cout);
    if (cusp->parsed() && !cuspMap.empty())
      return cuspidalMapCommand(cuspRobot, cuspMap, cuspThreads, cuspJson, cuspPng, std::cout);
    if (cusp->parsed()) return cuspidalCommand(cuspRobot, cuspJson, cuspPng, std::cout, cuspPoses, cuspPairSeconds);
    if (stewart->parsed())
      return stewartCommand(stewartFile, stewartMethod, applyScalar(stewartScalar), stewartJson, std::cout);
  } catch (const SelectionError& e) {
    std::cerr << "soma: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const InvalidInput& e) {
    std::cerr << "soma: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "soma: " << e.what() << "\n";
    return kExitBadInput;
  }
  return kExitBadInput;
}
