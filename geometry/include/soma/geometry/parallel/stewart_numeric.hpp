#pragma once
// Forward kinematics of a Stewart–Gough platform by local numerical methods (the alternatives to
// the homotopy of stewart.hpp, DESIGN §3): many random starts, each run to a root of the six leg
// equations by Ceres (Levenberg–Marquardt) or NLopt (L-BFGS on the squared residual), polished by
// Newton and clustered. Such a search finds real postures only and cannot certify that it found
// them all; the homotopy can (GF §11.5.4, GF-11.5.4-stewart-forty), so these are measured against
// it (studies: SOMA-11.5.4-stewart-speed-accuracy).
//
// Unknowns: a posture p ↦ R p + t in the platform's centred and scaled coordinates, R updated on
// the right (R exp(ω̂)) so that no chart of SO(3) is singular; residuals
// r_i = (|R q_i + t − p_i|² − L_i²) / 2, i = 1..6 (GF §11.5.4, the leg constraint).
#include "soma/geometry/parallel/stewart.hpp"

#include <cstdint>

namespace soma {

struct StewartNumericOptions {
  int starts = 256;               ///< random initial postures (uniform rotation, translation in a box)
  std::uint64_t seed = 1;         ///< fixed seed of the starts
  int max_iterations = 100;       ///< per start
};

/// Multi-start Levenberg–Marquardt with Ceres. Method name "ceres" (double).
StewartForwardSolution<double> solveStewartForwardCeres(const StewartPlatform<double>& P,
                                                        const StewartNumericOptions& options = {});

/// Multi-start L-BFGS with NLopt on Σ r_i². Method name "nlopt" (double).
StewartForwardSolution<double> solveStewartForwardNlopt(const StewartPlatform<double>& P,
                                                        const StewartNumericOptions& options = {});

/// Newton on the six leg equations from posture g, in S (R updated on the right). Returns the
/// polished posture; `converged` (if given) is set when the last correction reached the rounding
/// floor of S. Used to carry a double posture to a wider scalar.
template <class S>
SE3<S> polishStewartPosture(const StewartPlatform<S>& P, const SE3<S>& g, bool* converged = nullptr);

#define SOMA_STEWART_NUMERIC_EXTERN(S) \
  extern template SE3<S> polishStewartPosture<S>(const StewartPlatform<S>&, const SE3<S>&, bool*);
SOMA_FOR_EACH_SCALAR(SOMA_STEWART_NUMERIC_EXTERN)
#undef SOMA_STEWART_NUMERIC_EXTERN

}  // namespace soma
