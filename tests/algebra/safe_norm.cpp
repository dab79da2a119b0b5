// safeNorm (soma/algebra/safe_norm.hpp, issue 24): the Euclidean norm without overflow or
// underflow. Exact answers at the ends of each scalar's range (powers of two times the 3-4-5
// triangle, where every step of the scaled sum is exact), and agreement with the plain norm where
// the plain norm is right.
#include "soma/algebra/safe_norm.hpp"
#include "support/scalars.hpp"

#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

TEMPLATE_TEST_CASE("safeNorm: no overflow and no underflow at the ends of the range", "[safe_norm][hostile]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  using std::sqrt;
  using L = std::numeric_limits<S>;
  // big: the largest power of two with 8·big ≤ max; the 3-4-5 triangle scaled by it.
  S big = S(1);
  while (big * S(16) <= L::max()) big *= S(2);
  const Vec3<S> large(S(3) * big, S(4) * big, S(0));
  CHECK(safeNorm(large) == S(5) * big);
  CHECK_FALSE(isFinite(S(sqrt(large.squaredNorm()))));  // what the plain norm gave (issue 24)
  // The smallest normal number and the smallest subnormal: exact, where the squares underflow to 0.
  const Vec3<S> small(S(3) * L::min(), S(0), S(4) * L::min());
  CHECK(safeNorm(small) == S(5) * L::min());
  CHECK(S(sqrt(small.squaredNorm())) == S(0));
  const Vec2<S> sub(S(3) * L::denorm_min(), S(4) * L::denorm_min());
  CHECK(safeNorm(sub) == S(5) * L::denorm_min());
  // A norm beyond the largest number overflows, as it must; zero, infinity and NaN pass through.
  CHECK_FALSE(isFinite(safeNorm(Vec3<S>(L::max(), L::max(), S(0)))));
  CHECK(safeNorm(Vec3<S>(Vec3<S>::Zero())) == S(0));
  CHECK(safeNorm(Vec3<S>(S(1), L::infinity(), S(0))) == L::infinity());
  const S nan = safeNorm(Vec3<S>(L::infinity(), L::quiet_NaN(), S(1)));
  CHECK(nan != nan);
}

TEMPLATE_TEST_CASE("safeNorm: the plain norm where it is right, scaled exactly by powers of two", "[safe_norm]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::sqrt;
  const S eps = Tolerance<S>::epsilon();
  auto& g = rng(77);
  for (int i = 0; i < 40; ++i) {
    const Eigen::Matrix<S, 6, 1> v = uniformVec<S, 6>(g, -3, 3);
    const S plain = sqrt(v.squaredNorm()), safe = safeNorm(v);
    CHECK(abs(safe - plain) <= S(4) * eps * plain);
    // Scaling by 2^±100 is exact in every scalar, and so is the norm's response to it.
    const S up = S(1ull << 50) * S(1ull << 50);
    CHECK(safeNorm(Eigen::Matrix<S, 6, 1>(v * up)) == safe * up);
    CHECK(safeNorm(Eigen::Matrix<S, 6, 1>(v / up)) == safe / up);
    // An expression, not only a vector.
    CHECK(safeNorm(v.template head<3>() - v.template tail<3>()) ==
          safeNorm(Vec3<S>(v.template head<3>() - v.template tail<3>())));
  }
}

}  // namespace SOMA_UNITY_ID
