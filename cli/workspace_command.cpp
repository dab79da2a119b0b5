// `soma workspace ROBOT.json [--samples N] [--grid N] [--png FILE] [--from Q --to Q [--margin M]
// [--seconds T]] [--json]` (issue 9, GF §5.2.3): reachability and dexterity maps of the tool point
// in the section (ρ, z) about axis 1 from OMPL's state sampler within the joint limits; for a 3R
// arm the workspace boundary from the singular curves (images of det J = 0); with --from/--to a
// plan between two postures keeping σ_min ≥ margin (OMPL RRTConnect). --png FILE writes the
// reachability map to FILE, the dexterity map to STEM_dexterity.png and, with a plan,
// σ_min along the path to STEM_path.png. Bad input → InvalidInput (the caller exits 2).
#include "command.hpp"
#include "json_output.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/robot_file.hpp"
#include "soma/studies/workspace_figures.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <optional>

namespace soma::cli {

namespace {

using namespace soma::studies;

std::string fmtNum(double v) { return fmt::format("{:.6g}", v); }

/// The command line's options (the analysis takes WorkspaceOptions, workspace_analysis.hpp).
struct WorkspaceCommandOptions {
  int samples = 200000;
  int grid = 120;
  std::string png;
  std::string from, to;
  double margin = 0.05;
  double seconds = 2.0;
  bool json = false;
};

int workspaceCommand(const std::filesystem::path& file, const WorkspaceCommandOptions& o, std::ostream& out) {
  const io::RobotFile<double> rf = io::readRobot<double>(file);
  const SerialRobot<double>& robot = rf.robot;
  if (o.from.empty() != o.to.empty()) throw InvalidInput("workspace: --from and --to go together");
  WorkspaceOptions options;
  options.samples = o.samples;
  options.grid = o.grid;
  options.margin = o.margin;
  options.seconds = o.seconds;
  if (!o.from.empty()) {
    auto joints = [&](const std::string& text, const char* flag) {
      try {
        return io::parseJoints<double>(text, rf);
      } catch (const InvalidInput& e) {
        throw InvalidInput(std::string("workspace ") + flag + " '" + text + "': " + e.what());
      }
    };
    options.plan = std::make_pair(joints(o.from, "--from"), joints(o.to, "--to"));
  }
  const WorkspaceAnalysis a = analyseWorkspace(robot, options);
  const WorkspaceMaps& m = a.maps;
  const auto& boundary = a.boundary;
  const std::optional<SafePath>& plan = a.plan;
  const std::vector<Eigen::Vector2d>& trace = a.planTrace;
  const std::string name = robot.name().empty() ? file.stem().string() : robot.name();
  if (!o.png.empty()) {
    const std::filesystem::path p(o.png);
    const std::filesystem::path stem = p.parent_path() / p.stem();
    plotReachability(m, boundary, name + ": reachability (OMPL samples per cell)", p);
    plotDexterity(m, boundary, trace, name + ": dexterity (best inverse condition number)",
                  stem.string() + "_dexterity.png");
    if (plan && plan->found) plotPathSigma(robot, *plan, name + ": distance from the singularities along the plan",
                                           stem.string() + "_path.png");
  }
  const double unit = rf.degrees ? 180.0 / 3.14159265358979323846 : 1.0;
  auto jointsOut = [&](const JointVector<double>& q) {
    std::vector<double> v;
    for (int i = 0; i < q.size(); ++i) v.push_back(q(i) * (robot.joints()[i].type == JointType::Revolute ? unit : 1.0));
    return v;
  };
  if (o.json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["samples"] = m.samples;
    j["grid"] = {m.nRho, m.nZ};
    j["rho_max"] = m.rhoMax;
    j["z_range"] = {m.zMin, m.zMax};
    j["reached_fraction"] = m.reachedFraction;
    j["mean_dexterity"] = m.meanDexterity;
    j["boundary_curves"] = boundary.size();
    j["sampler"] = "OMPL default state sampler (uniform within the joint limits)";
    j["seconds"] = m.seconds;
    if (plan) {
      nlohmann::json p;
      p["found"] = plan->found;
      p["margin"] = plan->margin;
      p["start_sigma"] = plan->startSigma;
      p["goal_sigma"] = plan->goalSigma;
      p["start_det_sign"] = plan->startSign;
      p["goal_det_sign"] = plan->goalSign;
      if (plan->found) {
        p["min_sigma"] = plan->minSigma;
        nlohmann::json path = nlohmann::json::array();
        for (const auto& q : plan->path) path.push_back(jointsOut(q));
        p["path"] = path;
        p["planner"] = "OMPL RRTConnect";
      } else {
        p["note"] = plan->note;
      }
      p["seconds"] = plan->seconds;
      j["plan"] = p;
    }
    out << jsonText(j) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} ({} joints)\n", name, robot.dof());
  out << fmt::format("samples: {} postures within the joint limits (OMPL state sampler), {:.3f} s\n", m.samples, m.seconds);
  out << fmt::format("section about axis 1: ρ ≤ {}, z ∈ [{}, {}]; {} × {} grid, {:.1f} % of its cells reached\n",
                     fmtNum(m.rhoMax), fmtNum(m.zMin), fmtNum(m.zMax), m.nRho, m.nZ, 100 * m.reachedFraction);
  out << fmt::format("dexterity (σmin/σmax): mean {}\n", fmtNum(m.meanDexterity));
  if (!boundary.empty())
    out << fmt::format("workspace boundary: {} singular curve image(s) in (ρ, z)\n", boundary.size());
  else
    out << "workspace boundary: singular curves traced for 3R arms only\n";
  if (plan) {
    out << fmt::format("plan: σmin start {} goal {}, margin {}\n", fmtNum(plan->startSigma), fmtNum(plan->goalSigma),
                       fmtNum(plan->margin));
    if (plan->found)
      out << fmt::format("path found: {} states (OMPL RRTConnect), min σmin {} ≥ margin over a dense check\n",
                         plan->path.size(), fmtNum(plan->minSigma));
    else
      out << "no path: " << plan->note << "\n";
  }
  return 0;
}

class WorkspaceCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "workspace";
    spec.help = "reachability and dexterity maps from OMPL samples, the singular "
                "boundary, a plan keeping away from singularities";
    spec.add("robot", robot_, "robot JSON (DESIGN §6)").mustBeGiven();
    spec.add("--samples", o_.samples, "postures sampled within the joint limits").within(1, 1e7).withDefault();
    spec.add("--grid", o_.grid, "cells per side of the (ρ, z) maps").within(8, 2048).withDefault();
    spec.add("--png", o_.png, "reachability map (also STEM_dexterity.png, STEM_path.png)");
    spec.add("--from", o_.from, "start posture q1,q2,... (the robot's angle unit)");
    spec.add("--to", o_.to, "goal posture q1,q2,...");
    spec.add("--margin", o_.margin, "minimum σmin along the plan (dimensionless)").within(0, 1000).withDefault();
    spec.add("--seconds", o_.seconds, "planning time limit (seconds)").within(0.001, 3600).withDefault();
    spec.flag("--json", o_.json, "print one JSON object");
  }
  int run(const Spec&, const Invocation&) override { return workspaceCommand(robot_, o_, std::cout); }

 private:
  std::string robot_;
  WorkspaceCommandOptions o_;
};

}  // namespace

SOMA_CLI_COMMAND(WorkspaceCommand, 70);

}  // namespace soma::cli
