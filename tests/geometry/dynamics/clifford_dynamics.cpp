// SB's Cl(0,6,2) formulation against the 6×6 screw formulation (SB §2–6): random bodies and states
// agree to 1e-12 in double; the shuffle product against SB §4's literal definition; a free body
// integrated in both formulations.
#include "soma/geometry/dynamics/clifford_dynamics.hpp"
#include "soma/geometry/dynamics/free_body.hpp"
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
namespace c6 = soma::clifford_dynamics;

namespace {
template <class S> SpatialInertia<S> randomBody(std::mt19937_64& g) {
  const S m = uniform<S>(g, 0.5, 3);
  const Vec3<S> d = uniformVec<S, 3>(g, 0.3, 2);
  const Vec3<S> c = uniformVec<S, 3>(g, -1, 1);
  const Mat3<S> R = SO3<S>::Random(g).matrix();
  return SpatialInertia<S>(m, c, Mat3<S>(R * d.asDiagonal() * R.transpose()));
}
template <class S, int R, int C> S maxAbs(const Eigen::Matrix<S, R, C>& m) { return m.cwiseAbs().maxCoeff(); }
}  // namespace

TEST_CASE("SB shuffle: orientation-signed regressive product equals SB §4's definition on all blades",
          "[dynamics][clifford_dynamics]") {
  // Every pair of basis blades with grade sum ≥ 8 (the only ones with a nonzero shuffle).
  using D = c6::Dense<double>;
  int compared = 0, nonzero = 0;
  for (c6::Blade b = 0; b < 256; ++b)
    for (c6::Blade c = 0; c < 256; ++c) {
      if (std::popcount(b) + std::popcount(c) < 8) continue;
      const auto ref = c6::shuffleByDefinition(b, c);
      const D x = c6::shuffle(D::basisBlade(b), D::basisBlade(c));
      for (int i = 0; i < x.size; ++i) {
        const double expect = x.blade(i) == ref.result ? double(ref.sign) : 0.0;
        REQUIRE(x[i] == expect);
      }
      ++compared;
      if (ref.sign != 0) ++nonzero;
    }
  REQUIRE(compared == 39203);  // pairs with |b| + |c| ≥ 8: (2^16 + C(16,8))/2
  REQUIRE(nonzero == 6561);    // 3^8: each generator in b only, c only, or both
  // the two printed examples (SB §4)
  const auto ex = c6::shuffleByDefinition(c6::signedBlade({c6::a1, c6::a2, c6::a3, c6::a}).blade,
                                          c6::signedBlade({c6::a3, c6::a1, c6::e1, c6::e2, c6::e3, c6::e}).blade);
  // a₁a₂a₃a ∨ a₃a₁e₁e₂e₃e = a₃a₁ = −(library blade a₁a₃); the a₃a₁ factor brings a sign −1
  REQUIRE(ex.result == c6::signedBlade({c6::a1, c6::a3}).blade);
  REQUIRE(ex.sign * c6::signedBlade({c6::a3, c6::a1, c6::e1, c6::e2, c6::e3, c6::e}).sign ==
          c6::signedBlade({c6::a3, c6::a1}).sign);
}

TEMPLATE_TEST_CASE("Cl(0,6,2) and 6x6 formulations agree on random bodies and states", "[dynamics][clifford_dynamics]",
                   double, long double, __float128) {
  using S = TestType;
  auto& g = rng(6202);
  const int n = std::is_same_v<S, double> ? 200 : 10;
  // 1e-12 in double (the bar); the same relative size in the other scalars.
  const S tol = std::is_same_v<S, double> ? S(1e-12) : Tolerance<S>::identity(4096);
  const c6::Quadvector<S> A = c6::elementA<S>();
  for (int k = 0; k < n; ++k) {
    const SpatialInertia<S> body = randomBody<S>(g);
    const SE3<S> x(SO3<S>::Random(g), uniformVec<S, 3>(g, -1, 1));
    const SE3Tangent<S> s(uniformVec<S, 6>(g)), sd(uniformVec<S, 6>(g));
    const Vec6<S> P = uniformVec<S, 6>(g);
    const c6::Bivector<S> S_ = c6::screwElement(s), P_ = c6::coScrewElement(P);
    const c6::Even<S> gm = c6::motorElement(x);
    // motors: g g* = 1; screws by g s g* = H s; co-screws by ḡ P ḡ* = H^{-T} P
    REQUIRE(maxAbsDiff(c6::Even<S>(gm * gm.conjugate()), c6::Even<S>(S(1))) <= tol);
    REQUIRE(maxAbs(Vec6<S>(c6::screwOf(c6::actScrew(gm, S_)).coeffs() - x.adjoint() * s.coeffs())) <= tol);
    REQUIRE(maxAbs(Vec6<S>(c6::coScrewOf(c6::actCoScrew(gm, P_)) - coadjointAct(x, P))) <= tol);
    // inertia element: body at the identity, moved by (g ḡ) N (g ḡ)*, acts like H^{-T} N H^{-1}
    const c6::Quadvector<S> N0 = c6::inertiaElement(body.matrix());
    const c6::Quadvector<S> N = c6::actInertia(gm, N0);
    const Mat6<S> N6 = body.transformed(x).matrix();
    const S scale = maxAbs(N6);
    REQUIRE(maxAbs(Mat6<S>(c6::formMatrix(N) - N6)) <= tol * scale);
    REQUIRE(maxAbsDiff(N, c6::inertiaElement(N6)) <= tol * scale);
    // momentum, pairing, kinetic energy, coadjoint action
    REQUIRE(maxAbs(Vec6<S>(c6::coScrewOf(c6::momentum(N, S_)) - N6 * s.coeffs())) <= tol * scale);
    using std::abs;
    REQUIRE(abs(c6::pairing(P_, S_) - P.dot(s.coeffs())) <= tol);
    const S ek = s.coeffs().dot(N6 * s.coeffs()) / S(2);
    REQUIRE(abs(c6::kineticEnergy(N, S_) - ek) <= tol * scale);
    REQUIRE(maxAbs(Vec6<S>(c6::coScrewOf(c6::coadjoint(S_, P_)) - coadjoint(s, P))) <= tol);
    // A ∨ (Q0 ∧ s) = s̄
    REQUIRE(maxAbsDiff(c6::shuffle(A, c6::Hexavector<S>(clifford::outer(c6::elementQ0<S>(), S_))), c6::bar(S_)) <= tol);
    // E-form: left side equals W E with W = N ṡ + {s, N s}; only grade 6 survives
    const Vec6<S> W = N6 * sd.coeffs() + coadjoint(s, Vec6<S>(N6 * s.coeffs()));
    const auto lhs = c6::eFormLeft(N, S_, c6::screwElement(sd));
    REQUIRE(maxAbsDiff(lhs, c6::eFormRight(c6::coScrewElement(W))) <= tol * scale * S(4));
    // and solving the E-form for ṡ gives the 6×6 acceleration
    const auto acc = c6::rigidBodyAcceleration(N, S_, c6::coScrewElement(W));
    REQUIRE(acc.residual <= tol * scale * S(4));
    REQUIRE(maxAbs(Vec6<S>(c6::screwOf(acc.sdot).coeffs() - sd.coeffs())) <= tol * S(64));
  }
}

TEMPLATE_TEST_CASE("free body: Cl(0,6,2) and 6x6 trajectories agree — drift of each", "[dynamics][clifford_dynamics]",
                   double, long double) {
  using S = TestType;
  const SpatialInertia<S> body(S(2), Vec3<S>(S(3) / S(10), S(-2) / S(10), S(1) / S(10)),
                               Mat3<S>(Vec3<S>(S(1), S(2), S(3)).asDiagonal()));
  const SE3Tangent<S> s0(Vec3<S>(S(1) / S(10), S(2), S(1) / S(10)), Vec3<S>(S(1) / S(2), S(0), S(-1) / S(4)));
  const c6::Quadvector<S> N0 = c6::inertiaElement(body.matrix());
  auto acc6 = [&](const SE3<S>& g, const SE3Tangent<S>& s) {
    return rigidBodyAcceleration(coadjointTransform(g, body.matrix()), s, Vec6<S>(Vec6<S>::Zero()));
  };
  auto accC = [&](const SE3<S>& g, const SE3Tangent<S>& s) {
    const auto N = c6::actInertia(c6::motorElement(g), N0);
    return c6::screwOf(c6::rigidBodyAcceleration(N, c6::screwElement(s), c6::Bivector<S>()).sdot);
  };
  RigidBodyState<S> y6{SE3<S>::Identity(), s0}, yc = y6;
  const S h = S(1) / S(20);
  const S E0 = body.kineticEnergy(s0);
  S dTraj(0), dE(0);
  for (int i = 0; i < 100; ++i) {
    y6 = rkmk4Step(y6, h, acc6);
    yc = rkmk4Step(yc, h, accC);
    const S d = maxAbs(Vec6<S>(y6.velocity.coeffs() - yc.velocity.coeffs())) +
                maxAbs(Mat4<S>(y6.pose.matrix() - yc.pose.matrix()));
    if (d > dTraj) dTraj = d;
    using std::abs;
    const S e = abs(body.transformed(yc.pose).kineticEnergy(yc.velocity) - E0) / E0;
    if (e > dE) dE = e;
  }
  INFO("trajectory difference " << toDouble(dTraj) << ", Clifford energy drift " << toDouble(dE));
  // the two formulations integrate the same ODE with the same method: differences are rounding
  REQUIRE(dTraj <= S(100) * Tolerance<S>::identity(64));
  // a priori order-4 bound as in spatial_inertia.cpp: (hΩ)^4 Ω T
  const S Om = s0.ang().norm() + s0.lin().norm();
  using std::pow;
  REQUIRE(dE <= pow(h * Om, 4) * Om * S(5) + S(100) * Tolerance<S>::identity());
}

}  // namespace SOMA_UNITY_ID
