// Cl(p,q,r) products for n = 6 and n = 8 (dense 256×256 tables built at run time); the checks
// are described in clifford_products.cpp and live in clifford_checks.hpp.
#include "clifford_checks.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::clifford;
using namespace soma::test::clifford_checks;

// float runs the same checks on the small signatures (clifford_products.cpp); here only double
// and long double, to keep this TU's compile time near 40 s.
TEMPLATE_TEST_CASE("clifford products of large signatures", "[clifford]", double, long double) {
  using S = TestType;
  checkAll<Signature<1, 2, 3>, S>(3);
  checkAll<Signature<4, 4, 0>, S>(2);  // n = 8
  checkAll<Signature<0, 6, 2>, S>(2);  // n = 8, SB's rigid-body algebra
}

}  // namespace SOMA_UNITY_ID
