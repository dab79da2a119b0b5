// Stewart–Gough forward kinematics (GF §11.5.4): all 40 complex solutions of a general 6-6
// platform by soma's parameter homotopy (geometry/parallel/stewart.hpp), then the real postures
// polished by Newton, per platform, over a fixed pool of random platforms (seed 20261130; base
// joints in [−1, 1]² × [−0.2, 0.2], platform joints in [−0.6, 0.6]² × [−0.1, 0.1], a random
// posture above the base defines the leg lengths). The start system (a total-degree homotopy on
// a complex platform, once per process) is solved before timing. papers/benchmarks/stewart.md
// records the numbers. Goal from issues 8 and 21: ≤ 1 ms median for all 40 in double — the fast
// double tracker (BM_stewart_fast, solveStewartForward's default in double, with the widest kernel
// the CPU has; BM_stewart_fast_kernel with it capped to AVX2 and to the portable kernel) beside the
// general tracker (BM_stewart_homotopy) on the same pool.
#include "soma/geometry/parallel/stewart.hpp"

#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

namespace {
using namespace soma;

constexpr std::size_t kPool = 32;

double threadCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

const std::vector<StewartPlatform<double>>& pool() {
  static const std::vector<StewartPlatform<double>> platforms = [] {
    std::mt19937_64 g(20261130);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<StewartPlatform<double>> out;
    for (std::size_t k = 0; k < kPool; ++k) {
      StewartPlatform<double> P;
      for (int i = 0; i < 6; ++i) {
        P.base[i] = Vec3<double>(u(g), u(g), 0.2 * u(g));
        P.platform[i] = Vec3<double>(0.6 * u(g), 0.6 * u(g), 0.1 * u(g));
      }
      Vec6<double> xi;
      xi << 0.3 * u(g), 0.3 * u(g), 0.3 * u(g), 0.2 * u(g), 0.2 * u(g), 1.0 + 0.2 * u(g);
      P.legs = stewartLegLengths<double>(P, SE3Tangent<double>(xi).exp());
      out.push_back(P);
    }
    return out;
  }();
  return platforms;
}

/// One platform per iteration with the given tracker (StewartTracking::Auto: the fast double
/// tracker on these general 6-6 platforms, General: the general tracker, its cross-check).
template <class S> void stewartBench(benchmark::State& st, StewartTracking tracking) {
  std::vector<StewartPlatform<S>> ps;
  for (const auto& p : pool()) ps.push_back(p.template cast<S>());
  (void)stewartStartSolutions<S>();  // the start system, once per process, outside the timing
  std::size_t i = 0, calls = 0, complete = 0, real = 0, paths = 0, fast = 0, steps = 0;
  double worst = 0;
  std::vector<double> cpu;  // per-platform CPU seconds: the median is robust to the rare escalation
  for (auto _ : st) {
    const double c0 = threadCpuSeconds();
    const auto sol = solveStewartForward<S>(ps[i], tracking);
    cpu.push_back(threadCpuSeconds() - c0);
    benchmark::DoNotOptimize(sol.postures.data());
    complete += sol.complexCount() == 40;
    real += sol.count();
    paths += static_cast<std::size_t>(sol.paths_tracked);
    steps += static_cast<std::size_t>(sol.steps);
    fast += sol.tracker == "fast";
    worst = std::max(worst, toDouble(sol.worstResidual()));
    ++calls;
    i = (i + 1) % ps.size();
  }
  st.counters["complete(40)"] = double(complete) / double(calls);
  st.counters["real/platform"] = double(real) / double(calls);
  st.counters["paths/platform"] = double(paths) / double(calls);
  st.counters["steps/path"] = double(steps) / double(paths);
  st.counters["fast_tracker"] = double(fast) / double(calls);
  st.counters["worst_residual"] = worst;
  std::sort(cpu.begin(), cpu.end());
  st.counters["median_cpu_ms"] = 1e3 * cpu[cpu.size() / 2];
  st.counters["p90_cpu_ms"] = 1e3 * cpu[(cpu.size() * 9) / 10];
}
template <class S> void BM_stewart_homotopy(benchmark::State& st) { stewartBench<S>(st, StewartTracking::General); }
template <class S> void BM_stewart_fast(benchmark::State& st) {
  stewartBench<S>(st, StewartTracking::Auto);
  st.SetLabel(stewartFastKernel());  // the widest kernel this CPU has
}
/// The fast tracker with its kernel capped (SOMA_STEWART_KERNEL): the kernels side by side.
void BM_stewart_fast_kernel(benchmark::State& st, const char* cap) {
  setenv("SOMA_STEWART_KERNEL", cap, 1);
  stewartBench<double>(st, StewartTracking::Auto);
  st.SetLabel(stewartFastKernel());
  unsetenv("SOMA_STEWART_KERNEL");
}
BENCHMARK_TEMPLATE(BM_stewart_fast, double)->Unit(benchmark::kMillisecond)->Iterations(kPool)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_stewart_fast_kernel, avx2, "avx2")->Unit(benchmark::kMillisecond)->Iterations(kPool)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_stewart_fast_kernel, portable, "portable")->Unit(benchmark::kMillisecond)->Iterations(kPool)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK_TEMPLATE(BM_stewart_homotopy, double)->Unit(benchmark::kMillisecond)->Iterations(kPool)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK_TEMPLATE(BM_stewart_homotopy, long double)->Unit(benchmark::kMillisecond)->Iterations(8)->Repetitions(1);

}  // namespace

BENCHMARK_MAIN();
