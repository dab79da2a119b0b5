#pragma once
// Definitions of solveIk (ik.hpp): the closed forms, the general-6R eigenproblem with its numerical
// completion, and the numerical methods in double polished in the working scalar. Instantiated for
// the five scalars by soma_instantiate (geometry/CMakeLists.txt).
#include "soma/geometry/serial/ik.hpp"
#include "soma/geometry/serial/joint_limits.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/numeric_polish.hpp"
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/geometry/serial/standard_dh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace soma {

namespace {

template <class S> Robot6R<double> toDouble6R(const Robot6R<S>& rows) {
  Robot6R<double> rd;
  for (int i = 0; i < 6; ++i) rd[i] = rows[i].template cast<double>();
  return rd;
}

/// A posture of the general-6R methods in double carried to S: Newton steps on the pose
/// equations in S, the joint values wrapped by `robot`, with its residual.
template <class S> struct Lifted6R {
  JointVector<S> q;
  S residual;
};
template <class S>
Lifted6R<S> lift6R(const Robot6R<S>& rows, const SE3<S>& flange, const SerialRobot<S>& robot, const JointVector<double>& qd) {
  std::array<S, 6> q;
  for (int i = 0; i < 6; ++i) q[i] = scalarCast<S>(qd(i));
  q = polishGeneral6R<S>(rows, flange, q, General6ROptions{}.polish_iterations);
  JointVector<S> v(6);
  for (int i = 0; i < 6; ++i) v(i) = q[i];
  return {robot.wrap(v), general6rResidual<S>(rows, flange, q)};
}

/// True when the eigenproblem's answer may be short: not 16 complex solutions, an odd real
/// count, or the solver says so (e.g. a leading matrix singular at every θ3 offset, as for robots
/// just outside the Pieper class). GF §11.5 (16 complex postures)
template <class S> bool mayBeShort(const General6RSolution<S>& g) {
  bool shortAnswer = g.complex_count != 16 || g.count() % 2 == 1;
  for (const auto& n : g.notes)
    if (n.find("may be short") != std::string::npos) shortAnswer = true;
  return shortAnswer;
}

/// The change of strategy when the algebraic answer may be short: a Ceres multi-start search in
/// double, each posture Newton-polished in S and added when it is new. The count is then not
/// certified, and the notes say so. GF §11.5 (16 complex postures)
template <class S>
void completeNumerically(const Robot6R<S>& rows, const SE3<S>& flange, const SerialRobot<S>& robot, int starts,
                         General6RSolution<S>& g) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  General6RNumericOptions opt;
  opt.starts = starts;
  const Robot6R<double> rd = toDouble6R(rows);
  const SE3<double> fd = flange.template cast<double>();
  const auto lifted = searchInDoublePolishInS(
      [&] { return solveGeneral6RCeres(rd, fd, opt); },
      [&](const JointVector<double>& qd) -> std::optional<Lifted6R<S>> {
        Lifted6R<S> l = lift6R(rows, flange, robot, qd);
        if (!(l.residual <= Tolerance<S>::sqrtEpsilon())) return std::nullopt;
        return l;
      });
  int added = 0;
  for (const auto& l : lifted.polished) {
    bool known = false;
    for (const auto& p : g.postures) {
      S gap(0);
      for (int i = 0; i < 6; ++i) {
        const S d = l.q(i) - p(i);
        gap = std::max<S>(gap, abs(atan2(sin(d), cos(d))));
      }
      if (gap <= Tolerance<S>::input()) known = true;
    }
    if (known) continue;
    g.postures.push_back(l.q);
    g.residuals.push_back(l.residual);
    ++added;
  }
  g.seconds += lifted.seconds;
  g.notes.push_back("the eigenproblem answer may be short (" + std::to_string(g.complex_count) +
                    " complex solutions): numerical completion by Ceres (" + std::to_string(starts) +
                    " starts in double, Newton in " + std::string(scalarName<S>()) + ") added " +
                    std::to_string(added) + " posture(s); this count is not certified complete");
}

template <class S> IkSolution<S> general6R(const SerialRobot<S>& robotIn, const SE3<S>& target, const IkOptions& opt) {
  const IkMethod method = opt.method;
  const std::string name(ikMethodName(method));
  if (robotIn.dof() != 6 || !robotIn.allRevolute())
    throw InvalidInput("ik method " + name + ": needs a robot with 6 revolute joints");
  // The general 6R solver (general_6r.hpp) takes six standard DH rows and the pose of frame 6 in
  // frame 0: a POE (URDF) or modified-DH robot is rewritten in standard DH first, then the base
  // and tool are stripped.
  const SerialRobot<S> robot = robotIn.convention() == DHConvention::Standard ? robotIn : toStandardDH(robotIn);
  Robot6R<S> rows;
  for (int i = 0; i < 6; ++i) rows[i] = robot.dhRows()[i];
  const SE3<S> flange = robot.base().inverse() * target * robot.tool().inverse();
  General6RSolution<S> g;
  bool certified = false;
  if (method == IkMethod::General6R) {
    g = solveGeneral6R<S>(rows, flange);
    g.notes.push_back("complex solutions of the eigenproblem: " + std::to_string(g.complex_count) +
                      ", solved in " + g.solved_in);
    certified = !mayBeShort(g);
    if (!certified && opt.complete) completeNumerically<S>(rows, flange, robot, opt.completionStarts, g);
  } else {
    const Robot6R<double> rd = toDouble6R(rows);
    const SE3<double> fd = flange.template cast<double>();
    const auto lifted = searchInDoublePolishInS(
        [&] { return method == IkMethod::Ceres ? solveGeneral6RCeres(rd, fd) : solveGeneral6RNlopt(rd, fd); },
        [&](const JointVector<double>& qd) -> std::optional<Lifted6R<S>> {
          // Ceres and NLopt polish in double themselves: in double the posture is kept as found.
          if constexpr (std::is_same_v<S, double>) return std::nullopt;
          else return lift6R(rows, flange, robot, qd);
        });
    const General6RSolution<double>& gd = lifted.found;
    g.method = gd.method;
    g.expected_count = gd.expected_count;
    g.notes = gd.notes;
    g.continuum = gd.continuum;
    if constexpr (std::is_same_v<S, double>) {
      g.postures = gd.postures;
      g.residuals = gd.residuals;
    } else {
      for (const auto& l : lifted.polished) {
        g.postures.push_back(l.q);
        g.residuals.push_back(l.residual);
      }
      g.notes.push_back(polishedInNote<S>(name));
    }
    g.seconds = lifted.seconds;
  }
  // The robot's joint limits apply as for the closed forms (which drop such postures themselves).
  IkSolution<S> kept;
  static_cast<Solution<S>&>(kept) = static_cast<const Solution<S>&>(g);
  kept.postures.clear();
  kept.residuals.clear();
  for (std::size_t k = 0; k < g.count(); ++k)
    if (const auto inside = shiftIntoLimits(robot, g.postures[k])) {  // θ + 2πk where the limits lie off (−π, π]
      kept.postures.push_back(*inside);
      kept.residuals.push_back(g.residuals[k]);
    }
  if (kept.count() < g.count())
    kept.notes.push_back(std::to_string(g.count() - kept.count()) + " posture(s) outside the joint limits dropped");
  kept.certified = certified;
  if (method == IkMethod::General6R) {
    kept.complex_count = g.complex_count;
    kept.solved_in = g.solved_in;
    kept.elimination = g.elimination;
  }
  // More postures than the class has complex ones cannot be a posture count: the pose lies on
  // (or numerically next to) a self-motion, and the search returned points of it.
  if (int(kept.count()) > kept.expected_count) {
    kept.continuum = true;
    kept.certified = false;
    kept.notes.push_back(std::to_string(kept.count()) + " postures exceed the generic count " +
                         std::to_string(kept.expected_count) +
                         ": the pose lies on or next to a self-motion; these are points of it, not a count");
  }
  return kept;
}


/// A 6R robot of generic rank below 6 (self_motion.hpp): representatives of the self-motion over
/// the pose, or none with the reason. The asked method does not apply (it would count points of
/// a continuum): the notes say which was asked for.
template <class S>
IkSolution<S> selfMotionAnswer(const SerialRobot<S>& robot, const SE3<S>& pose, int rank, IkMethod asked) {
  const SelfMotion<S> m = solveSelfMotion<S>(robot, pose, rank);
  IkSolution<S> sol;
  sol.method = "self-motion";
  sol.expected_count = 0;
  sol.generic_rank = rank;
  sol.self_motion_dimension = m.dimension;
  sol.seconds = m.seconds;
  sol.notes.push_back("the joint screws span " + std::to_string(rank) + " of 6 dimensions at every configuration: every pose the robot reaches has a " +
                      std::to_string(m.dimension) + "-dimensional self-motion (no finite posture count)" +
                      (asked == IkMethod::Auto ? std::string() : "; method " + std::string(ikMethodName(asked)) + " not used"));
  int outside = 0;
  for (std::size_t k = 0; k < m.representatives.size(); ++k) {
    const auto inside = shiftIntoLimits(robot, m.representatives[k]);
    if (!inside) {
      ++outside;
      continue;
    }
    sol.postures.push_back(*inside);
    sol.residuals.push_back(m.residuals[k]);
  }
  sol.continuum = m.converged > 0;
  if (m.converged > 0) {
    sol.notes.push_back(std::to_string(m.representatives.size()) + " component(s) told apart among " + std::to_string(m.converged) + " of " +
                        std::to_string(m.starts) + " starts that reached the pose (points joined by a joint path on the self-motion are one component; "
                        "two representatives not joined may still lie on one)");
    sol.certified = true;  // the answer "a continuum" is exact: the rank deficiency holds everywhere
  }
  if (outside) {
    sol.notes.push_back(std::to_string(outside) + " representative(s) outside the joint limits dropped (the self-motion may meet the limits' box elsewhere: not searched)");
    if (sol.postures.empty()) sol.reason = "joint limits: every representative of the self-motion lies outside the joint limits";
  }
  if (m.converged == 0)
    sol.reason = "out of reach: the robot moves on a " + std::to_string(rank) + "-dimensional set of poses and none of " + std::to_string(m.starts) +
                 " starts reached this one (closest residual " + toString(m.closest, 3) + ")";
  return sol;
}

/// Why an answer without postures has none (IkSolution::reason).
template <class S> std::string noPostureReason(const IkSolution<S>& sol) {
  for (const auto& n : sol.notes)
    if (n.find("outside the joint limits dropped") != std::string::npos)
      return "joint limits: every posture lies outside the joint limits";
  if (sol.complex_count > 0)
    return "out of reach: the " + std::to_string(sol.complex_count) + " complex solutions are all non-real";
  return "out of reach: the pose equations have no real solution";
}

}  // namespace

template <class S> IkSolution<S> solveIk(const SerialRobot<S>& robot, const SE3<S>& pose, const IkOptions& options) {
  IkOptions opt = options;
  if (robot.dof() == 6 && robot.allRevolute()) {
    const int rank = genericJacobianRank(robot);
    if (rank < 6) return selfMotionAnswer<S>(robot, pose, rank, opt.method);
  }
  if (opt.method == IkMethod::Auto) opt.method = classifyRobot(robot);
  // A robot near, not exactly, Pieper (a calibrated arm whose axes miss meeting or being parallel by
  // more than rounding, less than the classification's Tolerance::input()) is the general 6R it is:
  // the closed form of its idealised robot would miss the pose by about the defect and can lose
  // postures (in float, input() = 2.2e-2 classes a 1e-3 calibration error as Pieper: 4 or 6 of 8
  // postures, SOMA-6R-calibration-sweep --scalar float). The threshold is 256 ulps of the length
  // scale: axes built in S (from DH rows, or a file's decimals) meet or are parallel to a few ulps.
  const PieperTriple<S> tri = options.method == IkMethod::Auto && opt.method == IkMethod::Pieper ? findPieperTriple(robot) : PieperTriple<S>{};
  const bool nearPieper = tri.first >= 0 && !(tri.defect <= Tolerance<S>::identity(256));
  if (nearPieper) opt.method = IkMethod::General6R;
  IkSolution<S> sol;
  if (nearPieper) {
    sol = general6R<S>(robot, pose, opt);
    sol.notes.push_back("the axes " + std::to_string(tri.first + 1) + "–" + std::to_string(tri.first + 3) + (tri.concurrent ? " miss a common point by " : " miss being parallel by ") +
                        toString(tri.defect, 3) + (tri.concurrent ? " of the length scale" : " rad") +
                        " (the robot is near, not exactly, a Pieper robot): solved as a general 6R");
  } else if (opt.method == IkMethod::General6R || opt.method == IkMethod::Ceres || opt.method == IkMethod::Nlopt) {
    sol = general6R<S>(robot, pose, opt);
  } else {
    static_cast<Solution<S>&>(sol) = solveClosedForm<S>(robot, pose, opt.method);
    sol.certified = true;
    // The safety net behind the defect test above: a closed form that misses the pose by more than
    // 4096 ulps, or finds no posture (an empty answer has no residual to miss by), is replaced by
    // the general 6R's answer.
    if (options.method == IkMethod::Auto && opt.method == IkMethod::Pieper &&
        (sol.count() == 0 || !(sol.worstResidual() <= Tolerance<S>::identity(4096)))) {
      const std::string missed = sol.count() == 0 ? std::string("found no posture") : "missed the pose by " + toString(sol.worstResidual(), 3);
      IkOptions g = opt;
      g.method = IkMethod::General6R;
      sol = general6R<S>(robot, pose, g);
      sol.notes.push_back("the Pieper closed form " + missed + ": solved as a general 6R");
    }
  }
  if (robot.dof() == 6) sol.generic_rank = 6;
  if (sol.count() == 0 && !sol.continuum) sol.reason = noPostureReason(sol);
  return sol;
}

#define SOMA_INSTANTIATE_IK(S) \
  template IkSolution<S> solveIk<S>(const SerialRobot<S>&, const SE3<S>&, const IkOptions&);

}  // namespace soma
