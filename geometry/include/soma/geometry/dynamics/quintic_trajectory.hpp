#pragma once
// The quintic rest-to-rest joint trajectory (the minimum-jerk profile of trajectory planning,
// GF §13.3's inverse-dynamics use): θ(t) = θ₀ + (θ₁ − θ₀) σ(τ), τ = t/T, σ = 10τ³ − 15τ⁴ + 6τ⁵,
// so θ, θ̇ = 0 and θ̈ = 0 at both ends.
#include "soma/algebra/errors.hpp"
#include "soma/geometry/dynamics/serial_dynamics.hpp"

namespace soma {

template <class S> struct TrajectorySample {
  S t;
  DynVector<S> theta, thetaDot, thetaDDot;
};

/// The sample at time t ∈ [0, T] of the quintic from θ₀ to θ₁ in T seconds (InvalidInput for
/// T ≤ 0, t outside [0, T] or mismatched sizes).
template <class S>
TrajectorySample<S> quinticSample(const DynVector<S>& from, const DynVector<S>& to, const S& duration, const S& t) {
  if (!(duration > S(0))) throw InvalidInput("quinticSample: the duration must be positive");
  if (from.size() != to.size()) throw InvalidInput("quinticSample: the end postures have different sizes");
  if (t < S(0) || t > duration) throw InvalidInput("quinticSample: t outside [0, T]");
  const S u = t / duration, u2 = u * u, u3 = u2 * u;
  const S sigma = u3 * (S(10) - S(15) * u + S(6) * u2);
  const S dsigma = S(30) * u2 * (S(1) - S(2) * u + u2) / duration;
  const S ddsigma = S(60) * u * (S(1) - S(3) * u + S(2) * u2) / (duration * duration);
  const DynVector<S> d = to - from;
  return {t, DynVector<S>(from + sigma * d), DynVector<S>(dsigma * d), DynVector<S>(ddsigma * d)};
}

}  // namespace soma
