// Studies of GF §11.5.2 and §11.5.4: the forward kinematics of Stewart–Gough platforms counted
// numerically — 40 complex postures of a general 6-6 platform, 16 of a 6-3 platform — by the
// homotopy solver of geometry/parallel/stewart.hpp, and the real postures of one platform drawn;
// SOMA-11.5.4-stewart-speed-accuracy: every method × the five scalars on random platforms.
// GF-11.5.4-stewart-forty, GF-11.5.2-6-3-stewart-sixteen and GF-11-fig-11.2 run in the asked scalar
// (draws in double cast to S, gf11/common.hpp); their figures are drawn from the postures cast to double.
#include "gf11/common.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/stewart_numeric.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/study.hpp"
#include "platform_plate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace soma::studies::gf11::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;  // the speed/accuracy study's cases (drawn and kept in double)
namespace rd = soma::render;

/// A random general platform (joints not coplanar) and the posture that defines its leg lengths, in
/// W: joints and twist drawn in double and cast to W, the posture and leg lengths computed in W.
template <class W> StewartPlatform<W> randomPlatform(std::mt19937_64& g, SE3<W>* pose) {
  StewartPlatform<W> P;
  for (int i = 0; i < 6; ++i) {
    const W bx = uni<W>(g, -1, 1), by = uni<W>(g, -1, 1), bz = uni<W>(g, -0.2, 0.2);
    const W qx = uni<W>(g, -0.6, 0.6), qy = uni<W>(g, -0.6, 0.6), qz = uni<W>(g, -0.1, 0.1);
    P.base[i] = Vec3<W>(bx, by, bz);
    P.platform[i] = Vec3<W>(qx, qy, qz);
  }
  Vec6<W> xi;
  for (int k = 0; k < 6; ++k) xi(k) = k < 3 ? uni<W>(g, -0.3, 0.3) : k < 5 ? uni<W>(g, -0.2, 0.2) : uni<W>(g, 0.8, 1.2);
  *pose = SE3Tangent<W>(xi).exp();
  P.legs = stewartLegLengths<W>(P, *pose);
  return P;
}

/// Non-real solutions whose conjugate is not in the set (0 for a real platform).
template <class W> int unpairedConjugates(const StewartForwardSolution<W>& s) {
  int n = 0;
  for (const auto& x : s.complex_solutions) {
    W im = W(0);
    using std::abs;
    for (const auto& z : x) im = std::max<W>(im, W(abs(z.imag())));
    if (im > Tolerance<W>::input() && !containsConjugate<W>(s.complex_solutions, x, Tolerance<W>::input())) ++n;
  }
  return n;
}

/// The platform of studies/platforms/general.json (irregular hexagons, joints off a plane), its
/// decimals parsed in W.
template <class W> StewartPlatform<W> examplePlatform() {
  StewartPlatform<W> P;
  const char* b[6][3] = {{"0.854648", "0.248159", "0.002365"},   {"0.806715", "0.596192", "-0.055343"},
                         {"-0.668405", "0.732368", "0.056675"},  {"-0.954569", "0.316566", "0.053623"},
                         {"-0.19489", "-0.936848", "-0.052013"}, {"0.304459", "-1.079584", "0.063352"}};
  const char* q[6][3] = {{"0.48443", "0.136726", "0.018518"},    {"-0.142747", "0.423322", "-0.024849"},
                         {"-0.24425", "0.452013", "0.030514"},   {"-0.241091", "-0.381148", "-0.042368"},
                         {"-0.196986", "-0.460494", "-0.020788"}, {"0.485676", "-0.026128", "0.020398"}};
  const char* L[6] = {"1.042060141", "1.415693982", "1.051051562", "1.443082953", "0.974698497", "1.427782454"};
  for (int i = 0; i < 6; ++i) {
    P.base[i] = Vec3<W>(fromString<W>(b[i][0]), fromString<W>(b[i][1]), fromString<W>(b[i][2]));
    P.platform[i] = Vec3<W>(fromString<W>(q[i][0]), fromString<W>(q[i][1]), fromString<W>(q[i][2]));
    P.legs[i] = fromString<W>(L[i]);
  }
  return P;
}

/// The real postures of P drawn side by side: base (grey), legs (blue), platform (orange); the
/// geometry cast to double for soma::render.
template <class W>
void postureGrid(Context& c, const StewartPlatform<W>& PW, const StewartForwardSolution<W>& s, const std::string& file) {
  const StewartPlatform<double> P = PW.template cast<double>();
  rd::Scene scene;
  scene.title = fmt::format("The {} real postures of one general 6-6 platform (of 40 complex solutions) for the same six leg lengths",
                            s.count());
  const int cols = 4;
  const double dx = 3.0, dz = 2.9;
  for (std::size_t k = 0; k < s.count(); ++k) {
    const Eigen::Vector3d o(dx * double(k % cols), 0.0, -dz * double(k / cols));
    const SE3<double> pk = s.postures[k].template cast<double>();
    std::vector<Eigen::Vector3d> base, top;
    for (int i = 0; i < 6; ++i) {
      base.push_back(P.base[i] + o);
      top.push_back(pk.act(P.platform[i]) + o);
    }
    gf11::addPlate(scene, base, rd::palette::darkGrey, 0.025);
    gf11::addPlate(scene, top, rd::palette::orange, 0.03, rd::palette::orange.withAlpha(0.45f));
    for (int i = 0; i < 6; ++i) {
      rd::Tube leg;
      leg.p = {base[i], top[i]};
      leg.radius = 0.018;
      leg.c = rd::palette::blue;
      scene.add(leg);
    }
    scene.add(rd::Points{base, rd::palette::darkGrey, 0.04});
    scene.add(rd::Points{top, rd::palette::vermillion, 0.04});
    rd::Label l;
    l.at = o + Eigen::Vector3d(0, 0, -1.2);
    l.text = fmt::format("{}: residual {:.1e}", k + 1, toDouble(s.residuals[k]));
    l.hAlign = rd::HAlign::Center;
    l.vAlign = rd::VAlign::Top;
    l.pixelHeight = 20;
    scene.add(l);
  }
  const int w = 1500, h = 1050;
  rd::FitOptions fo;
  fo.width = w;
  fo.height = h;
  fo.orthographic = true;
  rd::renderPng(scene, Eigen::Vector3d(0.0, 1.0, -0.3), fo, c.figurePath(file));
  c.figure(file, fmt::format("GF Fig. 11.1 for a real platform: the {} real assembly modes of one general 6-6 "
                             "Stewart platform (studies/platforms/general.json) for the same six leg lengths, "
                             "found with the other {} complex solutions by homotopy continuation; each posture's "
                             "largest leg-length error relative to the platform size is printed under it.",
                             s.count(), s.complexCount() - static_cast<int>(s.count())));
}

/// Distance (|ΔT|, 4×4) from g to the nearest real posture, in W (+∞ when there is none).
template <class W> W nearestIn(const StewartForwardSolution<W>& s, const SE3<W>& g) {
  W best = std::numeric_limits<W>::infinity();
  for (const auto& h : s.postures) {
    const W d = (h.matrix() - g.matrix()).norm();
    if (d < best) best = d;
  }
  return best;
}

/// float128 and mpfr solve in software (1.6 s and 12 s a platform: SOMA-11.5.4-stewart-speed-accuracy):
/// the random samples are smaller there, their size said in the check's name.
template <class W> inline constexpr bool kSlowScalar = std::is_same_v<W, float128> || std::is_same_v<W, mpreal>;

// GF §11.5.4, GF-11.5.4-stewart-forty, in the asked scalar W.
template <class W> void stewartForty(Context& c) {
  // The start system: a random complex platform solved by the total-degree homotopy (128 paths).
  // stewartTotalDegreeSolve exists in double only (it computes the start solutions, which
  // stewartStartSolutions<W> polishes in W): this part is the same in every scalar.
  const auto start = stewartStartPlatform<double>();
  const auto a = stewartTotalDegreeSolve(start, 1);
  const auto b = stewartTotalDegreeSolve(start, 9);
  c.checkEqual("random complex platform: finite solutions by a 2⁷ = 128-path total-degree homotopy (double)", 40,
               static_cast<long long>(a.size()));
  int same = 0;
  for (const auto& x : b) {
    for (const auto& y : a) {
      double d = 0;
      for (int k = 0; k < 8; ++k) d = std::max(d, std::abs(x[k] - y[k]));
      if (d <= Tolerance<double>::input()) {
        ++same;
        break;
      }
    }
  }
  c.checkEqual("… the same 40 points from another set of gammas (double)", 40, same);
  // The Study quadric's leg form (study/constraint_quadrics.hpp) and the solver's agree.
  {
    std::mt19937_64 g(1154);
    SE3<W> pose;
    const auto P = randomPlatform<W>(g, &pose);
    const Vec8<W> v = StudyParameters<W>::fromSE3(pose).coeffs();
    StudyPointC<W> x;
    Vec8<W> w = v;
    w(5) += frac<W>(1, 10);  // off the variety: both forms must agree there too
    for (int k = 0; k < 8; ++k) x[k] = w(k);
    const auto f = stewartSystem<W>(stewartComplexPlatform<W>(P), x);
    W worst = W(0);
    for (int i = 0; i < 6; ++i) {
      const Mat8<W> Q = sphereConstraintQuadric<W>(P.base[i], P.platform[i], P.legs[i]);
      using std::abs;
      worst = std::max<W>(worst, W(abs(W(f[i + 1].real() - w.dot(Q * w)))));
    }
    // two evaluations of one quadratic form of unit-scale entries (|w| ≈ 1): 256 ε (5.7e-14 in double)
    c.checkResidual("leg equation u·u − L²a·a = xᵀQx of the S–S sphere quadric (off the variety; 256 ε)", worst,
                    Tolerance<W>::identity(256));
  }
  // Random real general platforms.
  std::mt19937_64 g(2026);
  const int n = kSlowScalar<W> ? 2 : 20;
  int forty = 0, found = 0, evenReal = 0, unpaired = 0;
  W worstRes = W(0), worstPose = W(0);
  for (int t = 0; t < n; ++t) {
    SE3<W> pose;
    const auto P = randomPlatform<W>(g, &pose);
    const auto s = solveStewartForward<W>(P);
    forty += s.complexCount() == 40;
    found += nearestIn(s, pose) <= Tolerance<W>::sqrtEpsilon();
    evenReal += s.count() % 2 == 0;
    unpaired += unpairedConjugates(s);
    worstRes = std::max<W>(worstRes, s.worstResidual());
    worstPose = std::max<W>(worstPose, nearestIn(s, pose));
  }
  c.checkEqual(fmt::format("random real 6-6 platforms with 40 complex solutions (of {})", n), n, forty);
  c.checkEqual("… the posture that defined the leg lengths is among the real ones", n, found);
  // The posture is the solver's root polished in W: its distance from the defining posture is the
  // root's conditioning times ε; 2¹⁴ ε (3.6e-12 in double, as before).
  c.checkResidual("… distance of that posture (|ΔT|, 4×4) at worst (2¹⁴ ε)", worstPose, Tolerance<W>::identity(1u << 14));
  c.checkResidual("… worst leg-length residual / platform size over all real postures (64 ε)", worstRes,
                  Tolerance<W>::identity(64));
  c.checkEqual("… platforms with an even number of real postures", n, evenReal);
  c.checkEqual("… non-real solutions without their conjugate", 0, unpaired);
  // Extreme: base and platform planar. Still 40; real postures come in mirror pairs M g M.
  {
    std::mt19937_64 g2(41);
    SE3<W> pose;
    auto P = randomPlatform<W>(g2, &pose);
    for (int i = 0; i < 6; ++i) P.base[i](2) = P.platform[i](2) = W(0);
    P.legs = stewartLegLengths<W>(P, pose);
    const auto s = solveStewartForward<W>(P);
    c.checkEqual("planar base and planar platform: complex solutions", 40, s.complexCount());
    const Mat3<W> Mz = Vec3<W>(1, 1, -1).asDiagonal();
    W worst = W(0);
    for (const auto& h : s.postures) {
      Mat4<W> m = Mat4<W>::Identity();
      m.template topLeftCorner<3, 3>() = Mz * h.rotation() * Mz;
      m.template topRightCorner<3, 1>() = Mz * h.translation();
      W best = std::numeric_limits<W>::infinity();
      for (const auto& k : s.postures) best = std::min<W>(best, W((k.matrix() - m).norm()));
      worst = std::max<W>(worst, best);
    }
    c.checkResidual(fmt::format("… its {} real postures pair up under the mirror in the base plane (2¹⁴ ε)", s.count()), worst,
                    Tolerance<W>::identity(1u << 14));
  }
  // The example platform, drawn.
  const auto P = examplePlatform<W>();
  const auto s = solveStewartForward<W>(P);
  c.checkEqual("example platform (studies/platforms/general.json): complex solutions", 40, s.complexCount());
  // Regression value (soma's own earlier output); its independent source is PHCpack, which finds the
  // same real postures of general.json in SOMA-11.5-phcpack-counts.
  c.checkEqual("… real postures (regression value; PHCpack agrees in GF-11-fig-11.1)", 8,
               static_cast<long long>(s.count()));
  if (c.makeFigures() && s.count() > 0) postureGrid(c, P, s, "GF-11.5.4-stewart-postures.png");
}

// GF §11.5.2, GF-11.5.2-6-3-stewart-sixteen, in the asked scalar W: the platforms are drawn in
// double, converted exactly, and their leg lengths recomputed in W from the defining posture.
template <class W> void sixThree(Context& c) {
  std::mt19937_64 g(63);
  const int n = 5;
  int sixteen = 0, found = 0, failed = 0, singular = 0, expected = 0, escalated = 0;
  for (int t = 0; t < n; ++t) {
    SE3<S> pose;
    auto P = randomPlatform(g, &pose);
    const std::array<Vec3<S>, 3> t3{P.platform[0], P.platform[2], P.platform[4]};
    for (int i = 0; i < 6; ++i) P.platform[i] = t3[((i + 1) / 2) % 3];
    StewartPlatform<W> Q = P.template cast<W>();
    const SE3<W> poseW = pose.template cast<W>();
    Q.legs = stewartLegLengths<W>(Q, poseW);
    const auto s = solveStewartForward<W>(Q);
    sixteen += s.complexCount() == 16;
    expected += s.expected_count == 16;
    found += nearestIn(s, poseW) <= Tolerance<W>::sqrtEpsilon();
    failed += s.paths_failed;
    singular += 40 - s.complexCount() - s.paths_at_infinity;
    escalated += s.paths_escalated;  // float: paths that failed there, re-solved in double (a note says so)
  }
  c.note(fmt::format("{} paths of the {} platforms failed in {} and were re-solved in a wider scalar.", escalated, n,
                     scalarName<W>()));
  c.checkEqual(fmt::format("random 6-3 platforms with 16 finite nonsingular solutions (of {}), (2σ₄)³ = 16", n), n,
               sixteen);
  c.checkEqual("… recognised as 6-3 (expected_count 16)", n, expected);
  c.checkEqual("… the defining posture found", n, found);
  c.checkEqual("… paths that failed in tracking", 0, failed);
  c.checkEqual("… paths of the 40 that end at singular points of the degenerate system", 24 * n, singular);
}

// ---- SOMA-11.5.4-stewart-speed-accuracy ---------------------------------------------------------
struct Case {
  StewartPlatform<S> P;
  SE3<S> pose;
};

/// The case in T, its leg lengths recomputed in T from the defining posture (so that posture is a
/// solution to the precision of T, not only of double).
template <class T> StewartPlatform<T> castPlatform(const Case& k) {
  StewartPlatform<T> Q = k.P.template cast<T>();
  Q.legs = stewartLegLengths<T>(Q, k.pose.template cast<T>());
  return Q;
}

struct TradeRow {
  std::string method, scalar;
  std::size_t platforms = 0;
  double median = 0, p95 = 0, worst = 0, completeness = 0;
  std::size_t retracked = 0;
  std::string worstText;  ///< the worst residual in T's digits
};

double quantile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
}

/// Distance of two postures: max entry of the 4×4 difference, translations over the platform size.
template <class T> double poseDistance(const SE3<T>& a, const SE3<double>& b, double size) {
  Mat4<double> m = (a.template cast<double>().matrix() - b.matrix()).cwiseAbs();
  m.topRightCorner<3, 1>() /= size;
  return m.maxCoeff();
}

/// The homotopy in T on the first n cases: 40 complex solutions found, the defining posture among the
/// real ones (its completeness against the ground truth), the worst residual in T.
template <class T>
TradeRow homotopyRow(const std::vector<Case>& cases, std::size_t n, std::size_t& short40,
                     std::vector<std::vector<SE3<S>>>* keep) {
  TradeRow row;
  row.method = "homotopy";
  row.scalar = std::string(scalarName<T>());
  if constexpr (std::is_same_v<T, mpfr::mpreal>) row.scalar += " (" + std::to_string(mpfrBits()) + " bits)";
  T worst = 0;
  std::vector<double> times;
  std::size_t found = 0;
  const double match = std::max(toDouble(Tolerance<T>::precision(2)), toDouble(Tolerance<S>::precision(2)));
  for (std::size_t k = 0; k < n; ++k) {
    const auto P = castPlatform<T>(cases[k]);
    const auto sol = solveStewartForward<T>(P);
    times.push_back(sol.seconds);
    short40 += sol.complexCount() != 40;
    row.retracked += sol.paths_tracked > 40;
    const double size = toDouble(stewartScale<T>(P));
    bool hit = false;
    for (std::size_t j = 0; j < sol.count(); ++j) {
      hit = hit || poseDistance(sol.postures[j], cases[k].pose, size) < match;
      if (sol.residuals[j] > worst) worst = sol.residuals[j];
    }
    found += hit;
    if (keep) {
      keep->emplace_back();
      for (const auto& g : sol.postures) keep->back().push_back(g.template cast<S>());
    }
  }
  row.platforms = n;
  row.median = quantile(times, 0.5);
  row.p95 = quantile(times, 0.95);
  row.completeness = double(found) / double(n);
  row.worst = toDouble(worst);
  row.worstText = io::numberText(worst);
  return row;
}

/// A multi-start method (double) on the first n cases: the fraction of the homotopy's real
/// postures it found, and the postures it returned that the homotopy did not (`outside`).
template <class F>
TradeRow numericRow(const std::string& name, const std::vector<Case>& cases, std::size_t n,
                    const std::vector<std::vector<SE3<S>>>& ref, std::size_t& outside, F&& solve) {
  TradeRow row;
  row.method = name;
  row.scalar = "double";
  std::vector<double> times;
  std::size_t refTotal = 0, refFound = 0;
  const double same = Tolerance<S>::precision(2);
  for (std::size_t k = 0; k < n; ++k) {
    const auto sol = solve(cases[k].P);
    times.push_back(sol.seconds);
    const double size = stewartScale<S>(cases[k].P);
    for (std::size_t j = 0; j < sol.count(); ++j) {
      row.worst = std::max(row.worst, sol.residuals[j]);
      bool known = false;
      for (const auto& a : ref[k]) known = known || poseDistance(sol.postures[j], a, size) < same;
      outside += !known;
    }
    for (const auto& a : ref[k]) {
      ++refTotal;
      bool hit = false;
      for (const auto& b : sol.postures) hit = hit || poseDistance(b, a, size) < same;
      refFound += hit;
    }
  }
  row.platforms = n;
  row.median = quantile(times, 0.5);
  row.p95 = quantile(times, 0.95);
  row.completeness = refTotal ? double(refFound) / double(refTotal) : 1.0;
  return row;
}

// GF §11.5.4 (40 postures); SOMA-11.5.4-stewart-speed-accuracy
void speedAccuracy(Context& c) {
  const std::size_t nDouble = 1000, nFloat = 200, nLong = 50, nQuad = 3, nMpfr = 1, nNum = 100;
  std::mt19937_64 g(20261130);
  std::vector<Case> cases(nDouble);
  for (auto& k : cases) k.P = randomPlatform(g, &k.pose);
  (void)stewartStartSolutions<S>();  // once per process: not part of any platform's time
  std::vector<TradeRow> rows;
  std::vector<std::vector<SE3<S>>> ref;
  std::array<std::size_t, 5> short40{};
  rows.push_back(homotopyRow<S>(cases, nDouble, short40[0], &ref));
  rows.push_back(homotopyRow<float>(cases, nFloat, short40[1], nullptr));
  rows.push_back(homotopyRow<long double>(cases, nLong, short40[2], nullptr));
  rows.push_back(homotopyRow<__float128>(cases, nQuad, short40[3], nullptr));
  rows.push_back(homotopyRow<mpfr::mpreal>(cases, nMpfr, short40[4], nullptr));
  std::size_t outCeres = 0, outNlopt = 0;
  const StewartNumericOptions no;
  rows.push_back(numericRow(fmt::format("ceres ({} starts)", no.starts), cases, nNum, ref, outCeres,
                            [&](const StewartPlatform<S>& P) { return solveStewartForwardCeres(P, no); }));
  rows.push_back(numericRow(fmt::format("nlopt ({} starts)", no.starts), cases, nNum, ref, outNlopt,
                            [&](const StewartPlatform<S>& P) { return solveStewartForwardNlopt(P, no); }));

  const std::array<double, 5> floorOf{toDouble(Tolerance<S>::identity()), toDouble(Tolerance<float>::identity()),
                                      toDouble(Tolerance<long double>::identity()),
                                      toDouble(Tolerance<__float128>::identity()),
                                      toDouble(Tolerance<mpfr::mpreal>::identity())};
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& r = rows[i];
    c.checkEqual(fmt::format("homotopy {}: platforms short of 40 complex solutions (of {})", r.scalar, r.platforms), 0,
                 static_cast<long long>(short40[i]));
    c.checkEqual(fmt::format("homotopy {}: defining posture found (of {} platforms)", r.scalar, r.platforms),
                 static_cast<long long>(r.platforms), std::llround(r.completeness * double(r.platforms)));
    // Float: the polish runs in float, but the start solutions and escalations in wider scalars.
    c.checkResidual(fmt::format("homotopy {}: worst leg residual / platform size", r.scalar), r.worst, 64 * floorOf[i]);
  }
  // A real posture the homotopy did not return would falsify its completeness.
  c.checkEqual("ceres postures outside the homotopy's real set", 0, static_cast<long long>(outCeres));
  c.checkEqual("nlopt postures outside the homotopy's real set", 0, static_cast<long long>(outNlopt));
  c.checkResidual("ceres: worst residual", rows[5].worst, Tolerance<S>::identity(64));
  c.checkResidual("nlopt: worst residual", rows[6].worst, Tolerance<S>::identity(64));

  std::string table = "method | scalar | platforms | median ms | p95 ms | worst residual | completeness | re-tracked\n";
  for (const auto& r : rows)
    table += fmt::format("{} | {} | {} | {:.2f} | {:.2f} | {:.2e} | {:.4f} | {}\n", r.method, r.scalar, r.platforms,
                         1e3 * r.median, 1e3 * r.p95, r.worst, r.completeness, r.retracked);
  c.note(table);
  c.note(fmt::format(
      "Completeness: for the homotopy rows, the fraction of platforms whose defining posture (random posture → "
      "leg lengths) is among the real answers; for ceres/nlopt, the fraction of the homotopy's real postures "
      "(double) they found on the first {} platforms. Fewer platforms in float ({}), long double ({}), float128 "
      "({}) and mpfr ({}) to keep the report short. 're-tracked' counts platforms where some path was tracked "
      "again (smaller step, another gamma or a wider scalar). Times are wall seconds on a shared machine "
      "(papers/benchmarks/stewart.md has quiet runs).",
      nNum, nFloat, nLong, nQuad, nMpfr));

  // The trade table (the report's "speed vs accuracy"): the homotopy on every rung. Its
  // escalation is the re-track of a path (finer step, another γ, or the path in a wider scalar);
  // the start solutions are computed once per process in double and polished in each rung.
  TradeTable t;
  t.solver = "Stewart–Gough forward kinematics, homotopy (GF §11.5.4)";
  t.sample = "platform";
  t.errorLabel = "worst leg residual / size";
  for (std::size_t i : {std::size_t(1), std::size_t(0), std::size_t(2), std::size_t(3), std::size_t(4)}) {
    const auto& r = rows[i];
    TradeRung g;
    g.scalar = r.scalar;
    g.samples = r.platforms;
    g.medianSeconds = r.median;
    g.p95Seconds = r.p95;
    g.worstError = r.worst;
    g.worstErrorText = r.worstText;
    g.escalated = r.retracked;
    if (r.retracked) g.escalatedTo = "a re-track: finer step, another γ or a wider scalar";
    g.comment = fmt::format("defining posture found in {} of {}; {} short of 40", std::llround(r.completeness * double(r.platforms)),
                            r.platforms, short40[i]);
    t.rungs.push_back(std::move(g));
  }
  c.trade(std::move(t), "SOMA-11.5.4-stewart-speed-accuracy.png",
          "Stewart–Gough forward kinematics by the homotopy: median time per platform (point; bar to the p95) "
          "against the worst leg residual over the platform size, one point per scalar (log–log).");
}

// GF §11.5.2, GF-11-fig-11.2: in a 6-3 platform two legs share a platform joint; with their base
// joints they form a rigid triangle that can only turn about the line through the two base
// joints — a revolute joint there and a spherical joint at the apex (an R–S pair). The apex
// therefore lies on a circle about that axis, of radius the triangle's height.
template <class W> void triangleFigure(Context& c) {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  std::mt19937_64 g(112);
  SE3<W> pose;
  auto P = randomPlatform<W>(g, &pose);
  const std::array<Vec3<W>, 3> t3{P.platform[0], P.platform[2], P.platform[4]};
  for (int i = 0; i < 6; ++i) P.platform[i] = t3[((i + 1) / 2) % 3];  // as in sixThree: legs (1, 2) share a joint
  P.legs = stewartLegLengths<W>(P, pose);
  const Vec3<W> p1 = P.base[1], p2 = P.base[2], apex = pose.act(P.platform[1]);
  const W L1 = P.legs[1], L2 = P.legs[2], d = (p2 - p1).norm();
  const Vec3<W> u = (p2 - p1) / d;
  const Vec3<W> foot = p1 + u * W(u.dot(apex - p1));
  const W r = (apex - foot).norm();
  // Heron: the height of the triangle (L1, L2, d) over the side d.
  const W sp = (L1 + L2 + d) / W(2);
  const W height = W(2) * sqrt(W(sp * (sp - L1) * (sp - L2) * (sp - d))) / d;
  // The foot, the radius and Heron's product each carry a few roundings of lengths ≤ L1 + L2 + d: 64 ε.
  c.checkResidual("radius of the apex circle = height of the leg triangle over the base side (Heron; 64 ε·(L1 + L2 + d))",
                  W(abs(W(r - height))), W(Tolerance<W>::identity(64) * (L1 + L2 + d)));
  // Independently of the construction: every real posture the forward solver finds for this 6-3
  // platform (it knows nothing of the triangle) puts the shared joint on that circle — in the plane
  // through the foot normal to the axis, at the distance `height` from the axis. Bound: the solver's
  // leg residual (≤ 64 ε · size, checked in GF-11.5.4) over the sine of the triangle's angle at the
  // apex, times the 2 legs; measured: papers/checks.md.
  {
    const auto sol = solveStewartForward<W>(P);
    W worstCircle(0);
    for (const auto& h : sol.postures) {
      const Vec3<W> a = h.act(P.platform[1]);
      const W along = u.dot(a - foot), radial = (a - p1 - u * W(u.dot(a - p1))).norm();
      worstCircle = std::max<W>({worstCircle, W(abs(along)), W(abs(W(radial - height)))});
    }
    const W sinApex = height * d / (L1 * L2);  // sin of the apex angle = 2·area/(L1 L2)
    c.checkResidual(fmt::format("the {} real postures of the forward solver put the shared joint on that circle "
                                "(≤ 2·64 ε·(L1 + L2)/sin(apex angle))", sol.count()),
                    worstCircle, W(Tolerance<W>::identity(128) * (L1 + L2) / sinApex));
  }
  // Turning the triangle about the axis keeps both leg lengths: the R–S pair.
  const Vec3<W> e1 = (apex - foot) / r, e2 = u.cross(e1);
  W worst = W(0);
  std::vector<Vec3<W>> circle;
  for (int k = 0; k < 72; ++k) {
    const W phi = W(2) * pi<W>() * W(k) / W(72);
    const Vec3<W> x = foot + r * (cos(phi) * e1 + sin(phi) * e2);
    worst = std::max<W>({worst, W(abs(W((x - p1).norm() - L1))), W(abs(W((x - p2).norm() - L2)))});
    circle.push_back(x);
  }
  c.checkResidual("every point of the circle keeps both leg lengths (72 angles; 64 ε·(L1 + L2))", worst,
                  W(Tolerance<W>::identity(64) * (L1 + L2)));
  // And the apex positions with both leg lengths are only that circle: a point off the axis plane
  // through the foot changes one length to first order (by √ε·cos, against the rounding of the two
  // lengths, ≤ 8 ε·L each: 64 ε·(L1 + L2) leaves a margin of 4; 1024 ε before, which float's √ε cannot clear).
  const Vec3<W> off = apex + Tolerance<W>::sqrtEpsilon() * u;
  c.checkEqual("moving the apex along the axis by √ε changes a leg length to first order (> 64 ε·(L1 + L2))", 1,
               W(abs(W((off - p1).norm() - L1)) + abs(W((off - p2).norm() - L2))) > Tolerance<W>::identity(64) * (L1 + L2)
                   ? 1
                   : 0);
  if (!c.makeFigures()) return;
  // The figure: the geometry cast to double for soma::render.
  const StewartPlatform<double> Pd = P.template cast<double>();
  const SE3<double> posed = pose.template cast<double>();
  std::array<Eigen::Vector3d, 3> t3d;
  for (std::size_t k = 0; k < 3; ++k) t3d[k] = castMatrix<double>(t3[k]);
  const Eigen::Vector3d p1d = castMatrix<double>(p1), p2d = castMatrix<double>(p2), apexd = castMatrix<double>(apex),
                        footd = castMatrix<double>(foot);
  std::vector<Eigen::Vector3d> circled;
  for (const auto& x : circle) circled.push_back(castMatrix<double>(x));
  rd::Scene scene;
  scene.title = "GF Fig. 11.2: two legs of a 6-3 platform meet at one platform joint: an R-S pair";
  std::vector<Eigen::Vector3d> base(Pd.base.begin(), Pd.base.end());
  rd::Tube bt;
  bt.p = base;
  bt.closed = true;
  bt.radius = 0.012;
  bt.c = rd::palette::darkGrey;
  scene.add(bt);
  std::vector<Eigen::Vector3d> tri;
  for (const auto& q : t3d) tri.push_back(posed.act(q));
  rd::Mesh plate;
  plate.v = tri;
  plate.tri.push_back(Eigen::Vector3i(0, 1, 2));
  plate.c = rd::palette::orange.withAlpha(0.35f);
  scene.add(plate);
  for (int i = 0; i < 6; ++i) {
    rd::Tube leg;
    leg.p = {base[i], posed.act(Pd.platform[i])};
    const bool pair = i == 1 || i == 2;
    leg.radius = pair ? 0.022 : 0.008;
    leg.c = pair ? rd::palette::blue : rd::palette::lightGrey;
    scene.add(leg);
  }
  rd::Tube axis;  // the equivalent revolute axis through the two base joints
  axis.p = {p1d - 0.35 * (p2d - p1d), p2d + 0.35 * (p2d - p1d)};
  axis.radius = 0.01;
  axis.c = rd::palette::vermillion;
  scene.add(axis);
  rd::Tube ring;  // where the apex can go: the circle about the axis
  ring.p = circled;
  ring.closed = true;
  ring.radius = 0.007;
  ring.c = rd::palette::orange;
  scene.add(ring);
  rd::Tube h;  // the triangle's height: the radius of that circle
  h.p = {footd, apexd};
  h.radius = 0.005;
  h.c = rd::palette::darkGrey;
  scene.add(h);
  scene.add(rd::Points{{p1d, p2d}, rd::palette::vermillion, 0.035});
  scene.add(rd::Points{{apexd}, rd::palette::blue, 0.045});
  const auto label = [&](const Eigen::Vector3d& at, const std::string& text) {
    rd::Label l;
    l.at = at;
    l.text = text;
    l.pixelHeight = 20;
    scene.add(l);
  };
  label(p1d + 0.7 * (p2d - p1d) + Eigen::Vector3d(0, 0, -0.12), "revolute axis");
  label(apexd + Eigen::Vector3d(0, 0, 0.08), "spherical joint (shared platform joint)");
  label(circled[36] + Eigen::Vector3d(0, 0, -0.08), "circle of the apex");
  const std::string f = "GF-11-fig-11.2.png";
  rd::renderPng(scene, Eigen::Vector3d(0.35, 1.0, -0.45), {1200, 900}, c.figurePath(f));
  c.figure(f, fmt::format("Two legs (blue) of a 6-3 platform share a platform joint; with the line through their "
                          "base joints (red) they form a rigid triangle that turns about that line: a revolute joint "
                          "and a spherical joint. The apex moves on the orange circle, of radius the triangle's "
                          "height {:.4f} (Heron).", toDouble(height)));
}

SOMA_STUDY_SCALAR("GF-11.5.4-stewart-forty",
                  "General 6-6 Stewart platform: 40 complex forward-kinematics solutions (homotopy), real postures drawn",
                  "GF §11.5.4", stewartForty);
SOMA_STUDY_SCALAR("GF-11.5.2-6-3-stewart-sixteen", "6-3 Stewart platform: 16 postures (the other 24 paths end singular)",
                  "GF §11.5.2", sixThree);
SOMA_STUDY_SCALAR("GF-11-fig-11.2", "Fig. 11.2: two legs of a 6-3 platform sharing a joint form an R-S pair", "GF §11.5.2",
                  triangleFigure);
SOMA_STUDY({.id = "SOMA-11.5.4-stewart-speed-accuracy",
            .title = "Stewart-Gough forward kinematics: every method × scalar, time, worst residual, completeness",
            .source = "GF §11.5.4",
            .chapter = "soma — Stewart platforms",
            .scalarGeneric = false,
            .run = speedAccuracy,
            .ladder = true});

}  // namespace
}  // namespace soma::studies::gf11::SOMA_UNITY_ID
