// Cusp points with precision escalation for near-degenerate arms (GF §5.2.3; see cusps.hpp for
// the cluster analysis that sets the threshold), and the a1 → 0 limit of the cusp points.
#include "soma/geometry/cuspidal/cusps.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace soma {

namespace {

/// The analysis in S of the double robot, brought back to double.
template <class S> CuspAnalysis<double> solveIn(const SerialRobot<double>& robot, const Arm3RFrame<double>& frame) {
  const SerialRobot<S> r = robot.template cast<S>();
  const CuspAnalysis<S> c = findCusps(r);
  CuspAnalysis<double> out;
  out.frame = frame;
  out.phase = scalarCast<double>(c.phase);
  out.candidates = c.candidates;
  for (const auto& x : c.polynomial) out.polynomial.push_back(scalarCast<double>(x));
  for (const auto& k : c.cusps) {
    CuspPoint<double> p;
    p.rho = scalarCast<double>(k.rho);
    p.z = scalarCast<double>(k.z);
    p.posture = JointVector<double>(k.posture.size());
    for (int i = 0; i < k.posture.size(); ++i) p.posture(i) = scalarCast<double>(k.posture(i));
    p.residual = scalarCast<double>(k.residual);
    out.cusps.push_back(p);
  }
  out.scalar = std::string(scalarName<S>());
  return out;
}

std::string format3g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

/// Restores the mpfr precision on scope exit.
struct MpfrBitsGuard {
  int saved = mpfrBits();
  ~MpfrBitsGuard() { setMpfrBits(saved); }
};

}  // namespace

// GF §5.2.3, GF-5.2.3-cuspidal-posture-change (near-degenerate arms)
CuspAnalysis<double> findCuspsAdaptive(const SerialRobot<double>& robot) {
  const auto t0 = std::chrono::steady_clock::now();
  CuspAnalysis<double> out = findCusps(robot);
  out.scalar = "double";
  if (cuspsIllConditioned(out.frame)) {
    const double m = cuspClusterParameter(out.frame);
    const Arm3RFrame<double> frame = out.frame;
    std::string why = "min(s1², (2a1/L)²) = " + format3g(m) + " ≤ √eps of double (" +
                      format3g(Tolerance<double>::sqrtEpsilon()) +
                      "): the cusp polynomial's roots cluster below double's resolution";
    const __float128 mq = cuspClusterParameter(arm3RFrame(robot.cast<__float128>()));
    if (!(mq <= Tolerance<__float128>::sqrtEpsilon())) {
      out = solveIn<__float128>(robot, frame);
      why += "; re-solved in float128";
    } else {
      // √eps = 2^{−bits/2} ≤ m / 2⁸: bits ≥ 2 (8 − log2 m), in steps of 64, at least the default.
      // mpfr's working precision is process state (setMpfrBits): one escalation at a time.
      static std::mutex mpfrMutex;
      const std::lock_guard<std::mutex> lock(mpfrMutex);
      MpfrBitsGuard guard;
      const int need = int(std::ceil(2 * (8 - std::log2(m)) / 64.0)) * 64;
      const int bits = std::max(guard.saved, need);
      setMpfrBits(bits);
      out = solveIn<mpreal>(robot, frame);
      why += "; ill-conditioned in float128 too (√eps = " +
             format3g(scalarCast<double>(Tolerance<__float128>::sqrtEpsilon())) + "): re-solved in mpfr at " +
             std::to_string(bits) + " bits";
    }
    out.conditioning = why;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// GF §5.2.3 (the a1 → 0+ limit of the cusp points; derivation in cusps.hpp)
std::vector<Vec2<double>> cuspLimitA1Zero(const SerialRobot<double>& robot) {
  const Arm3RFrame<double> f = arm3RFrame(robot);
  std::vector<Vec2<double>> out;
  if (std::abs(f.c1) > Tolerance<double>::rank()) return out;
  // W, V depend on a(φ) − r2 only: the same for every a1 of a DH family (axis 2 and everything
  // after it move together along the common normal).
  const double base = std::atan2(f.W(2), f.W(1));
  for (double phi : {base, base + 3.14159265358979323846}) {
    const double w = f.W(0) + f.W(1) * std::cos(phi) + f.W(2) * std::sin(phi);
    const double v = f.V(0) + f.V(1) * std::cos(phi) + f.V(2) * std::sin(phi);
    const double h = w - v * v;  // squared distance of the tool point from axis 2
    if (!(h > Tolerance<double>::rank() * f.scale * f.scale)) return {};
    out.emplace_back(std::abs(v), f.z0 + std::sqrt(h));
    out.emplace_back(std::abs(v), f.z0 - std::sqrt(h));
  }
  std::sort(out.begin(), out.end(), [](const Vec2<double>& x, const Vec2<double>& y) {
    return x(1) < y(1) || (x(1) == y(1) && x(0) < y(0));
  });
  return out;
}

}  // namespace soma
