// Finite-position Burmester synthesis (beyond GF §5.3.5, which treats the infinitesimal case):
// round trips through random 4-bars in the asked scalar, and the figures (in double, soma::render).
// Called from GF-5.3.5-burmester-count.
#include "gf05/planar_common.hpp"

#include <algorithm>
#include <limits>
#include <random>

namespace soma::studies::gf05p {  // not per-file (SOMA_UNITY_ID): it defines functions other chapter files call

namespace {

template <class S> struct Trial {
  FourBar<S> bar;
  std::vector<SE2<S>> positions;
  Vec2<S> c1, c4, z2, z3;
};

/// A random crank-rocker and five coupler poses: draws in double (the same on every rung), the
/// linkage built and solved in S.
template <class S> Trial<S> randomTrial(std::mt19937_64& g) {
  using std::cos;
  using std::sin;
  using P = Vec2<S>;
  std::uniform_real_distribution<double> u(0, 1);
  auto d = [&](double lo, double width) { return scalarCast<S>(lo + width * u(g)); };
  for (;;) {
    const S l0 = d(2, 2), l1 = d(0.5, 0.7), l2 = d(1.5, 2), l3 = d(1.5, 2);
    const S ang = d(0, 6.283);
    const S x1 = d(-1, 2), y1 = d(-1, 2);
    const P c1(x1, y1), c4 = c1 + l0 * P(cos(ang), sin(ang));
    const S px = d(-1, 2), py = d(1, 1);
    const P pc(px, py);
    const FourBar<S> fb(c1, c4, l1, l2, l3, pc);
    if (fb.classify().type != GrashofType::CrankRocker) continue;
    const S t0 = d(0, 6.283);
    const int mode = u(g) < 0.5 ? 1 : -1;
    const SE2<S> off(frac<S>(4, 10), pc);
    std::vector<SE2<S>> pos;
    for (int i = 0; i < 5; ++i) {
      const S ti = t0 + frac<S>(9 * i, 10) + d(0, 0.3);
      pos.push_back(fb.solve(ti, mode)->coupler * off);
    }
    const SE2<S> B = off.inverse();
    return {fb, pos, c1, c4, B.act(P(S(0), S(0))), B.act(P(l2, S(0)))};
  }
}

void addPoints(render::Plot& plot, const std::string& name, const std::vector<V2>& pts, render::Color col, double radius, bool line = false) {
  std::vector<double> xs, ys;
  for (const V2& p : pts) {
    xs.push_back(p(0));
    ys.push_back(p(1));
  }
  auto& s = plot.add(name, xs, ys, col);
  s.line = line;
  s.markers = true;
  s.markerRadius = radius;
}

/// The two figures of the finite-position synthesis, from the first trial, drawn in double.
void synthesisFigures(Context& c) {
  std::mt19937_64 g(20261130);
  const Trial<double> shown = randomTrial<double>(g);
  // Figure 1: the two centre-point curves and their intersections
  const BurmesterSynthesis<double> bs(shown.positions);
  const auto pairs = bs.burmesterPairs();
  double lo = -1e9;
  V2 mn(1e9, 1e9), mx(-1e9, -1e9);
  for (const auto& p : pairs) {
    mn = mn.cwiseMin(p.centre);
    mx = mx.cwiseMax(p.centre);
  }
  for (const auto& p : shown.positions) {
    mn = mn.cwiseMin(p.translation());
    mx = mx.cwiseMax(p.translation());
  }
  (void)lo;
  const V2 mid = 0.5 * (mn + mx);
  const double half = 0.5 * (mx - mn).maxCoeff() + 2.0;
  render::Plot plot;
  plot.title = "Centre-point curves of positions {1,2,3,4} and {1,2,3,5}: Burmester points";
  plot.equalAspect = true;
  plot.x.label = "x";
  plot.y.label = "y";
  plot.x.min = mid(0) - half;
  plot.x.max = mid(0) + half;
  plot.y.min = mid(1) - half;
  plot.y.max = mid(1) + half;
  const auto k1 = sampleCurve(bs.centrePointCurve(4), mid(0) - half, mid(0) + half, mid(1) - half, mid(1) + half, 500);
  const auto k2 = sampleCurve(bs.centrePointCurve(5), mid(0) - half, mid(0) + half, mid(1) - half, mid(1) + half, 500);
  addPoints(plot, "centre-point curve {1,2,3,4}", k1, render::palette::blue, 1.5);
  addPoints(plot, "centre-point curve {1,2,3,5}", k2, render::palette::orange, 1.5);
  addPoints(plot, "poles P12, P13, P23 (spurious)", {bs.pole(1, 2), bs.pole(1, 3), bs.pole(2, 3)}, render::palette::grey, 8);
  std::vector<V2> centres;
  for (const auto& p : pairs) centres.push_back(p.centre);
  addPoints(plot, "Burmester centre points", centres, render::palette::vermillion, 10);
  std::vector<V2> traj;
  for (const auto& p : shown.positions) traj.push_back(p.translation());
  addPoints(plot, "prescribed positions (origin of the moving frame)", traj, render::palette::black, 6);
  render::renderPlotPngAndSvg(plot, c.figurePath("GF-5.3.5-centre-point-curves.png"), 1100, 1100);
  c.figure("GF-5.3.5-centre-point-curves.png",
           "Five positions from a random crank-rocker: the centre-point curves of {1,2,3,4} and {1,2,3,5} meet at the poles "
           "P12, P13, P23 (spurious, grey), at the circular points at infinity, and at " + std::to_string(pairs.size()) +
               " real Burmester centre points (red); two of them are the original ground pivots.");
  // Figure 2: the synthesized 4-bar in its five positions. Of the pairs of real Burmester pairs that
  // form a working linkage (every position reached on one circuit), the most compact one is drawn:
  // the smallest distance of its pivots, in every position, from the positions' centroid (the first
  // working pair found could reach 80 units away from positions 2 units apart, and hid them).
  V2 centroid = V2::Zero();
  for (const auto& p : shown.positions) centroid += p.translation() / double(shown.positions.size());
  auto extent = [&](const auto& pa, const auto& pb) {
    double e = std::max((pa.centre - centroid).norm(), (pb.centre - centroid).norm());
    for (const auto& M : shown.positions)
      e = std::max({e, (M.act(pa.circle) - centroid).norm(), (M.act(pb.circle) - centroid).norm()});
    return e;
  };
  int ia = -1, ib = -1;
  double best = std::numeric_limits<double>::infinity();
  DriveCheck<double> dc;  // the drawn linkage's drive
  for (int a = 0; a < int(pairs.size()); ++a)
    for (int b = 0; b < int(pairs.size()); ++b) {
      if (a == b) continue;
      const double e = extent(pairs[a], pairs[b]);
      if (!(e < best)) continue;  // only a more compact linkage is driven
      DriveCheck<double> d = bs.drive(pairs[a], pairs[b]);
      if (d.reached && d.sameCircuit && d.worstTranslation < 1e-9) {
        best = e;
        ia = a;
        ib = b;
        dc = std::move(d);
      }
    }
  if (ia < 0) return;
  const FourBar<double> fb = bs.fourBar(pairs[ia], pairs[ib]);
  render::Plot p2;
  p2.title = "Synthesized 4-bar in its five prescribed positions";
  p2.equalAspect = true;
  p2.x.label = "x";
  p2.y.label = "y";
  std::vector<double> xs, ys;
  for (const auto& p : fb.traceCircuit(dc.circuits.at(0), 720)) {
    const V2 q = fb.couplerPointWorld(p);
    xs.push_back(q(0));
    ys.push_back(q(1));
  }
  p2.add("coupler curve", xs, ys, render::palette::blue).closed = true;
  for (int i = 0; i < 5; ++i) {
    const SE2<double>& M = bs.positions()[i];
    const V2 a2 = M.act(pairs[ia].circle), b3 = M.act(pairs[ib].circle), o = M.translation();
    auto& link = p2.add(i == 0 ? "linkage at each position" : "", {pairs[ia].centre(0), a2(0), b3(0), pairs[ib].centre(0)},
                        {pairs[ia].centre(1), a2(1), b3(1), pairs[ib].centre(1)}, render::palette::cycle(i));
    link.markers = true;
    p2.add("", {a2(0), o(0), b3(0)}, {a2(1), o(1), b3(1)}, render::palette::cycle(i).lighter(0.3f));
    // the prescribed frame: a short arrow along its x axis
    const V2 e = M.rotation().col(0) * 0.5;
    auto& ar = p2.add("", {o(0), o(0) + e(0)}, {o(1), o(1) + e(1)}, render::palette::black);
    ar.width = 4;
    p2.texts.push_back({o(0), o(1), std::to_string(i + 1)});
  }
  addPoints(p2, "ground pivots", {pairs[ia].centre, pairs[ib].centre}, render::palette::vermillion, 9);
  render::renderPlotPngAndSvg(p2, c.figurePath("GF-5.3.5-synthesized-fourbar.png"), 1100, 1000);
  c.figure("GF-5.3.5-synthesized-fourbar.png",
           "The most compact 4-bar built from two real Burmester pairs of the five positions (its pivots nearest "
           "the positions' centroid), drawn at each prescribed position (colours "
           "1–5; black ticks: the prescribed frames' x axes) on its coupler curve; pose error " +
               toString(dc.worstTranslation, 2) + " (relative).");
}

}  // namespace

template <class S> void finitePositionSynthesis(Context& c) {
  std::mt19937_64 g(20261130);
  const int trials = 100;
  int success = 0, recovered = 0;
  S worstT(0), worstA(0), worstRes(0), worstComplex(0), worstAlgebraic(0);
  int hist[5] = {0, 0, 0, 0, 0};
  // Thresholds: the residuals after Newton (relative) at 4096 ε; the two-conic intersection before
  // Newton at 4096 ε too (it runs in S, in float in double: see burmesterPairs); the pivots matched
  // within √ε; a round trip succeeds when the rebuilt 4-bar reproduces the five poses to 4096 ε
  // (9.1e-13 in double, where 1e-9 was used before).
  const S match = Tolerance<S>::sqrtEpsilon(), drive = tol<S>(4096);
  for (int t = 0; t < trials; ++t) {
    const Trial<S> tr = randomTrial<S>(g);
    const BurmesterSynthesis<S> bs(tr.positions);
    int cc = 0;
    S cres(1), alg(1);
    const auto pairs = bs.burmesterPairs(&cc, &cres, &alg);
    worstComplex = maxOf(worstComplex, cres);
    worstAlgebraic = maxOf(worstAlgebraic, alg);
    if (int(pairs.size()) + cc == 4) ++hist[pairs.size()];
    int ia = -1, ib = -1;
    for (int k = 0; k < int(pairs.size()); ++k) {
      worstRes = maxOf(worstRes, pairs[k].residual);
      if ((pairs[k].centre - tr.c1).norm() < match && (pairs[k].circle - tr.z2).norm() < match) ia = k;
      if ((pairs[k].centre - tr.c4).norm() < match && (pairs[k].circle - tr.z3).norm() < match) ib = k;
    }
    if (ia < 0 || ib < 0) continue;
    ++recovered;
    const DriveCheck<S> dc = bs.drive(pairs[ia], pairs[ib]);
    worstT = maxOf(worstT, dc.worstTranslation);
    worstA = maxOf(worstA, dc.worstAngle);
    if (dc.reached && dc.sameCircuit && dc.worstTranslation < drive && dc.worstAngle < drive) ++success;
  }
  c.checkEqual("finite positions: real + complex Burmester pairs = 4 in every trial (of 100)", trials, hist[0] + hist[2] + hist[4]);
  c.checkResidual("… the non-real solutions are genuine: worst relative residual after complex Newton (4096 ε)", worstComplex, tol<S>(4096));
  c.checkResidual("… two-conic intersection alone (no spurious poles or circular points): worst relative residual before Newton (4096 ε)",
                  worstAlgebraic, tol<S>(4096));
  c.checkEqual("round trips: original pivots recovered among the Burmester pairs (of 100 random crank-rockers; within √ε)", trials, recovered);
  c.checkEqual("round trips: rebuilt 4-bar passes through all 5 positions on one circuit (success count; 4096 ε)", trials, success);
  c.checkResidual("worst translation error when driving through the positions (relative to the data scale; 4096 ε)", worstT, drive);
  c.checkResidual("worst angle error (rad; 4096 ε)", worstA, drive);
  c.checkResidual("worst bilinear residual of a Burmester pair (relative; 4096 ε)", worstRes, tol<S>(4096));
  c.note("Finite-position synthesis (beyond the book): 100 random crank-rockers (seed 20261130), five coupler poses each; "
         "real Burmester pair counts 0/2/4: " + std::to_string(hist[0]) + "/" + std::to_string(hist[2]) + "/" +
         std::to_string(hist[4]) + "; worst pair residual " + toString(toDouble(worstRes), 3) + " (relative to max(scale, |z|, |m − centroid|)²)" +
         "; success " + std::to_string(success) + "/" + std::to_string(trials) +
         "; worst pose error " + toString(toDouble(worstT), 3) + " (translation, relative), " + toString(toDouble(worstA), 3) + " rad.");
  if (c.makeFigures()) synthesisFigures(c);
}

#define SOMA_GF05_FINITE_POSITIONS(S) template void finitePositionSynthesis<S>(Context&);
SOMA_FOR_EACH_SCALAR(SOMA_GF05_FINITE_POSITIONS)
#undef SOMA_GF05_FINITE_POSITIONS

}  // namespace soma::studies::gf05p
