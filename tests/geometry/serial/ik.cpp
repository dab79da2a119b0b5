// The IK entry point (ik.hpp) and the standard-DH rewrite (standard_dh.hpp): every method through
// solveIk, certification, joint limits, the numerical completion; toStandardDH on POE robots.
#include "soma/geometry/serial/ik.hpp"
#include "soma/geometry/serial/standard_dh.hpp"

#include "soma/algebra/errors.hpp"
#include "robots.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {

/// Every posture reaches the pose: FK(q) recomputed here, not the solver's residual.
template <class S> void checkReaches(const SerialRobot<S>& robot, const SE3<S>& pose, const Solution<S>& sol) {
  for (std::size_t k = 0; k < sol.count(); ++k) {
    INFO("posture " << k + 1 << " of " << sol.count() << ", method " << sol.method);
    CHECK(poseResidual(robot.fk(sol.postures[k]), pose, robot.lengthScale()) <= Tolerance<S>::identity(4096));
    CHECK(sol.residuals[k] <= Tolerance<S>::identity(4096));
  }
}

/// Largest wrapped joint difference between two postures.
template <class S> S jointGap(const JointVector<S>& p, const JointVector<S>& q) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  S gap(0);
  for (int i = 0; i < p.size(); ++i) gap = std::max<S>(gap, abs(atan2(sin(p(i) - q(i)), cos(p(i) - q(i)))));
  return gap;
}

/// True when every posture of `a` is one of `b`'s (within tol).
template <class S> bool subset(const Solution<S>& a, const Solution<S>& b, const S& tol) {
  for (const auto& p : a.postures) {
    bool found = false;
    for (const auto& q : b.postures) found = found || jointGap(p, q) <= tol;
    if (!found) return false;
  }
  return true;
}

/// studies/robots/puma560_pose.json
template <class S> SE3<S> pumaPose() {
  Mat3<S> R;
  R << S(0), S(0), S(1), S(0), S(-1), S(0), S(1), S(0), S(0);
  return SE3<S>(SO3<S>::fromMatrix(R), Vec3<S>(S(45) / S(100), -S(15005) / S(100000), S(3) / S(10)));
}

/// The pose of the general-6R example at q = (−1.1, −0.1, 1.2, −2.7, 2.9, −2.9) (studies/robots/
/// general6r_pose.json): 10 real postures of 16 complex.
template <class S> SE3<S> general6rPose(const SerialRobot<S>& robot) {
  JointVector<S> q(6);
  q << S(-11) / S(10), S(-1) / S(10), S(12) / S(10), S(-27) / S(10), S(29) / S(10), S(-29) / S(10);
  return robot.fk(q);
}

/// A URDF-like chain: random joint axes and points, joint offsets and a tool home pose (fixed
/// seed); `parallel` makes axes 2 and 3 parallel (the common normal is not unique there).
template <class S> SerialRobot<S> randomPoe(std::mt19937_64& g, bool parallel) {
  std::vector<SerialJoint<S>> js(6);
  for (auto& j : js) {
    j.axis = test::unitVec3<S>(g);
    j.point = test::uniformVec<S, 3>(g);
    j.offset = test::uniform<S>(g, -3, 3);
    j.lower = test::uniform<S>(g, -3, -1);
    j.upper = test::uniform<S>(g, 1, 3);
  }
  if (parallel) js[2].axis = -js[1].axis;
  const SE3<S> home(SO3Tangent<S>(test::uniformVec<S, 3>(g)).exp(), test::uniformVec<S, 3>(g));
  return SerialRobot<S>::fromPOE(js, home, "random POE");
}

}  // namespace

TEMPLATE_TEST_CASE("solveIk: PUMA 560, 8 postures, each reaching the pose, certified", "[serial][ik][entry]", double,
                   long double, __float128) {
  using S = TestType;
  const auto robot = test::puma560<S>();
  const SE3<S> pose = pumaPose<S>();
  const IkSolution<S> sol = solveIk(robot, pose);
  CHECK(sol.method == "pieper");
  CHECK(sol.count() == 8);
  CHECK(sol.expected_count == 8);
  CHECK(sol.certified);
  checkReaches(robot, pose, sol);
  // The named method gives the same postures as auto.
  IkOptions named;
  named.method = IkMethod::Pieper;
  const IkSolution<S> again = solveIk(robot, pose, named);
  CHECK(again.count() == sol.count());
  CHECK(subset<S>(again, sol, Tolerance<S>::sqrtEpsilon()));
}

TEMPLATE_TEST_CASE("solveIk: general 6R, 10 real of 16 certified — ceres finds the same 10, not certified",
                   "[serial][ik][entry][sixr]", double, long double) {
  using S = TestType;
  const auto robot = test::general6rExample<S>();
  const SE3<S> pose = general6rPose(robot);
  CHECK(classifyRobot(robot) == IkMethod::General6R);
  const IkSolution<S> eig = solveIk(robot, pose);
  CHECK(eig.method == "general6r");
  CHECK(eig.complex_count == 16);
  CHECK(eig.expected_count == 16);
  CHECK(eig.count() == 10);
  CHECK(eig.certified);
  checkReaches(robot, pose, eig);
  IkOptions o;
  o.method = IkMethod::Ceres;
  const IkSolution<S> cer = solveIk(robot, pose, o);
  CHECK(cer.method == "ceres");
  CHECK_FALSE(cer.certified);
  CHECK(cer.count() == eig.count());
  CHECK(subset<S>(cer, eig, Tolerance<S>::sqrtEpsilon()));
  checkReaches(robot, pose, cer);
  if constexpr (!std::is_same_v<S, double>) {
    bool said = false;  // in a scalar other than double the note says each posture was polished there
    for (const auto& n : cer.notes) said = said || n.find("Newton-polished in " + std::string(scalarName<S>())) != std::string::npos;
    CHECK(said);
  }
}

TEST_CASE("solveIk: joint limits drop postures for the closed form and the numerical methods alike",
          "[serial][ik][entry][limits]") {
  const auto free = test::puma560<double>();
  const auto limited = test::puma560Limited<double>();
  const SE3<double> pose = pumaPose<double>();
  const auto all = solveIk(free, pose);
  std::size_t inside = 0;
  for (const auto& q : all.postures) inside += limited.withinLimits(q) ? 1 : 0;
  REQUIRE(all.count() == 8);
  CHECK(inside == 2);  // as the CLI test on studies/robots/puma560.json
  const auto closed = solveIk(limited, pose);
  CHECK(closed.count() == inside);
  CHECK(subset<double>(closed, all, Tolerance<double>::sqrtEpsilon()));
  IkOptions o;
  o.method = IkMethod::Nlopt;
  const auto nl = solveIk(limited, pose, o);
  CHECK(nl.count() == inside);
  CHECK(subset<double>(nl, all, Tolerance<double>::sqrtEpsilon()));
  for (const auto& q : nl.postures) CHECK(limited.withinLimits(q));
  bool said = false;
  for (const auto& n : nl.notes) said = said || n == "6 posture(s) outside the joint limits dropped";
  CHECK(said);
}

TEST_CASE("solveIk: just outside the Pieper class another elimination finds every posture, certified",
          "[serial][ik][entry][completion]") {
  // studies/robots/puma560_wrist_offset.json: a5 = 1 mm; the pose of its _pose.json.
  std::vector<DHRow<double>> rows = test::puma560<double>().dhRows();
  rows[4].a = 0.001;
  const auto robot = SerialRobot<double>::fromDH(rows);
  Mat3<double> R;
  R << 0.8019808734566147, -0.5639019546997732, 0.19708187155479306, 0.5688654247556513, 0.6203087120099046,
      -0.5400085465269837, 0.18226027303649442, 0.5451895883914034, 0.8182600476512795;
  const SE3<double> pose(SO3<double>::fromMatrix(R), Vec3<double>(0.5216767142024682, -0.028782796746962602, 0.12653997558372942));
  IkOptions plain;
  plain.complete = false;
  // θ3 last is singular for every offset here; the solver eliminates another joint last and
  // its eigenproblem is complete (16 complex), so no numerical completion is needed: the
  // 8 real postures the Ceres completion found before (issue 20) now come certified.
  const auto eig = solveIk(robot, pose, plain);
  CHECK(eig.certified);
  CHECK(eig.count() == 8);
  const auto full = solveIk(robot, pose);
  CHECK(full.certified);
  CHECK(full.count() == 8);
  CHECK(subset<double>(eig, full, Tolerance<double>::sqrtEpsilon()));
  checkReaches(robot, pose, full);
  bool relabelled = false, completed = false;
  for (const auto& n : full.notes) {
    relabelled = relabelled || n.find("ill-conditioned for every θ3 offset") != std::string::npos;
    completed = completed || n.find("numerical completion by Ceres") != std::string::npos;
  }
  CHECK(relabelled);
  CHECK_FALSE(completed);
}

TEST_CASE("solveIk: methods that do not apply are rejected", "[serial][ik][entry][errors]") {
  std::vector<DHRow<double>> rows(3);
  rows[0].alpha = 1.2, rows[1].a = 1, rows[2].a = 0.5;
  const auto arm = SerialRobot<double>::fromDH(rows);
  IkOptions o;
  o.method = IkMethod::General6R;
  CHECK_THROWS_WITH(solveIk(arm, SE3<double>(), o), Catch::Contains("needs a robot with 6 revolute joints"));
  o.method = IkMethod::Ceres;
  CHECK_THROWS_WITH(solveIk(arm, SE3<double>(), o), Catch::Contains("ik method ceres"));
  CHECK_THROWS_AS(toStandardDH(arm), InvalidInput);
  CHECK(parseIkMethod("ceres") == IkMethod::Ceres);
  CHECK(parseIkMethod("nlopt") == IkMethod::Nlopt);
  CHECK(ikMethodName(IkMethod::Nlopt) == "nlopt");
}

TEMPLATE_TEST_CASE("toStandardDH: a URDF-like POE chain has the same FK as its DH rows at random joints",
                   "[serial][ik][dh]", double, long double) {
  using S = TestType;
  auto& g = test::rng(1834);
  for (int trial = 0; trial < 6; ++trial) {
    const SerialRobot<S> poe = randomPoe<S>(g, trial % 2 == 1);
    const SerialRobot<S> dh = toStandardDH(poe);
    CHECK(dh.convention() == DHConvention::Standard);
    REQUIRE(dh.dhRows().size() == 6);
    for (int i = 0; i < 6; ++i) {
      CHECK(dh.joints()[i].lower == poe.joints()[i].lower);
      CHECK(dh.joints()[i].upper == poe.joints()[i].upper);
    }
    for (int k = 0; k < 20; ++k) {
      JointVector<S> q(6);
      for (int i = 0; i < 6; ++i) q(i) = test::uniform<S>(g, -3.2, 3.2);
      INFO("trial " << trial << ", sample " << k);
      CHECK(poseResidual(dh.fk(q), poe.fk(q), poe.lengthScale()) <= Tolerance<S>::identity(4096));
    }
  }
}

TEST_CASE("toStandardDH: the POE robot's IK through its DH rows reaches the pose", "[serial][ik][dh][entry]") {
  auto& g = test::rng(1835);
  const SerialRobot<double> poe = randomPoe<double>(g, false);
  JointVector<double> q(6);
  q << 0.3, -0.7, 0.9, 0.4, -0.8, 0.6;  // inside the random limits (|q| < 1)
  const SE3<double> pose = poe.fk(q);
  const auto sol = solveIk(poe, pose);
  CHECK(sol.method == "general6r");
  bool found = false;
  for (const auto& p : sol.postures) found = found || jointGap<double>(p, q) <= Tolerance<double>::sqrtEpsilon();
  CHECK(found);
  checkReaches(poe, pose, sol);
}

}  // namespace SOMA_UNITY_ID
