// The general 6R (GF §11.5): every real posture by the Raghavan–Roth / Manocha–Canny
// eigenproblem. Ground truth: random joint vectors through forward kinematics.
#include "soma/geometry/serial/general_6r.hpp"

#include "support/scalars.hpp"

#include <cmath>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {

template <class S> Robot6R<S> randomRobot(std::mt19937_64& g, double scale = 1) {
  Robot6R<S> rb;
  for (auto& r : rb) {
    r.a = test::uniform<S>(g, -scale, scale);
    r.alpha = test::uniform<S>(g, -3.1, 3.1);
    r.d = test::uniform<S>(g, -scale, scale);
    r.theta = test::uniform<S>(g, -0.5, 0.5);
  }
  return rb;
}

template <class S> std::array<S, 6> randomJoints(std::mt19937_64& g) {
  std::array<S, 6> q;
  for (auto& x : q) x = test::uniform<S>(g, -3.1, 3.1);
  return q;
}

template <class S> S angleDistance(const JointVector<S>& p, const std::array<S, 6>& q) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  S d = S(0);
  for (int i = 0; i < 6; ++i) {
    const S e = p(i) - q[i];
    d = std::max<S>(d, abs(atan2(sin(e), cos(e))));
  }
  return d;
}

/// The solver's answer contains q, every posture maps to the pose, the count is even and ≤ 16,
/// and the postures are distinct.
template <class S>
void requireComplete(const Robot6R<S>& rb, const std::array<S, 6>& q, const S& tol,
                     const S& match) {
  const SE3<S> T = general6rForward(rb, q);
  const General6RSolution<S> sol = solveGeneral6R(rb, T);
  INFO("count " << sol.count() << " complex " << sol.complex_count << " solved in "
                << sol.solved_in);
  for (const auto& n : sol.notes) INFO(n);
  REQUIRE(sol.count() <= 16);
  CHECK(sol.count() % 2 == 0);
  CHECK(sol.expected_count == 16);
  S best = S(10);
  for (std::size_t k = 0; k < sol.count(); ++k) {
    std::array<S, 6> p;
    for (int i = 0; i < 6; ++i) p[i] = sol.postures[k](i);
    const S r = general6rResidual(rb, T, p);
    CHECK(r <= tol);
    CHECK(sol.residuals[k] <= tol);
    best = std::min<S>(best, angleDistance(sol.postures[k], q));
    for (std::size_t j = 0; j < k; ++j) CHECK(angleDistance(sol.postures[j], p) > match);
  }
  CHECK(best <= match);
}

}  // namespace

TEST_CASE("general 6R: random robots and joints, the posture is found (double)", "[sixr]") {
  auto& g = test::rng(61);
  for (int n = 0; n < 40; ++n) {
    const Robot6R<double> rb = randomRobot<double>(g);
    const auto q = randomJoints<double>(g);
    INFO("robot " << n);
    requireComplete(rb, q, 64 * Tolerance<double>::identity(), 1e-9);
  }
}

TEMPLATE_TEST_CASE("general 6R: five scalars on random cases", "[sixr][scalars]", float, double,
                   long double, __float128, mpfr::mpreal) {
  using S = TestType;
  auto& g = test::rng(62);
  const int cases = std::is_same_v<S, mpfr::mpreal> ? 1 : 3;
  for (int n = 0; n < cases; ++n) {
    const Robot6R<S> rb = randomRobot<S>(g);
    const auto q = randomJoints<S>(g);
    INFO("robot " << n);
    // float: the solve escalates to double when needed; the polish is in float.
    requireComplete(rb, q, Tolerance<S>::identity(4096), Tolerance<S>::precision(2));
  }
}

TEST_CASE("general 6R: float near a double root, escalated, answers as double does", "[sixr][scalars]") {
  // Pose 103 of SOMA-6R-speed-accuracy's pool (seed 20261130, drawn as the study draws it): in
  // float two real roots lie 5.5e-4 apart, the answer is suspect and re-solved in double, and the
  // answer is the union of float's postures and double's (polished in float). Float's own
  // candidates there can stop short of converging between the two roots: with the 12×12 blocks
  // rounded differently (the substitution summed in another order) two of them polished to 1.4e-4
  // only, 0.01-0.02 rad from double's postures, and were listed beside them: 6 postures for 4.
  std::mt19937_64 g(20261130);
  std::uniform_real_distribution<double> u(-1, 1);
  Robot6R<double> rb;
  std::array<double, 6> q{};
  for (int k = 0; k <= 103; ++k) {
    for (auto& r : rb) {
      r.a = u(g);
      r.alpha = 3.1 * u(g);
      r.d = u(g);
      r.theta = 0.5 * u(g);
    }
    for (auto& x : q) x = 3.1 * u(g);
  }
  const SE3<double> T = general6rForward(rb, q);
  Robot6R<float> rf;
  for (int i = 0; i < 6; ++i) rf[i] = rb[i].cast<float>();
  const auto d = solveGeneral6R(rb, T);
  const auto f = solveGeneral6R(rf, T.cast<float>());
  for (const auto& n : f.notes) INFO(n);
  CHECK(f.solved_in == "double");  // (else this pose no longer tests the escalation)
  CHECK(d.count() == 4);
  CHECK(f.count() == d.count());
  for (std::size_t k = 0; k < f.count(); ++k) CHECK(f.residuals[k] <= 64 * Tolerance<float>::epsilon());
}

TEST_CASE("general 6R: counts agree with an independent real-root count", "[sixr]") {
  // Every posture found by one pose is found again from each of its postures' poses (the pose is
  // the same: the sets must coincide).
  auto& g = test::rng(63);
  for (int n = 0; n < 10; ++n) {
    const Robot6R<double> rb = randomRobot<double>(g);
    const auto q = randomJoints<double>(g);
    const SE3<double> T = general6rForward(rb, q);
    const auto sol = solveGeneral6R(rb, T);
    for (std::size_t k = 0; k < sol.count(); ++k) {
      std::array<double, 6> p;
      for (int i = 0; i < 6; ++i) p[i] = sol.postures[k](i);
      const auto again = solveGeneral6R(rb, general6rForward(rb, p));
      CHECK(again.count() == sol.count());
    }
  }
}

TEST_CASE("general 6R: near-degenerate robots and joints", "[sixr][degenerate]") {
  auto& g = test::rng(64);
  const double tol = 4096 * Tolerance<double>::identity();
  SECTION("θ3 at π (root at infinity of x3 = tan(θ3/2)) and near it") {
    for (double e : {0.0, 1e-12, 1e-8, -1e-8}) {
      Robot6R<double> rb = randomRobot<double>(g);
      auto q = randomJoints<double>(g);
      q[2] = pi<double>() - rb[2].theta + e;
      INFO("e = " << e);
      requireComplete(rb, q, tol, 1e-7);
    }
  }
  SECTION("joint angles 0 and π") {
    Robot6R<double> rb = randomRobot<double>(g);
    requireComplete(rb, std::array<double, 6>{0, 0, 0, 0, 0, 0}, tol, 1e-7);
    requireComplete(rb, std::array<double, 6>{pi<double>(), 0, pi<double>(), 0, pi<double>(), 0},
                    tol, 1e-7);
    requireComplete(rb,
                    std::array<double, 6>{pi<double>(), pi<double>(), pi<double>(), pi<double>(),
                                          pi<double>(), pi<double>()},
                    tol, 1e-7);
  }
  SECTION("lengths scaled by 1e-8 and 1e8 (angles are scale-free)") {
    for (double s : {1e-8, 1e8}) {
      const Robot6R<double> rb = randomRobot<double>(g, s);
      INFO("scale " << s);
      requireComplete(rb, randomJoints<double>(g), tol, 1e-8);
    }
  }
  SECTION("nearly parallel consecutive axes (α2 = 1e-5) and nearly intersecting (a3 = 1e-6)") {
    Robot6R<double> rb = randomRobot<double>(g);
    rb[1].alpha = 1e-5;
    requireComplete(rb, randomJoints<double>(g), tol, 1e-6);
    rb = randomRobot<double>(g);
    rb[2].a = 1e-6;
    requireComplete(rb, randomJoints<double>(g), tol, 1e-6);
  }
}

TEST_CASE("general 6R: bad input is rejected", "[sixr][input]") {
  auto& g = test::rng(65);
  Robot6R<double> rb = randomRobot<double>(g);
  const SE3<double> T = general6rForward(rb, randomJoints<double>(g));
  Robot6R<double> bad = rb;
  bad[3].a = std::nan("");
  CHECK_THROWS_AS(solveGeneral6R(bad, T), InvalidInput);
  bad = rb;
  bad[2].type = JointType::Prismatic;
  CHECK_THROWS_AS(solveGeneral6R(bad, T), InvalidInput);
  Mat4<double> m = T.matrix();
  m(0, 0) *= 1.1;  // not a rotation
  CHECK_THROWS_AS(solveGeneral6R(rb, m), InvalidInput);
  m = T.matrix();
  m(1, 3) = std::nan("");
  CHECK_THROWS_AS(solveGeneral6R(rb, m), InvalidInput);
  m = T.matrix();
  CHECK_NOTHROW(solveGeneral6R(rb, m));
}

}  // namespace SOMA_UNITY_ID
