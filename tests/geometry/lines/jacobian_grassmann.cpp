// §6.7 inverse Jacobian by reciprocal lines and §6.8 Grassmannians.
#include "soma/geometry/lines/grassmannian.hpp"
#include "soma/geometry/lines/inverse_jacobian.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
template <class S> S tol(int ulps = 512) { return Tolerance<S>::identity(ulps); }

// A PUMA-like configuration: ω₁ = z, ω₂ ⟂ ω₁, elbow and wrist in the plane ⟂ ω₂ through o.
template <class S> PumaLikeArm<S> arm(std::mt19937_64& g) {
  PumaLikeArm<S> a;
  a.w1 = Vec3<S>::UnitZ();
  const S t = uniform<S>(g, -3, 3);
  using std::cos;
  using std::sin;
  a.w2 = Vec3<S>(cos(t), sin(t), S(0));
  const Vec3<S> e = a.w1.cross(a.w2);
  a.xe = uniform<S>(g, 0.3, 1) * (cos(uniform<S>(g)) * e + sin(uniform<S>(g)) * a.w1);
  a.xc = a.xe + uniform<S>(g, 0.3, 1) * (cos(uniform<S>(g, 1, 2)) * e + sin(uniform<S>(g, 1, 2)) * a.w1);
  a.w4 = (a.xc - a.xe).normalized();
  a.w5 = unitVec3<S>(g);
  a.w6 = unitVec3<S>(g);
  return a;
}
}  // namespace

TEMPLATE_TEST_CASE("Inverse Jacobian of the PUMA-like arm by reciprocal lines (GF-6.7)", "[lines][jacobian]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(41);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 3 : 30;
  for (int k = 0; k < n; ++k) {
    const PumaLikeArm<S> a = arm<S>(g);
    const Mat6<S> j = a.jacobian();
    const auto z = pumaLikeReciprocalLines(a);
    for (int i = 0; i < 6; ++i)
      for (int m = 0; m < 6; ++m)
        if (i != m) REQUIRE(abs(reciprocalProduct(z[i], Vec6<S>(j.col(m)))) <= tol<S>(4096) * S(16));
    const Mat6<S> w = inverseJacobianFromReciprocals(j, z);
    const S cond = S(1) + (j.inverse()).norm() * j.norm();
    REQUIRE((w * j - Mat6<S>::Identity()).norm() <= tol<S>(4096) * cond);
  }
}

TEST_CASE("Inverse Jacobian near the elbow singularity: both sides", "[lines][jacobian]") {
  auto& g = rng(42);
  PumaLikeArm<double> a = arm<double>(g);
  // Put x_c on the line o–x_e (collinear: elbow singular), then off it by δ.
  const Vec3<double> e = a.w1.cross(a.w2);
  a.xe = 0.7 * e;
  a.w4 = e;
  a.xc = 1.5 * e;
  REQUIRE_THROWS_AS(inverseJacobianFromReciprocals(a.jacobian(), pumaLikeReciprocalLines(a)), InvalidInput);
  a.xc = 1.5 * e + 1e-6 * a.w1;
  a.w4 = (a.xc - a.xe).normalized();
  const Mat6<double> w = inverseJacobianFromReciprocals(a.jacobian(), pumaLikeReciprocalLines(a));
  REQUIRE((w * a.jacobian() - Mat6<double>::Identity()).norm() <= 1e-6);
}

TEMPLATE_TEST_CASE("Grassmannians: Plücker relations, dimension (GF-6.8)", "[lines][grassmann]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using M = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  using V = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  auto& g = rng(43);
  REQUIRE(grassmannianDimension(2, 4) == 4);
  REQUIRE(grassmannianDimension(2, 6) == 8);
  REQUIRE(grassmannianDimension(3, 6) == 9);
  REQUIRE(grassmannianDimension(1, 5) == 4);  // G(1, m) = PR^(m−1) (E6.7)
  REQUIRE(pluckerIndexSets(3, 6).size() == 20);
  for (const int m : {4, 5, 6}) {
    M b(m, 2);
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < 2; ++c) b(i, c) = uniform<S>(g);
    const V p = pluckerEmbedding<S>(b);
    const V r = pluckerRelationsG2<S>(p, m);
    REQUIRE(r.size() == (m == 4 ? 1 : m == 5 ? 5 : 15));
    REQUIRE(r.cwiseAbs().maxCoeff() <= tol<S>(64));
    V q(p.size());
    for (int i = 0; i < q.size(); ++i) q(i) = uniform<S>(g);
    REQUIRE(pluckerRelationsG2<S>(q, m).cwiseAbs().maxCoeff() > S(1) / S(1000000));
  }
  // G(2, 4): the 4-vector points x = (1, q₁), y = (1, q₂) give the Klein quadric's line (E6.2).
  M b(4, 2);
  b << S(1), S(1), S(1), S(4), S(2), S(5), S(3), S(7);
  const V p = pluckerEmbedding<S>(b);  // p01 p02 p03 p12 p13 p23
  // ω = (p01, p02, p03) = q₂ − q₁, v = (p23, p31, p12) = q₁ × q₂.
  REQUIRE(abs(p(0) - S(3)) + abs(p(1) - S(3)) + abs(p(2) - S(4)) <= tol<S>());
  const Vec3<S> v = Vec3<S>(S(1), S(2), S(3)).cross(Vec3<S>(S(4), S(5), S(7)));
  REQUIRE(abs(p(5) - v(0)) + abs(-p(4) - v(1)) + abs(p(3) - v(2)) <= tol<S>());
}

}  // namespace SOMA_UNITY_ID
