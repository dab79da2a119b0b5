// checkPrintedFails (issue 27): an erratum check passes only when the printed formula misses by far
// more than rounding (kPrintedMissFactor × the rounding bound), in every scalar, and says by how much.
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::studies;

TEMPLATE_TEST_CASE("checkPrintedFails: a miss of a few ulps is not an erratum", "[studies][printed]", float, double,
                   long double, __float128) {
  using S = TestType;
  Context c(ScalarKind::Double, std::filesystem::temp_directory_path(), false);
  const S eps = std::numeric_limits<S>::epsilon(), bound = Tolerance<S>::identity(16);
  // a formula that differs from the corrected one by rounding only: 4 ulps, and 100× the bound
  CHECK_FALSE(c.checkPrintedFails("rounding only", "E0", S(4) * eps, bound));
  CHECK_FALSE(c.checkPrintedFails("100× the bound", "E0", S(100) * bound, bound));
  // just above the rule, and a real erratum (a miss of order 1)
  CHECK(c.checkPrintedFails("just above 10³× the bound", "E0", S(1001) * bound, bound));
  CHECK(c.checkPrintedFails("a miss of 0.5", "E0", S(1) / S(2), bound));
  // a NaN residual is not a demonstration of anything
  CHECK_FALSE(c.checkPrintedFails("NaN", "E0", std::numeric_limits<S>::quiet_NaN(), bound));
  // exact arithmetic (a count, integer entries): bound 0, any nonzero miss is exact
  CHECK(c.checkPrintedFails("a count", "E0", S(3), S(0)));
  CHECK_FALSE(c.checkPrintedFails("a count of 0", "E0", S(0), S(0)));
  REQUIRE(c.checks().size() == 7);
  // the miss is printed as a multiple of the bound, and the failing rows say why
  CHECK_THAT(c.checks()[3].got, Catch::StartsWith("residual 0.5 = "));
  CHECK_THAT(c.checks()[3].got, Catch::Contains("× the rounding bound"));
  CHECK_THAT(c.checks()[0].got, Catch::Contains("an erratum must miss by more than 1e+03× the rounding bound"));
  CHECK_THAT(c.checks()[5].got, Catch::Contains("exact computation: rounding bound 0"));
  CHECK(c.checks()[3].tolerance == Approx(Context::kPrintedMissFactor * double(bound)));
  CHECK(c.checks()[3].name == "a miss of 0.5 [as printed]");
  CHECK(c.checks()[3].expected == "fails (erratum E0)");
}

TEST_CASE("the tightened bounds of issue 27 reject values the old tolerances let through", "[studies][printed]") {
  Context c(ScalarKind::Double, std::filesystem::temp_directory_path(), false);
  // GF-15.2 velocity tracking: decay rate λ = 2 under RK4 at h = 2 ms; bound 10·λ⁵h⁴/120 = 4.3e-11
  // (gf15/control.cpp). A rate off by 1e-6 passed the old tolerance 0.02 and fails now.
  const double rateBound = 10 * std::pow(2.0, 5) * std::pow(0.002, 4) / 120;
  CHECK(c.checkNear("decay rate, old tolerance", 2.0, 2.0 + 1e-6, 0.02));
  CHECK_FALSE(c.checkNear("decay rate, derived bound", 2.0, 2.0 + 1e-6, rateBound));
  CHECK(c.checkNear("decay rate, derived bound, within it", 2.0, 2.0 + rateBound / 2, rateBound));
  // SOMA-6R-speed-accuracy: polished residual ≤ 64 ε (was 4096·64 ε = 2^18 ε). A residual of 1e-12
  // (a posture polished to 1e-12, not to rounding) passed before and fails now, in double and float.
  const double eps = std::numeric_limits<double>::epsilon();
  CHECK(c.checkResidual("6R residual, old tolerance", 1e-12, 262144 * eps));
  CHECK_FALSE(c.checkResidual("6R residual, 64 ε", 1e-12, 64 * eps));
  const float epsF = std::numeric_limits<float>::epsilon();
  CHECK(c.checkResidual("6R float residual, old tolerance", 1e-4f, 262144 * epsF));
  CHECK_FALSE(c.checkResidual("6R float residual, 64 ε", 1e-4f, 64 * epsF));
  // GF-4.5.2 E4.9 in float: the printed 4-term series misses by 2.857e-3 against the rounding bound
  // 12ε e^‖ad‖|ẋ| = 1.81e-6 (measured); a miss of 100× the bound is rejected, the real one accepted.
  const float boundF = 1.81e-6f;
  CHECK_FALSE(c.checkPrintedFails("E4.9 in float, a miss of 100× rounding", "E4.9", 100 * boundF, boundF));
  CHECK(c.checkPrintedFails("E4.9 in float, the measured miss", "E4.9", 2.857e-3f, boundF));
}

}  // namespace SOMA_UNITY_ID
