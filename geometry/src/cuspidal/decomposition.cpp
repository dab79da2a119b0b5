// decomposeForCuspidality, liftArmWitness (decomposition.hpp).
#include "soma/geometry/cuspidal/decomposition.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/serial/closed_form_ik.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace soma {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool parallelAxes(const SerialJoint<double>& a, const SerialJoint<double>& b) {
  return a.axis.cross(b.axis).norm() <= Tolerance<double>::input();
}

/// Lines meeting in one point (not parallel), within tol.
bool axesMeet(const SerialJoint<double>& a, const SerialJoint<double>& b, double tol) {
  const Eigen::Vector3d n = a.axis.cross(b.axis);
  if (n.norm() <= Tolerance<double>::input()) return false;
  return std::abs(n.normalized().dot(b.point - a.point)) <= tol;
}

/// The common point of three axes (least squares), when each is within tol of it.
bool concurrentAxes(const std::vector<SerialJoint<double>>& J, int first, double tol, Eigen::Vector3d& c) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int i = first; i < first + 3; ++i) {
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - J[i].axis * J[i].axis.transpose();
    A += P;
    b += P * J[i].point;
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(A);
  if (lu.rank() < 3) return false;
  c = lu.solve(b);
  for (int i = first; i < first + 3; ++i) {
    const Eigen::Vector3d d = (c - J[i].point) - J[i].axis * J[i].axis.dot(c - J[i].point);
    if (d.norm() > tol) return false;
  }
  return true;
}

std::string axesText(int first, bool reversed) {
  // 0-based first joint of the chain (reversed: joint k of the chain is joint 7 − k of the robot).
  std::string s;
  for (int i = 0; i < 3; ++i) {
    const int j = reversed ? 6 - (first + i) : first + i + 1;
    s += (i ? ", " : "") + std::to_string(j);
  }
  return s;
}

/// Wrist at joints 4–6 of `ch` (axes meeting in c; neither 4 ∥ 5 nor 5 ∥ 6): the decomposition.
CuspidalDecomposition wristDecomposition(const SerialRobot<double>& ch, const Eigen::Vector3d& c, bool reversed) {
  CuspidalDecomposition d;
  d.kind = CuspidalDecompositionKind::SphericalWrist;
  d.reversed = reversed;
  d.axes = axesText(3, reversed);
  d.centre = c;
  std::vector<SerialJoint<double>> arm(ch.joints().begin(), ch.joints().begin() + 3);
  d.arm = SerialRobot<double>::fromPOE(arm, SE3<double>(SO3<double>::Identity(), c),
                                       (ch.name().empty() ? std::string("robot") : ch.name()) + ": positioning arm");
  d.chain = ch;
  d.reason = "spherical wrist: axes " + d.axes + " meet in one point C; det J = det J_arm(θ1, θ2, θ3) · w(θ5), the two "
             "wrist postures lie on opposite sides of w = 0, so the 6R is cuspidal exactly when the 3R arm "
             "positioning C is" + std::string(reversed ? " (chain reversed: the wrist is at the base)" : "");
  return d;
}

/// Parallel joints 2–4 of `ch` (0-based 1..3) and meeting axes 5, 6, non-degenerate.
bool parallelChain(const SerialRobot<double>& ch, double tol) {
  const auto& J = ch.joints();
  if (!(parallelAxes(J[1], J[2]) && parallelAxes(J[1], J[3]))) return false;
  if (parallelAxes(J[0], J[1]) || parallelAxes(J[4], J[1])) return false;  // four parallel axes: degenerate
  if (!axesMeet(J[4], J[5], tol)) return false;
  // The three parallel axes are three different lines (else the planar elbow has no length).
  auto distance = [&](int a, int b) {
    const Eigen::Vector3d dp = J[b].point - J[a].point;
    return (dp - J[a].axis * J[a].axis.dot(dp)).norm();
  };
  return distance(1, 2) > tol && distance(2, 3) > tol;
}

constexpr double kCheckStep = 0.002;  // rad between densely checked points (as in witness6r)

}  // namespace

// GF §5.2.3, GF-5.2.3-cuspidal-posture-change
CuspidalDecomposition decomposeForCuspidality(const SerialRobot<double>& robot) {
  if (robot.dof() != 6 || !robot.allRevolute())
    throw InvalidInput("cuspidal: the decomposition needs a 6R robot with revolute joints (robot '" + robot.name() +
                       "' has " + std::to_string(robot.dof()) + " joints)");
  const double tol = Tolerance<double>::input() * robot.lengthScale();
  const SerialRobot<double> rev = robot.reversed();
  for (bool reversed : {false, true}) {
    const SerialRobot<double>& ch = reversed ? rev : robot;
    const auto& J = ch.joints();
    Eigen::Vector3d c;
    if (concurrentAxes(J, 3, tol, c) && !parallelAxes(J[3], J[4]) && !parallelAxes(J[4], J[5]))
      return wristDecomposition(ch, c, reversed);
  }
  for (bool reversed : {false, true}) {
    const SerialRobot<double>& ch = reversed ? rev : robot;
    if (!parallelChain(ch, tol)) continue;
    CuspidalDecomposition d;
    d.kind = CuspidalDecompositionKind::ParallelChain;
    d.reversed = reversed;
    d.axes = axesText(1, reversed);
    d.reason = "axes " + d.axes + " parallel and axes " + (reversed ? std::string("2, 1") : std::string("5, 6")) +
               " meeting: the IK is a chain of linear trigonometric equations in θ1, θ5, θ3 (of the chain) whose "
               "two roots are always separated by a factor of det J, so no two postures of a pose share an aspect";
    return d;
  }
  CuspidalDecomposition d;
  d.reason = "no spherical wrist at either end and no parallel triple next to a meeting pair";
  return d;
}

// GF §5.2.3 (the witness of the arm carried to the 6R)
Witness6R liftArmWitness(const SerialRobot<double>& robot, const CuspidalDecomposition& d, const WitnessPath& w,
                         const Eigen::Vector3d& wristStart) {
  const auto t0 = std::chrono::steady_clock::now();
  Witness6R out;
  out.ikMethod = "decomposition";
  out.planner = "decomposition";
  auto finish = [&](const std::string& note) {
    out.note = note;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (d.kind != CuspidalDecompositionKind::SphericalWrist || !d.chain)
    return finish("no spherical-wrist decomposition to lift a witness from");
  if (!w.found || w.path.size() < 2) return finish("the positioning arm has no witness path");
  const SerialRobot<double>& ch = *d.chain;
  const auto& J = ch.joints();
  const Eigen::Matrix3d RM = ch.home().rotation().matrix();
  auto rot = [&](int i, double q) { return Eigen::AngleAxisd(q + J[i].offset, J[i].axis).toRotationMatrix(); };
  auto armRot = [&](const Eigen::Vector3d& a) { return Eigen::Matrix3d(rot(0, a(0)) * rot(1, a(1)) * rot(2, a(2))); };
  // Sign of the wrist factor w = v4·(v5 × Rot(v5, θ5) v6) (home directions, raw angle).
  auto wristFactor = [&](double q5) {
    return J[3].axis.dot(J[4].axis.cross(Eigen::AngleAxisd(q5 + J[4].offset, J[4].axis) * J[5].axis));
  };
  auto full = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    JointVector<double> q(6);
    q << a(0), a(1), a(2), b(0), b(1), b(2);
    return q;
  };
  JointVector<double> q0 = full(w.path.front(), wristStart);
  const Eigen::Matrix3d Rt = ch.fk(q0).rotation().matrix();
  const int wsign = wristFactor(wristStart(1)) > 0 ? 1 : -1;
  if (std::abs(wristFactor(wristStart(1))) < 1e-3) return finish("the start wrist posture is singular");
  // Wrist angles holding Rt for arm state a: the solution with the sign `wsign`, nearest `prev`.
  auto wristFor = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& prev, bool& ok) {
    const Eigen::Matrix3d X = armRot(a).transpose() * Rt * RM.transpose();
    const WristAngles<double> wa = wrist3R<double>(J[3].axis, J[4].axis, J[5].axis, X);
    Eigen::Vector3d best = prev;
    double bestDist = std::numeric_limits<double>::infinity();
    for (const auto& raw : wa.angles) {
      Eigen::Vector3d q(raw(0) - J[3].offset, raw(1) - J[4].offset, raw(2) - J[5].offset);
      if (wristFactor(q(1)) * wsign <= 0) continue;
      for (int i = 0; i < 3; ++i) q(i) = prev(i) + std::remainder(q(i) - prev(i), 2 * kPi);
      const double dist = (q - prev).cwiseAbs().maxCoeff();
      if (dist < bestDist) {
        bestDist = dist;
        best = q;
      }
    }
    ok = std::isfinite(bestDist) && !wa.gimbal;
    return best;
  };
  // The arm path, refined to ≤ kCheckStep per step, each state completed by its wrist.
  std::vector<JointVector<double>> path;
  Eigen::Vector3d wprev = wristStart;
  path.push_back(q0);
  for (std::size_t s = 0; s + 1 < w.path.size(); ++s) {
    Eigen::Vector3d da = w.path[s + 1] - w.path[s];
    for (int i = 0; i < 3; ++i) da(i) = std::remainder(da(i), 2 * kPi);
    const int m = std::max(1, int(std::ceil(da.cwiseAbs().maxCoeff() / kCheckStep)));
    for (int t = 1; t <= m; ++t) {
      const Eigen::Vector3d a = w.path[s] + da * (double(t) / m);
      bool ok = false;
      const Eigen::Vector3d wq = wristFor(a, wprev, ok);
      if (!ok || (wq - wprev).cwiseAbs().maxCoeff() > 0.1)
        return finish("holding the start orientation meets a wrist singularity along the arm's witness path");
      wprev = wq;
      path.push_back(full(a, wq));
    }
  }
  // Dense re-check in the 6R (consecutive states ≤ kCheckStep apart in the arm, wrist continuous).
  const double det0 = jacobianDet6(ch, path.front());
  const int sign = det0 > 0 ? 1 : -1;
  double minDet = std::numeric_limits<double>::infinity();
  for (const auto& q : path) minDet = std::min(minDet, sign * jacobianDet6(ch, q));
  if (!(minDet > 0)) return finish("the lifted path meets det J = 0 (min sign·det J / L³ = " + std::to_string(minDet) + ")");
  // Back to the robot's joint order; the dense minimum there; a state kept every ≥ 0.04 rad.
  auto own = [&](const JointVector<double>& q) {
    if (!d.reversed) return q;
    JointVector<double> r(6);
    for (int i = 0; i < 6; ++i) r(i) = q(5 - i);
    return r;
  };
  for (auto& q : path) q = own(q);
  out.found = true;
  out.start = path.front();
  out.goal = path.back();
  out.pose = robot.fk(out.start);
  out.startResidual = 0;
  out.goalResidual = poseResidual(robot.fk(out.goal), out.pose, robot.lengthScale());
  out.sign = jacobianDet6(robot, out.start) > 0 ? 1 : -1;
  out.minSignedDet = std::numeric_limits<double>::infinity();
  for (const auto& q : path) out.minSignedDet = std::min(out.minSignedDet, out.sign * jacobianDet6(robot, q));
  std::vector<JointVector<double>> kept{path.front()};
  for (std::size_t k = 1; k + 1 < path.size(); ++k)
    if ((path[k] - kept.back()).cwiseAbs().maxCoeff() >= 0.04) kept.push_back(path[k]);
  kept.push_back(path.back());
  path = std::move(kept);
  out.path = std::move(path);
  return finish("");
}

}  // namespace soma
