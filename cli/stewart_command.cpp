// `soma stewart PLATFORM.json [--method M] [--scalar T] [--json] [--complex]` (DESIGN §6): every
// real posture of a Stewart–Gough platform for its six leg lengths (forward kinematics), with the
// platform's class and its expected count (stewart_class.hpp), the complex count found, each
// posture's residual and multiplicity, the time; with --complex every complex solution too.
#include "command.hpp"
#include "json_output.hpp"
#include "posture_figure.hpp"
#include "scalar_options.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/io/stewart_json.hpp"
#include "soma/io/pose_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <complex>
#include <iostream>

namespace soma::cli {

namespace {


using json = nlohmann::json;

json pointsJson(const auto& pts) {
  json a = json::array();
  for (const auto& p : pts) a.push_back(io::jsonNumbers(p));
  return a;
}


template <class S> std::string complexText(const std::complex<S>& z) {
  return fmt::format("{}{}{}i", io::numberText(z.real()), z.imag() < S(0) ? "-" : "+", io::numberText(z.imag() < S(0) ? -z.imag() : z.imag()));
}

template <class S>
int stewartImpl(const std::filesystem::path& file, StewartMethod method, bool json_, bool complex_, std::ostream& out,
                const FigureFiles& fig) {
  const StewartPlatform<S> P = io::readPlatform<S>(file);
  StewartOptions options;
  options.method = method;
  const StewartSolution<S> sol = solveStewart<S>(P, options);
  const bool numeric = method != StewartMethod::Homotopy;
  if (numeric && complex_) throw InvalidInput("--complex: only the homotopy finds the complex solutions (--method homotopy)");
  // Exit 1 when short of (or beyond) the class's count; a class with no tabulated count is not certified but not short.
  bool ok = numeric || sol.expected_count == 0 || sol.complexCount() == sol.expected_count;
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
    if (!numeric) {
      j["class"] = sol.platform_class;
      j["pattern"] = sol.pattern;
    }
    j["expected_count"] = sol.expected_count;
    if (!numeric) {
      j["complex_count"] = sol.complexCount();
      j["distinct_complex_count"] = sol.distinctCount();
      j["paths_escalated"] = sol.paths_escalated;
      j["tracker"] = sol.tracker;
    }
    j["certified"] = sol.certified;
    j["count"] = sol.count();
    j["paths_tracked"] = sol.paths_tracked;
    j["notes"] = sol.notes;
    j["solutions"] = io::stewartPosturesJson(sol);
    if (complex_) j["complex_solutions"] = io::stewartComplexSolutionsJson(P, sol);
    out << jsonText(j) << "\n";
    return ok ? 0 : 1;
  }
  out << fmt::format("platform: {}   method: {}   scalar: {}\n", file.string(), sol.method, scalarName<S>());
  if (numeric)
    out << fmt::format("real postures: {} (multi-start in double, {} starts: completeness not certified)   "
                       "time: {:.3g} s\n",
                       sol.count(), sol.paths_tracked, sol.seconds);
  else
    out << fmt::format("complex solutions: {} found, {} expected ({} platform{})   real postures: {}   "
                       "time: {:.3g} s\n",
                       sol.complexCount(), sol.expected_count == 0 ? std::string("none") : std::to_string(sol.expected_count),
                       sol.platform_class, sol.certified ? ", certified" : ", not certified", sol.count(), sol.seconds);
  for (std::size_t k = 0; k < sol.count(); ++k) {
    const SE3<S>& g = sol.postures[k];
    const Vec3<S> t = g.translation();
    const Vec3<S> w = g.so3().log().coeffs();  // rotation vector
    const int m = k < sol.posture_multiplicity.size() ? sol.posture_multiplicity[k] : 1;
    out << fmt::format("  {:>2}: t = ({}, {}, {})  rotation vector = ({}, {}, {})  residual {}{}\n", k + 1,
                       io::numberText(t(0)), io::numberText(t(1)), io::numberText(t(2)), io::numberText(w(0)),
                       io::numberText(w(1)), io::numberText(w(2)), toString(sol.residuals[k], 3),
                       m > 1 ? fmt::format("  multiplicity {}", m) : std::string());
  }
  if (complex_) {
    out << fmt::format("complex solutions ({} distinct): translation t, rotation quaternion a (a·a = 1)\n", sol.distinctCount());
    for (std::size_t k = 0; k < sol.complex_postures.size(); ++k) {
      const auto& c = sol.complex_postures[k];
      out << fmt::format("  {:>2}: t = ({}, {}, {})  a = ({}, {}, {}, {}){}{}\n", k + 1, complexText(c.translation[0]),
                         complexText(c.translation[1]), complexText(c.translation[2]), complexText(c.rotation[0]),
                         complexText(c.rotation[1]), complexText(c.rotation[2]), complexText(c.rotation[3]),
                         c.real ? "  real" : "", c.multiplicity > 1 ? fmt::format("  multiplicity {}", c.multiplicity) : std::string());
    }
  }
  for (const auto& n : sol.notes) out << "note: " << n << "\n";
  return ok ? 0 : 1;
}


int stewartCommand(const std::filesystem::path& platform, const std::string& method, ScalarKind scalar, bool json,
                   bool complex_, std::ostream& out, const FigureFiles& fig) {
  const auto m = parseStewartMethod(method);
  if (!m) throw InvalidInput("--method: \"" + method + "\" is not one of " + stewartMethodNames());
  return withScalar(scalar, [&]<class S>() { return stewartImpl<S>(platform, *m, json, complex_, out, fig); });
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
    spec.flag("--complex", complex_, "also print every complex solution (translation, rotation quaternion, Study parameters, multiplicity)");
    spec.add("--png", fig_.png, "write the figure (PNG): the platform at each real posture, a panel each");
    spec.add("--svg", fig_.svg, "write the figure as SVG (a line drawing of the same panels)");
  }
  int run(const Spec&, const Invocation&) override {
    return stewartCommand(file_, method_, scalar_.apply(), json_, complex_, std::cout, fig_);
  }

 private:
  std::string file_, method_ = "homotopy";
  ScalarOptions scalar_;
  FigureFiles fig_;
  bool json_ = false, complex_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(StewartCommand, 90);

}  // namespace soma::cli
