// The intersection ring of the Study quadric (GF Table 11.2) and the counts derived from it, and
// the constraint quadrics of legs and dyads against motions built directly in SE(3).
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/geometry/study/intersection_ring.hpp"
#include "soma/geometry/study/quaternion_matrices.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
// GF §11.5.4 lines 7263–7278 as printed: the homogenised leg equation with quaternions h₀ = a, h₁ = c,
// (|p|² + |q|² − L²) h₀h₀* + h₀ q h₀* p + p h₀ q h₀* + 2 h₀ q h₁* − 2 h₁ q h₀* + 2 p h₁ h₀* − 2 h₀ h₁* p + 4 h₁ h₁*
template <class S> Vec4<S> stewartLegExpressionAsPrinted(const Vec8<S>& x, const Vec3<S>& p, const Vec3<S>& q, const S& L) {
  const Vec4<S> h0 = x.template head<4>(), h1 = x.template tail<4>();
  const Vec4<S> qq(S(0), q.x(), q.y(), q.z()), pp(S(0), p.x(), p.y(), p.z());
  auto mul = [](const Vec4<S>& u, const Vec4<S>& v) { return Vec4<S>(quaternionLeftMatrix<S>(u) * v); };
  auto conj = [](const Vec4<S>& u) { return Vec4<S>(u(0), -u(1), -u(2), -u(3)); };
  const Vec4<S> h0s = conj(h0), h1s = conj(h1);
  return (p.squaredNorm() + q.squaredNorm() - L * L) * mul(h0, h0s) + mul(mul(mul(h0, qq), h0s), pp) +
         mul(pp, mul(mul(h0, qq), h0s)) + S(2) * mul(mul(h0, qq), h1s) - S(2) * mul(mul(h1, qq), h0s) +
         S(2) * mul(mul(pp, h1), h0s) - S(2) * mul(mul(h0, h1s), pp) + S(4) * mul(h1, h1s);
}
// GF §11.5.3 line 7242 as printed: the S–S link quadric (c₀ − l a₃)c₀ + (c₁ + l a₂)c₁ + (c₂ − l a₁)c₂ + (c₃ + l a₀)c₃
template <class S> S sphericalSphericalFormAsPrinted(const Vec8<S>& x, const S& l) {
  return (x(4) - l * x(3)) * x(4) + (x(5) + l * x(2)) * x(5) + (x(6) - l * x(1)) * x(6) + (x(7) + l * x(0)) * x(7);
}
}  // namespace

TEST_CASE("StudyClass: Table 11.2 is a commutative, associative graded ring of degree 2", "[study][ring]") {
  using C = StudyClass;
  std::vector<C::Cell> cells;
  for (int k = 0; k < C::kCells; ++k) cells.push_back(C::Cell(k));
  for (auto a : cells)
    for (auto b : cells) {
      CHECK(cellProduct(a, b) == cellProduct(b, a));
      // Grading: every term of a·b has dimension dim a + dim b − 6.
      const C p = cellProduct(a, b);
      for (auto c : cells)
        if (p[c] != 0) CHECK(C::dimension(c) == C::dimension(a) + C::dimension(b) - 6);
      for (auto c : cells) CHECK((C::cell(a) * C::cell(b)) * C::cell(c) == C::cell(a) * (C::cell(b) * C::cell(c)));
    }
  // The degree of the quadric: a general line meets it twice, σ₅⁶ = 2.
  CHECK(C::sigma5().pow(6).degree() == 2);
  CHECK(C::sigma5().pow(2) == C::sigma4());
  CHECK((C::sigma5() * C::sigma4()).toString() == "σ_A + σ_B");
}

TEST_CASE("StudyClass: the book's counts", "[study][ring]") {
  using C = StudyClass;
  const C threeR = 2 * C::sigmaA() + 4 * C::sigmaB();
  CHECK((threeR * threeR).degree() == 16);                       // GF-11.5.1-6R-sixteen
  CHECK((2 * C::sigma4()).pow(3).degree() == 16);                // GF-11.5.2-6-3-stewart-sixteen
  CHECK((2 * C::sigma5()).pow(3) == 8 * C::sigmaA() + 8 * C::sigmaB());  // GF-11.5.3-tripod-wrist-eight
  CHECK(((2 * C::sigma5()).pow(3) * C::sigmaA()).degree() == 8);
  CHECK((2 * C::sigma2() * C::sigma4()).degree() == 2);          // GF-11.5-2R-class
  CHECK((2 * C::sigma5()).pow(6).degree() == 128);               // GF-11.5.4: the naive count, not 40
  CHECK((C::sigmaA() * C::sigmaA()).isZero());
  CHECK((C::sigmaA() * C::sigmaB()).degree() == 1);
  CHECK_THROWS(C::sigma1().pow(-1));
}

namespace {
template <class S> SE3<S> rotationAbout(const Vec3<S>& axis, const S& angle, const Vec3<S>& point) {
  const SO3<S> R = SO3<S>::fromAxisAngle(axis, angle);
  return SE3<S>(R, Vec3<S>(point - R.act(point)));
}
template <class S> Vec8<S> study(const SE3<S>& g) { return StudyParameters<S>::fromSE3(g).coeffs(); }
}  // namespace

TEMPLATE_TEST_CASE("sphereConstraintQuadric: vanishes exactly on the leg's motions — equals the book's leg expression",
                   "[study][quadric]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs, std::cos, std::sin, std::sqrt;
  auto& g = rng(21);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 3 : 30;
  const S tol = Tolerance<S>::identity(512);
  for (int k = 0; k < n; ++k) {
    const Vec3<S> p = uniformVec<S, 3>(g, -2, 2), q = uniformVec<S, 3>(g, -1, 1);
    const SE3<S> m = SE3<S>::Random(g);
    const S L = sqrt((m.act(q) - p).squaredNorm());
    const Mat8<S> Q = sphereConstraintQuadric<S>(p, q, L);
    Vec8<S> x = study(m) * uniform<S>(g, 0.5, 3);  // any projective scale
    CHECK(abs(quadricResidual<S>(Q, x)) <= tol * (S(1) + L * L));
    // Off the sphere: the residual is (|g(q) − p|² − L'²)·|a|²/|x|².
    const S L2 = L + S(1) / S(4);
    const S expect = (L * L - L2 * L2) * x.template head<4>().squaredNorm() / x.squaredNorm();
    CHECK(abs(quadricResidual<S>(sphereConstraintQuadric<S>(p, q, L2), x) - expect) <= tol * (S(1) + L2 * L2));
    // The book's homogenised quaternion expression (GF §11.5.4) is the same quadratic form: equal
    // scalar part, zero vector part, on and off the sphere.
    const Vec4<S> book = stewartLegExpressionAsPrinted<S>(x, p, q, L2);
    CHECK(abs(book(0) - x.dot(sphereConstraintQuadric<S>(p, q, L2) * x)) <= tol * (S(1) + L2 * L2) * x.squaredNorm());
    CHECK(book.template tail<3>().cwiseAbs().maxCoeff() <= tol * (S(1) + L2 * L2) * x.squaredNorm());
  }
}

TEST_CASE("Leg quadrics: Wampler's differences lose the c-c block — all contain the quadric at infinity", "[study][quadric]") {
  auto& g = rng(22);
  using S = double;
  const Mat8<S> Q1 = sphereConstraintQuadric<S>(uniformVec<S, 3>(g), uniformVec<S, 3>(g), 1.3);
  const Mat8<S> Q2 = sphereConstraintQuadric<S>(uniformVec<S, 3>(g), uniformVec<S, 3>(g), 0.7);
  // GF §11.5.4: subtracting one leg quadric from another removes 4 h1 h1*.
  CHECK((Q1 - Q2).bottomRightCorner<4, 4>().cwiseAbs().maxCoeff() == 0.0);
  CHECK(Q1.bottomRightCorner<4, 4>().isApprox(4 * Mat4<S>::Identity()));
  // GF-11.5.3-SS-quadric-at-infinity: on a = 0 every leg quadric is 4(c0² + … + c3²).
  Vec8<S> x = Vec8<S>::Zero();
  x.tail<4>() = uniformVec<S, 4>(g);
  CHECK(x.dot(Q1 * x) == Approx(4 * x.tail<4>().squaredNorm()).epsilon(1e-14));
}

TEMPLATE_TEST_CASE("The book's S-S link quadric and 2R three-plane hold on motions built in SE(3)", "[study][quadric]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs, std::cos, std::sin, std::sqrt;
  auto& g = rng(23);
  const S tol = Tolerance<S>::identity(512);
  for (int k = 0; k < 20; ++k) {
    // GF-11.5.3-SS-link-variety: e^{φ s1} e^{ψ s2}, s1 through the origin, s2 through (0, 0, l).
    const S l = uniform<S>(g, 0.2, 3);
    const SE3<S> ss = rotationAbout(unitVec3<S>(g), uniform<S>(g, -3, 3), Vec3<S>::Zero().eval()) *
                      rotationAbout(unitVec3<S>(g), uniform<S>(g, -3, 3), Vec3<S>(S(0), S(0), l));
    const Vec8<S> x = study(ss);
    CHECK(abs(sphericalSphericalFormAsPrinted<S>(x, l)) <= tol * (S(1) + l * l));
    CHECK(abs(quadricResidual<S>(sphereConstraintQuadric<S>(Vec3<S>::Zero(), Vec3<S>(S(0), S(0), l), l), x)) <=
          tol * (S(1) + l * l));
    // The other side: a motion off the S–S variety.
    const Vec8<S> y = study(SE3<S>(ss.so3(), Vec3<S>(ss.translation() + Vec3<S>(S(0), S(0), S(1) / S(2)))));
    CHECK(abs(sphericalSphericalFormAsPrinted<S>(y, l)) > S(1) / S(1000));

    // GF-11.4-2R-three-plane: first axis z through 0, second through (l, 0, 0) along (0, −sin α, cos α).
    const S alpha = uniform<S>(g, 0.1, 3);
    const SE3<S> dyad = rotationAbout(Vec3<S>(S(0), S(0), S(1)), uniform<S>(g, -3, 3), Vec3<S>::Zero().eval()) *
                        rotationAbout(Vec3<S>(S(0), -sin(alpha), cos(alpha)), uniform<S>(g, -3, 3), Vec3<S>(l, S(0), S(0)));
    const Vec8<S> z = study(dyad);
    CHECK((twoRevoluteEquations<S>(l, alpha) * z).cwiseAbs().maxCoeff() <= tol * (S(1) + l));
  }
}

}  // namespace SOMA_UNITY_ID
