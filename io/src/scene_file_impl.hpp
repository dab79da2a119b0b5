#pragma once
// Definitions of scene_file.hpp's templates (an entity's numbers in a scalar), instantiated for the
// five scalars by soma_instantiate (io/CMakeLists.txt). The robot, pose and platform bodies go to
// the robot, pose and platform readers: a scene has no second parser of them.
#include "soma/io/scene_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/urdf_file.hpp"
#include "soma/geometry/lines/screw_axis.hpp"

namespace soma::io {

namespace {

template <class S, int N> Eigen::Matrix<S, N, 1> sceneVector(const nlohmann::json& j, const KeyPath& where) {
  if (!j.is_array() || j.size() != std::size_t(N))
    throw InvalidInput(where.str() + ": expected an array of " + std::to_string(N) + " numbers");
  Eigen::Matrix<S, N, 1> v;
  for (int i = 0; i < N; ++i) v(i) = readNumber<S>(j[std::size_t(i)], where.index(std::size_t(i)));
  return v;
}

nlohmann::json sceneBody(const SceneEntity& e) { return nlohmann::json::parse(e.body); }

// A geometry constructor's InvalidInput ("PluckerLine::pointDirection: direction d is zero") with
// the entity's key path in front.
template <class F> auto atEntity(const SceneEntity& e, F&& f) {
  try {
    return f();
  } catch (const InvalidInput& x) {
    const std::string m = x.what();
    if (m.rfind(e.where, 0) == 0) throw;
    throw InvalidInput(e.where + ": " + m);
  }
}

void requireKeys(const nlohmann::json& j, std::initializer_list<const char*> keys, const std::string& where) {
  for (const char* k : keys)
    if (!j.contains(k)) throw InvalidInput(where + ": missing \"" + std::string(k) + "\"");
}

}  // namespace

template <class S> RobotFile<S> sceneRobot(const SceneEntity& e) {
  if (e.file) return readAnyRobot<S>(*e.file, e.tip);
  return parseRobot<S>(e.body, e.where);
}

template <class S> SE3<S> scenePose(const SceneEntity& e) {
  if (e.file) return readPose<S>(*e.file);
  return poseFromJson<S>(sceneBody(e), e.where);
}

template <class S> StewartPlatform<S> scenePlatform(const SceneEntity& e) {
  if (e.file) return readPlatform<S>(*e.file);
  return parsePlatform<S>(e.body, e.where);
}

template <class S> Vec3<S> scenePoint(const SceneEntity& e) {
  const nlohmann::json j = sceneBody(e);
  requireKeys(j, {"at"}, e.where);
  return sceneVector<S, 3>(j["at"], KeyPath(e.origin).key(e.path).key("at"));
}

template <class S> PluckerLine<S> sceneLine(const SceneEntity& e) {
  const nlohmann::json j = sceneBody(e);
  const KeyPath w = KeyPath(e.origin).key(e.path);
  if (j.contains("through")) {
    if (j.contains("point") || j.contains("direction"))
      throw InvalidInput(e.where + ": give \"through\" or \"point\" and \"direction\", not both");
    const nlohmann::json& t = j["through"];
    if (!t.is_array() || t.size() != 2) throw InvalidInput(w.key("through").str() + ": expected two points [x, y, z]");
    const Vec3<S> a = sceneVector<S, 3>(t[0], w.key("through").index(0));
    const Vec3<S> b = sceneVector<S, 3>(t[1], w.key("through").index(1));
    return atEntity(e, [&] { return PluckerLine<S>::throughPoints(a, b); });
  }
  requireKeys(j, {"point", "direction"}, e.where);
  const Vec3<S> q = sceneVector<S, 3>(j["point"], w.key("point"));
  const Vec3<S> d = sceneVector<S, 3>(j["direction"], w.key("direction"));
  return atEntity(e, [&] { return PluckerLine<S>::pointDirection(q, d); });
}

template <class S> Vec6<S> sceneScrew(const SceneEntity& e) {
  const nlohmann::json j = sceneBody(e);
  const KeyPath w = KeyPath(e.origin).key(e.path);
  if (j.contains("coordinates")) {
    if (j.contains("point") || j.contains("direction") || j.contains("pitch"))
      throw InvalidInput(e.where + ": give \"coordinates\" or \"point\", \"direction\" and \"pitch\", not both");
    const Vec6<S> s = sceneVector<S, 6>(j["coordinates"], w.key("coordinates"));
    if (s.squaredNorm() == S(0)) throw InvalidInput(w.key("coordinates").str() + ": the zero screw");
    return s;
  }
  requireKeys(j, {"point", "direction", "pitch"}, e.where);
  const Vec3<S> q = sceneVector<S, 3>(j["point"], w.key("point"));
  const Vec3<S> d = sceneVector<S, 3>(j["direction"], w.key("direction"));
  const S h = readNumber<S>(j["pitch"], w.key("pitch"));
  // GF §6.4: the screw (u; q × u + h u) of unit amplitude about the axis through q along u.
  return atEntity(e, [&] { return screwFromAxis(PluckerLine<S>::pointDirection(q, d), h); });
}

template <class S> JointVector<S> sceneJoints(const SceneOutput& o, const RobotFile<S>& rf) {
  const nlohmann::json j = nlohmann::json::parse(o.joints);
  const KeyPath w = KeyPath(o.origin).key(o.path).key("joints");
  if (int(j.size()) != rf.robot.dof())
    throw InvalidInput(w.str() + ": " + std::to_string(j.size()) + " values given, the robot has " +
                       std::to_string(rf.robot.dof()) + " joints");
  JointVector<S> q(rf.robot.dof());
  for (int i = 0; i < rf.robot.dof(); ++i) {
    q(i) = readNumber<S>(j[std::size_t(i)], w.index(std::size_t(i)));
    if (rf.degrees && rf.robot.joints()[std::size_t(i)].type == JointType::Revolute) q(i) *= pi<S>() / S(180);
  }
  return q;
}

#define SOMA_INSTANTIATE_SCENE_FILE(S) namespace io {                                  \
  template RobotFile<S> sceneRobot<S>(const SceneEntity&);                              \
  template SE3<S> scenePose<S>(const SceneEntity&);                                     \
  template StewartPlatform<S> scenePlatform<S>(const SceneEntity&);                     \
  template Vec3<S> scenePoint<S>(const SceneEntity&);                                   \
  template PluckerLine<S> sceneLine<S>(const SceneEntity&);                             \
  template Vec6<S> sceneScrew<S>(const SceneEntity&);                                   \
  template JointVector<S> sceneJoints<S>(const SceneOutput&, const RobotFile<S>&); }

}  // namespace soma::io
