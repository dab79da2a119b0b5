// Studies of GF §5.1–5.2 (3R wrists and 3R arms): the wrist's forward kinematics, θ2 from the
// quadratic, θ1/θ3 (E5.1), the RPY example (E5.2), the reachability discriminant, det J and the
// posture, the revolute-joint exponential, the 3R arm's quartic, θ2 recovery (E5.6), the elbow
// manipulator's 8 postures, and the finger/PUMA example (E5.4–E5.5). Every study runs in the asked
// scalar (--scalar): the draws are made in double and cast to S, the book's values are exact
// fractions or decimal strings parsed in S, and every threshold is a multiple of ε of S.
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <map>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using draws::frac;
using draws::maxOf;
using draws::minOf;
using draws::printedTol;
using draws::uni;
using std::abs;
using std::cos;
using std::hypot;
using std::sin;
using std::sqrt;
const char* kChapter = "GF 5 — A little kinematics";

template <class S> Mat3<S> rot(const Vec3<S>& v, const S& th) { return SO3Tangent<S>(Vec3<S>(v * th)).exp().matrix(); }
/// A random unit vector: three normal draws in double (the same inputs on every rung), normalised in S.
template <class S> Vec3<S> unit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  const double x = n(g), y = n(g), z = n(g);
  return Vec3<S>(scalarCast<S>(x), scalarCast<S>(y), scalarCast<S>(z)).normalized();
}
template <class S> S ang(std::mt19937_64& g) { return uni<S>(g, -3, 3); }
template <class S> S wrapDiff(const S& a, const S& b) { return abs(S(sin((a - b) / S(2)))); }

// GF §5.1, GF-5.1-wrist-fk: Rodrigues e^{θv}u = u + sin θ v×u + (1−cos θ) v×(v×u) vs the
// exponential of SO(3), and the wrist robot's FK vs the product of exponentials.
template <class S> void wristFk(Context& c) {
  std::mt19937_64 g(501);
  S worst(0), worstFk(0);
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v = unit<S>(g), u = unit<S>(g);
    const S th = k == 0 ? S(0) : k == 1 ? pi<S>() : ang<S>(g);
    const Vec3<S> rod = u + sin(th) * v.cross(u) + (S(1) - cos(th)) * v.cross(v.cross(u));
    worst = maxOf(worst, S((rod - rot(v, th) * u).norm()));
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) j.axis = unit<S>(g);
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>());
    const S q0 = ang<S>(g), q1 = ang<S>(g);
    const Vec3<S> q(q0, q1, th);
    const Mat3<S> R = rot(js[0].axis, q(0)) * rot(js[1].axis, q(1)) * rot(js[2].axis, q(2));
    worstFk = maxOf(worstFk, S((robot.fk(JointVector<S>(q)).rotation() - R).norm()));
  }
  c.checkResidual("Rodrigues formula vs exp of so(3) (50 draws incl. θ = 0, π; 16 ε)", worst, Tolerance<S>::identity(16));
  c.checkResidual("wrist FK = e^{θ1 v1} e^{θ2 v2} e^{θ3 v3} (16 ε)", worstFk, Tolerance<S>::identity(16));
}

// GF §5.1, GF-5.1-wrist-theta2: the identity for v1ᵀRv3 and the quadratic in cos θ2.
template <class S> void wristTheta2(Context& c) {
  std::mt19937_64 g(502);
  S worstId(0), worstPair(0);
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v1 = unit<S>(g), v2 = unit<S>(g), v3 = unit<S>(g);
    const S t0 = ang<S>(g), t1 = ang<S>(g), t2 = ang<S>(g);
    const Vec3<S> th(t0, t1, t2);
    const Mat3<S> R = rot(v1, th(0)) * rot(v2, th(1)) * rot(v3, th(2));
    const S lhs = v1.dot(R * v3);
    const S rhs = v1.dot(v3) + sin(th(1)) * v1.dot(v2.cross(v3)) + (S(1) - cos(th(1))) * v1.dot(v2.cross(v2.cross(v3)));
    worstId = maxOf(worstId, S(abs(lhs - rhs)));
    const S T = v1.dot(v2.cross(v3));
    const S a = (lhs - v1.dot(v2) * v2.dot(v3)) / T, b = (v1.dot(v2) * v2.dot(v3) - v1.dot(v3)) / T;
    const S disc = maxOf(S(0), S(S(1) - a * a + b * b));
    S best(1e9);
    for (int s : {-1, 1}) {
      const S cs = (-a * b + S(s) * sqrt(disc)) / (b * b + S(1)), sn = (a + S(s) * b * sqrt(disc)) / (b * b + S(1));
      best = minOf(best, S(hypot(cs - cos(th(1)), sn - sin(th(1)))));
    }
    worstPair = maxOf(worstPair, best);
  }
  c.checkResidual("v1ᵀRv3 = v1·v3 + sin θ2 v1·(v2×v3) + (1−cos θ2) v1·(v2×(v2×v3)) (50 random, 16 ε)", worstId,
                  Tolerance<S>::identity(16));
  // Division by v1·(v2×v3) amplifies round-off for nearly coplanar axes, and √disc of a nearly double
  // root loses half the digits: tolerance √ε.
  c.checkResidual("one of the two (cos θ2, sin θ2) of the book's formula is the true θ2 (√ε)", worstPair,
                  Tolerance<S>::sqrtEpsilon());
}

// GF §5.1, GF-5.1-wrist-theta1-theta3 (E5.1)
template <class S> void wristTheta13(Context& c) {
  std::mt19937_64 g(503);
  S worst[4] = {S(0), S(0), S(0), S(0)}, printedMin(1e9);
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v1 = unit<S>(g), v2 = unit<S>(g), v3 = unit<S>(g);
    const S t0 = ang<S>(g), t1 = ang<S>(g), t2 = ang<S>(g);
    const Vec3<S> th(t0, t1, t2);
    const Mat3<S> R = rot(v1, th(0)) * rot(v2, th(1)) * rot(v3, th(2));
    const Vec3<S> x = rot(v2, S(-th(1))) * v1, y = rot(v2, th(1)) * v3;
    const S yv = y.dot(v1), xv = x.dot(v3);
    worst[0] = maxOf(worst[0], S(abs(y.dot(R * v3) - (yv * yv + (S(1) - yv * yv) * cos(th(0))))));
    const S corrected = -y.cross(v1).squaredNorm() * sin(th(0));
    worst[1] = maxOf(worst[1], S(abs(y.cross(v1).dot(R * v3) - corrected)));
    if (corrected != S(0)) printedMin = minOf(printedMin, S(abs(y.cross(v1).dot(R * v3) + corrected) / abs(corrected)));
    worst[2] = maxOf(worst[2], S(abs(v1.dot(R * x) - (xv * xv + (S(1) - xv * xv) * cos(th(2))))));
    worst[3] = maxOf(worst[3], S(abs(v1.dot(R * x.cross(v3)) - x.cross(v3).squaredNorm() * sin(th(2)))));
  }
  const S tol = Tolerance<S>::identity(32);
  c.checkResidual("yᵀRv3 = (y·v1)² + (1 − (y·v1)²) cos θ1 (32 ε)", worst[0], tol);
  c.checkResidual("(y×v1)ᵀRv3 = −|y×v1|² sin θ1 (corrected sign, E5.1; 32 ε)", worst[1], tol);
  // The smallest relative miss over 50 draws, against the corrected formula's 32 ε.
  c.checkPrintedFails("(y×v1)ᵀRv3 = +|y×v1|² sin θ1", "E5.1", printedMin, tol);
  c.checkResidual("v1ᵀRx = (x·v3)² + (1 − (x·v3)²) cos θ3 (32 ε)", worst[2], tol);
  c.checkResidual("v1ᵀR(x×v3) = |x×v3|² sin θ3 (32 ε)", worst[3], tol);
}

// GF §5.1, GF-5.1-rpy-wrist-example (E5.2)
template <class S> void rpyExample(Context& c) {
  const Vec3<S> k = Vec3<S>::UnitZ(), j = Vec3<S>::UnitY(), i = Vec3<S>::UnitX();
  const Vec3<S> th(frac<S>(7, 10), frac<S>(-4, 10), frac<S>(22, 10));
  const Mat3<S> R = rot(k, th(0)) * rot(j, th(1)) * rot(i, th(2));
  // r_ij is a sum of products of three rotations' entries (≈ 4 ε), the division by cos θ2 ≈ 0.92 adds 1 ε: 8 ε
  const S tol = Tolerance<S>::identity(8);
  c.checkNear("sin θ2 = −r31 (corrected, E5.2; 7 decimals + 8 ε)", fromString<S>("-0.3894183"), S(-R(2, 0)),
              printedTol<S>(7, 8));
  c.checkPrintedFails("sin θ2 = r13", "E5.2", S(abs(R(0, 2) - sin(th(1)))), tol);
  const S c2 = cos(th(1));
  c.checkNear("sin θ1 = r21 / cos θ2 (corrected; 8 ε)", S(sin(th(0))), S(R(1, 0) / c2), tol);
  c.checkNear("sin θ3 = r32 / cos θ2 (corrected; 8 ε)", S(sin(th(2))), S(R(2, 1) / c2), tol);
  c.checkPrintedFails("sin θ3 = −r32 / cos²θ2", "E5.2", S(abs(-R(2, 1) / (c2 * c2) - sin(th(2)))), tol);
  const auto w = wrist3R<S>(k, j, i, R);
  c.checkEqual("wrist3R returns two postures", 2, int(w.angles.size()));
  S best(1e9);
  for (const auto& a : w.angles) best = minOf(best, S((a - th).norm()));
  c.checkResidual("one posture is θ = (0.7, −0.4, 2.2) (64 ε)", best, Tolerance<S>::identity(64));
  // Gimbal lock θ2 = π/2: flagged, residual still small.
  const Mat3<S> Rg = rot(k, frac<S>(3, 10)) * rot(j, S(pi<S>() / S(2))) * rot(i, frac<S>(-5, 10));
  const auto wg = wrist3R<S>(k, j, i, Rg);
  c.checkEqual("θ2 = π/2: gimbal singularity flagged", 1, wg.gimbal ? 1 : 0);
  S res(0);
  for (const auto& a : wg.angles) res = maxOf(res, S((rot(k, a(0)) * rot(j, a(1)) * rot(i, a(2)) - Rg).norm()));
  c.checkResidual("… and the representative postures reproduce R (64 ε)", res, Tolerance<S>::identity(64));
}

// GF §5.1, GF-5.1-wrist-discriminant-design (E5.3)
template <class S> void discriminantDesign(Context& c) {
  std::mt19937_64 g(504);
  S worst(0);
  for (int k = 0; k < 50; ++k) {
    const S p12 = ang<S>(g), p23 = ang<S>(g), t = ang<S>(g);
    const Vec3<S> v1(cos(p12), -sin(p12), S(0)), v2(S(1), S(0), S(0)), v3(cos(p23), sin(p23) * cos(t), sin(p23) * sin(t));
    const Mat3<S> R = SO3<S>::Random(g).matrix();
    const S T = v1.dot(v2.cross(v3));
    const S a = (v1.dot(R * v3) - v1.dot(v2) * v2.dot(v3)) / T, b = (v1.dot(v2) * v2.dot(v3) - v1.dot(v3)) / T;
    const S st = sin(p12) * sin(p23) * sin(t), s2 = sin(p12) * sin(p23), d = v1.dot(R * v3) - cos(p12) * cos(p23);
    const S lhs = (S(1) - a * a + b * b) * st * st;
    const S rhs = s2 * s2 - d * d;
    worst = maxOf(worst, S(abs(lhs - rhs)));
  }
  c.checkResidual("Δ (sin φ12 sin φ23 sin θ)² = sin²φ12 sin²φ23 − (v1ᵀRv3 − cos φ12 cos φ23)² (64 ε)", worst,
                  Tolerance<S>::identity(64));
  // Reachable fraction of random rotations: 1 only at φ12 = φ23 = π/2.
  auto fraction = [&](const S& p12, const S& p23) {
    const Vec3<S> v1(cos(p12), -sin(p12), S(0)), v2(S(1), S(0), S(0)), v3(cos(p23), sin(p23) * frac<S>(3, 5), sin(p23) * frac<S>(4, 5));
    std::mt19937_64 h(505);
    int ok = 0;
    for (int k = 0; k < 400; ++k) ok += wrist3R<S>(v1, v2, v3, SO3<S>::Random(h).matrix()).angles.empty() ? 0 : 1;
    return ok;
  };
  c.checkEqual("φ12 = φ23 = π/2: every rotation reachable (400 of 400)", 400, fraction(S(pi<S>() / S(2)), S(pi<S>() / S(2))));
  const int f = fraction(S(pi<S>() / S(3)), S(pi<S>() / S(2)));
  c.record("φ12 = π/3, φ23 = π/2: some rotations unreachable", "< 1", fmt::format("{:.3f}", f / 400.0), 1 - f / 400.0, 0, f < 400);
}

// GF §5.1, GF-5.1-wrist-jacobian-posture: det J in three forms; the postures differ by sign det J.
template <class S> void wristJacobian(Context& c) {
  std::mt19937_64 g(506);
  S worst(0);
  int opposite = 0, pairs = 0;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v1 = unit<S>(g), v2 = unit<S>(g), v3 = unit<S>(g);
    const S t0 = ang<S>(g), t1 = ang<S>(g), t2 = ang<S>(g);
    const Vec3<S> th(t0, t1, t2);
    auto detJ = [&](const Vec3<S>& t) {
      Mat3<S> J;
      J.col(0) = v1;
      J.col(1) = rot(v1, t(0)) * v2;
      J.col(2) = rot(v1, t(0)) * rot(v2, t(1)) * v3;
      return S(J.determinant());
    };
    const Vec3<S> y = rot(v2, th(1)) * v3;
    const S d1 = detJ(th), d2 = v1.cross(v2).dot(y), d3 = (cos(th(1)) * v1 + sin(th(1)) * v1.cross(v2)).dot(v2.cross(v3));
    worst = maxOf(worst, maxOf(S(abs(d1 - d2)), S(abs(d1 - d3))));
    const auto w = wrist3R<S>(v1, v2, v3, rot(v1, th(0)) * rot(v2, th(1)) * rot(v3, th(2)));
    if (w.angles.size() == 2) {
      ++pairs;
      if (detJ(w.angles[0]) * detJ(w.angles[1]) < S(0)) ++opposite;
    }
  }
  c.checkResidual("det J = (v1×v2)·y = (cos θ2 v1 + sin θ2 v1×v2)·(v2×v3) (32 ε)", worst, Tolerance<S>::identity(32));
  c.checkEqual("the two postures have opposite signs of det J (50 random wrists)", pairs, opposite);
}

// GF §5.2.1, GF-5.2.1-revolute-joint-exp
template <class S> void revoluteExp(Context& c) {
  std::mt19937_64 g(507);
  S worst(0), inv(0);
  for (int k = 0; k < 50; ++k) {
    SerialJoint<S> j;
    j.axis = unit<S>(g);
    j.point = draws::rv3<S>(g) * (k < 5 ? S(1000000) : S(1));
    const S th = k == 5 ? pi<S>() : ang<S>(g);
    const Vec3<S> p = draws::rv3<S>(g), d = p - j.point;
    const Vec3<S> pp = p + sin(th) * j.axis.cross(d) + (S(1) - cos(th)) * j.axis.cross(j.axis.cross(d));
    const SE3<S> e = (j.twist() * th).exp();
    const S scale = maxOf(S(1), S(j.point.norm()));
    worst = maxOf(worst, S((pp - e.act(p)).norm() / scale));
    worst = maxOf(worst, S((pp - j.motion(th).act(p)).norm() / scale));
    inv = maxOf(inv, S(maxOf(S(abs(pp.dot(j.axis) - p.dot(j.axis))), S(abs((pp - j.point).norm() - d.norm()))) / scale));
  }
  c.checkResidual("p′ = p + sin θ v×(p−r) + (1−cos θ) v×(v×(p−r)) = exp(θS)p (|r| up to 1e6, θ = π; relative to max(1, |r|), 64 ε)",
                  worst, Tolerance<S>::identity(64));
  c.checkResidual("invariants p′·v and |p′ − r| (relative to max(1, |r|), 64 ε)", inv, Tolerance<S>::identity(64));
}

struct ArmStats {
  std::map<int, int> counts;
  int recovered = 0, trials = 0, odd = 0;
  double worst = 0;
};
template <class S> ArmStats armSweep(int trials, std::uint64_t seed, S& worst) {
  std::mt19937_64 g(seed);
  ArmStats s;
  worst = S(0);
  // A posture is the drawn one when every joint is within √ε of it (the quartic's roots are
  // accurate to √ε at worst, at a nearly double root).
  const S same = Tolerance<S>::sqrtEpsilon();
  for (int k = 0; k < trials; ++k) {
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) {
      j.axis = unit<S>(g);
      j.point = draws::rv3<S>(g);
    }
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), draws::rv3<S>(g)));
    const S q0 = ang<S>(g), q1 = ang<S>(g), q2 = ang<S>(g);
    const JointVector<S> q = Vec3<S>(q0, q1, q2);
    const auto sol = solveArm3R(robot, robot.fk(q));
    ++s.counts[int(sol.count())];
    s.odd += sol.count() % 2;
    worst = maxOf(worst, S(sol.worstResidual()));
    for (const auto& p : sol.postures)
      if (wrapDiff(p(0), q(0)) + wrapDiff(p(1), q(1)) + wrapDiff(p(2), q(2)) < same) {
        ++s.recovered;
        break;
      }
    ++s.trials;
  }
  return s;
}

// GF §5.2.1, GF-5.2.1-3r-ik-procedure
template <class S> void armProcedure(Context& c) {
  S worst;
  const ArmStats s = armSweep<S>(300, 508, worst);
  c.checkEqual("true joint angles recovered (300 random arms and targets)", s.trials, s.recovered);
  c.checkEqual("counts even", 0, s.odd);
  c.checkEqual("counts ≤ 4", 0, int(s.counts.upper_bound(4) != s.counts.end()));
  c.checkResidual("worst position residual |p(q) − p|/L (4096 ε)", worst, Tolerance<S>::identity(4096));
  std::string h;
  for (const auto& [n, k] : s.counts) h += fmt::format("{}{}×{}", h.empty() ? "" : ", ", k, n);
  c.note("posture counts: " + h + " (the catalogue's run: 18×2, 12×4 of 30)");
  c.checkEqual("4-posture targets occur", 1, s.counts.count(4) ? 1 : 0);
}

// GF §5.2.1, GF-5.2.1-theta2-recovery (E5.6)
template <class S> void theta2Recovery(Context& c) {
  std::mt19937_64 g(509);
  S worst(0);
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v = unit<S>(g), r = draws::rv3<S>(g), a = draws::rv3<S>(g);
    const S th = ang<S>(g);
    const Vec3<S> w = v.cross(a - r), ww = v.cross(w);
    const Vec3<S> b = a + sin(th) * w + (S(1) - cos(th)) * ww;
    const S cs = S(1) - (b - a).dot(ww) / ww.squaredNorm(), sn = (b - a).dot(w) / w.squaredNorm();
    const S ar = (a - r).dot(v);
    const S cs2 = ((a - r).dot(b - r) - ar * ar) / w.squaredNorm();
    const S sn2 = (b - r).dot(w) / w.squaredNorm();
    // Each quotient divides dot products of size |a − r|² by |v × (a − r)|²: its rounding is
    // 16 ε·|a − r|²/|v × (a − r)|² (the condition of the recovery).
    const S kappa = maxOf(S(1), S((a - r).squaredNorm() / w.squaredNorm()));
    worst = maxOf(worst, S(maxOf(maxOf(S(abs(cs - cos(th))), S(abs(sn - sin(th)))), maxOf(S(abs(cs2 - cos(th))), S(abs(sn2 - sin(th))))) /
                           kappa));
  }
  c.checkResidual("cos θ2, sin θ2 from b − a and (corrected E5.6) from (a−r)·(b−r), (b−r)·(v×(a−r)) (16 ε·|a − r|²/|v×(a − r)|²)",
                  worst, Tolerance<S>::identity(16));
}

// GF §5.2.1, GF-5.2.1-elbow-pieper: PUMA-like elbow manipulator, 8 postures.
template <class S> void elbowPieper(Context& c) {
  const auto robot = puma560Robot<S>();
  std::mt19937_64 g(510);
  int eight = 0, max = 0;
  S worst(0);
  for (int k = 0; k < 100; ++k) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = ang<S>(g);
    const auto sol = solvePieper(robot, robot.fk(q));
    eight += sol.count() == 8;
    max = std::max(max, int(sol.count()));
    worst = maxOf(worst, S(sol.worstResidual()));
  }
  c.checkEqual("largest count over 100 random poses (4 arm postures × 2 wrist postures)", 8, max);
  c.checkResidual("every posture reproduces the pose (4096 ε)", worst, Tolerance<S>::identity(4096));
  c.note(fmt::format("{} of 100 random poses have all 8 postures real", eight));
}

// GF §5.2.2, GF-5.2.2-finger-puma-example (E5.4, E5.5)
template <class S> void fingerExample(Context& c) {
  const S l1 = frac<S>(8, 10), l2 = frac<S>(11, 10), l3 = frac<S>(6, 10);
  std::vector<SerialJoint<S>> js(3);
  js[0].axis = Vec3<S>::UnitZ();
  js[1].axis = Vec3<S>::UnitX(), js[1].point = Vec3<S>(S(0), l1, S(0));
  js[2].axis = Vec3<S>::UnitX(), js[2].point = Vec3<S>(S(0), S(l1 + l2), S(0));
  const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), Vec3<S>(S(0), S(l1 + l2 + l3), S(0))));
  const Vec3<S> q(frac<S>(9, 10), frac<S>(-5, 10), frac<S>(12, 10));
  const Vec3<S> p = robot.fk(JointVector<S>(q)).translation();
  const S r2 = p.squaredNorm(), rho = hypot(p.x(), p.y());
  const S A = (r2 + l1 * l1 - l2 * l2 - l3 * l3) / (S(2) * l1), B = -l2 * l3 / l1;
  const S c3a = (-A + rho) / B, c3b = (-A - rho) / B;
  // (−A ± ρ)/B with |A|, ρ ≤ 3 and |B| = 0.825: a few ε of each term, 64 ε in all
  c.checkNear("corrected A, B (E5.4): a root cos θ3 = 0.3623578 (7 decimals + 64 ε)", fromString<S>("0.3623578"), minOf(c3a, c3b),
              printedTol<S>(7, 64));
  c.checkNear("… the other root 5.754470 (infeasible; 6 decimals + 64 ε)", fromString<S>("5.754470"), maxOf(c3a, c3b), printedTol<S>(6, 64));
  c.checkNear("true cos θ3 (64 ε)", S(cos(q(2))), minOf(c3a, c3b), Tolerance<S>::identity(64));
  const auto sol = solveArm3R(robot, robot.fk(JointVector<S>(q)));
  c.checkEqual("solveArm3R: 2 postures at this target", 2, int(sol.count()));
  c.checkResidual("… each reaching p (4096 ε)", S(sol.worstResidual()), Tolerance<S>::identity(4096));
  // The printed A, B (E5.4) and the printed cos θ3 = A/B ± √(x²+y²) (E5.5).
  const S L = l1 + l2 + l3;
  const S Ap = (L * L - r2 + S(2) * (l1 + l2) * p.y() - S(2) * l1 * l1 - S(2) * l1 * l2) / (S(2) * l2);
  const S Bp = -l1 * l3 / l2;
  const S pr = minOf(S(abs(Ap / Bp + rho - cos(q(2)))), S(abs(Ap / Bp - rho - cos(q(2)))));
  c.checkPrintedFails("cos θ3 = A/B ± √(x²+y²) with the printed A, B", "E5.4, E5.5", pr, Tolerance<S>::identity(64));
}

SOMA_STUDY_SCALAR("GF-5.1-wrist-fk", "3R wrist forward kinematics: Rodrigues and the product of exponentials", "GF §5.1", wristFk);
SOMA_STUDY_SCALAR("GF-5.1-wrist-theta2", "3R wrist: θ2 from v1ᵀRv3 (a quadratic in cos θ2)", "GF §5.1", wristTheta2);
SOMA_STUDY_SCALAR("GF-5.1-wrist-theta1-theta3", "3R wrist: θ1 and θ3 (erratum E5.1)", "GF §5.1", wristTheta13);
SOMA_STUDY_SCALAR("GF-5.1-rpy-wrist-example", "The roll-pitch-yaw wrist (erratum E5.2), gimbal lock", "GF §5.1", rpyExample);
SOMA_STUDY_SCALAR("GF-5.1-wrist-discriminant-design", "Wrist reachability discriminant and the design angles", "GF §5.1",
                  discriminantDesign);
SOMA_STUDY_SCALAR("GF-5.1-wrist-jacobian-posture", "det J of a wrist and the sign that tells the postures apart", "GF §5.1",
                  wristJacobian);
SOMA_STUDY_SCALAR("GF-5.2.1-revolute-joint-exp", "The exponential of a revolute joint and its invariants", "GF §5.2.1", revoluteExp);
SOMA_STUDY_SCALAR("GF-5.2.1-3r-ik-procedure", "3R arm IK: pencil of conics, quartic, ≤ 4 postures", "GF §5.2.1", armProcedure);
SOMA_STUDY_SCALAR("GF-5.2.1-theta2-recovery", "θ2 from a and b (erratum E5.6)", "GF §5.2.1", theta2Recovery);
SOMA_STUDY_SCALAR("GF-5.2.1-elbow-pieper", "Elbow manipulator with a spherical wrist: 8 postures", "GF §5.2.1", elbowPieper);
SOMA_STUDY_SCALAR("GF-5.2.2-finger-puma-example", "The finger / PUMA arm (errata E5.4, E5.5)", "GF §5.2.2", fingerExample);

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
