// Oriented flags of R⁴ and the stereographic projection (GF §11.1): round trips, the frame of a
// flag, the orthonormality threshold on both sides, the centre of projection.
#include "soma/geometry/study/oriented_flag.hpp"

#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using std::abs;
using std::cos;
using std::sin;
using std::sqrt;

TEMPLATE_TEST_CASE("stereographic projection: round trips on S³ and R³", "[flag]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = soma::test::rng(1111);
  for (int n = 0; n < 50; ++n) {
    Vec3<S> u = soma::test::uniformVec<S, 3>(g, -20, 20);
    const Vec4<S> p = inverseStereographicProjection<S>(u);
    CHECK(abs(p.squaredNorm() - S(1)) <= Tolerance<S>::identity(16));
    CHECK((stereographicProjection<S>(p) - u).norm() <= Tolerance<S>::identity(256) * (S(1) + u.norm()));
  }
  CHECK_THROWS_WITH(stereographicProjection<S>(Vec4<S>(S(0), S(0), S(0), S(-1))), Catch::Contains("centre of projection"));
}

TEMPLATE_TEST_CASE("oriented flags: frames are right-handed and the home flag is the identity", "[flag]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const OrientedFlag<S> home(Vec4<S>::Unit(3), Vec4<S>::Unit(0), Vec4<S>::Unit(1));
  CHECK((home.soma().matrix() - Mat4<S>::Identity()).cwiseAbs().maxCoeff() <= Tolerance<S>::identity(16));
  CHECK(abs(home.so4().determinant() - S(1)) <= Tolerance<S>::identity(16));
  // A flag moved by a rotation of the (x, w) plane by angle t: the origin is pr(e1) = (2 sin t/(1 + cos t), 0, 0).
  for (double td : {0.3, 2.0, 3.1}) {
    const S t = scalarCast<S>(td);
    const OrientedFlag<S> f(Vec4<S>(sin(t), S(0), S(0), cos(t)), Vec4<S>(cos(t), S(0), S(0), -sin(t)), Vec4<S>::Unit(1));
    const SE3<S> m = f.soma();
    CHECK(abs(m.translation()(0) - S(2) * sin(t) / (S(1) + cos(t))) <= Tolerance<S>::identity(256) * (S(1) + m.translation().norm()));
    CHECK(abs(m.rotation().determinant() - S(1)) <= Tolerance<S>::identity(64));
  }
}

TEMPLATE_TEST_CASE("oriented flags: orthonormality threshold on both sides, e1 = −w refused", "[flag]", double, __float128,
                   mpfr::mpreal) {
  using S = TestType;
  const S in = Tolerance<S>::input() / S(4), out = Tolerance<S>::input() * S(4);
  CHECK_NOTHROW(OrientedFlag<S>(Vec4<S>::Unit(0), Vec4<S>(in, S(1), S(0), S(0)), Vec4<S>::Unit(2)));
  CHECK_THROWS_WITH(OrientedFlag<S>(Vec4<S>::Unit(0), Vec4<S>(out, S(1), S(0), S(0)), Vec4<S>::Unit(2)),
                    Catch::Contains("not orthonormal"));
  const OrientedFlag<S> bad(-Vec4<S>::Unit(3), Vec4<S>::Unit(0), Vec4<S>::Unit(1));
  CHECK_FALSE(bad.isSoma());
  CHECK_THROWS_WITH(bad.soma(), Catch::Contains("not a soma"));
  // The pole threshold on both sides: 1 + w = threshold/2 is the centre, 2·threshold is not.
  for (const S& delta : {OrientedFlag<S>::poleThreshold() / S(2), OrientedFlag<S>::poleThreshold() * S(2)}) {
    const OrientedFlag<S> f(Vec4<S>(sqrt(delta * (S(2) - delta)), S(0), S(0), delta - S(1)), Vec4<S>::Unit(1), Vec4<S>::Unit(2));
    CHECK(f.isSoma() == (delta > OrientedFlag<S>::poleThreshold()));
  }
  // e1 just off −w: a soma, far away (|origin| = 2 sin t/(1 − cos t) ≈ 4/t).
  const S t = scalarCast<S>(1e-5);
  const OrientedFlag<S> near(Vec4<S>(sin(t), S(0), S(0), -cos(t)), Vec4<S>(cos(t), S(0), S(0), sin(t)), Vec4<S>::Unit(1));
  CHECK(near.isSoma());
  CHECK(abs(near.soma().translation().norm() * t / S(4) - S(1)) <= S(1) / S(1000000));
}

}  // namespace SOMA_UNITY_ID
