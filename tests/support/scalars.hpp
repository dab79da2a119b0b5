#pragma once
// Test support: the scalar ladder for TEMPLATE_TEST_CASE, fixed-seed random draws,
// and Catch2 printing of __float128 / mpreal.
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <catch2/catch.hpp>
#include <random>

/// All five rungs; use with TEMPLATE_TEST_CASE("...", "[tag]", SOMA_TEST_SCALARS).
#define SOMA_TEST_SCALARS float, double, long double, __float128, mpfr::mpreal
/// The rungs without mpfr, for the heavier randomized suites.
#define SOMA_TEST_SCALARS_FAST float, double, long double, __float128

namespace Catch {
template <> struct StringMaker<__float128> {
  static std::string convert(__float128 x) { return soma::toString(x); }
};
}  // namespace Catch

namespace soma::test {

/// One fixed-seed engine per test case: call rng(seed) at the top of the case.
inline std::mt19937_64& rng(std::uint64_t seed = 20261125) {
  static std::mt19937_64 engine;
  engine.seed(seed);
  return engine;
}

/// Uniform draw in [lo, hi) converted to S (randomness comes from double; precision from S).
template <class S> S uniform(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return scalarCast<S>(std::uniform_real_distribution<double>(lo, hi)(g));
}
template <class S, int N> Eigen::Matrix<S, N, 1> uniformVec(std::mt19937_64& g, double lo = -1,
                                                            double hi = 1) {
  Eigen::Matrix<S, N, 1> v;
  for (int i = 0; i < N; ++i) v(i) = uniform<S>(g, lo, hi);
  return v;
}
/// Unit vector with a uniform direction.
template <class S> Vec3<S> unitVec3(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  Vec3<S> v;
  do {
    v = Vec3<S>(scalarCast<S>(n(g)), scalarCast<S>(n(g)), scalarCast<S>(n(g)));
  } while (v.squaredNorm() < S(1e-6));
  return v.normalized();
}

}  // namespace soma::test
