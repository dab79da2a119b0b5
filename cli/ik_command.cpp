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
#include "soma/io/json_number.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/robot_file.hpp"
#include "soma/io/urdf_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <iostream>

namespace soma::cli {

namespace {


template <class S>
int ikImpl(const std::filesystem::path& file, const std::string& tip, const std::filesystem::path& poseFile,
           IkMethod method, bool json, std::ostream& out, const FigureFiles& fig) {
  const io::RobotFile<S> rf = io::readAnyRobot<S>(file, tip);
  const SE3<S> target = io::readPose<S>(poseFile);
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
              const std::string& tip, const FigureFiles& fig) {
  const auto m = parseIkMethod(method);
  if (!m) throw InvalidInput("--method: \"" + method + "\" is not one of " + ikMethodNames());
  return withScalar(scalar, [&]<class S>() { return ikImpl<S>(robot, tip, pose, *m, json, out, fig); });
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
    spec.flag("--json", json_, "print one JSON object");
    spec.add("--png", fig_.png, "write the figure (PNG): the robot at each posture, a panel each");
    spec.add("--svg", fig_.svg, "write the figure as SVG (a line drawing of the same panels)");
  }
  int run(const Spec&, const Invocation&) override {
    return ikCommand(robot_, pose_, method_, scalar_.apply(), json_, std::cout, tip_, fig_);
  }

 private:
  std::string robot_, pose_, method_ = "auto", tip_;
  ScalarOptions scalar_;
  FigureFiles fig_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(IkCommand, 50);

}  // namespace soma::cli
