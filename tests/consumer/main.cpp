// A soma user's program: every posture of a PUMA 560 for one pose through the library's front door
// soma::solveIk (method auto: the closed-form Pieper solver, GF §10.3.1), each checked by forward
// kinematics.
#include <soma/soma.hpp>

#include <cstdio>
#include <vector>

int main() {
  using S = double;
  using namespace soma;
  // Standard DH table of the PUMA 560 (a, α, d, θ; metres and radians).
  const S h = pi<S>() / 2;
  const std::vector<DHRow<S>> rows = {
      {JointType::Revolute, 0.0, h, 0.0, 0.0},          {JointType::Revolute, 0.4318, 0.0, 0.0, 0.0},
      {JointType::Revolute, 0.0203, -h, 0.15005, 0.0}, {JointType::Revolute, 0.0, h, 0.4318, 0.0},
      {JointType::Revolute, 0.0, -h, 0.0, 0.0},         {JointType::Revolute, 0.0, 0.0, 0.05625, 0.0}};
  const auto robot = SerialRobot<S>::fromDH(rows, DHConvention::Standard, SE3<S>(), SE3<S>(), "PUMA 560");

  // The target is the robot's own pose at a generic joint vector: it has 8 real postures.
  JointVector<S> q0(6);
  q0 << 0.3, -0.7, 0.4, 1.1, -0.6, 0.9;
  const SE3<S> target = robot.fk(q0);
  const IkSolution<S> sol = solveIk(robot, target, IkOptions{});

  const S tol = Tolerance<S>::input();
  int bad = 0;
  bool foundQ0 = false;
  for (const auto& q : sol.postures) {
    if (poseResidual(robot.fk(q), target, robot.lengthScale()) > tol) ++bad;
    if ((robot.wrap(q) - robot.wrap(q0)).cwiseAbs().maxCoeff() <= tol) foundQ0 = true;
  }
  std::printf("%s, method %s: %zu postures (%d expected), %d with FK off the pose, q0 %s, %s\n",
              robot.name().c_str(), sol.method.c_str(), sol.count(), sol.expected_count, bad,
              foundQ0 ? "found" : "missing", sol.certified ? "certified" : "not certified");
  return sol.count() == 8 && bad == 0 && foundQ0 && sol.certified ? 0 : 1;
}
