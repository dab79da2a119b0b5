// SOMA-burmester-speed-accuracy: five-position Burmester synthesis (GF §5.3, finite-position
// analogue of GF-5.3.5-burmester-count; BurmesterSynthesis::burmesterPairs) on every rung of the
// scalar ladder: the time per problem, the worst error of the real Burmester pairs (centre point m,
// circle point z) against an mpfr solution of the same problem at ≥ 512 bits, their residual in
// the defining equations evaluated in mpfr, the real-pair counts against the reference's, and the
// float rung's escalation (its conic intersection runs in double).
#include "soma/geometry/planar/burmester_synthesis.hpp"
#include "soma/studies/mpfr_bits.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using planar::BurmesterPair;
using planar::BurmesterSynthesis;
using planar::FourBar;
using planar::GrashofType;

/// Five positions, each (angle, tx, ty) with float-exact values: the same problem in every rung
/// (each rung's SE2 takes cos and sin of the angle in its own precision).
struct Problem {
  std::array<std::array<double, 3>, 5> pose;
};

/// Coupler poses of a random crank-rocker (as GF-5.3.5-burmester-count's round trips), rounded
/// to float: two of the four Burmester pairs are near the linkage's pivots, so real pairs exist.
std::vector<Problem> randomProblems(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Problem> out;
  while (out.size() < n) {
    const double l0 = 2 + 2 * u(g), l1 = 0.5 + 0.7 * u(g), l2 = 1.5 + 2 * u(g), l3 = 1.5 + 2 * u(g);
    const double ang = 6.283 * u(g);
    const Vec2<double> c1(2 * u(g) - 1, 2 * u(g) - 1), c4 = c1 + l0 * Vec2<double>(std::cos(ang), std::sin(ang));
    const Vec2<double> pc(2 * u(g) - 1, 1 + u(g));
    const FourBar<double> fb(c1, c4, l1, l2, l3, pc);
    if (fb.classify().type != GrashofType::CrankRocker) continue;
    const double t0 = 6.283 * u(g);
    const int mode = u(g) < 0.5 ? 1 : -1;
    const SE2<double> off(0.4, pc);
    Problem p;
    for (int i = 0; i < 5; ++i) {
      const SE2<double> m = fb.solve(t0 + 0.9 * i + 0.3 * u(g), mode)->coupler * off;
      p.pose[std::size_t(i)] = {double(float(m.angle())), double(float(m.translation()(0))),
                                double(float(m.translation()(1)))};
    }
    out.push_back(p);
  }
  return out;
}

template <class S> std::vector<SE2<S>> positionsIn(const Problem& p) {
  std::vector<SE2<S>> q;
  for (const auto& x : p.pose) q.emplace_back(S(x[0]), Vec2<S>(S(x[1]), S(x[2])));
  return q;
}

/// The reference of one problem in mpfr (≥ 512 bits): its positions, real pairs, and per pair
/// the scale ρ and the condition number κ of the defining equations.
struct Reference {
  std::vector<SE2<mpreal>> pos;
  Vec2<mpreal> centroid;
  mpreal scale;
  std::vector<BurmesterPair<mpreal>> pairs;
  std::vector<mpreal> rho, kappa;
};

/// ρ = max(scale, |z|, |m − centroid|): the size of the terms of e_i (the library's residual uses
/// the same normalisation, so the rungs compare).
mpreal rhoOf(const Reference& r, const Vec2<mpreal>& m, const Vec2<mpreal>& z) {
  return std::max({r.scale, mpreal(z.norm()), mpreal((m - r.centroid).norm())});
}

/// max_{i=2..5} | |M_i z − m|² − |M_1 z − m|² | / ρ²: the defining equations (GF §5.3, the circle
/// condition), written out here, not the library's evaluation.
mpreal residualOf(const Reference& r, const Vec2<mpreal>& m, const Vec2<mpreal>& z) {
  const mpreal rho = rhoOf(r, m, z);
  const mpreal r1 = (r.pos[0].act(z) - m).squaredNorm();
  mpreal worst = 0;
  for (int i = 1; i < 5; ++i) worst = std::max(worst, mpreal(mpfr::abs((r.pos[std::size_t(i)].act(z) - m).squaredNorm() - r1)));
  return worst / (rho * rho);
}

/// κ = ‖J̃⁻¹‖∞ of the scaled Jacobian J̃ = ∂(e/ρ²)/∂((m, z)/ρ) at the pair (rows e_2..e_5):
/// ∂e_i/∂m = −2(w_i − w_1), ∂e_i/∂z = 2(R_iᵀ(w_i − m) − R_1ᵀ(w_1 − m)), w_i = M_i z. A rung's pair
/// with residual r (in these units) lies within κ r (to first order) of the exact pair.
mpreal kappaOf(const Reference& r, const Vec2<mpreal>& m, const Vec2<mpreal>& z, const mpreal& rho) {
  Eigen::Matrix<mpreal, 4, 4> j;
  const Vec2<mpreal> w1 = r.pos[0].act(z);
  for (int i = 1; i < 5; ++i) {
    const Vec2<mpreal> wi = r.pos[std::size_t(i)].act(z);
    const Vec2<mpreal> gm = mpreal(-2) * (wi - w1);
    const Vec2<mpreal> gz = mpreal(2) * (r.pos[std::size_t(i)].rotation().transpose() * (wi - m) -
                                         r.pos[0].rotation().transpose() * (w1 - m));
    j.row(i - 1) << gm(0), gm(1), gz(0), gz(1);
  }
  const Eigen::Matrix<mpreal, 4, 4> inv = (j / rho).partialPivLu().inverse();
  mpreal k = 0;
  for (int i = 0; i < 4; ++i) k = std::max(k, mpreal(inv.row(i).cwiseAbs().sum()));
  return k;
}

Reference referenceOf(const Problem& p) {
  Reference r;
  r.pos = positionsIn<mpreal>(p);
  r.centroid = Vec2<mpreal>::Zero();
  for (const auto& q : r.pos) r.centroid += q.translation();
  r.centroid /= mpreal(5);
  mpreal d = 0;
  for (const auto& q : r.pos) d = std::max(d, mpreal((q.translation() - r.centroid).norm()));
  r.scale = 1 + d;
  r.pairs = BurmesterSynthesis<mpreal>(r.pos).burmesterPairs();
  for (const auto& b : r.pairs) {
    r.rho.push_back(rhoOf(r, b.centre, b.circle));
    r.kappa.push_back(kappaOf(r, b.centre, b.circle, r.rho.back()));
  }
  return r;
}

struct Measured {
  TradeRung rung;
  std::size_t countsAgree = 0, problems = 0, unmatched = 0;
  double worstResidualUlps = 0;  ///< worst mpfr residual / ε_S
  double worstForwardRatio = 0;  ///< worst forward error / (κ · residual)
  double worstKappaEps = 0;      ///< worst κ ε_S over the matched pairs
  std::string notes;
  double eps = 0;  ///< ε of the rung
};

/// The first n problems in S; every real pair matched to the nearest reference pair.
template <class S> Measured measure(const std::vector<Problem>& problems, const std::vector<Reference>& refs,
                                    std::size_t n, int refBits, bool escalate = true) {
  Measured out;
  TradeRung& g = out.rung;
  const int bits = mpfrBits();
  g.scalar = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) g.scalar += " (" + std::to_string(bits) + " bits)";
  if (!escalate) g.scalar += " (no escalation)";
  const double eps = toDouble(Tolerance<S>::epsilon());
  out.eps = eps;
  std::vector<double> times;
  double worstForward = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<SE2<S>> pos = positionsIn<S>(problems[k]);
    std::string notes;
    std::vector<BurmesterPair<S>> pairs;
    double best = 0;
    for (int rep = 0; rep < 3; ++rep) {  // the least of three runs: the machine is shared
      const auto t0 = std::chrono::steady_clock::now();
      const BurmesterSynthesis<S> bs(pos);
      pairs = bs.burmesterPairs(nullptr, nullptr, nullptr, &notes, escalate);
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = rep == 0 ? dt : std::min(best, dt);
    }
    times.push_back(best);
    if (!notes.empty() && out.notes.find(notes) == std::string::npos) out.notes += (out.notes.empty() ? "" : "; ") + notes;
    const Reference& ref = refs[k];
    ++out.problems;
    out.countsAgree += pairs.size() == ref.pairs.size();
    setMpfrBits(refBits);
    std::vector<bool> used(ref.pairs.size(), false);
    for (const auto& b : pairs) {
      const Vec2<mpreal> m(scalarCast<mpreal>(b.centre(0)), scalarCast<mpreal>(b.centre(1)));
      const Vec2<mpreal> z(scalarCast<mpreal>(b.circle(0)), scalarCast<mpreal>(b.circle(1)));
      std::size_t near = ref.pairs.size();
      mpreal nearD = 0;
      for (std::size_t j = 0; j < ref.pairs.size(); ++j) {
        const mpreal d = std::max((m - ref.pairs[j].centre).cwiseAbs().maxCoeff(),
                                  (z - ref.pairs[j].circle).cwiseAbs().maxCoeff()) / ref.rho[j];
        if (near == ref.pairs.size() || d < nearD) {
          near = j;
          nearD = d;
        }
      }
      const mpreal res = residualOf(ref, m, z);
      out.worstResidualUlps = std::max(out.worstResidualUlps, toDouble(res) / eps);
      if (near == ref.pairs.size() || used[near]) {
        ++out.unmatched;  // a real pair the reference does not have (or a second pair at the same one)
        continue;
      }
      used[near] = true;
      const mpreal kappa = ref.kappa[near];
      worstForward = std::max(worstForward, toDouble(nearD));
      out.worstKappaEps = std::max(out.worstKappaEps, toDouble(kappa) * eps);
      if (res > 0) out.worstForwardRatio = std::max(out.worstForwardRatio, toDouble(nearD / (kappa * res)));
    }
    setMpfrBits(bits);
  }
  g.samples = n;
  timeQuantiles(times, g.medianSeconds, g.p95Seconds);
  g.worstError = worstForward;
  g.worstErrorText = io::numberText(worstForward);  // measured in mpfr, rounded to double
  if (std::is_same_v<S, float> && escalate) {
    g.escalated = n;
    g.escalatedTo = "double: the conic intersection of every problem; the pairs are polished in float";
  }
  g.comment = fmt::format("real-pair count = the reference's on {} of {}; worst residual {:.3g} ε",
                          out.countsAgree, n, out.worstResidualUlps);
  return out;
}

// GF §5.3 (finite-position Burmester theory, the analogue of GF-5.3.5-burmester-count);
// SOMA-burmester-speed-accuracy
void burmesterTrade(Context& c) {
  const MpfrBitsRestore restore;  // the rung's precision, restored on any exit
  const int bits = restore.bits();
  const int refBits = std::max(512, 2 * bits + 64);
  const std::vector<Problem> problems = randomProblems(100, 5352026);
  setMpfrBits(refBits);
  std::vector<Reference> refs;
  for (const auto& p : problems) refs.push_back(referenceOf(p));
  // The reference itself: its pairs satisfy the defining equations to its own precision.
  mpreal refWorst = 0;
  std::size_t refPairs = 0;
  double worstKappa = 0;
  for (const auto& r : refs)
    for (std::size_t j = 0; j < r.pairs.size(); ++j) {
      refWorst = std::max(refWorst, residualOf(r, r.pairs[j].centre, r.pairs[j].circle));
      worstKappa = std::max(worstKappa, toDouble(r.kappa[j]));
      ++refPairs;
    }
  const double refUlps = toDouble(refWorst / Tolerance<mpreal>::epsilon());
  setMpfrBits(bits);
  c.record(fmt::format("reference (mpfr {} bits): worst residual of its {} real pairs ≤ 64 ε (see below)", refBits, refPairs),
           "≤ 64 ε", fmt::format("{:.3g} ε", refUlps), refUlps, 64.0, refUlps <= 64.0);

  const std::array<std::size_t, 5> n{100, 100, 100, 40, 12};
  std::vector<Measured> ms;
  ms.push_back(measure<float>(problems, refs, n[0], refBits, false));
  ms.push_back(measure<float>(problems, refs, n[0], refBits));
  ms.push_back(measure<double>(problems, refs, n[1], refBits));
  ms.push_back(measure<long double>(problems, refs, n[2], refBits));
  ms.push_back(measure<__float128>(problems, refs, n[3], refBits));
  ms.push_back(measure<mpreal>(problems, refs, n[4], refBits));
  TradeTable t;
  t.solver = "Burmester pairs of five positions (GF §5.3)";
  t.sample = "problem";
  t.errorLabel = "worst relative pivot error";
  for (const Measured& m : ms) {
    const std::string& s = m.rung.scalar;
    // The a-priori bound on the residual: the positions' rounding in S (cos, sin within 1 ulp;
    // translations exact) moves e_i by ≤ 4 ε ρ², evaluating e_i in S costs ≤ 12 ε ρ², the
    // normalisation of the frame ≤ 4 ε ρ²; Newton keeps its best iterate, within twice that floor:
    // 40 ε, rounded up to 64 ε.
    c.record(fmt::format("{}: worst residual of the real pairs, evaluated in mpfr on the exact positions, ≤ 64 ε", s),
             "≤ 64 ε", fmt::format("{:.3g} ε", m.worstResidualUlps), m.worstResidualUlps, 64.0, m.worstResidualUlps <= 64.0);
    // First-order perturbation: |Δ(m, z)| / ρ ≤ κ · residual (1 + O(Δ)); factor 2 for the second order.
    c.record(fmt::format("{}: pivot error against the reference ≤ 2 κ × residual (κ = ‖J̃⁻¹‖∞ per pair)", s), "≤ 2",
             fmt::format("{:.3g}", m.worstForwardRatio), m.worstForwardRatio, 2.0, m.worstForwardRatio <= 2.0);
    // Each pair is matched to the nearest reference pair; the check above says it is near enough.
    c.checkEqual(fmt::format("{}: no two real pairs match the same reference pair", s), 0LL, (long long)m.unmatched);
    // A real pair turns complex only where it meets another (a double root, where κ → ∞): a rung
    // whose perturbation κ ε is far below 1 keeps every count. From double up κ ε ≤ 1e-9 here;
    // float's κ ε reaches the order of 1 on the worst pairs, so its count is reported, not checked.
    if (m.worstKappaEps < 1e-3)
      c.checkEqual(fmt::format("{}: real-pair count = the reference's (of {} problems; worst κ ε = {:.2g})", s,
                               m.problems, m.worstKappaEps),
                   (long long)m.problems, (long long)m.countsAgree);
    TradeRung r = m.rung;
    if (m.notes.find("infinity") != std::string::npos) r.comment += "; " + m.notes;  // the rest: the row's label
    t.rungs.push_back(r);
  }
  for (std::size_t i = 2; i < ms.size(); ++i)
    if (ms[i].eps < ms[i - 1].eps)  // (mpfr below 113 bits is not a wider rung than float128)
      c.checkEqual(fmt::format("worst pivot error in {} below the error in {}", ms[i].rung.scalar, ms[i - 1].rung.scalar),
                   "below", ms[i].rung.worstError < ms[i - 1].rung.worstError ? "below" : "not below");
  c.note(fmt::format(
      "{} five-position problems from random crank-rockers (seed 5352026; positions rounded to float, so every rung "
      "solves the same problem), solved by BurmesterSynthesis<S>::burmesterPairs; the first {}, {}, {}, {}, {} in "
      "float … mpfr. Reference: the same problems in mpfr at {} bits ({} real pairs, worst condition κ = {:.3g}). "
      "Error: max(|m − m_ref|, |z − z_ref|)∞ / ρ, ρ = max(scale, |z|, |m − centroid|), over the real pairs; residual: "
      "max_i | |M_i z − m|² − |M_1 z − m|² | / ρ² evaluated in mpfr on the exact positions. Float escalates by design: "
      "its conic intersection runs in double and the pairs are polished in float (in float alone it misjudged a "
      "near-tangent real/complex pair in 1 of 2000 random position sets, papers/selig-2005/ch05.md); the row 'float "
      "(no escalation)' is the float rung alone (burmesterPairs(…, escalateFloat = false)). No other rung re-solves. "
      "Time: the least of three runs per problem (the machine is shared); the float, long double, float128 and mpfr "
      "instantiations of the library are compiled at -O1, double at -O3 (cmake/SomaInstantiate.cmake).",
      problems.size(), n[0], n[1], n[2], n[3], n[4], refBits, refPairs, worstKappa));
  c.trade(std::move(t), "SOMA-burmester-speed-accuracy.png",
          "Burmester pairs of five positions: median time per problem (point; bar to the p95) against the worst "
          "relative pivot error, one point per scalar (log–log).");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-burmester-speed-accuracy",
            .title = "Burmester pairs of five positions on every scalar: time per problem, pivot error against mpfr",
            .source = "GF §5.3",
            .chapter = "soma — speed vs accuracy",
            .scalarGeneric = false,
            .run = [](Context& c) { burmesterTrade(c); },
            .ladder = true});

}  // namespace soma::studies::SOMA_UNITY_ID
