// ScrewSystem: rank, reciprocal (dimension 6 − n, double reciprocal, Ad-equivariance), union and
// intersection (dimensions, de Morgan, non-transversal pairs), isotropy and completion dimensions
// of the Table 8.1/8.2 normal forms (GF §8.1–8.3, §8.5).
#include "soma/geometry/screws/identification.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using T = ScrewSystemType;

namespace {
template <class S> ScrewMatX<S> randomGenerators(int n, std::mt19937_64& g) {
  ScrewMatX<S> m(6, n);
  for (int j = 0; j < n; ++j) m.col(j) = uniformVec<S, 6>(g);
  return m;
}
template <class S> S tightTol() { return Tolerance<S>::identity(1024); }
}  // namespace

TEMPLATE_TEST_CASE("reciprocal system: dimension 6 − n, reciprocal of reciprocal, Ad-equivariance",
                   "[screws][reciprocal]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(8101);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 1 : 4;
  for (int k = 0; k < trials; ++k)
    for (int n = 0; n <= 6; ++n) {
      const ScrewSystem<S> d(randomGenerators<S>(n, g));
      REQUIRE(d.dimension() == n);
      const ScrewSystem<S> r = d.reciprocal();
      CHECK(r.dimension() == 6 - n);
      S worst(0);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < 6 - n; ++j)
          worst = std::max<S>(worst, abs(reciprocalProduct<S>(d.basis().col(i), r.basis().col(j))));
      CHECK(worst <= tightTol<S>());
      CHECK(r.reciprocal().distanceTo(d) <= tightTol<S>());
      const SE3<S> x = SE3<S>::Random(g);
      CHECK(d.transformed(x).reciprocal().distanceTo(r.transformed(x)) <= tightTol<S>() * S(16));
    }
}

TEMPLATE_TEST_CASE("union and intersection: dimensions, containment, de Morgan", "[screws][union]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(8102);
  for (int i = 1; i <= 5; ++i)
    for (int j = 1; j <= 5; ++j) {
      const ScrewSystem<S> a(randomGenerators<S>(i, g)), b(randomGenerators<S>(j, g));
      const ScrewSystem<S> u = unionOf(a, b), c = intersectionOf(a, b);
      CHECK(u.dimension() == std::min(6, i + j));
      CHECK(c.dimension() == std::max(0, i + j - 6));
      for (int k = 0; k < c.dimension(); ++k) {
        CHECK(a.residualOf(c.basis().col(k)) <= tightTol<S>() * S(16));
        CHECK(b.residualOf(c.basis().col(k)) <= tightTol<S>() * S(16));
      }
      CHECK(unionOf(a, b).reciprocal().distanceTo(intersectionOf(a.reciprocal(), b.reciprocal())) <=
            tightTol<S>() * S(16));
    }
  // Non-transversal: two 3-systems sharing a screw meet in a 1-system (the generic count is 0).
  ScrewMatX<S> ga = randomGenerators<S>(3, g), gb = randomGenerators<S>(3, g);
  gb.col(0) = ga.col(0) * S(2) - ga.col(1);
  const ScrewSystem<S> a(ga), b(gb);
  const ScrewSystem<S> c = intersectionOf(a, b);
  CHECK(c.dimension() == 1);
  CHECK(unionOf(a, b).dimension() == 5);
  CHECK(c.residualOf(Vec6<S>(gb.col(0))) <= tightTol<S>() * S(16));
}

TEMPLATE_TEST_CASE("rank decisions on nearly dependent generators, both sides", "[screws][rank]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(8103);
  ScrewMatX<S> m = randomGenerators<S>(3, g);
  const Vec6<S> e = uniformVec<S, 6>(g);
  const S tol = Tolerance<S>::rank();
  m.col(2) = (m.col(0) + m.col(1)) / S(2);
  CHECK(ScrewSystem<S>(m).dimension() == 2);
  ScrewMatX<S> lo = m, hi = m;
  lo.col(2) += e * (tol / S(100));
  hi.col(2) += e * (tol * S(100));
  CHECK(ScrewSystem<S>(lo).dimension() == 2);
  CHECK(ScrewSystem<S>(hi).dimension() == 3);
  CHECK(ScrewSystem<S>(lo).droppedRatio() <= tol);
  // A zero generator is skipped; a NaN is rejected.
  ScrewMatX<S> z = ScrewMatX<S>::Zero(6, 2);
  z(0, 1) = S(1);
  CHECK(ScrewSystem<S>(z).dimension() == 1);
  z(1, 0) = std::numeric_limits<S>::infinity();
  CHECK_THROWS_AS(ScrewSystem<S>(z), InvalidInput);
  CHECK_THROWS_AS(ScrewSystem<S>(ScrewMatX<S>::Zero(5, 2)), InvalidInput);
}

// GF-8.1-derived-systems-completion and GF-8.2-isotropy-algebra: the catalogue's (checked)
// completion and isotropy-algebra dimensions of every normal form.
TEMPLATE_TEST_CASE("completion and isotropy-algebra dimensions of the normal forms", "[screws][completion]",
                   float, double, long double, __float128, mpfr::mpreal) {
  using S = TestType;
  const S p = S(7) / S(10), q = -S(3) / S(10), r = S(11) / S(10);
  struct Row { T t; std::array<S, 3> prm; int completion; int isotropy; };
  const std::vector<Row> rows = {
      {T::IIC_2, {}, 2, 4},        {T::IB0sup_2, {}, 2, 2},     {T::IIA0_2, {}, 3, 1},
      {T::IIBp_2, {p}, 3, 2},      {T::IIB0_2, {}, 3, 2},       {T::IBp_2, {p}, 4, 1},
      {T::IIAp_2, {p}, 6, 1},      {T::IA_2, {p, q}, 6, 0},     {T::IID_3, {}, 3, 6},
      {T::IIA0_3, {}, 3, 3},       {T::IIC0_3, {}, 3, 4},       {T::IICp_3, {p}, 3, 4},
      {T::ICp_3, {p}, 4, 2},       {T::IC0_3, {}, 4, 2},        {T::IIB_3, {p}, 6, 3},
      {T::IB3_3, {p, q}, 6, 2},    {T::IB0_3, {p, q}, 6, 0},    {T::IIAp_3, {p}, 6, 3},
      {T::IA2_3, {p, q}, 6, 1},    {T::IA1_3, {r, p, q}, 6, 0}};
  for (const auto& row : rows) {
    INFO(screwSystemTypeName(row.t));
    const ScrewSystem<S> d(ScrewMatX<S>(screwSystemNormalForm<S>(row.t, row.prm)));
    CHECK(completion(d).dimension() == row.completion);
    CHECK(isotropyAlgebra(d).dimension() == row.isotropy);
  }
}

TEMPLATE_TEST_CASE("wedge: Plücker coordinates scale by det M under a basis change", "[screws][wedge]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(8104);
  for (int n = 1; n <= 5; ++n) {
    const ScrewMatX<S> a = randomGenerators<S>(n, g);
    ScrewMatX<S> m(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) m(i, j) = uniform<S>(g);
    const auto w = wedge<S>(a), wm = wedge<S>(ScrewMatX<S>(a * m));
    ScrewMatX<S> mm = ScrewMatX<S>::Zero(6, n);
    mm.topRows(n) = m;
    const S detm = wedge<S>(mm)(0);  // the leading minor of [M; 0] is det M
    CHECK((wm - w * detm).template lpNorm<Eigen::Infinity>() <= Tolerance<S>::identity(256) * S(8));
  }
}

}  // namespace SOMA_UNITY_ID
