#pragma once
// Shared helpers of the GF §5.3–5.4 studies (planar kinematics), templated on the scalar S of a
// study that runs in the asked scalar (--scalar); S = double for the figures (soma::render draws
// double geometry).
#include "soma/geometry/planar/burmester_synthesis.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace soma::studies::gf05p {

using namespace soma::planar;
using V2 = Vec2<double>;
using draws::frac;
using draws::maxOf;
using draws::printedTol;

inline const char* kChapter = "GF 5 — A little kinematics";

/// The book's E₂ = [[0, 1], [−1, 0]]: E₂v = (v_y, −v_x).
template <class S> Vec2<S> E2(const Vec2<S>& v) { return Vec2<S>(v(1), -v(0)); }

/// Catalogue test instance (the book gives no numbers): c1 = (0,0), c4 = (3,0), crank 1.2,
/// coupler 2.5, rocker 2.0, crank angle 1 rad, ω1 = 1, ω̇1 = 0.3, ω̈1 = −0.2, upper branch; the
/// lengths and rates exact fractions in S.
template <class S = double> FourBar<S> catalogueBar(const Vec2<S>& pc = Vec2<S>::Zero()) {
  return FourBar<S>(Vec2<S>(S(0), S(0)), Vec2<S>(S(3), S(0)), frac<S>(12, 10), frac<S>(25, 10), S(2), pc);
}
template <class S = double> std::array<S, 5> catalogueLaw() { return {S(1), S(1), frac<S>(3, 10), frac<S>(-2, 10), S(0)}; }
template <class S = double> MotionJet<S> catalogueJet() { return catalogueBar<S>().couplerJet(S(1), 1, catalogueLaw<S>()); }

/// Identity tolerance: k ulps of unit-scale data in S.
template <class S = double> S tol(int k = 1024) { return Tolerance<S>::identity(k); }

/// Whether S resolves a finite-difference check of tolerance `tolerance` (the truncation bound of
/// the stencil): its rounding, ulps·ε/h^order, must stay below. Otherwise (float) the check is
/// skipped, with a note saying so.
template <class S> bool fdResolves(Context& c, const std::string& what, double h, int order, const S& tolerance, int ulps = 16) {
  S hk(1);
  for (int i = 0; i < order; ++i) hk *= S(h);
  const S rounding = Tolerance<S>::identity(ulps) / hk;
  if (rounding <= tolerance) return true;
  c.note("Skipped in this scalar: " + what + " (finite differences with h = " + toString(h, 3) + ": the rounding " +
         std::to_string(ulps) + " ε/h^" + std::to_string(order) + " = " + toString(toDouble(rounding), 3) +
         " exceeds the tolerance " + toString(toDouble(tolerance), 3) + ").");
  return false;
}

/// checkPrintedFails where S can tell the erratum from rounding: the printed formula's miss, of size
/// `missScale` (as measured in double), must exceed Context::kPrintedMissFactor × the rounding bound.
/// Where it cannot (float's bound is too wide), the check is skipped with a note.
template <class S>
void printedFailsIfResolved(Context& c, const std::string& name, const std::string& erratum, const S& residual, const S& bound,
                            double missScale) {
  if (S(Context::kPrintedMissFactor) * bound < S(missScale)) {
    c.checkPrintedFails(name, erratum, residual, bound);
    return;
  }
  c.note("Skipped in this scalar: the printed-formula check \"" + name + "\" (erratum " + erratum + "): its miss " +
         toString(toDouble(residual), 3) + " cannot be 1000× the rounding bound " + toString(toDouble(bound), 3) + ".");
}

/// Finite-difference curvature of the path of a coupler body point at crank angle th (mode m),
/// 5-point stencil in θ1 (an independent method: the mechanism is solved at each sample).
template <class S> S fdCurvature(const FourBar<S>& fb, const S& th, int mode, const Vec2<S>& body, const S& h = S(1) / S(1000)) {
  using std::abs;
  Vec2<S> P[5];
  for (int k = -2; k <= 2; ++k) P[k + 2] = fb.solve(th + S(k) * h, mode)->coupler.act(body);
  const Vec2<S> d1 = (P[0] - S(8) * P[1] + S(8) * P[3] - P[4]) / (S(12) * h);
  const Vec2<S> d2 = (-P[0] + S(16) * P[1] - S(30) * P[2] + S(16) * P[3] - P[4]) / (S(12) * h * h);
  const S n = d1.norm();
  return cross2<S>(d1, d2) / (n * n * n);
}

/// Finite-position synthesis round trips in S and their figures in double (gf05/planar_synthesis.cpp,
/// instantiated there for the ladder), run inside GF-5.3.5-burmester-count (the catalogue has no item
/// of its own for it: it is beyond the book).
template <class S> void finitePositionSynthesis(Context& c);

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
