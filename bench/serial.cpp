// Serial robots: forward kinematics and closed-form inverse kinematics (PUMA 560 as a Pieper
// robot, a 3R arm, a 3R wrist) in soma, side by side with Orocos KDL's recursive FK solver and its
// numerical IK (ChainIkSolverPos_LMA, Levenberg–Marquardt, one posture from a start guess).
// Medians per pose over a fixed pool of random poses (seed 7). KDL's LMA returns ONE posture
// near its seed; soma's closed forms return all of them (8 for the PUMA) — the rows say so.
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/example_robots.hpp"

#include <benchmark/benchmark.h>

#ifdef SOMA_HAVE_KDL
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#endif

#include <random>

namespace {

using namespace soma;
using S = double;
constexpr std::size_t kPool = 256;

struct DH {
  double a, alpha, d;
};
const DH kPuma[6] = {{0, M_PI / 2, 0},      {0.4318, 0, 0}, {0.0203, -M_PI / 2, 0.15005},
                     {0, M_PI / 2, 0.4318}, {0, -M_PI / 2, 0}, {0, 0, 0.05625}};

SerialRobot<S> puma() {
  std::vector<DHRow<S>> rows;
  for (const auto& r : kPuma) rows.push_back({JointType::Revolute, r.a, r.alpha, r.d, 0});
  return SerialRobot<S>::fromDH(rows);
}

struct Pool {
  SerialRobot<S> robot = puma();
  std::vector<JointVector<S>> q;
  std::vector<SE3<S>> pose;
  Pool() {
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u(-3, 3);
    for (std::size_t i = 0; i < kPool; ++i) {
      JointVector<S> x(6);
      for (int k = 0; k < 6; ++k) x(k) = u(g);
      q.push_back(x);
      pose.push_back(robot.fk(x));
    }
  }
};
const Pool& pool() {
  static const Pool p;
  return p;
}

void BM_soma_fk_puma(benchmark::State& st) {
  const auto& p = pool();
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(p.robot.fk(p.q[i++ % kPool]));
}
BENCHMARK(BM_soma_fk_puma);

void BM_soma_ik_pieper_puma_all8(benchmark::State& st) {
  const auto& p = pool();
  std::size_t i = 0, postures = 0, n = 0;
  for (auto _ : st) {
    const auto sol = solvePieper(p.robot, p.pose[i++ % kPool]);
    postures += sol.count();
    ++n;
    benchmark::DoNotOptimize(sol);
  }
  st.counters["postures/pose"] = double(postures) / double(n);
}
BENCHMARK(BM_soma_ik_pieper_puma_all8);

// UR5 (axes 2-4 parallel, 5 and 6 meeting): every real posture, same joint pool.
void BM_soma_ik_pieper_ur5_all(benchmark::State& st) {
  const SerialRobot<S> ur5 = ur5Robot<S>();
  std::vector<SE3<S>> targets;
  for (const auto& q : pool().q) targets.push_back(ur5.fk(q));
  std::size_t i = 0, postures = 0, n = 0;
  for (auto _ : st) {
    const auto sol = solvePieper(ur5, targets[i++ % kPool]);
    postures += sol.count();
    ++n;
    benchmark::DoNotOptimize(sol);
  }
  st.counters["postures/pose"] = double(postures) / double(n);
}
BENCHMARK(BM_soma_ik_pieper_ur5_all);

void BM_soma_ik_arm3r(benchmark::State& st) {
  std::vector<SerialJoint<S>> js(3);
  js[0].axis = Vec3<S>::UnitZ();
  js[1].axis = Vec3<S>::UnitX(), js[1].point = Vec3<S>(0, 0.8, 0);
  js[2].axis = Vec3<S>(0, 0.6, 0.8), js[2].point = Vec3<S>(0.1, 1.9, 0);
  const auto arm = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), Vec3<S>(0, 2.5, 0.2)));
  std::vector<SE3<S>> targets;
  for (const auto& q : pool().q) targets.push_back(arm.fk(JointVector<S>(q.head<3>())));
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(solveArm3R(arm, targets[i++ % kPool]));
}
BENCHMARK(BM_soma_ik_arm3r);

void BM_soma_ik_wrist3r(benchmark::State& st) {
  std::vector<SerialJoint<S>> js(3);
  js[0].axis = Vec3<S>::UnitZ(), js[1].axis = Vec3<S>::UnitY(), js[2].axis = Vec3<S>::UnitX();
  const auto wrist = SerialRobot<S>::fromPOE(js, SE3<S>());
  std::vector<SE3<S>> targets;
  for (const auto& q : pool().q) targets.push_back(wrist.fk(JointVector<S>(q.head<3>())));
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(solveWrist3R(wrist, targets[i++ % kPool]));
}
BENCHMARK(BM_soma_ik_wrist3r);

#ifdef SOMA_HAVE_KDL
KDL::Chain kdlPuma() {
  KDL::Chain c;
  for (const auto& r : kPuma) c.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ), KDL::Frame::DH(r.a, r.alpha, r.d, 0)));
  return c;
}
KDL::Frame toKdl(const SE3<S>& x) {
  const Mat3<S> R = x.rotation();
  return KDL::Frame(KDL::Rotation(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)),
                    KDL::Vector(x.translation().x(), x.translation().y(), x.translation().z()));
}

void BM_kdl_fk_puma(benchmark::State& st) {
  const KDL::Chain chain = kdlPuma();
  KDL::ChainFkSolverPos_recursive fk(chain);
  std::vector<KDL::JntArray> qs;
  for (const auto& q : pool().q) {
    KDL::JntArray j(6);
    for (int k = 0; k < 6; ++k) j(k) = q(k);
    qs.push_back(j);
  }
  KDL::Frame out;
  std::size_t i = 0;
  for (auto _ : st) {
    fk.JntToCart(qs[i++ % kPool], out);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_kdl_fk_puma);

// One posture per call, from a start guess 0.3 rad from the answer (KDL's typical use).
void BM_kdl_ik_lma_puma_one(benchmark::State& st) {
  const KDL::Chain chain = kdlPuma();
  KDL::ChainIkSolverPos_LMA ik(chain);
  std::vector<KDL::Frame> targets;
  std::vector<KDL::JntArray> seeds;
  for (std::size_t i = 0; i < kPool; ++i) {
    targets.push_back(toKdl(pool().pose[i]));
    KDL::JntArray s(6);
    for (int k = 0; k < 6; ++k) s(k) = pool().q[i](k) + 0.3;
    seeds.push_back(s);
  }
  KDL::JntArray out(6);
  std::size_t i = 0, ok = 0, n = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % kPool;
    ok += ik.CartToJnt(seeds[k], targets[k], out) >= 0;
    ++n;
    benchmark::DoNotOptimize(out);
  }
  st.counters["converged"] = double(ok) / double(n);
}
BENCHMARK(BM_kdl_ik_lma_puma_one);

// KDL's Newton–Raphson with joint limits (ChainIkSolverPos_NR_JL: pseudo-inverse velocity solver,
// limits ±2π so they never bind), one posture from the same 0.3 rad start.
void BM_kdl_ik_nrjl_puma_one(benchmark::State& st) {
  const KDL::Chain chain = kdlPuma();
  KDL::JntArray qmin(6), qmax(6);
  for (int k = 0; k < 6; ++k) qmin(k) = -2 * M_PI, qmax(k) = 2 * M_PI;
  KDL::ChainFkSolverPos_recursive fk(chain);
  KDL::ChainIkSolverVel_pinv vel(chain);
  KDL::ChainIkSolverPos_NR_JL ik(chain, qmin, qmax, fk, vel, 100, 1e-10);
  std::vector<KDL::Frame> targets;
  std::vector<KDL::JntArray> seeds;
  for (std::size_t i = 0; i < kPool; ++i) {
    targets.push_back(toKdl(pool().pose[i]));
    KDL::JntArray s(6);
    for (int k = 0; k < 6; ++k) s(k) = pool().q[i](k) + 0.3;
    seeds.push_back(s);
  }
  KDL::JntArray out(6);
  std::size_t i = 0, ok = 0, n = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % kPool;
    ok += ik.CartToJnt(seeds[k], targets[k], out) >= 0;
    ++n;
    benchmark::DoNotOptimize(out);
  }
  st.counters["converged"] = double(ok) / double(n);
}
BENCHMARK(BM_kdl_ik_nrjl_puma_one);
#endif

}  // namespace

BENCHMARK_MAIN();
