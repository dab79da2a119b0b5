#pragma once
// Definitions of solveStewart (solve_stewart.hpp), instantiated for the five scalars by soma_instantiate.
#include "soma/geometry/parallel/solve_stewart.hpp"

#include "soma/geometry/numeric_polish.hpp"

#include <chrono>
#include <cstdio>
#include <optional>
#include <type_traits>

namespace soma {

namespace {

template <class S> struct LiftedPosture {
  SE3<S> g;
  S residual;
  bool converged = true;
};

}  // namespace

template <class S> StewartSolution<S> solveStewart(const StewartPlatform<S>& P, const StewartOptions& options) {
  StewartSolution<S> sol;
  if (options.method == StewartMethod::Homotopy) {
    // The start system (a 128-path total-degree homotopy on a random complex platform) is solved
    // once per process; its time is reported apart from the per-platform solve.
    const auto s0 = std::chrono::steady_clock::now();
    (void)stewartStartSolutions<S>();
    sol.start_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    static_cast<StewartForwardSolution<S>&>(sol) = solveStewartForward<S>(P, options.fineTracking ? StewartTracking::Fine : StewartTracking::Auto);
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.3g", sol.start_seconds);
    sol.notes.push_back(std::string("start system (40 solutions of a random complex platform, 128-path total-degree "
                                    "homotopy, once per process): ") +
                        secs + " s, not included in the time");
    // Certified: every path tracked and the count (with multiplicity) is the class's (stewart_class.hpp).
    sol.certified = sol.expected_count > 0 && sol.complexCount() == sol.expected_count;
    return sol;
  }
  // Ceres and NLopt run in double; in a wider scalar each posture is then polished by Newton in S.
  validateStewartPlatform<S>(P);
  const StewartPlatform<double> Pd = P.template cast<double>();
  const auto lifted = searchInDoublePolishInS(
      [&] {
        return options.method == StewartMethod::Ceres ? solveStewartForwardCeres(Pd, options.numeric)
                                                      : solveStewartForwardNlopt(Pd, options.numeric);
      },
      [&](const SE3<double>& g) -> std::optional<LiftedPosture<S>> {
        LiftedPosture<S> l{g.template cast<S>(), S(0), true};
        if constexpr (!std::is_same_v<S, double>) l.g = polishStewartPosture<S>(P, l.g, &l.converged);
        l.residual = stewartResidual<S>(P, l.g);
        return l;
      });
  const StewartForwardSolution<double>& d = lifted.found;
  sol.method = d.method;
  sol.seconds = lifted.seconds;
  sol.paths_tracked = d.paths_tracked;
  sol.notes = d.notes;
  for (const auto& l : lifted.polished) {
    if (!l.converged)
      sol.notes.push_back("a posture did not converge in the Newton polish in " + std::string(scalarName<S>()));
    sol.postures.push_back(l.g);
    sol.residuals.push_back(l.residual);
  }
  sol.real_count = static_cast<int>(sol.postures.size());
  sol.certified = false;
  return sol;
}

#define SOMA_INSTANTIATE_SOLVE_STEWART(S) \
  template StewartSolution<S> solveStewart<S>(const StewartPlatform<S>&, const StewartOptions&);

}  // namespace soma
