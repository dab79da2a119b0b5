// SerialRobot: DH/MDH → POE, forward kinematics, Jacobians, singularity measures, bad robots.
#include "soma/geometry/serial/serial_robot.hpp"

#include "soma/algebra/errors.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;

namespace {

template <class S> std::vector<DHRow<S>> randomDH(std::mt19937_64& g, int n, bool withPrismatic) {
  std::vector<DHRow<S>> rows;
  for (int i = 0; i < n; ++i) {
    DHRow<S> r;
    r.type = (withPrismatic && i == 2) ? JointType::Prismatic : JointType::Revolute;
    r.a = uniform<S>(g);
    r.alpha = uniform<S>(g, -3, 3);
    r.d = uniform<S>(g);
    r.theta = uniform<S>(g, -3, 3);
    rows.push_back(r);
  }
  return rows;
}

template <class S> JointVector<S> randomQ(std::mt19937_64& g, int n) {
  JointVector<S> q(n);
  for (int i = 0; i < n; ++i) q(i) = uniform<S>(g, -3, 3);
  return q;
}

}  // namespace

TEMPLATE_TEST_CASE("serial: standard and modified DH products equal the POE forward kinematics",
                   "[serial][fk]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(11);
  const int trials = std::is_same_v<S, mpreal> ? 3 : 20;
  for (int k = 0; k < trials; ++k) {
    const auto rows = randomDH<S>(g, 6, true);
    const SE3<S> base = SE3<S>::Random(g), tool = SE3<S>::Random(g);
    const JointVector<S> q = randomQ<S>(g, 6);
    for (auto conv : {DHConvention::Standard, DHConvention::Modified}) {
      const auto robot = SerialRobot<S>::fromDH(rows, conv, base, tool);
      SE3<S> t = base;
      for (int i = 0; i < 6; ++i)
        t = t * (conv == DHConvention::Standard ? dhTransform(rows[i], q(i)) : mdhTransform(rows[i], q(i)));
      t = t * tool;
      CHECK(robot.fk(q).isApprox(t, Tolerance<S>::identity(512)));
      // The last DH frame (standard) is the flange: frames() ends at F_n.
      const auto fr = robot.frames(q);
      REQUIRE(fr.size() == 7);
      if (conv == DHConvention::Standard) CHECK((fr.back() * tool).isApprox(t, Tolerance<S>::identity(512)));
    }
  }
}

TEMPLATE_TEST_CASE("serial: Jacobians against central differences on SE(3)", "[serial][jacobian]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cbrt;
  auto& g = rng(12);
  const int trials = std::is_same_v<S, mpreal> ? 2 : 10;
  // Central difference error is O(h²) with h = eps^(1/3): eps^(2/3) times the third derivative.
  const S h = cbrt(Tolerance<S>::epsilon());
  const S tol = S(1000) * h * h;
  for (int k = 0; k < trials; ++k) {
    const auto robot = SerialRobot<S>::fromDH(randomDH<S>(g, 6, true), DHConvention::Standard);
    const JointVector<S> q = randomQ<S>(g, 6);
    const JacobianMatrix<S> Js = robot.spatialJacobian(q), Jb = robot.bodyJacobian(q);
    const SE3<S> T = robot.fk(q);
    for (int i = 0; i < 6; ++i) {
      JointVector<S> qp = q, qm = q;
      qp(i) += h;
      qm(i) -= h;
      const SE3<S> Tp = robot.fk(qp), Tm = robot.fk(qm);
      const Vec6<S> fs = (Tp * Tm.inverse()).log().coeffs() / (S(2) * h);
      const Vec6<S> fb = (Tm.inverse() * Tp).log().coeffs() / (S(2) * h);
      CHECK((fs - Js.col(i)).template lpNorm<Eigen::Infinity>() <= tol);
      CHECK((fb - Jb.col(i)).template lpNorm<Eigen::Infinity>() <= tol);
    }
    // J_b = Ad(T⁻¹) J_s, checked the other way round: J_s = Ad(T) J_b.
    CHECK((T.adjoint() * Jb - Js).template lpNorm<Eigen::Infinity>() <= Tolerance<S>::identity(1024));
  }
}

TEMPLATE_TEST_CASE("serial: the reversed robot gives the inverse pose", "[serial][fk]", SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  auto& g = rng(13);
  for (int k = 0; k < 10; ++k) {
    const auto robot = SerialRobot<S>::fromDH(randomDH<S>(g, 6, true), DHConvention::Standard,
                                              SE3<S>::Random(g), SE3<S>::Random(g));
    const JointVector<S> q = randomQ<S>(g, 6);
    const JointVector<S> qr = q.reverse();
    CHECK(robot.reversed().fk(qr).isApprox(robot.fk(q).inverse(), Tolerance<S>::identity(1024)));
  }
}

TEMPLATE_TEST_CASE("serial: singularity measures", "[serial][singularity]", SOMA_TEST_SCALARS) {
  using S = TestType;
  // PUMA 560-like DH (lengths in metres): elbow straight when θ3 = π/2 − atan(d4/a3) etc. Use
  // the wrist singularity θ5 = 0 instead: axes 4 and 6 coincide, rank 5.
  std::vector<DHRow<S>> rows(6);
  const S h = pi<S>() / S(2);
  rows[0] = {JointType::Revolute, S(0), h, S(0), S(0)};
  rows[1] = {JointType::Revolute, S(4318) / S(10000), S(0), S(0), S(0)};
  rows[2] = {JointType::Revolute, S(203) / S(10000), -h, S(15005) / S(100000), S(0)};
  rows[3] = {JointType::Revolute, S(0), h, S(4318) / S(10000), S(0)};
  rows[4] = {JointType::Revolute, S(0), -h, S(0), S(0)};
  rows[5] = {JointType::Revolute, S(0), S(0), S(0), S(0)};
  const auto robot = SerialRobot<S>::fromDH(rows);
  JointVector<S> q(6);
  q << S(1) / S(10), S(-1) / S(2), S(3) / S(10), S(7) / S(10), S(0), S(1) / S(5);
  const auto m0 = singularityMeasures(robot, q);
  CHECK(m0.rank == 5);
  CHECK(m0.smallestSingularValue <= Tolerance<S>::rank() * m0.largestSingularValue);
  q(4) = S(1) / S(2);
  const auto m1 = singularityMeasures(robot, q);
  CHECK(m1.rank == 6);
  CHECK(m1.condition < S(1000));
  // Manipulability = √det(JᵀJ) for the 6×6 case = |det J| (scaled rows).
  JacobianMatrix<S> J = robot.spatialJacobian(q);
  J.bottomRows(3) /= robot.lengthScale();
  const Mat6<S> J6 = J;
  using std::abs;
  CHECK(abs(m1.manipulability - abs(J6.determinant())) <= Tolerance<S>::identity(4096) * m1.manipulability);
}

TEST_CASE("serial: bad robots are rejected with the joint and the defect", "[serial][errors]") {
  using S = double;
  CHECK_THROWS_WITH(SerialRobot<S>::fromDH({}), Catch::Contains("no rows"));
  std::vector<DHRow<S>> rows(2);
  rows[1].a = std::nan("");
  CHECK_THROWS_WITH(SerialRobot<S>::fromDH(rows), Catch::Contains("joint 2 a is NaN"));
  std::vector<SerialJoint<S>> js(2);
  js[1].axis = Vec3<S>(0, 0, 2);
  CHECK_THROWS_WITH(SerialRobot<S>::fromPOE(js, SE3<S>()), Catch::Contains("joint 2 axis is not a unit vector"));
  js[1].axis = Vec3<S>(0, std::nan(""), 1);
  CHECK_THROWS_WITH(SerialRobot<S>::fromPOE(js, SE3<S>()), Catch::Contains("joint 2 axis has a NaN"));
  js[1].axis = Vec3<S>::UnitZ();
  js[0].lower = 1;
  js[0].upper = -1;
  CHECK_THROWS_WITH(SerialRobot<S>::fromPOE(js, SE3<S>()), Catch::Contains("joint 1 lower limit exceeds"));
  CHECK_THROWS_WITH(SerialRobot<S>::fromPOE({}, SE3<S>()), Catch::Contains("no joints"));
  const auto robot = SerialRobot<S>::fromDH(std::vector<DHRow<S>>(3));
  CHECK_THROWS_WITH(robot.fk(JointVector<S>::Zero(2)), Catch::Contains("robot has 3 joints"));
  JointVector<S> q = JointVector<S>::Zero(3);
  q(1) = std::numeric_limits<S>::infinity();
  CHECK_THROWS_WITH(robot.fk(q), Catch::Contains("joint value 2"));
  // An axis just inside the unit tolerance is accepted, one just outside rejected.
  js = std::vector<SerialJoint<S>>(1);
  js[0].axis = Vec3<S>(0, 0, 1 + 0.25 * Tolerance<S>::input());
  CHECK_NOTHROW(SerialRobot<S>::fromPOE(js, SE3<S>()));
  js[0].axis = Vec3<S>(0, 0, 1 + 2 * Tolerance<S>::input());
  CHECK_THROWS_AS(SerialRobot<S>::fromPOE(js, SE3<S>()), InvalidInput);
}

// Issue 24: at 1e160 the squared lengths overflow double; the length scale is a norm (safeNorm), so
// the robot is the same robot, of rank 6, at every scale its lengths can be written in.
TEST_CASE("serial: lengths 1e-8 … 1e160 scale the pose exactly and keep the rank", "[serial][fk][extreme][hostile]") {
  auto& g = rng(14);
  const auto rows = randomDH<double>(g, 6, false);
  const JointVector<double> q = randomQ<double>(g, 6);
  const auto unit = SerialRobot<double>::fromDH(rows);
  const SE3<double> t1 = unit.fk(q);
  const auto m1 = singularityMeasures(unit, q);
  REQUIRE(m1.rank == 6);
  for (double s : {1e-8, 1e8, 1e-160, 1e160, 1e300}) {
    auto scaled = rows;
    for (auto& r : scaled) {
      r.a *= s;
      r.d *= s;
    }
    const auto robot = SerialRobot<double>::fromDH(scaled);
    const SE3<double> ts = robot.fk(q);
    CHECK((ts.rotation() - t1.rotation()).norm() <= Tolerance<double>::identity(64));
    CHECK((ts.translation() / s - t1.translation()).norm() <= Tolerance<double>::identity(64));
    CHECK(robot.lengthScale() / s > 0.1);
    CHECK(robot.lengthScale() / s < 10);
    INFO("lengths ×" << s);
    const auto ms = singularityMeasures(robot, q);
    CHECK(ms.rank == 6);
    CHECK(std::abs(ms.condition - m1.condition) <= 1e-10 * m1.condition);
  }
}

}  // namespace SOMA_UNITY_ID
