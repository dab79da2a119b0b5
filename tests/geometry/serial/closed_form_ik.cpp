// Closed-form IK: 3R wrists (GF §5.1), 3R arms (GF §5.2), Pieper robots (GF §10.3).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/example_robots.hpp"

#include "soma/algebra/errors.hpp"
#include "robots.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::puma560;
using soma::test::rng;
using soma::test::uniform;
using soma::test::unitVec3;

namespace {

/// Residual tolerance of a closed-form posture: the solvers polish by Newton's method, so the
/// residual is a few hundred ulps of unit-scale data unless the pose is near-singular.
template <class S> S postureTol() { return Tolerance<S>::identity(4096); }

template <class S> bool containsPosture(const Solution<S>& sol, const JointVector<S>& q, const S& tol) {
  using std::abs;
  using std::cos;
  using std::sin;
  for (const auto& p : sol.postures) {
    bool same = true;
    for (int i = 0; i < q.size(); ++i)
      if (abs(sin(p(i) - q(i))) > tol || cos(p(i) - q(i)) < S(0)) same = false;
    if (same) return true;
  }
  return false;
}

template <class S> JointVector<S> randomQ(std::mt19937_64& g, int n) {
  JointVector<S> q(n);
  for (int i = 0; i < n; ++i) q(i) = uniform<S>(g, -3, 3);
  return q;
}

/// Round trip: q → T → IK; q is among the postures, every posture reproduces T, the count is
/// even and at most the class maximum.
template <class S> void roundTrip(const SerialRobot<S>& robot, const JointVector<S>& q, IkMethod m,
                                  int maxCount, const S& tol) {
  const SE3<S> T = robot.fk(q);
  const Solution<S> sol = solveClosedForm(robot, T, m);
  INFO("method " << sol.method << " count " << sol.count());
  CHECK(sol.count() <= std::size_t(maxCount));
  CHECK(sol.count() % 2 == 0);
  CHECK(sol.expected_count == maxCount);
  CHECK(containsPosture(sol, q, S(1000) * tol));
  for (const auto& r : sol.residuals) CHECK(r <= tol);
  // Every posture reproduces T by the robot's own forward kinematics (SE(3) products of the joint
  // motions), independently of the solver's residual, whose forward kinematics takes the cosines and
  // sines each angle was computed from: a wrong step from those to the returned angle fails here.
  using std::sqrt;
  for (const auto& p : sol.postures) {
    const SE3<S> Tp = robot.fk(p);
    const S rot = sqrt((Tp.rotation() - T.rotation()).squaredNorm());
    const S pos = sqrt((Tp.translation() - T.translation()).squaredNorm()) / robot.lengthScale();
    const S r = sol.method == "wrist3r" ? rot : sol.method == "arm3r" ? pos : poseResidual(Tp, T, robot.lengthScale());
    CHECK(r <= tol);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("closed form: p cos φ + q sin φ = k on both sides of the discriminant threshold",
                   "[serial][ik][trig]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const S r = Tolerance<S>::rank();
  // p = 1, q = 0, k = 1 + δ: disc = −2δ (relative to ρ² = 1).
  const auto inside = solveLinearTrig<S>(S(1), S(0), S(1) + r / S(8));
  CHECK(inside.angles.size() == 2);
  CHECK(inside.doubleRoot);
  const auto outside = solveLinearTrig<S>(S(1), S(0), S(1) + S(2) * r);
  CHECK(outside.angles.empty());
  const auto generic = solveLinearTrig<S>(S(3), S(4), S(1));
  REQUIRE(generic.angles.size() == 2);
  using std::cos;
  using std::sin;
  using std::abs;
  for (const auto& a : generic.angles) CHECK(abs(S(3) * cos(a) + S(4) * sin(a) - S(1)) <= Tolerance<S>::identity(16));
  CHECK(solveLinearTrig<S>(S(0), S(0), S(0)).free);
  CHECK(solveLinearTrig<S>(S(0), S(0), S(1)).angles.empty());
}

TEMPLATE_TEST_CASE("closed form: 3R wrist, random axes, both postures (GF §5.1)", "[serial][ik][wrist]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(21);
  const int trials = std::is_same_v<S, mpreal> ? 3 : 40;
  for (int k = 0; k < trials; ++k) {
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) j.axis = unitVec3<S>(g);
    const SE3<S> home(SO3<S>::Random(g), Vec3<S>::Zero());
    const auto robot = SerialRobot<S>::fromPOE(js, home);
    roundTrip(robot, randomQ<S>(g, 3), IkMethod::Auto, 2, postureTol<S>());
  }
}

TEST_CASE("closed form: RPY wrist, the book's example with errata E5.1/E5.2", "[serial][ik][wrist]") {
  // GF §5.1 RPY wrist v1 = k, v2 = j, v3 = i: R = Rz(θ1) Ry(θ2) Rx(θ3); θ = (0.7, −0.4, 2.2).
  const Vec3<double> v1 = Vec3<double>::UnitZ(), v2 = Vec3<double>::UnitY(), v3 = Vec3<double>::UnitX();
  const Mat3<double> R = (Eigen::AngleAxisd(0.7, v1) * Eigen::AngleAxisd(-0.4, v2) * Eigen::AngleAxisd(2.2, v3))
                             .toRotationMatrix();
  CHECK(-R(2, 0) == Approx(-0.3894183).epsilon(1e-6));  // sin θ2 = −r31 (E5.2; printed r13 = 0.696)
  const auto w = wrist3R<double>(v1, v2, v3, R);
  REQUIRE(w.angles.size() == 2);
  bool found = false;
  for (const auto& a : w.angles)
    if ((a - Vec3<double>(0.7, -0.4, 2.2)).norm() < 1e-12) found = true;
  CHECK(found);
  // The other posture is (θ1 + π, π − θ2, θ3 + π).
  CHECK(!w.gimbal);
}

TEMPLATE_TEST_CASE("closed form: wrist gimbal singularity on both sides of the threshold",
                   "[serial][ik][wrist][singular]", SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::sqrt;
  const Vec3<S> v1 = Vec3<S>::UnitZ(), v2 = Vec3<S>::UnitY(), v3 = Vec3<S>::UnitX();
  // θ2 = π/2 − δ: y = e^{θ2 v2} v3 is at angle δ from v1 (|y × v1| = sin δ). Threshold √(64 eps).
  const S thr = sqrt(Tolerance<S>::identity(64));
  for (const S delta : {S(thr / S(10)), S(thr * S(10)), S(0)}) {
    JointVector<S> q(3);
    q << S(3) / S(10), pi<S>() / S(2) - delta, S(-1) / S(2);
    std::vector<SerialJoint<S>> js(3);
    js[0].axis = v1, js[1].axis = v2, js[2].axis = v3;
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>());
    const auto sol = solveWrist3R(robot, robot.fk(q));
    INFO("delta " << toDouble(delta));
    CHECK(sol.continuum == (delta < thr));
    CHECK(sol.count() == 2);
    // Near the singularity θ1, θ3 individually lose ~eps/δ; the residual stays at √eps scale.
    for (const auto& r : sol.residuals) CHECK(r <= S(16) * sqrt(Tolerance<S>::identity(64)));
  }
}

TEMPLATE_TEST_CASE("closed form: 3R arm, random arms, up to 4 postures (GF §5.2.1)", "[serial][ik][arm]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(22);
  const int trials = std::is_same_v<S, mpreal> ? 3 : 40;
  int four = 0;
  for (int k = 0; k < trials; ++k) {
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) {
      j.axis = unitVec3<S>(g);
      j.point = soma::test::uniformVec<S, 3>(g);
    }
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), soma::test::uniformVec<S, 3>(g)));
    const JointVector<S> q = randomQ<S>(g, 3);
    roundTrip(robot, q, IkMethod::Arm3R, 4, postureTol<S>());
    if (solveArm3R(robot, robot.fk(q)).count() == 4) ++four;
  }
  if (trials > 10) CHECK(four > 0);  // 4-posture targets occur (12 of 30 in the catalogue's run)
}

TEST_CASE("closed form: the finger / PUMA arm of GF §5.2.2 (errata E5.4–E5.6)", "[serial][ik][arm]") {
  // v1 = k, v2 = v3 = i; r1 = 0, r2 = l1 j, r3 = (l1 + l2) j; p0 = (l1 + l2 + l3) j.
  const double l1 = 0.8, l2 = 1.1, l3 = 0.6;
  std::vector<SerialJoint<double>> js(3);
  js[0].axis = Vec3<double>::UnitZ();
  js[1].axis = Vec3<double>::UnitX(), js[1].point = Vec3<double>(0, l1, 0);
  js[2].axis = Vec3<double>::UnitX(), js[2].point = Vec3<double>(0, l1 + l2, 0);
  const auto robot = SerialRobot<double>::fromPOE(js, SE3<double>(SO3<double>(), Vec3<double>(0, l1 + l2 + l3, 0)));
  JointVector<double> q(3);
  q << 0.9, -0.5, 1.2;
  const auto sol = solveArm3R(robot, robot.fk(q));
  // The catalogue: corrected cos θ3 roots {0.3623578, 5.754470}: the second is infeasible, so 2 postures.
  CHECK(sol.count() == 2);
  CHECK(containsPosture(sol, q, 1e-9));
  for (const auto& p : sol.postures) CHECK(std::cos(p(2)) == Approx(0.3623578).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("closed form: PUMA 560, random poses, up to 8 postures (GF §10.3.3)",
                   "[serial][ik][pieper]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(23);
  const auto robot = puma560Robot<S>();
  REQUIRE(classifyRobot(robot) == IkMethod::Pieper);
  const int trials = std::is_same_v<S, mpreal> ? 2 : 30;
  int eight = 0;
  for (int k = 0; k < trials; ++k) {
    const JointVector<S> q = randomQ<S>(g, 6);
    roundTrip(robot, q, IkMethod::Auto, 8, postureTol<S>());
    if (solvePieper(robot, robot.fk(q)).count() == 8) ++eight;
  }
  if (trials > 10) CHECK(eight > 0);
}

TEMPLATE_TEST_CASE("closed form: T³ robot, parallel axes 2-4 (GF §10.3.2)", "[serial][ik][pieper]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(24);
  const auto robot = t3Robot<S>();
  const auto tri = findPieperTriple(robot);
  CHECK(tri.first == 1);
  CHECK(!tri.concurrent);
  const int trials = std::is_same_v<S, mpreal> ? 2 : 30;
  JointVector<S> q0(6);  // the catalogue's instance
  q0 << S(4) / S(10), S(-7) / S(10), S(11) / S(10), S(1) / S(2), S(35) / S(100), S(-12) / S(10);
  roundTrip(robot, q0, IkMethod::Pieper, 8, postureTol<S>());
  for (int k = 0; k < trials; ++k) roundTrip(robot, randomQ<S>(g, 6), IkMethod::Pieper, 8, postureTol<S>());
}

TEMPLATE_TEST_CASE("closed form: Pieper triples in every position (reversed robots)", "[serial][ik][pieper]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  auto& g = rng(25);
  // Random 6R robots made Pieper by forcing a triple to meet (or be parallel) at each position.
  for (int first = 0; first < 4; ++first)
    for (bool concurrent : {true, false})
      for (int k = 0; k < 6; ++k) {
        std::vector<SerialJoint<S>> js(6);
        for (auto& j : js) {
          j.axis = unitVec3<S>(g);
          j.point = soma::test::uniformVec<S, 3>(g);
        }
        const Vec3<S> c = soma::test::uniformVec<S, 3>(g), u = unitVec3<S>(g);
        for (int i = first; i < first + 3; ++i) {
          if (concurrent) js[i].point = c;
          else js[i].axis = u;
        }
        const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>::Random(g));
        const auto tri = findPieperTriple(robot);
        INFO("triple " << first + 1 << (concurrent ? " concurrent" : " parallel"));
        REQUIRE(tri.first >= 0);
        roundTrip(robot, randomQ<S>(g, 6), IkMethod::Pieper, 8, postureTol<S>());
      }
}

TEST_CASE("closed form: PUMA extremes — wrist singular, elbow straight, angles 0 and π, lengths 1e±8",
          "[serial][ik][pieper][extreme]") {
  using S = double;
  const auto robot = puma560Robot<S>();
  JointVector<S> q(6);
  q << 0.3, -0.8, 0.4, 1.1, 0.0, -0.6;  // θ5 = 0: axes 4 and 6 coincide
  auto sol = solvePieper(robot, robot.fk(q));
  CHECK(sol.continuum);
  CHECK(sol.count() >= 2);
  for (const auto& r : sol.residuals) CHECK(r <= 1e-7);
  q << 0, 0, 0, 0, 0.5, 0;  // angles 0
  roundTrip(robot, q, IkMethod::Pieper, 8, 1e-12);
  q << pi<S>(), -pi<S>() / 2, pi<S>(), pi<S>(), 0.5, pi<S>();  // angles π
  roundTrip(robot, q, IkMethod::Pieper, 8, 1e-12);
  for (double s : {1e-8, 1e8}) {
    const auto scaled = puma560Robot<S>(s);
    q << 0.3, -0.8, 0.4, 1.1, 0.7, -0.6;
    roundTrip(scaled, q, IkMethod::Pieper, 8, 1e-11);
  }
}

TEST_CASE("closed form: bad robots and methods", "[serial][ik][errors]") {
  const auto robot = puma560Robot<double>();
  std::vector<SerialJoint<double>> js(6);
  auto& g = rng(26);
  for (auto& j : js) {
    j.axis = unitVec3<double>(g);
    j.point = soma::test::uniformVec<double, 3>(g);
  }
  const auto general = SerialRobot<double>::fromPOE(js, SE3<double>());
  CHECK(classifyRobot(general) == IkMethod::General6R);
  CHECK_THROWS_WITH(solvePieper(general, SE3<double>()), Catch::Contains("no three consecutive axes"));
  CHECK_THROWS_WITH(solveArm3R(robot, SE3<double>()), Catch::Contains("needs a robot with 3 joints"));
  std::vector<DHRow<double>> rows(3);
  rows[1].type = JointType::Prismatic;
  CHECK_THROWS_WITH(classifyRobot(SerialRobot<double>::fromDH(rows)), Catch::Contains("prismatic"));
  CHECK(!parseIkMethod("newton"));
}

}  // namespace SOMA_UNITY_ID
