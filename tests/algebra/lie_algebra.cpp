// Lie-algebra tools (GF §4.3–4.8): Jacobi identity, Killing forms (−2I for so(3), diag(−4I, 0)
// for se(3), erratum E4.10), the CBH series order by order, the dexp series and its printed
// fourth term (erratum E4.9).
#include "soma/algebra/lie_algebra.hpp"
#include "support/scalars.hpp"

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
    const S bad = maxAbs(Mat6<S>(dexpSeriesPrinted4(t) - t.ljac()));
    CHECK(bad > S(10) * good);
  }
}
