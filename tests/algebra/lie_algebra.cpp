// Lie-algebra tools (GF §4.3–4.8): Jacobi identity, Killing forms (−2I for so(3), diag(−4I, 0)
// for se(3), erratum E4.10), the CBH series order by order, the dexp series and its printed
// fourth term (erratum E4.9).
#include "soma/algebra/lie_algebra.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using Catch::Matchers::Contains;

namespace {
template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }
}

TEMPLATE_TEST_CASE("Killing forms and the Jacobi identity", "[lie]", SOMA_TEST_SCALARS) {
  using S = TestType;
  // GF-4.7-killing-so3: −2 I₃ exactly.
  CHECK(bool(killingForm<SO3Tangent<S>>() == Mat3<S>(-S(2) * Mat3<S>::Identity())));
  // GF-4.7-killing-se3 (corrected, E4.10): diag(−4 I₃, 0), not the printed −2; rank 3.
  Mat6<S> k6 = Mat6<S>::Zero();
  k6.template topLeftCorner<3, 3>() = -S(4) * Mat3<S>::Identity();
  CHECK(bool(killingForm<SE3Tangent<S>>() == k6));
  // GF-4.3-bracket-structure-constants, GF-4.6-ideals: Jacobi; translations are an ideal.
  auto& g = rng(111);
  const S tol = S(32) * Tolerance<S>::epsilon();
  for (int i = 0; i < 20; ++i) {
    const SE3Tangent<S> a(uniformVec<S, 6>(g)), b(uniformVec<S, 6>(g)), c(uniformVec<S, 6>(g));
    const Vec6<S> jac = bracket(a, bracket(b, c)).coeffs() + bracket(b, bracket(c, a)).coeffs() +
                        bracket(c, bracket(a, b)).coeffs();
    CHECK(maxAbs(jac) <= tol);
    const SE3Tangent<S> trans(Vec3<S>::Zero(), uniformVec<S, 3>(g));
    CHECK(maxAbs(Vec3<S>(bracket(a, trans).ang())) == S(0));
  }
}

TEMPLATE_TEST_CASE("CBH series: the error drops with the order of the truncation", "[lie]",
                   double, long double, __float128, mpfr::mpreal) {
  using S = TestType;
  auto& g = rng(113);
  // GF-4.8-cbh-series: with |X|, |Y| ~ r the order-n truncation leaves O(r^(n+1)); halving X, Y
  // divides the error by ≈ 2^(n+1) (8, 16, 32 for orders 2, 3, 4).
  for (int i = 0; i < 5; ++i) {
    const SE3Tangent<S> x(uniformVec<S, 6>(g)), y(uniformVec<S, 6>(g));
    const SE3Tangent<S> x1 = x * (S(1) / S(20)), y1 = y * (S(1) / S(20));
    for (int order = 2; order <= 4; ++order) {
      auto err = [&](const S& f) {
        const SE3Tangent<S> xs = x1 * f, ys = y1 * f;
        const SE3Tangent<S> exact = (xs.exp() * ys.exp()).log();
        return maxAbs(Vec6<S>(bch(xs, ys, order).coeffs() - exact.coeffs()));
      };
      const S ratio = err(S(1)) / err(S(1) / S(2));
      const double expected = std::pow(2.0, order + 1);
      INFO("order " << order << ", ratio " << toDouble(ratio));
      CHECK(toDouble(ratio) > 0.7 * expected);
      CHECK(toDouble(ratio) < 1.4 * expected);
    }
  }
  CHECK_THROWS_WITH(bch(SO3Tangent<S>(), SO3Tangent<S>(), 5), Contains("order must be"));
}

TEMPLATE_TEST_CASE("so(3) closed-form BCH composition", "[lie]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  auto& g = rng(119);
  const S tol = S(64) * Tolerance<S>::epsilon();
  // GF-4.8-so3-closed-form-bch (test values θ1 = 1.1, θ2 = −0.8, random unit axes):
  // cos(φ/2) = c1c2 − s1s2 x1·x2, a sin(φ/2) = s1c2, b sin(φ/2) = c1s2, c sin(φ/2) = s1s2,
  // e^{θ1x1} e^{θ2x2} = e^{φ(a x1 + b x2 + c [x1, x2])}, [x1, x2] = x1 × x2 in so(3).
  for (int i = 0; i < 10; ++i) {
    const Vec3<S> x1 = unitVec3<S>(g), x2 = unitVec3<S>(g);
    const S t1 = S(11) / S(10), t2 = -S(8) / S(10);
    const S c1 = cos(t1 / S(2)), s1 = sin(t1 / S(2)), c2 = cos(t2 / S(2)), s2 = sin(t2 / S(2));
    const S cphi = c1 * c2 - s1 * s2 * x1.dot(x2);
    const Vec3<S> sv = s1 * c2 * x1 + c1 * s2 * x2 + s1 * s2 * x1.cross(x2);  // sin(φ/2)(a, b, c)
    const S sphi = sqrt(sv.squaredNorm());
    const S phi = S(2) * atan2(sphi, cphi);
    const S a = s1 * c2 / sphi, b = c1 * s2 / sphi, c = s1 * s2 / sphi;
    const SO3Tangent<S> X1(Vec3<S>(x1 * t1)), X2(Vec3<S>(x2 * t2));
    const SO3Tangent<S> expected(Vec3<S>(phi * (a * x1 + b * x2 + c * x1.cross(x2))));
    CHECK((X1.exp() * X2.exp()).log().isApprox(expected, tol));
    CHECK(bracket(SO3Tangent<S>(x1), SO3Tangent<S>(x2)).isApprox(SO3Tangent<S>(Vec3<S>(x1.cross(x2))), tol));
  }
}

TEMPLATE_TEST_CASE("dexp series: ljac, rjac, and the printed 4th term (E4.9)", "[lie]",
                   double, long double, __float128) {
  using S = TestType;
  auto& g = rng(117);
  const S tol = S(64) * Tolerance<S>::epsilon();
  for (int i = 0; i < 10; ++i) {
    const SE3Tangent<S> s(uniformVec<S, 6>(g));
    // GF-4.5.2-dexp-hausdorff: Σ ad^k/(k+1)! = ljac, Σ (−ad)^k/(k+1)! = rjac.
    CHECK(maxAbs(Mat6<S>(dexpSeries(s, 80) - s.ljac())) <= tol);
    CHECK(maxAbs(Mat6<S>(dexpSeries(s, 80, true) - s.rjac())) <= tol);
    // 4-term truncations at |s| ≈ 0.3: the corrected 4th term ad³/4! is closer than the
    // printed ad²/4!.
    const SE3Tangent<S> t = s * (S(3) / S(10) / s.coeffs().norm());
    const S good = maxAbs(Mat6<S>(dexpSeries(t, 4) - t.ljac()));
    // GF §4.5.2 seed line 2067 as printed (erratum E4.9): I + ad/2! + ad²/3! + ad²/4!
    const Mat6<S> a = t.ad();
    const Mat6<S> printed4 = Mat6<S>::Identity() + a / S(2) + a * a / S(6) + a * a / S(24);
    const S bad = maxAbs(Mat6<S>(printed4 - t.ljac()));
    CHECK(bad > S(10) * good);
  }
}

}  // namespace SOMA_UNITY_ID
