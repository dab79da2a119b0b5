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

namespace {
template <class S> JointVector<S> jointValues(const SceneOutput& o, const std::string& text, const char* key,
                                              const RobotFile<S>& rf) {
  const nlohmann::json j = nlohmann::json::parse(text);
  const KeyPath w = KeyPath(o.origin).key(o.path).key(key);
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
}  // namespace

template <class S> JointVector<S> sceneJoints(const SceneOutput& o, const RobotFile<S>& rf) {
  return jointValues<S>(o, o.joints, "joints", rf);
}

template <class S>
std::pair<JointVector<S>, JointVector<S>> sceneTrajectoryEnds(const SceneOutput& o, const RobotFile<S>& rf) {
  return {jointValues<S>(o, o.from, "from", rf), jointValues<S>(o, o.to, "to", rf)};
}

template <class S> LinearComplex<S> sceneLinearComplex(const SceneEntity& e) {
  // The same body as a screw's: the complex of the lines reciprocal to it (GF §6.6).
  return atEntity(e, [&] { return LinearComplex<S>(sceneScrew<S>(e)); });
}

namespace {
const SceneEntity& usedEntity(const SceneFile& scene, const SceneEntity& e, std::size_t i) {
  const SceneEntity* u = scene.entity(e.uses.at(i));
  if (!u) throw InvalidInput(e.where + ": no entity named \"" + e.uses.at(i) + "\"");
  return *u;
}
}  // namespace

template <class S> ThreeLineRegulus<S> sceneRegulus(const SceneFile& scene, const SceneEntity& e) {
  const PluckerLine<S> a = sceneLine<S>(usedEntity(scene, e, 0)), b = sceneLine<S>(usedEntity(scene, e, 1)),
                       c = sceneLine<S>(usedEntity(scene, e, 2));
  return atEntity(e, [&] { return ThreeLineRegulus<S>(a, b, c); });
}

template <class S> Cylindroid<S> sceneCylindroid(const SceneFile& scene, const SceneEntity& e) {
  const Vec6<S> a = sceneScrew<S>(usedEntity(scene, e, 0)), b = sceneScrew<S>(usedEntity(scene, e, 1));
  return atEntity(e, [&] { return Cylindroid<S>(a, b); });
}

template <class S> SceneRuledSurface<S> sceneRuledSurface(const SceneFile& scene, const SceneEntity& e) {
  const PluckerLine<S> l = sceneLine<S>(usedEntity(scene, e, 0));
  const Vec6<S> xi = sceneScrew<S>(usedEntity(scene, e, 1));
  const nlohmann::json j = sceneBody(e);
  const KeyPath w = KeyPath(e.origin).key(e.path);
  S t0(0), t1 = S(2) * pi<S>();
  if (j.contains("range")) {
    t0 = readNumber<S>(j["range"][0], w.key("range").index(0));
    t1 = readNumber<S>(j["range"][1], w.key("range").index(1));
    if (!(t1 > t0)) throw InvalidInput(w.key("range").str() + ": expected t0 < t1");
  }
  // GF §9.4: the line l swept by the one-parameter motion exp(t ξ).
  return atEntity(e, [&] { return SceneRuledSurface<S>{RuledSurface<S>::sweep(xi, l), t0, t1}; });
}

template <class S> Eigen::Matrix<S, 6, Eigen::Dynamic> sceneScrewSystem(const SceneFile& scene, const SceneEntity& e) {
  Eigen::Matrix<S, 6, Eigen::Dynamic> g(6, Eigen::Index(e.uses.size()));
  for (std::size_t i = 0; i < e.uses.size(); ++i) g.col(Eigen::Index(i)) = sceneScrew<S>(usedEntity(scene, e, i));
  return g;
}

template <class S> SpatialInertia<S> sceneRigidBody(const SceneEntity& e) {
  const nlohmann::json j = sceneBody(e);
  const KeyPath w = KeyPath(e.origin).key(e.path);
  requireKeys(j, {"mass", "com", "inertia"}, e.where);
  const S m = readNumber<S>(j["mass"], w.key("mass"));
  if (!(m > S(0))) throw InvalidInput(w.key("mass").str() + ": the mass must be positive");
  const Vec3<S> c = sceneVector<S, 3>(j["com"], w.key("com"));
  const Vec6<S> I = sceneVector<S, 6>(j["inertia"], w.key("inertia"));
  Mat3<S> Ic;  // [Ixx, Iyy, Izz, Ixy, Iyz, Ixz], as a robot file's "links" (link_inertia_file.hpp)
  Ic << I(0), I(3), I(5), I(3), I(1), I(4), I(5), I(4), I(2);
  return atEntity(e, [&] { return SpatialInertia<S>(m, c, Ic); });
}

#define SOMA_INSTANTIATE_SCENE_FILE(S) namespace io {                                  \
  template RobotFile<S> sceneRobot<S>(const SceneEntity&);                              \
  template SE3<S> scenePose<S>(const SceneEntity&);                                     \
  template StewartPlatform<S> scenePlatform<S>(const SceneEntity&);                     \
  template Vec3<S> scenePoint<S>(const SceneEntity&);                                   \
  template PluckerLine<S> sceneLine<S>(const SceneEntity&);                             \
  template Vec6<S> sceneScrew<S>(const SceneEntity&);                                   \
  template JointVector<S> sceneJoints<S>(const SceneOutput&, const RobotFile<S>&);                      \
  template LinearComplex<S> sceneLinearComplex<S>(const SceneEntity&);                                  \
  template ThreeLineRegulus<S> sceneRegulus<S>(const SceneFile&, const SceneEntity&);                   \
  template Cylindroid<S> sceneCylindroid<S>(const SceneFile&, const SceneEntity&);                      \
  template SceneRuledSurface<S> sceneRuledSurface<S>(const SceneFile&, const SceneEntity&);             \
  template Eigen::Matrix<S, 6, Eigen::Dynamic> sceneScrewSystem<S>(const SceneFile&, const SceneEntity&); \
  template SpatialInertia<S> sceneRigidBody<S>(const SceneEntity&);                                     \
  template std::pair<JointVector<S>, JointVector<S>> sceneTrajectoryEnds<S>(const SceneOutput&, const RobotFile<S>&); }

}  // namespace soma::io
