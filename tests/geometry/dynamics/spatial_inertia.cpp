// The 6×6 screw formulation (GF §13.1–13.2.1, SB §2): spatial inertia, its transformation under
// SE(3) against the direct parallel-axis computation, coadjoint duality, the equation of motion,
// and a free tumbling body integrated with RKMK4 (energy/momentum drift against the order bound).
#include "soma/geometry/dynamics/free_body.hpp"
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#include "../../support/scalars.hpp"

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;

namespace {
template <class S> SpatialInertia<S> randomBody(std::mt19937_64& g) {
  const S m = uniform<S>(g, 0.5, 3);
  const Vec3<S> d = uniformVec<S, 3>(g, 0.3, 2);
  const Vec3<S> c = uniformVec<S, 3>(g, -1, 1);
  const Mat3<S> R = SO3<S>::Random(g).matrix();
  return SpatialInertia<S>(m, c, Mat3<S>(R * d.asDiagonal() * R.transpose()));
}
template <class S> S relMax(const Mat6<S>& a, const Mat6<S>& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}
}  // namespace

TEMPLATE_TEST_CASE("spatial inertia: skew-axis theorem equals the direct parallel-axis move",
                   "[dynamics]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1301);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 50;
  const S tol = Tolerance<S>::identity(256);
  for (int k = 0; k < n; ++k) {
    const SpatialInertia<S> b = randomBody<S>(g);
    const SE3<S> x(SO3<S>::Random(g), uniformVec<S, 3>(g, -2, 2));
    // GF §13.1: N' = H^{-T} N H^{-1}; direct: c' = R c + t, I_c' = R I_c R^T, then [[I,mC],[mC^T,m]].
    REQUIRE(relMax(coadjointTransform(x, b.matrix()), b.transformed(x).matrix()) <= tol);
    // kinetic energy is invariant: ½ (Hs)^T N' (Hs) = ½ s^T N s
    const SE3Tangent<S> s(uniformVec<S, 6>(g));
    const SE3Tangent<S> hs(Vec6<S>(x.adjoint() * s.coeffs()));
    using std::abs;
    REQUIRE(abs(b.transformed(x).kineticEnergy(hs) - b.kineticEnergy(s)) <= tol * b.kineticEnergy(s) * S(4));
    // the momentum formula of GF §13.1 is the matrix product
    REQUIRE((b.momentum(s) - b.matrix() * s.coeffs()).cwiseAbs().maxCoeff() <= tol * b.matrix().cwiseAbs().maxCoeff());
    // read back, and composite bodies add their 6×6 inertias
    REQUIRE(relMax(SpatialInertia<S>::fromMatrix(b.matrix()).matrix(), b.matrix()) <= tol);
    const SpatialInertia<S> b2 = randomBody<S>(g);
    REQUIRE(relMax((b + b2).matrix(), Mat6<S>(b.matrix() + b2.matrix())) <= tol);
  }
}

TEST_CASE("spatial inertia: translation by t_x is the printed parallel-axis matrix (SB §5)", "[dynamics]") {
  // SB-5-translated-inertia-example: d = (1.3, 0.7, 2.1), m = 3, t_x = 0.8.
  const double m = 3, tx = 0.8;
  const auto b = SpatialInertia<double>::diagonal(m, Vec3<double>(1.3, 0.7, 2.1));
  const SE3<double> x(SO3<double>::Identity(), Vec3<double>(tx, 0, 0));
  Mat6<double> printed;
  printed << 1.3, 0, 0, 0, 0, 0,  //
      0, 0.7 + m * tx * tx, 0, 0, 0, -m * tx,  //
      0, 0, 2.1 + m * tx * tx, 0, m * tx, 0,  //
      0, 0, 0, m, 0, 0,  //
      0, 0, m * tx, 0, m, 0,  //
      0, -m * tx, 0, 0, 0, m;
  REQUIRE((b.transformed(x).matrix() - printed).cwiseAbs().maxCoeff() <= 1e-15);
  REQUIRE((coadjointTransform(x, b.matrix()) - printed).cwiseAbs().maxCoeff() <= 1e-15);
}

TEMPLATE_TEST_CASE("coadjoint action is dual to the Lie bracket; equation of motion", "[dynamics]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1302);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 50;
  const S tol = Tolerance<S>::identity(256);
  for (int k = 0; k < n; ++k) {
    const SE3Tangent<S> s1(uniformVec<S, 6>(g)), s2(uniformVec<S, 6>(g));
    const Vec6<S> P = uniformVec<S, 6>(g);
    using std::abs;
    // SB §2: s1^T {s2, P} = [s1, s2]^T P  (GF §13.1: {s2, M}(s1) = M([s1, s2]))
    const Vec6<S> br = s1.ad() * s2.coeffs();
    REQUIRE(abs(s1.coeffs().dot(coadjoint(s2, P)) - br.dot(P)) <= tol);
    // {s, P} = -ad(s)^T P
    REQUIRE((coadjoint(s1, P) + s1.ad().transpose() * P).cwiseAbs().maxCoeff() <= tol);
    // the acceleration satisfies N ṡ + {s, N s} = W
    const SpatialInertia<S> b = randomBody<S>(g);
    const Mat6<S> N = b.matrix();
    const Vec6<S> W = uniformVec<S, 6>(g);
    const SE3Tangent<S> sd = rigidBodyAcceleration(N, s1, W);
    const Vec6<S> res = N * sd.coeffs() + coadjoint(s1, Vec6<S>(N * s1.coeffs())) - W;
    REQUIRE(res.cwiseAbs().maxCoeff() <= tol * S(16) * N.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("spatial inertia: bad input is rejected with a message", "[dynamics]") {
  REQUIRE_THROWS_AS(SpatialInertia<double>(-1, Vec3<double>::Zero(), Mat3<double>::Identity()), InvalidInput);
  REQUIRE_THROWS_AS(SpatialInertia<double>(1, Vec3<double>::Zero(), Mat3<double>(-Mat3<double>::Identity())),
                    InvalidInput);
  Mat3<double> ns = Mat3<double>::Identity();
  ns(0, 1) = 0.5;
  REQUIRE_THROWS_AS(SpatialInertia<double>(1, Vec3<double>::Zero(), ns), InvalidInput);
  Mat6<double> N = SpatialInertia<double>::diagonal(2, Vec3<double>(1, 1, 1)).matrix();
  N(3, 4) = 0.3;
  N(4, 3) = 0.3;
  REQUIRE_THROWS_AS(SpatialInertia<double>::fromMatrix(N), InvalidInput);
  REQUIRE_THROWS_AS(rigidBodyAcceleration(Mat6<double>(-Mat6<double>::Identity()), SE3Tangent<double>(),
                                          Vec6<double>(Vec6<double>::Zero())),
                    InvalidInput);
}

namespace {
/// Max relative drift of energy and spatial momentum over a free flight of n steps of size h.
template <class S> std::pair<S, S> freeFlightDrift(const SpatialInertia<S>& body, const SE3Tangent<S>& s0,
                                                   const S& h, int n) {
  auto accel = [&](const SE3<S>& g, const SE3Tangent<S>& s) {
    return rigidBodyAcceleration(coadjointTransform(g, body.matrix()), s, Vec6<S>(Vec6<S>::Zero()));
  };
  RigidBodyState<S> y{SE3<S>::Identity(), s0};
  const S E0 = body.kineticEnergy(s0);
  const Vec6<S> P0 = body.momentum(s0);
  S dE(0), dP(0);
  for (int i = 0; i < n; ++i) {
    y = rkmk4Step(y, h, accel);
    const SpatialInertia<S> bi = body.transformed(y.pose);
    using std::abs;
    const S e = abs(bi.kineticEnergy(y.velocity) - E0) / E0;
    const S p = (bi.momentum(y.velocity) - P0).norm() / P0.norm();
    if (e > dE) dE = e;
    if (p > dP) dP = p;
  }
  return {dE, dP};
}
}  // namespace

TEMPLATE_TEST_CASE("free tumbling body (6x6): drift follows the order-4 bound of RKMK4", "[dynamics]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  // A body off its centre of mass with unequal moments, tumbling about an unstable-ish axis.
  const SpatialInertia<S> body(S(2), Vec3<S>(S(3) / S(10), S(-2) / S(10), S(1) / S(10)),
                               Mat3<S>(Vec3<S>(S(1), S(2), S(3)).asDiagonal()));
  const SE3Tangent<S> s0(Vec3<S>(S(1) / S(10), S(2), S(1) / S(10)), Vec3<S>(S(1) / S(2), S(0), S(-1) / S(4)));
  const S T(8);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 40 : 80;
  const S h = T / S(n);
  const auto [dE1, dP1] = freeFlightDrift(body, s0, h, n);
  const auto [dE2, dP2] = freeFlightDrift(body, s0, S(h / S(2)), 2 * n);
  // Order-4 method: halving h divides the truncation drift by 16. Bound: drift(h/2) ≤ drift(h)/2^3.5
  // plus a rounding floor of (steps)·64 ε (the 0.5 in the exponent is the allowance for the
  // next-order term at this h; no tolerance depends on the measured values themselves).
  using std::pow;
  const S floor2 = S(2 * n) * Tolerance<S>::identity();
  const S shrink = pow(S(2), S(7) / S(2));
  INFO("dE(h) = " << toDouble(dE1) << "  dE(h/2) = " << toDouble(dE2) << "  dP(h) = " << toDouble(dP1)
                  << "  dP(h/2) = " << toDouble(dP2));
  REQUIRE(dE2 <= dE1 / shrink + floor2);
  REQUIRE(dP2 <= dP1 / shrink + floor2);
  // a priori: RK4 truncation per unit time ≤ (h Ω)^4 Ω with Ω = |ω₀| + |v₀| (rates of the flow)
  const S Om = s0.ang().norm() + s0.lin().norm();
  const S apriori = pow(h * Om, 4) * Om * T + S(n) * Tolerance<S>::identity();
  REQUIRE(dE1 <= apriori);
  REQUIRE(dP1 <= apriori);
}
