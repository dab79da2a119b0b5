#include "soma/studies/ik_command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/robot_file.hpp"
#include "soma/io/urdf_file.hpp"

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

// A 6R robot given by its joint axes (POE, a URDF chain, modified DH) as standard DH rows with a
// base and a tool transform, for the general-6R solver (GF §3.4: DH frames from the common normals
// of consecutive axes). Frame i-1 has z along axis i; x_i runs along the common normal of axes i
// and i+1 (for parallel axes: the normal through the previous origin, d_i = 0); frame 6 = frame 5
// turned by joint 6. Joint offsets go into the θ_i. Checked: the DH robot's FK equals the robot's.
template <class S> SerialRobot<S> standardDH(const SerialRobot<S>& robot) {
  using std::atan2;
  using std::sqrt;
  const auto& J = robot.joints();
  std::array<Vec3<S>, 7> x, z, o;  // frames 0..6 (x_0 = x_1, frame 6 = frame 5)
  std::vector<DHRow<S>> rows(6);
  const S par = Tolerance<S>::input();
  Vec3<S> prevOrigin = J[0].point;
  for (int i = 0; i < 5; ++i) {
    const Vec3<S> ui = J[i].axis, uj = J[i + 1].axis, w = J[i + 1].point - J[i].point;
    const Vec3<S> n = ui.cross(uj);
    Vec3<S> foot;  // foot of the common normal on axis i (c_i) and on axis i+1 (o_i)
    if (n.squaredNorm() > par * par) {
      x[i + 1] = n / sqrt(n.squaredNorm());
      // c_i = p_i + s u_i, o_i = p_j + t u_j with o_i − c_i ∥ x: (w + t u_j − s u_i)·u_{i,j} = 0.
      const S b = ui.dot(uj), d1 = w.dot(ui), d2 = w.dot(uj), den = S(1) - b * b;
      const S sPar = (d1 - b * d2) / den, tPar = (b * d1 - d2) / den;
      foot = J[i].point + sPar * ui;
      o[i + 1] = J[i + 1].point + tPar * uj;
    } else {
      foot = prevOrigin;  // on axis i already (the previous foot), so d_i = 0 for i > 0
      const Vec3<S> r = J[i + 1].point - foot, perp = r - r.dot(ui) * ui;
      x[i + 1] = perp.squaredNorm() > par * par * robot.lengthScale() * robot.lengthScale()
                     ? Vec3<S>(perp / sqrt(perp.squaredNorm()))
                     : (i == 0 ? Vec3<S>(ui.unitOrthogonal()) : x[i]);
      o[i + 1] = foot + perp.dot(x[i + 1]) * x[i + 1];
    }
    z[i + 1] = uj;
    if (i == 0) {
      x[0] = x[1], z[0] = ui, o[0] = foot;
    }
    DHRow<S>& r = rows[i];
    r.d = (foot - o[i]).dot(z[i]);
    r.theta = atan2(x[i].cross(x[i + 1]).dot(z[i]), x[i].dot(x[i + 1])) + J[i].offset;
    r.a = (o[i + 1] - foot).dot(x[i + 1]);
    r.alpha = atan2(z[i].cross(z[i + 1]).dot(x[i + 1]), z[i].dot(z[i + 1]));
    prevOrigin = o[i + 1];
  }
  rows[5].theta = J[5].offset;
  auto frame = [&](int i) {
    Mat3<S> R;
    R.col(0) = x[i], R.col(1) = z[i].cross(x[i]), R.col(2) = z[i];
    return SE3<S>(SO3<S>::fromMatrix(R), o[i]);
  };
  const SE3<S> base = frame(0), tool = frame(5).inverse() * robot.home();
  SerialRobot<S> dh = SerialRobot<S>::fromDH(rows, DHConvention::Standard, base, tool, robot.name());
  std::vector<S> lo, hi;
  for (const auto& j : J) lo.push_back(j.lower), hi.push_back(j.upper);
  dh = dh.withLimits(lo, hi);
  JointVector<S> q(6);
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 6; ++i) q(i) = S(k + 1) * S(i - 2) / S(3);
    if (!(poseResidual(dh.fk(q), robot.fk(q), robot.lengthScale()) <= Tolerance<S>::identity(4096)))
      throw InvalidInput("ik: the robot's joint axes could not be written as standard DH rows (FK mismatch)");
  }
  return dh;
}

/// When the algebraic answer may be short (the eigenproblem did not give 16 complex solutions, an
/// odd real count, or the solver says so — e.g. a leading matrix singular at every θ3 offset, as
/// for robots just outside the Pieper class), change strategy: a Ceres multi-start search in
/// double, each posture Newton-polished in S and added when it is new. The count is then not
/// certified, and the notes say so. GF §11.5 (16 complex postures)
template <class S>
void completeNumerically(const Robot6R<S>& rows, const SE3<S>& flange, const io::RobotFile<S>& rf, General6RSolution<S>& g) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  bool mayBeShort = g.complex_count != 16 || g.count() % 2 == 1;
  for (const auto& n : g.notes)
    if (n.find("may be short") != std::string::npos) mayBeShort = true;
  if (!mayBeShort) return;
  Robot6R<double> rd;
  for (int i = 0; i < 6; ++i) rd[i] = rows[i].template cast<double>();
  const SE3<double> fd = flange.template cast<double>();
  const auto t0 = std::chrono::steady_clock::now();
  General6RNumericOptions opt;
  opt.starts = 128;
  const General6RSolution<double> gd = solveGeneral6RCeres(rd, fd, opt);
  int added = 0;
  for (const auto& qd : gd.postures) {
    std::array<S, 6> q;
    for (int i = 0; i < 6; ++i) q[i] = scalarCast<S>(qd(i));
    q = polishGeneral6R<S>(rows, flange, q, General6ROptions{}.polish_iterations);
    const S r = general6rResidual<S>(rows, flange, q);
    if (!(r <= Tolerance<S>::sqrtEpsilon())) continue;
    JointVector<S> v(6);
    for (int i = 0; i < 6; ++i) v(i) = q[i];
    v = rf.robot.wrap(v);
    bool known = false;
    for (const auto& p : g.postures) {
      S gap(0);
      for (int i = 0; i < 6; ++i) {
        const S d = v(i) - p(i);
        gap = std::max<S>(gap, abs(atan2(sin(d), cos(d))));
      }
      if (gap <= Tolerance<S>::input()) known = true;
    }
    if (known) continue;
    g.postures.push_back(v);
    g.residuals.push_back(r);
    ++added;
  }
  g.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  g.notes.push_back("the eigenproblem answer may be short (" + std::to_string(g.complex_count) +
                    " complex solutions): numerical completion by Ceres (128 starts in double, Newton in " +
                    std::string(scalarName<S>()) + ") added " + std::to_string(added) +
                    " posture(s); this count is not certified complete");
}

template <class S>
Solution<S> general6R(const io::RobotFile<S>& rfIn, const SE3<S>& target, Numeric numeric) {
  const std::string name = numeric == Numeric::None ? "general6r" : numeric == Numeric::Ceres ? "ceres" : "nlopt";
  if (rfIn.robot.dof() != 6 || !rfIn.robot.allRevolute())
    throw InvalidInput("ik method " + name + ": needs a robot with 6 revolute joints");
  // The general 6R solver (geometry/serial/general_6r.hpp) takes six standard DH rows and the
  // pose of frame 6 in frame 0: a POE (URDF) or modified-DH robot is rewritten in standard DH
  // first, then the base and tool are stripped.
  io::RobotFile<S> rf = rfIn;
  if (rf.robot.convention() != DHConvention::Standard) rf.robot = standardDH(rf.robot);
  Robot6R<S> rows;
  for (int i = 0; i < 6; ++i) rows[i] = rf.robot.dhRows()[i];
  const SE3<S> flange = rf.robot.base().inverse() * target * rf.robot.tool().inverse();
  General6RSolution<S> g;
  if (numeric == Numeric::None) {
    g = solveGeneral6R<S>(rows, flange);
    g.notes.push_back("complex solutions of the eigenproblem: " + std::to_string(g.complex_count) +
                      ", solved in " + g.solved_in);
    completeNumerically<S>(rows, flange, rf, g);
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
  const io::RobotFile<S> rf = io::readAnyRobot<S>(file, tip);
  const SE3<S> target = io::readPose<S>(poseFile);
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
