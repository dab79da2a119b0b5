// Inverse kinematics at the extremes (issue 7 item 6): lengths 1e-8 and 1e8 (postures are
// scale-free, residuals are relative), joint angles at 0 and π, poses on both sides of the wrist
// and elbow singularity thresholds, nearly parallel and nearly intersecting axes on both sides
// of the classification threshold, and random joints → pose → IK on a robot with 16 real
// postures. Closed forms (GF §5.1, §10.3) and the general 6R (GF §11.5).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/geometry/serial/ik.hpp"

#include "support/scalars.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::uniform;

namespace {

template <class S> S angleGap(const JointVector<S>& p, const JointVector<S>& q) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  S d = S(0);
  for (int i = 0; i < q.size(); ++i) {
    const S e = p(i) - q(i);
    d = std::max<S>(d, abs(atan2(sin(e), cos(e))));
  }
  return d;
}

template <class S> S nearest(const Solution<S>& sol, const JointVector<S>& q) {
  S best = S(10);
  for (const auto& p : sol.postures) best = std::min<S>(best, angleGap(p, q));
  return best;
}

/// UR-type arm: joints 2, 3, 4 parallel (α2 = α3 = 0), α3 replaced by `tilt`.
template <class S> SerialRobot<S> urArm(const S& tilt = S(0)) {
  std::vector<DHRow<S>> rows(6);
  const S h = pi<S>() / S(2);
  rows[0] = {JointType::Revolute, S(0), h, S(89159) / S(1000000), S(0)};
  rows[1] = {JointType::Revolute, -S(425) / S(1000), S(0), S(0), S(0)};
  rows[2] = {JointType::Revolute, -S(39225) / S(100000), tilt, S(0), S(0)};
  rows[3] = {JointType::Revolute, S(0), h, S(10915) / S(100000), S(0)};
  rows[4] = {JointType::Revolute, S(0), -h, S(9465) / S(100000), S(0)};
  rows[5] = {JointType::Revolute, S(0), S(0), S(823) / S(10000), S(0)};
  return SerialRobot<S>::fromDH(rows, DHConvention::Standard);
}

/// The Manseur–Doty arm in Manocha & Canny's variant (16 real postures for their pose;
/// studies/robots/manseur_doty.json).
template <class S> SerialRobot<S> manseurDoty(const S& scale = S(1)) {
  const S deg = pi<S>() / S(180);
  std::vector<DHRow<S>> rows(6);
  rows[0] = {JointType::Revolute, S(3) / S(10) * scale, S(90) * deg, S(0), S(0)};
  rows[1] = {JointType::Revolute, scale, deg, S(0), S(0)};
  rows[2] = {JointType::Revolute, S(0), S(90) * deg, S(2) / S(10) * scale, S(0)};
  rows[3] = {JointType::Revolute, S(3) / S(2) * scale, deg, S(0), S(0)};
  rows[4] = {JointType::Revolute, S(0), S(90) * deg, S(0), S(0)};
  rows[5] = {JointType::Revolute, S(0), deg, S(0), S(0)};
  return SerialRobot<S>::fromDH(rows, DHConvention::Standard);
}

/// The class `auto` picks, solved: the closed forms directly, the general 6R on the DH rows
/// (geometry/serial/general_6r.hpp; closed_form_ik's dispatcher does not carry it).
template <class S> Solution<S> solveAuto(const SerialRobot<S>& robot, const SE3<S>& T) {
  const IkMethod m = classifyRobot(robot);
  if (m != IkMethod::General6R) return solveClosedForm(robot, T, m);
  Robot6R<S> rows;
  for (int i = 0; i < 6; ++i) rows[i] = robot.dhRows()[i];
  General6RSolution<S> g = solveGeneral6R(rows, T);
  return static_cast<Solution<S>&>(g);
}

/// q → T → IK: every posture on the pose, the count even and ≤ the class bound, q among them.
template <class S>
Solution<S> roundTrip(const SerialRobot<S>& robot, const JointVector<S>& q, const S& residualTol, const S& matchTol) {
  const SE3<S> T = robot.fk(q);
  const Solution<S> sol = solveAuto(robot, T);
  INFO("method " << sol.method << ", count " << sol.count());
  std::string notes;
  for (const auto& n : sol.notes) notes += n + "; ";
  INFO("notes: " << notes);
  CHECK(sol.count() % 2 == 0);
  CHECK(int(sol.count()) <= sol.expected_count);
  CHECK(sol.expected_count <= 16);
  for (std::size_t k = 0; k < sol.count(); ++k) {
    CHECK(sol.residuals[k] <= residualTol);
    CHECK(poseResidual(robot.fk(sol.postures[k]), T, robot.lengthScale()) <= residualTol);
  }
  // q itself is known to the accuracy of the pose over the smallest singular value of the
  // Jacobian (first-order perturbation): near a singular configuration the match is looser.
  const S sigma = singularityMeasures(robot, q).smallestSingularValue;
  INFO("smallest singular value of J(q) " << toDouble(sigma));
  CHECK(nearest(sol, q) <= std::max<S>(matchTol, S(64) * residualTol / sigma));
  return sol;
}

/// Two posture sets are the same (same count, each posture of `a` within tol of one of `b`).
template <class S> void samePostures(const Solution<S>& a, const Solution<S>& b, const S& tol) {
  REQUIRE(a.count() == b.count());
  for (const auto& p : a.postures) CHECK(nearest(b, p) <= tol);
}

template <class S> S tol4096() { return Tolerance<S>::identity(4096); }

}  // namespace

TEMPLATE_TEST_CASE("IK extremes: lengths 1e-8 and 1e8 — the same postures, relative residuals",
                   "[serial][ik][extreme][scale]", double, long double) {
  using S = TestType;
  auto& g = test::rng(811);
  for (int trial = 0; trial < 4; ++trial) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = uniform<S>(g, -3, 3);
    // Pieper (PUMA 560) and the general 6R (Manseur–Doty arm) at scale 1 and 1e∓8.
    for (int kind = 0; kind < 2; ++kind) {
      const auto base = kind == 0 ? puma560Robot<S>() : manseurDoty<S>();
      const Solution<S> ref = roundTrip(base, q, tol4096<S>(), S(1e-7));
      for (const S s : {S(1e-8), S(1e8)}) {
        INFO("kind " << kind << " scale " << toDouble(s) << " trial " << trial);
        const auto scaled = kind == 0 ? puma560Robot<S>(s) : manseurDoty<S>(s);
        CHECK(scaled.lengthScale() == Approx(toDouble(s * base.lengthScale())).epsilon(1e-12));
        // The scaled pose is the pose of the scaled robot: T(s) = (R, s t).
        const SE3<S> T = base.fk(q);
        CHECK(poseResidual(scaled.fk(q), SE3<S>(SO3<S>::fromMatrix(T.rotation()), s * T.translation()),
                           scaled.lengthScale()) <= tol4096<S>());
        const Solution<S> sol = roundTrip(scaled, q, tol4096<S>(), S(1e-7));
        samePostures(sol, ref, S(1e-7));
      }
    }
  }
}

TEMPLATE_TEST_CASE("IK extremes: joint angles at 0 and π", "[serial][ik][extreme][angles]", double, long double) {
  using S = TestType;
  const S p = pi<S>();
  // Every joint at 0 or π in a fixed pattern set (θ5 = 0 or π is the PUMA's wrist singularity:
  // kept for the general 6R, where it is not singular, and moved off for the PUMA).
  const int patterns[6][6] = {{0, 0, 0, 0, 0, 0}, {1, 1, 1, 1, 1, 1}, {1, 0, 1, 0, 1, 0},
                              {0, 1, 0, 1, 0, 1}, {1, 1, 0, 0, 1, 1}, {0, 0, 1, 1, 0, 0}};
  for (const auto& pat : patterns) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = pat[i] ? p : S(0);
    INFO("pattern " << q.transpose().template cast<double>() / 3.141592653589793);
    roundTrip(manseurDoty<S>(), q, tol4096<S>(), S(1e-7));
    JointVector<S> qp = q;
    qp(4) = S(1) / S(2);  // off the wrist singularity
    roundTrip(puma560Robot<S>(), qp, tol4096<S>(), S(1e-9));
  }
}

TEST_CASE("IK extremes: PUMA wrist singularity (θ5 → 0) on both sides of the gimbal threshold",
          "[serial][ik][extreme][wrist]") {
  using S = double;
  const auto robot = puma560Robot<S>();
  JointVector<S> q(6);
  // The threshold is |θ5| ≈ √(64 eps) ≈ 1.2e-7 (closed_form_ik.hpp, wrist3R): inside, θ4 and θ6
  // are determined only in combination (a continuum, one representative); outside, every
  // posture individually.
  for (const double e : {0.0, 1e-12, 1e-9, -1e-9, 1e-8}) {
    q << 0.3, -0.8, 0.4, 1.1, e, -0.6;
    INFO("θ5 = " << e);
    const SE3<S> T = robot.fk(q);
    const Solution<S> sol = solveClosedForm(robot, T, IkMethod::Pieper);
    CHECK(sol.continuum);
    CHECK(sol.count() >= 2);
    // Inside the threshold the representative takes θ5 as exactly singular: its residual is of
    // the order of |θ5|, bounded by the threshold itself.
    for (const auto& r : sol.residuals) CHECK(r <= 8 * Tolerance<S>::sqrtEpsilon());
    // The representative of the true posture has θ1, θ2, θ3 and θ4 + θ6 right.
    bool found = false;
    for (const auto& p : sol.postures) {
      JointVector<S> a = p, b = q;
      a(3) += a(5), a(5) = 0, b(3) += b(5), b(5) = 0;
      a(4) = b(4) = 0;
      found = found || angleGap(a, b) <= 1e-6;
    }
    CHECK(found);
  }
  for (const double e : {1e-6, -1e-6, 1e-4, 1e-2, 0.3}) {
    q << 0.3, -0.8, 0.4, 1.1, e, -0.6;
    INFO("θ5 = " << e);
    const Solution<S> sol = roundTrip(robot, q, tol4096<S>(), 1e-9 / std::abs(e) + 1e-10);
    CHECK_FALSE(sol.continuum);
    CHECK(sol.count() == 8);
  }
}

TEST_CASE("IK extremes: PUMA elbow singularity (arm stretched) on both sides", "[serial][ik][extreme][elbow]") {
  using S = double;
  const auto robot = puma560Robot<S>();
  // The wrist centre's distance from axis 2 is extremal at tan θ3 = −d4/a3 (a3 = 0.0203,
  // d4 = 0.4318): the elbow-up and elbow-down postures merge there (a double root of the
  // positioning equations).
  const double stretched = std::atan2(-0.4318, 0.0203);
  JointVector<S> q(6);
  for (const double e : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3, 0.1}) {
    q << 0.3, -0.8, stretched + e, 1.1, 0.7, -0.6;
    INFO("θ3 − θ3* = " << e);
    // A double root is accurate to √eps: the posture matches to √eps·scale (64·√eps), the
    // residual is still at rounding level after the Newton polish.
    const double match = std::abs(e) < 1e-5 ? 64 * Tolerance<S>::sqrtEpsilon() : 1e-9;
    const Solution<S> sol = roundTrip(robot, q, tol4096<S>(), match);
    CHECK(sol.count() >= 4);
  }
}

// A PUMA 560 whose wrist axes 5 and 6 miss by a5 = ε (classified general6r above
// Tolerance::input()·L): the θ3-last elimination's leading matrix is singular at every θ3 offset
// (structural for a1 = d2 = α2 = a4 = d5 = 0), so the solver eliminates on the reversed chain
// (general_6r_impl.hpp). Below the threshold the Pieper closed form is used.
TEST_CASE("IK extremes: nearly intersecting wrist axes across the Pieper threshold",
          "[serial][ik][extreme][axes]") {
  using S = double;
  auto& g = test::rng(812);
  // Wrist offset a5 = ε: axes 4-6 meet for ε = 0, miss by ε otherwise. Below the classification
  // threshold (Tolerance::input()·L) the Pieper closed form is used, above it the general 6R;
  // both must return the true posture with a residual at rounding level.
  for (const double e : {0.0, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1}) {
    const auto robot = puma560Robot<S>(1.0, e);
    for (int t = 0; t < 3; ++t) {
      JointVector<S> q(6);
      for (int i = 0; i < 6; ++i) q(i) = uniform<S>(g, -3, 3);
      q(4) = uniform<S>(g, 0.3, 2.8);  // off the wrist singularity
      INFO("a5 = " << e << ", class " << ikMethodName(classifyRobot(robot)));
      roundTrip(robot, q, tol4096<S>(), 1e-7);
    }
  }
}

// A UR-type arm with axis 4 tilted by α3 = ε off the parallel axes 2-3 (classified general6r
// above the threshold): the same structural degeneracy, the same remedy.
TEST_CASE("IK extremes: nearly parallel axes 2-4 across the Pieper threshold",
          "[serial][ik][extreme][axes]") {
  using S = double;
  auto& g = test::rng(813);
  for (const double e : {0.0, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1}) {
    const auto robot = urArm<S>(e);
    for (int t = 0; t < 3; ++t) {
      JointVector<S> q(6);
      for (int i = 0; i < 6; ++i) q(i) = uniform<S>(g, -3, 3);
      q(4) = uniform<S>(g, 0.3, 2.8);
      INFO("α3 = " << e << ", class " << ikMethodName(classifyRobot(robot)));
      roundTrip(robot, q, tol4096<S>(), 1e-7);
    }
  }
}

// solveIk's auto mode on a PUMA whose wrist axes miss a common point by a5 = e: classified Pieper
// on both sides (e < Tolerance::input()·L), solved by the closed form while the triple's defect is
// rounding (16 ulps of L) and as the general 6R above 256 ulps (2¹⁶ ulps of L) — in float too,
// where input() = 2.2e-2 and the idealised closed form lost postures (SOMA-6R-calibration-sweep).
// The count is the exact PUMA's at the same pose (the real postures move continuously with e).
TEMPLATE_TEST_CASE("IK auto: near, not exactly, Pieper is solved as the general 6R, on both sides of 256 ulps",
                   "[serial][ik][extreme][axes]", float, double, long double) {
  using S = TestType;
  auto& g = test::rng(814);
  const S eps = Tolerance<S>::epsilon();
  const S L = puma560Robot<S>().lengthScale();
  for (int t = 0; t < 4; ++t) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = uniform<S>(g, -3, 3);
    q(4) = uniform<S>(g, 0.3, 2.8);  // off the wrist singularity
    q(2) = uniform<S>(g, 0.3, 1.2);  // off the elbow singularity
    const auto exact = puma560Robot<S>();
    const SE3<S> T0 = exact.fk(q);
    const Solution<S> ref = solveClosedForm(exact, T0, IkMethod::Pieper);
    for (const bool above : {false, true}) {
      const S e = (above ? S(65536) : S(16)) * eps * L;
      const auto robot = puma560Robot<S>(S(1), e);
      REQUIRE(classifyRobot(robot) == IkMethod::Pieper);
      const PieperTriple<S> tri = findPieperTriple(robot);
      INFO("a5 = " << toDouble(e) << ", defect " << toDouble(tri.defect) << (above ? " (above" : " (below") << " 256 ulps)");
      CHECK((tri.defect > Tolerance<S>::identity(256)) == above);
      const SE3<S> T = robot.fk(q);
      const IkSolution<S> sol = solveIk(robot, T, IkOptions{});
      bool general = false;
      for (const auto& n : sol.notes) general = general || n.find("near, not exactly, a Pieper robot") != std::string::npos;
      CHECK(general == above);
      CHECK(sol.count() == ref.count());
      // q is known to the pose's accuracy over the smallest singular value of J(q) (as in roundTrip)
      CHECK(nearest(sol, q) <= S(64) * tol4096<S>() / singularityMeasures(robot, q).smallestSingularValue);
      for (std::size_t k = 0; k < sol.count(); ++k) CHECK(poseResidual(robot.fk(sol.postures[k]), T, robot.lengthScale()) <= tol4096<S>());
    }
  }
}

// SOMA-6R-calibration-sweep --scalar long-double, PUMA 560 with every DH parameter perturbed by 1e-9
// of its length scale (the sweep's robot, printed to 21 digits), pose 42 (0.16° from the wrist
// singularity): the general 6R's two 4-fold clusters of roots (the shoulder and wrist postures
// share θ1 to 2e-7) came out of the long-double eigensolver as complex pairs with |Im| up to
// 9.2e-5 relative, above realTol = eps^(1/3); the answer was 0 postures, certified, no warning.
// Complex eigenvalues within 16 eps^(1/4) of the real axis now make the answer suspect, and the
// re-solve in float128 separates the clusters. Checked against the 8 postures double finds.
TEMPLATE_TEST_CASE("IK extremes: nearly Pieper PUMA at a near-wrist-singular pose, clustered roots", "[serial][ik][extreme][cluster]",
                   double, long double) {
  using S = TestType;
  const long double rows[6][4] = {
      {-8.62840033570531695051e-11L, 1.57079632710297178695L, -3.51882391863937123081e-10L, -8.76646504892350408859e-10L},
      {0.43180000034773734647L, -4.74651395852815571866e-10L, -3.52241740213851301992e-10L, -1.89462202056430273347e-10L},
      {0.0202999999918335894222L, -1.57079632588505913873L, 0.150049999844935488518L, 3.22466472498905032383e-10L},
      {2.31800376419869373159e-10L, 1.57079632602315113826L, 0.431799999731638078622L, -6.83199613779477910033e-10L},
      {1.38716281001976912718e-10L, -1.57079632681103037992L, -8.1771521604496003871e-11L, -1.30710352490373993277e-10L},
      {3.5826691729581751407e-10L, 8.5277580389364060485e-10L, 0.0562500004003721579755L, 5.18078555286603847911e-10L}};
  std::vector<DHRow<S>> dh(6);
  for (int i = 0; i < 6; ++i) dh[i] = {JointType::Revolute, S(rows[i][0]), S(rows[i][1]), S(rows[i][2]), S(rows[i][3])};
  const auto robot = SerialRobot<S>::fromDH(dh, DHConvention::Standard);
  JointVector<S> q(6);
  q << S(2.58295939323219547745L), S(0.00213788071343001817581L), S(1.61468334971845939307L),
      S(-0.337346486158248914933L), S(-0.00282155966906394439775L), S(2.38701953951597056758L);
  const SE3<S> T = robot.fk(q);
  const IkSolution<S> sol = solveIk(robot, T, IkOptions{});
  CHECK(sol.method == "general6r");
  CHECK(sol.count() == 8);
  // q is known to the pose's accuracy over the smallest singular value of J(q) (as in roundTrip)
  CHECK(nearest(sol, q) <= S(64) * tol4096<S>() / singularityMeasures(robot, q).smallestSingularValue);
  for (std::size_t k = 0; k < sol.count(); ++k) CHECK(poseResidual(robot.fk(sol.postures[k]), T, robot.lengthScale()) <= tol4096<S>());
}

TEST_CASE("IK extremes: random joints on a robot with 16 real postures", "[serial][ik][extreme][sixteen]") {
  using S = double;
  auto& g = test::rng(814);
  const auto robot = manseurDoty<S>();
  int sixteen = 0;
  for (int t = 0; t < 40; ++t) {
    JointVector<S> q(6);
    for (int i = 0; i < 6; ++i) q(i) = uniform<S>(g, -3.1, 3.1);
    const Solution<S> sol = roundTrip(robot, q, tol4096<S>(), 1e-7);
    sixteen += sol.count() == 16;
  }
  // Manocha & Canny's pose has 16 (GF-11.5.1-6R-sixteen); random poses of this arm reach 16 too.
  CHECK(sixteen >= 1);
}

}  // namespace SOMA_UNITY_ID
