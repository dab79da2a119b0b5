// 3-planes of the Study quadric (GF §11.2): the subgroups they are, cosets, intersections.
#include "soma/geometry/study/study_plane.hpp"
#include "support/scalars.hpp"

#include <Eigen/QR>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
/// A random orthogonal 4×4 matrix with the given determinant sign.
template <class S> Mat4<S> randomOrthogonal(std::mt19937_64& g, int det) {
  Mat4<S> A;
  for (int i = 0; i < 4; ++i) A.col(i) = uniformVec<S, 4>(g);
  Eigen::HouseholderQR<Mat4<S>> qr(A);
  Mat4<S> Q = qr.householderQ();
  if ((Q.determinant() > S(0)) != (det > 0)) Q.col(0) = -Q.col(0);
  return Q;
}
template <class S> SE3<S> rotationAbout(const Vec3<S>& axis, const S& angle, const Vec3<S>& point) {
  const SO3<S> R = SO3<S>::fromAxisAngle(axis, angle);
  return SE3<S>(R, Vec3<S>(point - R.act(point)));
}
template <class S> Vec8<S> study(const SE3<S>& g) { return StudyParameters<S>::fromSE3(g).coeffs(); }
template <class S> S tol() { return Tolerance<S>::identity(256); }
}  // namespace

TEMPLATE_TEST_CASE("StudyPlane: x = M y planes lie in the quadric — det M gives A or B", "[study][plane]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs, std::cos, std::sin, std::sqrt;
  auto& g = rng(11);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 3 : 20;
  for (int k = 0; k < n; ++k)
    for (int det : {1, -1}) {
      const auto P = StudyPlane<S>::fromOrthogonal(randomOrthogonal<S>(g, det));
      CHECK((P.kind() == StudyPlaneKind::A) == (det > 0));
      const Vec8<S> x = P.point(uniformVec<S, 4>(g));
      CHECK(abs(StudyParameters<S>(x).studyCondition()) <= tol<S>() * x.squaredNorm());
      CHECK(P.residual(x) <= tol<S>());
      // GF-11.2.2-A-plane-cosets: the span of four points gives back M.
      const auto P2 = StudyPlane<S>::fromSpan(P.basis());
      CHECK((P2.M() - P.M()).cwiseAbs().maxCoeff() <= tol<S>());
    }
}

TEMPLATE_TEST_CASE("StudyPlane: SO(3)_p is the Cayley plane diag(1, Cay(p)) — SE(2)_n the half-turn plane", "[study][plane]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs, std::cos, std::sin, std::sqrt;
  auto& g = rng(12);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 3 : 20;
  for (int k = 0; k < n; ++k) {
    const Vec3<S> p = uniformVec<S, 3>(g, -2, 2), axis = unitVec3<S>(g);
    const S angle = soma::test::uniform<S>(g, -3, 3);
    const auto P = StudyPlane<S>::rotationsAbout(p);
    CHECK(P.kind() == StudyPlaneKind::A);
    CHECK(P.residual(study(rotationAbout(axis, angle, p))) <= tol<S>());
    // The other side: a rotation about another point is not in the plane.
    const Vec3<S> off = p + S(1) / S(10) * unitVec3<S>(g);
    CHECK(P.residual(study(rotationAbout(axis, S(1), off))) > S(1) / S(1000));
    // GF-11.2.2: all its points have c0 = 0 and c⃗ = p × a⃗ (the book's verification).
    const Vec8<S> x = study(rotationAbout(axis, angle, p));
    CHECK(abs(x(4)) <= tol<S>());
    CHECK((x.template segment<3>(5) - p.cross(Vec3<S>(x.template segment<3>(1)))).cwiseAbs().maxCoeff() <= tol<S>());

    const Vec3<S> nrm = unitVec3<S>(g);
    const auto E = StudyPlane<S>::planarMotions(nrm);
    CHECK(E.kind() == StudyPlaneKind::A);
    Vec3<S> u = nrm.cross(unitVec3<S>(g));
    u.normalize();
    const SE3<S> planar = SE3<S>(SO3<S>(), Vec3<S>(S(3) / S(2) * u)) * rotationAbout(nrm, angle, p);
    CHECK(E.residual(study(planar)) <= tol<S>());
    const SE3<S> lifted = SE3<S>(SO3<S>(), Vec3<S>(nrm / S(10))) * planar;  // a translation along n leaves SE(2)
    CHECK(E.residual(study(lifted)) > S(1) / S(1000));
  }
  const auto T = StudyPlane<S>::translations();
  CHECK(T.kind() == StudyPlaneKind::B);
  CHECK(T.residual(study(SE3<S>(SO3<S>(), uniformVec<S, 3>(g, -5, 5)))) <= tol<S>());
  CHECK(T.residual(study(rotationAbout(unitVec3<S>(g), S(1) / S(2), Vec3<S>::Zero().eval()))) > S(1) / S(10));
  const auto I = StudyPlane<S>::atInfinity();
  CHECK(I.kind() == StudyPlaneKind::A);
  const Vec8<S> ideal = I.point(uniformVec<S, 4>(g));
  CHECK(StudyParameters<S>(ideal).inExceptionalPlane());
}

// Issue 22: residual() took ::sqrt(double) for long double and __float128 (no ADL for builtin types),
// so its value was good to double's 1e-16 only. Against |E x|/|x| in mpfr-256 from the same E and x,
// rounding bounds it by ε(8‖|E||x|‖/‖E x‖ + 16): the 8-term products (γ₈ relative to |E||x|), the two
// squared norms (γ₈, γ₄), two square roots and the quotient.
TEMPLATE_TEST_CASE("StudyPlane: residual(x) = |E x|/|x| to the rounding of S (mpfr-256 reference)", "[study][plane]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using M = mpfr::mpreal;
  const auto toM = [](const S& v) { return scalarCast<M>(v); };
  auto& g = rng(16);
  const M eps = scalarCast<M>(std::numeric_limits<S>::epsilon());
  M worst = 0;
  for (int k = 0; k < 50; ++k) {
    const auto P = StudyPlane<S>::rotationsAbout(uniformVec<S, 3>(g, -2, 2));
    const Vec8<S> x = uniformVec<S, 8>(g);
    const Eigen::Matrix<M, 4, 8> E = P.equations().unaryExpr(toM);
    const Eigen::Matrix<M, 8, 1> xm = x.unaryExpr(toM);
    const M exact = sqrt((E * xm).squaredNorm()) / sqrt(xm.squaredNorm());
    const M size = sqrt((E.cwiseAbs() * xm.cwiseAbs()).squaredNorm()) / sqrt((E * xm).squaredNorm());
    const M err = abs(scalarCast<M>(P.residual(x)) - exact) / exact / (eps * (8 * size + 16));
    worst = std::max(worst, err);
  }
  INFO("worst error / bound " << worst.toString(3));
  CHECK(worst <= 1);
}

TEMPLATE_TEST_CASE("StudyPlane: cosets g·SO(3)_p stay A-planes and contain g times the rotations", "[study][plane]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs, std::cos, std::sin, std::sqrt;
  auto& g = rng(13);
  for (int k = 0; k < 10; ++k) {
    const SE3<S> m = SE3<S>::Random(g);
    const Vec3<S> p = uniformVec<S, 3>(g);
    const auto P = StudyPlane<S>::rotationsAbout(p).leftTranslated(DualQuaternion<S>::fromSE3(m));
    CHECK(P.kind() == StudyPlaneKind::A);
    CHECK(P.residual(study(SE3<S>(m * rotationAbout(unitVec3<S>(g), S(7) / S(10), p)))) <= tol<S>());
    const auto T = StudyPlane<S>::translations().rightTranslated(DualQuaternion<S>::fromSE3(m));
    CHECK(T.kind() == StudyPlaneKind::B);
    CHECK(T.residual(study(SE3<S>(SE3<S>(SO3<S>(), uniformVec<S, 3>(g)) * m))) <= tol<S>());
  }
}

TEMPLATE_TEST_CASE("StudyPlane intersections: corank = multiplicity of eigenvalue 1 of M1 M2ᵀ", "[study][plane]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::abs, std::cos, std::sin, std::sqrt;
  auto& g = rng(14);
  for (int k = 0; k < 20; ++k) {
    const auto A1 = StudyPlane<S>::fromOrthogonal(randomOrthogonal<S>(g, 1));
    const auto A2 = StudyPlane<S>::fromOrthogonal(randomOrthogonal<S>(g, 1));
    const auto B1 = StudyPlane<S>::fromOrthogonal(randomOrthogonal<S>(g, -1));
    const auto B2 = StudyPlane<S>::fromOrthogonal(randomOrthogonal<S>(g, -1));
    // GF-11.2.3-intersection-cases: A∩A, B∩B empty; A∩B a point.
    CHECK(intersectionDimension(A1, A2) == -1);
    CHECK(intersectionDimension(B1, B2) == -1);
    CHECK(intersectionDimension(A1, B1) == 0);
    CHECK(intersectionDimensionByEigenvalues(A1, A2) == -1);
    CHECK(intersectionDimensionByEigenvalues(A1, B2) == 0);
    CHECK(intersectionDimension(A1, A1) == 3);
  }
  // Special position: M2 = M1·rot(θ) in a 2-plane. θ = 0 gives a line; θ on either side of the
  // rank threshold (Tolerance::rank, relative to the unit scale of M): a line just below it, the
  // generic empty intersection just above.
  const Mat4<S> M1 = randomOrthogonal<S>(g, 1);
  const S thr = Tolerance<S>::rank();
  for (const S theta : {S(0), S(thr / S(16)), S(thr * S(16))}) {
    Mat4<S> Rb = Mat4<S>::Identity();
    Rb(0, 0) = cos(theta), Rb(0, 1) = -sin(theta), Rb(1, 0) = sin(theta), Rb(1, 1) = cos(theta);
    Rb(2, 2) = cos(S(1)), Rb(2, 3) = -sin(S(1)), Rb(3, 2) = sin(S(1)), Rb(3, 3) = cos(S(1));
    const auto P2 = StudyPlane<S>::fromOrthogonal(Mat4<S>(Rb * M1));
    const int expected = theta < thr ? 1 : -1;
    INFO("θ = " << toString(theta, 3) << ", threshold " << toString(thr, 3));
    CHECK(intersectionDimension(StudyPlane<S>::fromOrthogonal(M1), P2) == expected);
    CHECK(intersectionDimensionByEigenvalues(StudyPlane<S>::fromOrthogonal(M1), P2) == expected);
  }
}

TEST_CASE("StudyPlane: the book's meetings with the A-plane at infinity", "[study][plane]") {
  // GF §11.2.3, GF-11.2.3-meet-infinite-A-plane: SO(3)_p none, SE(2) a line, a generic B-plane
  // through 1 a point, R³ a 2-plane.
  using S = double;
  const auto inf = StudyPlane<S>::atInfinity();
  CHECK(intersectionDimension(inf, StudyPlane<S>::rotationsAbout(Vec3<S>(0.3, -1, 2))) == -1);
  CHECK(intersectionDimension(inf, StudyPlane<S>::planarMotions(Vec3<S>(0, 0, 1))) == 1);
  Mat4<S> M = Mat4<S>::Identity();
  M.bottomRightCorner<3, 3>() = -cayleyRotation<S>(Vec3<S>(0.2, 0.5, -0.7));  // det −1, generic
  CHECK(intersectionDimension(inf, StudyPlane<S>::fromOrthogonal(M)) == 0);
  CHECK(intersectionDimension(inf, StudyPlane<S>::translations()) == 2);
}

TEST_CASE("StudyPlane: bad input is named", "[study][plane]") {
  Mat4<double> M = Mat4<double>::Identity();
  M(0, 1) = 0.01;
  CHECK_THROWS_WITH(StudyPlane<double>::fromOrthogonal(M), Catch::Matchers::Contains("not orthogonal"));
  M(0, 1) = std::nan("");
  CHECK_THROWS_WITH(StudyPlane<double>::fromOrthogonal(M), Catch::Matchers::Contains("NaN"));
  Eigen::Matrix<double, 8, 4> P = Eigen::Matrix<double, 8, 4>::Zero();
  P.topRows<4>() = Mat4<double>::Identity();  // the a-space: a·c = 0 but not isotropic for x·x − y·y
  P(4, 1) = 1;
  CHECK_THROWS_AS(StudyPlane<double>::fromSpan(P), InvalidInput);
  CHECK_THROWS_WITH(StudyPlane<double>::planarMotions(Vec3<double>(0, 0, 2)), Catch::Matchers::Contains("not a unit vector"));
}

}  // namespace SOMA_UNITY_ID
