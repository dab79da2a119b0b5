// `soma stewart PLATFORM.json [--method M] [--scalar T] [--json]` (DESIGN §6): every real posture
// of a Stewart–Gough platform for its six leg lengths (forward kinematics), with the expected
// count (40), the complex count found, each posture's residual and the time.
#include "command.hpp"
#include "scalar_options.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <iostream>

namespace soma::cli {

namespace {


using json = nlohmann::json;

template <class S> S number(const json& j, const std::string& where) {
  if (j.is_number()) return scalarCast<S>(j.get<double>());
  if (j.is_string()) {
    const std::string t = j.get<std::string>();
    std::size_t used = 0;
    try {
      (void)std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != t.size()) throw InvalidInput(where + ": \"" + t + "\" is not a number");
    return fromString<S>(t);
  }
  throw InvalidInput(where + ": expected a number, got " + std::string(j.type_name()));
}

template <class S> std::array<Vec3<S>, 6> points(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 6)
    throw InvalidInput(where + ": expected an array of 6 points [x, y, z]" +
                       (j.is_array() ? " (got " + std::to_string(j.size()) + ")" : std::string()));
  std::array<Vec3<S>, 6> p;
  for (int i = 0; i < 6; ++i) {
    const std::string w = where + "[" + std::to_string(i) + "]";
    if (!j[i].is_array() || j[i].size() != 3) throw InvalidInput(w + ": expected a point [x, y, z]");
    for (int k = 0; k < 3; ++k) p[i](k) = number<S>(j[i][k], w + "[" + std::to_string(k) + "]");
  }
  return p;
}

json pointsJson(const auto& pts) {
  json a = json::array();
  for (const auto& p : pts) a.push_back({toDouble(p(0)), toDouble(p(1)), toDouble(p(2))});
  return a;
}

/// Reads a platform file {"base": [6 points], "platform": [6 points], "leg_lengths": [6]};
/// throws InvalidInput naming the file, the field and the defect.
template <class S> StewartPlatform<S> readPlatform(const std::filesystem::path& file);

template <class S>
int stewartImpl(const std::filesystem::path& file, StewartMethod method, bool json_, std::ostream& out) {
  const StewartPlatform<S> P = readPlatform<S>(file);
  StewartOptions options;
  options.method = method;
  const StewartSolution<S> sol = solveStewart<S>(P, options);
  const bool numeric = method != StewartMethod::Homotopy;
  bool ok = numeric || sol.complexCount() == sol.expected_count;
  for (const auto& r : sol.residuals)
    if (!(r <= Tolerance<S>::sqrtEpsilon())) ok = false;
  if (json_) {
    json j;
    j["platform_file"] = file.string();
    j["base"] = pointsJson(P.base);
    j["platform"] = pointsJson(P.platform);
    json L = json::array();
    for (const auto& l : P.legs) L.push_back(toDouble(l));
    j["leg_lengths"] = L;
    j["method"] = sol.method;
    j["scalar"] = std::string(scalarName<S>());
    j["seconds"] = sol.seconds;
    j["expected_count"] = sol.expected_count;
    if (!numeric) j["complex_count"] = sol.complexCount();
    j["certified"] = sol.certified;
    j["count"] = sol.count();
    j["paths_tracked"] = sol.paths_tracked;
    j["notes"] = sol.notes;
    json arr = json::array();
    for (std::size_t k = 0; k < sol.count(); ++k) {
      const Mat3<S> R = sol.postures[k].rotation();
      const Vec3<S> t = sol.postures[k].translation();
      json rot = json::array();
      for (int r = 0; r < 3; ++r) rot.push_back({toDouble(R(r, 0)), toDouble(R(r, 1)), toDouble(R(r, 2))});
      arr.push_back({{"rotation", rot},
                     {"translation", {toDouble(t(0)), toDouble(t(1)), toDouble(t(2))}},
                     {"residual", toDouble(sol.residuals[k])}});
    }
    j["solutions"] = arr;
    out << j.dump(2) << "\n";
    return ok ? 0 : 1;
  }
  out << fmt::format("platform: {}   method: {}   scalar: {}\n", file.string(), sol.method, scalarName<S>());
  if (numeric)
    out << fmt::format("real postures: {} (multi-start in double, {} starts: completeness not certified)   "
                       "time: {:.3g} s\n",
                       sol.count(), sol.paths_tracked, sol.seconds);
  else
    out << fmt::format("complex solutions: {} found, {} expected ({} platform)   real postures: {}   "
                       "time: {:.3g} s\n",
                       sol.complexCount(), sol.expected_count, sol.expected_count == 16 ? "6-3" : "general 6-6",
                       sol.count(), sol.seconds);
  for (std::size_t k = 0; k < sol.count(); ++k) {
    const SE3<S>& g = sol.postures[k];
    const Vec3<S> t = g.translation();
    const Vec3<S> w = g.so3().log().coeffs();  // rotation vector
    out << fmt::format("  {:>2}: t = ({:>11.6f}, {:>11.6f}, {:>11.6f})  rotation vector = ({:>9.6f}, {:>9.6f}, "
                       "{:>9.6f})  residual {}\n",
                       k + 1, toDouble(t(0)), toDouble(t(1)), toDouble(t(2)), toDouble(w(0)), toDouble(w(1)),
                       toDouble(w(2)), toString(sol.residuals[k], 3));
  }
  for (const auto& n : sol.notes) out << "note: " << n << "\n";
  return ok ? 0 : 1;
}


template <class S> StewartPlatform<S> readPlatform(const std::filesystem::path& file) {
  const std::string origin = file.string();
  std::ifstream in(file);
  if (!in) throw InvalidInput(origin + ": cannot open the platform file");
  std::stringstream ss;
  ss << in.rdbuf();
  json j;
  try {
    j = json::parse(ss.str());
  } catch (const std::exception& e) {
    throw InvalidInput(origin + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw InvalidInput(origin + ": a platform must be a JSON object");
  for (const auto& [key, v] : j.items()) {
    (void)v;
    if (key != "base" && key != "platform" && key != "leg_lengths" && key != "name" && key != "comment")
      throw InvalidInput(origin + ": unknown field \"" + key + "\" (expected base, platform, leg_lengths)");
  }
  for (const char* f : {"base", "platform", "leg_lengths"})
    if (!j.contains(f)) throw InvalidInput(origin + ": missing \"" + std::string(f) + "\"");
  StewartPlatform<S> P;
  try {
    P.base = points<S>(j["base"], "base");
    P.platform = points<S>(j["platform"], "platform");
    const json& L = j["leg_lengths"];
    if (!L.is_array() || L.size() != 6) throw InvalidInput("leg_lengths: expected an array of 6 numbers");
    for (int i = 0; i < 6; ++i) P.legs[i] = number<S>(L[i], "leg_lengths[" + std::to_string(i) + "]");
    validateStewartPlatform<S>(P);
  } catch (const InvalidInput& e) {
    throw InvalidInput(origin + ": " + e.what());
  }
  return P;
}

int stewartCommand(const std::filesystem::path& platform, const std::string& method, ScalarKind scalar, bool json,
                   std::ostream& out) {
  const auto m = parseStewartMethod(method);
  if (!m) throw InvalidInput("--method: \"" + method + "\" is not one of " + stewartMethodNames());
  return withScalar(scalar, [&]<class S>() { return stewartImpl<S>(platform, *m, json, out); });
}


class StewartCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "stewart";
    spec.help = "forward kinematics of a Stewart-Gough platform: all 40 complex solutions, the real postures";
    spec.add("platform", file_, "platform JSON: {\"base\": [6 points], \"platform\": [6 points], "
                                "\"leg_lengths\": [6]}")
        .mustBeGiven();
    spec.add("--method", method_, "homotopy (all 40 complex solutions, certified count), ceres or nlopt (multi-start, real postures only)")
        .withDefault();
    scalar_.declare(spec);
    spec.flag("--json", json_, "print one JSON object");
  }
  int run(const Spec&, const Invocation&) override {
    return stewartCommand(file_, method_, scalar_.apply(), json_, std::cout);
  }

 private:
  std::string file_, method_ = "homotopy";
  ScalarOptions scalar_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(StewartCommand, 90);

}  // namespace soma::cli
