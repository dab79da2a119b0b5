#pragma once
// Helpers shared by the studies of GF chapter 12 (gf12/statics.cpp, gf12/grasp.cpp): the chapter's
// report section, random draws in double cast to the working scalar S (the same inputs on every rung
// of the ladder), exact fractions, a NaN-propagating max and the smaller samples of the slow scalars.
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <random>
#include <string>
#include <type_traits>

namespace soma::studies::gf12 {

inline constexpr const char* kChapter = "GF 12 — Statics";

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
/// float128 and mpfr run in software: long searches (thousands of linear programs) use a smaller
/// sample there, and say the count in the check's name.
template <class S> inline constexpr bool kSlowScalar = std::is_same_v<S, float128> || std::is_same_v<S, mpreal>;
template <class S> int samples(int full, int slow) { return kSlowScalar<S> ? slow : full; }
inline std::string yesNo(bool b) { return b ? "yes" : "no"; }

}  // namespace soma::studies::gf12
