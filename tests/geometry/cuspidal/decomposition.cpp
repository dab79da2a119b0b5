// The 6R decompositions (decomposition.hpp): both sides of each argument.
//   spherical wrist — Wenger's cuspidal orthogonal arm + a wrist is cuspidal (4 cusp points of the
//     arm, a lifted witness re-checked here, the same robot reversed too); the PUMA 560 and a KUKA
//     KR6 (modified DH with a base transform) are not (their arms split into quadratics);
//   parallel chain — the UR5 (POE) is not cuspidal; the argument checked on random postures: the
//     three step derivatives g1, g5, g3 multiply to det J up to a constant (so each vanishes only
//     on the singular set), and the 8 postures of random poses have 8 different sign vectors.
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/decomposition.hpp"
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/example_robots.hpp"

#include "soma/algebra/errors.hpp"
#include "support/scalars.hpp"

#include <cmath>
#include <random>
#include <set>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

constexpr double kPi = 3.14159265358979323846, kHalfPi = kPi / 2;

SerialRobot<double> ur5(double d1 = 0.089159, double a2 = -0.425, double a3 = -0.39225, double d4 = 0.10915,
                        double d5 = 0.09465, double d6 = 0.0823) {
  return ur5Robot<double>(d1, a2, a3, d4, d5, d6);
}

SerialRobot<double> kr6() { return kr6Robot<double>(); }

double apart(const JointVector<double>& a, const JointVector<double>& b) {
  double m = 0;
  for (int i = 0; i < a.size(); ++i) m = std::max(m, std::abs(std::remainder(a(i) - b(i), 2 * kPi)));
  return m;
}

/// The witness is a posture change of one pose along which det J keeps its sign.
void checkWitness(const SerialRobot<double>& robot, const Witness6R& w) {
  REQUIRE(w.found);
  CHECK(poseResidual(robot.fk(w.goal), robot.fk(w.start), robot.lengthScale()) <= Tolerance<double>::sqrtEpsilon());
  CHECK(apart(w.start, w.goal) > 0.1);
  REQUIRE(w.path.size() >= 2);
  double minDet = std::numeric_limits<double>::infinity(), step = 0;
  for (std::size_t k = 0; k < w.path.size(); ++k) {
    minDet = std::min(minDet, w.sign * jacobianDet6(robot, w.path[k]));
    if (k > 0) step = std::max(step, apart(w.path[k], w.path[k - 1]));
  }
  CHECK(minDet > 0);
  CHECK(minDet >= w.minSignedDet);  // the states are among the densely checked points
  CHECK(step <= 0.15);  // a dense path (the lift keeps a state every 0.04 rad; the search every 0.05 rad)
}

TEST_CASE("decomposition: a cuspidal orthogonal arm + spherical wrist is cuspidal, its arm's witness lifted",
          "[cuspidal][6r][decomposition][ompl]") {
  const SerialRobot<double> robot = orthogonalWristRobot<double>();
  const CuspidalDecomposition d = decomposeForCuspidality(robot);
  CHECK(d.kind == CuspidalDecompositionKind::SphericalWrist);
  CHECK_FALSE(d.reversed);
  CHECK(d.axes == "4, 5, 6");
  CuspidalOptions o;
  o.aspectGrid = 128;
  const CuspidalAnalysis a = analyseCuspidality(robot, o);
  CHECK(a.sixR);
  CHECK(a.decided);
  CHECK(a.cuspidal);
  CHECK(a.cusps.cusps.size() == 4);  // Wenger's arm (1, 2, 1.5, 1, 0): four cusp points (cusps.cpp)
  CHECK(a.reversals.size() == 4);    // the second method agrees
  REQUIRE(a.witness.found);
  checkWitness(robot, a.witness6r);
  // The wrist holds the orientation along the lifted path (not only at its ends).
  const Mat3<double> R0 = robot.fk(a.witness6r.start).rotation().matrix();
  double drift = 0;
  for (const auto& q : a.witness6r.path) drift = std::max(drift, (robot.fk(q).rotation().matrix() - R0).norm());
  CHECK(drift <= Tolerance<double>::sqrtEpsilon());
  // The wrist first: the reversed chain decides the same way, the witness in its own joint order.
  const SerialRobot<double> rev = robot.reversed();
  const CuspidalDecomposition dr = decomposeForCuspidality(rev);
  CHECK(dr.kind == CuspidalDecompositionKind::SphericalWrist);
  CHECK(dr.reversed);
  CHECK(dr.axes == "3, 2, 1");
  const CuspidalAnalysis b = analyseCuspidality(rev, o);
  CHECK(b.cuspidal);
  CHECK(b.cusps.cusps.size() == 4);
  checkWitness(rev, b.witness6r);
}

TEST_CASE("decomposition: the PUMA 560 and a KUKA KR6 (MDH, base transform) are not cuspidal",
          "[cuspidal][6r][decomposition]") {
  for (const SerialRobot<double>& robot : {puma560Robot<double>(), kr6()}) {
    CAPTURE(robot.name());
    const CuspidalAnalysis a = analyseCuspidality(robot);
    CHECK(a.decomposition.kind == CuspidalDecompositionKind::SphericalWrist);
    CHECK(a.decided);
    CHECK_FALSE(a.cuspidal);
    CHECK(a.cusps.cusps.empty());
    CHECK(a.cusps.frame.decoupled);  // axes 2, 3 parallel: the arm's IK splits into quadratics
    CHECK(a.aspectMap.count() == 4);  // shoulder × elbow
    CHECK_FALSE(a.witness6r.found);
  }
}

/// The three step derivatives of the parallel-chain argument at posture q (current axes from the
/// spatial Jacobian: direction ω, point ω × v).
Eigen::Vector3d stepDerivatives(const SerialRobot<double>& robot, const JointVector<double>& q) {
  const JacobianMatrix<double> J = robot.spatialJacobian(q);
  auto dir = [&](int i) { return Eigen::Vector3d(J.col(i).head<3>()); };
  auto pt = [&](int i) { return Eigen::Vector3d(dir(i).cross(J.col(i).tail<3>())); };
  const Eigen::Vector3d n = dir(1);
  // C = axis 5 ∩ axis 6 (closest point of axis 6 to axis 5).
  const Eigen::Vector3d u = dir(4), v = dir(5), w0 = pt(4) - pt(5);
  const double b = u.dot(v), dd = u.dot(w0), e = v.dot(w0);
  const Eigen::Vector3d C = pt(5) + v * ((e - b * dd) / (1 - b * b));
  const double g1 = dir(0).cross(n).dot(C - pt(0));
  const double g5 = n.dot(dir(4).cross(dir(5)));
  const double g3 = n.dot((pt(2) - pt(1)).cross(pt(3) - pt(2)));
  return {g1, g5, g3};
}

TEST_CASE("decomposition: the UR5 (POE) is not cuspidal — the sign vectors of the argument, checked",
          "[cuspidal][6r][decomposition]") {
  const SerialRobot<double> robot = ur5();
  const CuspidalDecomposition d = decomposeForCuspidality(robot);
  CHECK(d.kind == CuspidalDecompositionKind::ParallelChain);
  CHECK(d.axes == "2, 3, 4");
  const CuspidalAnalysis a = analyseCuspidality(robot);
  CHECK(a.decided);
  CHECK_FALSE(a.cuspidal);
  // A UR-type robot with other lengths, and the UR5 reversed (meeting axes 1, 2 before parallel 3, 4, 5).
  CHECK(decomposeForCuspidality(ur5(0.3, 0.7, -0.2, 0.15, 0.4, 0.1)).kind == CuspidalDecompositionKind::ParallelChain);
  const CuspidalDecomposition dr = decomposeForCuspidality(robot.reversed());
  CHECK(dr.kind == CuspidalDecompositionKind::ParallelChain);
  CHECK(dr.reversed);
  // GF's T3 robot (§10.3.2: parallel 2, 3, 4, axes 5, 6 meeting on the tool axis) too.
  CHECK(decomposeForCuspidality(t3Robot<double>()).kind == CuspidalDecompositionKind::ParallelChain);
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> U(-kPi, kPi);
  for (const SerialRobot<double>& r : {robot, ur5(0.3, 0.7, -0.2, 0.15, 0.4, 0.1), t3Robot<double>()}) {
    // det J = c · g1 · g5 · g3 for one constant c: each g vanishes only where det J does.
    double c = 0;
    for (int k = 0; k < 50; ++k) {
      JointVector<double> q(6);
      for (int i = 0; i < 6; ++i) q(i) = U(g);
      const Eigen::Vector3d s = stepDerivatives(r, q);
      const double ratio = jacobianDet6(r, q) / (s(0) * s(1) * s(2));
      if (k == 0) c = ratio;
      CHECK(ratio == Approx(c).epsilon(1e-9));
    }
    // The postures of random poses (up to 8: a shoulder branch may miss the elbow's annulus), each
    // with its own sign vector (g1, g5, g3).
    int eight = 0;
    for (int k = 0; k < 20; ++k) {
      JointVector<double> q(6);
      for (int i = 0; i < 6; ++i) q(i) = U(g);
      const Solution<double> sol = solveClosedForm(r, r.fk(q), IkMethod::Pieper);
      REQUIRE(sol.postures.size() >= 4);  // the sampled posture's shoulder branch: 2 wrists × 2 elbows
      eight += sol.postures.size() == 8;
      std::set<int> signs;
      for (const auto& p : sol.postures) {
        const Eigen::Vector3d s = stepDerivatives(r, p);
        signs.insert((s(0) > 0) * 4 + (s(1) > 0) * 2 + (s(2) > 0));
      }
      CHECK(signs.size() == sol.postures.size());
    }
    CHECK(eight >= 1);  // the full count is seen (UR5: most poses; T3: fewer)
  }
}

TEST_CASE("decomposition: what does not decompose", "[cuspidal][6r][decomposition]") {
  // A general 6R (standard DH, no three axes meeting or parallel).
  std::vector<DHRow<double>> rows = {{JointType::Revolute, 0.3, 0.7, 0.1, 0},  {JointType::Revolute, 0.8, -0.4, 0.2, 0},
                                     {JointType::Revolute, 0.5, 1.1, -0.3, 0}, {JointType::Revolute, 0.2, 0.6, 0.4, 0},
                                     {JointType::Revolute, 0.4, -0.9, 0.1, 0}, {JointType::Revolute, 0.1, 0.3, 0.2, 0}};
  CHECK(decomposeForCuspidality(SerialRobot<double>::fromDH(rows)).kind == CuspidalDecompositionKind::None);
  // A wrist in the middle (axes 3, 4, 5 meet): no positioning 3R arm of a point.
  rows = {{JointType::Revolute, 0.3, kHalfPi, 0.1, 0}, {JointType::Revolute, 0.8, 0, 0, 0},
          {JointType::Revolute, 0, kHalfPi, 0.5, 0},   {JointType::Revolute, 0, -kHalfPi, 0, 0},
          {JointType::Revolute, 0.3, kHalfPi, 0, 0},   {JointType::Revolute, 0.1, 0.4, 0.2, 0}};
  const SerialRobot<double> mid = SerialRobot<double>::fromDH(rows);
  REQUIRE(findPieperTriple(mid).first == 2);
  CHECK(decomposeForCuspidality(mid).kind == CuspidalDecompositionKind::None);
  // Bad input.
  rows.resize(4);
  CHECK_THROWS_AS(decomposeForCuspidality(SerialRobot<double>::fromDH(rows)), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
