// Double quaternions h0 + h1σ (GF §11.1): the product for σ² = 1, 1/r² and 0, the action on R⁴,
// Spin(4) ↔ SO(4), and bad input.
#include "soma/algebra/double_quaternion.hpp"

#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using std::abs;
using std::cos;
using std::sin;
using std::sqrt;
using soma::test::uniform;

namespace {
template <class S> Quat<S> randomQuat(std::mt19937_64& g) {
  return Quat<S>(uniform<S>(g), uniform<S>(g), uniform<S>(g), uniform<S>(g));
}
template <class S> Quat<S> unitQuat(std::mt19937_64& g) {
  Quat<S> q = randomQuat<S>(g);
  q.coeffs() /= sqrt(q.coeffs().squaredNorm());
  return q;
}
template <class S> S gap(const DoubleQuaternion<S>& a, const DoubleQuaternion<S>& b) {
  return (a.studyPoint() - b.studyPoint()).cwiseAbs().maxCoeff();
}
}  // namespace

TEMPLATE_TEST_CASE("double quaternions: associative product for σ² = 1, 1/r², 0", "[double_quaternion]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = soma::test::rng(1101);
  for (const S& s2 : {S(1), S(1) / S(10000), S(0), S(-1)}) {
    for (int n = 0; n < 20; ++n) {
      const DoubleQuaternion<S> a(randomQuat<S>(g), randomQuat<S>(g), s2), b(randomQuat<S>(g), randomQuat<S>(g), s2),
          c(randomQuat<S>(g), randomQuat<S>(g), s2);
      CHECK(gap((a * b) * c, a * (b * c)) <= Tolerance<S>::identity(64));
    }
  }
}

TEMPLATE_TEST_CASE("double quaternions: σ² = 0 is the dual-quaternion product", "[double_quaternion]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = soma::test::rng(1102);
  for (int n = 0; n < 20; ++n) {
    const Quat<S> a = randomQuat<S>(g), c = randomQuat<S>(g), b = randomQuat<S>(g), d = randomQuat<S>(g);
    const DoubleQuaternion<S> p = DoubleQuaternion<S>(a, c, S(0)) * DoubleQuaternion<S>(b, d, S(0));
    const DualQuaternion<S> q = DualQuaternion<S>(a, c) * DualQuaternion<S>(b, d);
    CHECK((p.studyPoint() - q.coeffs()).cwiseAbs().maxCoeff() <= Tolerance<S>::identity(64));
  }
}

TEMPLATE_TEST_CASE("double quaternions: Spin(4) acts by SO(4), and SO(4) → Spin(4) → SO(4)", "[double_quaternion]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = soma::test::rng(1103);
  for (int n = 0; n < 20; ++n) {
    const DoubleQuaternion<S> h = DoubleQuaternion<S>::fromSpin3Pair(unitQuat<S>(g), unitQuat<S>(g));
    CHECK(abs(h.normDefect()) <= Tolerance<S>::identity(16));
    CHECK(abs(h.studyForm()) <= Tolerance<S>::identity(16));
    const Mat4<S> M = h.matrix();
    CHECK((M.transpose() * M - Mat4<S>::Identity()).cwiseAbs().maxCoeff() <= Tolerance<S>::identity(64));
    CHECK(abs(M.determinant() - S(1)) <= Tolerance<S>::identity(64));
    const DoubleQuaternion<S> back = DoubleQuaternion<S>::fromSO4(M);
    // ±h: compare the rotations, and the points of PR⁷ up to sign.
    CHECK((back.matrix() - M).cwiseAbs().maxCoeff() <= Tolerance<S>::identity(256));
    const S same = (back.studyPoint() - h.studyPoint()).cwiseAbs().maxCoeff();
    const S opposite = (back.studyPoint() + h.studyPoint()).cwiseAbs().maxCoeff();
    CHECK(std::min(same, opposite) <= Tolerance<S>::identity(256));
  }
}

TEMPLATE_TEST_CASE("double quaternions: bad input", "[double_quaternion]", double, mpfr::mpreal) {
  using S = TestType;
  Mat4<S> reflect = Mat4<S>::Identity();
  reflect(3, 3) = S(-1);
  CHECK_THROWS_WITH(DoubleQuaternion<S>::fromSO4(reflect), Catch::Contains("det M = −1"));
  // Orthogonality at Tolerance::input: inside is accepted, outside refused.
  Mat4<S> inside = Mat4<S>::Identity(), outside = Mat4<S>::Identity();
  inside(0, 1) = Tolerance<S>::input() / S(4);
  outside(0, 1) = Tolerance<S>::input() * S(4);
  CHECK_NOTHROW(DoubleQuaternion<S>::fromSO4(inside));
  CHECK_THROWS_WITH(DoubleQuaternion<S>::fromSO4(outside), Catch::Contains("not orthogonal"));
  Mat4<S> nan = Mat4<S>::Identity();
  nan(2, 2) = std::numeric_limits<S>::quiet_NaN();
  CHECK_THROWS_WITH(DoubleQuaternion<S>::fromSO4(nan), Catch::Contains("NaN"));
  const DoubleQuaternion<S> a(Quat<S>(S(1), S(0), S(0), S(0)), Quat<S>(S(0), S(0), S(0), S(0)), S(1));
  const DoubleQuaternion<S> b(Quat<S>(S(1), S(0), S(0), S(0)), Quat<S>(S(0), S(0), S(0), S(0)), S(0));
  CHECK_THROWS_WITH(a * b, Catch::Contains("different σ²"));
}

}  // namespace SOMA_UNITY_ID
