#pragma once
// Definitions of scene_output.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/scene_output.hpp"

#include "soma/io/json_number.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/stewart_json.hpp"

#include <nlohmann/json.hpp>

namespace soma::io {

namespace {

template <class S> nlohmann::json outputHead(const SceneOutput& o, const std::string& method, double seconds,
                                             const S& residual, bool ok) {
  nlohmann::json j;
  j["output"] = o.name;
  j["kind"] = std::string(sceneOutputKindName(o.kind));
  j["method"] = method;
  j["scalar"] = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) j["bits"] = o.bits;
  j["seconds"] = seconds;
  j["residual"] = jsonNumber(residual);
  j["ok"] = ok;
  return j;
}

// Joint values in the robot file's unit (degrees when the file gives degrees), in S's digits.
template <class S> nlohmann::json jointsJson(const RobotFile<S>& rf, const JointVector<S>& q) {
  const S unit = rf.degrees ? S(180) / pi<S>() : S(1);
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < q.size(); ++i)
    a.push_back(jsonNumber(S(q(i) * (rf.robot.joints()[std::size_t(i)].type == JointType::Revolute ? unit : S(1)))));
  return a;
}

}  // namespace

template <class S>
std::string ikOutputJson(const SceneOutput& o, const RobotFile<S>& rf, const IkSolution<S>& sol, bool ok) {
  nlohmann::json j = outputHead<S>(o, sol.method, sol.seconds, sol.worstResidual(), ok);
  j["robot"] = o.robot;
  j["pose"] = o.pose;
  j["angles"] = rf.degrees ? "degrees" : "radians";
  j["expected_count"] = sol.expected_count;
  j["count"] = sol.count();
  j["certified"] = sol.certified;
  j["continuum"] = sol.continuum;
  j["notes"] = sol.notes;
  nlohmann::json arr = nlohmann::json::array();
  for (std::size_t k = 0; k < sol.count(); ++k)
    arr.push_back({{"joints", jointsJson(rf, sol.postures[k])}, {"residual", jsonNumber(sol.residuals[k])}});
  j["solutions"] = arr;
  return j.dump();
}

template <class S>
std::string fkOutputJson(const SceneOutput& o, const RobotFile<S>& rf, const JointVector<S>& q, const SE3<S>& pose,
                         double seconds) {
  nlohmann::json j = outputHead<S>(o, "product of exponentials", seconds, S(0), true);
  j["robot"] = o.robot;
  j["angles"] = rf.degrees ? "degrees" : "radians";
  j["joints"] = jointsJson(rf, q);
  j["pose"] = poseJson(pose);
  return j.dump();
}

template <class S>
std::string stewartOutputJson(const SceneOutput& o, const StewartPlatform<S>& P, const StewartSolution<S>& sol, bool ok) {
  S worst(0);
  for (const S& r : sol.residuals)
    if (r > worst) worst = r;
  nlohmann::json j = outputHead<S>(o, sol.method, sol.seconds, worst, ok);
  j["platform"] = o.platform;
  const bool homotopy = sol.method == "homotopy";
  if (homotopy) {
    j["tracker"] = sol.tracker;
    j["class"] = sol.platform_class;
    j["pattern"] = sol.pattern;
  }
  j["expected_count"] = sol.expected_count;
  j["complex_count"] = sol.complexCount();
  if (homotopy) j["distinct_complex_count"] = sol.distinctCount();
  j["certified"] = sol.certified;
  j["count"] = sol.count();
  j["notes"] = sol.notes;
  j["solutions"] = stewartPosturesJson(sol);
  if (o.complex) j["complex_solutions"] = stewartComplexSolutionsJson(P, sol);
  return j.dump();
}

template <class S>
std::string cylindroidOutputJson(const SceneOutput& o, const Cylindroid<S>& c, const S& residual, double seconds,
                                 bool ok) {
  nlohmann::json j = outputHead<S>(o, "principal form", seconds, residual, ok);
  j["screws"] = o.screws;
  j["pitches"] = nlohmann::json::array({jsonNumber(c.pitchMax()), jsonNumber(c.pitchMin())});
  j["principal_screws"] = {jsonNumbers(c.principal(1)), jsonNumbers(c.principal(2))};
  j["centre"] = jsonNumbers(c.centre());
  nlohmann::json f = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) f.push_back({jsonNumber(c.frame()(r, 0)), jsonNumber(c.frame()(r, 1)), jsonNumber(c.frame()(r, 2))});
  j["frame"] = f;
  return j.dump();
}

template <class S>
std::string screwSystemOutputJson(const SceneOutput& o, const ScrewSystemIdentification<S>& id, double seconds, bool ok) {
  nlohmann::json j = outputHead<S>(o, "geometric reduction (GF §8.2.7, §8.3.6)", seconds, id.frameResidual, ok);
  j["screws"] = o.screws;
  j["type"] = id.name();
  j["type_name"] = screwSystemTypeName(id.type);
  j["dimension"] = id.dimension;
  j["via_reciprocal"] = id.viaReciprocal;
  nlohmann::json p = nlohmann::json::array();
  for (int i = 0; i < id.parameterCount; ++i) p.push_back(jsonNumber(id.parameters[std::size_t(i)]));
  j["parameters"] = p;
  j["frame"] = poseJson(id.frame);
  j["nearest_other_type"] = screwSystemTypeName(id.nearestOtherType);
  j["boundary_distance"] = jsonNumber(id.boundaryDistance);
  return j.dump();
}

#define SOMA_INSTANTIATE_SCENE_OUTPUT(S) namespace io {                                                   \
  template std::string ikOutputJson<S>(const SceneOutput&, const RobotFile<S>&, const IkSolution<S>&, bool); \
  template std::string fkOutputJson<S>(const SceneOutput&, const RobotFile<S>&, const JointVector<S>&,     \
                                       const SE3<S>&, double);                                          \
  template std::string stewartOutputJson<S>(const SceneOutput&, const StewartPlatform<S>&, const StewartSolution<S>&, bool);          \
  template std::string cylindroidOutputJson<S>(const SceneOutput&, const Cylindroid<S>&, const S&, double, bool); \
  template std::string screwSystemOutputJson<S>(const SceneOutput&, const ScrewSystemIdentification<S>&, double, bool); }

}  // namespace soma::io
