// Cuspidal 3R arms (GF §5.2.3): the verdict of one arm (findCuspsAdaptive: frame, degree-12 cusp
// polynomial, Aberth roots, Newton polish; double unless near-degenerate), over a fixed pool of
// random 3R arms (seed 20261130), and the 100 × 100 cusp-count map of orthogonal arms
// (d2, d3, d4, r2, r3) = (1, a2, a3, 1, 0) over a2 ∈ [0.2, 4], a3 ∈ [0.2, 3] in parallel with TBB
// on 1 and 2 threads. Goals from issue 9: a verdict ≤ 10 ms; the 100 × 100 map ≤ 60 s on 2 cores.
// papers/benchmarks/cuspidal.md records the numbers.
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/cuspidal/parameter_map.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace {
using namespace soma;

SerialRobot<double> dh3r(double a1, double al1, double a2, double al2, double d2, double a3, double d3) {
  DHRow<double> r1, r2, r3;
  r1.a = a1;
  r1.alpha = al1;
  r2.a = a2;
  r2.alpha = al2;
  r2.d = d2;
  r3.a = a3;
  r3.d = d3;
  return SerialRobot<double>::fromDH({r1, r2, r3});
}

const std::vector<SerialRobot<double>>& pool() {
  static const std::vector<SerialRobot<double>> arms = [] {
    std::mt19937_64 g(20261130);
    std::uniform_real_distribution<double> len(0.2, 2), ang(0.3, 2.8), off(-1, 1);
    std::vector<SerialRobot<double>> out;
    for (int k = 0; k < 64; ++k) out.push_back(dh3r(len(g), ang(g), len(g), ang(g), off(g), len(g), off(g)));
    return out;
  }();
  return arms;
}

void BM_cuspidal_verdict(benchmark::State& st) {
  std::size_t i = 0, calls = 0, cuspidal = 0, cusps = 0;
  for (auto _ : st) {
    const CuspAnalysis<double> c = findCuspsAdaptive(pool()[i]);
    benchmark::DoNotOptimize(c.cusps.data());
    cuspidal += !c.cusps.empty();
    cusps += c.cusps.size();
    ++calls;
    i = (i + 1) % pool().size();
  }
  st.counters["cuspidal_fraction"] = double(cuspidal) / double(calls);
  st.counters["cusps/arm"] = double(cusps) / double(calls);
}
BENCHMARK(BM_cuspidal_verdict)->Unit(benchmark::kMicrosecond)->Iterations(640)->Repetitions(3)->ReportAggregatesOnly(true);

void BM_cuspidal_verdict_near_degenerate(benchmark::State& st) {
  // a1 = 1e-8: re-solved in float128.
  const SerialRobot<double> arm = dh3r(1e-8, -1.5707963267948966, 2, 1.5707963267948966, 1, 1.5, 0);
  for (auto _ : st) benchmark::DoNotOptimize(findCuspsAdaptive(arm).cusps.data());
}
BENCHMARK(BM_cuspidal_verdict_near_degenerate)->Unit(benchmark::kMillisecond)->Iterations(20);

void BM_cuspidal_map_100x100(benchmark::State& st) {
  const SerialRobot<double> base = dh3r(1, -1.5707963267948966, 2, 1.5707963267948966, 1, 1.5, 0);
  ParameterAxis x, y;
  x.name = "a2", x.isA = true, x.row = 1, x.min = 0.2, x.max = 4, x.n = 100;
  y.name = "a3", y.isA = true, y.row = 2, y.min = 0.2, y.max = 3, y.n = 100;
  int cuspidal = 0;
  for (auto _ : st) {
    const CuspMap m = cuspMap(base, x, y, int(st.range(0)));
    cuspidal = 0;
    for (int c : m.counts) cuspidal += c > 0;
  }
  st.counters["threads"] = double(st.range(0));
  st.counters["cuspidal_arms"] = cuspidal;
}
BENCHMARK(BM_cuspidal_map_100x100)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
