#pragma once
// Shared pieces of the Lie-group benchmarks (bench/se3.cpp, bench/so3.cpp): fixed-seed input
// pools prepared outside the timed loops, the same inputs cast to every rung of the scalar
// ladder, conversion to Orocos KDL, a pre-benchmark agreement check, and a main() that refuses
// to time anything when the implementations disagree.
//
// Timing goals live here only (DESIGN §8); tests never time anything.
#include "soma/algebra/se3.hpp"
#include "soma/algebra/so3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <benchmark/benchmark.h>

#ifdef SOMA_HAVE_KDL
#include <kdl/config.h>
#include <kdl/frames.hpp>
#endif

#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#ifndef SOMA_BENCH_CXX_FLAGS
#define SOMA_BENCH_CXX_FLAGS "unknown"
#endif

namespace soma::bench {

/// Number of prepared inputs per pool (a power of two: the loops cycle with a mask).
inline constexpr std::size_t kPool = 256;
inline constexpr std::uint64_t kSeed = 20261130;
inline constexpr int kMpfrBits = 256;

/// The inputs, drawn once in double with a fixed seed.
struct DoubleInputs {
  std::vector<Vec3<double>> w;   // rotation vectors, |ω| uniform in [0, π), uniform direction
  std::vector<Vec3<double>> v;   // twist linear parts, uniform in [−1, 1]³
  std::vector<SE3<double>> a;    // uniform random rotation, translation uniform in [−1, 1]³
  std::vector<SE3<double>> b;
  std::vector<Vec3<double>> p;   // points uniform in [−1, 1]³
};

inline const DoubleInputs& doubleInputs() {
  static const DoubleInputs in = [] {
    DoubleInputs d;
    std::mt19937_64 g(kSeed);
    std::uniform_real_distribution<double> u(-1, 1), angle(0, pi<double>());
    std::normal_distribution<double> n;
    for (std::size_t i = 0; i < kPool; ++i) {
      Vec3<double> axis;
      do axis = Vec3<double>(n(g), n(g), n(g));
      while (axis.squaredNorm() < 1e-6);
      d.w.push_back(axis.normalized() * angle(g));
      d.v.emplace_back(u(g), u(g), u(g));
      d.a.push_back(SE3<double>::Random(g));
      d.b.push_back(SE3<double>::Random(g));
      d.p.emplace_back(u(g), u(g), u(g));
    }
    return d;
  }();
  return in;
}

/// The same inputs in scalar S (cast from the double draws, so every rung sees the same data).
template <class S> struct Inputs {
  std::vector<SO3Tangent<S>> w;
  std::vector<SE3Tangent<S>> twist;
  std::vector<SO3<S>> r;
  std::vector<SE3<S>> a, b;
  std::vector<Vec3<S>> p;
};

template <class S> const Inputs<S>& inputs() {
  static const Inputs<S> in = [] {
    const DoubleInputs& d = doubleInputs();
    Inputs<S> s;
    for (std::size_t i = 0; i < kPool; ++i) {
      s.w.emplace_back(castMatrix<S>(d.w[i]));
      Vec6<S> t;  // (ω, v), filled by blocks (GCC 12 warns falsely on Eigen's comma init here)
      t.template head<3>() = castMatrix<S>(d.w[i]);
      t.template tail<3>() = castMatrix<S>(d.v[i]);
      s.twist.emplace_back(t);
      s.a.push_back(d.a[i].template cast<S>());
      s.b.push_back(d.b[i].template cast<S>());
      s.r.push_back(s.a.back().so3());
      s.p.push_back(castMatrix<S>(d.p[i]));
    }
    return s;
  }();
  return in;
}

/// Benchmark a unary operation f(i) over the pool; f returns the value to keep alive.
template <class F> void loop(benchmark::State& st, F&& f) {
  std::size_t i = 0;
  for (auto _ : st) {
    auto r = f(i);
    benchmark::DoNotOptimize(r);
    benchmark::ClobberMemory();
    i = (i + 1) & (kPool - 1);
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}

/// Benchmark name "<op>/soma/<scalar>" (parsed by scripts/bench_table.py).
template <class S> std::string somaName(const std::string& op) {
  std::string s(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) s += std::to_string(kMpfrBits);
  return op + "/soma/" + s;
}

// ---- agreement checks ----------------------------------------------------------------------

/// Collects failed agreement checks; main() refuses to run the benchmarks if any failed.
struct Checker {
  int failures = 0;
  int checks = 0;
  /// err ≤ tol, both in double for the message; `detail` says more about the input.
  void expect(const std::string& what, std::size_t i, double err, double tol,
              const std::string& detail = "") {
    ++checks;
    if (err <= tol) return;
    if (failures < 20)
      std::fprintf(stderr,
                   "agreement check FAILED: %s, input %zu%s: error %.3e > tolerance %.3e\n",
                   what.c_str(), i, detail.c_str(), err, tol);
    ++failures;
  }
};

/// Largest error of each benchmarked implementation against the 256-bit mpfr result of the
/// same inputs, over the whole pool (measured before timing; reported as the counter max_err).
inline std::map<std::string, double>& maxErrors() {
  static std::map<std::string, double> m;
  return m;
}
inline void recordError(const std::string& benchName, double err) {
  double& e = maxErrors()[benchName];
  e = std::max(e, err);
}
/// Attach the recorded error of benchmark `name` to its state (no-op if none was recorded).
inline void reportError(benchmark::State& st, const std::string& name) {
  const auto it = maxErrors().find(name);
  if (it != maxErrors().end()) st.counters["max_err"] = benchmark::Counter(it->second);
}

/// Register benchmark `name`: make() runs once, outside the timing, and returns the timed
/// body f(i) over input i of the pool. The label (shown in the table) says what is timed.
template <class Make> void reg(const std::string& name, const std::string& label, Make make) {
  benchmark::RegisterBenchmark(name.c_str(), [name, label, make](benchmark::State& st) {
    if (!label.empty()) st.SetLabel(label);
    reportError(st, name);
    loop(st, make());
  });
}

/// max |a − b| in S, after casting b (the reference) to S.
template <class S, class DA, class DB>
S maxDiff(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& ref) {
  using std::abs;
  const auto r = castMatrix<S>(ref);
  S m(0);
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) {
      const S d = abs(S(a(i, j)) - r(i, j));
      if (d > m) m = d;
    }
  return m;
}
template <class Derived> double maxAbs(const Eigen::MatrixBase<Derived>& a) {
  double m = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) m = std::max(m, std::abs(toDouble(a(i, j))));
  return m;
}

/// Tolerance for comparing a result in S against the 256-bit mpfr result of the same input:
/// Tolerance<S>::identity() (64 ulps) relative to the result's scale.
template <class S> double ladderTol(double scale) {
  return toDouble(Tolerance<S>::identity()) * (1 + scale);
}

#ifdef SOMA_HAVE_KDL
// ---- Orocos KDL (double only) --------------------------------------------------------------
inline KDL::Vector toKdl(const Vec3<double>& v) { return KDL::Vector(v.x(), v.y(), v.z()); }
inline KDL::Rotation toKdl(const Mat3<double>& r) {
  return KDL::Rotation(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1),
                       r(2, 2));
}
inline KDL::Frame toKdl(const SE3<double>& x) {
  return KDL::Frame(toKdl(x.rotation()), toKdl(x.translation()));
}
inline Vec3<double> fromKdl(const KDL::Vector& v) { return Vec3<double>(v.x(), v.y(), v.z()); }
inline Mat4<double> fromKdl(const KDL::Frame& f) {
  Mat4<double> m = Mat4<double>::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = f.M(i, j);
    m(i, 3) = f.p(i);
  }
  return m;
}
inline Mat3<double> fromKdl(const KDL::Rotation& r) {
  Mat3<double> m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r(i, j);
  return m;
}

struct KdlInputs {
  std::vector<KDL::Vector> w, p;
  std::vector<KDL::Twist> twist;  // KDL orders a twist (vel, rot)
  std::vector<KDL::Rotation> r;
  std::vector<KDL::Frame> a, b;
};
inline const KdlInputs& kdlInputs() {
  static const KdlInputs in = [] {
    const DoubleInputs& d = doubleInputs();
    KdlInputs k;
    for (std::size_t i = 0; i < kPool; ++i) {
      k.w.push_back(toKdl(d.w[i]));
      k.twist.emplace_back(toKdl(d.v[i]), toKdl(d.w[i]));
      k.a.push_back(toKdl(d.a[i]));
      k.b.push_back(toKdl(d.b[i]));
      k.r.push_back(k.a.back().M);
      k.p.push_back(toKdl(d.p[i]));
    }
    return k;
  }();
  return in;
}

/// Tolerance for soma double against KDL: Tolerance<double>::identity() relative to scale.
inline double kdlTol(double scale) { return toDouble(Tolerance<double>::identity()) * (1 + scale); }
#endif

/// Records what the table needs to say how the numbers were made.
inline void addContext() {
#if defined(__clang__)
  benchmark::AddCustomContext("soma_compiler", std::string("clang ") + __clang_version__);
#elif defined(__GNUC__)
  benchmark::AddCustomContext("soma_compiler", std::string("GCC ") + __VERSION__);
#else
  benchmark::AddCustomContext("soma_compiler", "unknown");
#endif
  benchmark::AddCustomContext("soma_cxx_flags", SOMA_BENCH_CXX_FLAGS);
  benchmark::AddCustomContext("soma_mpfr_bits", std::to_string(mpfrBits()));
  benchmark::AddCustomContext("soma_seed", std::to_string(kSeed));
  benchmark::AddCustomContext("soma_pool", std::to_string(kPool));
  benchmark::AddCustomContext("soma_eigen", std::to_string(EIGEN_WORLD_VERSION) + "." +
                                                std::to_string(EIGEN_MAJOR_VERSION) + "." +
                                                std::to_string(EIGEN_MINOR_VERSION));
#ifdef SOMA_HAVE_KDL
  benchmark::AddCustomContext("soma_kdl", KDL_VERSION_STRING);
#else
  benchmark::AddCustomContext("soma_kdl", "not found at configure time");
#endif
}

/// main() of a benchmark executable: agreement check first (exit 2 on any disagreement, so
/// wrong code is never timed), then the registered benchmarks.
inline int benchMain(int argc, char** argv, const std::function<void(Checker&)>& check,
                     const std::function<void()>& registerAll) {
  setMpfrBits(kMpfrBits);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Checker c;
  check(c);
  if (c.failures > 0) {
    std::fprintf(stderr, "%d of %d agreement checks failed: not timing code that disagrees\n",
                 c.failures, c.checks);
    return 2;
  }
  std::fprintf(stderr, "agreement: %d checks passed\n", c.checks);
  addContext();
  registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace soma::bench
