// Inverse dynamics and the generalised inertia (mass matrix) of a 6-joint (PUMA 560, Armstrong et
// al. 1986 inertias from studies/robots/puma560_dynamics.json) and a 7-joint arm (iiwa-like DH
// geometry with synthetic inertias), in soma (GF §13.3 recursive Newton–Euler in home
// coordinates; GF §13.2.2 A_ij = s_iᵀN̄_max(i,j)s_j) and in Orocos KDL (ChainIdSolver_RNE,
// ChainDynParam::JntToMass) on the same robot in the same binary. Before timing, main() checks that
// both libraries give the same torques and mass matrices (1e-10 relative) on the pool.
// Results: papers/benchmarks/dynamics.md.
#include "soma/geometry/dynamics/robot_dynamics.hpp"

#include <benchmark/benchmark.h>

#ifdef SOMA_HAVE_KDL
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#endif

#include <cstdio>
#include <random>

namespace {

using namespace soma;
using S = double;
constexpr std::size_t kPool = 256;

struct Link {
  double a, alpha, d, m, cx, cy, cz, ixx, iyy, izz;
};
// PUMA 560: DH of studies/robots/puma560.json, inertias of puma560_dynamics.json (same numbers).
const Link kPuma[6] = {
    {0, M_PI / 2, 0, 1.0, 0, 0, 0, 0.35, 0.35, 0.35},
    {0.4318, 0, 0, 17.4, -0.3638, 0.006, 0.2275, 0.13, 0.524, 0.539},
    {0.0203, -M_PI / 2, 0.15005, 4.8, -0.0203, -0.0141, 0.070, 0.066, 0.086, 0.0125},
    {0, M_PI / 2, 0.4318, 0.82, 0, 0.019, 0, 1.8e-3, 1.3e-3, 1.8e-3},
    {0, -M_PI / 2, 0, 0.34, 0, 0, 0, 0.3e-3, 0.4e-3, 0.3e-3},
    {0, 0, 0.05625, 0.09, 0, 0, 0.032, 0.15e-3, 0.15e-3, 0.04e-3}};
// 7-joint arm with the DH geometry of a KUKA LBR iiwa 14 and synthetic (made-up) inertias.
const Link kArm7[7] = {{0, -M_PI / 2, 0.36, 4.0, 0, -0.03, -0.03, 0.03, 0.03, 0.01},
                       {0, M_PI / 2, 0, 4.0, 0, 0.04, 0.06, 0.04, 0.01, 0.04},
                       {0, M_PI / 2, 0.42, 3.0, 0, 0.03, -0.03, 0.03, 0.03, 0.01},
                       {0, -M_PI / 2, 0, 2.7, 0, -0.03, 0.06, 0.02, 0.01, 0.02},
                       {0, -M_PI / 2, 0.4, 1.7, 0, 0.02, -0.02, 0.01, 0.01, 0.005},
                       {0, M_PI / 2, 0, 1.8, 0, -0.01, 0.01, 0.005, 0.004, 0.005},
                       {0, 0, 0.126, 0.3, 0, 0, 0.02, 0.001, 0.001, 0.001}};

template <std::size_t N> SerialDynamics<S> somaRobot(const Link (&L)[N]) {
  std::vector<DHRow<S>> rows;
  std::vector<SpatialInertia<S>> links;
  for (const auto& l : L) {
    rows.push_back({JointType::Revolute, l.a, l.alpha, l.d, 0});
    links.emplace_back(l.m, Vec3<S>(l.cx, l.cy, l.cz), Mat3<S>(Vec3<S>(l.ixx, l.iyy, l.izz).asDiagonal()));
  }
  return serialDynamicsOf(SerialRobot<S>::fromDH(rows), links, 9.81);
}

struct Pool {
  std::vector<DynVector<S>> q, qd, qdd;
  explicit Pool(int n) {
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u(-3, 3);
    for (std::size_t i = 0; i < kPool; ++i) {
      DynVector<S> a(n), b(n), c(n);
      for (int k = 0; k < n; ++k) {
        a(k) = u(g);
        b(k) = u(g);
        c(k) = u(g);
      }
      q.push_back(a);
      qd.push_back(b);
      qdd.push_back(c);
    }
  }
};
const SerialDynamics<S>& puma() {
  static const SerialDynamics<S> r = somaRobot(kPuma);
  return r;
}
const SerialDynamics<S>& arm7() {
  static const SerialDynamics<S> r = somaRobot(kArm7);
  return r;
}
const Pool& pool(int n) {
  static const Pool p6(6), p7(7);
  return n == 6 ? p6 : p7;
}

void somaRnea(benchmark::State& st, const SerialDynamics<S>& r) {
  const Pool& p = pool(r.dof());
  DynVector<S> tau(r.dof());
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % kPool;
    r.inverseDynamics(p.q[k], p.qd[k], p.qdd[k], tau);
    benchmark::DoNotOptimize(tau.data());
  }
}
void somaMass(benchmark::State& st, const SerialDynamics<S>& r) {
  const Pool& p = pool(r.dof());
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(r.massMatrix(p.q[i++ % kPool]));
}
void BM_soma_rnea_puma(benchmark::State& st) { somaRnea(st, puma()); }
void BM_soma_rnea_arm7(benchmark::State& st) { somaRnea(st, arm7()); }
void BM_soma_mass_puma(benchmark::State& st) { somaMass(st, puma()); }
void BM_soma_mass_arm7(benchmark::State& st) { somaMass(st, arm7()); }
BENCHMARK(BM_soma_rnea_puma);
BENCHMARK(BM_soma_rnea_arm7);
BENCHMARK(BM_soma_mass_puma);
BENCHMARK(BM_soma_mass_arm7);

#ifdef SOMA_HAVE_KDL
template <std::size_t N> KDL::Chain kdlChain(const Link (&L)[N]) {
  KDL::Chain c;
  for (const auto& l : L) {
    const KDL::Frame tip = KDL::Frame::DH(l.a, l.alpha, l.d, 0);
    // KDL's segment inertia is expressed in the segment's TIP frame (as kdl_parser builds it from a
    // URDF link), which for Frame::DH is the DH frame F_i of link i: the robot file's frame.
    const KDL::RigidBodyInertia inTip(l.m, KDL::Vector(l.cx, l.cy, l.cz),
                                      KDL::RotationalInertia(l.ixx, l.iyy, l.izz, 0, 0, 0));
    c.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ), tip, inTip));
  }
  return c;
}
struct KdlPool {
  std::vector<KDL::JntArray> q, qd, qdd;
  explicit KdlPool(int n) {
    const Pool& p = pool(n);
    for (std::size_t i = 0; i < kPool; ++i) {
      KDL::JntArray a{unsigned(n)}, b{unsigned(n)}, c{unsigned(n)};
      for (int k = 0; k < n; ++k) {
        a(unsigned(k)) = p.q[i](k);
        b(unsigned(k)) = p.qd[i](k);
        c(unsigned(k)) = p.qdd[i](k);
      }
      q.push_back(a);
      qd.push_back(b);
      qdd.push_back(c);
    }
  }
};
const KdlPool& kdlPool(int n) {
  static const KdlPool p6(6), p7(7);
  return n == 6 ? p6 : p7;
}
const KDL::Vector kGravity(0, 0, -9.81);

template <std::size_t K> void kdlRnea(benchmark::State& st, const Link (&L)[K]) {
  constexpr std::size_t N = K;
  const KDL::Chain chain = kdlChain(L);
  KDL::ChainIdSolver_RNE id(chain, kGravity);
  const KdlPool& p = kdlPool(int(N));
  KDL::JntArray tau{unsigned(N)};
  KDL::Wrenches f(N, KDL::Wrench::Zero());
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % kPool;
    id.CartToJnt(p.q[k], p.qd[k], p.qdd[k], f, tau);
    benchmark::DoNotOptimize(tau.data.data());
  }
}
template <std::size_t K> void kdlMass(benchmark::State& st, const Link (&L)[K]) {
  constexpr std::size_t N = K;
  const KDL::Chain chain = kdlChain(L);
  KDL::ChainDynParam dp(chain, kGravity);
  const KdlPool& p = kdlPool(int(N));
  KDL::JntSpaceInertiaMatrix M{unsigned(N)};
  std::size_t i = 0;
  for (auto _ : st) {
    dp.JntToMass(p.q[i++ % kPool], M);
    benchmark::DoNotOptimize(M.data.data());
  }
}
void BM_kdl_rnea_puma(benchmark::State& st) { kdlRnea(st, kPuma); }
void BM_kdl_rnea_arm7(benchmark::State& st) { kdlRnea(st, kArm7); }
void BM_kdl_mass_puma(benchmark::State& st) { kdlMass(st, kPuma); }
void BM_kdl_mass_arm7(benchmark::State& st) { kdlMass(st, kArm7); }
BENCHMARK(BM_kdl_rnea_puma);
BENCHMARK(BM_kdl_rnea_arm7);
BENCHMARK(BM_kdl_mass_puma);
BENCHMARK(BM_kdl_mass_arm7);

/// Same robot in both libraries: largest relative difference of τ and of A over the pool.
template <std::size_t K> bool agree(const char* name, const Link (&L)[K], const SerialDynamics<S>& r) {
  constexpr std::size_t N = K;
  const KDL::Chain chain = kdlChain(L);
  KDL::ChainIdSolver_RNE id(chain, kGravity);
  KDL::ChainDynParam dp(chain, kGravity);
  const KdlPool& kp = kdlPool(int(N));
  const Pool& p = pool(int(N));
  KDL::JntArray tau{unsigned(N)};
  KDL::Wrenches f(N, KDL::Wrench::Zero());
  KDL::JntSpaceInertiaMatrix M{unsigned(N)};
  double et = 0, em = 0;
  for (std::size_t k = 0; k < kPool; ++k) {
    id.CartToJnt(kp.q[k], kp.qd[k], kp.qdd[k], f, tau);
    const DynVector<S> t = r.inverseDynamics(p.q[k], p.qd[k], p.qdd[k]);
    et = std::max(et, (t - tau.data).cwiseAbs().maxCoeff() / t.cwiseAbs().maxCoeff());
    dp.JntToMass(kp.q[k], M);
    const DynMatrix<S> A = r.massMatrix(p.q[k]);
    em = std::max(em, (A - M.data).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff());
  }
  std::printf("# %s: soma vs KDL over %zu states: torque %.2e, mass matrix %.2e (relative)\n", name, kPool, et, em);
  return et <= 1e-10 && em <= 1e-10;
}
#endif

}  // namespace

int main(int argc, char** argv) {
#ifdef SOMA_HAVE_KDL
  const bool okPuma = agree("PUMA 560", kPuma, puma());  // both run: each prints its line
  const bool okArm7 = agree("7-joint arm", kArm7, arm7());
  const bool ok = okPuma && okArm7;
  if (!ok) {
    std::fprintf(stderr, "soma and KDL disagree: not timing different robots\n");
    return 1;
  }
#endif
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("cxx_flags", SOMA_BENCH_CXX_FLAGS);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
