// Chasles (GF §2.5.2): every rigid motion is a screw motion; screwOf recovers the axis, angle,
// pitch (per radian) and foot point of screwMotion, at the edges θ → 0, θ = π, pitch 0.
#include "soma/algebra/screw.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using Catch::Matchers::Contains;

namespace {
template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }
}

TEMPLATE_TEST_CASE("Chasles: screwOf inverts screwMotion", "[screw]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::cos;
  using std::sin;
  const S eps = Tolerance<S>::epsilon();
  auto& g = rng(101);
  const int n = std::is_same_v<S, mpreal> ? 5 : 50;
  for (int i = 0; i < n; ++i) {
    const Vec3<S> axis = unitVec3<S>(g);
    Vec3<S> u = uniformVec<S, 3>(g);
    const S pitch = i % 5 == 0 ? S(0) : uniform<S>(g, -2, 2);
    const S theta = uniform<S>(g, 0.05, 3.1);
    const SE3<S> X = screwMotion(axis, u, pitch, theta);
    // GF-2.5.2-screw-motion-matrix: [[R, θh â + (I − R)u], [0, 1]] and points of the axis
    // advance by θh â.
    CHECK(maxAbs(Vec3<S>(X.act(u) - (u + theta * pitch * axis))) <= S(16) * eps);
    const Screw<S> sc = screwOf(X);
    INFO("theta = " << toString(theta) << ", pitch = " << toString(pitch));
    CHECK_FALSE(sc.pureTranslation);
    CHECK(abs(sc.theta - theta) <= S(16) * eps);
    CHECK(maxAbs(Vec3<S>(sc.axis - axis)) <= S(32) * eps / sin(theta / S(2)));
    CHECK(abs(sc.pitch - pitch) <= S(64) * eps / sin(theta / S(2)));
    // The foot of the perpendicular from the origin: u minus its component along the axis.
    const Vec3<S> foot = u - u.dot(axis) * axis;
    CHECK(maxAbs(Vec3<S>(sc.point - foot)) <= S(64) * eps / sin(theta / S(2)));
    CHECK(abs(sc.point.dot(sc.axis)) <= S(64) * eps / sin(theta / S(2)));
    // Reconstruction and the moment convention v = q × ω + h ω (GF-4.1-se3-twist-velocity).
    CHECK(screwMotion(sc.axis, sc.point, sc.pitch, sc.theta).isApprox(X, S(64) * eps));
    const SE3Tangent<S> s = X.log();
    CHECK(maxAbs(Vec3<S>(s.lin() - (sc.point.cross(s.ang()) + sc.pitch * s.ang()))) <=
          S(64) * eps);
    // Book's per-turn pitch p = 2πh: the advance over θ is θp/2π.
    const S p = S(2) * pi<S>() * sc.pitch;
    CHECK(abs(theta * p / (S(2) * pi<S>()) - sc.translationDistance) <= S(64) * eps);
  }
  // θ = π: axis sign ambiguous, motion reproduced.
  const Vec3<S> ax(S(0), S(3) / S(5), S(4) / S(5));
  const SE3<S> half = screwMotion(ax, Vec3<S>(S(1), S(0), S(0)), S(1) / S(4), pi<S>());
  const Screw<S> hs = screwOf(half);
  CHECK(abs(hs.theta - pi<S>()) <= S(16) * eps);
  CHECK(abs(abs(hs.axis.dot(ax)) - S(1)) <= S(16) * eps);
  CHECK(screwMotion(hs.axis, hs.point, hs.pitch, hs.theta).isApprox(half, S(64) * eps));
  // A pure translation (and the identity).
  const SE3<S> tr(SO3<S>(), Vec3<S>(S(3), S(0), S(4)));
  const Screw<S> ts = screwOf(tr);
  CHECK(ts.pureTranslation);
  CHECK(abs(ts.translationDistance - S(5)) <= S(4) * eps);
  CHECK(maxAbs(Vec3<S>(ts.translationDirection - Vec3<S>(S(3) / S(5), S(0), S(4) / S(5)))) <=
        S(4) * eps);
  CHECK(screwOf(SE3<S>()).translationDistance == S(0));
  // Bad input.
  CHECK_THROWS_WITH(screwMotion(Vec3<S>(S(1), S(1), S(0)), Vec3<S>(Vec3<S>::Zero()), S(0), S(1)),
                    Contains("not a unit vector"));
  const S nan = std::numeric_limits<S>::quiet_NaN();
  CHECK_THROWS_WITH(screwMotion(ax, Vec3<S>(nan, S(0), S(0)), S(0), S(1)), Contains("NaN"));
}

// Issue 24: `soma pose` failed its own screw round trip on ordinary poses with rotation angles
// 1e-3 … 1e-12 in double. At a small angle θ the axis of a motion with an O(1) translation lies
// |u| ≈ |t|/θ away, and (I − R)u taken as u − Ru kept only |t|/|u| ≈ θ of u's digits. Rodrigues'
// form −sin θ â×u − 2 sin²(θ/2) â×(â×u) (GF §4.4.1) keeps them: the translation is exact to a few
// ulps of |t| against the same motion computed in mpfr at 512 bits from the same inputs.
TEMPLATE_TEST_CASE("screwMotion at small angles: (I − R)u to a few ulps of the translation",
                   "[screw][hostile]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using M = mpreal;
  using std::abs;
  const S eps = Tolerance<S>::epsilon();
  const int savedBits = mpfrBits();
  auto& g = rng(2024);
  for (const double th : {1e-3, 1e-5, 1e-7, 1e-9, 1e-12}) {
    for (int k = 0; k < 8; ++k) {
      const Vec3<S> axis = unitVec3<S>(g);
      const Vec3<S> w = uniformVec<S, 3>(g);
      const S theta = scalarCast<S>(th) * uniform<S>(g, 0.5, 2);
      const Vec3<S> u = Vec3<S>(axis.cross(w)) / theta;  // the axis |w|/θ from the origin: |t| = O(1)
      const S pitch = uniform<S>(g, -1, 1) / theta;         // an O(1) advance θh along the axis
      const SE3<S> X = screwMotion(axis, u, pitch, theta);
      setMpfrBits(512);
      auto hi = [](const S& x) {  // x exactly, at 512 bits (an mpreal copy keeps its own precision)
        M y = scalarCast<M>(x);
        y.setPrecision(512);
        return y;
      };
      const Vec3<M> am(hi(axis(0)), hi(axis(1)), hi(axis(2))), um(hi(u(0)), hi(u(1)), hi(u(2)));
      const M tm = hi(theta), hm = hi(pitch);
      const Vec3<M> a = am / sqrt(am.squaredNorm());
      const Vec3<M> ref = tm * hm * a + um - SO3<M>::fromAxisAngle(a, tm).act(um);  // u − Ru at 512 bits
      const M scale = sqrt(ref.squaredNorm()) + abs(tm) * sqrt(um.squaredNorm());
      const M err = sqrt(Vec3<M>(castMatrix<M>(X.translation()) - ref).squaredNorm()) / scale;
      setMpfrBits(savedBits);
      INFO("theta = " << th << ", error in ulps of |t| = " << toDouble(err) / toDouble(eps));
      CHECK(toDouble(err) <= 16 * toDouble(eps));
    }
    // The round trip of `soma pose`: an ordinary pose (R about a unit axis by θ, t of size 1) back
    // through screwOf and screwMotion, within its tolerance Tolerance::identity()·(1 + |t|∞)
    // (an angle below 64 eps is a pure translation for screwOf: float at 1e-7 and below).
    if (!(scalarCast<S>(th) > S(64) * eps)) continue;
    const Vec3<S> axis = unitVec3<S>(g);
    const Vec3<S> t = uniformVec<S, 3>(g);
    const SE3<S> X(SO3<S>::fromAxisAngle(axis, scalarCast<S>(th)), t);
    const Screw<S> sc = screwOf(X);
    REQUIRE_FALSE(sc.pureTranslation);
    const SE3<S> Y = screwMotion(sc.axis, sc.point, sc.pitch, sc.theta);
    const S tol = Tolerance<S>::identity() * (S(1) + t.template lpNorm<Eigen::Infinity>());
    INFO("theta = " << th);
    CHECK(maxAbs(Mat4<S>(Y.matrix() - X.matrix())) <= tol);
  }
}

}  // namespace SOMA_UNITY_ID
