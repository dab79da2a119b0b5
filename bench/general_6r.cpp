// The general 6R, every real posture (GF §11.5): soma's algebraic method (Raghavan–Roth /
// Manocha–Canny eigenproblem) in double and long double, per pose, over a fixed pool of random
// robots and poses; side by side with Orocos KDL's ChainIkSolverPos_LMA, which returns ONE
// posture from an initial guess (the true posture perturbed by 0.3 rad per joint: the tracking
// use case; from a far guess LMA often converges to another posture or not at all).
// papers/benchmarks/ik.md records the numbers.
#include "soma/geometry/serial/general_6r.hpp"

#include <Eigen/Eigenvalues>
#include <benchmark/benchmark.h>

#ifdef SOMA_HAVE_KDL
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#endif

#include <memory>
#include <random>
#include <vector>

namespace {
using namespace soma;

constexpr std::size_t kPool = 64;

struct Case {
  Robot6R<double> robot;
  std::array<double, 6> q;
  SE3<double> pose;
};

const std::vector<Case>& pool() {
  static const std::vector<Case> cases = [] {
    std::mt19937_64 g(20261130);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Case> out;
    for (std::size_t i = 0; i < kPool; ++i) {
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
  }();
  return cases;
}

template <class S> void BM_general6r(benchmark::State& st) {
  std::vector<Robot6R<S>> robots;
  std::vector<SE3<S>> poses;
  for (const auto& c : pool()) {
    Robot6R<S> r;
    for (int i = 0; i < 6; ++i) r[i] = c.robot[i].template cast<S>();
    robots.push_back(r);
    poses.push_back(c.pose.template cast<S>());
  }
  std::size_t i = 0, postures = 0, calls = 0;
  for (auto _ : st) {
    const auto sol = solveGeneral6R(robots[i], poses[i]);
    benchmark::DoNotOptimize(sol.postures.data());
    postures += sol.count();
    ++calls;
    i = (i + 1) % kPool;
  }
  st.counters["postures/pose"] = double(postures) / double(calls);
}
BENCHMARK_TEMPLATE(BM_general6r, double)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_TEMPLATE(BM_general6r, long double)->Repetitions(3)->ReportAggregatesOnly(true);

// The yardstick of issue 20 item 3: one dense 16×16 eigenvalue solve (Eigen's EigenSolver on a
// fixed-size matrix, eigenvalues only) over a pool of random matrices, in the same run, so that
// "the general 6R below one dense 16×16 eigensolve" is a ratio read off one run on one machine.
void BM_dense16_eigenvalues(benchmark::State& st) {
  std::mt19937_64 g(20261205);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Matrix<double, 16, 16>> ms(kPool);
  for (auto& m : ms) m = Eigen::Matrix<double, 16, 16>::NullaryExpr([&] { return u(g); });
  Eigen::EigenSolver<Eigen::Matrix<double, 16, 16>> es;
  std::size_t i = 0, ok = 0, calls = 0;
  for (auto _ : st) {
    es.compute(ms[i], false);
    benchmark::DoNotOptimize(es.eigenvalues().data());
    ok += es.info() == Eigen::Success;
    ++calls;
    i = (i + 1) % kPool;
  }
  st.counters["converged"] = double(ok) / double(calls);
}
BENCHMARK(BM_dense16_eigenvalues)->Repetitions(5)->ReportAggregatesOnly(true);

#ifdef SOMA_HAVE_KDL
void BM_kdl_lma(benchmark::State& st) {
  std::vector<KDL::Chain> chains;
  std::vector<KDL::Frame> goals;
  std::vector<KDL::JntArray> inits;
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (const auto& c : pool()) {
    KDL::Chain ch;
    for (const auto& r : c.robot)
      ch.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ),
                                 KDL::Frame::DH(r.a, r.alpha, r.d, r.theta)));
    chains.push_back(ch);
    const Mat4<double> m = c.pose.matrix();
    goals.emplace_back(KDL::Rotation(m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0),
                                     m(2, 1), m(2, 2)),
                       KDL::Vector(m(0, 3), m(1, 3), m(2, 3)));
    KDL::JntArray q0(6);
    for (int k = 0; k < 6; ++k) q0(k) = c.q[k] + u(g);
    inits.push_back(q0);
  }
  std::vector<std::unique_ptr<KDL::ChainIkSolverPos_LMA>> solvers;
  for (const auto& ch : chains) solvers.push_back(std::make_unique<KDL::ChainIkSolverPos_LMA>(ch));
  std::size_t i = 0, ok = 0, calls = 0;
  KDL::JntArray out(6);
  for (auto _ : st) {
    const int rc = solvers[i]->CartToJnt(inits[i], goals[i], out);
    ok += rc >= 0;
    ++calls;
    benchmark::DoNotOptimize(out.data.data());
    i = (i + 1) % kPool;
  }
  st.counters["success"] = double(ok) / double(calls);
}
BENCHMARK(BM_kdl_lma)->Repetitions(5)->ReportAggregatesOnly(true);
#endif

}  // namespace

BENCHMARK_MAIN();
