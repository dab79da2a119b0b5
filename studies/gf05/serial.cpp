// Studies of GF §5.1–5.2 (3R wrists and 3R arms), in double: the wrist's forward kinematics,
// θ2 from the quadratic, θ1/θ3 (E5.1), the RPY example (E5.2), the reachability discriminant,
// det J and the posture, the revolute-joint exponential, the 3R arm's quartic, θ2 recovery
// (E5.6), the elbow manipulator's 8 postures, and the finger/PUMA example (E5.4–E5.5).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <map>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
const char* kChapter = "GF 5 — A little kinematics";

Mat3<S> rot(const Vec3<S>& v, double th) { return SO3Tangent<S>(Vec3<S>(v * th)).exp().matrix(); }
Vec3<S> unit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  return Vec3<S>(n(g), n(g), n(g)).normalized();
}
double ang(std::mt19937_64& g) { return std::uniform_real_distribution<double>(-3, 3)(g); }
double wrapDiff(double a, double b) { return std::abs(std::sin((a - b) / 2)); }

// GF §5.1, GF-5.1-wrist-fk: Rodrigues e^{θv}u = u + sin θ v×u + (1−cos θ) v×(v×u) vs the
// exponential of SO(3), and the wrist robot's FK vs the product of exponentials.
void wristFk(Context& c) {
  std::mt19937_64 g(501);
  double worst = 0, worstFk = 0;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v = unit(g), u = unit(g);
    const double th = k == 0 ? 0.0 : k == 1 ? pi<S>() : ang(g);
    const Vec3<S> rod = u + std::sin(th) * v.cross(u) + (1 - std::cos(th)) * v.cross(v.cross(u));
    worst = std::max(worst, (rod - rot(v, th) * u).norm());
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) j.axis = unit(g);
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>());
    const Vec3<S> q(ang(g), ang(g), th);
    const Mat3<S> R = rot(js[0].axis, q(0)) * rot(js[1].axis, q(1)) * rot(js[2].axis, q(2));
    worstFk = std::max(worstFk, (robot.fk(JointVector<S>(q)).rotation() - R).norm());
  }
  c.checkResidual("Rodrigues formula vs exp of so(3) (50 draws incl. θ = 0, π)", worst, Tolerance<S>::identity(16));
  c.checkResidual("wrist FK = e^{θ1 v1} e^{θ2 v2} e^{θ3 v3}", worstFk, Tolerance<S>::identity(16));
}

// GF §5.1, GF-5.1-wrist-theta2: the identity for v1ᵀRv3 and the quadratic in cos θ2.
void wristTheta2(Context& c) {
  std::mt19937_64 g(502);
  double worstId = 0, worstPair = 0;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v1 = unit(g), v2 = unit(g), v3 = unit(g);
    const Vec3<S> th(ang(g), ang(g), ang(g));
    const Mat3<S> R = rot(v1, th(0)) * rot(v2, th(1)) * rot(v3, th(2));
    const double lhs = v1.dot(R * v3);
    const double rhs = v1.dot(v3) + std::sin(th(1)) * v1.dot(v2.cross(v3)) +
                       (1 - std::cos(th(1))) * v1.dot(v2.cross(v2.cross(v3)));
    worstId = std::max(worstId, std::abs(lhs - rhs));
    const double T = v1.dot(v2.cross(v3));
    const double a = (lhs - v1.dot(v2) * v2.dot(v3)) / T, b = (v1.dot(v2) * v2.dot(v3) - v1.dot(v3)) / T;
    const double disc = std::max(0.0, 1 - a * a + b * b);
    double best = 1e9;
    for (int s : {-1, 1}) {
      const double cs = (-a * b + s * std::sqrt(disc)) / (b * b + 1), sn = (a + s * b * std::sqrt(disc)) / (b * b + 1);
      best = std::min(best, std::hypot(cs - std::cos(th(1)), sn - std::sin(th(1))));
    }
    worstPair = std::max(worstPair, best);
  }
  c.checkResidual("v1ᵀRv3 = v1·v3 + sin θ2 v1·(v2×v3) + (1−cos θ2) v1·(v2×(v2×v3)) (50 random)", worstId,
                  Tolerance<S>::identity(16));
  // Division by v1·(v2×v3) amplifies round-off for nearly coplanar axes: tolerance sqrt-eps scale.
  c.checkResidual("one of the two (cos θ2, sin θ2) of the book's formula is the true θ2", worstPair,
                  Tolerance<S>::sqrtEpsilon());
}

// GF §5.1, GF-5.1-wrist-theta1-theta3 (E5.1)
void wristTheta13(Context& c) {
  std::mt19937_64 g(503);
  double worst[4] = {0, 0, 0, 0}, printedMin = 1e9;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v1 = unit(g), v2 = unit(g), v3 = unit(g);
    const Vec3<S> th(ang(g), ang(g), ang(g));
    const Mat3<S> R = rot(v1, th(0)) * rot(v2, th(1)) * rot(v3, th(2));
    const Vec3<S> x = rot(v2, -th(1)) * v1, y = rot(v2, th(1)) * v3;
    const double yv = y.dot(v1), xv = x.dot(v3);
    worst[0] = std::max(worst[0], std::abs(y.dot(R * v3) - (yv * yv + (1 - yv * yv) * std::cos(th(0)))));
    const double corrected = -y.cross(v1).squaredNorm() * std::sin(th(0));
    worst[1] = std::max(worst[1], std::abs(y.cross(v1).dot(R * v3) - corrected));
    printedMin = std::min(printedMin, std::abs(y.cross(v1).dot(R * v3) + corrected) /
                                          std::max(1e-300, std::abs(corrected)));
    worst[2] = std::max(worst[2], std::abs(v1.dot(R * x) - (xv * xv + (1 - xv * xv) * std::cos(th(2)))));
    worst[3] = std::max(worst[3], std::abs(v1.dot(R * x.cross(v3)) - x.cross(v3).squaredNorm() * std::sin(th(2))));
  }
  c.checkResidual("yᵀRv3 = (y·v1)² + (1 − (y·v1)²) cos θ1", worst[0], Tolerance<S>::identity(32));
  c.checkResidual("(y×v1)ᵀRv3 = −|y×v1|² sin θ1 (corrected sign, E5.1)", worst[1], Tolerance<S>::identity(32));
  c.record("(y×v1)ᵀRv3 = +|y×v1|² sin θ1 [as printed]", "fails (erratum E5.1)",
           fmt::format("smallest relative error {:.3g} over 50 draws", printedMin), printedMin, 1e-12, printedMin > 1e-6);
  c.checkResidual("v1ᵀRx = (x·v3)² + (1 − (x·v3)²) cos θ3", worst[2], Tolerance<S>::identity(32));
  c.checkResidual("v1ᵀR(x×v3) = |x×v3|² sin θ3", worst[3], Tolerance<S>::identity(32));
}

// GF §5.1, GF-5.1-rpy-wrist-example (E5.2)
void rpyExample(Context& c) {
  const Vec3<S> k = Vec3<S>::UnitZ(), j = Vec3<S>::UnitY(), i = Vec3<S>::UnitX();
  const Vec3<S> th(0.7, -0.4, 2.2);
  const Mat3<S> R = rot(k, th(0)) * rot(j, th(1)) * rot(i, th(2));
  c.checkNear("sin θ2 = −r31 (corrected, E5.2)", -0.3894183, -R(2, 0), 5e-8);
  c.record("sin θ2 = r13 [as printed]", "fails (erratum E5.2)", fmt::format("r13 = {:.7f}", R(0, 2)),
           std::abs(R(0, 2) - std::sin(th(1))), 1e-12, std::abs(R(0, 2) - std::sin(th(1))) > 1e-3);
  const double c2 = std::cos(th(1));
  c.checkNear("sin θ1 = r21 / cos θ2 (corrected)", std::sin(th(0)), R(1, 0) / c2, 1e-15);
  c.checkNear("sin θ3 = r32 / cos θ2 (corrected)", std::sin(th(2)), R(2, 1) / c2, 1e-15);
  c.record("sin θ3 = −r32 / cos²θ2 [as printed]", "fails (erratum E5.2)", fmt::format("{:.7f}", -R(2, 1) / (c2 * c2)),
           std::abs(-R(2, 1) / (c2 * c2) - std::sin(th(2))), 1e-12, std::abs(-R(2, 1) / (c2 * c2) - std::sin(th(2))) > 1e-3);
  const auto w = wrist3R<S>(k, j, i, R);
  c.checkEqual("wrist3R returns two postures", 2, int(w.angles.size()));
  double best = 1e9;
  for (const auto& a : w.angles) best = std::min(best, (a - th).norm());
  c.checkResidual("one posture is θ = (0.7, −0.4, 2.2)", best, 1e-14);
  // Gimbal lock θ2 = π/2: flagged, residual still small.
  const Mat3<S> Rg = rot(k, 0.3) * rot(j, pi<S>() / 2) * rot(i, -0.5);
  const auto wg = wrist3R<S>(k, j, i, Rg);
  c.checkEqual("θ2 = π/2: gimbal singularity flagged", 1, wg.gimbal ? 1 : 0);
  double res = 0;
  for (const auto& a : wg.angles) res = std::max(res, (rot(k, a(0)) * rot(j, a(1)) * rot(i, a(2)) - Rg).norm());
  c.checkResidual("… and the representative postures reproduce R", res, 1e-7);
}

// GF §5.1, GF-5.1-wrist-discriminant-design (E5.3)
void discriminantDesign(Context& c) {
  std::mt19937_64 g(504);
  double worst = 0;
  for (int k = 0; k < 50; ++k) {
    const double p12 = ang(g), p23 = ang(g), t = ang(g);
    const Vec3<S> v1(std::cos(p12), -std::sin(p12), 0), v2(1, 0, 0),
        v3(std::cos(p23), std::sin(p23) * std::cos(t), std::sin(p23) * std::sin(t));
    const Mat3<S> R = SO3<S>::Random(g).matrix();
    const double T = v1.dot(v2.cross(v3));
    const double a = (v1.dot(R * v3) - v1.dot(v2) * v2.dot(v3)) / T, b = (v1.dot(v2) * v2.dot(v3) - v1.dot(v3)) / T;
    const double lhs = (1 - a * a + b * b) * std::pow(std::sin(p12) * std::sin(p23) * std::sin(t), 2);
    const double rhs = std::pow(std::sin(p12) * std::sin(p23), 2) - std::pow(v1.dot(R * v3) - std::cos(p12) * std::cos(p23), 2);
    worst = std::max(worst, std::abs(lhs - rhs));
  }
  c.checkResidual("Δ (sin φ12 sin φ23 sin θ)² = sin²φ12 sin²φ23 − (v1ᵀRv3 − cos φ12 cos φ23)²", worst, 1e-12);
  // Reachable fraction of random rotations: 1 only at φ12 = φ23 = π/2.
  auto fraction = [&](double p12, double p23) {
    const Vec3<S> v1(std::cos(p12), -std::sin(p12), 0), v2(1, 0, 0), v3(std::cos(p23), std::sin(p23) * 0.6, std::sin(p23) * 0.8);
    std::mt19937_64 h(505);
    int ok = 0;
    for (int k = 0; k < 400; ++k) ok += wrist3R<S>(v1, v2, v3, SO3<S>::Random(h).matrix()).angles.empty() ? 0 : 1;
    return ok / 400.0;
  };
  c.checkNear("φ12 = φ23 = π/2: every rotation reachable", 1.0, fraction(pi<S>() / 2, pi<S>() / 2), 0.0);
  const double f = fraction(pi<S>() / 3, pi<S>() / 2);
  c.record("φ12 = π/3, φ23 = π/2: some rotations unreachable", "< 1", fmt::format("{:.3f}", f), 1 - f, 0, f < 1);
}

// GF §5.1, GF-5.1-wrist-jacobian-posture: det J in three forms; the postures differ by sign det J.
void wristJacobian(Context& c) {
  std::mt19937_64 g(506);
  double worst = 0;
  int opposite = 0, pairs = 0;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v1 = unit(g), v2 = unit(g), v3 = unit(g);
    const Vec3<S> th(ang(g), ang(g), ang(g));
    auto detJ = [&](const Vec3<S>& t) {
      Mat3<S> J;
      J.col(0) = v1;
      J.col(1) = rot(v1, t(0)) * v2;
      J.col(2) = rot(v1, t(0)) * rot(v2, t(1)) * v3;
      return J.determinant();
    };
    const Vec3<S> y = rot(v2, th(1)) * v3;
    const double d1 = detJ(th), d2 = v1.cross(v2).dot(y),
                 d3 = (std::cos(th(1)) * v1 + std::sin(th(1)) * v1.cross(v2)).dot(v2.cross(v3));
    worst = std::max({worst, std::abs(d1 - d2), std::abs(d1 - d3)});
    const auto w = wrist3R<S>(v1, v2, v3, rot(v1, th(0)) * rot(v2, th(1)) * rot(v3, th(2)));
    if (w.angles.size() == 2) {
      ++pairs;
      if (detJ(w.angles[0]) * detJ(w.angles[1]) < 0) ++opposite;
    }
  }
  c.checkResidual("det J = (v1×v2)·y = (cos θ2 v1 + sin θ2 v1×v2)·(v2×v3)", worst, Tolerance<S>::identity(32));
  c.checkEqual("the two postures have opposite signs of det J (50 random wrists)", pairs, opposite);
}

// GF §5.2.1, GF-5.2.1-revolute-joint-exp
void revoluteExp(Context& c) {
  std::mt19937_64 g(507);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0, inv = 0;
  for (int k = 0; k < 50; ++k) {
    SerialJoint<S> j;
    j.axis = unit(g);
    j.point = Vec3<S>(u(g), u(g), u(g)) * (k < 5 ? 1e6 : 1.0);
    const double th = k == 5 ? pi<S>() : ang(g);
    const Vec3<S> p(u(g), u(g), u(g)), d = p - j.point;
    const Vec3<S> pp = p + std::sin(th) * j.axis.cross(d) + (1 - std::cos(th)) * j.axis.cross(j.axis.cross(d));
    const SE3<S> e = (j.twist() * th).exp();
    worst = std::max(worst, (pp - e.act(p)).norm() / std::max(1.0, j.point.norm()));
    worst = std::max(worst, (pp - j.motion(th).act(p)).norm() / std::max(1.0, j.point.norm()));
    inv = std::max({inv, std::abs(pp.dot(j.axis) - p.dot(j.axis)), std::abs((pp - j.point).norm() - d.norm())});
  }
  c.checkResidual("p′ = p + sin θ v×(p−r) + (1−cos θ) v×(v×(p−r)) = exp(θS)p (|r| up to 1e6, θ = π)", worst,
                  Tolerance<S>::identity(64));
  c.checkResidual("invariants p′·v and |p′ − r|", inv, 1e-9);
}

struct ArmStats {
  std::map<int, int> counts;
  int recovered = 0, trials = 0, odd = 0;
  double worst = 0;
};
ArmStats armSweep(int trials, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  ArmStats s;
  for (int k = 0; k < trials; ++k) {
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) {
      j.axis = unit(g);
      j.point = Vec3<S>(u(g), u(g), u(g));
    }
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), Vec3<S>(u(g), u(g), u(g))));
    const JointVector<S> q = Vec3<S>(ang(g), ang(g), ang(g));
    const auto sol = solveArm3R(robot, robot.fk(q));
    ++s.counts[int(sol.count())];
    s.odd += sol.count() % 2;
    s.worst = std::max(s.worst, sol.worstResidual());
    for (const auto& p : sol.postures)
      if (wrapDiff(p(0), q(0)) + wrapDiff(p(1), q(1)) + wrapDiff(p(2), q(2)) < 1e-8) {
        ++s.recovered;
        break;
      }
    ++s.trials;
  }
  return s;
}

// GF §5.2.1, GF-5.2.1-3r-ik-procedure
void armProcedure(Context& c) {
  const ArmStats s = armSweep(300, 508);
  c.checkEqual("true joint angles recovered (300 random arms and targets)", s.trials, s.recovered);
  c.checkEqual("counts even", 0, s.odd);
  c.checkEqual("counts ≤ 4", 0, int(s.counts.upper_bound(4) != s.counts.end()));
  c.checkResidual("worst position residual |p(q) − p|/L", s.worst, Tolerance<S>::identity(4096));
  std::string h;
  for (const auto& [n, k] : s.counts) h += fmt::format("{}{}×{}", h.empty() ? "" : ", ", k, n);
  c.note("posture counts: " + h + " (the catalogue's run: 18×2, 12×4 of 30)");
  c.checkEqual("4-posture targets occur", 1, s.counts.count(4) ? 1 : 0);
}

// GF §5.2.1, GF-5.2.1-theta2-recovery (E5.6)
void theta2Recovery(Context& c) {
  std::mt19937_64 g(509);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> v = unit(g), r(u(g), u(g), u(g)), a(u(g), u(g), u(g));
    const double th = ang(g);
    const Vec3<S> w = v.cross(a - r), ww = v.cross(w);
    const Vec3<S> b = a + std::sin(th) * w + (1 - std::cos(th)) * ww;
    const double cs = 1 - (b - a).dot(ww) / ww.squaredNorm(), sn = (b - a).dot(w) / w.squaredNorm();
    const double cs2 = ((a - r).dot(b - r) - std::pow((a - r).dot(v), 2)) / w.squaredNorm();
    const double sn2 = (b - r).dot(w) / w.squaredNorm();
    worst = std::max({worst, std::abs(cs - std::cos(th)), std::abs(sn - std::sin(th)), std::abs(cs2 - std::cos(th)),
                      std::abs(sn2 - std::sin(th))});
  }
  c.checkResidual("cos θ2, sin θ2 from b − a and (corrected E5.6) from (a−r)·(b−r), (b−r)·(v×(a−r))", worst, 1e-12);
}

// GF §5.2.1, GF-5.2.1-elbow-pieper: PUMA-like elbow manipulator, 8 postures.
void elbowPieper(Context& c) {
  const auto robot = puma560Robot<S>();
  std::mt19937_64 g(510);
  int eight = 0, max = 0;
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = ang(g);
    const auto sol = solvePieper(robot, robot.fk(q));
    eight += sol.count() == 8;
    max = std::max(max, int(sol.count()));
    worst = std::max(worst, sol.worstResidual());
  }
  c.checkEqual("largest count over 100 random poses (4 arm postures × 2 wrist postures)", 8, max);
  c.checkResidual("every posture reproduces the pose", worst, Tolerance<S>::identity(4096));
  c.note(fmt::format("{} of 100 random poses have all 8 postures real", eight));
}

// GF §5.2.2, GF-5.2.2-finger-puma-example (E5.4, E5.5)
void fingerExample(Context& c) {
  const double l1 = 0.8, l2 = 1.1, l3 = 0.6;
  std::vector<SerialJoint<S>> js(3);
  js[0].axis = Vec3<S>::UnitZ();
  js[1].axis = Vec3<S>::UnitX(), js[1].point = Vec3<S>(0, l1, 0);
  js[2].axis = Vec3<S>::UnitX(), js[2].point = Vec3<S>(0, l1 + l2, 0);
  const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), Vec3<S>(0, l1 + l2 + l3, 0)));
  const Vec3<S> q(0.9, -0.5, 1.2);
  const Vec3<S> p = robot.fk(JointVector<S>(q)).translation();
  const double r2 = p.squaredNorm(), rho = std::hypot(p.x(), p.y());
  const double A = (r2 + l1 * l1 - l2 * l2 - l3 * l3) / (2 * l1), B = -l2 * l3 / l1;
  const double c3a = (-A + rho) / B, c3b = (-A - rho) / B;
  c.checkNear("corrected A, B (E5.4): a root cos θ3 = 0.3623578", 0.3623578, std::min(c3a, c3b), 5e-8);
  c.checkNear("… the other root 5.754470 (infeasible)", 5.754470, std::max(c3a, c3b), 5e-7);
  c.checkNear("true cos θ3", std::cos(q(2)), std::min(c3a, c3b), 1e-14);
  const auto sol = solveArm3R(robot, robot.fk(JointVector<S>(q)));
  c.checkEqual("solveArm3R: 2 postures at this target", 2, int(sol.count()));
  c.checkResidual("… each reaching p", sol.worstResidual(), Tolerance<S>::identity(4096));
  // The printed A, B (E5.4) and the printed cos θ3 = A/B ± √(x²+y²) (E5.5).
  const double Ap = (std::pow(l1 + l2 + l3, 2) - r2 + 2 * (l1 + l2) * p.y() - 2 * l1 * l1 - 2 * l1 * l2) / (2 * l2);
  const double Bp = -l1 * l3 / l2;
  const double pr = std::min(std::abs(Ap / Bp + rho - std::cos(q(2))), std::abs(Ap / Bp - rho - std::cos(q(2))));
  c.record("cos θ3 = A/B ± √(x²+y²) with the printed A, B [as printed]", "fails (errata E5.4, E5.5)",
           fmt::format("nearest root off by {:.4f}", pr), pr, 1e-12, pr > 1e-3);
}

SOMA_STUDY({.id = "GF-5.1-wrist-fk", .title = "3R wrist forward kinematics: Rodrigues and the product of exponentials",
            .source = "GF §5.1", .chapter = kChapter, .run = wristFk});
SOMA_STUDY({.id = "GF-5.1-wrist-theta2", .title = "3R wrist: θ2 from v1ᵀRv3 (a quadratic in cos θ2)",
            .source = "GF §5.1", .chapter = kChapter, .run = wristTheta2});
SOMA_STUDY({.id = "GF-5.1-wrist-theta1-theta3", .title = "3R wrist: θ1 and θ3 (erratum E5.1)",
            .source = "GF §5.1", .chapter = kChapter, .run = wristTheta13});
SOMA_STUDY({.id = "GF-5.1-rpy-wrist-example", .title = "The roll-pitch-yaw wrist (erratum E5.2), gimbal lock",
            .source = "GF §5.1", .chapter = kChapter, .run = rpyExample});
SOMA_STUDY({.id = "GF-5.1-wrist-discriminant-design", .title = "Wrist reachability discriminant and the design angles",
            .source = "GF §5.1", .chapter = kChapter, .run = discriminantDesign});
SOMA_STUDY({.id = "GF-5.1-wrist-jacobian-posture", .title = "det J of a wrist and the sign that tells the postures apart",
            .source = "GF §5.1", .chapter = kChapter, .run = wristJacobian});
SOMA_STUDY({.id = "GF-5.2.1-revolute-joint-exp", .title = "The exponential of a revolute joint and its invariants",
            .source = "GF §5.2.1", .chapter = kChapter, .run = revoluteExp});
SOMA_STUDY({.id = "GF-5.2.1-3r-ik-procedure", .title = "3R arm IK: pencil of conics, quartic, ≤ 4 postures",
            .source = "GF §5.2.1", .chapter = kChapter, .run = armProcedure});
SOMA_STUDY({.id = "GF-5.2.1-theta2-recovery", .title = "θ2 from a and b (erratum E5.6)",
            .source = "GF §5.2.1", .chapter = kChapter, .run = theta2Recovery});
SOMA_STUDY({.id = "GF-5.2.1-elbow-pieper", .title = "Elbow manipulator with a spherical wrist: 8 postures",
            .source = "GF §5.2.1", .chapter = kChapter, .run = elbowPieper});
SOMA_STUDY({.id = "GF-5.2.2-finger-puma-example", .title = "The finger / PUMA arm (errata E5.4, E5.5)",
            .source = "GF §5.2.2", .chapter = kChapter, .run = fingerExample});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
