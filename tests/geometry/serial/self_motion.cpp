// Robots with a self-motion at every pose (self_motion.hpp; issue 20 item 2): the generic Jacobian
// rank, the answer of solveIk for them (a continuum with representatives, never a count), the
// threshold tested on both sides, and the reason of an answer without postures.
#include "soma/geometry/serial/ik.hpp"
#include "soma/geometry/serial/self_motion.hpp"

#include "robots.hpp"
#include "support/scalars.hpp"

#include <random>

namespace SOMA_UNITY_ID {

using namespace soma;

namespace {

template <class S> S deg(double d) { return scalarCast<S>(d) * pi<S>() / S(180); }

/// A standard-DH 6R from rows (a, α degrees, d) in metres.
template <class S> SerialRobot<S> dh6(const double (&rows)[6][3], const char* name) {
  std::vector<DHRow<S>> dh(6);
  for (int i = 0; i < 6; ++i)
    dh[i] = {JointType::Revolute, scalarCast<S>(rows[i][0]), deg<S>(rows[i][1]), scalarCast<S>(rows[i][2]), S(0)};
  return SerialRobot<S>::fromDH(dh, DHConvention::Standard, SE3<S>(), SE3<S>(), name);
}

/// Every axis through the origin: the robot only rotates (rank 3, a 3-dimensional self-motion).
template <class S> SerialRobot<S> concurrent(double a4 = 0) {
  const double r[6][3] = {{0, 90, 0}, {0, -90, 0}, {0, 90, 0}, {a4, -90, 0}, {0, 90, 0}, {0, 0, 0}};
  return dh6<S>(r, "all axes concurrent");
}
/// Every axis parallel: planar motion (rank 3).
template <class S> SerialRobot<S> parallel() {
  const double r[6][3] = {{0.4, 0, 0.1}, {0.3, 0, 0}, {0.2, 0, 0}, {0.1, 0, 0}, {0.1, 0, 0}, {0.05, 0, 0}};
  return dh6<S>(r, "all axes parallel");
}
/// Joints 1 and 2 on one line (a = α = 0 between them): rank 5, a 1-dimensional self-motion
/// (a1 moves axis 2 off axis 1).
template <class S> SerialRobot<S> coincident(double a1 = 0) {
  const double r[6][3] = {{a1, 0, 0}, {0, 90, 0.3}, {0.4, 0, 0}, {0.1, -90, 0.4}, {0, 90, 0}, {0, -90, 0.1}};
  return dh6<S>(r, "joints 1 and 2 coincident");
}

template <class S> JointVector<S> randomJoints(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  JointVector<S> q(6);
  for (int i = 0; i < 6; ++i) q(i) = scalarCast<S>(u(g));
  return q;
}

/// Each representative reaches the pose: FK recomputed here, not the solver's residual.
template <class S> void checkRepresentatives(const SerialRobot<S>& robot, const SE3<S>& pose, const IkSolution<S>& sol) {
  for (std::size_t k = 0; k < sol.count(); ++k) {
    INFO("representative " << k + 1 << " of " << sol.count());
    CHECK(poseResidual(robot.fk(sol.postures[k]), pose, robot.lengthScale()) <= Tolerance<S>::identity(4096));
  }
}

}  // namespace

TEMPLATE_TEST_CASE("genericJacobianRank: concurrent 3, parallel 3, coincident 5, PUMA and a general 6R 6",
                   "[serial][self-motion]", SOMA_TEST_SCALARS) {
  using S = TestType;
  CHECK(genericJacobianRank(concurrent<S>()) == 3);
  CHECK(genericJacobianRank(parallel<S>()) == 3);
  CHECK(genericJacobianRank(coincident<S>()) == 5);
  CHECK(genericJacobianRank(test::puma560<S>()) == 6);
  CHECK(genericJacobianRank(test::general6rExample<S>()) == 6);
}

TEST_CASE("genericJacobianRank: the threshold on both sides (axis 2 off axis 1 by 1e-15 vs 1e-9 m, length scale 0.4 m)",
          "[serial][self-motion]") {
  // The threshold is 1024 ε(double) ≈ 2.3e-13 relative to σ₁ (judged at double's tolerance in every
  // scalar wider than double): an offset far below it is the coincident robot, far above it is not.
  CHECK(genericJacobianRank(coincident<double>(1e-15)) == 5);
  CHECK(genericJacobianRank(coincident<double>(1e-9)) == 6);
  CHECK(genericJacobianRank(coincident<long double>(1e-15)) == 5);
  CHECK(genericJacobianRank(coincident<__float128>(1e-15)) == 5);
  CHECK(genericJacobianRank(coincident<__float128>(1e-9)) == 6);
}

TEMPLATE_TEST_CASE("solveIk: a robot with a self-motion answers a continuum with representatives at its home and random poses, "
                   "whatever the method",
                   "[serial][self-motion][ik]", SOMA_TEST_SCALARS) {
  using S = TestType;
  std::mt19937_64 g(20);
  struct Case {
    SerialRobot<S> robot;
    int dimension;
  };
  const Case cases[] = {{concurrent<S>(), 3}, {parallel<S>(), 3}, {coincident<S>(), 1}};
  for (const auto& c : cases) {
    for (int trial = 0; trial < 2; ++trial) {
      const JointVector<S> q0 = trial == 0 ? JointVector<S>(JointVector<S>::Zero(6)) : randomJoints<S>(g);
      const SE3<S> pose = c.robot.fk(q0);
      // Every method gives the self-motion: all three in double, auto in the other scalars.
      std::vector<IkMethod> methods{IkMethod::Auto};
      if (std::is_same_v<S, double>) methods = {IkMethod::Auto, IkMethod::General6R, IkMethod::Pieper};
      for (IkMethod m : methods) {
        INFO(c.robot.name() << ", trial " << trial << ", method " << ikMethodName(m));
        IkOptions opt;
        opt.method = m;
        const IkSolution<S> sol = solveIk(c.robot, pose, opt);
        CHECK(sol.method == "self-motion");
        CHECK(sol.continuum);
        CHECK(sol.certified);
        CHECK(sol.self_motion_dimension == c.dimension);
        CHECK(sol.expected_count == 0);
        CHECK(sol.reason.empty());
        REQUIRE(sol.count() >= 1);
        CHECK(sol.count() <= 16);
        checkRepresentatives(c.robot, pose, sol);
      }
    }
  }
}

TEMPLATE_TEST_CASE("solveIk: a pose off a degenerate robot's reachable set answers no posture, out of reach",
                   "[serial][self-motion][ik]", double, long double) {
  using S = TestType;
  // The concurrent robot's tool never leaves the origin; the parallel robot's never tilts.
  const SE3<S> shifted(SO3<S>::Identity(), Vec3<S>(S(1) / S(2), S(0), S(0)));
  const IkSolution<S> a = solveIk(concurrent<S>(), shifted);
  CHECK(a.count() == 0);
  CHECK_FALSE(a.continuum);
  CHECK_FALSE(a.certified);
  CHECK(a.reason.rfind("out of reach", 0) == 0);
  const SE3<S> tilted(SO3<S>::fromAxisAngle(Vec3<S>(S(1), S(0), S(0)), S(1) / S(2)), Vec3<S>(S(1) / S(2), S(0), S(1) / S(10)));
  const IkSolution<S> b = solveIk(parallel<S>(), tilted);
  CHECK(b.count() == 0);
  CHECK(b.reason.rfind("out of reach", 0) == 0);
}

TEST_CASE("solveIk: no posture says why, out of reach or joint limits", "[serial][ik]") {
  // A PUMA 560 pose 10 m away: no real solution of the positioning equations.
  const SE3<double> far(SO3<double>::Identity(), Vec3<double>(10, 0, 0));
  const IkSolution<double> a = solveIk(test::puma560<double>(), far);
  CHECK(a.count() == 0);
  CHECK(a.reason.rfind("out of reach", 0) == 0);
  // The general 6R (general6r) for the same far pose: all 16 complex solutions non-real.
  const IkSolution<double> b = solveIk(test::general6rExample<double>(), far);
  CHECK(b.count() == 0);
  CHECK(b.reason.rfind("out of reach", 0) == 0);
  // θ1 limited to [0, 0.1] rad and a pose of θ1 = 2: both shoulder solutions of θ1 are outside.
  auto robot = test::puma560<double>();
  std::vector<double> lo(6, -10), hi(6, 10);
  lo[0] = 0, hi[0] = 0.1;
  robot = robot.withLimits(lo, hi);
  JointVector<double> q(6);
  q << 2.0, -0.5, 0.4, 0.3, 0.6, 0.2;
  const IkSolution<double> c = solveIk(robot, robot.fk(q));
  CHECK(c.count() == 0);
  CHECK(c.reason.rfind("joint limits", 0) == 0);
  // The same robot without the limits reaches it: the reason is the limits, not the reach.
  CHECK(solveIk(test::puma560<double>(), robot.fk(q)).count() == 8);
}

}  // namespace SOMA_UNITY_ID
