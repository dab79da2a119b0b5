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
inline constexpr const char* kChapter9 = "GF 9 — Clifford algebra";

using V3 = Eigen::Vector3d;
using V6 = Vec6<double>;
using L = PluckerLine<double>;

inline std::mt19937_64 rng(std::uint64_t seed = 66) { return std::mt19937_64(seed); }
inline double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
inline V3 rv(std::mt19937_64& g, double lo = -1, double hi = 1) { return V3(uni(g, lo, hi), uni(g, lo, hi), uni(g, lo, hi)); }
inline V3 ru(std::mt19937_64& g) {
  V3 v;
  do v = rv(g);
  while (v.squaredNorm() < 0.1);
  return v.normalized();
}
inline V6 six(const V3& a, const V3& b) {
  V6 s;
  s << a, b;
  return s;
}
inline double tolId(int ulps = 64) { return Tolerance<double>::identity(ulps); }
inline std::string num(double x) { return toString(x, 6); }

/// The figure of GF-6.6-linear-complex (gf06/figures.cpp): complex lines through a few points.
void complexFigure(Context& c);

}  // namespace soma::studies::gf06
