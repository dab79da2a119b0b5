#pragma once
// Definitions of self_motion.hpp: the generic Jacobian rank and points on a self-motion.
// Instantiated for the five scalars with the other entry points (serial_entry in geometry/CMakeLists.txt).
#include "soma/geometry/serial/self_motion.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>

namespace soma {

namespace selfmotion {

/// Relative threshold of the singular values that count: the working scalar's rank tolerance, but
/// never finer than double's (a robot read from a file is judged at double's tolerance in every
/// scalar: a structural deficiency is a property of the file, not of the scalar it is read in).
template <class S> S rankThreshold() { return std::max<S>(Tolerance<S>::rank(), scalarCast<S>(Tolerance<double>::rank())); }

/// The pose error e = (log(R* Rᵀ), (t* − t)/L) and the Jacobian of the pose at q in the same
/// coordinates (spatial angular velocity, tool-origin velocity / L): GF §4.5.
template <class S> struct PoseError {
  Vec6<S> e;
  Eigen::Matrix<S, 6, Eigen::Dynamic> J;
  S residual;
};

template <class S>
PoseError<S> poseError(const SerialRobot<S>& robot, const SE3<S>& target, const JointVector<S>& q) {
  const SE3<S> T = robot.fk(q);
  const S L = robot.lengthScale();
  PoseError<S> p;
  const SO3<S> E = target.so3().compose(T.so3().inverse());
  p.e.template head<3>() = E.log().coeffs();
  p.e.template tail<3>() = (target.translation() - T.translation()) / L;
  p.J = robot.spatialJacobian(q);
  const Vec3<S> t = T.translation();
  for (Eigen::Index i = 0; i < p.J.cols(); ++i) {
    const Vec3<S> w = p.J.col(i).template head<3>();
    const Vec3<S> v = p.J.col(i).template tail<3>();
    p.J.col(i).template tail<3>() = (v + w.cross(t)) / L;
  }
  p.residual = poseResidual<S>(T, target, L);
  return p;
}

/// The minimum-norm solution of J dq = e (singular values below S's rank tolerance × σ₁ cut: the
/// step is computed in S's own precision; only the rank decision is floored at double's).
template <class S> JointVector<S> minimumNormStep(const Eigen::Matrix<S, 6, Eigen::Dynamic>& J, const Vec6<S>& e) {
  detail::SmallMat<S> u, v;
  std::vector<S> sig;
  detail::smallSvd<S>(detail::SmallMat<S>(J), u, sig, v);
  JointVector<S> dq = JointVector<S>::Zero(J.cols());
  if (sig.empty() || !(sig[0] > S(0))) return dq;
  for (std::size_t k = 0; k < sig.size(); ++k) {
    if (!(sig[k] > Tolerance<S>::rank() * sig[0])) break;
    const S c = u.col(Eigen::Index(k)).dot(e) / sig[k];
    dq += c * v.col(Eigen::Index(k));
  }
  return dq;
}

/// Minimum-norm Gauss–Newton steps with step halving (a step is kept only when the error falls):
/// moves q onto the self-motion by the shortest joint displacement to first order. Returns the
/// residual reached.
template <class S>
S newtonOnto(const SerialRobot<S>& robot, const SE3<S>& target, JointVector<S>& q, int iterations, const S& stop) {
  PoseError<S> p = poseError(robot, target, q);
  for (int it = 0; it < iterations && !(p.residual <= stop); ++it) {
    const JointVector<S> dq = minimumNormStep<S>(p.J, p.e);
    if (!allFinite(dq)) break;
    S step(1);
    bool moved = false;
    for (int h = 0; h < 12; ++h, step /= S(2)) {
      const JointVector<S> qn = q + step * dq;
      PoseError<S> pn = poseError(robot, target, qn);
      if (pn.e.squaredNorm() < p.e.squaredNorm()) {
        q = qn;
        p = std::move(pn);
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return p.residual;
}

/// Joint difference b − a, revolute joints wrapped into (−π, π].
template <class S> JointVector<S> jointGap(const SerialRobot<S>& robot, const JointVector<S>& a, const JointVector<S>& b) {
  using std::atan2;
  using std::cos;
  using std::sin;
  JointVector<S> d = b - a;
  for (int i = 0; i < robot.dof(); ++i)
    if (robot.joints()[i].type == JointType::Revolute) d(i) = atan2(sin(d(i)), cos(d(i)));
  return d;
}

/// True when a path on the self-motion joins a to b: steps of at most 0.05 rad along the
/// projection of the joint gap to b onto the self-motion's tangent space (the null space of the
/// Jacobian), each step moved back onto the self-motion by minimum-norm Newton steps: the descent
/// of the distance to b along the self-motion. False when it stalls (the gap is normal to the
/// self-motion: a local minimum of the distance, or another component) or leaves the pose.
inline bool joined(const SerialRobot<double>& robot, const SE3<double>& target, const JointVector<double>& a,
                   const JointVector<double>& b) {
  constexpr double kStep = 0.05;
  JointVector<double> q = a;
  for (int it = 0; it < 600; ++it) {
    const JointVector<double> gap = jointGap(robot, q, b);
    const double dist = gap.norm();
    if (dist <= 1e-6) return true;
    const PoseError<double> p = poseError(robot, target, q);
    detail::SmallMat<double> u, v;
    std::vector<double> sig;
    detail::smallSvd<double>(detail::SmallMat<double>(p.J), u, sig, v);
    std::size_t r = 0;
    while (r < sig.size() && sig[r] > rankThreshold<double>() * sig[0]) ++r;
    JointVector<double> d = gap;
    for (std::size_t k = 0; k < r; ++k) d -= v.col(Eigen::Index(k)).dot(gap) * v.col(Eigen::Index(k));
    const double dn = d.norm();
    if (dn <= 1e-3 * dist) return false;
    q += d * std::min(1.0, kStep / dn);
    if (!(newtonOnto(robot, target, q, 10, 1e-13) <= 1e-10)) return false;
  }
  return false;
}

}  // namespace selfmotion

template <class S> int genericJacobianRank(const SerialRobot<S>& robot, int samples) {
  std::mt19937_64 g(0x5e1f);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  int best = 0;
  for (int s = 0; s <= samples; ++s) {
    JointVector<S> q = JointVector<S>::Zero(robot.dof());
    if (s > 0)
      for (int i = 0; i < robot.dof(); ++i) q(i) = scalarCast<S>(u(g));
    JacobianMatrix<S> J = robot.spatialJacobian(q);
    J.bottomRows(3) /= robot.lengthScale();
    const std::vector<S> sig = detail::smallSingularValues<S>(detail::SmallMat<S>(J));
    int r = 0;
    if (!sig.empty() && sig[0] > S(0))
      for (const S& x : sig)
        if (x > selfmotion::rankThreshold<S>() * sig[0]) ++r;
    best = std::max(best, r);
  }
  return best;
}

template <class S>
SelfMotion<S> solveSelfMotion(const SerialRobot<S>& robot, const SE3<S>& target, int rank, const SelfMotionOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  if (!allFinite(target.translation()) || !allFinite(target.quaternion().coeffs()))
    throw InvalidInput("self-motion: the target pose has a NaN or infinite entry");
  SelfMotion<S> out;
  out.rank = rank;
  out.dimension = robot.dof() - rank;
  // The search in double (fast; the points are polished in S below).
  const SerialRobot<double> rd = robot.template cast<double>();
  const SE3<double> td = target.template cast<double>();
  std::mt19937_64 g(options.seed);
  std::uniform_real_distribution<double> u(-pi<double>(), pi<double>());
  // A pose given in S is on the reachable set to S's rounding only (float: ~1e-7): "reached" at
  // 64 ulps of S, never finer than 1e-10 in the double search.
  const double reach = std::max(1e-10, toDouble(Tolerance<S>::identity(64)));
  std::vector<JointVector<double>> found;
  double closest = std::numeric_limits<double>::infinity();
  for (int s = 0; s < options.starts; ++s) {
    JointVector<double> q = JointVector<double>::Zero(rd.dof());
    if (s > 0)
      for (int i = 0; i < rd.dof(); ++i) q(i) = u(g);
    ++out.starts;
    const double res = selfmotion::newtonOnto(rd, td, q, options.iterations, 1e-13);
    closest = std::min(closest, res);
    if (!(res <= reach)) continue;
    ++out.converged;
    q = rd.wrap(q);
    bool known = false;
    for (const auto& f : found)
      if (selfmotion::jointGap(rd, f, q).norm() <= 1e-6) known = true;
    if (!known) found.push_back(q);
  }
  // Components: a point joins the first component whose representative a followed path reaches.
  std::vector<JointVector<double>> reps;
  for (const auto& q : found) {
    bool same = false;
    for (const auto& r : reps)
      if (selfmotion::joined(rd, td, r, q)) {
        same = true;
        break;
      }
    if (!same) reps.push_back(q);
  }
  for (const auto& qd : reps) {
    JointVector<S> q(qd.size());
    for (Eigen::Index i = 0; i < qd.size(); ++i) q(i) = scalarCast<S>(qd(i));
    const S res = selfmotion::newtonOnto<S>(robot, target, q, 300, Tolerance<S>::identity(16));
    out.representatives.push_back(robot.wrap(q));
    out.residuals.push_back(res);
  }
  out.closest = scalarCast<S>(closest);
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

#define SOMA_INSTANTIATE_SELF_MOTION(S)                                    \
  template int genericJacobianRank<S>(const SerialRobot<S>&, int);         \
  template SelfMotion<S> solveSelfMotion<S>(const SerialRobot<S>&, const SE3<S>&, int, \
                                            const SelfMotionOptions&);

}  // namespace soma
