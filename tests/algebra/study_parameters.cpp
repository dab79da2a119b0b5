// Study parameters (GF §9.3, §11.1–11.4): round trips matrix → SE3 → DQ → Study → SE3 → matrix at
// the edges, the Study condition on images of motions and its failure off the quadric, the
// exceptional 3-plane (both sides of the threshold), projective scaling and the 2-to-1 cover,
// the book's examples of §11.4 (isotropy group of a line, erratum 1; the 2R three-plane) and the
// rejection of bad input.
#include "soma/algebra/study_parameters.hpp"
#include "support/scalars.hpp"

#include <vector>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using Catch::Matchers::Contains;

namespace {

template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }

template <class S> std::vector<S> edgeAngles() {
  const S p = pi<S>();
  return {S(0), S(1e-8), S(7) / S(10), S(2), p - S(1e-8), p};
}
template <class S> std::vector<S> edgeLengths() {
  return {S(0), S(1e-8), S(1), S(1000), S(100000000)};
}
template <class S> int randomCount() { return std::is_same_v<S, mpreal> ? 10 : 100; }

/// The motion with rotation θ about a fixed generic axis and translation of length len.
template <class S> SE3<S> edgeMotion(const S& th, const S& len) {
  const Vec3<S> u = Vec3<S>(S(2), S(-3), S(6)) / S(7);
  const Vec3<S> w = Vec3<S>(S(6), S(3), S(2)) / S(7);
  return SE3<S>(SO3<S>::fromAxisAngle(u, th), Vec3<S>(len * w));
}

}  // namespace

TEMPLATE_TEST_CASE("Study round trip matrix → SE3 → DQ → Study → SE3 → matrix", "[study]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const S eps = Tolerance<S>::epsilon();
  for (const S& th : edgeAngles<S>())
    for (const S& len : edgeLengths<S>()) {
      INFO("theta = " << toString(th) << ", |t| = " << toString(len));
      const Mat4<S> m = edgeMotion(th, len).matrix();
      const SE3<S> g = SE3<S>::fromMatrix(m);
      const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(g);
      const StudyParameters<S> p = StudyParameters<S>::fromDualQuaternion(h);
      CHECK(p.onStudyQuadric(S(8) * eps));
      // |a|/|v| ≈ 2/|t|: beyond |t| ≈ 2/eps the rotation part is below the rounding level of
      // the coordinates, the point is numerically in the exceptional plane, and the conversion
      // refuses (float at |t| = 1e8); below, the round trip holds to a few ulps of |t|.
      if (len / S(2) >= S(1) / eps) {
        CHECK(p.inExceptionalPlane());
        REQUIRE_THROWS_WITH(p.toSE3(), Contains("exceptional 3-plane"));
        continue;
      }
      CHECK(!p.inExceptionalPlane());
      const Mat4<S> back = p.toSE3().matrix();
      CHECK(maxAbs(Mat4<S>(back - m)) <= S(16) * eps * (S(1) + len));
      CHECK(maxAbs(Mat4<S>(StudyParameters<S>::fromMatrix(m).matrix() - m)) <=
            S(16) * eps * (S(1) + len));
      CHECK(StudyParameters<S>::fromSE3(g).isApprox(p, S(0)));
      // Through the dual quaternion again: same coefficients (a·a = 1 already).
      CHECK(p.toDualQuaternion().isApprox(h, S(4) * eps * (S(1) + len)));
    }
}

TEMPLATE_TEST_CASE("Study condition holds on motions and fails off the quadric", "[study]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::sqrt;
  auto& g = test::rng(21);
  const S eps = Tolerance<S>::epsilon();
  const S tol = Tolerance<S>::input();
  int offQuadric = 0;
  for (int i = 0; i < randomCount<S>(); ++i) {
    // A product of three motions (a short serial chain), so rounding has accumulated.
    const SE3<S> x = SE3<S>::Random(g) * SE3<S>::Random(g) * SE3<S>::Random(g);
    const StudyParameters<S> p = StudyParameters<S>::fromDualQuaternion(
        DualQuaternion<S>::fromSE3(SE3<S>::Random(g)) * DualQuaternion<S>::fromSE3(x));
    // GF-9.3-study-quadric: a0c0 + a1c1 + a2c2 + a3c3 = 0 on every image of a motion.
    CHECK(abs(p.studyCondition()) <= S(16) * eps * p.a().norm() * p.c().norm());
    CHECK(p.studyDefect() <= S(16) * eps);
    CHECK(p.onStudyQuadric());
    // Perturb c along a by δ|c|: the defect is δ/√(1 + δ²), computed exactly as expected.
    const Vec4<S> ahat = p.a() / p.a().norm();
    for (const S& delta : {S(4) * tol, tol / S(4)}) {
      const StudyParameters<S> q(p.a(), Vec4<S>(p.c() + delta * p.c().norm() * ahat));
      CHECK(abs(q.studyDefect() - delta / sqrt(S(1) + delta * delta)) <= S(64) * eps);
      if (delta > tol) {
        CHECK(!q.onStudyQuadric());
        REQUIRE_THROWS_WITH(StudyParameters<S>::fromCoordinates(q.coeffs()),
                            Contains("off the Study quadric"));
        REQUIRE_THROWS_WITH(q.toSE3(), Contains("off the Study quadric"));
      } else {
        // Accepted, never projected: fromCoordinates keeps the coordinates as given; the motion
        // is within the defect of the original (the component along a does not move points).
        CHECK(q.onStudyQuadric());
        CHECK(maxAbs(Vec8<S>(StudyParameters<S>::fromCoordinates(q.coeffs()).coeffs() - q.coeffs())) == S(0));
        CHECK(q.toSE3().isApprox(p.toSE3(), S(64) * eps * (S(1) + p.c().norm())));
      }
    }
    // A random point of PR⁷ is off the quadric (a·c = 0 has measure zero). Judged at 1000 eps:
    // Tolerance::input() is 64√eps (0.022 in float), so about 2% of random float points would
    // pass the input test.
    const StudyParameters<S> r(test::uniformVec<S, 8>(g));
    if (!r.onStudyQuadric(S(1000) * eps)) ++offQuadric;
  }
  CHECK(offQuadric == randomCount<S>());
}

TEMPLATE_TEST_CASE("Study exceptional 3-plane a = 0: in the quadric, not a motion", "[study]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(22);
  const S eps = Tolerance<S>::epsilon();
  for (int i = 0; i < 10; ++i) {
    const StudyParameters<S> p(Vec4<S>::Zero(), test::uniformVec<S, 4>(g));
    CHECK(p.inExceptionalPlane());
    CHECK(p.onStudyQuadric());  // the 3-plane lies in the quadric (GF §9.3, seed 5716)
    REQUIRE_THROWS_WITH(p.toSE3(), Contains("exceptional 3-plane"));
    REQUIRE_THROWS_WITH(StudyParameters<S>::fromCoordinates(p.coeffs()),
                        Contains("not a rigid motion"));
    REQUIRE_THROWS_WITH(p.normalized(), Contains("exceptional 3-plane"));
  }
  // Both sides of the threshold |a| = eps·|v|: a translation of T along a unit direction has
  // |a|/|v| = 1/√(1 + T²/4) ≈ 2/T.
  const SO3<S> r = SO3<S>::fromAxisAngle(Vec3<S>(S(0), S(0), S(1)), S(1) / S(3));
  const Vec3<S> dir = Vec3<S>(S(2), S(3), S(6)) / S(7);
  const S inside = S(1) / eps;     // |a|/|v| ≈ 2 eps: a motion
  const S outside = S(8) / eps;    // |a|/|v| ≈ eps/4: numerically exceptional
  const StudyParameters<S> pin = StudyParameters<S>::fromSE3(SE3<S>(r, Vec3<S>(inside * dir)));
  const StudyParameters<S> pout = StudyParameters<S>::fromSE3(SE3<S>(r, Vec3<S>(outside * dir)));
  CHECK(!pin.inExceptionalPlane());
  const SE3<S> back = pin.toSE3();
  CHECK(back.so3().isApprox(r, S(16) * eps));
  CHECK(maxAbs(Vec3<S>(back.translation() - inside * dir)) <= S(16) * eps * inside);
  CHECK(pout.inExceptionalPlane());
  REQUIRE_THROWS_WITH(pout.toSE3(), Contains("exceptional 3-plane"));
}

TEMPLATE_TEST_CASE("Study points are projective: λv and the 2-to-1 cover give one motion",
                   "[study]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = test::rng(23);
  const S eps = Tolerance<S>::epsilon();
  for (int i = 0; i < randomCount<S>(); ++i) {
    const SE3<S> x = SE3<S>::Random(g);
    const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(x);
    const StudyParameters<S> p = StudyParameters<S>::fromDualQuaternion(h);
    // g and −g: two dual quaternions, one point of PR⁷, one motion.
    const StudyParameters<S> q = StudyParameters<S>::fromDualQuaternion(-h);
    CHECK(maxAbs(Vec8<S>(q.coeffs() + p.coeffs())) == S(0));
    CHECK(q.isApprox(p, S(0)));
    CHECK(q.toSE3().isApprox(x, S(16) * eps));
    for (const S& lambda : {S(-1), S(7) / S(2), S(-1) / S(1000), S(100000)}) {
      const StudyParameters<S> s(Vec8<S>(lambda * p.coeffs()));
      CHECK(s.isApprox(p, S(4) * eps));
      CHECK(s.toSE3().isApprox(x, S(16) * eps));
      // normalized(): a·a = 1 with a positive factor (the sign of λ is kept).
      const StudyParameters<S> n = s.normalized();
      CHECK(abs(n.a().squaredNorm() - S(1)) <= S(8) * eps);
      CHECK(maxAbs(Vec8<S>(n.coeffs() - (lambda > S(0) ? S(1) : S(-1)) * p.coeffs())) <=
            S(8) * eps);
    }
    // GF-11.5.4 (seed 7274): t = 2 h1 h0* = −2 h0 h1* for the normalised point.
    const DualQuaternion<S> u = p.toDualQuaternion();
    const Quat<S> t1 = quaternionProduct(u.dual(), u.real().conjugate());
    const Quat<S> t2 = quaternionProduct(u.real(), u.dual().conjugate());
    CHECK(maxAbs(Vec3<S>(S(2) * t1.vec() - x.translation())) <= S(16) * eps);
    CHECK(maxAbs(Vec3<S>(S(-2) * t2.vec() - x.translation())) <= S(16) * eps);
  }
}

TEMPLATE_TEST_CASE("Study parameters reproduce the book's §11.4 examples", "[study]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  auto& g = test::rng(24);
  const S tol = S(32) * Tolerance<S>::epsilon();
  const Quat<S> k(S(0), S(0), S(0), S(1));
  for (int i = 0; i < 10; ++i) {
    const S th = test::uniform<S>(g, -3, 3), t = test::uniform<S>(g, -2, 2);
    const S c = cos(th / S(2)), s = sin(th / S(2));
    // GF-11.4-line-isotropy-quadric (seed 7007): (cos θ/2 + k sin θ/2)(1 + (t/2)kε)
    // = (cos θ/2 + k sin θ/2) + ((t/2) cos θ/2 k − (t/2) sin θ/2)ε.
    const DualQuaternion<S> rot(Quat<S>(c, S(0), S(0), s), Quat<S>(S(0), S(0), S(0), S(0)));
    const DualQuaternion<S> slide(Quat<S>(S(1), S(0), S(0), S(0)), Quat<S>(S(0), S(0), S(0), t / S(2)));
    Vec8<S> printed;
    printed << c, S(0), S(0), s, -t / S(2) * s, S(0), S(0), t / S(2) * c;
    const DualQuaternion<S> prod = rot * slide;
    CHECK(maxAbs(Vec8<S>(prod.coeffs() - printed)) <= tol);
    // It is the screw motion about the z-axis: rotation θ, translation t along z.
    const SE3<S> screw(SO3<S>::fromAxisAngle(Vec3<S>(S(0), S(0), S(1)), th), Vec3<S>(S(0), S(0), t));
    CHECK(StudyParameters<S>::fromSE3(screw).isApprox(StudyParameters<S>(printed), tol));
    // It lies in the 3-plane a1 = a2 = c1 = c2 = 0, on the conic a0c0 + a3c3 = 0.
    CHECK(printed(1) == S(0));
    CHECK(printed(2) == S(0));
    CHECK(abs(printed(0) * printed(4) + printed(3) * printed(7)) <= tol);
  }
  // Erratum 1 (seed 7009): "the line at infinity a2 = a3 = 0" contains (1:0:0:0:0:0:0:1), which
  // is a motion of the subgroup (translation by 2 along z); the line at infinity is a0 = a3 = 0.
  Vec8<S> e;
  e << S(1), S(0), S(0), S(0), S(0), S(0), S(0), S(1);
  const SE3<S> two = StudyParameters<S>::fromCoordinates(e).toSE3();
  CHECK(two.isApprox(SE3<S>(SO3<S>(), Vec3<S>(S(0), S(0), S(2))), tol));
  Vec8<S> inf;
  inf << S(0), S(0), S(0), S(0), S(3), S(0), S(0), S(-5);
  CHECK(StudyParameters<S>(inf).inExceptionalPlane());
  REQUIRE_THROWS_WITH(StudyParameters<S>(inf).toSE3(), Contains("exceptional 3-plane"));

  // GF-11.4-2R-three-plane (seed 7011–7037): e^{θ1 s1} e^{θ2 s2} with s1 the z-axis and s2 the
  // line through (l, 0, 0) with direction (0, −sin α, cos α) (moment q × ω).
  for (int i = 0; i < 10; ++i) {
    const S t1 = test::uniform<S>(g, -3, 3), t2 = test::uniform<S>(g, -3, 3);
    const S l = test::uniform<S>(g, -2, 2), al = test::uniform<S>(g, -3, 3);
    const Vec3<S> w2(S(0), -sin(al), cos(al));
    const Vec3<S> v2 = Vec3<S>(l, S(0), S(0)).cross(w2);
    const DualQuaternion<S> e1 =
        DualQuaternion<S>::exp(SE3Tangent<S>(Vec3<S>(S(0), S(0), t1), Vec3<S>::Zero()));
    const DualQuaternion<S> e2 = DualQuaternion<S>::exp(SE3Tangent<S>(Vec3<S>(t2 * w2), Vec3<S>(t2 * v2)));
    const S c1 = cos(t1 / S(2)), s1 = sin(t1 / S(2)), c2 = cos(t2 / S(2)), s2 = sin(t2 / S(2));
    const S ca = cos(al), sa = sin(al);
    // The printed factors.
    Vec8<S> f2;
    f2 << c2, S(0), -s2 * sa, s2 * ca, S(0), S(0), -l * s2 * ca, -l * s2 * sa;
    CHECK(maxAbs(Vec8<S>(e2.coeffs() - f2)) <= tol);
    // The printed product coefficients.
    Vec8<S> book;
    book << c1 * c2 - s1 * s2 * ca, s1 * s2 * sa, -c1 * s2 * sa, s1 * c2 + c1 * s2 * ca,
        l * s1 * s2 * sa, l * s1 * s2 * ca, -l * c1 * s2 * ca, -l * c1 * s2 * sa;
    const StudyParameters<S> p = StudyParameters<S>::fromDualQuaternion(e1 * e2);
    CHECK(maxAbs(Vec8<S>(p.coeffs() - book)) <= tol);
    // The four linear equations of the three-plane, and the Study condition.
    const Vec8<S>& v = p.coeffs();
    CHECK(abs(l * v(2) - v(7)) <= tol);
    CHECK(abs(l * v(1) - v(4)) <= tol);
    CHECK(abs(l * v(1) * ca - v(5) * sa) <= tol);
    CHECK(abs(l * v(2) * ca - v(6) * sa) <= tol);
    CHECK(p.onStudyQuadric(tol));
  }
}

TEMPLATE_TEST_CASE("Study parameters reject bad input with a clear message", "[study]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  Vec8<S> v = StudyParameters<S>::fromSE3(SE3<S>(SO3<S>(), Vec3<S>(S(1), S(0), S(0)))).coeffs();
  v(3) = nan;
  REQUIRE_THROWS_AS(StudyParameters<S>::fromCoordinates(v), InvalidInput);
  REQUIRE_THROWS_WITH(StudyParameters<S>::fromCoordinates(v), Contains("NaN"));
  REQUIRE_THROWS_WITH(StudyParameters<S>(v).toSE3(), Contains("NaN"));
  CHECK(!StudyParameters<S>(v).onStudyQuadric());
  REQUIRE_THROWS_WITH(StudyParameters<S>::fromCoordinates(Vec8<S>::Zero()), Contains("zero vector"));
  Vec8<S> off;
  off << S(1), S(0), S(0), S(0), S(1), S(0), S(0), S(0);  // a·c = 1: off the quadric
  REQUIRE_THROWS_WITH(StudyParameters<S>::fromCoordinates(off), Contains("off the Study quadric"));
  REQUIRE_THROWS_WITH(StudyParameters<S>(off).normalized(), Contains("off the Study quadric"));
  Mat4<S> bad = Mat4<S>::Identity();
  bad(3, 0) = S(1) / S(2);
  REQUIRE_THROWS_WITH(StudyParameters<S>::fromMatrix(bad), Contains("last row"));
}

}  // namespace SOMA_UNITY_ID
