// GF §15.1 and §15.3 (curvature): invariant metrics on se(3), the bi-invariant connection, the
// joint-space pull-back metric, the book's Christoffel symbols against the Levi-Civita symbols of
// JᵀQ_pJ (analytic for five scalars, finite differences in double), geodesics = one-parameter
// subgroups for every Q_p, the covariant derivative's metric compatibility, the Maurer–Cartan
// structure equation, and the singular-Jacobian edge.
#include "soma/geometry/riemannian/invariant_metric.hpp"
#include "soma/geometry/riemannian/joint_space_geometry.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
template <class S> Vec6<S> lineScrew(std::mt19937_64& g, double pitch = 0) {
  const Vec3<S> w = unitVec3<S>(g), r = uniformVec<S, 3>(g);
  Vec6<S> s;
  s << w, Vec3<S>(r.cross(w) + scalarCast<S>(pitch) * w);
  return s;
}
template <class S> std::vector<Vec6<S>> randomScrews(std::mt19937_64& g, int n) {
  std::vector<Vec6<S>> s;
  for (int i = 0; i < n; ++i) s.push_back(lineScrew<S>(g));
  return s;
}
template <class S> DgVector<S> randomVec(std::mt19937_64& g, int n, double lo = -1, double hi = 1) {
  DgVector<S> v(n);
  for (int i = 0; i < n; ++i) v(i) = uniform<S>(g, lo, hi);
  return v;
}
template <class S> S maxAbsDiff(const std::vector<DgMatrix<S>>& a, const std::vector<DgMatrix<S>>& b) {
  S m = S(0);
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max<S>(m, (a[i] - b[i]).cwiseAbs().maxCoeff());
  return m;
}
template <class S> S maxAbsAll(const std::vector<DgMatrix<S>>& a) {
  S m = S(0);
  for (const auto& x : a) m = std::max<S>(m, x.cwiseAbs().maxCoeff());
  return m;
}
}  // namespace

TEMPLATE_TEST_CASE("GF §15.1: Q0, Qinf and every Q_p are ad-invariant — a pitch-p screw is Q_p-null", "[riemannian][metric]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1501);
  const S tol = Tolerance<S>::identity(16);
  CHECK(invarianceDefect<S>(reciprocalProductMatrix<S>()) <= tol);
  CHECK(invarianceDefect<S>(killingMatrixQinf<S>()) <= tol);
  CHECK(invarianceDefect<S>(Mat6<S>::Identity()) >= S(1) / S(2));  // the Euclidean 6×6 metric is not invariant
  for (int t = 0; t < 4; ++t) {
    const double p = std::uniform_real_distribution<double>(-2, 2)(g);
    const InvariantMetric<S> Q = InvariantMetric<S>::withNullPitch(scalarCast<S>(p));
    CHECK(invarianceDefect<S>(Q.matrix()) <= S(8) * tol);
    CHECK(abs(Q.nullPitch() - scalarCast<S>(p)) <= S(8) * tol);
    const Vec6<S> s = lineScrew<S>(g, p);
    CHECK(abs(Q(s, s)) <= S(64) * tol);
    const Vec6<S> s2 = lineScrew<S>(g, p + 0.5);  // another pitch is not null: Q_p(s, s) = 2α(p' − p)|ω|² = 1
    CHECK(abs(Q(s2, s2) - S(1)) <= S(64) * tol);
  }
  CHECK_THROWS_AS((InvariantMetric<S>{S(0), S(1)}.nullPitch()), InvalidInput);
}

TEMPLATE_TEST_CASE("GF §15.1/§15.3: nabla = ½[,] is torsion-free and metric — R = ¼[[X,Y],Z] — Q(R(X,Y)Z,W) = ¼Q([X,Y],[Z,W])",
                   "[riemannian][metric]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1502);
  const InvariantMetric<S> Q{S(1), S(3) / S(10)};
  const S tol = Tolerance<S>::identity(256);
  for (int t = 0; t < 5; ++t) {
    const Vec6<S> X = uniformVec<S, 6>(g), Y = uniformVec<S, 6>(g), Z = uniformVec<S, 6>(g), W = uniformVec<S, 6>(g);
    const Vec6<S> XY = SE3Tangent<S>(X).ad() * Y;
    CHECK((biinvariantCovariant<S>(X, Y) - biinvariantCovariant<S>(Y, X) - XY).cwiseAbs().maxCoeff() <= tol);
    CHECK(abs(Q(biinvariantCovariant<S>(X, Y), Z) + Q(Y, biinvariantCovariant<S>(X, Z))) <= tol);
    CHECK((curvatureFromConnection<S>(X, Y, Z) - curvature<S>(X, Y, Z)).cwiseAbs().maxCoeff() <= tol);
    const Vec6<S> ZW = SE3Tangent<S>(Z).ad() * W;
    CHECK(abs(Q(curvature<S>(X, Y, Z), W) - Q(XY, ZW) / S(4)) <= S(4) * tol);
    CHECK(abs(sectionalCurvature<S>(Q, X, X)) <= tol);  // K(X, X) = 0
  }
  // the Christoffel symbols in the Lie-algebra frame are anti-symmetric: Γ^k_ij = −½C^k_ij
  const auto G = biinvariantChristoffel<S>();
  for (const auto& m : G) CHECK((m + m.transpose()).cwiseAbs().maxCoeff() <= tol);
}

TEMPLATE_TEST_CASE("GF §15.1: the book's joint-space Christoffel symbols equal the Levi-Civita symbols of J^T Q_p J",
                   "[riemannian][christoffel]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1503);
  // relative bound: J⁻¹ of random 6R robots has condition numbers up to ~1e3 here, so 1e5 ulps
  const S tol = Tolerance<S>::identity(100000);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 1 : 4;
  for (int t = 0; t < trials; ++t) {
    const JointSpaceGeometry<S> geo(randomScrews<S>(g, 6), InvariantMetric<S>{S(1), uniform<S>(g, -1, 1)});
    const DgVector<S> th = randomVec<S>(g, 6);
    const auto book = geo.christoffelBook(th);
    const auto lc = geo.christoffelLeviCivita(th);
    const S scale = maxAbsAll(book);
    CHECK(maxAbsDiff(book, lc) <= tol * scale);
    for (const auto& m : book) CHECK((m - m.transpose()).cwiseAbs().maxCoeff() <= tol * scale);  // symmetric (E15.1)
    // the printed "anti-symmetric" reading is not the Levi-Civita connection
    // GF §15.1 line 9581 as printed (erratum E15.1): Γ^i_jk = ½W_i([s_j, s_k]) for all j ≠ k
    const ScrewMatrix<S> J = geo.screws(th);
    const DgMatrix<S> W = geo.coScrews(J);
    std::vector<DgMatrix<S>> printed(6, DgMatrix<S>::Zero(6, 6));
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        if (j == k) continue;
        const DgVector<S> w = W * Vec6<S>(SE3Tangent<S>(Vec6<S>(J.col(j))).ad() * J.col(k)) / S(2);
        for (int i = 0; i < 6; ++i) printed[std::size_t(i)](j, k) = w(i);
      }
    CHECK(maxAbsDiff(printed, lc) >= scale / S(10));
  }
}

TEST_CASE("GF §15.1: Levi-Civita from finite differences of J^T Q_p J equals the book form (double, |err| < 1e-7)",
          "[riemannian][christoffel]") {
  using S = double;
  auto& g = rng(1504);
  for (int t = 0; t < 3; ++t) {
    const JointSpaceGeometry<S> geo(randomScrews<S>(g, 6), InvariantMetric<S>{1, 0.3});
    const DgVector<S> th = randomVec<S>(g, 6);
    const int n = 6;
    const double h = 1e-4;
    std::vector<DgMatrix<S>> dG;
    for (int i = 0; i < n; ++i) {  // 4th-order central differences: error ~ h⁴ ≈ 1e-16·|G⁽⁵⁾|
      auto at = [&](double u) {
        DgVector<S> a = th;
        a(i) += u;
        return geo.pullbackMetric(a);
      };
      dG.push_back((8 * (at(h) - at(-h)) - (at(2 * h) - at(-2 * h))) / (12 * h));
    }
    const auto dA = geo.pullbackMetricDerivative(th);
    for (int i = 0; i < n; ++i) CHECK((dG[std::size_t(i)] - dA[std::size_t(i)]).cwiseAbs().maxCoeff() < 1e-8);
    const DgMatrix<S> Gi = geo.pullbackMetric(th).inverse();
    const auto book = geo.christoffelBook(th);
    double err = 0;
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        DgVector<S> lower(n);
        for (int l = 0; l < n; ++l) lower(l) = (dG[std::size_t(j)](l, k) + dG[std::size_t(k)](l, j) - dG[std::size_t(l)](j, k)) / 2;
        const DgVector<S> up = Gi * lower;
        for (int i = 0; i < n; ++i) err = std::max(err, std::abs(up(i) - book[std::size_t(i)](j, k)));
      }
    CHECK(err < 1e-7);
  }
}

TEMPLATE_TEST_CASE("GF §15.1: geodesics are one-parameter subgroups for every Q_p (end-effector twist constant)",
                   "[riemannian][geodesic]", double, long double, __float128) {
  using S = TestType;
  auto& g = rng(1505);
  const JointSpaceGeometry<S> geo(randomScrews<S>(g, 6));
  DgVector<S> th = randomVec<S>(g, 6, -0.5, 0.5), v = randomVec<S>(g, 6, -0.3, 0.3);
  const SE3<S> g0 = geo.forward(th);
  const Vec6<S> X = geo.screws(th) * v;
  // the geodesic acceleration −Γ_LC θ̇θ̇ of J^T Q_p J is the same for every non-degenerate Q_p
  for (double beta : {-2.0, 0.0, 0.7}) {
    const JointSpaceGeometry<S> gq(geo.homeScrews(), InvariantMetric<S>{S(1), scalarCast<S>(beta)});
    const auto lc = gq.christoffelLeviCivita(th);
    DgVector<S> a(6);
    for (int i = 0; i < 6; ++i) a(i) = -v.dot(lc[std::size_t(i)] * v);
    CHECK((a - geo.geodesicAcceleration(th, v)).cwiseAbs().maxCoeff() <= Tolerance<S>::identity(100000));
  }
  const S h = S(1) / S(100);
  for (int k = 0; k < 100; ++k) geo.geodesicStep(th, v, h);
  const S drift = (geo.screws(th) * v - X).cwiseAbs().maxCoeff();
  const SE3<S> expect = SE3Tangent<S>(X).exp().compose(g0);  // ρ(t) = e^{tX}ρ(0), t = 1
  // RK4 with h = 0.01: local error ~ h⁵ per step; bound 1e-9 (the twist is conserved to round-off
  // only by the exact flow)
  CHECK(drift <= S(1e-9));
  CHECK(geo.forward(th).isApprox(expect, S(1e-9)));
}

TEST_CASE("GF §15.1: metric compatibility of the joint-space covariant derivative and the Maurer–Cartan equation (double)",
          "[riemannian][geodesic]") {
  using S = double;
  auto& g = rng(1506);
  const InvariantMetric<S> Q{1, -0.4};
  const JointSpaceGeometry<S> geo(randomScrews<S>(g, 6), Q);
  const DgVector<S> th = randomVec<S>(g, 6), td = randomVec<S>(g, 6), a = randomVec<S>(g, 6), b = randomVec<S>(g, 6);
  const DgVector<S> zero = DgVector<S>::Zero(6);
  // V = J a, W = J b with constant coefficients along θ(t) = θ + t θ̇: d/dt Q(V, W) = Q(∇_U V, W) + Q(V, ∇_U W)
  auto q = [&](double t) {
    const ScrewMatrix<S> J = geo.screws(DgVector<S>(th + t * td));
    return Q(Vec6<S>(J * a), Vec6<S>(J * b));
  };
  const double h = 1e-3;
  const double dq = (8 * (q(h) - q(-h)) - (q(2 * h) - q(-2 * h))) / (12 * h);
  const ScrewMatrix<S> J = geo.screws(th);
  const double rhs = Q(geo.covariantDerivative(th, td, a, zero), Vec6<S>(J * b)) + Q(Vec6<S>(J * a), geo.covariantDerivative(th, td, b, zero));
  CHECK(std::abs(dq - rhs) < 1e-9 * std::max(1.0, std::abs(dq)));
  // ∇_U U = q̈₆ (the spatial end-effector acceleration)
  const DgVector<S> tdd = randomVec<S>(g, 6);
  CHECK((geo.covariantDerivative(th, td, td, tdd) - geo.endEffectorAcceleration(th, td, tdd)).cwiseAbs().maxCoeff() < 1e-13);
  // d(ρ*Ω)(∂_i, ∂_j) = ∂_i s_j − ∂_j s_i = [s_i, s_j]
  const auto d = geo.maurerCartanDifferential(th);
  double err = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      auto col = [&](int which, int dir, double u) {
        DgVector<S> x = th;
        x(dir) += u;
        return Vec6<S>(geo.screws(x).col(which));
      };
      const Vec6<S> dsj = (8 * (col(j, i, h) - col(j, i, -h)) - (col(j, i, 2 * h) - col(j, i, -2 * h))) / (12 * h);
      const Vec6<S> dsi = (8 * (col(i, j, h) - col(i, j, -h)) - (col(i, j, 2 * h) - col(i, j, -2 * h))) / (12 * h);
      err = std::max(err, (dsj - dsi - d[std::size_t(i)][std::size_t(j)]).cwiseAbs().maxCoeff());
    }
  CHECK(err < 1e-9);
}

TEMPLATE_TEST_CASE("GF §15.1 edge: a singular Jacobian gives InvalidInput, never NaN", "[riemannian][edge]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1507);
  auto s = randomScrews<S>(g, 6);
  s[4] = s[3];  // two coincident joint axes: J has rank 5 at θ = 0 (and with θ₄ = θ₅ = 0 rotations keep it)
  const JointSpaceGeometry<S> geo(s);
  const DgVector<S> th = DgVector<S>::Zero(6), v = DgVector<S>::Ones(6);
  CHECK_THROWS_AS(geo.geodesicAcceleration(th, v), InvalidInput);
  CHECK_THROWS_AS(geo.christoffelBook(th), InvalidInput);
  CHECK_THROWS_AS(geo.christoffelLeviCivita(th), InvalidInput);
  // just off the singular set the symbols are finite
  auto s2 = s;
  s2[4](3) += S(1) / S(10);
  s2[4].template head<3>() += Vec3<S>(S(0), S(1) / S(10), S(0));
  s2[4] /= s2[4].template head<3>().norm();
  const JointSpaceGeometry<S> ok(s2);
  CHECK(allFinite(ok.geodesicAcceleration(th, v)));
  // Q_inf alone is degenerate: no Levi-Civita connection
  const JointSpaceGeometry<S> degenerate(randomScrews<S>(g, 6), InvariantMetric<S>{S(0), S(1)});
  CHECK_THROWS_AS(degenerate.christoffelLeviCivita(th), InvalidInput);
  CHECK_THROWS_AS(JointSpaceGeometry<S>(std::vector<Vec6<S>>{}), InvalidInput);
  CHECK_THROWS_AS(geo.screws(DgVector<S>::Zero(5)), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
