// `soma stewart PLATFORM.json [--method M] [--scalar T] [--json]` (DESIGN §6): every real posture
// of a Stewart–Gough platform for its six leg lengths (forward kinematics), with the expected
// count (40), the complex count found, each posture's residual and the time.
#include "command.hpp"
#include "json_output.hpp"
#include "posture_figure.hpp"
#include "scalar_options.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/io/pose_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

namespace soma::cli {

namespace {


using json = nlohmann::json;

json pointsJson(const auto& pts) {
  json a = json::array();
  for (const auto& p : pts) a.push_back(io::jsonNumbers(p));
  return a;
}


template <class S>
int stewartImpl(const std::filesystem::path& file, StewartMethod method, bool json_, std::ostream& out, const FigureFiles& fig) {
  const StewartPlatform<S> P = io::readPlatform<S>(file);
  StewartOptions options;
  options.method = method;
  const StewartSolution<S> sol = solveStewart<S>(P, options);
  const bool numeric = method != StewartMethod::Homotopy;
  bool ok = numeric || sol.complexCount() == sol.expected_count;
  for (const auto& r : sol.residuals)
    if (!(r <= Tolerance<S>::sqrtEpsilon())) ok = false;
  writePlatformFigures<S>(P, sol.postures, fmt::format("{}: {} real posture(s)", file.filename().string(), sol.count()), fig);
  if (json_) {
    json j;
    j["platform_file"] = file.string();
    j["base"] = pointsJson(P.base);
    j["platform"] = pointsJson(P.platform);
    json L = json::array();
    for (const auto& l : P.legs) L.push_back(io::jsonNumber(l));
    j["leg_lengths"] = L;
    j["method"] = sol.method;
    io::addScalar<S>(j);
    j["seconds"] = sol.seconds;
    j["expected_count"] = sol.expected_count;
    if (!numeric) j["complex_count"] = sol.complexCount();
    j["certified"] = sol.certified;
    j["count"] = sol.count();
    j["paths_tracked"] = sol.paths_tracked;
    j["notes"] = sol.notes;
    json arr = json::array();
    for (std::size_t k = 0; k < sol.count(); ++k) {
      json posture = io::poseJson(sol.postures[k]);
      posture["residual"] = io::jsonNumber(sol.residuals[k]);
      arr.push_back(std::move(posture));
    }
    j["solutions"] = arr;
    out << jsonText(j) << "\n";
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
    out << fmt::format("  {:>2}: t = ({}, {}, {})  rotation vector = ({}, {}, {})  residual {}\n", k + 1,
                       io::numberText(t(0)), io::numberText(t(1)), io::numberText(t(2)), io::numberText(w(0)),
                       io::numberText(w(1)), io::numberText(w(2)), toString(sol.residuals[k], 3));
  }
  for (const auto& n : sol.notes) out << "note: " << n << "\n";
  return ok ? 0 : 1;
}


int stewartCommand(const std::filesystem::path& platform, const std::string& method, ScalarKind scalar, bool json,
                   std::ostream& out, const FigureFiles& fig) {
  const auto m = parseStewartMethod(method);
  if (!m) throw InvalidInput("--method: \"" + method + "\" is not one of " + stewartMethodNames());
  return withScalar(scalar, [&]<class S>() { return stewartImpl<S>(platform, *m, json, out, fig); });
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
    spec.add("--png", fig_.png, "write the figure (PNG): the platform at each real posture, a panel each");
    spec.add("--svg", fig_.svg, "write the figure as SVG (a line drawing of the same panels)");
  }
  int run(const Spec&, const Invocation&) override {
    return stewartCommand(file_, method_, scalar_.apply(), json_, std::cout, fig_);
  }

 private:
  std::string file_, method_ = "homotopy";
  ScalarOptions scalar_;
  FigureFiles fig_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(StewartCommand, 90);

}  // namespace soma::cli
