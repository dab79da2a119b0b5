#include "soma/studies/stewart_command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/stewart_numeric.hpp"
#include "soma/io/platform_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>

namespace soma::studies {

namespace {

using json = nlohmann::json;

json pointsJson(const auto& pts) {
  json a = json::array();
  for (const auto& p : pts) a.push_back({toDouble(p(0)), toDouble(p(1)), toDouble(p(2))});
  return a;
}

template <class S>
int stewartImpl(const std::filesystem::path& file, const std::string& method, bool json_, std::ostream& out) {
  const StewartPlatform<S> P = io::readPlatform<S>(file);
  // The start system (a 128-path total-degree homotopy on a random complex platform) is solved
  // once per process; its time is reported apart from the per-platform solve.
  StewartForwardSolution<S> sol;
  const bool numeric = method == "ceres" || method == "nlopt";
  if (numeric) {
    // Ceres and NLopt run in double; in a wider scalar each posture is then polished by Newton in S.
    StewartPlatform<double> Pd;
    for (int i = 0; i < 6; ++i) {
      Pd.base[i] = castMatrix<double>(P.base[i]);
      Pd.platform[i] = castMatrix<double>(P.platform[i]);
      Pd.legs[i] = toDouble(P.legs[i]);
    }
    const auto d = method == "ceres" ? solveStewartForwardCeres(Pd) : solveStewartForwardNlopt(Pd);
    sol.method = d.method;
    sol.seconds = d.seconds;
    sol.paths_tracked = d.paths_tracked;
    sol.notes = d.notes;
    for (const auto& g : d.postures) {
      bool converged = true;
      const SE3<S> gs = std::is_same_v<S, double>
                            ? g.template cast<S>()
                            : polishStewartPosture<S>(P, g.template cast<S>(), &converged);
      if (!converged) sol.notes.push_back("a posture did not converge in the Newton polish in " +
                                          std::string(scalarName<S>()));
      sol.postures.push_back(gs);
      sol.residuals.push_back(stewartResidual<S>(P, gs));
    }
    sol.real_count = static_cast<int>(sol.postures.size());
  } else {
    // The start system (a 128-path total-degree homotopy on a random complex platform) is solved
    // once per process; its time is reported apart from the per-platform solve.
    const auto s0 = std::chrono::steady_clock::now();
    (void)stewartStartSolutions<S>();
    const double startSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    sol = solveStewartForward<S>(P);
    sol.notes.push_back(fmt::format("start system (40 solutions of a random complex platform, 128-path total-degree "
                                    "homotopy, once per process): {:.3g} s, not included in the time",
                                    startSeconds));
  }
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
    j["certified"] = !numeric;
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

}  // namespace

int stewartCommand(const std::filesystem::path& platform, const std::string& method, ScalarKind scalar, bool json,
                   std::ostream& out) {
  if (method != "homotopy" && method != "auto" && method != "ceres" && method != "nlopt")
    throw InvalidInput("--method: \"" + method + "\" is not one of auto homotopy ceres nlopt");
  return withScalar(scalar, [&]<class S>() { return stewartImpl<S>(platform, method, json, out); });
}

}  // namespace soma::studies
