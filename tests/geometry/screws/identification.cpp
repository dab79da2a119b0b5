// Gibson–Hunt identification (GF ch. 8): randomly posed normal forms of every class (random SE3,
// random basis change) recover type, parameters and frame; 4- and 5-systems through their
// reciprocals; both sides of every type boundary.
#include "soma/geometry/screws/identification.hpp"

#include "../../support/scalars.hpp"

#include <functional>
#include <iostream>
#include <map>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using T = ScrewSystemType;
using std::abs;

namespace {

const std::vector<T> kTypes = {T::Line,   T::Screw,  T::Translation, T::IIC_2,  T::IB0sup_2, T::IIA0_2,
                               T::IIBp_2, T::IIB0_2, T::IBp_2,       T::IIAp_2, T::IA_2,     T::IID_3,
                               T::IIA0_3, T::IIC0_3, T::IICp_3,      T::ICp_3,  T::IC0_3,    T::IIB_3,
                               T::IB0_3,  T::IB3_3,  T::IIAp_3,      T::IA2_3,  T::IA1_3};

/// Parameters satisfying the type's conventions (ordering, signs), |p| in [0.2, 2].
template <class S> std::array<S, 3> randomParams(T t, std::mt19937_64& g) {
  auto mag = [&]() { return uniform<S>(g, 0.2, 2.0); };
  auto sgn = [&]() { return uniform<S>(g) < S(0) ? S(-1) : S(1); };
  std::array<S, 3> p{};
  switch (t) {
    case T::Screw: case T::IIBp_2: case T::IIAp_2: case T::IICp_3: case T::IIB_3: case T::IIAp_3:
      p[0] = sgn() * mag();
      break;
    case T::IBp_2: case T::ICp_3: p[0] = mag(); break;
    case T::IA_2: case T::IB3_3: {
      const S a = sgn() * mag();
      p = {a, a - mag(), S(0)};
      break;
    }
    case T::IB0_3: p = {sgn() * mag(), mag(), S(0)}; break;
    case T::IA2_3: p = {sgn() * mag(), sgn() * mag(), S(0)}; if (abs(p[0] - p[1]) < S(2) / S(10)) p[1] += S(1); break;
    case T::IA1_3: {
      const S a = sgn() * mag();
      const S b = a - mag();
      p = {a, b, b - mag()};
      break;
    }
    default: break;
  }
  return p;
}

template <class S> ScrewMatX<S> randomBasisChange(int n, std::mt19937_64& g) {
  ScrewMatX<S> m(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m(i, j) = uniform<S>(g, -0.5, 0.5) + (i == j ? S(2) : S(0));
  return m;
}

template <class S> ScrewMatX<S> posed(T t, const std::array<S, 3>& p, const SE3<S>& g, std::mt19937_64& rg) {
  const ScrewBasis<S> nf = screwSystemNormalForm<S>(t, p);
  return ScrewMatX<S>(g.adjoint() * nf) * randomBasisChange<S>(int(nf.cols()), rg);
}

template <class S> S paramTolerance() { return Tolerance<S>::identity(8192); }

template <class S> void recoverAll(int trials, std::map<std::string, int>* counts) {
  auto& g = rng(8001);
  for (T t : kTypes) {
    for (int k = 0; k < trials; ++k) {
      const std::array<S, 3> p = randomParams<S>(t, g);
      const SE3<S> pose = SE3<S>::Random(g);
      const ScrewMatX<S> gen = posed<S>(t, p, pose, g);
      const ScrewSystem<S> sys(gen);
      const int n = screwSystemTypeDimension(t);
      REQUIRE(sys.dimension() == n);
      for (int via = 0; via < 2; ++via) {  // the system, then its reciprocal (dimension 6 − n)
        const ScrewSystem<S> s = via ? sys.reciprocal() : sys;
        const auto id = identifyScrewSystem(s);
        INFO(screwSystemTypeName(t) << " trial " << k << " via reciprocal " << via << ": found " << id.name());
        REQUIRE(id.dimension == (via ? 6 - n : n));
        REQUIRE(id.viaReciprocal == (via && n < 3));
        if (via && n == 3) {
          // The reciprocal of a 3-system is a 3-system of the same type (GF-8.3-reciprocal-3-systems);
          // pitches change sign (IA₁: −p_a, −p_b, −p_c), so only the type is compared here.
          CHECK(screwSystemTypeName(id.type) == screwSystemTypeName(t));
          if (screwSystemTypeName(id.type) == screwSystemTypeName(t) && counts) ++(*counts)[screwSystemTypeName(t) + " (3, reciprocal)"];
          continue;
        }
        REQUIRE(id.type == t);
        REQUIRE(id.parameterCount == screwSystemTypeParameterCount(t));
        for (int i = 0; i < id.parameterCount; ++i)
          CHECK(abs(id.parameters[std::size_t(i)] - p[std::size_t(i)]) <= paramTolerance<S>() * S(4));
        CHECK(id.frameResidual <= paramTolerance<S>());
        // The frame maps the normal form onto the input: compare with the input directly.
        const ScrewSystem<S> back(ScrewMatX<S>(id.frame.adjoint() * id.normalForm));
        CHECK(back.distanceTo(s) <= paramTolerance<S>());
        if (counts) ++(*counts)[std::to_string(id.dimension) + "-system " + screwSystemTypeName(t)];
      }
    }
  }
}

}  // namespace

TEST_CASE("identification recovers randomly posed normal forms of every Gibson–Hunt class (double)",
          "[screws][identify]") {
  std::map<std::string, int> counts;
  recoverAll<double>(40, &counts);
  std::cout << "Recovered per class (double, 40 random poses and bases each):\n";
  int total = 0;
  for (const auto& [k, v] : counts) {
    std::cout << "  " << k << ": " << v << "\n";
    total += v;
  }
  std::cout << "  total " << total << "\n";
  CHECK(total == 40 * 2 * int(kTypes.size()));
}

TEMPLATE_TEST_CASE("identification recovers every class, other scalars", "[screws][identify]", float,
                   long double, __float128) {
  std::map<std::string, int> counts;
  recoverAll<TestType>(6, &counts);
  int total = 0;
  for (const auto& kv : counts) total += kv.second;
  CHECK(total == 6 * 2 * int(kTypes.size()));
}

TEST_CASE("identification recovers every class, mpfr", "[screws][identify][mpfr]") {
  std::map<std::string, int> counts;
  recoverAll<mpfr::mpreal>(1, &counts);
  int total = 0;
  for (const auto& kv : counts) total += kv.second;
  CHECK(total == 2 * int(kTypes.size()));
}

// ---- both sides of every type boundary ----------------------------------------------------
namespace {
template <class S> struct Family {
  const char* quantity;  // substring of the deciding quantity
  T below, above;        // type at δ = tol/30 and at δ = 30 tol
  std::function<ScrewMatX<S>(const S&)> gen;
};

template <class S> std::vector<Family<S>> families() {
  auto col = [](std::initializer_list<std::initializer_list<double>> cols) {
    ScrewMatX<S> m(6, Eigen::Index(cols.size()));
    int j = 0;
    for (const auto& c : cols) {
      int i = 0;
      for (double x : c) m(i++, j) = scalarCast<S>(x);
      ++j;
    }
    return m;
  };
  const S h = S(3) / S(10);
  std::vector<Family<S>> f;
  f.push_back({"p_a − p_b", T::IIAp_2, T::IA_2, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}});
                 m(3, 0) = h + d; m(4, 1) = h; return m; }});
  f.push_back({"|p|", T::IIA0_2, T::IIAp_2, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}});
                 m(3, 0) = d; m(4, 1) = d; return m; }});
  f.push_back({"sine", T::IB0sup_2, T::IBp_2, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 0, 0, 1, 0, 0}});
                 m(4, 1) = d; return m; }});
  f.push_back({"cosine", T::IIB0_2, T::IBp_2, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0}});
                 m(3, 1) = d; return m; }});
  f.push_back({"|p|", T::IIB0_2, T::IIBp_2, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0}});
                 m(3, 0) = d; return m; }});
  f.push_back({"singular value", T::IIC_2, T::IIB0_2, [=](const S& d) {
                 ScrewMatX<S> m = col({{0, 0, 0, 1, 0, 0}, {0, 0, 0, 0, 1, 0}});
                 m(2, 0) = d; return m; }});
  f.push_back({"p_a − p_b", T::IA2_3, T::IA1_3, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 1, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}});
                 m(4, 1) = d; return m; }});
  f.push_back({"p_a − p_b", T::IIAp_3, T::IA2_3, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}});
                 m(3, 0) = h + d; m(4, 1) = h; m(5, 2) = h; return m; }});
  f.push_back({"p_a − p_b", T::IIB_3, T::IB3_3, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 1}});
                 m(3, 0) = h + d; m(4, 1) = h; return m; }});
  f.push_back({"|t_W|", T::IB3_3, T::IB0_3, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 1}});
                 m(3, 0) = h; m(4, 1) = -h; m(3, 2) = d; return m; }});
  f.push_back({"sine", T::IC0_3, T::ICp_3, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 0, 0}});
                 m(5, 2) = d; return m; }});
  f.push_back({"|ω_T|", T::IICp_3, T::ICp_3, [=](const S& d) {
                 ScrewMatX<S> m = col({{1, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 1}});
                 m(3, 0) = h; m(3, 2) = d; return m; }});
  f.push_back({"|p|", T::Line, T::Screw, [=](const S& d) {
                 ScrewMatX<S> m = col({{0, 0, 1, 0, 0, 0}});
                 m(5, 0) = d; return m; }});
  return f;
}

template <class S> void bothSides() {
  auto& g = rng(8002);
  for (const auto& fam : families<S>()) {
    const SE3<S> pose = SE3<S>::Random(g);
    auto run = [&](const S& d) {
      return identifyScrewSystem(ScrewSystem<S>(ScrewMatX<S>(pose.adjoint() * fam.gen(d))));
    };
    const auto base = run(S(0));
    S tol(-1);
    for (const auto& dec : base.decisions)
      if (dec.quantity.find(fam.quantity) != std::string::npos) tol = dec.tolerance;
    INFO("family " << screwSystemTypeName(fam.below) << " | " << screwSystemTypeName(fam.above));
    REQUIRE(tol > S(0));
    REQUIRE(base.type == fam.below);
    const auto lo = run(tol / S(30)), hi = run(tol * S(30));
    INFO("below: " << lo.name() << ", above: " << hi.name());
    CHECK(lo.type == fam.below);
    CHECK(lo.nearestOtherType == fam.above);
    CHECK(hi.type == fam.above);
    // IB → IIB: every IIB(h) lies at the same distance (the pitch of the screws about ω in an IB
    // system takes every value), so the flipped decision may land on IIB(p=0) or IIB(p≠0).
    if (fam.below == T::IIB0_2)
      CHECK((hi.nearestOtherType == T::IIB0_2 || hi.nearestOtherType == T::IIBp_2));
    else
      CHECK(hi.nearestOtherType == fam.below);
    CHECK(lo.boundaryDistance <= tol);
    CHECK(hi.boundaryDistance > tol);
  }
}
}  // namespace

TEMPLATE_TEST_CASE("near a type boundary: the type on each side and the nearest other type",
                   "[screws][boundary]", float, double, long double, __float128, mpfr::mpreal) {
  bothSides<TestType>();
}

TEMPLATE_TEST_CASE("identification of degenerate and trivial systems", "[screws][identify]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const auto z = identifyScrewSystem(ScrewSystem<S>(ScrewMatX<S>::Zero(6, 3)));
  CHECK(z.type == T::Zero);
  CHECK(z.dimension == 0);
  const auto w = identifyScrewSystem(ScrewSystem<S>(ScrewMatX<S>(Mat6<S>::Identity())));
  CHECK(w.type == T::Whole);
  // Four generators spanning a 2-system (duplicates and a combination): IA from its rank-2 span.
  ScrewMatX<S> m(6, 4);
  m.setZero();
  m(0, 0) = S(1); m(3, 0) = S(1) / S(2);
  m(1, 1) = S(1); m(4, 1) = -S(1) / S(4);
  m.col(2) = m.col(0) * S(3);
  m.col(3) = m.col(0) - m.col(1);
  const auto id = identifyScrewSystem(m);
  CHECK(id.type == T::IA_2);
  CHECK(abs(id.parameters[0] - S(1) / S(2)) <= Tolerance<S>::identity(256));
  CHECK(abs(id.parameters[1] + S(1) / S(4)) <= Tolerance<S>::identity(256));
  ScrewMatX<S> bad = m;
  bad(2, 1) = std::numeric_limits<S>::quiet_NaN();
  CHECK_THROWS_AS(identifyScrewSystem(bad), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
