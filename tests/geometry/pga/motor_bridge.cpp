// GF §9.2–9.3: motors as g + ½tg𝐞 built in the algebra; dual quaternion, Study parameter and SE3
// round trips; exp/log; composition; bad input.
#include "pga_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using namespace soma::test::pga;
using Catch::Matchers::Contains;

TEMPLATE_TEST_CASE("pga motors: g + ½tg𝐞 in the algebra, round trips, exp/log, composition",
                   "[pga][motor]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = rng(1103);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 2 : 20;
  for (int t = 0; t < trials; ++t) {
    const SE3<S> m(SO3<S>::Random(g), rvec<S>(g, 3));
    const Motor<S> h = Motor<S>::fromSE3(m);
    // The book's element built from Clifford products: g = a0 + a1 e2e3 + a2 e3e1 + a3 e1e2,
    // t = t1e1 + t2e2 + t3e3, h = g + ½ t g 𝐞 (GF §9.3); independent of the ε map.
    const Quat<S>& q = m.quaternion();
    EvenElement<S> gg(q.w());
    setBookCoeff(gg, basis::e23, q.x());
    setBookCoeff(gg, basis::e31, q.y());
    setBookCoeff(gg, basis::e12, q.z());
    const Grade1<S> tv = Plane<S>(m.translation(), S(0)).element();
    const auto E = Grade1<S>::basisBlade(basis::e.mask);
    const EvenElement<S> book(gg + EvenElement<S>((tv * gg * E) * (S(1) / S(2))));
    CHECK(clifford::maxAbsDiff(book, h.element()) <= tol<S>(64));
    // hh* = 1 and h* = h⁻¹.
    const auto [n0, n4] = h.normSquared();
    CHECK(abs(n0 - S(1)) <= tol<S>());
    CHECK(abs(n4) <= tol<S>(64));
    CHECK((h * h.conjugate()).sameMotion(Motor<S>(), tol<S>(64)));
    // Round trips: SE3, dual quaternion, Study parameters (homogeneous, scaled by −7).
    CHECK(h.toSE3().isApprox(m, tol<S>(256)));
    const DualQuaternion<S> dq = DualQuaternion<S>::fromSE3(m);
    CHECK(h.toDualQuaternion().isApprox(dq, tol<S>()));
    CHECK(Motor<S>::fromDualQuaternion(dq).isApprox(h, S(0)));
    const StudyParameters<S> sp(Vec8<S>(h.toStudyParameters().coeffs() * S(-7)));
    CHECK(Motor<S>::fromStudyParameters(sp).sameMotion(h, tol<S>()));
    CHECK(h.toStudyParameters().isApprox(StudyParameters<S>::fromSE3(m), tol<S>()));
    // Composition is the geometric product.
    const SE3<S> m2(SO3<S>::Random(g), rvec<S>(g, 3));
    CHECK((h * Motor<S>::fromSE3(m2)).toSE3().isApprox(m * m2, tol<S>(512)));
    // exp(½B(ξ)) = SE3Tangent::exp and DualQuaternion::exp; log ∘ exp = id (θ < π).
    SE3Tangent<S> xi(uniformVec<S, 6>(g, -1, 1));
    const Motor<S> ex = Motor<S>::exp(xi);
    CHECK(ex.toSE3().isApprox(xi.exp(), tol<S>(512)));
    CHECK(ex.isApprox(Motor<S>::fromDualQuaternion(DualQuaternion<S>::exp(xi)), tol<S>(256)));
    CHECK(ex.log().isApprox(xi, tol<S>(1024)));
    CHECK(Motor<S>::exp(h.log()).sameMotion(h, tol<S>(1024)));
  }
  // Extremes: pure translation (θ = 0), θ = 1e-8, θ = π − 1e-8.
  for (const double th : {0.0, 1e-8, 3.141592653589793 - 1e-8}) {
    const Vec3<S> axis = unitVec3<S>(g);
    const SE3Tangent<S> xi(Vec3<S>(axis * scalarCast<S>(th)), rvec<S>(g));
    CHECK(Motor<S>::exp(xi).toSE3().isApprox(xi.exp(), tol<S>(512)));
  }
  // Rotation about a line: cos(θ/2) + sin(θ/2)ℓ = exp(θℓ/2) = rotation about the axis.
  const Vec3<S> q = rvec<S>(g), v = unitVec3<S>(g);
  const S th = uniform<S>(g, -3, 3);
  const Line<S> l = Line<S>::throughPoint(q, v);
  const Motor<S> a = Motor<S>::rotationAbout(l, th);
  CHECK(a.isApprox(Motor<S>::exp(l * (th / S(2))), tol<S>(64)));
  const Vec3<S> x = rvec<S>(g);
  const Vec3<S> ref = q + SO3<S>::fromAxisAngle(v, th).act(Vec3<S>(x - q));
  CHECK(maxDiff<S>(a(Point<S>(x)).position(), ref) <= tol<S>(512));
  CHECK(Motor<S>::translation(x).toSE3().isApprox(SE3<S>(SO3<S>::Identity(), x), tol<S>()));
}

TEMPLATE_TEST_CASE("pga motors: bad input", "[pga][motor]", float, double) {
  using S = TestType;
  using std::abs;
  // Not on the Study quadric, both sides of Tolerance::input().
  Motor<S> h = Motor<S>::translation(Vec3<S>(S(1), S(0), S(0)));
  EvenElement<S> e = h.element();
  setBookCoeff(e, basis::e123e, S(4) * Tolerance<S>::input());  // Study defect ≈ 4·input/|c|
  CHECK_FALSE(Motor<S>(e).isUnit());
  CHECK_THROWS_WITH(Motor<S>(e).toSE3(), Contains("not a unit motor"));
  setBookCoeff(e, basis::e123e, Tolerance<S>::input() / S(4));
  CHECK(Motor<S>(e).isUnit());
  CHECK_NOTHROW(Motor<S>(e).toSE3());
  // Scale: |a| = 2.
  CHECK_THROWS_AS(Motor<S>(EvenElement<S>(S(2))).toSE3(), InvalidInput);
  // A non-unit axis for rotationAbout.
  CHECK_THROWS_WITH(Motor<S>::rotationAbout(Line<S>(Vec3<S>(S(2), S(0), S(0)), Vec3<S>::Zero()), S(1)),
                    Contains("not a unit line"));
}

}  // namespace SOMA_UNITY_ID
