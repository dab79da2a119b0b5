#pragma once
// Definitions of robot_file.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/robot_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/input_limits.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/link_inertia_file.hpp"
#include "soma/io/number.hpp"
#include "soma/io/pose_file.hpp"


namespace soma::io {

namespace {
using json = nlohmann::json;

template <class S> Vec3<S> vec3(const json& j, const std::string& where, const KeyPath& path) {
  if (!j.is_array() || j.size() != 3) throw InvalidInput(where + ": expected an array of 3 numbers");
  Vec3<S> v;
  for (int i = 0; i < 3; ++i) v(i) = readNumber<S>(j[std::size_t(i)], path.index(std::size_t(i)));
  return v;
}

template <class S> S angleUnit(bool degrees) { return degrees ? S(pi<S>() / S(180)) : S(1); }

template <class S>
void jointLimits(const json& jj, const std::string& where, const KeyPath& path, bool angular, bool degrees, S& lo, S& hi) {
  if (!jj.contains("limits")) return;
  const json& l = jj["limits"];
  if (!l.is_array() || l.size() != 2) throw InvalidInput(where + " limits: expected [lower, upper]");
  const S u = angular ? angleUnit<S>(degrees) : S(1);
  lo = readNumber<S>(l[0], path.key("limits").index(0)) * u;
  hi = readNumber<S>(l[1], path.key("limits").index(1)) * u;
  if (lo > hi) throw InvalidInput(where + " limits: lower limit exceeds upper limit");
}

JointType jointType(const json& jj, const std::string& where) {
  if (!jj.contains("type")) return JointType::Revolute;
  const json& t = jj["type"];
  if (t.is_string() && (t == "R" || t == "revolute")) return JointType::Revolute;
  if (t.is_string() && (t == "P" || t == "prismatic")) return JointType::Prismatic;
  throw InvalidInput(where + " type: expected \"R\" or \"P\"");
}
}  // namespace

template <class S> RobotFile<S> parseRobot(const std::string& text, const std::string& origin) {
  const json j = parseJson(text, origin);
  if (!j.is_object()) throw InvalidInput(origin + ": a robot must be a JSON object");
  checkKeys(j, {"name", "angles", "convention", "joints", "base", "tool", "home", "description", "links"}, origin);
  RobotFile<S> out;
  if (j.contains("links")) out.links = linkInertiasFromJson(j, origin);  // GF ch. 13 inertial data
  const std::string name = j.contains("name") && j["name"].is_string() ? j["name"].get<std::string>() : "";
  if (j.contains("angles")) {
    if (j["angles"] == "degrees") out.degrees = true;
    else if (j["angles"] != "radians")
      throw InvalidInput(origin + ": \"angles\" must be \"degrees\" or \"radians\"");
  }
  if (!j.contains("convention") || !j["convention"].is_string())
    throw InvalidInput(origin + ": missing \"convention\" (\"dh\", \"mdh\" or \"poe\")");
  const std::string conv = j["convention"];
  if (conv != "dh" && conv != "mdh" && conv != "poe")
    throw InvalidInput(origin + ": convention \"" + conv + "\" is not one of dh, mdh, poe");
  if (!j.contains("joints") || !j["joints"].is_array() || j["joints"].empty())
    throw InvalidInput(origin + ": \"joints\" must be a non-empty array");
  if (j["joints"].size() > limits::maxJoints)
    throw InvalidInput(origin + ": joints: " + std::to_string(j["joints"].size()) + " joints, more than the " +
                       std::to_string(limits::maxJoints) + " soma reads");
  const S du = angleUnit<S>(out.degrees);
  const KeyPath joints = KeyPath(origin).key("joints");
  std::vector<S> lo, hi;
  if (conv == "poe") {
    if (!j.contains("home")) throw InvalidInput(origin + ": a poe robot needs the tool's \"home\" pose");
    std::vector<SerialJoint<S>> js;
    for (std::size_t i = 0; i < j["joints"].size(); ++i) {
      const json& jj = j["joints"][i];
      const std::string where = origin + ": joint " + std::to_string(i + 1);
      const KeyPath path = joints.index(i);
      if (!jj.is_object()) throw InvalidInput(where + ": expected an object");
      checkKeys(jj, {"type", "axis", "point", "offset", "limits"}, where,
                "(a poe joint has type, axis, point, offset, limits)");
      SerialJoint<S> sj;
      sj.type = jointType(jj, where);
      if (!jj.contains("axis")) throw InvalidInput(where + ": missing \"axis\"");
      sj.axis = vec3<S>(jj["axis"], where + " axis", path.key("axis"));
      if (sj.type == JointType::Revolute) {
        if (!jj.contains("point")) throw InvalidInput(where + ": missing \"point\" (a point of the axis)");
        sj.point = vec3<S>(jj["point"], where + " point", path.key("point"));
      }
      const bool ang = sj.type == JointType::Revolute;
      if (jj.contains("offset")) sj.offset = readNumber<S>(jj["offset"], path.key("offset")) * (ang ? du : S(1));
      jointLimits<S>(jj, where, path, ang, out.degrees, sj.lower, sj.upper);
      js.push_back(sj);
    }
    out.robot = SerialRobot<S>::fromPOE(js, poseFromJson<S>(j["home"], origin + ": home"), name);
    return out;
  }
  std::vector<DHRow<S>> rows;
  for (std::size_t i = 0; i < j["joints"].size(); ++i) {
    const json& jj = j["joints"][i];
    const std::string where = origin + ": joint " + std::to_string(i + 1);
    const KeyPath path = joints.index(i);
    if (!jj.is_object()) throw InvalidInput(where + ": expected an object");
    checkKeys(jj, {"type", "a", "alpha", "d", "theta", "limits"}, where,
              "(a DH row has type, a, alpha, d, theta, limits)");
    DHRow<S> r;
    r.type = jointType(jj, where);
    for (const char* f : {"a", "alpha", "d", "theta"})
      if (!jj.contains(f)) throw InvalidInput(where + ": missing \"" + f + "\"");
    r.a = readNumber<S>(jj["a"], path.key("a"));
    r.alpha = readNumber<S>(jj["alpha"], path.key("alpha")) * du;
    r.d = readNumber<S>(jj["d"], path.key("d"));
    r.theta = readNumber<S>(jj["theta"], path.key("theta")) * du;
    S l = -std::numeric_limits<S>::infinity(), h = std::numeric_limits<S>::infinity();
    jointLimits<S>(jj, where, path, r.type == JointType::Revolute, out.degrees, l, h);
    lo.push_back(l);
    hi.push_back(h);
    rows.push_back(r);
  }
  const SE3<S> base = j.contains("base") ? poseFromJson<S>(j["base"], origin + ": base") : SE3<S>();
  const SE3<S> tool = j.contains("tool") ? poseFromJson<S>(j["tool"], origin + ": tool") : SE3<S>();
  out.robot = SerialRobot<S>::fromDH(rows, conv == "dh" ? DHConvention::Standard : DHConvention::Modified,
                                     base, tool, name)
                  .withLimits(lo, hi);
  return out;
}

template <class S> RobotFile<S> readRobot(const std::filesystem::path& file) {
  return parseRobot<S>(readTextFile(file, "robot"), file.string());
}

template <class S> std::vector<S> parseJointValues(const std::string& text, const RobotFile<S>& rf) {
  std::vector<S> vals;
  // Every comma separates two entries: "0,0," has an empty third entry (refused), not two values.
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    // The list's own syntax allows spaces around an entry ("0, 0.5"); the number reader does not.
    const std::size_t b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    item = b == std::string::npos ? std::string() : item.substr(b, e - b + 1);
    const std::string where = "--joints value " + std::to_string(vals.size() + 1);
    if (item.empty())
      throw InvalidInput(where + ": empty" +
                         std::string(comma == std::string::npos && !vals.empty() ? " (a trailing comma?)" : ""));
    vals.push_back(parseDecimal<S>(item, where));
    if (vals.size() > limits::maxJoints)
      throw InvalidInput("--joints: more than " + std::to_string(limits::maxJoints) + " values");
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (int(vals.size()) != rf.robot.dof())
    throw InvalidInput("--joints: " + std::to_string(vals.size()) + " values given, the robot has " +
                       std::to_string(rf.robot.dof()) + " joints");
  return vals;
}

template <class S> JointVector<S> parseJoints(const std::string& text, const RobotFile<S>& rf) {
  const std::vector<S> vals = parseJointValues<S>(text, rf);
  JointVector<S> q(vals.size());
  for (std::size_t i = 0; i < vals.size(); ++i) {
    q(i) = vals[i];
    if (rf.degrees && rf.robot.joints()[i].type == JointType::Revolute) q(i) *= pi<S>() / S(180);
  }
  return q;
}

#define SOMA_INSTANTIATE_ROBOT_FILE(S) namespace io {                                                 \
  template RobotFile<S> parseRobot<S>(const std::string&, const std::string&);         \
  template RobotFile<S> readRobot<S>(const std::filesystem::path&);                    \
  template std::vector<S> parseJointValues<S>(const std::string&, const RobotFile<S>&);  \
  template JointVector<S> parseJoints<S>(const std::string&, const RobotFile<S>&); }

}  // namespace soma::io
