// SE(2): exp/log against a 512-bit reference on both sides of every Taylor switch, the book's
// closed forms of §5.3 (C³ + C = 0, e^{θC} = rotation about c, dexp, BCH), group identities,
// Jacobians by finite differences, and rejection of bad input.
#include "soma/algebra/se2.hpp"
#include "support/scalars.hpp"

#include <vector>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using Catch::Matchers::Contains;

namespace {

template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }

/// RAII: run a block at another mpfr precision (for reference values).
struct MpfrBits {
  int old;
  explicit MpfrBits(int bits) : old(mpfrBits()) { setMpfrBits(bits); }
  ~MpfrBits() { setMpfrBits(old); }
};

/// x as a 512-bit mpreal (exact: every rung has at most 256 bits).
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

/// Matrix exponential by its power series (enough terms for |L| ≤ 4 at 512 bits).
template <class S> Mat3<S> expSeries(const Mat3<S>& L, int terms) {
  Mat3<S> sum = Mat3<S>::Identity(), term = Mat3<S>::Identity();
  for (int k = 1; k < terms; ++k) {
    term = (term * L / S(k)).eval();
    sum += term;
  }
  return sum;
}

/// φ(A) = Σ A^k/(k+1)!, the series of the left Jacobian (dexp) in the adjoint representation.
template <class S> Mat3<S> phiSeries(const Mat3<S>& A, int terms) {
  Mat3<S> sum = Mat3<S>::Identity(), term = Mat3<S>::Identity();
  for (int k = 1; k < terms; ++k) {
    term = (term * A / S(k + 1)).eval();
    sum += term;
  }
  return sum;
}

/// The angles every SE(2) test walks through: both sides of each switch, the extremes.
template <class S> std::vector<S> edgeAngles() {
  const S thr = Tolerance<S>::precision(7);
  const S p = pi<S>();
  return {S(0),          S(1e-8),        -S(1e-8),       thr / S(2),     S(2) * thr,
          S(3) / S(10),  p / S(2),       p - S(1e-8),    p,              -p + S(1e-8),
          -p + S(2) * Tolerance<S>::epsilon(), S(2),     -S(25) / S(10),
          // just below and just above the switch (relative 2^-10): the worst case of each side
          thr * (S(1) - S(1) / S(1024)), thr * (S(1) + S(1) / S(1024))};
}
template <class S> std::vector<S> edgeLengths() { return {S(0), S(1e-8), S(1), S(1e8)}; }

}  // namespace

TEMPLATE_TEST_CASE("SE2 exp and log agree with a 512-bit reference at the edges", "[se2]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  const S eps = Tolerance<S>::epsilon();
  for (const S& th : edgeAngles<S>())
    for (const S& len : edgeLengths<S>()) {
      const SE2Tangent<S> xi(th, len * S(3) / S(5), -len * S(4) / S(5));
      const SE2<S> g = xi.exp();
      // Reference: the power series of the matrix exponential at 512 bits, and the principal
      // logarithm of that exact element. log(exp(ξ)) = ξ only for θ ∈ (−π, π]: pi<S>() is
      // the rounding of π and lies ABOVE π for float and long double, so exp(±pi<S>()) is the
      // rotation by ∓(2π − pi<S>()) and its principal log is the wrapped angle (with the
      // linear part V(θ')⁻¹ t of that angle) — that is what the reference computes.
      Mat3<S> expected;
      Vec3<S> expectedLog;
      {
        MpfrBits bits(512);
        const Mat3<mpreal> L = SE2Tangent<mpreal>(refVec(xi.coeffs())).hat();
        const Mat3<mpreal> E = expSeries(L, 160);
        expected = castMatrix<S>(E);
        const mpreal a = atan2(E(1, 0), E(0, 0)), h = a / 2;
        const mpreal k = a == 0 ? mpreal(1) : h * cos(h) / sin(h);
        expectedLog = castMatrix<S>(
            Vec3<mpreal>(a, k * E(0, 2) + h * E(1, 2), -h * E(0, 2) + k * E(1, 2)));
      }
      INFO("theta = " << toString(th) << ", |v| = " << toString(len));
      const S scale = S(1) + len;
      CHECK(maxAbs(Mat3<S>(g.matrix() - expected)) <= S(16) * eps * scale);
      const SE2Tangent<S> back = g.log();
      CHECK(abs(back.angular() - expectedLog(0)) <= S(8) * eps * (S(1) + abs(th)));
      CHECK(maxAbs(Vec2<S>(back.linear() - expectedLog.template tail<2>())) <=
            S(64) * eps * scale);
      // Inside (−π, π] (judged exactly) the round trip returns ξ itself.
      if (abs(expectedLog(0) - th) <= S(8) * eps * (S(1) + abs(th)))
        CHECK(maxAbs(Vec2<S>(back.linear() - xi.linear())) <= S(64) * eps * scale);
    }
}

TEMPLATE_TEST_CASE("SE2 log agrees with a 512-bit reference at the edges", "[se2]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  const S eps = Tolerance<S>::epsilon();
  for (const S& th : edgeAngles<S>())
    for (const S& len : edgeLengths<S>()) {
      const SE2<S> g(th, Vec2<S>(len * S(-5) / S(13), len * S(12) / S(13)));
      // The stored (c, s) define the element exactly: the reference starts from them.
      Vec3<S> expected;
      {
        MpfrBits bits(512);
        const mpreal c = ref(g.real()), s = ref(g.imag());
        const mpreal a = atan2(s, c), h = a / 2;
        const mpreal k = a == 0 ? mpreal(1) : h * cos(h) / sin(h);
        const Vec2<mpreal> t = refVec(g.translation());
        expected = castMatrix<S>(Vec3<mpreal>(a, k * t(0) + h * t(1), -h * t(0) + k * t(1)));
      }
      INFO("theta = " << toString(th) << ", |t| = " << toString(len));
      const Vec3<S> got = g.log().coeffs();
      CHECK(abs(got(0) - expected(0)) <= S(4) * eps * (S(1) + abs(th)));
      CHECK(maxAbs(Vec2<S>(got.template tail<2>() - expected.template tail<2>())) <=
            S(16) * eps * (S(1) + len));
      // exp(log g) = g.
      CHECK(g.log().exp().isApprox(g, S(64) * eps));
    }
}

TEMPLATE_TEST_CASE("SE2 group identities over random elements", "[se2]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(7);
  const S tol = S(64) * Tolerance<S>::epsilon();
  const int n = std::is_same_v<S, mpreal> ? 20 : 200;
  for (int i = 0; i < n; ++i) {
    const SE2<S> a = SE2<S>::Random(g), b = SE2<S>::Random(g), c = SE2<S>::Random(g);
    const Vec2<S> x = test::uniformVec<S, 2>(g);
    // GF-2.5.1-homogeneous: the product is the matrix product, the action is on the plane z = 1.
    CHECK(maxAbs(Mat3<S>((a * b).matrix() - a.matrix() * b.matrix())) <= tol);
    const Vec3<S> xh = a.matrix() * Vec3<S>(x(0), x(1), S(1));
    CHECK(maxAbs(Vec2<S>(a.act(x) - xh.template head<2>())) <= tol);
    CHECK(abs(xh(2) - S(1)) == S(0));
    CHECK(((a * b) * c).isApprox(a * (b * c), tol));
    CHECK((a * a.inverse()).isApprox(SE2<S>(), tol));
    CHECK((a.inverse() * a).isApprox(SE2<S>(), tol));
    // GF-2.5.1-euclidean-pairs: distances are preserved.
    const Vec2<S> y = test::uniformVec<S, 2>(g);
    CHECK(abs((a.act(x) - a.act(y)).norm() - (x - y).norm()) <= tol);
    // fromMatrix round trip.
    CHECK(SE2<S>::fromMatrix(a.matrix()).isApprox(a, tol));
    // Adjoint: Ad(a) ξ = vee(a hat(ξ) a⁻¹) and a exp(ξ) a⁻¹ = exp(Ad(a) ξ).
    const SE2Tangent<S> xi = SE2Tangent<S>::Random(g);
    const Mat3<S> conj = a.matrix() * xi.hat() * a.inverse().matrix();
    CHECK(maxAbs(Vec3<S>(SE2Tangent<S>::vee(conj).coeffs() - a.adjoint() * xi.coeffs())) <= tol);
    CHECK((a * xi.exp() * a.inverse()).isApprox(SE2Tangent<S>(Vec3<S>(a.adjoint() * xi.coeffs())).exp(),
                                                S(4) * tol));
    CHECK(maxAbs(Mat3<S>((a * b).adjoint() - a.adjoint() * b.adjoint())) <= tol);
    // ad(ξ) η = vee[hat ξ, hat η]; Jacobi identity.
    const SE2Tangent<S> eta = SE2Tangent<S>::Random(g), zeta = SE2Tangent<S>::Random(g);
    const Mat3<S> br = xi.hat() * eta.hat() - eta.hat() * xi.hat();
    CHECK(maxAbs(Vec3<S>(SE2Tangent<S>::vee(br).coeffs() - xi.bracket(eta).coeffs())) <= tol);
    const Vec3<S> jacobi = xi.bracket(eta.bracket(zeta)).coeffs() +
                           eta.bracket(zeta.bracket(xi)).coeffs() +
                           zeta.bracket(xi.bracket(eta)).coeffs();
    CHECK(maxAbs(jacobi) <= tol);
    // Ad(exp ξ) = exp(ad ξ).
    CHECK(maxAbs(Mat3<S>(xi.exp().adjoint() - expSeries(xi.ad(), 100))) <= tol);
    // Interpolation: endpoints and the midpoint m with (a⁻¹m)² = a⁻¹b.
    CHECK(SE2<S>::interpolate(a, b, S(0)).isApprox(a, tol));
    CHECK(SE2<S>::interpolate(a, b, S(1)).isApprox(b, S(4) * tol));
    const SE2<S> m = SE2<S>::interpolate(a, b, S(1) / S(2));
    CHECK(((a.inverse() * m) * (a.inverse() * m)).isApprox(a.inverse() * b, S(4) * tol));
    // plus/minus are inverse to each other.
    CHECK(maxAbs(Vec3<S>(a.plus(xi).minus(a).coeffs() - xi.coeffs())) <= S(4) * tol);
  }
}

TEMPLATE_TEST_CASE("SE2 matches the book's §5.3 closed forms", "[se2]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const S tol = S(64) * Tolerance<S>::epsilon();
  // GF-5.3-se2-algebra-exp-ad: C = [[0,−1,cy],[1,0,−cx],[0,0,0]] (rotation about c, unit speed)
  // satisfies C³ + C = 0 and e^{θC} = I + sinθ C + (1−cosθ) C² = rotation about c.
  const Vec2<S> c(S(3) / S(10), -S(12) / S(10));
  const S th = S(9) / S(10);
  const SE2Tangent<S> C(S(1), c(1), -c(0));
  const Mat3<S> Cm = C.hat();
  Mat3<S> book;
  book << S(0), S(-1), c(1), S(1), S(0), -c(0), S(0), S(0), S(0);
  CHECK(maxAbs(Mat3<S>(Cm - book)) == S(0));
  CHECK(maxAbs(Mat3<S>(Cm * Cm * Cm + Cm)) <= tol);
  using std::cos;
  using std::sin;
  const Mat3<S> rodrigues = Mat3<S>::Identity() + sin(th) * Cm + (S(1) - cos(th)) * Cm * Cm;
  CHECK(maxAbs(Mat3<S>((th * C).exp().matrix() - rodrigues)) <= tol);
  const SE2<S> rot = SE2<S>::rotationAbout(th, c);
  CHECK((th * C).exp().isApprox(rot, tol));
  // GF-5.3-se2-rotation-about-point: the explicit matrix and the centre formula.
  Mat3<S> explicitM;
  explicitM << cos(th), -sin(th), c(0) - c(0) * cos(th) + c(1) * sin(th), sin(th), cos(th),
      c(1) - c(0) * sin(th) - c(1) * cos(th), S(0), S(0), S(1);
  CHECK(maxAbs(Mat3<S>(rot.matrix() - explicitM)) <= tol);
  CHECK(maxAbs(Vec2<S>(rot.centre() - c)) <= tol);
  CHECK(maxAbs(Vec2<S>(rot.act(c) - c)) <= tol);
  const Vec2<S> t = rot.translation();
  const Mat2<S> R = rot.rotation();
  const Vec2<S> bookCentre = (Mat2<S>::Identity() - R.transpose()) * t / (S(2) - S(2) * cos(th));
  CHECK(maxAbs(Vec2<S>(bookCentre - c)) <= tol);
  // GF-5.3-se2-bch (catalogue instance): c1 = (1/3, −2/5), c2 = (3/4, 1/2), θ1 = 0.7, θ2 = −1.1.
  // e^{θ1C1} e^{θ2C2} = e^{φ(αC1 + βC2 + γ[C1, C2])}.
  const Vec2<S> c1(S(1) / S(3), -S(2) / S(5)), c2(S(3) / S(4), S(1) / S(2));
  const S t1 = S(7) / S(10), t2 = -S(11) / S(10);
  const SE2Tangent<S> C1(S(1), c1(1), -c1(0)), C2(S(1), c2(1), -c2(0));
  using std::tan;
  const S a = tan(t1 / S(2)), b = tan(t2 / S(2));
  const S alpha = a / (a + b), beta = b / (a + b), gamma = a * b / (a + b), phi = t1 + t2;
  const SE2Tangent<S> bch = phi * (alpha * C1 + beta * C2 + gamma * C1.bracket(C2));
  CHECK(((t1 * C1).exp() * (t2 * C2).exp()).isApprox(bch.exp(), S(4) * tol));
}

TEMPLATE_TEST_CASE("SE2 Jacobians: book dexp, finite differences, inverses", "[se2]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cbrt;
  const S eps = Tolerance<S>::epsilon();
  const S tol = S(64) * eps;
  auto& g = test::rng(11);
  std::vector<SE2Tangent<S>> xis;
  for (const S& th : edgeAngles<S>()) xis.emplace_back(th, S(7) / S(10), -S(3) / S(10));
  for (int i = 0; i < (std::is_same_v<S, mpreal> ? 5 : 40); ++i)
    xis.push_back(SE2Tangent<S>::Random(g));
  const S h = cbrt(eps);
  for (const SE2Tangent<S>& xi : xis) {
    INFO("xi = " << toString(xi.angular()));
    const Mat3<S> Jr = xi.rjac(), Jl = xi.ljac();
    // GF-5.3-se2-dexp: Jl = I + (1−cosθ)/θ² ad + (θ−sinθ)/θ³ ad²; for θ = 0 the series I + ad/2.
    const S th = xi.angular();
    const Mat3<S> ad = xi.ad();
    using std::abs;
    using std::cos;
    using std::sin;
    if (abs(th) > S(1) / S(10)) {
      const Mat3<S> book = Mat3<S>::Identity() + (S(1) - cos(th)) / (th * th) * ad +
                           (th - sin(th)) / (th * th * th) * ad * ad;
      CHECK(maxAbs(Mat3<S>(Jl - book)) <= tol);
    }
    CHECK(maxAbs(Mat3<S>(Jl - phiSeries(ad, 100))) <= tol);
    // Jl = Ad(exp ξ) Jr; Jr(ξ) = Jl(−ξ).
    CHECK(maxAbs(Mat3<S>(Jl - xi.exp().adjoint() * Jr)) <= tol);
    // Inverses (ω is never a nonzero multiple of 2π here).
    CHECK(maxAbs(Mat3<S>(Jr * xi.rjacinv() - Mat3<S>::Identity())) <= tol);
    CHECK(maxAbs(Mat3<S>(Jl * xi.ljacinv() - Mat3<S>::Identity())) <= tol);
    // Right Jacobian by central differences on the manifold: log(exp(ξ)⁻¹ exp(ξ ± h e_i)).
    const SE2<S> g0inv = xi.exp().inverse();
    for (int i = 0; i < 3; ++i) {
      Vec3<S> e = Vec3<S>::Zero();
      e(i) = h;
      const Vec3<S> dp = (g0inv * (xi + SE2Tangent<S>(e)).exp()).log().coeffs();
      const Vec3<S> dm = (g0inv * (xi - SE2Tangent<S>(e)).exp()).log().coeffs();
      const Vec3<S> col = (dp - dm) / (S(2) * h);
      CHECK(maxAbs(Vec3<S>(col - Jr.col(i))) <= S(16) * h * h);
    }
  }
  // At ω = 2π the inverse Jacobians do not exist.
  const SE2Tangent<S> full(S(2) * pi<S>(), S(1), S(0));
  CHECK_THROWS_AS(full.ljacinv(), InvalidInput);
}

TEMPLATE_TEST_CASE("SE2 cast keeps the bits across the ladder", "[se2]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(3);
  const SE2<S> a = SE2<S>::Random(g);
  const SE2<mpreal> up = a.template cast<mpreal>();
  const SE2<S> down = up.template cast<S>();
  CHECK(down.isApprox(a, S(2) * Tolerance<S>::epsilon()));
  const SE2<float> f = a.template cast<float>();
  using std::abs;
  CHECK(abs(scalarCast<S>(f.angle()) - a.angle()) <=
        S(4) * scalarCast<S>(Tolerance<float>::epsilon()));
  CHECK(abs(scalarCast<S>(f.translation()(1)) - a.translation()(1)) <=
        scalarCast<S>(Tolerance<float>::epsilon()));
}

TEMPLATE_TEST_CASE("SE2 rejects bad input with a message naming the defect", "[se2]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  CHECK_THROWS_WITH(SE2<S>(nan, Vec2<S>::Zero()), Contains("not finite"));
  CHECK_THROWS_WITH(SE2<S>(S(1), Vec2<S>(S(0), nan)), Contains("not finite"));
  CHECK_THROWS_WITH(SE2<S>::fromComplex(S(1), S(1), Vec2<S>::Zero()), Contains("not a unit"));
  Mat3<S> m = SE2<S>(S(1), Vec2<S>(S(2), S(3))).matrix();
  Mat3<S> bad = m;
  // A defect well above the accepted one. (A fixed 1/100 is accepted for float, whose
  // Tolerance::input() = 64·sqrt(ε) ≈ 0.022: the old expectation ignored the rung.)
  bad(0, 0) += S(4) * Tolerance<S>::input();
  CHECK_THROWS_WITH(SE2<S>::fromMatrix(bad), Contains("not orthogonal"));
  bad = m;
  bad(0, 0) += S(1) / S(10);
  CHECK_THROWS_WITH(SE2<S>::fromMatrix(bad), Contains("not orthogonal"));
  bad = m;
  bad.col(0) = -bad.col(0);
  bad(2, 0) = S(0);
  CHECK_THROWS_WITH(SE2<S>::fromMatrix(bad), Contains("reflection"));
  bad = m;
  bad(2, 1) = S(1) / S(10);
  CHECK_THROWS_WITH(SE2<S>::fromMatrix(bad), Contains("last row"));
  bad = m;
  bad(1, 2) = nan;
  CHECK_THROWS_WITH(SE2<S>::fromMatrix(bad), Contains("NaN"));
  CHECK_THROWS_WITH(SE2<S>::translation(Vec2<S>(S(1), S(2))).centre(), Contains("pure translation"));
  Mat3<S> notAlg = SE2Tangent<S>(S(1), S(2), S(3)).hat();
  notAlg(2, 2) = S(1);
  CHECK_THROWS_WITH(SE2Tangent<S>::vee(notAlg), Contains("not of the form"));
  // Input within Tolerance::input() of a rotation is accepted (and projected).
  Mat3<S> near = m;
  near(0, 0) += Tolerance<S>::input() / S(8);
  CHECK_NOTHROW(SE2<S>::fromMatrix(near));
  CHECK_THROWS_AS(SE2Tangent<S>(nan, S(0), S(0)).exp(), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
