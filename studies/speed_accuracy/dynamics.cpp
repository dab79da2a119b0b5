// SOMA-dynamics-speed-accuracy: inverse dynamics of a serial chain by the recursive Newton–Euler
// algorithm (GF §13.3) on every rung of the scalar ladder: the time of one call and the worst
// normwise error of the torques against the same algorithm in mpfr at ≥ 2p + 64 bits (the
// robot, state and accelerations converted exactly).
#include "gf13/common.hpp"
#include "soma/studies/mpfr_bits.hpp"

#include <fmt/format.h>

#include <chrono>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using gf13::castRobot;
using gf13::castV;

struct Case {
  DynVector<double> q, qd, qdd;
};

/// The worst max|τ_S − τ_ref| / max|τ_ref| over the cases, and the time per call (median, p95 of
/// `blocks` passes over the cases).
template <class S>
TradeRung measure(const SerialDynamics<double>& robot, const std::vector<Case>& cases, std::size_t n, int blocks,
                  double& worstUlps) {
  const SerialDynamics<S> r = castRobot<S>(robot);
  std::vector<DynVector<S>> q, qd, qdd;
  for (std::size_t k = 0; k < n; ++k) {
    q.push_back(castV<S>(cases[k].q));
    qd.push_back(castV<S>(cases[k].qd));
    qdd.push_back(castV<S>(cases[k].qdd));
  }
  DynVector<S> tau(robot.dof());
  std::vector<double> per;
  std::vector<DynVector<S>> taus(n);
  for (int b = 0; b < blocks; ++b) {
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n; ++k) {
      r.inverseDynamics(q[k], qd[k], qdd[k], tau);
      if (b == 0) taus[k] = tau;
    }
    per.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / double(n));
  }
  // The reference: the same chain in mpfr at ≥ 2p + 64 bits (the precision restored on any exit).
  const MpfrBitsRestore restore;
  const int oldBits = restore.bits();
  setMpfrBits(std::max(320, 2 * digits<S>() + 64));
  const SerialDynamics<mpreal> ref = castRobot<mpreal>(robot);
  mpreal worst = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const DynVector<mpreal> t =
        ref.inverseDynamics(castV<mpreal>(cases[k].q), castV<mpreal>(cases[k].qd), castV<mpreal>(cases[k].qdd));
    mpreal num = 0, den = 0;
    for (Eigen::Index i = 0; i < t.size(); ++i) {
      const mpreal d = mpfr::abs(scalarCast<mpreal>(taus[k](i)) - t(i)), a = mpfr::abs(t(i));
      if (d > num) num = d;
      if (a > den) den = a;
    }
    if (num / den > worst) worst = num / den;
  }
  TradeRung g;
  g.scalar = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) g.scalar += " (" + std::to_string(oldBits) + " bits)";
  S worstS = scalarCast<S>(worst);
  setMpfrBits(oldBits);
  if constexpr (std::is_same_v<S, mpreal>) worstS.setPrecision(oldBits);  // written in the rung's digits
  g.samples = n;
  timeQuantiles(per, g.medianSeconds, g.p95Seconds);
  g.worstError = toDouble(worstS);
  g.worstErrorText = io::numberText(worstS);
  worstUlps = toDouble(worstS / Tolerance<S>::epsilon());
  g.comment = fmt::format("{:.3g} ulps of {}", worstUlps, scalarName<S>());
  return g;
}

// GF §13.3 (recursive Newton–Euler); SOMA-dynamics-speed-accuracy
void dynamicsTrade(Context& c) {
  std::mt19937_64 g(13032026);
  const int dof = 6;
  // Joint axes along the coordinate axes (x, y, z, x, y, z) through random points: unit screws
  // exactly, in every rung and in the reference (a random unit axis is unit only to double's
  // precision, which the mpfr reference rejects), with random links.
  std::vector<SE3Tangent<double>> screws;
  std::vector<SpatialInertia<double>> links;
  for (int i = 0; i < dof; ++i) {
    Vec3<double> w = Vec3<double>::Zero();
    w(i % 3) = 1;
    screws.emplace_back(gf13::lineScrew(w, gf13::rv3(g)));
    links.push_back(gf13::randomBody(g));
  }
  const SerialDynamics<double> robot(screws, links, 9.81);
  std::vector<Case> cases(200);
  for (auto& k : cases) {
    k.q = gf13::rjoints(g, dof, -3, 3);
    k.qd = gf13::rjoints(g, dof, -2, 2);
    k.qdd = gf13::rjoints(g, dof, -2, 2);
  }
  TradeTable t;
  t.solver = "Inverse dynamics, recursive Newton–Euler, 6R chain (GF §13.3)";
  t.sample = "call";
  t.errorLabel = "worst relative torque error";
  std::array<double, 5> ulps{};
  t.rungs.push_back(measure<float>(robot, cases, 200, 21, ulps[0]));
  t.rungs.push_back(measure<double>(robot, cases, 200, 21, ulps[1]));
  t.rungs.push_back(measure<long double>(robot, cases, 200, 21, ulps[2]));
  t.rungs.push_back(measure<__float128>(robot, cases, 50, 7, ulps[3]));
  t.rungs.push_back(measure<mpreal>(robot, cases, 20, 5, ulps[4]));
  // The error shrinks with the rung: each rung's worst error below the previous one's (the
  // rungs' ε differ by 2^29 at least, so an inversion means a computation not in S).
  for (std::size_t i = 1; i < t.rungs.size(); ++i)
    c.checkEqual(fmt::format("worst torque error in {} below the error in {}", t.rungs[i].scalar, t.rungs[i - 1].scalar),
                 "below", t.rungs[i].worstError < t.rungs[i - 1].worstError ? "below" : "not below");
  // Backward-stable dot products: the normwise forward error of RNEA is a modest multiple of ε
  // times the cancellation in τ; a thousand ulps flags an algorithm that is not computing in S.
  for (std::size_t i = 0; i < t.rungs.size(); ++i)
    c.record(fmt::format("worst torque error in {}, in ulps of the rung (200 random states of one 6R chain, random links)",
                         t.rungs[i].scalar),
             "≤ 1000 ulps", fmt::format("{:.3g} ulps", ulps[i]), ulps[i], 1000.0, ulps[i] <= 1000.0);
  c.note("Time: wall time of one SerialDynamics<S>::inverseDynamics into caller storage (median and p95 of passes "
         "over the states); no rung escalates. The float, long double, float128 and mpfr instantiations of the "
         "library are compiled at -O1, double at -O3 (cmake/SomaInstantiate.cmake).");
  c.trade(std::move(t), "SOMA-dynamics-speed-accuracy.png",
          "Inverse dynamics (recursive Newton–Euler, 6 joints): median time per call (point; bar to the p95) against "
          "the worst relative torque error, one point per scalar (log–log).");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-dynamics-speed-accuracy",
            .title = "Inverse dynamics (RNEA) on every scalar: time per call and worst torque error",
            .source = "GF §13.3",
            .chapter = "soma — speed vs accuracy",
            .scalarGeneric = false,
            .run = [](Context& c) { dynamicsTrade(c); },
            .ladder = true});

}  // namespace soma::studies::SOMA_UNITY_ID
