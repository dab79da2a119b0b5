#pragma once
// Shared helpers of the GF §5.3–5.4 studies (planar kinematics). Studies run in double.
#include "soma/geometry/planar/burmester_synthesis.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"
#include "soma/studies/study.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace soma::studies::gf05p {

using namespace soma::planar;
using V2 = Vec2<double>;

inline const char* kChapter = "GF 5 — A little kinematics";

/// The book's E₂ = [[0, 1], [−1, 0]]: E₂v = (v_y, −v_x).
inline V2 E2(const V2& v) { return V2(v(1), -v(0)); }

/// Catalogue test instance (the book gives no numbers): c1 = (0,0), c4 = (3,0), crank 1.2,
/// coupler 2.5, rocker 2.0, crank angle 1 rad, ω1 = 1, ω̇1 = 0.3, ω̈1 = −0.2, upper branch.
inline FourBar<double> catalogueBar(const V2& pc = V2::Zero()) { return FourBar<double>(V2(0, 0), V2(3, 0), 1.2, 2.5, 2.0, pc); }
inline std::array<double, 5> catalogueLaw() { return {1.0, 1.0, 0.3, -0.2, 0.0}; }
inline MotionJet<double> catalogueJet() { return catalogueBar().couplerJet(1.0, 1, catalogueLaw()); }

/// Identity tolerance for double studies: k ulps of unit-scale data.
inline double tol(double k = 1024) { return k * Tolerance<double>::epsilon(); }

/// Finite-difference curvature of the path of a coupler body point at crank angle th (mode m),
/// 5-point stencil in θ1 (an independent method: the mechanism is solved at each sample).
inline double fdCurvature(const FourBar<double>& fb, double th, int mode, const V2& body, double h = 1e-3) {
  V2 P[5];
  for (int k = -2; k <= 2; ++k) P[k + 2] = fb.solve(th + k * h, mode)->coupler.act(body);
  const V2 d1 = (P[0] - 8 * P[1] + 8 * P[3] - P[4]) / (12 * h);
  const V2 d2 = (-P[0] + 16 * P[1] - 30 * P[2] + 16 * P[3] - P[4]) / (12 * h * h);
  return cross2<double>(d1, d2) / std::pow(d1.norm(), 3);
}

/// Finite-position synthesis round trips and figures (gf05/planar_synthesis.cpp), run inside
/// GF-5.3.5-burmester-count (the catalogue has no item of its own for it: it is beyond the book).
void finitePositionSynthesis(Context& c);

inline void circlePoints(const V2& c, double r, std::vector<double>& xs, std::vector<double>& ys, int n = 240) {
  xs.clear();
  ys.clear();
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / n;
    xs.push_back(c(0) + r * std::cos(a));
    ys.push_back(c(1) + r * std::sin(a));
  }
}

}  // namespace soma::studies::gf05p
