// Workspace maps and singularity-avoiding plans with OMPL (the second TU that includes OMPL).
#include "ompl_setup.hpp"
#include "soma/geometry/cuspidal/workspace.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"

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

namespace soma {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

constexpr double kPi = 3.14159265358979323846;

using detail::quietOmpl;  // ompl_setup.hpp

/// The joint space: SO(2) for an unlimited revolute joint, an interval for a limited one.
std::shared_ptr<ob::CompoundStateSpace> jointSpace(const SerialRobot<double>& robot) {
  auto space = std::make_shared<ob::CompoundStateSpace>();
  for (int i = 0; i < robot.dof(); ++i) {
    const auto& j = robot.joints()[i];
    const bool limited = std::isfinite(j.lower) && std::isfinite(j.upper);
    if (!limited && j.type != JointType::Revolute)
      throw InvalidInput("workspace: joint " + std::to_string(i + 1) + " of robot '" + robot.name() +
                         "' is prismatic without limits; give it \"limits\" to sample it");
    if (limited && (j.upper - j.lower < 2 * kPi - Tolerance<double>::sqrtEpsilon() || j.type != JointType::Revolute)) {
      auto r = std::make_shared<ob::RealVectorStateSpace>(1);
      r->setBounds(j.lower, j.upper);
      space->addSubspace(r, 1.0);
    } else {
      space->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    }
  }
  return space;
}

bool isSO2(const ob::CompoundStateSpace& space, int i) {
  return space.getSubspace(i)->getType() == ob::STATE_SPACE_SO2;
}

JointVector<double> toJoints(const ob::CompoundStateSpace& space, const ob::State* s) {
  const auto* cs = s->as<ob::CompoundState>();
  JointVector<double> q(space.getSubspaceCount());
  for (unsigned i = 0; i < space.getSubspaceCount(); ++i)
    q(i) = isSO2(space, int(i)) ? cs->as<ob::SO2StateSpace::StateType>(i)->value
                                : cs->as<ob::RealVectorStateSpace::StateType>(i)->values[0];
  return q;
}

void fromJoints(const ob::CompoundStateSpace& space, const JointVector<double>& q, ob::State* s) {
  auto* cs = s->as<ob::CompoundState>();
  for (unsigned i = 0; i < space.getSubspaceCount(); ++i) {
    if (isSO2(space, int(i))) cs->as<ob::SO2StateSpace::StateType>(i)->value = std::remainder(q(i), 2 * kPi);
    else cs->as<ob::RealVectorStateSpace::StateType>(i)->values[0] = q(i);
  }
}

/// Section frame about axis 1: foot of the base origin on the axis, and the axis direction.
struct Section {
  Vec3<double> c, ez;
  Eigen::Vector2d of(const Vec3<double>& p) const {
    const Vec3<double> d = p - c;
    const double z = ez.dot(d);
    return {std::sqrt((d - ez * z).squaredNorm()), z};
  }
};
Section sectionOf(const SerialRobot<double>& robot) {
  const auto& j0 = robot.joints()[0];
  Section s;
  s.ez = j0.axis;
  const Vec3<double> o = robot.base().translation();
  s.c = j0.type == JointType::Revolute ? Vec3<double>(j0.point + j0.axis * j0.axis.dot(o - j0.point)) : o;
  return s;
}

}  // namespace

Eigen::Vector2d dexteritySingularValues(const SerialRobot<double>& robot, const JointVector<double>& q) {
  const JacobianMatrix<double> Js = robot.spatialJacobian(q);
  const Vec3<double> p = robot.fk(q).translation();
  const int n = robot.dof();
  const double L = robot.lengthScale();
  detail::SmallMat<double> M(n == 3 ? 3 : 6, n);
  for (int i = 0; i < n; ++i) {
    const Vec3<double> w = Js.block<3, 1>(0, i), v = Js.block<3, 1>(3, i);
    const Vec3<double> pv = v + w.cross(p);  // velocity of the tool point
    if (n == 3) {
      M.col(i) = pv / L;
    } else {
      M.block<3, 1>(0, i) = w;
      M.block<3, 1>(3, i) = pv / L;
    }
  }
  const std::vector<double> sig = detail::smallSingularValues<double>(M);
  return {sig.back(), sig.front()};
}

// GF §5.2.3 (the workspace and its singular boundary)
WorkspaceMaps sampleWorkspace(const SerialRobot<double>& robot, int samples, int n) {
  if (samples < 1) throw InvalidInput("workspace: samples must be at least 1, got " + std::to_string(samples));
  if (n < 8) throw InvalidInput("workspace: grid size must be at least 8, got " + std::to_string(n));
  if (robot.dof() < 1) throw InvalidInput("workspace: robot '" + robot.name() + "' has no joints");
  quietOmpl();
  const auto t0 = std::chrono::steady_clock::now();
  auto space = jointSpace(robot);
  ob::StateSamplerPtr sampler = space->allocDefaultStateSampler();
  ob::State* s = space->allocState();
  const Section sec = sectionOf(robot);
  std::vector<Eigen::Vector2d> rz(static_cast<std::size_t>(samples));
  std::vector<double> dex(static_cast<std::size_t>(samples));
  WorkspaceMaps m;
  m.samples = samples;
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    sampler->sampleUniform(s);
    const JointVector<double> q = toJoints(*space, s);
    rz[std::size_t(k)] = sec.of(robot.fk(q).translation());
    const Eigen::Vector2d sv = dexteritySingularValues(robot, q);
    dex[std::size_t(k)] = sv(1) > 0 ? sv(0) / sv(1) : 0;
    sum += dex[std::size_t(k)];
  }
  space->freeState(s);
  m.meanDexterity = sum / samples;
  double rmax = 0, zmin = rz[0](1), zmax = rz[0](1);
  for (const auto& p : rz) rmax = std::max(rmax, p(0)), zmin = std::min(zmin, p(1)), zmax = std::max(zmax, p(1));
  const double pad = 0.02 * std::max({rmax, zmax - zmin, robot.lengthScale() * Tolerance<double>::sqrtEpsilon()});
  m.rhoMax = rmax + pad;
  m.zMin = zmin - pad;
  m.zMax = zmax + pad;
  m.nRho = m.nZ = n;
  m.hits.assign(std::size_t(n) * n, 0);
  m.dexterity.assign(std::size_t(n) * n, -1.0);
  for (int k = 0; k < samples; ++k) {
    const auto& p = rz[std::size_t(k)];
    const int i = std::clamp(int(p(0) / m.rhoMax * n), 0, n - 1);
    const int j = std::clamp(int((p(1) - m.zMin) / (m.zMax - m.zMin) * n), 0, n - 1);
    const std::size_t c = std::size_t(j) * n + i;
    ++m.hits[c];
    m.dexterity[c] = std::max(m.dexterity[c], dex[std::size_t(k)]);
  }
  int reached = 0;
  for (int h : m.hits) reached += h > 0;
  m.reachedFraction = double(reached) / double(m.hits.size());
  m.points.assign(rz.begin(), rz.begin() + std::min<std::size_t>(rz.size(), 4000));
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

// GF §5.2.3 (a posture change that keeps away from det J = 0)
SafePath planAwayFromSingularities(const SerialRobot<double>& robot, const JointVector<double>& start,
                                   const JointVector<double>& goal, double margin, double seconds) {
  quietOmpl();
  const auto t0 = std::chrono::steady_clock::now();
  const int n = robot.dof();
  auto check = [&](const JointVector<double>& q, const char* what) {
    if (q.size() != n)
      throw InvalidInput(std::string("workspace: ") + what + " posture has " + std::to_string(q.size()) +
                         " joint values; robot '" + robot.name() + "' has " + std::to_string(n));
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(q(i))) throw InvalidInput(std::string("workspace: ") + what + " joint " + std::to_string(i + 1) + " is not finite");
    if (!robot.withinLimits(q))
      throw InvalidInput(std::string("workspace: ") + what + " posture is outside the joint limits");
  };
  check(start, "start");
  check(goal, "goal");
  if (!(margin >= 0) || !std::isfinite(margin))
    throw InvalidInput("workspace: the singularity margin must be a finite number ≥ 0");
  if (!(seconds > 0)) throw InvalidInput("workspace: the planning time must be positive");
  SafePath out;
  out.margin = margin;
  out.startSigma = dexteritySingularValues(robot, start)(0);
  out.goalSigma = dexteritySingularValues(robot, goal)(0);
  if (out.startSigma < margin)
    throw InvalidInput("workspace: the start posture is closer to a singularity than the margin (σ_min " +
                       std::to_string(out.startSigma) + " < " + std::to_string(margin) + ")");
  if (out.goalSigma < margin)
    throw InvalidInput("workspace: the goal posture is closer to a singularity than the margin (σ_min " +
                       std::to_string(out.goalSigma) + " < " + std::to_string(margin) + ")");
  auto detSign = [&](const JointVector<double>& q) {
    if (n != 3 && n != 6) return 0;
    const JacobianMatrix<double> Js = robot.spatialJacobian(q);
    const Vec3<double> p = robot.fk(q).translation();
    detail::SmallMat<double> M(n, n);
    for (int i = 0; i < n; ++i) {
      const Vec3<double> w = Js.block<3, 1>(0, i), v = Js.block<3, 1>(3, i);
      if (n == 3) M.col(i) = v + w.cross(p);
      else M.col(i) << w, v + w.cross(p);
    }
    const double d = detail::smallDeterminant<double>(M);
    return d > 0 ? 1 : (d < 0 ? -1 : 0);
  };
  out.startSign = detSign(start);
  out.goalSign = detSign(goal);
  auto finish = [&]() {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (margin > 0 && out.startSign * out.goalSign < 0) {
    out.note = "start and goal have opposite signs of det J: every path between them meets a singularity";
    return finish();
  }
  auto space = jointSpace(robot);
  og::SimpleSetup ss(space);
  const ob::CompoundStateSpace* sp = space.get();
  ss.setStateValidityChecker([&robot, sp, margin](const ob::State* s) {
    const JointVector<double> q = toJoints(*sp, s);
    return robot.withinLimits(q) && dexteritySingularValues(robot, q)(0) >= margin;
  });
  ss.getSpaceInformation()->setStateValidityCheckingResolution(0.002);
  ob::ScopedState<ob::CompoundStateSpace> a(space), b(space);
  fromJoints(*space, start, a.get());
  fromJoints(*space, goal, b.get());
  ss.setStartAndGoalStates(a, b);
  ss.setPlanner(std::make_shared<og::RRTConnect>(ss.getSpaceInformation()));
  const ob::PlannerStatus st = ss.solve(seconds);
  if (st != ob::PlannerStatus::EXACT_SOLUTION) {
    out.note = "OMPL RRTConnect found no path keeping σ_min ≥ margin in " + std::to_string(seconds) + " s";
    return finish();
  }
  ss.simplifySolution(0.5);
  og::PathGeometric& p = ss.getSolutionPath();
  p.interpolate();
  for (std::size_t k = 0; k < p.getStateCount(); ++k) out.path.push_back(toJoints(*space, p.getState(k)));
  // Dense check between consecutive states (shortest arcs on SO(2) joints, as OMPL interpolates).
  out.minSigma = out.startSigma;
  for (std::size_t k = 0; k + 1 < out.path.size(); ++k) {
    JointVector<double> d = out.path[k + 1] - out.path[k];
    for (int i = 0; i < n; ++i)
      if (isSO2(*space, i)) d(i) = std::remainder(d(i), 2 * kPi);
    const int m = std::max(1, int(std::ceil(d.cwiseAbs().maxCoeff() / 0.002)));
    for (int t = 1; t <= m; ++t)
      out.minSigma = std::min(out.minSigma, dexteritySingularValues(robot, out.path[k] + d * (double(t) / m))(0));
  }
  out.found = out.minSigma >= margin;
  if (!out.found) out.note = "the dense check found σ_min below the margin between OMPL's checked states";
  return finish();
}

}  // namespace soma
