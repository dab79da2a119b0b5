#pragma once
// Truncated Taylor series f(t) = Σ_{k<N} a_k t^k (a_k = f^(k)(0)/k!) with the arithmetic that
// the planar position analysis needs (+, −, ×, ÷, sqrt, sin/cos, atan2). Pushing a motion
// through the closed-form position formulas with this type gives its derivatives exactly
// (to rounding): the "jet" of GF §5.3.1 without finite differences. Header only: it is small.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"

#include <array>

namespace soma::planar {

template <class S, int N> struct TaylorSeries {
  static_assert(N >= 1);
  std::array<S, N> a;

  TaylorSeries() { a.fill(S(0)); }
  /// The constant c.
  explicit TaylorSeries(const S& c) {
    a.fill(S(0));
    a[0] = c;
  }
  /// The variable t shifted: c + t.
  static TaylorSeries variable(const S& c) {
    TaylorSeries r(c);
    if (N > 1) r.a[1] = S(1);
    return r;
  }
  /// From derivatives f(0), f'(0), ..., f^(N−1)(0).
  static TaylorSeries fromDerivatives(const std::array<S, N>& d) {
    TaylorSeries r;
    S fact(1);
    for (int k = 0; k < N; ++k) {
      if (k > 0) fact *= S(k);
      r.a[k] = d[k] / fact;
    }
    return r;
  }
  /// f^(k)(0) = k! a_k.
  S derivative(int k) const {
    S fact(1);
    for (int j = 2; j <= k; ++j) fact *= S(j);
    return a[k] * fact;
  }
  S value() const { return a[0]; }
  /// Value at t (Horner); meaningful for small t only.
  S operator()(const S& t) const {
    S v = a[N - 1];
    for (int k = N - 2; k >= 0; --k) v = v * t + a[k];
    return v;
  }

  TaylorSeries operator+(const TaylorSeries& o) const {
    TaylorSeries r;
    for (int k = 0; k < N; ++k) r.a[k] = a[k] + o.a[k];
    return r;
  }
  TaylorSeries operator-(const TaylorSeries& o) const {
    TaylorSeries r;
    for (int k = 0; k < N; ++k) r.a[k] = a[k] - o.a[k];
    return r;
  }
  TaylorSeries operator-() const {
    TaylorSeries r;
    for (int k = 0; k < N; ++k) r.a[k] = -a[k];
    return r;
  }
  TaylorSeries operator*(const S& c) const {
    TaylorSeries r;
    for (int k = 0; k < N; ++k) r.a[k] = a[k] * c;
    return r;
  }
  friend TaylorSeries operator*(const S& c, const TaylorSeries& f) { return f * c; }
  TaylorSeries operator+(const S& c) const {
    TaylorSeries r = *this;
    r.a[0] += c;
    return r;
  }
  TaylorSeries operator-(const S& c) const {
    TaylorSeries r = *this;
    r.a[0] -= c;
    return r;
  }
  TaylorSeries operator*(const TaylorSeries& o) const {
    TaylorSeries r;
    for (int k = 0; k < N; ++k) {
      S s(0);
      for (int i = 0; i <= k; ++i) s += a[i] * o.a[k - i];
      r.a[k] = s;
    }
    return r;
  }
  /// Division; throws InvalidInput when the divisor's constant term is zero.
  TaylorSeries operator/(const TaylorSeries& o) const {
    if (o.a[0] == S(0)) throw InvalidInput("Taylor series: division by a series that vanishes at t = 0");
    TaylorSeries r;
    for (int k = 0; k < N; ++k) {
      S s = a[k];
      for (int i = 1; i <= k; ++i) s -= o.a[i] * r.a[k - i];
      r.a[k] = s / o.a[0];
    }
    return r;
  }
  TaylorSeries operator/(const S& c) const { return *this * (S(1) / c); }

  /// f'(t) as a series; its last coefficient is unknown and set to 0 (one order is lost).
  TaylorSeries derivativeSeries() const {
    TaylorSeries r;
    for (int k = 0; k + 1 < N; ++k) r.a[k] = S(k + 1) * a[k + 1];
    return r;
  }
  /// (f(t)/t) for f(0) = 0: the coefficients shifted down; the last one is unknown (0).
  TaylorSeries shiftDown() const {
    TaylorSeries r;
    for (int k = 0; k + 1 < N; ++k) r.a[k] = a[k + 1];
    return r;
  }
};

/// √f; throws InvalidInput when f(0) ≤ 0 (the derivatives of √f are infinite at f = 0: a branch point).
template <class S, int N> TaylorSeries<S, N> sqrt(const TaylorSeries<S, N>& f) {
  using std::sqrt;
  if (!(f.a[0] > S(0)))
    throw InvalidInput("Taylor series: square root of a series with f(0) = " + toString(f.a[0]) +
                       " ≤ 0 (a branch point: derivatives are infinite)");
  TaylorSeries<S, N> r;
  r.a[0] = sqrt(f.a[0]);
  for (int k = 1; k < N; ++k) {
    S s = f.a[k];
    for (int i = 1; i < k; ++i) s -= r.a[i] * r.a[k - i];
    r.a[k] = s / (S(2) * r.a[0]);
  }
  return r;
}

/// (sin f, cos f) together: k s_k = Σ j f_j c_{k−j}, k c_k = −Σ j f_j s_{k−j}.
template <class S, int N> void sincos(const TaylorSeries<S, N>& f, TaylorSeries<S, N>& s, TaylorSeries<S, N>& c) {
  using std::cos;
  using std::sin;
  s.a[0] = sin(f.a[0]);
  c.a[0] = cos(f.a[0]);
  for (int k = 1; k < N; ++k) {
    S ss(0), cc(0);
    for (int j = 1; j <= k; ++j) {
      ss += S(j) * f.a[j] * c.a[k - j];
      cc -= S(j) * f.a[j] * s.a[k - j];
    }
    s.a[k] = ss / S(k);
    c.a[k] = cc / S(k);
  }
}

/// atan2(y, x) as a series: θ(0) from atan2, θ' = (x y' − y x')/(x² + y²) integrated.
template <class S, int N> TaylorSeries<S, N> atan2(const TaylorSeries<S, N>& y, const TaylorSeries<S, N>& x) {
  using std::atan2;
  const TaylorSeries<S, N> num = x * y.derivativeSeries() - y * x.derivativeSeries();
  const TaylorSeries<S, N> g = num / (x * x + y * y);
  TaylorSeries<S, N> r;
  r.a[0] = atan2(y.a[0], x.a[0]);
  for (int k = 1; k < N; ++k) r.a[k] = g.a[k - 1] / S(k);
  return r;
}

}  // namespace soma::planar
