#pragma once
// Inputs of the studies that run in the asked scalar: random draws made in double and cast to S (the
// same inputs on every rung of the ladder), exact fractions n/d in S, NaN-propagating max and min, and
// the tolerance of a value printed to a few decimals.
// In their own namespace: a chapter takes them by using-declarations (gf12/common.hpp,
// gf13/common.hpp), so that another chapter's helpers of the same name in a unity batch stay unambiguous.
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <random>

namespace soma::studies::draws {

/// Uniform in [lo, hi], drawn in double and cast to S.
template <class S> S uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return scalarCast<S>(std::uniform_real_distribution<double>(lo, hi)(g));
}
template <class S> Vec3<S> rv3(std::mt19937_64& g, double lo = -1, double hi = 1) {
  const S x = uni<S>(g, lo, hi), y = uni<S>(g, lo, hi), z = uni<S>(g, lo, hi);
  return Vec3<S>(x, y, z);
}
template <class S> Vec6<S> rv6(std::mt19937_64& g) {
  Vec6<S> v;
  for (int i = 0; i < 6; ++i) v(i) = uni<S>(g);
  return v;
}
/// n/d in S: an input such as 0.3 written exactly as the scalar rounds it, not as a double.
template <class S> S frac(long n, long d = 1) { return S(n) / S(d); }
/// max(a, b), propagating NaN (a comparison-based max would silently skip it).
template <class S> S maxOf(const S& a, const S& b) {
  if (!isFinite(a)) return a;
  if (!isFinite(b)) return b;
  return a < b ? b : a;
}
/// min(a, b), propagating NaN (as maxOf).
template <class S> S minOf(const S& a, const S& b) {
  if (!isFinite(a)) return a;
  if (!isFinite(b)) return b;
  return b < a ? b : a;
}
/// xⁿ by repeated multiplication, in S (std::pow(float, int) would return double).
template <class S> S ipow(const S& x, int n) {
  S r(1);
  for (int k = 0; k < n; ++k) r *= x;
  return r;
}
/// The tolerance of a value printed with `decimals` decimals (the book's, the catalogue's): half a
/// unit of its last digit, plus `ulps` ε of S times its magnitude `scale` for the rounding of the
/// computation it is compared with.
template <class S> S printedTol(int decimals, int ulps, double scale = 1) {
  S unitLast(1);
  for (int i = 0; i < decimals; ++i) unitLast /= S(10);
  return unitLast / S(2) + scalarCast<S>(scale) * S(ulps) * Tolerance<S>::epsilon();
}

}  // namespace soma::studies::draws
