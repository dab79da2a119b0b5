// Dual quaternions (GF §9.3): the book's expansion of g + ½tge, the homomorphism to SE(3), the
// point and adjoint actions (erratum E9.3), the three conjugates and the dual norm, exp against
// SE3::exp, against the power series and against the book's dual-angle formula, log against
// SE3::log and a 512-bit reference, ScLERP = SE3::interpolate, the 2-to-1 cover, bad input.
#include "soma/algebra/dual_quaternion.hpp"
#include "support/scalars.hpp"

#include <vector>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using Catch::Matchers::Contains;

namespace {

template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }

struct MpfrBits {
  int old;
  explicit MpfrBits(int bits) : old(mpfrBits()) { setMpfrBits(bits); }
  ~MpfrBits() { setMpfrBits(old); }
};

/// The value of x as a 512-bit mpreal (exact).
template <class S> mpreal ref(const S& x) {
  mpreal r = scalarCast<mpreal>(x);
  r.setPrecision(512);
  return r;
}
template <class S, int N> Eigen::Matrix<mpreal, N, 1> refVec(const Eigen::Matrix<S, N, 1>& v) {
  Eigen::Matrix<mpreal, N, 1> r;
  for (int i = 0; i < N; ++i) r(i) = ref(v(i));
  return r;
}

/// Rotation angles every test walks through: 0, 1e-8, both sides of the Taylor switch of the
/// half angle (φ² < precision(3)²), ordinary, π − 1e-8, π, beyond π and beyond 2π.
template <class S> std::vector<S> edgeAngles() {
  const S thr = S(2) * Tolerance<S>::precision(3);  // θ at which φ = θ/2 crosses the switch
  const S p = pi<S>();
  return {S(0), S(1e-8), thr / S(2), S(2) * thr, S(7) / S(10), p - S(1e-8), p, S(4), S(7)};
}
template <class S> std::vector<S> edgeLengths() { return {S(0), S(1e-8), S(1), S(1000)}; }

/// A twist of rotation angle θ and linear part of length len, in a fixed generic direction.
template <class S> SE3Tangent<S> edgeTwist(const S& th, const S& len) {
  const Vec3<S> u = Vec3<S>(S(2), S(-3), S(6)) / S(7);   // unit
  const Vec3<S> w = Vec3<S>(S(6), S(3), S(2)) / S(7);    // unit, u·w = 15/49: pitch ≠ 0
  return SE3Tangent<S>(Vec3<S>(th * u), Vec3<S>(len * w));
}

/// The book's expansion of g + ½tge (GF §9.3, seed 5696), written out coefficient by coefficient.
template <class S> Vec8<S> bookExpansion(const Quat<S>& a, const Vec3<S>& b) {
  const S h = S(1) / S(2);
  Vec8<S> v;
  v << a.w(), a.x(), a.y(), a.z(), -h * (a.x() * b(0) + a.y() * b(1) + a.z() * b(2)),
      h * (a.w() * b(0) - a.y() * b(2) + a.z() * b(1)),
      h * (a.w() * b(1) + a.x() * b(2) - a.z() * b(0)),
      h * (a.w() * b(2) - a.x() * b(1) + a.y() * b(0));
  return v;
}

template <class S> DualQuaternion<S> randomDQ(std::mt19937_64& g) {
  return DualQuaternion<S>(test::uniformVec<S, 8>(g));
}

template <class S> int randomCount() { return std::is_same_v<S, mpreal> ? 10 : 100; }

}  // namespace

TEMPLATE_TEST_CASE("DQ of a motion is the book's expansion of g + ½tge", "[dualquat]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(11);
  const S eps = Tolerance<S>::epsilon();
  for (int i = 0; i < randomCount<S>(); ++i) {
    const SE3<S> m = SE3<S>::Random(g);
    const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(m);
    // GF-9.3-dual-quaternion-isomorphism: the eight printed coefficients.
    CHECK(maxAbs(Vec8<S>(h.coeffs() - bookExpansion(m.quaternion(), m.translation()))) <= S(4) * eps);
    // GF-9.3-study-quadric: h1 h0* = −h0 h1* = t/2, so h1 h0* − h0 h1* = t (seed 5728–5730).
    const Quat<S> c = h.dual(), a = h.real();
    const Quat<S> ca = quaternionProduct(c, a.conjugate()), ac = quaternionProduct(a, c.conjugate());
    CHECK(maxAbs(Vec4<S>(ca.coeffs() + ac.coeffs())) <= S(8) * eps);
    CHECK(maxAbs(Vec3<S>(ca.vec() - ac.vec() - m.translation())) <= S(8) * eps);
    // ȟȟ* = 1 (h0h0* = 1 and h0h1* + h1h0* = 0).
    const DualQuaternion<S> n = h * h.conjugate();
    CHECK(n.isApprox(DualQuaternion<S>::Identity(), S(8) * eps));
    CHECK(h.squaredNorm().isApprox(DualNumber<S>(S(1), S(0)), S(8) * eps));
    CHECK(h.isUnit());
    CHECK(h.toSE3().isApprox(m, S(8) * eps));
    CHECK(maxAbs(Mat4<S>(h.matrix() - m.matrix())) <= S(8) * eps);
    CHECK(DualQuaternion<S>::fromMatrix(m.matrix()).sameMotion(h, S(16) * eps));
  }
}

TEMPLATE_TEST_CASE("DQ product is the SE3 composition (homomorphism)", "[dualquat]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  auto& g = test::rng(12);
  const S tol = S(16) * Tolerance<S>::epsilon();
  for (int i = 0; i < randomCount<S>(); ++i) {
    const SE3<S> x = SE3<S>::Random(g), y = SE3<S>::Random(g);
    const DualQuaternion<S> hx = DualQuaternion<S>::fromSE3(x), hy = DualQuaternion<S>::fromSE3(y);
    const DualQuaternion<S> hxy = hx * hy;
    // Same sign, not only the same motion: the real part is the quaternion product.
    CHECK(hxy.isApprox(DualQuaternion<S>::fromSE3(x * y), tol));
    CHECK(hxy.toSE3().isApprox(x * y, tol));
    // Inverse: the conjugate of a unit dual quaternion, and the motion's inverse.
    CHECK(hx.inverse().isApprox(hx.conjugate(), tol));
    CHECK(hx.inverse().toSE3().isApprox(x.inverse(), tol));
    // Associativity in H ⊗ D on general (non-unit) elements, and the general inverse.
    const DualQuaternion<S> p = randomDQ<S>(g), q = randomDQ<S>(g), r = randomDQ<S>(g);
    CHECK(((p * q) * r).isApprox(p * (q * r), S(4) * tol));
    const DualQuaternion<S> pi = p.inverse();
    const S cond = S(1) + p.coeffs().squaredNorm() / p.real().coeffs().squaredNorm();
    CHECK((p * pi).isApprox(DualQuaternion<S>::Identity(), tol * cond * cond));
    CHECK((pi * p).isApprox(DualQuaternion<S>::Identity(), tol * cond * cond));
    // The three conjugates: the book's ȟ* and the full conjugate reverse products, the dual
    // conjugate (an automorphism) keeps the order.
    CHECK((p * q).conjugate().isApprox(q.conjugate() * p.conjugate(), tol));
    CHECK((p * q).fullConjugate().isApprox(q.fullConjugate() * p.fullConjugate(), tol));
    CHECK((p * q).dualConjugate().isApprox(p.dualConjugate() * q.dualConjugate(), tol));
    CHECK(p.fullConjugate().isApprox(p.conjugate().dualConjugate(), S(0)));
    // ȟȟ* is the dual number |a|² + ε2a·c, multiplicative; the norm is its square root.
    const DualQuaternion<S> pp = p * p.conjugate();
    const DualNumber<S> n2 = p.squaredNorm();
    CHECK(abs(pp.real().w() - n2.re) <= tol);
    CHECK(abs(pp.dual().w() - n2.du) <= tol);
    CHECK(maxAbs(Vec3<S>(pp.real().vec())) <= tol);
    CHECK(maxAbs(Vec3<S>(pp.dual().vec())) <= tol);
    CHECK((p * q).squaredNorm().isApprox(p.squaredNorm() * q.squaredNorm(), S(8) * tol));
    const DualNumber<S> nn = p.norm();
    CHECK((nn * nn).isApprox(n2, tol));
  }
}

TEMPLATE_TEST_CASE("DQ acts on points and twists as SE3 does (erratum E9.3)", "[dualquat]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(13);
  const S tol = S(32) * Tolerance<S>::epsilon();
  for (int i = 0; i < randomCount<S>(); ++i) {
    const SE3<S> m = SE3<S>::Random(g);
    const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(m);
    const Vec3<S> x = test::uniformVec<S, 3>(g);
    CHECK(maxAbs(Vec3<S>(h.act(x) - m.act(x))) <= tol);
    // The sandwich itself: ȟ(1 + εx)(a* − εc*) = 1 + ε(Rx + t) (GF §9.3, seed 5722).
    const DualQuaternion<S> px(Quat<S>(S(1), S(0), S(0), S(0)), Quat<S>(S(0), x.x(), x.y(), x.z()));
    const DualQuaternion<S> s = h * px * h.fullConjugate();
    Vec8<S> expected = Vec8<S>::Zero();
    expected(0) = S(1);
    expected.template tail<3>() = m.act(x);
    CHECK(maxAbs(Vec8<S>(s.coeffs() - expected)) <= tol);
    // Homogeneous: λȟ moves points as ȟ does (λ = −2.5 also shows the 2-to-1 cover).
    CHECK(maxAbs(Vec3<S>((h * S(-2.5)).act(x) - m.act(x))) <= tol);
    // Adjoint on twists ½ω + ε½v: ȟ(·)ȟ* = Ad(g) = [[R, 0], [TR, R]] (corrected E9.3).
    const SE3Tangent<S> xi(test::uniformVec<S, 6>(g));
    const Vec6<S> ad = m.adjoint() * xi.coeffs();
    CHECK(maxAbs(Vec6<S>(h.adjoint(xi).coeffs() - ad)) <= tol);
    // The printed dual part R v0 + R v1 × t (seed 5768) is not the adjoint (erratum E9.3).
    const Mat3<S> R = m.rotation();
    const Vec3<S> printed = R * xi.ang() + (R * xi.lin()).cross(m.translation());
    CHECK(maxAbs(Vec3<S>(printed - ad.template tail<3>())) > S(1) / S(1000));
  }
}

TEMPLATE_TEST_CASE("DQ exp equals SE3 exp and a 512-bit reference at the edges", "[dualquat]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const S eps = Tolerance<S>::epsilon();
  for (const S& th : edgeAngles<S>())
    for (const S& len : edgeLengths<S>()) {
      const SE3Tangent<S> xi = edgeTwist(th, len);
      INFO("theta = " << toString(th) << ", |v| = " << toString(len));
      const DualQuaternion<S> h = DualQuaternion<S>::exp(xi);
      const S scale = S(1) + len;
      // Two methods: the closed form in H ⊗ D and SE3Tangent::exp (Rodrigues + left Jacobian),
      // taken to a dual quaternion with c = ½ta. Same sign (both are the Spin exponential).
      CHECK(h.isApprox(DualQuaternion<S>::fromSE3(xi.exp()), S(32) * eps * scale));
      // Reference: the same closed form at 512 bits, from the exact same input.
      Vec8<S> expected;
      {
        MpfrBits bits(512);
        const SE3Tangent<mpreal> x512(refVec(xi.coeffs()));
        expected = castMatrix<S>(DualQuaternion<mpreal>::exp(x512).coeffs());
      }
      CHECK(maxAbs(Vec8<S>(h.coeffs() - expected)) <= S(8) * eps * (S(1) + len * (S(1) + th)));
    }
}

TEST_CASE("DQ exp is the power series of ½ω + ε½v and the book's dual-angle formula", "[dualquat]") {
  using S = mpreal;
  auto& g = test::rng(14);
  const S tol = S(1e4) * Tolerance<S>::epsilon();
  for (int i = 0; i < 6; ++i) {
    const SE3Tangent<S> xi(test::uniformVec<S, 6>(g, -2, 2));
    // Σ ŝᵏ/k! in H ⊗ D (GF §9.3: the Lie algebra is the pure dual quaternions).
    const DualQuaternion<S> s = DualQuaternion<S>::hat(xi);
    DualQuaternion<S> term, sum;
    for (int k = 1; k < 120; ++k) {
      term = term * s * (S(1) / S(k));
      sum = sum + term;
    }
    CHECK(DualQuaternion<S>::exp(xi).isApprox(sum, tol));
    CHECK(s.vee().isApprox(xi, S(0)));
  }
  // The book's e^{θ̌v̌/2} = cos(θ̌/2) + sin(θ̌/2)v̌ with θ̌ = θ + εp and the line v̌ = v0 + εv1
  // (v0 unit, v1 = r × v0), and t = sin θ v1 + (1 − cos θ) v0 × v1 + p v0 (GF-9.3-exp-log).
  const Vec3<S> v0 = Vec3<S>(S(1), S(-4), S(8)) / S(9);
  const Vec3<S> r(S(3) / S(10), S(-11) / S(10), S(7) / S(10));
  const Vec3<S> v1 = r.cross(v0);
  for (const S& th : {S(4) / S(10), S(29) / S(10), S(55) / S(10)})
    for (const S& p : {S(0), S(-6) / S(10), S(13) / S(10)}) {
      const DualNumber<S> half(th / S(2), p / S(2));
      const DualNumber<S> c = half.cos(), sn = half.sin();
      // (c + sn v̌) = c.re + sn.re v0 + ε(c.du + sn.re v1 + sn.du v0).
      const Vec3<S> av = sn.re * v0, cv = sn.re * v1 + sn.du * v0;
      const DualQuaternion<S> book(Quat<S>(c.re, av.x(), av.y(), av.z()),
                                   Quat<S>(c.du, cv.x(), cv.y(), cv.z()));
      const SE3Tangent<S> xi(Vec3<S>(th * v0), Vec3<S>(th * v1 + p * v0));
      const DualQuaternion<S> h = DualQuaternion<S>::exp(xi);
      CHECK(h.isApprox(book, tol));
      using std::cos;
      using std::sin;
      const Vec3<S> t = sin(th) * v1 + (S(1) - cos(th)) * v0.cross(v1) + p * v0;
      CHECK(maxAbs(Vec3<S>(h.translation() - t)) <= tol);
      // The axis point r is fixed up to the slide p along v0: (I − R) r + p v0 = t.
      CHECK(maxAbs(Vec3<S>(h.act(r) - r - p * v0)) <= tol);
    }
}

TEMPLATE_TEST_CASE("DQ log inverts exp and agrees with SE3 log and a 512-bit reference",
                   "[dualquat]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  const S eps = Tolerance<S>::epsilon();
  for (const S& th : edgeAngles<S>())
    for (const S& len : edgeLengths<S>()) {
      const SE3Tangent<S> xi = edgeTwist(th, len);
      INFO("theta = " << toString(th) << ", |v| = " << toString(len));
      const DualQuaternion<S> h = DualQuaternion<S>::exp(xi);
      const SE3Tangent<S> back = h.log();
      const S scale = S(1) + len;
      // exp(log h) = h as a motion (at θ = π and beyond, log picks the other sign / branch).
      CHECK(DualQuaternion<S>::exp(back).sameMotion(h, S(32) * eps * scale));
      // Where θ (as rounded in S) is below π, i.e. a0 = cos(θ/2) > 0, the round trip
      // twist → DQ → twist returns ξ itself (this includes θ = π − 1e-8 and, in double, θ = π
      // rounded down; in float both round above π and log returns the other branch).
      if (h.real().w() > S(0)) CHECK(back.isApprox(xi, S(32) * eps * scale));
      // Two methods: SE3::log of the motion (log R and Jl⁻¹ t) against the dual-angle inverse.
      CHECK(back.isApprox(h.toSE3().log(), S(64) * eps * scale));
      // Reference: the same log at 512 bits. h is unit only to the precision of S, so the
      // reference first does what log() does: scale to a·a = 1 and drop the component of c
      // along a (the Study defect of the rounded input).
      Vec6<S> expected;
      {
        MpfrBits bits(512);
        const Vec8<mpreal> v = refVec(h.coeffs());
        Vec4<mpreal> a = v.head<4>(), c = v.tail<4>();
        const mpreal n = sqrt(a.squaredNorm());
        a /= n;
        c /= n;
        c -= a.dot(c) * a;
        Vec8<mpreal> u;
        u << a, c;
        expected = castMatrix<S>(DualQuaternion<mpreal>(u).log().coeffs());
      }
      CHECK(maxAbs(Vec6<S>(back.coeffs() - expected)) <= S(32) * eps * scale);
    }
}

TEMPLATE_TEST_CASE("ScLERP equals SE3::interpolate", "[dualquat]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(15);
  const S tol = S(64) * Tolerance<S>::epsilon();
  const std::vector<S> ts = {S(0), S(1) / S(4), S(1) / S(2), S(9) / S(10), S(1), S(3) / S(2)};
  for (int i = 0; i < randomCount<S>(); ++i) {
    const SE3<S> x = SE3<S>::Random(g), y = SE3<S>::Random(g);
    const DualQuaternion<S> hx = DualQuaternion<S>::fromSE3(x), hy = DualQuaternion<S>::fromSE3(y);
    for (const S& t : ts) {
      const DualQuaternion<S> h = DualQuaternion<S>::sclerp(hx, hy, t);
      CHECK(h.toSE3().isApprox(SE3<S>::interpolate(x, y, t), S(4) * tol));
      CHECK(h.isUnit(tol));
    }
    CHECK(DualQuaternion<S>::sclerp(hx, hy, S(0)).sameMotion(hx, tol));
    CHECK(DualQuaternion<S>::sclerp(hx, hy, S(1)).sameMotion(hy, tol));
    // The path does not depend on the sign of either end (shortest screw path).
    CHECK(DualQuaternion<S>::sclerp(-hx, hy, S(1) / S(3))
              .sameMotion(DualQuaternion<S>::sclerp(hx, -hy, S(1) / S(3)), S(4) * tol));
  }
}

TEMPLATE_TEST_CASE("DQ 2-to-1 cover: h and −h are the same motion", "[dualquat]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(16);
  const S tol = S(16) * Tolerance<S>::epsilon();
  for (int i = 0; i < randomCount<S>(); ++i) {
    const SE3<S> m = SE3<S>::Random(g);
    const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(m), mh = -h;
    CHECK(!mh.isApprox(h, S(1) / S(10)));
    CHECK(mh.sameMotion(h, S(0)));
    CHECK(mh.toSE3().isApprox(m, tol));
    CHECK(maxAbs(Mat4<S>(mh.matrix() - m.matrix())) <= tol);
    CHECK(mh.log().isApprox(h.log(), S(4) * tol));
  }
  // A full turn about any line is −1 (GF-9.3-exp-log, extreme θ = 2π): identity motion.
  const Vec3<S> v0 = Vec3<S>(S(2), S(3), S(6)) / S(7);
  const Vec3<S> v1 = Vec3<S>(S(1), S(-2), S(1) / S(2)).cross(v0);
  const DualQuaternion<S> full =
      DualQuaternion<S>::exp(SE3Tangent<S>(Vec3<S>(S(2) * pi<S>() * v0), Vec3<S>(S(2) * pi<S>() * v1)));
  CHECK(full.isApprox(-DualQuaternion<S>::Identity(), tol));
  CHECK(full.toSE3().isApprox(SE3<S>::Identity(), tol));
}

TEMPLATE_TEST_CASE("DQ rejects bad input with a clear message", "[dualquat]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(
      SE3<S>(SO3<S>::fromAxisAngle(Vec3<S>(S(0), S(0), S(1)), S(1)), Vec3<S>(S(1), S(2), S(3))));
  Vec8<S> v = h.coeffs();
  v(5) = nan;
  REQUIRE_THROWS_AS(DualQuaternion<S>(v).toSE3(), InvalidInput);
  REQUIRE_THROWS_WITH(DualQuaternion<S>(v).toSE3(), Contains("NaN"));
  REQUIRE_THROWS_WITH((h * S(2)).toSE3(), Contains("not a unit quaternion"));
  REQUIRE_THROWS_WITH((h * S(2)).log(), Contains("not a unit quaternion"));
  // Off the quadric: c gets a component along a well beyond Tolerance::input().
  const S d = S(8) * Tolerance<S>::input();
  const DualQuaternion<S> off(h.real(), Quat<S>(Vec4<S>(h.dual().coeffs() + d * S(4) * h.real().coeffs())));
  CHECK(off.studyDefect() > Tolerance<S>::input());
  CHECK(!off.isUnit());
  REQUIRE_THROWS_WITH(off.toSE3(), Contains("off the Study quadric"));
  // Just inside the tolerance it is accepted (and the defect, along a, does not move points).
  const S d2 = Tolerance<S>::input() / S(8);
  const DualQuaternion<S> near(h.real(), Quat<S>(Vec4<S>(h.dual().coeffs() + d2 * S(4) * h.real().coeffs())));
  CHECK(near.isUnit());
  CHECK(near.toSE3().isApprox(h.toSE3(), S(64) * Tolerance<S>::epsilon() * S(8)));
  // a = 0: no inverse, no action.
  const DualQuaternion<S> z(Quat<S>(S(0), S(0), S(0), S(0)), Quat<S>(S(1), S(2), S(3), S(4)));
  REQUIRE_THROWS_WITH(z.inverse(), Contains("a = 0"));
  REQUIRE_THROWS_WITH(z.act(Vec3<S>::Zero()), Contains("a = 0"));
  REQUIRE_THROWS_WITH(z.norm(), Contains("real part must be positive"));
  REQUIRE_THROWS_WITH(DualNumber<S>(S(1)) / DualNumber<S>(S(0), S(1)), Contains("division"));
  Mat4<S> bad = h.matrix();
  bad(0, 0) += S(1) / S(10);
  REQUIRE_THROWS_WITH(DualQuaternion<S>::fromMatrix(bad), Contains("not orthogonal"));
}

}  // namespace SOMA_UNITY_ID
