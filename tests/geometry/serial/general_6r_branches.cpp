// The general 6R solver's strategy changes (GF §11.5; general_6r_impl.hpp), each reached on a
// robot or pose that needs it, and each checked for its answer: the generating posture is among
// the postures, every residual is at round-off, and when the answer may be short the notes say so.
#include "soma/geometry/serial/general_6r.hpp"

#include "support/scalars.hpp"

#include <cmath>
#include <string>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {

template <class S> Robot6R<S> randomRobot6(std::mt19937_64& g) {
  Robot6R<S> rb;
  for (auto& r : rb) {
    r.a = test::uniform<S>(g, -1, 1);
    r.alpha = test::uniform<S>(g, -3.1, 3.1);
    r.d = test::uniform<S>(g, -1, 1);
    r.theta = S(0);
  }
  return rb;
}

bool hasNote(const General6RSolution<double>& s, const std::string& what) {
  for (const auto& n : s.notes)
    if (n.find(what) != std::string::npos) return true;
  return false;
}
template <class S> bool hasNoteS(const General6RSolution<S>& s, const std::string& what) {
  for (const auto& n : s.notes)
    if (n.find(what) != std::string::npos) return true;
  return false;
}

/// Smallest joint-space distance (wrapped) from q to a returned posture.
template <class S> double nearest(const General6RSolution<S>& s, const std::array<S, 6>& q) {
  double best = 10;
  for (const auto& p : s.postures) {
    double d = 0;
    for (int i = 0; i < 6; ++i) {
      const double e = toDouble(S(p(i) - q[i]));
      d = std::max(d, std::abs(std::atan2(std::sin(e), std::cos(e))));
    }
    best = std::min(best, d);
  }
  return best;
}

const std::array<double, 6> kQ{0.3, -0.7, 1.1, 0.4, -1.3, 0.9};

}  // namespace

TEST_CASE("general 6R branches: generic robots deflate x3 = ±i and need no re-solve", "[sixr][branches]") {
  auto& g = test::rng(71);
  for (int n = 0; n < 20; ++n) {
    const Robot6R<double> rb = randomRobot6<double>(g);
    const SE3<double> T = general6rForward(rb, kQ);
    const auto s = solveGeneral6R(rb, T);
    INFO("robot " << n);
    CHECK_FALSE(hasNote(s, "deflation of x3 = ±i not clean"));
    CHECK_FALSE(hasNote(s, "Francis QR did not converge"));
    CHECK(s.complex_count == 16);
    CHECK(nearest(s, kQ) <= 1e-9);
    CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
  }
}

TEST_CASE("general 6R branches: θ3 = π rotates the half-angle variable", "[sixr][branches]") {
  auto& g = test::rng(72);
  const Robot6R<double> rb = randomRobot6<double>(g);
  std::array<double, 6> q = kQ;
  q[2] = pi<double>();
  const auto s = solveGeneral6R(rb, general6rForward(rb, q));
  CHECK(hasNote(s, "half-angle variable rotated"));
  CHECK(s.theta3_offset != 0.0);
  CHECK(nearest(s, q) <= 1e-9);
  CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
}

TEST_CASE("general 6R branches: three parallel axes 3-5, deflation not clean, full 24×24 problem",
          "[sixr][branches]") {
  auto& g = test::rng(73);
  Robot6R<double> rb = randomRobot6<double>(g);
  rb[2].alpha = 0;
  rb[3].alpha = 0;  // axes 3, 4, 5 parallel: the kernel of M(i) is larger than 4
  const auto s = solveGeneral6R(rb, general6rForward(rb, kQ));
  CHECK(hasNote(s, "full 24×24 eigenproblem"));
  CHECK(s.complex_count < 16);  // fewer than 16 finite solutions: said, and re-solved
  CHECK(hasNote(s, "re-solved in long-double"));
  CHECK(nearest(s, kQ) <= 1e-9);
  CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
}

/// A random robot whose wrist axes 4-6 meet (a Pieper robot, a degenerate case of the
/// eigenproblem; its closed form is solvePieper).
Robot6R<double> wristRobot() {
  auto& g = test::rng(74);
  Robot6R<double> rb = randomRobot6<double>(g);
  rb[3].a = 0;
  rb[4].a = 0;
  rb[4].d = 0;
  rb[3].alpha = pi<double>() / 2;
  rb[4].alpha = -pi<double>() / 2;
  return rb;
}

TEST_CASE("general 6R branches: wrist axes 4-6 meeting, θ3 kept last: leading matrix singular for every offset (QZ)",
          "[sixr][branches]") {
  const Robot6R<double> rb = wristRobot();
  General6ROptions o;
  o.choose_elimination = false;
  const auto s = solveGeneral6R(rb, general6rForward(rb, kQ), o);
  CHECK(s.elimination == "theta3 last");
  for (const auto& n : s.notes) INFO(n);
  CHECK(hasNote(s, "generalized eigenproblem (QZ)"));
  CHECK(hasNote(s, "re-solved in long-double"));
  // A Pieper robot is a degenerate case of the eigenproblem (its closed form is solvePieper):
  // every posture returned is at round-off, and the generating posture is found or the answer
  // says it may be short — never fewer postures silently.
  CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
  CHECK((nearest(s, kQ) <= 1e-9 || hasNote(s, "the answer above may be short")));
}

TEST_CASE("general 6R branches: wrist axes 4-6 meeting, another joint eliminated last",
          "[sixr][branches]") {
  // θ3 last is structurally singular here (the test above); a cyclic relabelling or the
  // reversed loop is well conditioned and finds the generating posture in double.
  const Robot6R<double> rb = wristRobot();
  const auto s = solveGeneral6R(rb, general6rForward(rb, kQ));
  for (const auto& n : s.notes) INFO(n);
  INFO("elimination " << s.elimination);
  CHECK(hasNote(s, "ill-conditioned for every θ3 offset"));
  CHECK(s.elimination != "theta3 last");
  CHECK_FALSE(hasNote(s, "generalized eigenproblem (QZ)"));
  CHECK(s.leading_rcond > Tolerance<double>::precision(2));
  CHECK(s.count() % 2 == 0);
  CHECK(nearest(s, kQ) <= 1e-9);
  CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
}

TEST_CASE("general 6R branches: a planar robot (all α = 0) — an exactly singular leading matrix (QZ), and the answer says it may be short",
          "[sixr][branches]") {
  auto& g = test::rng(75);
  Robot6R<double> rb = randomRobot6<double>(g);
  for (auto& r : rb) r.alpha = 0;
  const auto s = solveGeneral6R(rb, general6rForward(rb, kQ));
  std::string notes;
  for (const auto& n : s.notes) notes += n + "\n";
  INFO(notes);
  CHECK(hasNote(s, "rank-deficient"));
  // The leading matrix has an exactly zero pivot: its rcond is 0 and the pencil goes to QZ. (Until
  // 2026-12-04 Eigen's PartialPivLU::rcond() estimated 3e-4 here — its estimator meets inf in the
  // solves — and the companion matrix, full of inf, made the Francis QR and Eigen's EigenSolver
  // fail.)
  CHECK(s.leading_rcond == 0.0);
  CHECK(hasNote(s, "generalized eigenproblem (QZ)"));
  CHECK(hasNote(s, "no higher precision left: the answer above may be short"));
}

TEST_CASE("general 6R branches: float escalates to double when its eigenproblem is too coarse",
          "[sixr][branches]") {
  auto& g = test::rng(76);
  int escalated = 0;
  for (int n = 0; n < 6; ++n) {
    const Robot6R<float> rb = randomRobot6<float>(g);
    std::array<float, 6> q;
    for (int i = 0; i < 6; ++i) q[i] = float(kQ[i]);
    const auto s = solveGeneral6R(rb, general6rForward(rb, q));
    INFO("robot " << n);
    if (s.solved_in == "double") {
      ++escalated;
      CHECK(hasNoteS(s, "re-solved in double"));
    }
    CHECK(nearest(s, q) <= 1e-3);
    CHECK(s.worstResidual() <= Tolerance<float>::identity(4096));
  }
  CHECK(escalated >= 1);
}

}  // namespace SOMA_UNITY_ID
