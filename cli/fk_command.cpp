// `soma fk ROBOT.json|ROBOT.urdf [--tip LINK] --joints q1,q2,... [--json]` (DESIGN §6): the tool pose T(q), and the
// singularity measures of the configuration, in any scalar type.
#include "command.hpp"
#include "json_output.hpp"
#include "posture_figure.hpp"
#include "scalar_options.hpp"

#include "soma/io/json_number.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/robot_file.hpp"
#include "soma/io/urdf_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace soma::cli {

namespace {

template <class S> int fkImpl(const std::filesystem::path& file, const std::string& tip, const std::string& joints, bool json,
                              std::ostream& out, const FigureFiles& fig) {
  const io::RobotFile<S> rf = io::readAnyRobot<S>(file, tip);
  const JointVector<S> q = io::parseJoints<S>(joints, rf);
  const auto t0 = std::chrono::steady_clock::now();
  const SE3<S> T = rf.robot.fk(q);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto sm = singularityMeasures(rf.robot, q);
  const Mat3<S> R = T.rotation();
  writeRobotFigures<S>(rf.robot, {q}, rf.degrees, rf.robot.name() + " at the joints given", fig);
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = rf.robot.name();
    j["angles"] = rf.degrees ? "degrees" : "radians";
    nlohmann::json jq = nlohmann::json::array();  // echoed as given (degrees stay exact: no round trip through radians)
    for (const S& v : io::parseJointValues<S>(joints, rf)) jq.push_back(io::jsonNumber(v));
    j["joints"] = jq;
    io::addScalar<S>(j);
    j["seconds"] = secs;
    j["pose"] = io::poseJson(T);
    j["singularity"] = {{"manipulability", io::jsonNumber(sm.manipulability)},
                        {"smallest_singular_value", io::jsonNumber(sm.smallestSingularValue)},
                        {"condition", io::jsonNumber(sm.condition)},
                        {"rank", sm.rank}};
    out << jsonText(j) << "\n";
    return 0;
  }
  out << fmt::format("robot: {} ({} joints)   scalar: {}\n", rf.robot.name(), rf.robot.dof(), scalarName<S>());
  // Every number in S's digits (json_number.hpp): 17 for double, 79 for mpfr at 256 bits.
  out << "rotation:\n";
  for (int r = 0; r < 3; ++r)
    out << fmt::format("  {:>24} {:>24} {:>24}\n", io::numberText(R(r, 0)), io::numberText(R(r, 1)),
                       io::numberText(R(r, 2)));
  out << fmt::format("translation: {} {} {}\n", io::numberText(T.translation()(0)),
                     io::numberText(T.translation()(1)), io::numberText(T.translation()(2)));
  out << fmt::format("singularity: manipulability {}  smallest singular value {}  condition {}  rank {}\n",
                     toString(sm.manipulability, 6), toString(sm.smallestSingularValue, 6),
                     toString(sm.condition, 6), sm.rank);
  return 0;
}

int fkCommand(const std::filesystem::path& robot, const std::string& joints, ScalarKind scalar,
              bool json, std::ostream& out, const std::string& tip, const FigureFiles& fig) {
  return withScalar(scalar, [&]<class S>() { return fkImpl<S>(robot, tip, joints, json, out, fig); });
}

class FkCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "fk";
    spec.help = "forward kinematics: the tool pose of a robot file at a joint vector";
    spec.add("robot", robot_, "robot JSON (DESIGN §6: dh, mdh or poe joints) or URDF (.urdf: a serial chain)").mustBeGiven();
    spec.add("--tip", tip_, "URDF only: the chain's tip link (default: the only leaf link)");
    spec.add("--joints", joints_, "q1,q2,... (degrees when the robot file says \"angles\": \"degrees\"; --joints=-0.5,... for a leading minus)")
        .mustBeGiven();
    scalar_.declare(spec);
    spec.flag("--json", json_, "print one JSON object");
    spec.add("--png", fig_.png, "write the figure (PNG): the robot at each posture, a panel each");
    spec.add("--svg", fig_.svg, "write the figure as SVG (a line drawing of the same panels)");
  }
  int run(const Spec&, const Invocation&) override {
    return fkCommand(robot_, joints_, scalar_.apply(), json_, std::cout, tip_, fig_);
  }

 private:
  std::string robot_, joints_, tip_;
  ScalarOptions scalar_;
  FigureFiles fig_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(FkCommand, 40);

}  // namespace soma::cli
