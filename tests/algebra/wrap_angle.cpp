// wrapAngle (soma/algebra/wrap_angle.hpp): an angle modulo 2π in [−π, π], in every scalar. Angles
// already in range come back bit for bit; a + 2πk comes back as a to within the rounding of a + 2πk
// (|a + 2πk| ulps, the error of forming the argument, not of the wrap).
#include "soma/algebra/wrap_angle.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

TEMPLATE_TEST_CASE("wrapAngle: identity in range, a + 2πk back to a, the result in [−π, π]", "[wrap_angle]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  const S p = pi<S>(), eps = Tolerance<S>::epsilon();
  for (const S a : {S(0), S(1) / S(3), S(-2), S(3), p, S(-3)}) {
    CHECK(wrapAngle(a) == a);  // in (−π, π]: unchanged
    for (const int k : {-7, -1, 1, 2, 100}) {
      const S x = a + S(2 * k) * p;
      const S w = wrapAngle(x);
      INFO("a " << toDouble(a) << " k " << k);
      CHECK(w >= -p);
      CHECK(w <= p);
      // a = π and −π are the same angle: compare on the circle.
      const S gap = abs(w - a) > p ? S(2) * p - abs(w - a) : abs(w - a);
      // x carries |x|·eps/2 of rounding from its formation; sin, cos and atan2 add a few ulps of 1.
      CHECK(toDouble(gap) <= toDouble(S(4) * eps * (abs(x) + S(4))));
    }
  }
}

}  // namespace SOMA_UNITY_ID
