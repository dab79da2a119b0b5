// SO(3) accuracy: exp, log and the four Jacobians against 512-bit mpfr references on both sides
// of every Taylor switch and at the edge angles (a few ulp), Jacobian identities in every rung,
// and every analytic J_out / Jacobian against central differences on the manifold.
#include "lie_suite.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

TEMPLATE_TEST_CASE("SO3 exp, log, Jacobians: a few ulp of a 512-bit reference at every switch",
                   "[so3][accuracy]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(41);
  for (const auto& smp : lie::samples<SO3<S>>(g, std::is_same_v<S, mpreal> ? 1 : 8))
    lie::checkAgainstReference(smp, 8);
}

TEMPLATE_TEST_CASE("SO3 Jacobian identities: inverses, Ad, dexp series, J_out", "[so3][jacobian]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(43);
  for (const auto& smp : lie::samples<SO3<S>>(g, std::is_same_v<S, mpreal> ? 2 : 20))
    lie::checkJacobianIdentities(smp);
}

TEMPLATE_TEST_CASE("SO3 analytic Jacobians agree with central differences on the manifold",
                   "[so3][jacobian]", double, long double) {
  using S = TestType;
  auto& g = rng(47);
  for (const auto& smp : lie::samples<SO3<S>>(g, 20)) lie::checkJacobiansNumerically(smp, g);
}

}  // namespace SOMA_UNITY_ID
