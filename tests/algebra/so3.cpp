// SO(3): the generic Lie-group property suite (lie_suite.hpp) at the identity, Random·1e-8,
// the edge angles, both sides of each Taylor switch and random rotations, for all five
// scalars; the book's values (hat map, commutators, Rodrigues, trace formula, Ad, dexp);
// rejection of bad input with a message naming the defect.
#include "lie_suite.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using Catch::Matchers::Contains;
using lie::maxAbs;

TEMPLATE_TEST_CASE("SO3 group properties over identity, 1e-8, edges, switches, random", "[so3]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(31);
  for (const auto& smp : lie::samples<SO3<S>>(g, std::is_same_v<S, mpreal> ? 3 : 30))
    lie::checkGroupProperties(smp, g);
}

TEMPLATE_TEST_CASE("SO3 matches the book: hat map, commutators, Rodrigues, trace, Ad, dexp",
                   "[so3]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::cos;
  using std::sin;
  const S eps = Tolerance<S>::epsilon();
  const S tol = S(16) * eps;
  // GF-4.3-so3-su2-commutators: hat(e_x) = X, hat(e_y) = Y, hat(e_z) = Z exactly (sign
  // convention of GF-4.1-hat-map, not the printed ε-formula, erratum E4.2).
  Mat3<S> X, Y, Z;
  X << 0, 0, 0, 0, 0, -1, 0, 1, 0;
  Y << 0, 0, 1, 0, 0, 0, -1, 0, 0;
  Z << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  const SO3Tangent<S> ex(Vec3<S>::UnitX()), ey(Vec3<S>::UnitY()), ez(Vec3<S>::UnitZ());
  CHECK(bool(ex.hat() == X));
  CHECK(bool(ey.hat() == Y));
  CHECK(bool(ez.hat() == Z));
  CHECK(bool(ex.ad() == X));
  CHECK(bool(Mat3<S>(X * Y - Y * X) == Z));
  CHECK(bool(Mat3<S>(Y * Z - Z * Y) == X));
  CHECK(bool(Mat3<S>(Z * X - X * Z) == Y));
  CHECK(bool(bracket(ex, ey).coeffs() == ez.coeffs()));
  CHECK(bool(SO3Tangent<S>::vee(Z).coeffs() == ez.coeffs()));
  auto& g = rng(5);
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> w = uniformVec<S, 3>(g), x = uniformVec<S, 3>(g);
    CHECK(maxAbs(Vec3<S>(skew(w) * x - w.cross(x))) <= tol);
    // GF-4.4.1-rodrigues, matrix and vector forms; GF-4.4.1-so3-idempotents: Ω³ + θ²Ω = 0.
    const SO3Tangent<S> t(w);
    const S th = t.angle();
    const Mat3<S> W = t.hat();
    CHECK(maxAbs(Mat3<S>(W * W * W + th * th * W)) <= tol);
    const Mat3<S> rod = Mat3<S>::Identity() + sin(th) / th * W + (S(1) - cos(th)) / (th * th) * W * W;
    CHECK(maxAbs(Mat3<S>(t.exp().matrix() - rod)) <= tol);
    const Vec3<S> vh = w / th;
    const Vec3<S> rv = x + sin(th) * vh.cross(x) + (S(1) - cos(th)) * vh.cross(vh.cross(x));
    CHECK(maxAbs(Vec3<S>(t.exp().act(x) - rv)) <= tol);
    // GF-4.4.1-so3-log-trace: Tr R = 1 + 2cos θ, log R = θ/(2 sin θ)(R − Rᵀ) (θ ∈ (0, π)).
    const Mat3<S> R = t.exp().matrix();
    CHECK(abs(R.trace() - (S(1) + S(2) * cos(th))) <= tol);
    const Mat3<S> logR = th / (S(2) * sin(th)) * (R - R.transpose());
    CHECK(maxAbs(Mat3<S>(t.exp().log().hat() - logR)) <= S(4) * tol / sin(th));
    // GF-4.2-adjoint-SO3: R Ω Rᵀ = hat(R ω), Ad(R) = R.
    const SO3<S> r = SO3<S>::Random(g);
    CHECK(maxAbs(Mat3<S>(r.matrix() * W * r.matrix().transpose() - skew<S>(r.matrix() * w))) <= tol);
    CHECK(bool(r.adjoint() == r.matrix()));
    // GF-4.5.3-so3-dexp-and-inverse: the closed forms, both printed inverse forms.
    const Mat3<S> dexp =
        Mat3<S>::Identity() + (S(1) - cos(th)) / (th * th) * W + (th - sin(th)) / (th * th * th) * W * W;
    CHECK(maxAbs(Mat3<S>(t.ljac() - dexp)) <= tol);
    const Mat3<S> inv1 = Mat3<S>::Identity() - W / S(2) +
                         (S(1) / (th * th) + sin(th) / (S(2) * th * (cos(th) - S(1)))) * W * W;
    const Mat3<S> inv2 = Mat3<S>::Identity() - W / S(2) +
                         (S(1) / (th * th) - cos(th / S(2)) / (S(2) * th * sin(th / S(2)))) * W * W;
    CHECK(maxAbs(Mat3<S>(t.ljacinv() - inv1)) <= S(4) * tol);
    CHECK(maxAbs(Mat3<S>(t.ljacinv() - inv2)) <= S(4) * tol);
  }
  // A half-turn from its matrix (1 + tr R = 0, chart 1 undefined): log = ±π e_x.
  Mat3<S> half;
  half << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const SO3Tangent<S> lh = SO3<S>::fromMatrix(half).log();
  CHECK(abs(abs(lh.coeffs().x()) - pi<S>()) <= S(4) * eps);
  CHECK(abs(lh.coeffs().y()) + abs(lh.coeffs().z()) == S(0));
  // 2π turn is the identity (GF-4.6-soup-plate: the quaternion is −1, the rotation I).
  const SO3<S> full = SO3Tangent<S>(Vec3<S>(S(0), S(0), S(2) * pi<S>())).exp();
  CHECK(full.isApprox(SO3<S>(), S(4) * eps));
  CHECK(full.quaternion().w() < S(0));
}

TEMPLATE_TEST_CASE("SO3 rejects bad input with a message naming the defect", "[so3]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  const S inf = std::numeric_limits<S>::infinity();
  CHECK_THROWS_WITH(SO3<S>::fromQuaternion(Quat<S>(nan, S(0), S(0), S(0))), Contains("NaN"));
  CHECK_THROWS_WITH(SO3<S>::fromQuaternion(Quat<S>(S(1), S(0), inf, S(0))), Contains("infinite"));
  // Defects above Tolerance::input() (≈ 0.022 for float: a fixed 1/10 component is not enough).
  CHECK_THROWS_WITH(SO3<S>::fromQuaternion(Quat<S>(S(1), S(0), S(0), S(1) / S(2))),
                    Contains("not unit"));
  CHECK_THROWS_WITH(SO3<S>::fromQuaternion(Quat<S>(S(1) + S(4) * Tolerance<S>::input(), S(0), S(0), S(0))),
                    Contains("not unit"));
  CHECK_THROWS_WITH(SO3<S>::fromQuaternion(Quat<S>(S(0), S(0), S(0), S(0))), Contains("not unit"));
  // Just inside the accepted defect: accepted and normalised.
  const S d = Tolerance<S>::input() / S(4);
  CHECK(SO3<S>::fromQuaternion(Quat<S>(S(1) + d, S(0), S(0), S(0))).quaternion().w() == S(1));
  const Mat3<S> R = SO3<S>::fromAxisAngle(Vec3<S>(S(0), S(3) / S(5), S(4) / S(5)), S(1)).matrix();
  Mat3<S> bad = R;
  bad(1, 2) = nan;
  CHECK_THROWS_WITH(SO3<S>::fromMatrix(bad), Contains("NaN"));
  bad = R;
  bad(0, 0) += S(4) * Tolerance<S>::input();
  CHECK_THROWS_WITH(SO3<S>::fromMatrix(bad), Contains("not orthogonal"));
  bad = R * S(11) / S(10);
  CHECK_THROWS_WITH(SO3<S>::fromMatrix(bad), Contains("not orthogonal"));
  bad = -R;  // orthogonal, det −1
  CHECK_THROWS_WITH(SO3<S>::fromMatrix(bad), Contains("det = −1"));
  CHECK_THROWS_WITH(SO3<S>::fromAxisAngle(Vec3<S>(S(1), S(1), S(0)), S(1)),
                    Contains("not a unit vector"));
  CHECK_THROWS_WITH(SO3<S>::fromAxisAngle(Vec3<S>(S(1), S(0), S(0)), nan), Contains("NaN"));
  CHECK_THROWS_WITH(SO3Tangent<S>(Vec3<S>(S(0), nan, S(0))).exp(), Contains("NaN"));
  CHECK_THROWS_WITH(rotationFromQuaternion(Quat<S>(S(0), S(0), S(0), S(0))),
                    Contains("zero quaternion"));
}

}  // namespace SOMA_UNITY_ID
