#pragma once
// Helpers shared by the studies of GF chapter 6 and §9.4 (gf06/*.cpp, gf09/ruled.cpp): fixed-seed
// draws and independent reference methods (brute-force minimisation, null spaces by SVD).
// Nothing here is library code: these are the "other method" a study compares against.
#include "soma/geometry/lines/curvature_axes.hpp"
#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/lines/grassmannian.hpp"
#include "soma/geometry/lines/inverse_jacobian.hpp"
#include "soma/geometry/lines/linear_complex.hpp"
#include "soma/geometry/lines/regulus.hpp"
#include "soma/geometry/lines/ruled_surface.hpp"
#include "soma/studies/study.hpp"

#include <random>
#include <string>

namespace soma::studies::gf06 {

inline constexpr const char* kChapter = "GF 6 — Line geometry";

using V3 = Eigen::Vector3d;
using V6 = Vec6<double>;
using L = PluckerLine<double>;

inline std::mt19937_64 rng(std::uint64_t seed = 66) { return std::mt19937_64(seed); }
/// Uniform draws made in double and cast to S: the same inputs on every rung of the ladder.
template <class S = double> S uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return scalarCast<S>(std::uniform_real_distribution<double>(lo, hi)(g));
}
template <class S = double> Vec3<S> rv(std::mt19937_64& g, double lo = -1, double hi = 1) {
  const S x = uni<S>(g, lo, hi), y = uni<S>(g, lo, hi), z = uni<S>(g, lo, hi);
  return Vec3<S>(x, y, z);
}
/// A unit vector: a draw in [−1, 1]³ with |v|² ≥ 0.1, normalised.
template <class S = double> Vec3<S> ru(std::mt19937_64& g) {
  Vec3<S> v;
  do v = rv<S>(g);
  while (v.squaredNorm() * S(10) < S(1));
  return v.normalized();
}
inline V6 six(const V3& a, const V3& b) {
  V6 s;
  s << a, b;
  return s;
}
template <class S> Vec6<S> six(const Vec3<S>& a, const Vec3<S>& b) {
  Vec6<S> s;
  s << a, b;
  return s;
}
/// k ulps of unit-scale data in S (Tolerance<S>::identity).
template <class S = double> S tolId(int ulps = 64) { return Tolerance<S>::identity(ulps); }
inline std::string num(double x) { return toString(x, 6); }
template <class S> std::string num(const S& x) { return toString(toDouble(x), 6); }
template <class S> using Ln = PluckerLine<S>;
/// 10⁻ᵏ correctly rounded in S (a double literal cast to mpreal keeps the double's error).
template <class S> S tenTo(int k) {
  S r(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) r *= S(10);
  return k < 0 ? S(1) / r : r;
}

/// The figure of GF-6.6-linear-complex (gf06/figures.cpp): complex lines through a few points.
void complexFigure(Context& c);

}  // namespace soma::studies::gf06
