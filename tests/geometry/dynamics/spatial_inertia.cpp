// The 6×6 screw formulation (GF §13.1–13.2.1, SB §2): spatial inertia, its transformation under
// SE(3) against the direct parallel-axis computation, coadjoint duality, the equation of motion.
// (The free tumbling body is in free_body.cpp.)
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;

namespace {
template <class S> SpatialInertia<S> randomBody(std::mt19937_64& g) {
  const S m = uniform<S>(g, 0.5, 3);
  const Vec3<S> d = uniformVec<S, 3>(g, 0.3, 2);
  const Vec3<S> c = uniformVec<S, 3>(g, -1, 1);
  const Mat3<S> R = SO3<S>::Random(g).matrix();
  return SpatialInertia<S>(m, c, Mat3<S>(R * d.asDiagonal() * R.transpose()));
}
template <class S> S relMax(const Mat6<S>& a, const Mat6<S>& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}
}  // namespace

TEMPLATE_TEST_CASE("spatial inertia: skew-axis theorem equals the direct parallel-axis move",
                   "[dynamics]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1301);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 50;
  const S tol = Tolerance<S>::identity(256);
  for (int k = 0; k < n; ++k) {
    const SpatialInertia<S> b = randomBody<S>(g);
    const SE3<S> x(SO3<S>::Random(g), uniformVec<S, 3>(g, -2, 2));
    // GF §13.1: N' = H^{-T} N H^{-1}; direct: c' = R c + t, I_c' = R I_c R^T, then [[I,mC],[mC^T,m]].
    REQUIRE(relMax(coadjointTransform(x, b.matrix()), b.transformed(x).matrix()) <= tol);
    // kinetic energy is invariant: ½ (Hs)^T N' (Hs) = ½ s^T N s
    const SE3Tangent<S> s(uniformVec<S, 6>(g));
    const SE3Tangent<S> hs(Vec6<S>(x.adjoint() * s.coeffs()));
    using std::abs;
    REQUIRE(abs(b.transformed(x).kineticEnergy(hs) - b.kineticEnergy(s)) <= tol * b.kineticEnergy(s) * S(4));
    // the momentum formula of GF §13.1 is the matrix product
    REQUIRE((b.momentum(s) - b.matrix() * s.coeffs()).cwiseAbs().maxCoeff() <= tol * b.matrix().cwiseAbs().maxCoeff());
    // read back, and composite bodies add their 6×6 inertias
    REQUIRE(relMax(SpatialInertia<S>::fromMatrix(b.matrix()).matrix(), b.matrix()) <= tol);
    const SpatialInertia<S> b2 = randomBody<S>(g);
    REQUIRE(relMax((b + b2).matrix(), Mat6<S>(b.matrix() + b2.matrix())) <= tol);
  }
}

TEST_CASE("spatial inertia: translation by t_x is the printed parallel-axis matrix (SB §5)", "[dynamics]") {
  // SB-5-translated-inertia-example: d = (1.3, 0.7, 2.1), m = 3, t_x = 0.8.
  const double m = 3, tx = 0.8;
  const auto b = SpatialInertia<double>::diagonal(m, Vec3<double>(1.3, 0.7, 2.1));
  const SE3<double> x(SO3<double>::Identity(), Vec3<double>(tx, 0, 0));
  Mat6<double> printed;
  printed << 1.3, 0, 0, 0, 0, 0,  //
      0, 0.7 + m * tx * tx, 0, 0, 0, -m * tx,  //
      0, 0, 2.1 + m * tx * tx, 0, m * tx, 0,  //
      0, 0, 0, m, 0, 0,  //
      0, 0, m * tx, 0, m, 0,  //
      0, -m * tx, 0, 0, 0, m;
  REQUIRE((b.transformed(x).matrix() - printed).cwiseAbs().maxCoeff() <= 1e-15);
  REQUIRE((coadjointTransform(x, b.matrix()) - printed).cwiseAbs().maxCoeff() <= 1e-15);
}

TEMPLATE_TEST_CASE("coadjoint action is dual to the Lie bracket — equation of motion", "[dynamics]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1302);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 50;
  const S tol = Tolerance<S>::identity(256);
  for (int k = 0; k < n; ++k) {
    const SE3Tangent<S> s1(uniformVec<S, 6>(g)), s2(uniformVec<S, 6>(g));
    const Vec6<S> P = uniformVec<S, 6>(g);
    using std::abs;
    // SB §2: s1^T {s2, P} = [s1, s2]^T P  (GF §13.1: {s2, M}(s1) = M([s1, s2]))
    const Vec6<S> br = s1.ad() * s2.coeffs();
    REQUIRE(abs(s1.coeffs().dot(coadjoint(s2, P)) - br.dot(P)) <= tol);
    // {s, P} = -ad(s)^T P
    REQUIRE((coadjoint(s1, P) + s1.ad().transpose() * P).cwiseAbs().maxCoeff() <= tol);
    // the acceleration satisfies N ṡ + {s, N s} = W
    const SpatialInertia<S> b = randomBody<S>(g);
    const Mat6<S> N = b.matrix();
    const Vec6<S> W = uniformVec<S, 6>(g);
    const SE3Tangent<S> sd = rigidBodyAcceleration(N, s1, W);
    const Vec6<S> res = N * sd.coeffs() + coadjoint(s1, Vec6<S>(N * s1.coeffs())) - W;
    REQUIRE(res.cwiseAbs().maxCoeff() <= tol * S(16) * N.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("spatial inertia: bad input is rejected with a message", "[dynamics]") {
  REQUIRE_THROWS_AS(SpatialInertia<double>(-1, Vec3<double>::Zero(), Mat3<double>::Identity()), InvalidInput);
  REQUIRE_THROWS_AS(SpatialInertia<double>(1, Vec3<double>::Zero(), Mat3<double>(-Mat3<double>::Identity())),
                    InvalidInput);
  Mat3<double> ns = Mat3<double>::Identity();
  ns(0, 1) = 0.5;
  REQUIRE_THROWS_AS(SpatialInertia<double>(1, Vec3<double>::Zero(), ns), InvalidInput);
  Mat6<double> N = SpatialInertia<double>::diagonal(2, Vec3<double>(1, 1, 1)).matrix();
  N(3, 4) = 0.3;
  N(4, 3) = 0.3;
  REQUIRE_THROWS_AS(SpatialInertia<double>::fromMatrix(N), InvalidInput);
  REQUIRE_THROWS_AS(rigidBodyAcceleration(Mat6<double>(-Mat6<double>::Identity()), SE3Tangent<double>(),
                                          Vec6<double>(Vec6<double>::Zero())),
                    InvalidInput);
}

}  // namespace SOMA_UNITY_ID
