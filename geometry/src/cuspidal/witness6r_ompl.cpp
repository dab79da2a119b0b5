// Witness search for cuspidal 6R robots with OMPL (see witness6r.hpp).
#include "ompl_setup.hpp"
#include "soma/geometry/cuspidal/witness6r.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/general_6r.hpp"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
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

Solution<double> allPostures(const SerialRobot<double>& robot, const SE3<double>& pose, std::string& method) {
  const IkMethod m = classifyRobot(robot);
  if (m == IkMethod::Pieper) {
    method = "pieper";
    return solveClosedForm(robot, pose, IkMethod::Pieper);
  }
  const auto& rows = robot.dhRows();
  const bool identity = (robot.base().translation().squaredNorm() == 0 && robot.tool().translation().squaredNorm() == 0 &&
                         (robot.base().rotation().matrix() - Mat3<double>::Identity()).norm() == 0 &&
                         (robot.tool().rotation().matrix() - Mat3<double>::Identity()).norm() == 0);
  if (rows.size() != 6 || robot.convention() != DHConvention::Standard || !identity)
    throw InvalidInput("cuspidal: the 6R witness search needs a Pieper robot, or a general 6R given by standard DH "
                       "rows without base or tool transform (robot '" + robot.name() + "')");
  method = "general6r";
  Robot6R<double> r6;
  for (int i = 0; i < 6; ++i) r6[std::size_t(i)] = rows[std::size_t(i)];
  const General6RSolution<double> g = solveGeneral6R(r6, pose);
  return Solution<double>(g);
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
Witness6R findWitness6R(const SerialRobot<double>& robot, int poses, double secondsPerPair, unsigned long long seed) {
  if (robot.dof() != 6)
    throw InvalidInput("cuspidal: robot '" + robot.name() + "' has " + std::to_string(robot.dof()) +
                       " joints; the witness search handles 3R arms and 6R robots");
  for (int i = 0; i < 6; ++i)
    if (robot.joints()[i].type != JointType::Revolute)
      throw InvalidInput("cuspidal: joint " + std::to_string(i + 1) + " of robot '" + robot.name() + "' is prismatic");
  if (poses < 1) throw InvalidInput("cuspidal: the number of poses must be at least 1");
  if (!(secondsPerPair > 0)) throw InvalidInput("cuspidal: the planning time per pair must be positive");
  quietOmpl();
  const auto t0 = std::chrono::steady_clock::now();
  Witness6R w;
  auto finish = [&]() {
    w.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return w;
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
  std::mt19937_64 g(seed);
  for (int k = 0; k < poses; ++k) {
    // A random posture within the limits defines a reachable pose.
    JointVector<double> q0(6);
    for (int i = 0; i < 6; ++i) {
      const auto& j = robot.joints()[i];
      std::uniform_real_distribution<double> u(limitedJoint(j) ? j.lower : -kPi, limitedJoint(j) ? j.upper : kPi);
      q0(i) = u(g);
    }
    const SE3<double> pose = robot.fk(q0);
    ++w.posesTried;
    const Solution<double> sol = allPostures(robot, pose, w.ikMethod);
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
    for (std::size_t a = 0; a < qs.size(); ++a)
      for (std::size_t b = a + 1; b < qs.size(); ++b) {
        if (!(det[a] * det[b] > 0)) continue;
        const int sign = det[a] > 0 ? 1 : -1;
        const double margin = 0.25 * std::min(std::abs(det[a]), std::abs(det[b]));
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
        if (ss.solve(secondsPerPair) != ob::PlannerStatus::EXACT_SOLUTION) continue;
        ss.simplifySolution(0.2);
        og::PathGeometric& p = ss.getSolutionPath();
        p.interpolate();
        std::vector<JointVector<double>> path;
        for (std::size_t s = 0; s < p.getStateCount(); ++s) path.push_back(toJoints(p.getState(s)));
        // Dense re-check (≤ 0.002 rad between checked points, shortest arcs on SO(2) joints).
        double minDet = sign * det[a];
        for (std::size_t s = 0; s + 1 < path.size(); ++s) {
          JointVector<double> d = path[s + 1] - path[s];
          for (int i = 0; i < 6; ++i)
            if (so2[std::size_t(i)]) d(i) = std::remainder(d(i), 2 * kPi);
          const int m = std::max(1, int(std::ceil(d.cwiseAbs().maxCoeff() / 0.002)));
          for (int t = 1; t <= m; ++t) minDet = std::min(minDet, sign * jacobianDet6(robot, path[s] + d * (double(t) / m)));
        }
        if (!(minDet > 0)) continue;
        w.found = true;
        w.pose = pose;
        w.start = qs[a];
        w.goal = qs[b];
        w.path = std::move(path);
        w.sign = sign;
        w.margin = margin;
        w.minSignedDet = minDet;
        w.startResidual = res[a];
        w.goalResidual = res[b];
        return finish();
      }
  }
  w.note = "none found after " + std::to_string(w.posesTried) + " poses (" + std::to_string(w.pairsTried) +
           " same-sign posture pairs, " + std::to_string(secondsPerPair) +
           " s of OMPL RRTConnect each) — not a proof that the robot is not cuspidal";
  return finish();
}

}  // namespace soma
