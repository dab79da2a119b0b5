// `soma ik ROBOT.json|ROBOT.urdf [--tip LINK] --pose POSE.json [--method M] [--scalar T] [--json]` (DESIGN §6): every
// real posture of the robot for the pose, each with its residual, the method, the expected count
// and the time.
#include "command.hpp"
#include "json_output.hpp"
#include "posture_figure.hpp"
#include "scalar_options.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/serial/ik.hpp"
#include "soma/geometry/serial/redundant_ik.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/number.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/robot_file.hpp"
#include "soma/io/urdf_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <iostream>
#include <optional>

namespace soma::cli {

namespace {

/// `--redundancy` and `--sweep` of a redundant arm (7 or more joints).
struct RedundancyRequest {
  std::string spec;  ///< "J", "J=V" or "J=V,K=W,…" (1-based joints, values in the file's unit); empty: chosen
  std::string sweep;  ///< number of values of the first locked joint over its range; empty: not asked
};

/// The locked joints and their value lists from the request: a sweep of the first locked joint
/// (over its range, redundancySweepValues) unless every joint has a value and no sweep is asked.
template <class S>
std::pair<std::vector<int>, std::vector<std::vector<S>>> redundancyValues(const io::RobotFile<S>& rf, const RedundancyRequest& req) {
  const SerialRobot<S>& robot = rf.robot;
  std::vector<int> joints;
  std::vector<std::optional<S>> fixed;
  if (req.spec.empty()) {
    joints.push_back(chooseRedundancyJoint(robot));
    fixed.emplace_back();
  } else {
    std::size_t start = 0;
    while (start <= req.spec.size()) {
      const std::size_t comma = std::min(req.spec.find(',', start), req.spec.size());
      const std::string item = req.spec.substr(start, comma - start);
      const std::size_t eq = item.find('=');
      const int k = int(io::parseInteger(item.substr(0, eq), "--redundancy: \"" + item + "\": joint", 1, robot.dof())) - 1;
      joints.push_back(k);
      if (eq == std::string::npos) {
        fixed.emplace_back();
      } else {
        S v = io::parseDecimal<S>(item.substr(eq + 1), "--redundancy: \"" + item + "\": value");
        const bool deg = rf.degrees && robot.joints()[k].type == JointType::Revolute;
        const S given = v;
        if (deg) v = v * pi<S>() / S(180);
        const auto& jt = robot.joints()[k];
        if (v < jt.lower || v > jt.upper) {  // said in the file's unit, not the library's radians
          const S u = deg ? S(180) / pi<S>() : S(1);
          throw InvalidInput("--redundancy: joint " + std::to_string(k + 1) + " value " + io::numberText(given) + " is outside its limits [" +
                             toString(jt.lower * u, 6) + ", " + toString(jt.upper * u, 6) + "]" + (deg ? " (degrees)" : ""));
        }
        fixed.emplace_back(v);
      }
      start = comma + 1;
    }
  }
  const int needed = robot.dof() - 6;
  if (int(joints.size()) != needed)
    throw InvalidInput("--redundancy: a " + std::to_string(robot.dof()) + "-joint robot needs " + std::to_string(needed) +
                       " locked joint(s), \"" + req.spec + "\" names " + std::to_string(joints.size()));
  for (std::size_t a = 1; a < fixed.size(); ++a)
    if (!fixed[a]) throw InvalidInput("--redundancy: joint " + std::to_string(joints[a] + 1) + " needs a value (only the first locked joint is swept)");
  const bool sweep = !req.sweep.empty() || !fixed[0];
  const int count = req.sweep.empty() ? 12 : int(io::parseInteger(req.sweep, "--sweep", 1, 100000));
  if (!req.sweep.empty() && fixed[0])
    throw InvalidInput("--sweep: joint " + std::to_string(joints[0] + 1) + " has a value in --redundancy (give the joint alone to sweep it)");
  std::vector<std::vector<S>> values;
  std::vector<S> rest;
  for (std::size_t a = 1; a < fixed.size(); ++a) rest.push_back(*fixed[a]);
  if (sweep) {
    for (const S& v : redundancySweepValues(robot, joints[0], count)) {
      std::vector<S> row{v};
      row.insert(row.end(), rest.begin(), rest.end());
      values.push_back(row);
    }
  } else {
    std::vector<S> row{*fixed[0]};
    row.insert(row.end(), rest.begin(), rest.end());
    values.push_back(row);
  }
  return {joints, values};
}

/// `soma ik` on a redundant arm: the family of postures at each value of the redundancy parameter.
template <class S>
int redundantIk(const io::RobotFile<S>& rf, const std::filesystem::path& file, const std::filesystem::path& poseFile, const SE3<S>& target,
                IkMethod method, const RedundancyRequest& req, bool json, std::ostream& out, const FigureFiles& fig) {
  const SerialRobot<S>& robot = rf.robot;
  const auto [joints, values] = redundancyValues<S>(rf, req);
  RedundantIkOptions options;
  options.joints = joints;
  options.ik.method = method;
  const RedundantIkSolution<S> sol = solveRedundantIk<S>(robot, target, values, options);
  const S unit = rf.degrees ? S(180) / pi<S>() : S(1);
  auto shown = [&](const S& v, int i) -> S { return v * (robot.joints()[i].type == JointType::Revolute ? unit : S(1)); };
  bool ok = true;
  std::vector<JointVector<S>> drawn;  // one posture per value, for the figure
  for (const auto& s : sol.slices) {
    for (const auto& r : s.solution.residuals)
      if (!(r <= Tolerance<S>::sqrtEpsilon())) ok = false;
    if (s.solution.count() > 0) drawn.push_back(s.solution.postures.front());
  }
  const int exitCode = !ok ? 1 : sol.count() == 0 ? 3 : 0;
  std::string jointList;
  for (std::size_t a = 0; a < joints.size(); ++a) jointList += (a ? ", " : "") + std::to_string(joints[a] + 1);
  // One value: every posture of it; a sweep: the first posture at each value (one panel each).
  const bool single = sol.slices.size() == 1;
  if (single) drawn = sol.slices[0].solution.postures;
  writeRobotFigures<S>(robot, drawn, rf.degrees,
                       single ? fmt::format("{}: {} posture(s), joint {} locked", robot.name(), drawn.size(), joints[0] + 1)
                              : fmt::format("{}: joint {} swept, first posture per value", robot.name(), joints[0] + 1),
                       fig);
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = robot.name();
    j["pose_file"] = poseFile.string();
    j["pose"] = io::poseJson(target);
    j["angles"] = rf.degrees ? "degrees" : "radians";
    io::addScalar<S>(j);
    j["seconds"] = sol.seconds;
    j["count"] = sol.count();
    j["continuum"] = true;
    j["self_motion_dimension"] = robot.dof() - 6;
    nlohmann::json jj = nlohmann::json::array();
    for (int k : joints) jj.push_back(k + 1);
    j["redundancy"] = {{"joints", jj}, {"swept", values.size() > 1}};
    nlohmann::json fam = nlohmann::json::array();
    for (const auto& s : sol.slices) {
      nlohmann::json e;
      nlohmann::json jv = nlohmann::json::array();
      for (std::size_t a = 0; a < s.values.size(); ++a) jv.push_back(io::jsonNumber(shown(s.values[a], joints[a])));
      e["values"] = jv;
      e["method"] = s.solution.method;
      e["expected_count"] = s.solution.expected_count;
      e["count"] = s.solution.count();
      e["certified"] = s.solution.certified;
      if (!s.solution.elimination.empty()) e["elimination"] = s.solution.elimination;
      if (!s.solution.reason.empty()) e["reason"] = s.solution.reason;
      e["notes"] = s.solution.notes;
      nlohmann::json arr = nlohmann::json::array();
      for (std::size_t k = 0; k < s.solution.count(); ++k) {
        nlohmann::json jq = nlohmann::json::array();
        for (int i = 0; i < s.solution.postures[k].size(); ++i) jq.push_back(io::jsonNumber(shown(s.solution.postures[k](i), i)));
        arr.push_back({{"joints", jq}, {"residual", io::jsonNumber(s.solution.residuals[k])}});
      }
      e["solutions"] = arr;
      fam.push_back(e);
    }
    j["family"] = fam;
    out << jsonText(j) << "\n";
    return exitCode;
  }
  out << fmt::format("robot: {} ({} joints, redundant)   scalar: {}\n", robot.name(), robot.dof(), scalarName<S>());
  out << fmt::format("postures: a {}-dimensional family, parametrised by joint(s) {}: {} posture(s) at {} value(s)   time: {:.3g} s\n",
                     robot.dof() - 6, jointList, sol.count(), sol.slices.size(), sol.seconds);
  for (const auto& s : sol.slices) {
    std::string head = "joint";
    for (std::size_t a = 0; a < s.values.size(); ++a)
      head += fmt::format("{} {} = {}", a ? "," : "", joints[a] + 1, io::numberText(shown(s.values[a], joints[a])));
    out << fmt::format("{}: {} posture(s) ({}, {} expected in general{})\n", head, s.solution.count(), s.solution.method,
                       s.solution.expected_count, s.solution.certified ? ", certified complete" : "");
    if (!s.solution.reason.empty()) out << "  no posture: " << s.solution.reason << "\n";
    for (std::size_t k = 0; k < s.solution.count(); ++k) {
      std::string line = fmt::format("  {:>2}:", k + 1);
      for (int i = 0; i < s.solution.postures[k].size(); ++i) line += " " + io::numberText(shown(s.solution.postures[k](i), i));
      line += fmt::format("   residual {}", toString(s.solution.residuals[k], 3));
      out << line << "\n";
    }
    for (const auto& n : s.solution.notes) out << "  note: " << n << "\n";
  }
  if (rf.degrees) out << "  (joint angles in degrees)\n";
  return exitCode;
}

template <class S>
int ikImpl(const std::filesystem::path& file, const std::string& tip, const std::filesystem::path& poseFile,
           IkMethod method, const RedundancyRequest& req, bool json, std::ostream& out, const FigureFiles& fig) {
  const io::RobotFile<S> rf = io::readAnyRobot<S>(file, tip);
  const SE3<S> target = io::readPose<S>(poseFile);
  if (rf.robot.dof() >= 7) return redundantIk<S>(rf, file, poseFile, target, method, req, json, out, fig);
  if (!req.spec.empty() || !req.sweep.empty())
    throw InvalidInput(std::string(req.spec.empty() ? "--sweep" : "--redundancy") + ": " + rf.robot.name() + " has " +
                       std::to_string(rf.robot.dof()) + " joints (a redundancy parameter needs 7 or more)");
  IkOptions options;
  options.method = method;
  const IkSolution<S> sol = solveIk<S>(rf.robot, target, options);
  const S unit = rf.degrees ? S(180) / pi<S>() : S(1);
  auto jointValue = [&](const JointVector<S>& q, int i) -> S {
    return q(i) * (rf.robot.joints()[i].type == JointType::Revolute ? unit : S(1));
  };
  // general6r re-solves in a wider scalar when S fell short (DESIGN §3): the answer says so.
  const bool escalated = !sol.solved_in.empty() && sol.solved_in != scalarName<S>();
  bool ok = true;
  for (const auto& r : sol.residuals)
    if (!(r <= Tolerance<S>::sqrtEpsilon())) ok = false;
  // docs/cli.md: 1 a residual above its bound, 3 no posture (the reason says why), else 0.
  const int exitCode = !ok ? 1 : sol.count() == 0 ? 3 : 0;
  writeRobotFigures<S>(rf.robot, sol.postures, rf.degrees,
                       fmt::format("{}: {} posture(s) for {} ({})", rf.robot.name(), sol.count(), poseFile.filename().string(),
                                   sol.self_motion_dimension > 0 ? "representatives of a self-motion" : sol.method),
                       fig);
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = rf.robot.name();
    j["pose_file"] = poseFile.string();
    j["pose"] = io::poseJson(target);
    j["angles"] = rf.degrees ? "degrees" : "radians";
    j["method"] = sol.method;
    io::addScalar<S>(j);
    if (escalated) j["escalated_to"] = sol.solved_in;
    j["seconds"] = sol.seconds;
    j["expected_count"] = sol.expected_count;
    j["count"] = sol.count();
    j["certified"] = sol.certified;
    j["continuum"] = sol.continuum;
    if (sol.generic_rank >= 0) j["generic_rank"] = sol.generic_rank;
    if (sol.self_motion_dimension > 0) j["self_motion_dimension"] = sol.self_motion_dimension;
    if (!sol.elimination.empty()) j["elimination"] = sol.elimination;
    if (!sol.reason.empty()) j["reason"] = sol.reason;
    j["notes"] = sol.notes;
    nlohmann::json arr = nlohmann::json::array();
    for (std::size_t k = 0; k < sol.count(); ++k) {
      nlohmann::json jq = nlohmann::json::array();
      for (int i = 0; i < sol.postures[k].size(); ++i) jq.push_back(io::jsonNumber(jointValue(sol.postures[k], i)));
      arr.push_back({{"joints", jq}, {"residual", io::jsonNumber(sol.residuals[k])}});
    }
    j["solutions"] = arr;
    out << jsonText(j) << "\n";
    return exitCode;
  }
  out << fmt::format("robot: {} ({} joints)   method: {}   scalar: {}{}\n", rf.robot.name(), rf.robot.dof(),
                     sol.method, scalarName<S>(), escalated ? "   escalated to " + sol.solved_in : "");
  if (sol.self_motion_dimension > 0)
    out << fmt::format("postures: a {}-dimensional self-motion (generic rank {} of 6), {} representative(s)   time: {:.3g} s\n",
                       sol.self_motion_dimension, sol.generic_rank, sol.count(), sol.seconds);
  else
    out << fmt::format("postures: {} found, {} expected in general{}   time: {:.3g} s{}\n", sol.count(),
                       sol.expected_count, sol.certified ? " (certified complete)" : "", sol.seconds,
                       sol.continuum ? "   (a continuum: representatives)" : "");
  if (!sol.reason.empty()) out << "no posture: " << sol.reason << "\n";
  for (std::size_t k = 0; k < sol.count(); ++k) {
    std::string line = fmt::format("  {:>2}:", k + 1);
    for (int i = 0; i < sol.postures[k].size(); ++i) line += " " + io::numberText(jointValue(sol.postures[k], i));  // S's digits
    line += fmt::format("   residual {}", toString(sol.residuals[k], 3));
    out << line << "\n";
  }
  if (rf.degrees) out << "  (joint angles in degrees)\n";
  for (const auto& n : sol.notes) out << "note: " << n << "\n";
  return exitCode;
}

int ikCommand(const std::filesystem::path& robot, const std::filesystem::path& pose,
              const std::string& method, ScalarKind scalar, bool json, std::ostream& out,
              const std::string& tip, const FigureFiles& fig, const RedundancyRequest& req) {
  const auto m = parseIkMethod(method);
  if (!m) throw InvalidInput("--method: \"" + method + "\" is not one of " + ikMethodNames());
  return withScalar(scalar, [&]<class S>() { return ikImpl<S>(robot, tip, pose, *m, req, json, out, fig); });
}

class IkCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "ik";
    spec.help = "inverse kinematics: every real posture of a robot for a pose";
    spec.add("robot", robot_, "robot JSON (DESIGN §6) or URDF (.urdf: a serial chain)").mustBeGiven();
    spec.add("--tip", tip_, "URDF only: the chain's tip link (default: the only leaf link)");
    spec.add("--pose", pose_, "pose JSON: {\"rotation\": [[3x3]], \"translation\": [x,y,z]}").mustBeGiven();
    spec.add("--method", method_, "auto wrist3r arm3r pieper general6r (every scalar); ceres nlopt (double, Newton-polished in other scalars)")
        .withDefault();
    scalar_.declare(spec);
    spec.add("--redundancy", redundancy_.spec,
             "7+ joints: the locked joint(s) of the family, J or J=V[,K=W…] (1-based; V in the file's unit; default: chosen)");
    spec.add("--sweep", redundancy_.sweep, "7+ joints: N values of the first locked joint over its range (default 12 when it has no value)");
    spec.flag("--json", json_, "print one JSON object");
    spec.add("--png", fig_.png, "write the figure (PNG): the robot at each posture, a panel each");
    spec.add("--svg", fig_.svg, "write the figure as SVG (a line drawing of the same panels)");
  }
  int run(const Spec&, const Invocation&) override {
    return ikCommand(robot_, pose_, method_, scalar_.apply(), json_, std::cout, tip_, fig_, redundancy_);
  }

 private:
  std::string robot_, pose_, method_ = "auto", tip_;
  ScalarOptions scalar_;
  FigureFiles fig_;
  RedundancyRequest redundancy_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(IkCommand, 50);

}  // namespace soma::cli
