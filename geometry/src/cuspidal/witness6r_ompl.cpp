// Witness search for cuspidal 6R robots with OMPL (see witness6r.hpp).
#include "ompl_setup.hpp"
#include "soma/geometry/cuspidal/witness6r.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/serial/ik.hpp"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <random>

namespace soma {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

constexpr double kPi = 3.14159265358979323846;

using detail::quietOmpl;  // ompl_setup.hpp

bool limitedJoint(const SerialJoint<double>& j) {
  return std::isfinite(j.lower) && std::isfinite(j.upper) && j.upper - j.lower < 2 * kPi;
}

constexpr double kCheckStep = 0.002;  // rad between densely checked points

std::string fmtSeconds(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

}  // namespace

double jacobianDet6(const SerialRobot<double>& robot, const JointVector<double>& q) {
  const JacobianMatrix<double> Js = robot.spatialJacobian(q);
  detail::SmallMat<double> M(6, 6);
  for (int i = 0; i < 6; ++i) M.col(i) = Js.col(i);
  const double L = robot.lengthScale();
  return detail::smallDeterminant<double>(M) / (L * L * L);
}

// GF §5.2.3 (cuspidal robots: a posture change without a singularity)
Witness6R findWitness6R(const SerialRobot<double>& robot, const Witness6ROptions& options) {
  if (robot.dof() != 6)
    throw InvalidInput("cuspidal: robot '" + robot.name() + "' has " + std::to_string(robot.dof()) +
                       " joints; the witness search handles 3R arms and 6R robots");
  for (int i = 0; i < 6; ++i)
    if (robot.joints()[i].type != JointType::Revolute)
      throw InvalidInput("cuspidal: joint " + std::to_string(i + 1) + " of robot '" + robot.name() + "' is prismatic");
  if (options.poses < 1) throw InvalidInput("cuspidal: the number of poses must be at least 1");
  if (!(options.secondsPerPair > 0)) throw InvalidInput("cuspidal: the planning time per pair must be positive");
  if (!(options.budget >= 0)) throw InvalidInput("cuspidal: the budget must be a number of seconds ≥ 0");
  quietOmpl();
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  auto left = [&]() { return options.budget > 0 ? options.budget - elapsed() : std::numeric_limits<double>::infinity(); };
  Witness6R w;
  auto finish = [&]() {
    w.seconds = elapsed();
    return w;
  };
  double lastReport = 0;
  auto report = [&](bool force) {
    if (!options.progress) return;
    const double t = elapsed();
    if (!force && t - lastReport < 1.0) return;
    lastReport = t;
    options.progress({w.posesTried, w.pairsTried, w.posturesSeen, t});
  };
  // Joint space: SO(2) per unlimited joint, the limit interval otherwise.
  auto space = std::make_shared<ob::CompoundStateSpace>();
  std::vector<bool> so2(6);
  for (int i = 0; i < 6; ++i) {
    const auto& j = robot.joints()[i];
    so2[std::size_t(i)] = !limitedJoint(j);
    if (so2[std::size_t(i)]) {
      space->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    } else {
      auto r = std::make_shared<ob::RealVectorStateSpace>(1);
      r->setBounds(j.lower, j.upper);
      space->addSubspace(r, 1.0);
    }
  }
  auto toJoints = [&so2](const ob::State* s) {
    const auto* cs = s->as<ob::CompoundState>();
    JointVector<double> q(6);
    for (int i = 0; i < 6; ++i)
      q(i) = so2[std::size_t(i)] ? cs->as<ob::SO2StateSpace::StateType>(i)->value
                                 : cs->as<ob::RealVectorStateSpace::StateType>(i)->values[0];
    return q;
  };
  auto fromJoints = [&so2](const JointVector<double>& q, ob::State* s) {
    auto* cs = s->as<ob::CompoundState>();
    for (int i = 0; i < 6; ++i) {
      if (so2[std::size_t(i)]) cs->as<ob::SO2StateSpace::StateType>(i)->value = std::remainder(q(i), 2 * kPi);
      else cs->as<ob::RealVectorStateSpace::StateType>(i)->values[0] = q(i);
    }
  };
  // Dense check of a path (shortest arcs on SO(2) joints, ≤ kCheckStep between checked points):
  // min of sign·det J, and the path refined to the checked points.
  auto denseCheck = [&](const std::vector<JointVector<double>>& path, int sign, std::vector<JointVector<double>>* dense) {
    double minDet = sign * jacobianDet6(robot, path.front());
    if (dense) dense->assign(1, path.front());
    for (std::size_t s = 0; s + 1 < path.size(); ++s) {
      JointVector<double> d = path[s + 1] - path[s];
      for (int i = 0; i < 6; ++i)
        if (so2[std::size_t(i)]) d(i) = std::remainder(d(i), 2 * kPi);
      const int m = std::max(1, int(std::ceil(d.cwiseAbs().maxCoeff() / kCheckStep)));
      for (int t = 1; t <= m; ++t) {
        const JointVector<double> q = path[s] + d * (double(t) / m);
        minDet = std::min(minDet, sign * jacobianDet6(robot, q));
        if (!(minDet > 0)) return minDet;  // (callers ask more: the margin)
        if (dense && (t == m || t % 25 == 0)) dense->push_back(q);
      }
    }
    return minDet;
  };
  IkOptions ik;
  ik.method = IkMethod::Auto;
  std::mt19937_64 g(options.seed);
  for (int k = 0; k < options.poses; ++k) {
    if (left() <= 0) {
      w.budgetExhausted = true;
      break;
    }
    // A random posture within the limits defines a reachable pose.
    JointVector<double> q0(6);
    for (int i = 0; i < 6; ++i) {
      const auto& j = robot.joints()[i];
      std::uniform_real_distribution<double> u(limitedJoint(j) ? j.lower : -kPi, limitedJoint(j) ? j.upper : kPi);
      q0(i) = u(g);
    }
    const SE3<double> pose = robot.fk(q0);
    ++w.posesTried;
    const IkSolution<double> sol = solveIk(robot, pose, ik);
    w.ikMethod = sol.method;
    std::vector<JointVector<double>> qs;
    std::vector<double> det, res;
    for (std::size_t i = 0; i < sol.postures.size(); ++i) {
      JointVector<double> q = sol.postures[i];
      for (int a = 0; a < 6; ++a)
        if (so2[std::size_t(a)]) q(a) = std::remainder(q(a), 2 * kPi);
      if (!robot.withinLimits(q)) continue;
      qs.push_back(q);
      det.push_back(jacobianDet6(robot, q));
      res.push_back(sol.residuals[i]);
    }
    w.posturesSeen += int(qs.size());
    auto accept = [&](std::size_t a, std::size_t b, int sign, double margin, std::vector<JointVector<double>> path,
                      double minDet, const char* planner) {
      w.found = true;
      w.pose = pose;
      w.start = qs[a];
      w.goal = qs[b];
      w.path = std::move(path);
      w.planner = planner;
      w.sign = sign;
      w.margin = margin;
      w.minSignedDet = minDet;
      w.startResidual = res[a];
      w.goalResidual = res[b];
    };
    // Same-sign pairs: the straight joint path for all of them first (cheap), then OMPL.
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t a = 0; a < qs.size(); ++a)
      for (std::size_t b = a + 1; b < qs.size(); ++b)
        if (det[a] * det[b] > 0) pairs.emplace_back(a, b);
    // The margin matters: sign·det J > 0 at sampled points alone is fooled by an even-order zero
    // (two factors of det J vanishing at one point — a straight path between mirror postures of a
    // PUMA crosses the wrist and the elbow singularities at its midpoint, and det J touches 0).
    auto marginOf = [&](std::size_t a, std::size_t b) { return 0.25 * std::min(std::abs(det[a]), std::abs(det[b])); };
    for (const auto& [a, b] : pairs) {
      const int sign = det[a] > 0 ? 1 : -1;
      const double margin = marginOf(a, b);
      ++w.straightTried;
      std::vector<JointVector<double>> dense;
      const double minDet = denseCheck({qs[a], qs[b]}, sign, &dense);
      if (minDet >= margin) {
        ++w.pairsTried;
        accept(a, b, sign, margin, std::move(dense), minDet, "straight joint path");
        report(true);
        return finish();
      }
    }
    for (const auto& [a, b] : pairs) {
      const double budgetLeft = left();
      if (budgetLeft <= 0) {
        w.budgetExhausted = true;
        break;
      }
      const int sign = det[a] > 0 ? 1 : -1;
      const double margin = marginOf(a, b);
      ++w.pairsTried;
      og::SimpleSetup ss(space);
      ss.setStateValidityChecker([&](const ob::State* s) {
        const JointVector<double> q = toJoints(s);
        return robot.withinLimits(q) && sign * jacobianDet6(robot, q) >= margin;
      });
      ss.getSpaceInformation()->setStateValidityCheckingResolution(0.002);
      ob::ScopedState<ob::CompoundStateSpace> A(space), B(space);
      fromJoints(qs[a], A.get());
      fromJoints(qs[b], B.get());
      ss.setStartAndGoalStates(A, B);
      ss.setPlanner(std::make_shared<og::RRTConnect>(ss.getSpaceInformation()));
      const bool solved = ss.solve(std::min(options.secondsPerPair, budgetLeft)) == ob::PlannerStatus::EXACT_SOLUTION;
      report(false);
      if (!solved) continue;
      ss.simplifySolution(0.2);
      og::PathGeometric& p = ss.getSolutionPath();
      p.interpolate();
      std::vector<JointVector<double>> path;
      for (std::size_t s = 0; s < p.getStateCount(); ++s) path.push_back(toJoints(p.getState(s)));
      // Re-checked at ≤ 0.002 rad, at least half the margin (the planner checked its states at
      // its own resolution).
      const double minDet = denseCheck(path, sign, nullptr);
      if (!(minDet >= 0.5 * margin)) continue;
      accept(a, b, sign, margin, std::move(path), minDet, "OMPL RRTConnect");
      report(true);
      return finish();
    }
    report(true);
    if (w.budgetExhausted) break;
  }
  w.note = "none found after " + std::to_string(w.posesTried) + " poses (" + std::to_string(w.straightTried) +
           " same-sign posture pairs, straight joint paths, " + std::to_string(w.pairsTried) + " planned with " +
           fmtSeconds(options.secondsPerPair) + " s of OMPL RRTConnect each" +
           (w.budgetExhausted ? "; the budget of " + fmtSeconds(options.budget) + " s ran out" : std::string()) +
           ") — not a proof that the robot is not cuspidal";
  return finish();
}

}  // namespace soma
