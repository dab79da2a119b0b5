// GF §12.4: the end-effector wrench, stiffness, compliance and eigenscrews.
#include "soma/geometry/statics/robot_statics.hpp"
#include "soma/geometry/statics/wrench.hpp"
#include "soma/geometry/statics/wrist_sensor.hpp"
#include "soma/geometry/statics/grasp.hpp"

#include "../../support/scalars.hpp"

#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniformVec;

namespace {
template <class S> S tolId(int k = 256) { return Tolerance<S>::identity(k); }
/// 6 × 6 orthogonal matrix: block-diagonal of two random rotations.
template <class S> Mat6<S> blockRotation(std::mt19937_64& g) {
  Mat6<S> m = Mat6<S>::Zero();
  m.template topLeftCorner<3, 3>() = SO3<S>::Random(g).matrix();
  m.template bottomRightCorner<3, 3>() = SO3<S>::Random(g).matrix();
  return m;
}
template <class S> ScrewColumns<S> withSingularValues(std::mt19937_64& g, const Vec6<S>& sig) {
  return ScrewColumns<S>(blockRotation<S>(g) * sig.asDiagonal() * blockRotation<S>(g));
}
}  // namespace

TEMPLATE_TEST_CASE("GF-12.4 end-effector wrench: virtual work and J⁻ᵀ w", "[statics][robot]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1204);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 2 : 10;
  for (int i = 0; i < n; ++i) {
    ScrewColumns<S> J(6, 6);
    for (int c = 0; c < 6; ++c) J.col(c) = uniformVec<S, 6>(g);
    const Wrench<S> W(uniformVec<S, 6>(g));
    const VecX<S> w = jointEfforts<S>(J, W);
    const VecX<S> qd = VecX<S>(Vec6<S>(uniformVec<S, 6>(g)));
    // 𝒲ᵀ (J θ̇) = wᵀ θ̇ (power at the tool = power at the joints)
    CHECK(abs(W(SE3Tangent<S>(Vec6<S>(J * qd))) - w.dot(qd)) <= tolId<S>());
    const auto ee = endEffectorWrench<S>(J, w);
    CHECK(ee.rank == 6);
    CHECK(ee.structureWrenches.empty());
    CHECK((ee.wrench.coeffs() - W.coeffs()).cwiseAbs().maxCoeff() <= tolId<S>(64) * ee.condition);
    CHECK(ee.residual <= tolId<S>() * ee.condition);
  }
}

TEMPLATE_TEST_CASE("GF-12.4 end-effector wrench near a singularity: both sides of the rank threshold",
                   "[statics][robot]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1205);
  const S rk = Tolerance<S>::rank();
  Vec6<S> sig;
  sig << S(2), S(1.5), S(1), S(0.8), S(0.5), rk * S(8);
  const ScrewColumns<S> J = withSingularValues<S>(g, sig);
  const VecX<S> w = VecX<S>(Vec6<S>(uniformVec<S, 6>(g)));
  CHECK(endEffectorWrench<S>(J, w).rank == 6);
  sig(5) = rk / S(8);
  const ScrewColumns<S> Js = withSingularValues<S>(g, sig);
  const auto ee = endEffectorWrench<S>(Js, w);
  CHECK(ee.rank == 5);
  REQUIRE(ee.structureWrenches.size() == 1);
  // the structure wrench does no work on any joint screw
  CHECK((Js.transpose() * ee.structureWrenches[0].coeffs()).cwiseAbs().maxCoeff() <= rk);
  // w generically has a part no wrench balances; a consistent w has none
  CHECK(ee.residual > S(100) * tolId<S>());
  const VecX<S> wc = jointEfforts<S>(Js, Wrench<S>(uniformVec<S, 6>(g)));
  CHECK(endEffectorWrench<S>(Js, wc).residual <= tolId<S>(1024));
  CHECK_THROWS_AS(cartesianStiffness<S>(Js, VecX<S>(Vec6<S>::Ones())), InvalidInput);
  CHECK_THROWS_AS(endEffectorWrench<S>(Js, VecX<S>(Vec3<S>::Ones())), InvalidInput);
}

TEMPLATE_TEST_CASE("GF-12.4 stiffness and compliance: C · J⁻ᵀKJ⁻¹ = I, rigid joints", "[statics][robot]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1206);
  ScrewColumns<S> J(6, 6);
  for (int c = 0; c < 6; ++c) J.col(c) = uniformVec<S, 6>(g);
  J += ScrewColumns<S>(Mat6<S>::Identity() * S(2));
  Vec6<S> k;
  k << S(3), S(5), S(2), S(7), S(1), S(4);
  const Mat6<S> Kx = cartesianStiffness<S>(J, VecX<S>(k)), C = compliance<S>(J, VecX<S>(k));
  CHECK((C * Kx - Mat6<S>::Identity()).cwiseAbs().maxCoeff() <= tolId<S>(4096));
  CHECK((C - C.transpose()).cwiseAbs().maxCoeff() <= tolId<S>());
  // the wrench holding a displacement δx = J δθ is the one the joint springs k δθ give
  const Vec6<S> dth = uniformVec<S, 6>(g);
  const VecX<S> w = VecX<S>(Vec6<S>(k.asDiagonal() * dth));
  CHECK((Kx * (J * dth) - endEffectorWrench<S>(J, w).wrench.coeffs()).cwiseAbs().maxCoeff() <= tolId<S>(4096));
  // a rigid joint (k = ∞) drops its column from the compliance
  VecX<S> kr = VecX<S>(k);
  kr(2) = std::numeric_limits<S>::infinity();
  ScrewColumns<S> J5(6, 5);
  VecX<S> k5(5);
  for (int c = 0, d = 0; c < 6; ++c)
    if (c != 2) J5.col(d) = J.col(c), k5(d++) = k(c);
  CHECK((compliance<S>(J, kr) - compliance<S>(J5, k5)).cwiseAbs().maxCoeff() <= tolId<S>());
  // bad input
  VecX<S> kbad = VecX<S>(k);
  kbad(0) = S(0);
  CHECK_THROWS_AS(cartesianStiffness<S>(J, kbad), InvalidInput);
  CHECK_THROWS_AS(compliance<S>(J, kbad), InvalidInput);
  CHECK_THROWS_AS(cartesianStiffness<S>(J5, k5), InvalidInput);
  CHECK_THROWS_AS(compliance<S>(J, k5), InvalidInput);
}

TEMPLATE_TEST_CASE("GF-12.4 eigenscrews of a stiffness: K s = λ Q₀ s, Q₀-orthogonal", "[statics][robot]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1207);
  ScrewColumns<S> J(6, 6);
  for (int c = 0; c < 6; ++c) J.col(c) = uniformVec<S, 6>(g);
  J += ScrewColumns<S>(Mat6<S>::Identity() * S(2));
  Vec6<S> k;
  k << S(3), S(5), S(2), S(7), S(1), S(4);
  const Mat6<S> K = cartesianStiffness<S>(J, VecX<S>(k));
  Mat6<S> Q0 = Mat6<S>::Zero();
  Q0.template topRightCorner<3, 3>().setIdentity();
  Q0.template bottomLeftCorner<3, 3>().setIdentity();
  const auto es = stiffnessEigenscrews<S>(K);
  const S sc = K.cwiseAbs().maxCoeff();
  int positive = 0;
  for (int i = 0; i < 6; ++i) {
    const Vec6<S> s = es[std::size_t(i)].screw.coeffs();
    CHECK((K * s - es[std::size_t(i)].stiffness * Q0 * s).cwiseAbs().maxCoeff() <= tolId<S>(1 << 14) * sc * s.norm());
    for (int j = 0; j < 6; ++j) {
      const S q = s.dot(Q0 * es[std::size_t(j)].screw.coeffs());
      if (i == j) CHECK(abs(abs(q) - S(1)) <= tolId<S>(1 << 14));
      else CHECK(abs(q) <= tolId<S>(1 << 14) * S(16));
    }
    if (es[std::size_t(i)].stiffness > S(0)) ++positive;
  }
  // Q₀ has signature (3, 3): three eigenscrews of each sign of λ.
  CHECK(positive == 3);
  Mat6<S> bad = K;
  bad(0, 1) += S(1);
  CHECK_THROWS_AS(stiffnessEigenscrews<S>(bad), InvalidInput);
  CHECK_THROWS_AS(stiffnessEigenscrews<S>(Mat6<S>(-K)), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
