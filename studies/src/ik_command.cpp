#include "soma/studies/ik_command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/studies/pose_file.hpp"
#include "soma/studies/robot_file.hpp"
#include "soma/studies/urdf_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <optional>

namespace soma::studies {

namespace {
// The general-6R family of methods: the algebraic eigenproblem (`general6r`, every scalar) and the
// numerical multi-start enumerations (`ceres`, `nlopt`, double; in another scalar each posture is
// then Newton-polished in that scalar and the note says so).
enum class Numeric { None, Ceres, Nlopt };

template <class S>
Solution<S> general6R(const RobotFile<S>& rf, const SE3<S>& target, Numeric numeric) {
  const std::string name = numeric == Numeric::None ? "general6r" : numeric == Numeric::Ceres ? "ceres" : "nlopt";
  // The general 6R solver (geometry/serial/general_6r.hpp) takes six standard DH rows and the
  // pose of frame 6 in frame 0: strip the file's base and tool.
  if (rf.robot.convention() != DHConvention::Standard || rf.robot.dof() != 6)
    throw InvalidInput("ik method " + name + ": needs a 6-joint robot in standard DH (\"convention\": \"dh\")");
  Robot6R<S> rows;
  for (int i = 0; i < 6; ++i) rows[i] = rf.robot.dhRows()[i];
  const SE3<S> flange = rf.robot.base().inverse() * target * rf.robot.tool().inverse();
  General6RSolution<S> g;
  if (numeric == Numeric::None) {
    g = solveGeneral6R<S>(rows, flange);
    g.notes.push_back("complex solutions of the eigenproblem: " + std::to_string(g.complex_count) +
                      ", solved in " + g.solved_in);
  } else {
    Robot6R<double> rd;
    for (int i = 0; i < 6; ++i) rd[i] = rows[i].template cast<double>();
    const SE3<double> fd = flange.template cast<double>();
    const auto t0 = std::chrono::steady_clock::now();
    General6RSolution<double> gd =
        numeric == Numeric::Ceres ? solveGeneral6RCeres(rd, fd) : solveGeneral6RNlopt(rd, fd);
    g.method = gd.method;
    g.expected_count = gd.expected_count;
    g.notes = gd.notes;
    g.continuum = gd.continuum;
    if constexpr (std::is_same_v<S, double>) {
      g.postures = gd.postures;
      g.residuals = gd.residuals;
    } else {
      // Ceres and NLopt work in double: each posture is the start of Newton steps in S.
      for (const auto& qd : gd.postures) {
        std::array<S, 6> q;
        for (int i = 0; i < 6; ++i) q[i] = scalarCast<S>(qd(i));
        q = polishGeneral6R<S>(rows, flange, q, General6ROptions{}.polish_iterations);
        JointVector<S> v(6);
        for (int i = 0; i < 6; ++i) v(i) = q[i];
        g.postures.push_back(rf.robot.wrap(v));
        g.residuals.push_back(general6rResidual<S>(rows, flange, q));
      }
      g.notes.push_back(name + " enumerates in double; each posture Newton-polished in " +
                        std::string(scalarName<S>()));
    }
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  // The file's joint limits apply as for the closed forms (which drop such postures themselves).
  Solution<S> sol = static_cast<Solution<S>&>(g);
  Solution<S> kept = sol;
  kept.postures.clear();
  kept.residuals.clear();
  for (std::size_t k = 0; k < sol.count(); ++k)
    if (rf.robot.withinLimits(sol.postures[k])) {
      kept.postures.push_back(sol.postures[k]);
      kept.residuals.push_back(sol.residuals[k]);
    }
  if (kept.count() < sol.count())
    kept.notes.push_back(std::to_string(sol.count() - kept.count()) + " posture(s) outside the joint limits dropped");
  return kept;
}

template <class S>
int ikImpl(const std::filesystem::path& file, const std::string& tip, const std::filesystem::path& poseFile,
           IkMethod method, Numeric numeric, bool json, std::ostream& out) {
  const RobotFile<S> rf = readAnyRobot<S>(file, tip);
  const SE3<S> target = readPose<S>(poseFile);
  if (method == IkMethod::Auto) method = classifyRobot(rf.robot);
  Solution<S> sol;
  if (method == IkMethod::General6R) sol = general6R<S>(rf, target, numeric);
  else sol = solveClosedForm<S>(rf.robot, target, method);
  const double unit = rf.degrees ? 180.0 / pi<double>() : 1.0;
  auto jointValue = [&](const JointVector<S>& q, int i) {
    return toDouble(q(i)) * (rf.robot.joints()[i].type == JointType::Revolute ? unit : 1.0);
  };
  bool ok = true;
  for (const auto& r : sol.residuals)
    if (!(r <= Tolerance<S>::sqrtEpsilon())) ok = false;
  if (json) {
    nlohmann::json j;
    j["robot"] = file.string();
    j["name"] = rf.robot.name();
    j["pose_file"] = poseFile.string();
    const Mat3<S> R = target.rotation();
    nlohmann::json rot = nlohmann::json::array();
    for (int r = 0; r < 3; ++r) rot.push_back({toDouble(R(r, 0)), toDouble(R(r, 1)), toDouble(R(r, 2))});
    const Vec3<S> t = target.translation();
    j["pose"] = {{"rotation", rot}, {"translation", {toDouble(t(0)), toDouble(t(1)), toDouble(t(2))}}};
    j["angles"] = rf.degrees ? "degrees" : "radians";
    j["method"] = sol.method;
    j["scalar"] = std::string(scalarName<S>());
    j["seconds"] = sol.seconds;
    j["expected_count"] = sol.expected_count;
    j["count"] = sol.count();
    j["continuum"] = sol.continuum;
    j["notes"] = sol.notes;
    nlohmann::json arr = nlohmann::json::array();
    for (std::size_t k = 0; k < sol.count(); ++k) {
      nlohmann::json jq = nlohmann::json::array();
      for (int i = 0; i < sol.postures[k].size(); ++i) jq.push_back(jointValue(sol.postures[k], i));
      arr.push_back({{"joints", jq}, {"residual", toDouble(sol.residuals[k])}});
    }
    j["solutions"] = arr;
    out << j.dump(2) << "\n";
    return ok ? 0 : 1;
  }
  out << fmt::format("robot: {} ({} joints)   method: {}   scalar: {}\n", rf.robot.name(), rf.robot.dof(),
                     sol.method, scalarName<S>());
  out << fmt::format("postures: {} found, {} expected in general   time: {:.3g} s{}\n", sol.count(),
                     sol.expected_count, sol.seconds, sol.continuum ? "   (a continuum: representatives)" : "");
  for (std::size_t k = 0; k < sol.count(); ++k) {
    std::string line = fmt::format("  {:>2}:", k + 1);
    for (int i = 0; i < sol.postures[k].size(); ++i) line += fmt::format(" {:>12.7f}", jointValue(sol.postures[k], i));
    line += fmt::format("   residual {}", toString(sol.residuals[k], 3));
    out << line << "\n";
  }
  if (rf.degrees) out << "  (joint angles in degrees)\n";
  for (const auto& n : sol.notes) out << "note: " << n << "\n";
  return ok ? 0 : 1;
}
}  // namespace

int ikCommand(const std::filesystem::path& robot, const std::filesystem::path& pose,
              const std::string& method, ScalarKind scalar, bool json, std::ostream& out,
              const std::string& tip) {
  const Numeric numeric = method == "ceres" ? Numeric::Ceres : method == "nlopt" ? Numeric::Nlopt : Numeric::None;
  const auto m = numeric != Numeric::None ? std::optional<IkMethod>(IkMethod::General6R) : parseIkMethod(method);
  if (!m) throw InvalidInput("--method: \"" + method + "\" is not one of " + ikMethodNames() + " ceres nlopt");
  return withScalar(scalar, [&]<class S>() { return ikImpl<S>(robot, tip, pose, *m, numeric, json, out); });
}

}  // namespace soma::studies
