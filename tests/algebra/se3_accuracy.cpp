// SE(3) accuracy: exp, log and the four Jacobians (with the Q block) against 512-bit mpfr
// references on both sides of every Taylor switch and at the edge angles (a few ulp), Jacobian
// identities in every rung, every analytic J_out / Jacobian against central differences, and
// the log sweep of log_accuracy.hpp over θ ∈ (0, π].
#include "lie_suite.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

TEMPLATE_TEST_CASE("SE3 exp, log, Jacobians: a few ulp of a 512-bit reference at every switch",
                   "[se3][accuracy]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(81);
  for (const auto& smp : lie::samples<SE3<S>>(g, std::is_same_v<S, mpreal> ? 1 : 8))
    lie::checkAgainstReference(smp, 8);
}

TEMPLATE_TEST_CASE("SE3 Jacobian identities: inverses, Ad, dexp series, J_out", "[se3][jacobian]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(83);
  for (const auto& smp : lie::samples<SE3<S>>(g, std::is_same_v<S, mpreal> ? 2 : 20))
    lie::checkJacobianIdentities(smp);
}

TEMPLATE_TEST_CASE("SE3 analytic Jacobians agree with central differences on the manifold",
                   "[se3][jacobian]", double, long double) {
  using S = TestType;
  auto& g = rng(87);
  for (const auto& smp : lie::samples<SE3<S>>(g, 20)) lie::checkJacobiansNumerically(smp, g);
}

TEMPLATE_TEST_CASE("SE3 log sweep over 0 < theta <= pi: worst error a few ulp", "[se3][accuracy]", float,
                   double, long double, __float128) {
  using S = TestType;
  const LogAccuracy r = worstLogError<S>(240);
  INFO("worst " << r.worstUlps << " ulp at theta = " << r.worstTheta << " (rotation "
                << r.rotationUlps << ", translation " << r.translationUlps << ")");
  CHECK(r.samples == 240);
  CHECK(r.referenceBits >= 320);
  CHECK(r.worstUlps <= 8);
  CHECK(r.meanUlps <= 2);
}

}  // namespace SOMA_UNITY_ID
