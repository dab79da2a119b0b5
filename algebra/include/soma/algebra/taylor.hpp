#pragma once
// Small-angle helpers shared by the Lie groups (SE(2), SO(3), SE(3)): the cached Taylor
// switches and θ − sin θ without cancellation. (DESIGN §2: thresholds come from Tolerance.)
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <array>
#include <limits>
#include <type_traits>

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

/// Number of terms K of the series (θ − sin θ)/θ³ = Σ_{k<K} (−1)^k θ^{2k}/(2k+3)! that makes the
/// truncation error (below the first omitted term, θ^{2K}/(2K+3)! for |θ| ≤ 1, an alternating
/// series) smaller than half an ulp of its value 1/6 in a type with `digits` mantissa bits:
/// 6/(2K+3)! < 2^−digits. float 5, double 8, long double 10, __float128 15 terms.
constexpr int sinSeriesTerms(int digits) {
  long double bound = 1;  // 2^digits
  for (int i = 0; i < digits; ++i) bound *= 2;
  int K = 0;
  long double fact = 6;  // (2K+3)!
  while (fact / 6 <= bound) {
    ++K;
    fact *= static_cast<long double>((2 * K + 2) * (2 * K + 3));
  }
  return K;
}

static_assert(sinSeriesTerms(24) == 5 && sinSeriesTerms(53) == 8 && sinSeriesTerms(64) == 10 &&
              sinSeriesTerms(113) == 15);

/// The K coefficients c_k = 1/(2k+3)! in S's arithmetic (c_0 = 1/6, then one division by an
/// integer per step).
template <class S, int K> constexpr std::array<S, K> sinSeriesCoefficients() {
  std::array<S, K> c{};
  c[0] = S(1) / S(6);
  for (int k = 1; k < K; ++k) c[k] = c[k - 1] / S((2 * k + 2) * (2 * k + 3));
  return c;
}

/// (θ − sin θ)/θ³ for θ² = x2 ≤ 1: Horner evaluation of its Taylor series with a fixed number of
/// terms for the fixed-width types (float … __float128: no loop with a data-dependent exit, no
/// division, exact at θ = 0); mpreal sums the series until a term drops below its ε (its
/// precision is a run-time value).
template <class S> S thetaMinusSinOverCube(const S& x2) {
  if constexpr (!std::is_same_v<S, mpreal>) {
    constexpr int K = sinSeriesTerms(std::numeric_limits<S>::digits);
    // float, double, long double: the coefficients are compile-time constants; __float128's
    // software arithmetic is not constexpr-evaluable everywhere, so it builds them once.
    if constexpr (std::is_floating_point_v<S>) {
      constexpr std::array<S, K> c = sinSeriesCoefficients<S, K>();
      S p = c[K - 1];
      for (int k = K - 2; k >= 0; --k) p = c[k] - x2 * p;
      return p;
    } else {
      static const std::array<S, K> c = sinSeriesCoefficients<S, K>();
      S p = c[K - 1];
      for (int k = K - 2; k >= 0; --k) p = c[k] - x2 * p;
      return p;
    }
  } else {
    using std::abs;
    S term = S(1) / S(6);
    S sum = term;
    const S eps = Tolerance<S>::epsilon();
    for (int n = 1; n < 100000; ++n) {  // capped: the terms fall like 1/(2n+3)!
      term = -term * x2 / S((2 * n + 2) * (2 * n + 3));
      sum += term;
      if (abs(term) <= eps * abs(sum)) break;
    }
    return sum;
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
  return theta * x2 * thetaMinusSinOverCube(x2);
}

}  // namespace soma::detail
