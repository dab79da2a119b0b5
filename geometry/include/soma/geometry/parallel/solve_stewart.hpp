#pragma once
// The forward kinematics of a Stewart–Gough platform, one entry point for every method
// (DESIGN §3): every real posture for the six leg lengths.
//   homotopy   all 40 complex solutions by the parameter homotopy (stewart.hpp; GF §11.5.4,
//              GF-11.5.4-stewart-forty), in the working scalar: the count is certified;
//   ceres, nlopt   multi-start searches in double (stewart_numeric.hpp), each posture Newton-
//              polished in the working scalar (numeric_polish.hpp): real postures only, the count
//              not certified.
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/stewart_numeric.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace soma {

enum class StewartMethod { Homotopy, Ceres, Nlopt };
/// "auto" and "homotopy" → Homotopy, "ceres", "nlopt"; nullopt for any other name.
std::optional<StewartMethod> parseStewartMethod(std::string_view name);
std::string_view stewartMethodName(StewartMethod m);
/// "auto homotopy ceres nlopt", for messages.
std::string stewartMethodNames();

struct StewartOptions {
  StewartMethod method = StewartMethod::Homotopy;
  /// ceres, nlopt: starts, seed, iterations.
  StewartNumericOptions numeric;
  /// homotopy: track to √eps of S (see solveStewartForward).
  bool fineTracking = false;
};

/// The answer of solveStewart: StewartForwardSolution<S> plus its certification.
template <class S> struct StewartSolution : StewartForwardSolution<S> {
  /// Homotopy: true when the complex solutions found (with multiplicity) are exactly the count of
  /// the platform's class (stewart_class.hpp); false when short, when the class has no tabulated
  /// count, and always for ceres and nlopt (no certificate that every posture was found).
  bool certified = false;
  /// homotopy: seconds spent on the start system (solved once per process; 0 when cached), not
  /// included in `seconds`.
  double start_seconds = 0;
};

/// Every real posture of the platform for its leg lengths, each with its residual. Throws
/// InvalidInput for an invalid platform (validateStewartPlatform).
template <class S> StewartSolution<S> solveStewart(const StewartPlatform<S>& platform, const StewartOptions& options = {});

#define SOMA_SOLVE_STEWART_EXTERN(S) \
  extern template StewartSolution<S> solveStewart<S>(const StewartPlatform<S>&, const StewartOptions&);
SOMA_FOR_EACH_SCALAR(SOMA_SOLVE_STEWART_EXTERN)
#undef SOMA_SOLVE_STEWART_EXTERN

}  // namespace soma
