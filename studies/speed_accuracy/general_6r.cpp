// SOMA-6R-speed-accuracy: the general 6R (GF §11.5, 16 complex postures), every method × the
// five scalars on random robots × poses (fixed seed): time per pose (median, p95), the worst
// residual, and completeness — of the algebraic method against the forward-kinematics ground
// truth (the posture that generated the pose must be among the answers), of each numerical
// method against the algebraic method's real postures.
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/studies/study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

struct Case {
  Robot6R<double> robot;
  std::array<double, 6> q;
  SE3<double> pose;
};

std::vector<Case> randomCases(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Case> out;
  for (std::size_t i = 0; i < n; ++i) {
    Case c;
    for (auto& r : c.robot) {
      r.a = u(g);
      r.alpha = 3.1 * u(g);
      r.d = u(g);
      r.theta = 0.5 * u(g);
    }
    for (auto& x : c.q) x = 3.1 * u(g);
    c.pose = general6rForward(c.robot, c.q);
    out.push_back(c);
  }
  return out;
}

double wrapped(double a) { return std::atan2(std::sin(a), std::cos(a)); }

template <class S> double distance(const JointVector<S>& p, const std::array<double, 6>& q) {
  double d = 0;
  for (int i = 0; i < 6; ++i) d = std::max(d, std::abs(wrapped(toDouble(p(i)) - q[i])));
  return d;
}

struct Row {
  std::string method, scalar;
  std::size_t poses = 0;
  double median = 0, p95 = 0, worst = 0;
  double completeness = 0;  ///< fraction found (see the note)
  std::size_t escalated = 0;
  std::string escalatedTo;  ///< the rungs the escalated poses were solved in
  std::string worstText;    ///< the worst residual in the rung's digits
};

double quantile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
}

/// The algebraic method in S on the first n cases: ground-truth completeness and residuals in S
/// (evaluated against the pose cast to S).
template <class S>
Row algebraic(const std::vector<Case>& cases, std::size_t n,
              std::vector<General6RSolution<double>>* keep, const General6ROptions& options = {}) {
  Row row;
  row.method = "algebraic";
  row.scalar = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpfr::mpreal>) row.scalar += " (" + std::to_string(mpfrBits()) + " bits)";
  if (!options.escalate) row.scalar += " (no escalation)";
  S worst = 0;
  std::vector<double> times;
  std::size_t found = 0;
  for (std::size_t k = 0; k < n; ++k) {
    Robot6R<S> rb;
    for (int i = 0; i < 6; ++i) rb[i] = cases[k].robot[i].template cast<S>();
    const SE3<S> T = cases[k].pose.template cast<S>();
    const auto sol = solveGeneral6R(rb, T, options);
    times.push_back(sol.seconds);
    bool hit = false;
    for (std::size_t j = 0; j < sol.count(); ++j) {
      // The pose was made in double: the generating posture is known to double accuracy only.
      const double match = std::max(toDouble(Tolerance<S>::precision(2)),
                                    toDouble(Tolerance<double>::precision(2)));
      hit = hit || distance(sol.postures[j], cases[k].q) < match;
      if (sol.residuals[j] > worst) worst = sol.residuals[j];
    }
    found += hit;
    if (sol.solved_in != scalarName<S>()) {
      ++row.escalated;
      if (row.escalatedTo.find(sol.solved_in) == std::string::npos)
        row.escalatedTo += (row.escalatedTo.empty() ? "" : ", ") + sol.solved_in;
    }
    if (keep) {
      General6RSolution<double> d;
      for (const auto& p : sol.postures) d.postures.push_back(p.unaryExpr([](const S& x) { return toDouble(x); }));
      keep->push_back(d);
    }
  }
  row.poses = n;
  row.median = quantile(times, 0.5);
  row.p95 = quantile(times, 0.95);
  row.completeness = double(found) / double(n);
  row.worst = toDouble(worst);
  row.worstText = io::numberText(worst);
  return row;
}

template <class F>
Row numerical(const std::string& name, const std::vector<Case>& cases, std::size_t n,
              const std::vector<General6RSolution<double>>& ref, std::size_t& outside, F&& solve) {
  Row row;
  row.method = name;
  row.scalar = "double";
  std::vector<double> times;
  std::size_t refTotal = 0, refFound = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto sol = solve(cases[k].robot, cases[k].pose);
    times.push_back(sol.seconds);
    for (std::size_t j = 0; j < sol.count(); ++j) {
      row.worst = std::max(row.worst, sol.residuals[j]);
      std::array<double, 6> p;
      for (int i = 0; i < 6; ++i) p[i] = sol.postures[j](i);
      bool known = false;
      for (const auto& a : ref[k].postures) known = known || distance(a, p) < 1e-6;
      outside += !known;
    }
    for (const auto& a : ref[k].postures) {
      ++refTotal;
      std::array<double, 6> p;
      for (int i = 0; i < 6; ++i) p[i] = a(i);
      bool hit = false;
      for (const auto& b : sol.postures) hit = hit || distance(b, p) < 1e-6;
      refFound += hit;
    }
  }
  row.poses = n;
  row.median = quantile(times, 0.5);
  row.p95 = quantile(times, 0.95);
  row.completeness = refTotal ? double(refFound) / double(refTotal) : 1.0;
  return row;
}

// GF §11.5 (16 postures of the general 6R); SOMA-6R-speed-accuracy
void tradeoff(Context& ctx) {
  const std::size_t nDouble = 1000, nLong = 200, nQuad = 40, nMpfr = 8, nFloat = 200, nNum = 100;
  const auto cases = randomCases(nDouble, 20261130);
  std::vector<Row> rows;
  std::vector<General6RSolution<double>> ref;
  rows.push_back(algebraic<double>(cases, nDouble, &ref));
  rows.push_back(algebraic<float>(cases, nFloat, nullptr));
  rows.push_back(algebraic<long double>(cases, nLong, nullptr));
  rows.push_back(algebraic<__float128>(cases, nQuad, nullptr));
  rows.push_back(algebraic<mpfr::mpreal>(cases, nMpfr, nullptr));
  // The real float computation: no re-solve in double when the float eigenproblem is short.
  General6ROptions floatOnly;
  floatOnly.escalate = false;
  const Row floatOwn = algebraic<float>(cases, nFloat, nullptr, floatOnly);

  std::size_t total = 0;
  std::array<std::size_t, 17> hist{};
  for (const auto& s : ref) {
    total += s.count();
    hist[std::min<std::size_t>(16, s.count())]++;
  }
  std::size_t outCeres = 0, outNlopt = 0;
  General6RNumericOptions no;
  rows.push_back(numerical("ceres (64 starts)", cases, nNum, ref, outCeres,
                           [&](const Robot6R<double>& r, const SE3<double>& T) {
                             return solveGeneral6RCeres(r, T, no);
                           }));
  rows.push_back(numerical("nlopt (64 starts)", cases, nNum, ref, outNlopt,
                           [&](const Robot6R<double>& r, const SE3<double>& T) {
                             return solveGeneral6RNlopt(r, T, no);
                           }));

  // Checks: the algebraic method finds the generating posture of every pose, in every scalar
  // (float escalates to double when its own eigenproblem is short, and says so).
  for (const auto& r : rows) {
    if (r.method != "algebraic") continue;
    ctx.checkEqual("algebraic " + r.scalar + ": generating posture found in every pose (" +
                       std::to_string(r.poses) + " poses)",
                   (long long)r.poses, (long long)std::llround(r.completeness * double(r.poses)));
  }
  // Bound on the polished residual max(|R(q) − R*|, |t(q) − t*|/L): forward kinematics chains 6
  // link transforms, each entry of a product a 3-term dot product of unit-bounded factors plus the
  // sin/cos of the joint (≤ 4ε per link), so one evaluation carries ≤ 6·4 = 24ε; the polished posture
  // is itself rounded (Newton stops at the evaluation's noise), doubling it: 48ε; k = 64 ulps.
  auto bound = [](auto tag) { return 64 * toDouble(Tolerance<std::decay_t<decltype(tag)>>::epsilon()); };
  ctx.checkResidual("algebraic double: worst residual over " + std::to_string(nDouble) + " poses (≤ 64 ε: 6 links × 4ε, ×2)",
                    rows[0].worst, bound(0.0));
  ctx.checkResidual("algebraic long double: worst residual (≤ 64 ε)", rows[2].worst, bound(0.0L));
  ctx.checkResidual("algebraic float128: worst residual (≤ 64 ε)", rows[3].worst, bound(__float128(0)));
  ctx.checkResidual("algebraic mpfr: worst residual (≤ 64 ε)", rows[4].worst, bound(mpfr::mpreal(0)));
  ctx.checkResidual("algebraic float: worst residual (float polish; ≤ 64 ε)", rows[1].worst, bound(0.0f));
  // A numerical posture the algebraic method did not return would falsify its completeness.
  ctx.checkEqual("ceres postures outside the algebraic set", 0, (long long)outCeres);
  ctx.checkEqual("nlopt postures outside the algebraic set", 0, (long long)outNlopt);

  char buf[512];
  std::string table = "method | scalar | poses | median µs | p95 µs | worst residual | completeness | escalated\n";
  for (const auto& r : rows) {
    std::snprintf(buf, sizeof buf, "%s | %s | %zu | %.1f | %.1f | %.2e | %.4f | %zu\n",
                  r.method.c_str(), r.scalar.c_str(), r.poses, 1e6 * r.median, 1e6 * r.p95,
                  r.worst, r.completeness, r.escalated);
    table += buf;
  }
  ctx.note(table);
  std::string h = "real postures per pose over " + std::to_string(nDouble) + " poses (double):";
  for (int k = 0; k <= 16; ++k)
    if (hist[k]) h += " " + std::to_string(k) + "×" + std::to_string(hist[k]);
  h += "; total " + std::to_string(total) + ".";
  ctx.note(h);
  ctx.note("Completeness: for the algebraic rows, the fraction of poses whose generating posture "
           "(random joints → forward kinematics) is among the answers; for ceres/nlopt, the "
           "fraction of the algebraic method's real postures (double) they found on the first " +
           std::to_string(nNum) + " poses. Fewer poses in float (" + std::to_string(nFloat) +
           "), long double (" + std::to_string(nLong) + "), float128 (" + std::to_string(nQuad) +
           ") and mpfr 256 bits (" + std::to_string(nMpfr) +
           ") to keep the study short. 'escalated' counts poses re-solved in a higher scalar. "
           "Times are wall seconds on a shared machine (see papers/benchmarks/ik.md for quiet runs).");

  // The trade table (report section "speed vs accuracy"): the algebraic method on every rung,
  // float twice — as the solver runs it (escalating to double when the float eigenproblem is
  // short) and on its own (no escalation: a real float computation, completeness said).
  TradeTable t;
  t.solver = "General 6R, algebraic (GF §11.5)";
  t.sample = "pose";
  t.errorLabel = "worst residual";
  auto rung = [](const Row& r, std::string comment) {
    TradeRung g;
    g.scalar = r.scalar;
    g.samples = r.poses;
    g.medianSeconds = r.median;
    g.p95Seconds = r.p95;
    g.worstError = r.worst;
    g.worstErrorText = r.worstText;
    g.escalated = r.escalated;
    g.escalatedTo = r.escalatedTo;
    g.comment = std::move(comment);
    return g;
  };
  auto found = [](const Row& r) {
    return "generating posture found in " + std::to_string(std::llround(r.completeness * double(r.poses))) + " of " +
           std::to_string(r.poses);
  };
  t.rungs.push_back(rung(floatOwn, found(floatOwn) + " (float alone)"));
  t.rungs.push_back(rung(rows[1], found(rows[1]) + "; escalated poses solved again in double"));
  t.rungs.push_back(rung(rows[0], found(rows[0])));
  t.rungs.push_back(rung(rows[2], found(rows[2])));
  t.rungs.push_back(rung(rows[3], found(rows[3])));
  t.rungs.push_back(rung(rows[4], found(rows[4])));
  ctx.note("float on its own (no escalation): " + found(floatOwn) + " poses, worst residual " + floatOwn.worstText +
           "; as the solver runs it, float re-solves " + std::to_string(rows[1].escalated) + " of " +
           std::to_string(rows[1].poses) + " poses in " + (rows[1].escalatedTo.empty() ? "a higher rung" : rows[1].escalatedTo) +
           " (its time includes those re-solves).");
  // The float computation on its own finds fewer generating postures than the escalating one,
  // never more: an escalation only adds postures (a check that the two rows are what they say).
  ctx.checkEqual("float alone finds no posture the escalating float misses (count of poses)", 1,
                 floatOwn.completeness <= rows[1].completeness ? 1 : 0);
  ctx.trade(std::move(t), "SOMA-6R-speed-accuracy.png",
            "General 6R, algebraic method: median time per pose (point; bar to the p95) against the worst "
            "residual, one point per scalar (float alone and float escalating to double), log–log.");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-6R-speed-accuracy",
            .title = "General 6R: every method × scalar, time per pose, worst residual, completeness",
            .source = "GF §11.5",
            .chapter = "soma — inverse kinematics",
            .scalarGeneric = false,
            .run = [](Context& c) { tradeoff(c); },
            .ladder = true});

}  // namespace soma::studies::SOMA_UNITY_ID
