// Parameter-space maps of cusp counts (GF §5.2.3; Baili–Wenger–Chablat 2004): the parallel map
// equals the serial classification, is the same on 1 and 2 threads, and agrees with the traced
// second method at sample points; bad axis specifications are rejected.
#include "soma/geometry/cuspidal/parameter_map.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"

#include "soma/algebra/errors.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
SerialRobot<double> wenger() {
  DHRow<double> r1, r2, r3;
  r1.a = 1, r1.alpha = -1.5707963267948966;
  r2.a = 2, r2.alpha = 1.5707963267948966, r2.d = 1;
  r3.a = 1.5;
  return SerialRobot<double>::fromDH({r1, r2, r3});
}
}  // namespace

TEST_CASE("parameter map: axis specifications", "[cuspidal][map]") {
  const ParameterAxis a = parseParameterAxis("a2:0.5:4:100");
  CHECK(a.name == "a2");
  CHECK(a.isA);
  CHECK(a.row == 1);
  CHECK(a.n == 100);
  CHECK(a.value(0) == 0.5);
  CHECK(a.value(99) == 4);
  const ParameterAxis d = parseParameterAxis("d3:-1:1:3");
  CHECK_FALSE(d.isA);
  CHECK(d.row == 2);
  CHECK(d.value(1) == 0);
  CHECK_THROWS_WITH(parseParameterAxis("a2:0.5:4"), Catch::Contains("NAME:MIN:MAX:N"));
  CHECK_THROWS_WITH(parseParameterAxis("b2:0:1:4"), Catch::Contains("not a DH length"));
  CHECK_THROWS_WITH(parseParameterAxis("a4:0:1:4"), Catch::Contains("not a DH length"));
  CHECK_THROWS_WITH(parseParameterAxis("a2:x:1:4"), Catch::Contains("MIN 'x'"));
  // Decimal only (issue 24: "0x10" was 16), nothing around it, nothing beyond a double.
  CHECK_THROWS_WITH(parseParameterAxis("a2:0:0x10:4"), Catch::Contains("MAX '0x10' is not a finite number"));
  CHECK_THROWS_WITH(parseParameterAxis("a2: 0:1:4"), Catch::Contains("MIN ' 0' is not a finite number"));
  CHECK_THROWS_WITH(parseParameterAxis("a2:0:1e400:4"), Catch::Contains("MAX '1e400' is not a finite number"));
  CHECK_THROWS_WITH(parseParameterAxis("a2:0:inf:4"), Catch::Contains("MAX 'inf' is not a finite number"));
  CHECK(parseParameterAxis("a2:-0.5:2.5e0:4").max == 2.5);
  CHECK_THROWS_WITH(parseParameterAxis("a2:0:1:1"), Catch::Contains("N must be"));
  CHECK_THROWS_WITH(parseParameterAxis("a2:0:1:2.5"), Catch::Contains("N must be"));
  CHECK_THROWS_WITH(parseParameterAxis("a2:1:0:4"), Catch::Contains("MAX must exceed MIN"));
  CHECK_THROWS_AS(cuspMap(wenger(), a, a), InvalidInput);
}

TEST_CASE("parameter map: parallel = serial, 1 thread = 2 threads, traced count agrees", "[cuspidal][map]") {
  const SerialRobot<double> base = wenger();
  const ParameterAxis x = parseParameterAxis("a2:0.4:4:7"), y = parseParameterAxis("a3:0.3:3:7");
  const CuspMap m1 = cuspMap(base, x, y, 1), m2 = cuspMap(base, x, y, 2);
  REQUIRE(m1.counts.size() == 49);
  CHECK(m1.counts == m2.counts);
  std::vector<int> seen(9, 0);
  for (int j = 0; j < y.n; ++j)
    for (int i = 0; i < x.n; ++i) {
      const SerialRobot<double> arm = mapArm(base, x, x.value(i), y, y.value(j));
      const int c = int(findCuspsAdaptive(arm).cusps.size());
      CHECK(m1.count(i, j) == c);
      ++seen[std::size_t(std::min(c, 8))];
    }
  // The family crosses the cuspidal / non-cuspidal boundary: both verdicts occur.
  CHECK(seen[0] > 0);
  CHECK(seen[4] > 0);
  // Second method at every other cell: reversals of the traced image of det J = 0.
  for (int j = 0; j < y.n; j += 2)
    for (int i = 0; i < x.n; i += 2) {
      const SerialRobot<double> arm = mapArm(base, x, x.value(i), y, y.value(j));
      const auto rev = imageReversals(traceSingularCurves(arm, detJSeries(arm)));
      INFO("a2 = " << x.value(i) << ", a3 = " << y.value(j));
      CHECK(int(rev.size()) == m1.count(i, j));
    }
}

TEST_CASE("parameter map: the base robot must be a 3R DH arm", "[cuspidal][map]") {
  DHRow<double> r;
  r.a = 1;
  const auto two = SerialRobot<double>::fromDH({r, r});
  const ParameterAxis x = parseParameterAxis("a1:0.5:1:3"), y = parseParameterAxis("a2:0.5:1:3");
  CHECK_THROWS_WITH(cuspMap(two, x, y), Catch::Contains("has 2 joints"));
}

}  // namespace SOMA_UNITY_ID
