#pragma once
// Helpers shared by the studies of GF chapter 11 (gf11/*.cpp): the chapter's report section, the
// scalar draws of soma/studies/scalar_draws.hpp (inputs drawn in double and cast to S, the same on
// every rung of the ladder; exact fractions), unit vectors and orthonormal columns in S, and the
// identity tolerance k ε of S.
#include "soma/studies/scalar_draws.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <random>

namespace soma::studies::gf11 {

inline constexpr const char* kChapter = "GF 11 — The Study quadric";

using draws::frac;
using draws::maxOf;
using draws::rv3;
using draws::uni;  // soma/studies/scalar_draws.hpp

inline std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
/// k ε of S: the rounding of a short computation on unit-scale data (256 ε = 5.7e-14 in double).
template <class S> S tol(int ulps = 256) { return Tolerance<S>::identity(ulps); }
/// Uniform in [−1, 1]⁴, drawn in double and cast to S.
template <class S> Vec4<S> rv4(std::mt19937_64& g) {
  const S a = uni<S>(g), b = uni<S>(g), c = uni<S>(g), d = uni<S>(g);
  return Vec4<S>(a, b, c, d);
}
/// rv3 normalised in S.
template <class S> Vec3<S> unit3(std::mt19937_64& g) {
  using std::sqrt;
  const Vec3<S> v = rv3<S>(g);
  return Vec3<S>(v / S(sqrt(S(v.squaredNorm()))));
}
/// rv4 normalised in S.
template <class S> Vec4<S> unit4(std::mt19937_64& g) {
  using std::sqrt;
  const Vec4<S> v = rv4<S>(g);
  return Vec4<S>(v / S(sqrt(S(v.squaredNorm()))));
}
/// Orthonormal columns spanning those of a, in its scalar (modified Gram–Schmidt, twice).
template <class Derived> typename Derived::PlainObject orthonormalColumns(const Eigen::MatrixBase<Derived>& a) {
  using S = typename Derived::Scalar;
  using std::sqrt;
  typename Derived::PlainObject q = a;
  for (Eigen::Index j = 0; j < q.cols(); ++j) {
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index i = 0; i < j; ++i) {
        const S d = q.col(i).dot(q.col(j));
        q.col(j) -= d * q.col(i);
      }
    const S n = sqrt(S(q.col(j).squaredNorm()));
    q.col(j) /= n;
  }
  return q;
}

}  // namespace soma::studies::gf11
