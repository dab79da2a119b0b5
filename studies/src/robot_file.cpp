#include "soma/studies/robot_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/studies/pose_file.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace soma::studies {

namespace {
using json = nlohmann::json;

template <class S> S number(const json& j, const std::string& where) {
  if (j.is_number()) return scalarCast<S>(j.get<double>());
  if (j.is_string()) {
    const std::string t = j.get<std::string>();
    try {
      std::size_t used = 0;
      (void)std::stod(t, &used);
      if (used != t.size()) throw std::invalid_argument(t);
    } catch (const std::exception&) {
      throw InvalidInput(where + ": \"" + t + "\" is not a number");
    }
    return fromString<S>(t);
  }
  throw InvalidInput(where + ": expected a number, got " + std::string(j.type_name()));
}

template <class S> Vec3<S> vec3(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3) throw InvalidInput(where + ": expected an array of 3 numbers");
  Vec3<S> v;
  for (int i = 0; i < 3; ++i) v(i) = number<S>(j[i], where + "[" + std::to_string(i) + "]");
  if (!allFinite(v)) throw InvalidInput(where + ": has a NaN or infinite entry");
  return v;
}

template <class S> S angleUnit(bool degrees) { return degrees ? S(pi<S>() / S(180)) : S(1); }

template <class S> SE3<S> subPose(const json& j, const std::string& origin, const std::string& key) {
  return parsePose<S>(j.dump(), origin + ": " + key);
}

template <class S>
void limits(const json& jj, const std::string& where, bool angular, bool degrees, S& lo, S& hi) {
  if (!jj.contains("limits")) return;
  const json& l = jj["limits"];
  if (!l.is_array() || l.size() != 2) throw InvalidInput(where + " limits: expected [lower, upper]");
  const S u = angular ? angleUnit<S>(degrees) : S(1);
  lo = number<S>(l[0], where + " limits[0]") * u;
  hi = number<S>(l[1], where + " limits[1]") * u;
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
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InvalidInput(origin + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw InvalidInput(origin + ": a robot must be a JSON object");
  for (const auto& [key, value] : j.items())
    if (key != "name" && key != "angles" && key != "convention" && key != "joints" && key != "base" &&
        key != "tool" && key != "home" && key != "description" &&
        key != "links")  // "links": inertial data, read by soma::readLinkInertias (GF ch. 13)
      throw InvalidInput(origin + ": unknown field \"" + key + "\"");
  RobotFile<S> out;
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
  const S du = angleUnit<S>(out.degrees);
  std::vector<S> lo, hi;
  if (conv == "poe") {
    if (!j.contains("home")) throw InvalidInput(origin + ": a poe robot needs the tool's \"home\" pose");
    std::vector<SerialJoint<S>> js;
    for (std::size_t i = 0; i < j["joints"].size(); ++i) {
      const json& jj = j["joints"][i];
      const std::string where = origin + ": joint " + std::to_string(i + 1);
      if (!jj.is_object()) throw InvalidInput(where + ": expected an object");
      SerialJoint<S> sj;
      sj.type = jointType(jj, where);
      if (!jj.contains("axis")) throw InvalidInput(where + ": missing \"axis\"");
      sj.axis = vec3<S>(jj["axis"], where + " axis");
      if (sj.type == JointType::Revolute) {
        if (!jj.contains("point")) throw InvalidInput(where + ": missing \"point\" (a point of the axis)");
        sj.point = vec3<S>(jj["point"], where + " point");
      }
      const bool ang = sj.type == JointType::Revolute;
      if (jj.contains("offset")) sj.offset = number<S>(jj["offset"], where + " offset") * (ang ? du : S(1));
      limits<S>(jj, where, ang, out.degrees, sj.lower, sj.upper);
      js.push_back(sj);
    }
    out.robot = SerialRobot<S>::fromPOE(js, subPose<S>(j["home"], origin, "home"), name);
    return out;
  }
  std::vector<DHRow<S>> rows;
  for (std::size_t i = 0; i < j["joints"].size(); ++i) {
    const json& jj = j["joints"][i];
    const std::string where = origin + ": joint " + std::to_string(i + 1);
    if (!jj.is_object()) throw InvalidInput(where + ": expected an object");
    for (const auto& [key, value] : jj.items())
      if (key != "type" && key != "a" && key != "alpha" && key != "d" && key != "theta" && key != "limits")
        throw InvalidInput(where + ": unknown field \"" + key + "\" (a DH row has type, a, alpha, d, theta, limits)");
    DHRow<S> r;
    r.type = jointType(jj, where);
    for (const char* f : {"a", "alpha", "d", "theta"})
      if (!jj.contains(f)) throw InvalidInput(where + ": missing \"" + f + "\"");
    r.a = number<S>(jj["a"], where + " a");
    r.alpha = number<S>(jj["alpha"], where + " alpha") * du;
    r.d = number<S>(jj["d"], where + " d");
    r.theta = number<S>(jj["theta"], where + " theta") * du;
    S l = -std::numeric_limits<S>::infinity(), h = std::numeric_limits<S>::infinity();
    limits<S>(jj, where, r.type == JointType::Revolute, out.degrees, l, h);
    lo.push_back(l);
    hi.push_back(h);
    rows.push_back(r);
  }
  const SE3<S> base = j.contains("base") ? subPose<S>(j["base"], origin, "base") : SE3<S>();
  const SE3<S> tool = j.contains("tool") ? subPose<S>(j["tool"], origin, "tool") : SE3<S>();
  out.robot = SerialRobot<S>::fromDH(rows, conv == "dh" ? DHConvention::Standard : DHConvention::Modified,
                                     base, tool, name)
                  .withLimits(lo, hi);
  return out;
}

template <class S> RobotFile<S> readRobot(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InvalidInput(file.string() + ": cannot open the robot file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parseRobot<S>(ss.str(), file.string());
}

template <class S> JointVector<S> parseJoints(const std::string& text, const RobotFile<S>& rf) {
  std::vector<S> vals;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const std::string where = "--joints value " + std::to_string(vals.size() + 1);
    try {
      std::size_t used = 0;
      (void)std::stod(item, &used);
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InvalidInput(where + ": \"" + item + "\" is not a number");
    }
    vals.push_back(fromString<S>(item));
  }
  if (int(vals.size()) != rf.robot.dof())
    throw InvalidInput("--joints: " + std::to_string(vals.size()) + " values given, the robot has " +
                       std::to_string(rf.robot.dof()) + " joints");
  JointVector<S> q(vals.size());
  for (std::size_t i = 0; i < vals.size(); ++i) {
    q(i) = vals[i];
    if (!isFinite(q(i))) throw InvalidInput("--joints value " + std::to_string(i + 1) + " is not finite");
    if (rf.degrees && rf.robot.joints()[i].type == JointType::Revolute) q(i) *= pi<S>() / S(180);
  }
  return q;
}

#define SOMA_ROBOT_FILE_INSTANTIATE(S)                                                 \
  template RobotFile<S> parseRobot<S>(const std::string&, const std::string&);         \
  template RobotFile<S> readRobot<S>(const std::filesystem::path&);                    \
  template JointVector<S> parseJoints<S>(const std::string&, const RobotFile<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_ROBOT_FILE_INSTANTIATE)
#undef SOMA_ROBOT_FILE_INSTANTIATE

}  // namespace soma::studies
