// SOMA-cusps-speed-accuracy: the cusp points of orthogonal 3R arms (GF §5.2.3, findCusps: the
// triple roots of the IK equation, a degree-12 polynomial) on every rung of the scalar ladder: the
// time per arm, the worst cusp residual, the cusp counts against the wider rungs, and the arms
// whose polynomial is ill-conditioned in the rung (findCuspsAdaptive re-solves those higher).
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/serial/serial_robot.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <chrono>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

SerialRobot<double> orthogonalArm(double a1, double d2, double a2, double a3, double d3) {
  constexpr double kPi = 3.14159265358979323846;
  auto row = [](double a, double al, double d) {
    DHRow<double> r;
    r.a = a;
    r.alpha = al;
    r.d = d;
    return r;
  };
  return SerialRobot<double>::fromDH({row(a1, -kPi / 2, 0), row(a2, kPi / 2, d2), row(a3, 0, d3)},
                                     DHConvention::Standard, SE3<double>(), SE3<double>(), "orthogonal 3R");
}

template <class S>
TradeRung measure(const std::vector<SerialRobot<double>>& arms, std::size_t n, std::vector<int>& counts) {
  TradeRung g;
  g.scalar = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) g.scalar += " (" + std::to_string(mpfrBits()) + " bits)";
  std::vector<double> times;
  S worst = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const SerialRobot<S> arm = arms[k].template cast<S>();
    const auto t0 = std::chrono::steady_clock::now();
    const CuspAnalysis<S> a = findCusps(arm);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    counts.push_back(int(a.cusps.size()));
    for (const auto& p : a.cusps)
      if (p.residual > worst) worst = p.residual;
    g.escalated += cuspsIllConditioned(a.frame);
  }
  g.samples = n;
  timeQuantiles(times, g.medianSeconds, g.p95Seconds);
  g.worstError = toDouble(worst);
  g.worstErrorText = io::numberText(worst);
  if (g.escalated) g.escalatedTo = "float128/mpfr by findCuspsAdaptive (here: counted, solved in the rung)";
  return g;
}

// GF §5.2.3 (cusp points); SOMA-cusps-speed-accuracy
void cuspTrade(Context& c) {
  std::mt19937_64 g(5232026);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<SerialRobot<double>> arms;
  for (int k = 0; k < 40; ++k)
    arms.push_back(orthogonalArm(1, 0.5 + 1.5 * u(g), 0.5 + 2.5 * u(g), 0.5 + 2.5 * u(g), 0.8 * u(g)));
  const std::array<std::size_t, 5> n{40, 40, 40, 20, 4};
  std::array<std::vector<int>, 5> counts;
  TradeTable t;
  t.solver = "Cusp points of orthogonal 3R arms (GF §5.2.3)";
  t.sample = "arm";
  t.errorLabel = "worst cusp residual";
  t.rungs.push_back(measure<float>(arms, n[0], counts[0]));
  t.rungs.push_back(measure<double>(arms, n[1], counts[1]));
  t.rungs.push_back(measure<long double>(arms, n[2], counts[2]));
  t.rungs.push_back(measure<__float128>(arms, n[3], counts[3]));
  t.rungs.push_back(measure<mpreal>(arms, n[4], counts[4]));
  // The count of each rung against the widest rung that solved the same arm.
  for (std::size_t r = 0; r < 5; ++r) {
    std::size_t agree = 0, of = 0;
    for (std::size_t k = 0; k < n[r]; ++k) {
      const std::size_t ref = k < n[4] ? 4 : k < n[3] ? 3 : 2;
      if (ref == r) continue;
      ++of;
      agree += counts[r][k] == counts[ref][k];
    }
    t.rungs[r].comment = of ? fmt::format("cusp count = the wider rung's on {} of {} arms", agree, of) : "the widest rung";
    // Two independent computations of the same count (the same arm, exactly, in two scalars):
    // from long double up, where no arm here is ill-conditioned, they must agree.
    if (r >= 2 && of > 0 && t.rungs[r].escalated == 0)
      c.checkEqual(fmt::format("cusp counts in {} = the wider rung's (of {} arms)", t.rungs[r].scalar, of), (long long)of,
                   (long long)agree);
  }
  int total = 0;
  for (int x : counts[1]) total += x;
  c.note(fmt::format("{} random orthogonal arms (a1 = 1, d2 ∈ [0.5, 2], a2, a3 ∈ [0.5, 3], d3 ∈ [0, 0.8]): {} cusp "
                     "points in double. 'escalated' counts the arms whose cusp polynomial is ill-conditioned in the "
                     "rung (cuspsIllConditioned: findCuspsAdaptive would re-solve them in float128 or mpfr); here "
                     "every rung is solved as it is, so its count and residual show what the rung alone gives.",
                     arms.size(), total));
  c.trade(std::move(t), "SOMA-cusps-speed-accuracy.png",
          "Cusp points of orthogonal 3R arms: median time per arm (point; bar to the p95) against the worst cusp "
          "residual, one point per scalar (log–log).");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-cusps-speed-accuracy",
            .title = "Cusp points of 3R arms on every scalar: time per arm, worst residual, counts, ill-conditioned arms",
            .source = "GF §5.2.3",
            .chapter = "soma — speed vs accuracy",
            .scalarGeneric = false,
            .run = [](Context& c) { cuspTrade(c); },
            .ladder = true});

}  // namespace soma::studies::SOMA_UNITY_ID
