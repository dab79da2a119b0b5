#pragma once
// Small-angle helpers shared by the Lie groups (SE(2), SO(3), SE(3)): the cached Taylor
// switches and θ − sin θ without cancellation. (DESIGN §2: thresholds come from Tolerance.)
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

namespace soma::detail {

/// Square of the Taylor switch Tolerance<S>::precision(k), cached for the fixed-width types
/// (mpreal's precision can change at run time, so it is recomputed there).
template <class S> S taylorSwitch2(int k) {
  if constexpr (std::is_same_v<S, mpreal>) {
    const S s = Tolerance<S>::precision(k);
    return s * s;
  } else {
    static const S table[8] = {
        Tolerance<S>::precision(0) * Tolerance<S>::precision(0),
        Tolerance<S>::precision(1) * Tolerance<S>::precision(1),
        Tolerance<S>::precision(2) * Tolerance<S>::precision(2),
        Tolerance<S>::precision(3) * Tolerance<S>::precision(3),
        Tolerance<S>::precision(4) * Tolerance<S>::precision(4),
        Tolerance<S>::precision(5) * Tolerance<S>::precision(5),
        Tolerance<S>::precision(6) * Tolerance<S>::precision(6),
        Tolerance<S>::precision(7) * Tolerance<S>::precision(7)};
    if (k >= 0 && k < 8) return table[k];
    const S s = Tolerance<S>::precision(k);
    return s * s;
  }
}

/// θ − sin θ without cancellation: its Taylor series (summed to machine precision) for
/// |θ| ≤ 1, where the direct difference would lose bits; the direct difference above
/// (it loses < 3 bits at θ = 1 and fewer beyond).
template <class S> S thetaMinusSin(const S& theta) {
  using std::abs;
  using std::sin;
  if (abs(theta) > S(1)) return theta - sin(theta);
  const S x2 = theta * theta;
  S term = theta * x2 / S(6);
  S sum = term;
  const S eps = Tolerance<S>::epsilon();
  for (int n = 1; n < 200; ++n) {
    term = -term * x2 / S((2 * n + 2) * (2 * n + 3));
    sum += term;
    if (abs(term) <= eps * abs(sum)) break;
  }
  return sum;
}

}  // namespace soma::detail
