// SOMA-log-speed-accuracy: SE(3) log (GF §4.4.2) on every rung of the scalar ladder: the time of
// one SE3<S>::log and its worst normwise error over θ ∈ (0, π] against an mpfr reference
// (worstLogError, algebra/log_accuracy.hpp: the same sweep as GF-4.4-log-accuracy).
#include "soma/algebra/log_accuracy.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <chrono>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

struct Measured {
  TradeRung rung;
  LogAccuracy acc;
  double eps = 0;
};

/// Time per SE3<S>::log: `blocks` timings of one pass over n random elements (θ uniform in
/// (0, π)), each divided by n; and the worst error of worstLogError<S>(samples).
template <class S> Measured measure(int n, int blocks, int samples) {
  std::mt19937_64 g(20261202);
  std::uniform_real_distribution<double> u(-1, 1), a(0, 3.14159);
  std::vector<SE3<S>> xs;
  for (int k = 0; k < n; ++k) {
    Vec3<double> w(u(g), u(g), u(g));
    w = w.normalized() * a(g);
    const Vec3<double> t(u(g), u(g), u(g));
    xs.emplace_back(SO3Tangent<S>(Vec3<S>(castMatrix<S>(w))).exp(), Vec3<S>(castMatrix<S>(t)));
  }
  std::vector<double> per;
  S sink = 0;
  for (int b = 0; b < blocks; ++b) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& x : xs) sink += x.log().coeffs()(0);
    per.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / double(n));
  }
  Measured m;
  TradeRung& r = m.rung;
  r.scalar = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) r.scalar += " (" + std::to_string(mpfrBits()) + " bits)";
  m.eps = toDouble(Tolerance<S>::epsilon());
  m.acc = worstLogError<S>(samples);
  r.samples = std::size_t(m.acc.samples);
  timeQuantiles(per, r.medianSeconds, r.p95Seconds);
  // The error relative to the element, ulps × ε of S: comparable across the rungs.
  r.worstError = m.acc.worstUlps * m.eps;
  r.worstErrorText = io::numberText(r.worstError);  // measured in double (ulps × ε)
  r.comment = fmt::format("{:.3g} ulps at θ = {:.6g}; time: {} passes over {} elements{}", m.acc.worstUlps,
                          m.acc.worstTheta, blocks, n, isFinite(sink) ? "" : " (non-finite sum)");
  return m;
}

// GF §4.4.2, GF-4.4-log-accuracy; SOMA-log-speed-accuracy
void logTrade(Context& c) {
  std::vector<Measured> ms;
  ms.push_back(measure<float>(4096, 31, 300));
  ms.push_back(measure<double>(4096, 31, 300));
  ms.push_back(measure<long double>(4096, 31, 300));
  ms.push_back(measure<__float128>(512, 15, 200));
  ms.push_back(measure<mpreal>(64, 7, 60));
  TradeTable t;
  t.solver = "SE(3) log (GF §4.4.2)";
  t.sample = "call";
  t.errorLabel = "worst relative error";
  for (const auto& m : ms) {
    // The library's goal for its log (DESIGN, GF-4.4-log-accuracy): a few ulps, ≤ 4, in every rung.
    c.record(fmt::format("SE3::log in {}: worst normwise error over θ ∈ (0, π] ({} angles, reference mpfr {} bits)",
                         m.rung.scalar, m.acc.samples, m.acc.referenceBits),
             "≤ 4 ulps", fmt::format("{:.3g} ulps at θ = {:.6g}", m.acc.worstUlps, m.acc.worstTheta), m.acc.worstUlps,
             4.0, m.acc.worstUlps <= 4.0);
    t.rungs.push_back(m.rung);
  }
  c.note("Time: wall time of one SE3<S>::log (median and p95 of passes over random elements), in the study's "
         "code (compiled at -O1, studies/CMakeLists.txt). Error: worstLogError<S> (algebra/log_accuracy.hpp) "
         "in ulps of S times ε of S, so that the rungs compare; no rung escalates (the log is closed-form).");
  c.trade(std::move(t), "SOMA-log-speed-accuracy.png",
          "SE(3) log: median time per call (point; bar to the p95) against the worst normwise relative error over "
          "θ ∈ (0, π], one point per scalar (log–log).");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-log-speed-accuracy",
            .title = "SE(3) log on every scalar: time per call and worst error over θ ∈ (0, π]",
            .source = "GF §4.4.2",
            .chapter = "soma — speed vs accuracy",
            .scalarGeneric = false,
            .run = [](Context& c) { logTrade(c); },
            .ladder = true});

}  // namespace soma::studies::SOMA_UNITY_ID
