// Finite-position Burmester synthesis: 3, 4, 5 positions, round trips through random 4-bars.
#include "soma/geometry/planar/burmester_synthesis.hpp"
#include "support/scalars.hpp"

#include <iostream>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::planar;
using soma::test::rng;
using soma::test::uniform;
using std::abs;
using std::cos;
using std::sin;
using std::sqrt;

namespace {
template <class S> S tolFor(double k) { return scalarCast<S>(k) * Tolerance<S>::epsilon(); }

template <class S> std::vector<SE2<S>> randomPositions(std::mt19937_64& g, int n) {
  std::vector<SE2<S>> p;
  for (int i = 0; i < n; ++i) {
    // Drawn y, x, then the angle: explicit, because C++ leaves the order of constructor arguments
    // unspecified (GCC and clang differ) and the fixed-seed cases must not depend on the compiler.
    const S y = uniform<S>(g, -2, 2);
    const S x = uniform<S>(g, -2, 2);
    const S angle = uniform<S>(g, -1.2, 1.2);
    p.push_back(SE2<S>(angle, Vec2<S>(x, y)));
  }
  return p;
}

/// A random crank-rocker and five coupler poses along one circuit.
struct Trial {
  FourBar<double> bar;
  std::vector<SE2<double>> positions;
  Vec2<double> c1, c4, z2, z3;  // original pivots (moving ones in body coordinates of the coupler point frame)
};
Trial randomTrial(std::mt19937_64& g) {
  for (;;) {
    std::uniform_real_distribution<double> u(0, 1);
    const double l0 = 2 + 2 * u(g), l1 = 0.5 + 0.7 * u(g), l2 = 1.5 + 2 * u(g), l3 = 1.5 + 2 * u(g);
    const double ang = 6.283 * u(g);
    const Vec2<double> c1(2 * u(g) - 1, 2 * u(g) - 1), c4 = c1 + l0 * Vec2<double>(std::cos(ang), std::sin(ang));
    const Vec2<double> pc(2 * u(g) - 1, 1 + u(g));
    FourBar<double> fb(c1, c4, l1, l2, l3, pc);
    if (fb.classify().type != GrashofType::CrankRocker) continue;
    const double t0 = 6.283 * u(g);
    std::vector<SE2<double>> pos;
    std::vector<FourBarPose<double>> poses;
    const int mode = u(g) < 0.5 ? 1 : -1;
    for (int i = 0; i < 5; ++i) {
      const auto p = fb.solve(t0 + 0.9 * i + 0.3 * u(g), mode);
      poses.push_back(*p);
      // the moving frame: at the coupler point, rotated with the coupler (an arbitrary fixed offset)
      pos.push_back(p->coupler * SE2<double>(0.4, pc));
    }
    const SE2<double> B = SE2<double>(0.4, pc).inverse();  // coupler frame → moving frame body coords
    return {fb, pos, c1, c4, B.act(Vec2<double>(0, 0)), B.act(Vec2<double>(l2, 0))};
  }
}
}  // namespace

TEMPLATE_TEST_CASE("three positions: circle point ↔ centre point round trip", "[planar][synthesis]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(601);
  for (int c = 0; c < 8; ++c) {
    const BurmesterSynthesis<S> bs(randomPositions<S>(g, 3));
    const Vec2<S> z(uniform<S>(g, -2, 2), uniform<S>(g, -2, 2));
    const auto m = bs.centreForCirclePoint(z);
    REQUIRE(m);
    CHECK(bs.residual(*m, z) <= tolFor<S>(1 << 12) * (S(1) + m->squaredNorm()));
    const auto z2 = bs.circlePointForCentre(*m);
    REQUIRE(z2);
    CHECK((*z2 - z).norm() <= tolFor<S>(1 << 16) * (S(1) + z.norm() + m->norm()));
  }
}

TEMPLATE_TEST_CASE("four positions: the centre-point curve is a circular cubic through the six poles",
                   "[planar][synthesis]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(602);
  for (int c = 0; c < 4; ++c) {
    const BurmesterSynthesis<S> bs(randomPositions<S>(g, 4));
    const Poly2<S> F = bs.centrePointCurve(), C = bs.circlePointCurve();
    CHECK(F.degree(tolFor<S>(1 << 10)) == 3);
    CHECK(C.degree(tolFor<S>(1 << 10)) == 3);
    // circular: the cubic part is (x² + y²)·(linear): coefficients a30 = a12, a03 = a21
    CHECK(abs(F.at(3, 0) - F.at(1, 2)) <= tolFor<S>(1 << 12) * F.maxCoeff());
    CHECK(abs(F.at(0, 3) - F.at(2, 1)) <= tolFor<S>(1 << 12) * F.maxCoeff());
    for (int i = 1; i <= 4; ++i)
      for (int j = i + 1; j <= 4; ++j) {
        const Vec2<S> P = bs.pole(i, j);
        CHECK(abs(F(P(0), P(1))) <= tolFor<S>(1 << 14) * F.magnitude(P(0), P(1)));
      }
    // a point on the curve has a circle point, and four positions of it on one circle
    if (std::is_same_v<S, mpreal>) continue;
    const auto pts = sampleCurve(F, S(-3), S(3), S(-3), S(3), 12);
    REQUIRE(!pts.empty());
    int good = 0;
    for (const auto& m : pts) {
      const auto z = bs.circlePointForCentre(m);
      if (!z) continue;
      if (bs.residual(m, *z) <= std::max<S>(tolFor<S>(1 << 20), S(1e-9)) * (S(1) + z->squaredNorm())) ++good;
      // and z lies on the circle-point curve
      CHECK(abs(C((*z)(0), (*z)(1))) <= std::max<S>(tolFor<S>(1 << 20), S(1e-9)) * C.magnitude((*z)(0), (*z)(1)));
    }
    CHECK(good >= int(pts.size()) * 9 / 10);
  }
}

TEST_CASE("five positions from random 4-bars: the Burmester pairs contain the original pivots — the rebuilt 4-bar passes "
          "through all five positions (success rate, worst error)",
          "[planar][synthesis][round-trip]") {
  auto& g = rng(603);
  const int trials = 200;
  int success = 0, recovered = 0;
  double worstT = 0, worstA = 0, worstResidual = 0, worstComplex = 0, worstAlgebraic = 0;
  int countHist[5] = {0, 0, 0, 0, 0};
  for (int t = 0; t < trials; ++t) {
    const Trial tr = randomTrial(g);
    const BurmesterSynthesis<double> bs(tr.positions);
    int complexCount = -1;
    double complexRes = 1, algebraicRes = 1;
    const auto pairs = bs.burmesterPairs(&complexCount, &complexRes, &algebraicRes);
    CHECK(int(pairs.size()) + complexCount == 4);
    CHECK(complexRes <= 1e-12);   // the non-real solutions are genuine solutions
    CHECK(algebraicRes <= 1e-8);  // the conic intersection alone, before any Newton step
    worstComplex = std::max(worstComplex, complexRes);
    worstAlgebraic = std::max(worstAlgebraic, algebraicRes);
    ++countHist[pairs.size()];
    int ia = -1, ib = -1;
    for (int k = 0; k < int(pairs.size()); ++k) {
      worstResidual = std::max(worstResidual, pairs[k].residual);
      if ((pairs[k].centre - tr.c1).norm() < 1e-6 && (pairs[k].circle - tr.z2).norm() < 1e-6) ia = k;
      if ((pairs[k].centre - tr.c4).norm() < 1e-6 && (pairs[k].circle - tr.z3).norm() < 1e-6) ib = k;
    }
    if (ia < 0 || ib < 0) continue;
    ++recovered;
    const DriveCheck<double> dc = bs.drive(pairs[ia], pairs[ib]);
    worstT = std::max(worstT, dc.worstTranslation);
    worstA = std::max(worstA, dc.worstAngle);
    if (dc.reached && dc.sameCircuit && dc.worstTranslation < 1e-9 && dc.worstAngle < 1e-9) ++success;
  }
  std::cout << "[planar synthesis round trip] " << success << "/" << trials << " succeeded (" << recovered
            << " recovered both pivots); worst translation error " << worstT << " (relative), worst angle error " << worstA
            << " rad; worst pair residual " << worstResidual << "; real-pair counts 0/2/4: " << countHist[0] << "/"
            << countHist[2] << "/" << countHist[4]
            << "; worst non-real residual " << worstComplex << "; worst residual before Newton " << worstAlgebraic << "\n";
  CHECK(countHist[0] == 0);  // the original two pivots are always real
  CHECK(recovered == trials);
  CHECK(success == trials);
  CHECK(worstT < 1e-9);
  CHECK(worstA < 1e-9);
}

TEMPLATE_TEST_CASE("five arbitrary positions: every pair is exact, real + complex = 4", "[planar][synthesis]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(604);
  const int cases = std::is_same_v<S, mpreal> ? 2 : 10;
  for (int c = 0; c < cases; ++c) {
    const BurmesterSynthesis<S> bs(randomPositions<S>(g, 5));
    int cc = -1;
    S complexRes(1), algebraicRes(1);
    std::string notes;
    const auto pairs = bs.burmesterPairs(&cc, &complexRes, &algebraicRes, &notes);
    CHECK(int(pairs.size()) + cc == 4);
    CHECK(pairs.size() % 2 == 0);
    CHECK(complexRes <= tolFor<S>(1 << 14));
    CHECK(notes == (std::is_same_v<S, float> ? "conic intersection solved in double, pairs polished in float" : ""));
    for (const auto& p : pairs) CHECK(p.residual <= tolFor<S>(1 << 14));
    // second method: every Burmester centre lies on both centre-point cubics and every circle
    // point on both circle-point cubics; none is a pole P12, P13, P23 (the spurious intersections
    // of the cubics, which the two-conic formulation never produces); no pair is returned twice
    const Poly2<S> F4 = bs.centrePointCurve(4), F5 = bs.centrePointCurve(5);
    const Poly2<S> C4 = bs.circlePointCurve(4), C5 = bs.circlePointCurve(5);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const Vec2<S>& m = pairs[k].centre;
      const Vec2<S>& z = pairs[k].circle;
      CHECK(abs(F4(m(0), m(1))) <= tolFor<S>(1 << 14) * F4.magnitude(m(0), m(1)));
      CHECK(abs(F5(m(0), m(1))) <= tolFor<S>(1 << 14) * F5.magnitude(m(0), m(1)));
      CHECK(abs(C4(z(0), z(1))) <= tolFor<S>(1 << 14) * C4.magnitude(z(0), z(1)));
      CHECK(abs(C5(z(0), z(1))) <= tolFor<S>(1 << 14) * C5.magnitude(z(0), z(1)));
      for (const auto& ij : {std::pair<int, int>{1, 2}, {1, 3}, {2, 3}})
        CHECK((m - bs.pole(ij.first, ij.second)).norm() > Tolerance<S>::sqrtEpsilon() * bs.scale());
      for (std::size_t l = k + 1; l < pairs.size(); ++l)
        CHECK((m - pairs[l].centre).norm() + (z - pairs[l].circle).norm() > Tolerance<S>::sqrtEpsilon() * bs.scale());
    }
    if (pairs.size() >= 2) {
      const DriveCheck<S> dc = bs.drive(pairs[0], pairs[1]);
      // every position is reached by the linkage in some assembly mode (its circuit may differ)
      if (dc.reached) CHECK(dc.worstTranslation <= tolFor<S>(1 << 16));
    }
  }
}

TEST_CASE("five positions in float alone (escalateFloat = false): the pairs of the escalated float solve",
          "[planar][synthesis]") {
  // The same positions solved twice in float: with the conic intersection in double (default) and
  // in float; both polish in float, so where the counts agree the pairs agree to float's rounding
  // times the pair's conditioning κ: 16 √ε of the data scale holds for κ up to 16 / √ε ≈ 6.5e4.
  auto& g = rng(605);
  int agreed = 0;
  for (int c = 0; c < 10; ++c) {
    const BurmesterSynthesis<float> bs(randomPositions<float>(g, 5));
    std::string nd, nf;
    int cd = -1, cf = -1;
    const auto esc = bs.burmesterPairs(&cd, nullptr, nullptr, &nd);
    const auto alone = bs.burmesterPairs(&cf, nullptr, nullptr, &nf, false);
    CHECK(nf == "conic intersection solved in float (no escalation)");
    CHECK(int(alone.size()) + cf == 4);
    for (const auto& p : alone) CHECK(p.residual <= tolFor<float>(1 << 14));
    if (alone.size() != esc.size()) continue;
    ++agreed;
    for (const auto& p : alone) {
      float nearest = 1e30f;
      for (const auto& q : esc)
        nearest = std::min(nearest, float((p.centre - q.centre).norm() + (p.circle - q.circle).norm()));
      CHECK(nearest <= Tolerance<float>::sqrtEpsilon() * bs.scale() * 16);
    }
  }
  CHECK(agreed >= 9);  // a count may differ only on a near-tangent real/complex pair
}

TEST_CASE("synthesis: bad input", "[planar][synthesis][extremes]") {
  using S = double;
  CHECK_THROWS_AS(BurmesterSynthesis<S>({SE2<S>()}), InvalidInput);
  CHECK_THROWS_AS(BurmesterSynthesis<S>(std::vector<SE2<S>>(6, SE2<S>())), InvalidInput);
  CHECK_THROWS_AS(BurmesterSynthesis<S>({SE2<S>(), SE2<S>(0.5, Vec2<S>(1, 0)), SE2<S>()}), InvalidInput);
  const BurmesterSynthesis<S> four({SE2<S>(), SE2<S>(0.5, Vec2<S>(1, 0)), SE2<S>(1, Vec2<S>(1, 1)), SE2<S>(1.4, Vec2<S>(0, 2))});
  CHECK_THROWS_AS(four.burmesterPairs(), InvalidInput);
  // five pure translations: the linear system in (1, K, m, z, m·z, m×z) has rank 4 → InvalidInput;
  // the same translations with small distinct rotations (the other side) are solved exactly
  const Vec2<S> d[5] = {{0, 0}, {1, 0.2}, {1.7, 1.1}, {0.4, 2}, {-0.8, 1.3}};
  std::vector<SE2<S>> tr, rot;
  for (int i = 0; i < 5; ++i) {
    tr.push_back(SE2<S>(0, d[i]));
    rot.push_back(SE2<S>(0.05 * i * i - 0.1 * i, d[i]));
  }
  CHECK_THROWS_AS(BurmesterSynthesis<S>(tr).burmesterPairs(), InvalidInput);
  int cc = -1;
  const auto pairs = BurmesterSynthesis<S>(rot).burmesterPairs(&cc);
  CHECK(int(pairs.size()) + cc == 4);
  for (const auto& p : pairs) CHECK(p.residual <= 1e-13);
}

}  // namespace SOMA_UNITY_ID
