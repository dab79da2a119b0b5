// Cl(p,q,r) products checked independently of the blade-sign tables (GF §9.1, issue 4):
//  * geometric product against a matrix representation built from Kronecker products of Pauli
//    blocks (Jordan–Wigner): for degenerate signatures each null generator is represented by
//    f₊ + f₋ with f₊² = 1, f₋² = −1, which embeds Cl(p,q,r) in Cl(p+r, q+r, 0);
//  * outer, contractions and scalar product against grade projections of the geometric product;
//  * outer and regressive products against the exterior algebra with Poincaré duality, realised
//    in the Euclidean Cl(n,0,0) where the complements are x ↦ x̃ I and x ↦ I x̃ — the metric-free
//    products of a degenerate algebra must coincide with those coefficients.
#include "clifford_checks.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::clifford;
using namespace soma::test::clifford_checks;

TEMPLATE_TEST_CASE("clifford products agree with a matrix representation and the exterior algebra",
                   "[clifford]", float, double, long double) {
  using S = TestType;
  checkAll<Signature<0, 1, 0>, S>(8);  // ℂ
  checkAll<Signature<0, 0, 1>, S>(8);  // 𝔻
  checkAll<Signature<0, 2, 0>, S>(8);  // ℍ
  checkAll<Signature<3, 0, 0>, S>(8);
  checkAll<Signature<1, 3, 0>, S>(6);
  checkAll<Signature<0, 3, 1>, S>(6);  // GF §9.2 Euclidean group
  checkAll<Signature<2, 2, 1>, S>(4);
}

TEMPLATE_TEST_CASE("clifford products in extended precision (small signatures)", "[clifford]",
                   __float128, mpfr::mpreal) {
  using S = TestType;
  checkAll<Signature<0, 2, 0>, S>(2);
  checkAll<Signature<0, 3, 1>, S>(2);
  checkAll<Signature<1, 1, 1>, S>(2);
}

}  // namespace SOMA_UNITY_ID
