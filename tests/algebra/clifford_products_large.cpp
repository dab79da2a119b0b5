// Cl(p,q,r) products for n = 6 and n = 8 (dense 256×256 tables built at run time) and the
// extended-precision scalars on small signatures; the checks are described in
// clifford_products.cpp and live in clifford_checks.hpp.
#include "clifford_checks.hpp"

using namespace soma;
using namespace soma::clifford;
using namespace soma::test::clifford_checks;

TEMPLATE_TEST_CASE("clifford products of large signatures", "[clifford]", float, double,
                   long double) {
  using S = TestType;
  checkAll<Signature<1, 2, 3>, S>(3);
  checkAll<Signature<4, 4, 0>, S>(2);  // n = 8
  checkAll<Signature<0, 6, 2>, S>(2);  // n = 8, SB's rigid-body algebra
}

TEMPLATE_TEST_CASE("clifford products in extended precision (small signatures)", "[clifford]",
                   __float128, mpfr::mpreal) {
  using S = TestType;
  checkAll<Signature<0, 2, 0>, S>(2);
  checkAll<Signature<0, 3, 1>, S>(2);
  checkAll<Signature<1, 1, 1>, S>(2);
}
