// Witness paths of cuspidality planned with OMPL (the only TU that includes OMPL headers).
#include "ompl_setup.hpp"
#include "soma/geometry/cuspidal/witness.hpp"

#include "soma/geometry/serial/closed_form_ik.hpp"

#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cmath>
#include <mutex>

namespace soma {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

constexpr double kPi = 3.14159265358979323846;

using detail::quietOmpl;  // ompl_setup.hpp

/// Plan from a to b in SO(2)³ keeping sign·det J ≥ margin. Empty when no path was found in time.
std::vector<Eigen::Vector3d> plan(const DetJSeries& dj, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  int sign, double margin, double seconds) {
  auto space = std::make_shared<ob::CompoundStateSpace>();
  for (int i = 0; i < 3; ++i) space->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
  og::SimpleSetup ss(space);
  auto angle = [](const ob::State* s, int i) {
    return s->as<ob::CompoundState>()->as<ob::SO2StateSpace::StateType>(i)->value;
  };
  ss.setStateValidityChecker([&dj, sign, margin, angle](const ob::State* s) {
    return sign * dj.value(angle(s, 1), angle(s, 2)) >= margin;
  });
  // Motions are checked every 0.1 % of the space's extent (about 0.005 rad here).
  ss.getSpaceInformation()->setStateValidityCheckingResolution(0.001);
  ob::ScopedState<ob::CompoundStateSpace> start(space), goal(space);
  for (int i = 0; i < 3; ++i) {
    start->as<ob::SO2StateSpace::StateType>(i)->value = std::remainder(a(i), 2 * kPi);
    goal->as<ob::SO2StateSpace::StateType>(i)->value = std::remainder(b(i), 2 * kPi);
  }
  ss.setStartAndGoalStates(start, goal);
  ss.setPlanner(std::make_shared<og::RRTConnect>(ss.getSpaceInformation()));
  const ob::PlannerStatus st = ss.solve(seconds);
  std::vector<Eigen::Vector3d> out;
  if (st != ob::PlannerStatus::EXACT_SOLUTION) return out;
  ss.simplifySolution(0.2);
  og::PathGeometric& p = ss.getSolutionPath();
  p.interpolate();
  for (std::size_t k = 0; k < p.getStateCount(); ++k) {
    const ob::State* s = p.getState(k);
    out.emplace_back(angle(s, 0), angle(s, 1), angle(s, 2));
  }
  return out;
}

}  // namespace

// GF §5.2.3, GF-5.2.3-cuspidal-posture-change (posture change by circling a cusp, Fig. 5.2)
WitnessPath findWitness(const SerialRobot<double>& robot, const CuspAnalysis<double>& cusps,
                        const DetJSeries& dj, const AspectMap& aspectMap, double secondsPerPair) {
  quietOmpl();
  const auto t0 = std::chrono::steady_clock::now();
  WitnessPath w;
  const Arm3RFrame<double>& f = cusps.frame;
  const double L = f.scale;
  auto finish = [&]() {
    w.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return w;
  };
  if (cusps.cusps.empty()) {
    w.note = "no cusp point: no witness to look for";
    return finish();
  }
  const double radii[] = {0.01, 0.03, 0.1};
  for (const auto& c : cusps.cusps) {
    for (double r : radii) {
      for (int k = 0; k < 24; ++k) {
        const double beta = 2 * kPi * k / 24;
        const double rho = c.rho + r * L * std::cos(beta), z = c.z + r * L * std::sin(beta);
        if (!(rho > 0)) continue;
        const Eigen::Vector3d p = f.c + rho * f.ex + z * f.ez;
        const Solution<double> sol = solveArm3R<double>(robot, SE3<double>(SO3<double>(), p));
        if (sol.count() != 4) continue;
        ++w.targetsTried;
        std::vector<double> det(4);
        std::vector<int> asp(4);
        for (int i = 0; i < 4; ++i) {
          det[i] = toolPointJacobianDet(robot, sol.postures[i]);
          asp[i] = aspectMap.aspectOf(dj, sol.postures[i](1), sol.postures[i](2));
        }
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j) {
            if (det[i] * det[j] <= 0) continue;
            if (asp[i] >= 0 && asp[j] >= 0 && asp[i] != asp[j]) continue;  // different aspects
            const int sign = det[i] > 0 ? 1 : -1;
            const double margin = 0.25 * std::min(std::abs(det[i]), std::abs(det[j]));
            ++w.pairsTried;
            const Eigen::Vector3d a = sol.postures[i], b = sol.postures[j];
            auto path = plan(dj, a, b, sign, margin, secondsPerPair);
            if (path.empty()) continue;
            const PathCheck pc = checkPathSign(dj, path, sign);
            if (!(pc.minSignedDet > 0)) continue;
            w.found = true;
            w.target = p;
            w.rho = rho;
            w.z = z;
            w.start = sol.postures[i];
            w.goal = sol.postures[j];
            w.path = std::move(path);
            w.sign = sign;
            w.margin = margin;
            w.minSignedDet = pc.minSignedDet;
            w.certified = pc.certified;
            w.checkedPoints = pc.points;
            w.startResidual = sol.residuals[i];
            w.goalResidual = sol.residuals[j];
            w.aspectStart = asp[i];
            w.aspectGoal = asp[j];
            return finish();
          }
        if (w.targetsTried >= 12) break;
      }
      if (w.targetsTried >= 12) break;
    }
  }
  w.note = "no path found near any cusp (" + std::to_string(w.targetsTried) + " targets, " +
           std::to_string(w.pairsTried) + " posture pairs)";
  return finish();
}

}  // namespace soma
