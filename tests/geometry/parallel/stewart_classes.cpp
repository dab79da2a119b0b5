// Stewart–Gough platforms of every tabulated class solved to their class's count (stewart_class.hpp;
// the counts of 6-5, 6-4, 5-5, 4-4 cross-checked by PHCpack in SOMA-11.5-stewart-classes), the
// architecturally singular ones refused with the defect named, the complex solutions as postures
// of the user's platform, and a platform on the boundary of its assembly space (two postures
// merged) answered with one posture of multiplicity 2.
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/stewart_class.hpp"

#include "soma/algebra/errors.hpp"
#include "support/scalars.hpp"

#include <cstdlib>
#include <Eigen/SVD>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {

/// Joints of the incidence (b, q) (b[i], q[i]: the base and platform joint of leg i), random in a
/// box, and leg lengths from a random posture (returned).
template <class S>
StewartPlatform<S> platformOf(const std::array<int, 6>& b, const std::array<int, 6>& q, std::mt19937_64& g, SE3<S>* pose) {
  std::array<Vec3<S>, 6> B, Q;
  for (auto& v : B) v = Vec3<S>(test::uniform<S>(g), test::uniform<S>(g), test::uniform<S>(g, -0.3, 0.3));
  for (auto& v : Q) v = Vec3<S>(test::uniform<S>(g, -0.6, 0.6), test::uniform<S>(g, -0.6, 0.6), test::uniform<S>(g, -0.2, 0.2));
  StewartPlatform<S> P;
  for (std::size_t i = 0; i < 6; ++i) {
    P.base[i] = B[static_cast<std::size_t>(b[i])];
    P.platform[i] = Q[static_cast<std::size_t>(q[i])];
  }
  Vec6<S> xi;
  xi << test::uniform<S>(g, -0.3, 0.3), test::uniform<S>(g, -0.3, 0.3), test::uniform<S>(g, -0.3, 0.3),
      test::uniform<S>(g, -0.2, 0.2), test::uniform<S>(g, -0.2, 0.2), test::uniform<S>(g, 0.8, 1.2);
  *pose = SE3Tangent<S>(xi).exp();
  P.legs = stewartLegLengths<S>(P, *pose);
  return P;
}

template <class S> S nearestPosture(const StewartForwardSolution<S>& s, const SE3<S>& g) {
  S best = S(1e30);
  for (const auto& h : s.postures) best = std::min(best, S((h.matrix() - g.matrix()).norm()));
  return best;
}

struct Incidence {
  const char* what;
  std::array<int, 6> b, q;
  int count = 0;  ///< the class's count (stewart_class.hpp; PHCpack agrees in SOMA-11.5-stewart-classes)
};

}  // namespace

TEST_CASE("Stewart classes 6-5, 6-4, 5-5, 4-4: the class's count, certified, the defining posture found",
          "[stewart][stewart_class]") {
  // One incidence per tabulated pattern of these classes (the study enumerates them all).
  const Incidence cases[] = {
      {"6-5", {0, 1, 2, 3, 4, 5}, {0, 0, 1, 2, 3, 4}, 40},
      {"6-4 two pairs", {0, 1, 2, 3, 4, 5}, {0, 0, 1, 1, 2, 3}, 32},
      {"6-4 three legs on a joint", {0, 1, 2, 3, 4, 5}, {0, 0, 0, 1, 2, 3}, 16},
      {"5-5 pairs sharing a leg", {0, 0, 1, 2, 3, 4}, {0, 1, 1, 2, 3, 4}, 40},
      {"5-5 disjoint pairs", {0, 0, 1, 2, 3, 4}, {0, 1, 2, 2, 3, 4}, 24},
      {"4-4 pairs in a chain", {0, 0, 1, 1, 2, 3}, {0, 1, 1, 2, 2, 3}, 24},
      {"4-4 pairs crossed", {0, 0, 1, 1, 2, 3}, {0, 1, 0, 1, 2, 3}, 16},
      {"4-4 three legs on a joint", {0, 0, 0, 1, 2, 3}, {0, 1, 2, 0, 1, 3}, 16},
  };
  auto& g = test::rng(2104);
  for (const auto& k : cases) {
    INFO(k.what);
    SE3<double> pose;
    const auto P = platformOf<double>(k.b, k.q, g, &pose);
    const auto cls = classifyStewart<double>(P);
    REQUIRE(cls.singular_reason.empty());
    REQUIRE(cls.expected_count.has_value());
    const auto s = solveStewart<double>(P);
    CHECK(s.expected_count == k.count);
    CHECK(s.complexCount() == s.expected_count);
    CHECK(s.certified);
    CHECK(nearestPosture<double>(s, pose) <= Tolerance<double>::input());
    CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
    // --complex's list: every complex solution a posture of the platform, multiplicities summing to the count.
    int total = 0;
    double worst = 0;
    for (const auto& c : s.complex_postures) {
      total += c.multiplicity;
      worst = std::max(worst, stewartComplexResidual<double>(P, c));
    }
    CHECK(total == k.count);
    CHECK(worst <= Tolerance<double>::identity(4096));
  }
}

TEMPLATE_TEST_CASE("Stewart 6-5: a joint pair coincident or a few ulps apart is 6-5 — 10·√eps·size apart, 6-6",
                   "[stewart][stewart_class]", float, double, long double) {
  using S = TestType;
  auto& g = test::rng(65);
  SE3<S> pose;
  auto P = platformOf<S>({0, 1, 2, 3, 4, 5}, {0, 0, 1, 2, 3, 4}, g, &pose);
  const S size = stewartScale<S>(P), tol = Tolerance<S>::sqrtEpsilon() * size;
  const auto c = classifyStewart<S>(P);
  CHECK(c.name == "6-5");
  REQUIRE(c.expected_count.has_value());
  auto ulps = P, apart = P;
  ulps.platform[1].x() += S(4) * Tolerance<S>::epsilon() * size;
  apart.platform[1].x() += S(10) * tol;
  const auto cu = classifyStewart<S>(ulps), ca = classifyStewart<S>(apart);
  CHECK(cu.name == "6-5");
  CHECK(cu.expected_count == c.expected_count);
  CHECK(ca.name == "6-6");
  CHECK(ca.expected_count == 40);
  if constexpr (std::is_same_v<S, double>) {
    // The solver on both sides: the ulps-apart pair is solved as 6-5 (its count, certified).
    ulps.legs = stewartLegLengths<S>(ulps, pose);
    const auto s = solveStewart<S>(ulps);
    CHECK(s.complexCount() == *c.expected_count);
    CHECK(s.certified);
  }
}

TEMPLATE_TEST_CASE("Stewart 6-4, 5-5, 4-4: each coincidence decided at √eps·size, both sides", "[stewart][stewart_class]",
                   float, double, long double) {
  using S = TestType;
  auto& g = test::rng(44);
  const Incidence cases[] = {
      {"6-4", {0, 1, 2, 3, 4, 5}, {0, 0, 1, 1, 2, 3}},
      {"5-5", {0, 0, 1, 2, 3, 4}, {0, 1, 1, 2, 3, 4}},
      {"4-4", {0, 0, 1, 1, 2, 3}, {0, 1, 1, 2, 2, 3}},
  };
  for (const auto& k : cases) {
    INFO(k.what);
    SE3<S> pose;
    const auto P = platformOf<S>(k.b, k.q, g, &pose);
    const auto c = classifyStewart<S>(P);
    CHECK(c.name == std::string(k.what));
    CHECK(c.expected_count.has_value());
    // Separate the base joints of legs 1 and 2 (they share a joint in 5-5 and 4-4) or the platform
    // joints of legs 1 and 2 (6-4): within tol the class stays, beyond it one joint more.
    const bool onBase = k.b[0] == k.b[1];
    const S tol = Tolerance<S>::sqrtEpsilon() * stewartScale<S>(P);
    auto in = P, out = P;
    (onBase ? in.base[1] : in.platform[1]).y() += S(0.5) * tol;
    (onBase ? out.base[1] : out.platform[1]).y() += S(10) * tol;
    CHECK(classifyStewart<S>(in).pattern == c.pattern);
    const auto co = classifyStewart<S>(out);
    CHECK(co.pattern != c.pattern);
    CHECK(co.base_distinct + co.platform_distinct == c.base_distinct + c.platform_distinct + 1);
  }
}

TEST_CASE("Stewart pattern: invariant under renumbering the legs and swapping base and platform", "[stewart][stewart_class]") {
  const std::array<int, 6> b{0, 0, 1, 1, 2, 3}, q{0, 1, 1, 2, 2, 3};
  const std::string key = stewartPattern(b, q);
  CHECK(stewartPattern(q, b) == key);
  std::array<int, 6> perm{0, 1, 2, 3, 4, 5};
  std::mt19937_64 g(6);
  for (int t = 0; t < 20; ++t) {
    std::shuffle(perm.begin(), perm.end(), g);
    std::array<int, 6> b2, q2;
    for (std::size_t i = 0; i < 6; ++i) b2[i] = b[static_cast<std::size_t>(perm[i])], q2[i] = q[static_cast<std::size_t>(perm[i])];
    CHECK(stewartPattern(b2, q2) == key);
  }
  CHECK(stewartPattern({0, 1, 2, 3, 4, 5}, {0, 0, 1, 1, 2, 2}) == "aabbcc|abcdef");
  CHECK(stewartPattern({0, 0, 1, 1, 2, 2}, {0, 1, 1, 2, 2, 0}) == "aabbcc|abacbc");  // octahedral
  CHECK(stewartPattern({0, 0, 1, 1, 2, 3}, {0, 1, 1, 2, 2, 3}) != stewartPattern({0, 0, 1, 1, 2, 3}, {0, 1, 2, 3, 0, 1}));
}

TEST_CASE("Stewart: architecturally singular platforms are refused, the defect named", "[stewart][stewart_class]") {
  auto& g = test::rng(99);
  SE3<double> pose;
  // A repeated leg: legs 1 and 2 join the same two joints.
  const auto R = platformOf<double>({0, 0, 1, 2, 3, 4}, {0, 0, 1, 2, 3, 4}, g, &pose);
  CHECK_THROWS_WITH(solveStewartForward<double>(R), Catch::Contains("architecturally singular") &&
                                                        Catch::Contains("legs 1 and 2 join the same base joint"));
  // Four legs on one platform joint.
  const auto F = platformOf<double>({0, 1, 2, 3, 4, 5}, {0, 0, 0, 0, 1, 2}, g, &pose);
  CHECK_THROWS_WITH(solveStewartForward<double>(F), Catch::Contains("legs 1, 2, 3, 4 meet at one platform joint"));
  // Legs 1–3 on one base joint, legs 4–6 on one platform joint: a hinge through the two joints.
  const auto H = platformOf<double>({0, 0, 0, 1, 2, 3}, {0, 1, 2, 3, 3, 3}, g, &pose);
  CHECK_THROWS_WITH(solveStewartForward<double>(H), Catch::Contains("the platform turns about the line through those two joints"));
  // Collinear base joints (the platform turns about that line): refused, not "cannot be assembled".
  auto L = platformOf<double>({0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 5}, g, &pose);
  for (int i = 0; i < 6; ++i) L.base[static_cast<std::size_t>(i)] = Vec3<double>(0.3 * i - 0.7, 0.1 * i, 0.05);
  L.legs = stewartLegLengths<double>(L, pose);
  CHECK_THROWS_WITH(solveStewart<double>(L), Catch::Contains("base joints are collinear"));
  // The same collinear base but one joint a few ulps off the line is still refused; 1e-3 off, solved.
  auto off = L;
  off.base[3].z() += 4 * Tolerance<double>::epsilon() * stewartScale<double>(L);
  CHECK_THROWS_WITH(solveStewart<double>(off), Catch::Contains("base joints are collinear"));
  off.base[3].z() += 1e-3;
  CHECK_NOTHROW(classifyStewart<double>(off));
  CHECK(classifyStewart<double>(off).singular_reason.empty());
}

TEMPLATE_TEST_CASE("Stewart complex postures: every solution as (rotation, translation) of the user's platform", "[stewart]",
                   double, long double) {
  using S = TestType;
  auto& g = test::rng(4040);
  SE3<S> pose;
  // A general platform shifted far from the origin and scaled: the user's frame, not the solve's.
  auto P = platformOf<S>({0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 5}, g, &pose);
  for (auto& p : P.base) p = S(3) * p + Vec3<S>(S(5), S(-2), S(1));
  for (auto& q : P.platform) q = S(3) * q + Vec3<S>(S(-1), S(4), S(2));
  P.legs = stewartLegLengths<S>(P, pose);
  const auto s = solveStewartForward<S>(P);
  REQUIRE(s.complexCount() == 40);
  REQUIRE(s.complex_postures.size() == 40);
  int real = 0;
  S worst = S(0), worstNorm = S(0), worstReal = S(0);
  for (const auto& c : s.complex_postures) {
    worst = std::max(worst, stewartComplexResidual<S>(P, c));
    std::complex<S> aa(S(0));
    S a2 = S(0);  // |a|², the Hermitian square
    for (const auto& z : c.rotation) aa += z * z, a2 += std::norm(z);
    using std::abs;
    // The bilinear square a·a of a complex a carries rounding of eps·|a|², not eps: a complex
    // posture far from the real ones has |a|² ≫ |a·a| = 1 (up to 450 here), so relative to |a|².
    worstNorm = std::max(worstNorm, S(abs(aa - std::complex<S>(S(1)))) / std::max(S(1), a2));
    if (!c.real) continue;
    ++real;
    // A real one is one of the real postures: same rotation (±a) and translation.
    S best = S(1e30);
    for (const auto& h : s.postures) {
      const Quat<S> q = h.so3().quaternion();
      const S sgn = q.w() * c.rotation[0].real() + q.vec().dot(Vec3<S>(c.rotation[1].real(), c.rotation[2].real(), c.rotation[3].real())) < S(0) ? S(-1) : S(1);
      S d = abs(sgn * q.w() - c.rotation[0].real());
      for (int k = 0; k < 3; ++k) {
        d = std::max(d, S(abs(sgn * q.vec()(k) - c.rotation[static_cast<std::size_t>(k) + 1].real())));
        d = std::max(d, S(abs(h.translation()(k) - c.translation[static_cast<std::size_t>(k)].real()) / stewartScale<S>(P)));
      }
      best = std::min(best, d);
    }
    worstReal = std::max(worstReal, best);
  }
  CHECK(real == static_cast<int>(s.count()));
  // Leg equations at the rounding floor of S (the Study point polished to 64 eps, then rotated and
  // translated: a few hundred eps).
  CHECK(worst <= Tolerance<S>::identity(4096));
  CHECK(worstNorm <= Tolerance<S>::identity(256));
  CHECK(worstReal <= Tolerance<S>::sqrtEpsilon());
}

namespace {
/// A platform on the boundary of its assembly space: at `pose` its six leg lines are linearly
/// dependent (the Jacobian of the leg lengths is singular), so two real postures merge there.
/// Legs 1–5 of a random platform fix a twist s reciprocal to their lines; leg 6 is re-aimed so that
/// its line is reciprocal to s too (perpendicular to the velocity of its platform joint under s).
StewartPlatform<double> boundaryPlatform(std::mt19937_64& g, SE3<double>* pose) {
  auto P = platformOf<double>({0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 5}, g, pose);
  Eigen::Matrix<double, 5, 6> A;
  for (int i = 0; i < 5; ++i) {
    const Vec3<double> Q = pose->act(P.platform[static_cast<std::size_t>(i)]);
    const Vec3<double> d = (Q - P.base[static_cast<std::size_t>(i)]).normalized();
    A.row(i) << Q.cross(d).transpose(), d.transpose();  // (Q × d)·ω + d·v
  }
  const Eigen::JacobiSVD<Eigen::Matrix<double, 5, 6>> svd(A, Eigen::ComputeFullV);
  const Vec6<double> s = svd.matrixV().col(5);
  const Vec3<double> Q6 = pose->act(P.platform[5]);
  const Vec3<double> u = (s.tail<3>() + s.head<3>().cross(Q6)).normalized();  // velocity of Q6 under s
  Vec3<double> d = (Q6 - P.base[5]).normalized();
  d = (d - d.dot(u) * u).normalized();
  P.base[5] = Q6 - P.legs[5] * d;
  P.legs = stewartLegLengths<double>(P, *pose);
  return P;
}
/// The 6×6 matrix of the leg lines (Plücker rows) at g, its smallest over largest singular value.
double legLineConditioning(const StewartPlatform<double>& P, const SE3<double>& g) {
  Mat6<double> J;
  for (int i = 0; i < 6; ++i) {
    const Vec3<double> Q = g.act(P.platform[static_cast<std::size_t>(i)]);
    const Vec3<double> d = (Q - P.base[static_cast<std::size_t>(i)]).normalized();
    J.row(i) << Q.cross(d).transpose(), d.transpose();
  }
  const Eigen::JacobiSVD<Mat6<double>> svd(J);
  return svd.singularValues()(5) / svd.singularValues()(0);
}
}  // namespace

TEST_CASE("Stewart at the boundary of the assembly space: one posture of multiplicity 2, 40 with multiplicity",
          "[stewart]") {
  auto& g = test::rng(2103);
  for (int trial = 0; trial < 3; ++trial) {
    SE3<double> pose;
    const auto P = boundaryPlatform(g, &pose);
    CHECK(legLineConditioning(P, pose) <= Tolerance<double>::identity(256));  // singular at the pose
    const auto s = solveStewart<double>(P);
    CHECK(s.complexCount() == 40);
    CHECK(s.distinctCount() == 39);
    CHECK(s.certified);
    // A double root: the fast double tracker cannot certify it (two paths end together, singular)
    // and hands the platform to the general tracker, saying so.
    CHECK(s.tracker == "general");
    bool fellBack = false;
    for (const auto& n : s.notes) fellBack = fellBack || n.find("re-solved by the general tracker") != std::string::npos;
    CHECK(fellBack);
    // The fast tracker's portable kernel (the one a CPU without AVX2 takes) falls back there too.
    setenv("SOMA_STEWART_KERNEL", "portable", 1);
    const auto sp = solveStewartForward<double>(P);
    unsetenv("SOMA_STEWART_KERNEL");
    CHECK(sp.tracker == "general");
    CHECK(sp.distinctCount() == 39);
    int doubles = 0;
    std::size_t at = 0;
    for (std::size_t k = 0; k < s.count(); ++k)
      if (s.posture_multiplicity[k] == 2) ++doubles, at = k;
    REQUIRE(doubles == 1);
    // The double posture is the one that defined the leg lengths (a double root: √eps accurate),
    // and no other real posture lies near it (no near-duplicates).
    CHECK((s.postures[at].matrix() - pose.matrix()).norm() <= Tolerance<double>::input());
    for (std::size_t k = 0; k < s.count(); ++k)
      if (k != at) CHECK((s.postures[k].matrix() - pose.matrix()).norm() > 1e-3);
    CHECK(s.residuals[at] <= Tolerance<double>::sqrtEpsilon());
  }
  // Off the boundary (leg 6 lengthened by 1e-3 of the size): the double root splits, 40 distinct.
  SE3<double> pose;
  auto P = boundaryPlatform(g, &pose);
  P.legs[5] *= 1 + 1e-3;
  const auto s = solveStewart<double>(P);
  CHECK(s.complexCount() == 40);
  CHECK(s.distinctCount() == 40);
  CHECK(s.tracker == "fast");  // the other side: 40 distinct, no fallback
  setenv("SOMA_STEWART_KERNEL", "portable", 1);
  const auto sp = solveStewartForward<double>(P);
  unsetenv("SOMA_STEWART_KERNEL");
  CHECK(sp.distinctCount() == 40);
  CHECK(sp.tracker == "fast");
}

}  // namespace SOMA_UNITY_ID

namespace SOMA_UNITY_ID {
namespace {
/// A standard hexapod: base joints at 0°, 120°, 240° ± wb (radius rb), platform joints at 60°, 180°,
/// 300° ± wq (radius rq), legs joining each base joint to a neighbouring platform joint; planar and
/// 3-fold symmetric with the same leg permutation on both sides.
template <class S> StewartPlatform<S> standardHexapod(double wb, double wq, double rb, double rq, double phase) {
  StewartPlatform<S> P;
  const double deg = 3.14159265358979323846 / 180;
  std::array<Vec3<S>, 6> q;
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      const double ab = (120 * k + (s ? wb : -wb)) * deg, aq = (120 * k + 60 + (s ? wq : -wq) + phase) * deg;
      P.base[static_cast<std::size_t>(2 * k + s)] = Vec3<S>(S(rb * std::cos(ab)), S(rb * std::sin(ab)), S(0));
      q[static_cast<std::size_t>(2 * k + s)] = Vec3<S>(S(rq * std::cos(aq)), S(rq * std::sin(aq)), S(0));
    }
  for (std::size_t i = 0; i < 6; ++i) P.platform[i] = q[(i + 5) % 6];
  const SE3<S> g(SO3<S>(), Vec3<S>(S(0.02), S(-0.03), S(1)));
  P.legs = stewartLegLengths<S>(P, g);
  P.legs[1] *= S(1.02);  // lengths off the symmetric posture: the count is the geometry's
  return P;
}
}  // namespace

TEST_CASE("Stewart standard hexapod (planar, 3-fold symmetric): 28, certified — symmetry decided at tol, both sides",
          "[stewart][stewart_class]") {
  for (const double phase : {0.0, 7.0}) {
    INFO("phase " << phase);
    const auto P = standardHexapod<double>(12, 45, 1.0, 0.6, phase);
    const auto c = classifyStewart<double>(P);
    CHECK(c.threefold);
    CHECK(c.expected_count == 28);
    const auto s = solveStewart<double>(P);
    CHECK(s.complexCount() == 28);
    CHECK(s.certified);
    const double tol = Tolerance<double>::sqrtEpsilon() * stewartScale<double>(P);
    auto in = P, out = P;
    in.platform[2].x() += 0.5 * tol;
    out.platform[2].x() += 10 * tol;
    CHECK(classifyStewart<double>(in).threefold);
    CHECK(!classifyStewart<double>(out).threefold);
    CHECK(classifyStewart<double>(out).expected_count == 40);
  }
  // Only one side symmetric: a general planar platform, 40.
  auto A = standardHexapod<double>(12, 45, 1.0, 0.6, 0);
  A.platform[0] = Vec3<double>(0.31, -0.22, 0);
  CHECK(!classifyStewart<double>(A).threefold);
  CHECK(classifyStewart<double>(A).expected_count == 40);
}

}  // namespace SOMA_UNITY_ID
