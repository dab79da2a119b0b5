// Quaternions (GF §2.1–2.2): the product, the 1/Δ map to SO(3), the four charts back (printed vs
// corrected, errata E2.1/E2.2) and Shepperd's choice, including half-turns.
#include "soma/algebra/quaternion.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using Catch::Matchers::Contains;

namespace {
template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }
template <class S> Quat<S> randomQuat(std::mt19937_64& g) {
  return Quat<S>(uniform<S>(g), uniform<S>(g), uniform<S>(g), uniform<S>(g));
}
/// p and q are the same point of PR³: all 2×2 minors p_i q_j − p_j q_i vanish.
template <class S> S projectiveDefect(const Quat<S>& p, const Quat<S>& q) {
  using std::abs;
  S d(0);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const S m = abs(p.coeffs()(i) * q.coeffs()(j) - p.coeffs()(j) * q.coeffs()(i));
      if (m > d) d = m;
    }
  return d;
}
}  // namespace

TEMPLATE_TEST_CASE("quaternion product, norm and the map to SO(3)", "[quaternion]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::abs;
  using std::sqrt;
  const S tol = S(16) * Tolerance<S>::epsilon();
  // GF-2.1-quaternion-product: ij = k, jk = i, ki = j, ij = −ji, i² = −1 exactly.
  const Quat<S> i(0, 1, 0, 0), j(0, 0, 1, 0), k(0, 0, 0, 1), one(1, 0, 0, 0);
  CHECK(bool(quaternionProduct(i, j).coeffs() == k.coeffs()));
  CHECK(bool(quaternionProduct(j, k).coeffs() == i.coeffs()));
  CHECK(bool(quaternionProduct(k, i).coeffs() == j.coeffs()));
  CHECK(bool(quaternionProduct(j, i).coeffs() == (-k.coeffs()).eval()));
  CHECK(bool(quaternionProduct(i, i).coeffs() == (-one.coeffs()).eval()));
  auto& g = rng(91);
  const int n = std::is_same_v<S, mpreal> ? 10 : 100;
  for (int t = 0; t < n; ++t) {
    const Quat<S> a = randomQuat<S>(g), b = randomQuat<S>(g);
    // Independent of Eigen's own product; |ab| = |a||b|.
    CHECK(maxAbs(Vec4<S>(quaternionProduct(a, b).coeffs() - (a * b).coeffs())) <= tol);
    CHECK(abs(quaternionProduct(a, b).norm() - a.norm() * b.norm()) <= tol);
    // GF-2.2.2-SO3-from-quaternion: orthogonal, det 1, scale-free, multiplicative.
    const Mat3<S> R = rotationFromQuaternion(a);
    CHECK(maxAbs(Mat3<S>(R.transpose() * R - Mat3<S>::Identity())) <= tol);
    CHECK(abs(R.determinant() - S(1)) <= tol);
    CHECK(maxAbs(Mat3<S>(rotationFromQuaternion(Quat<S>(a.coeffs() * S(-7) / S(3))) - R)) <= tol);
    CHECK(maxAbs(Mat3<S>(rotationFromQuaternion(quaternionProduct(a, b)) -
                         R * rotationFromQuaternion(b))) <= S(4) * tol);
    // GF-2.2.2-SO3-to-quaternion-charts (corrected): each chart returns 2·q_k·(w:x:y:z).
    const Quat<S> u(a.coeffs() / a.norm());
    for (int c = 1; c <= 4; ++c) {
      const Quat<S> qc = quaternionFromRotationChart(R, c);
      const S qk = c == 1 ? u.w() : u.vec()(c - 2);
      CHECK(maxAbs(Vec4<S>(qc.coeffs() - S(2) * qk * u.coeffs())) <= S(4) * tol);
    }
    const Quat<S> back = quaternionFromRotation(R);
    CHECK(back.w() >= S(0));
    CHECK(projectiveDefect(back, u) <= S(4) * tol);
  }
  // Rotation of q and λq for tiny / huge λ: no overflow or underflow in the squares.
  const Quat<S> q(S(8) / S(10), S(2) / S(10), -S(3) / S(10), S(1) / S(10));
  const Mat3<S> R = rotationFromQuaternion(q);
  const S tiny = std::numeric_limits<S>::min() * S(1024);
  CHECK(maxAbs(Mat3<S>(rotationFromQuaternion(Quat<S>(q.coeffs() * tiny)) - R)) <= tol);
}

TEMPLATE_TEST_CASE("quaternion charts as printed return a doubled coordinate (E2.2)",
                   "[quaternion]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const S tol = S(16) * Tolerance<S>::epsilon();
  // The catalogue's demo point (0.8 : 0.2 : −0.3 : 0.1): printed chart 1 gives w/x = 8, not 4.
  const Quat<S> q(S(8) / S(10), S(2) / S(10), -S(3) / S(10), S(1) / S(10));
  const Mat3<S> R = rotationFromQuaternion(q);
  // GF §2.2.2 seed lines 635–649 as printed (erratum E2.2): chart c with the full diagonal-type
  // entry 1 ± r11 ± r22 ± r33 where the library halves it.
  const auto chartAsPrinted = [&](int c) {
    const S d[4] = {S(1) + R(0, 0) + R(1, 1) + R(2, 2), S(1) + R(0, 0) - R(1, 1) - R(2, 2),
                    S(1) - R(0, 0) + R(1, 1) - R(2, 2), S(1) - R(0, 0) - R(1, 1) + R(2, 2)};
    Quat<S> p = quaternionFromRotationChart(R, c);
    p.coeffs()(c == 1 ? 3 : c - 2) = d[c - 1];  // Eigen stores (x, y, z, w)
    return p;
  };
  const Quat<S> printed = chartAsPrinted(1);
  const Quat<S> fixed = quaternionFromRotationChart(R, 1);
  using std::abs;
  CHECK(abs(printed.w() / printed.x() - S(8)) <= S(8) * tol);
  CHECK(abs(fixed.w() / fixed.x() - S(4)) <= S(8) * tol);
  // Printed chart k doubles coordinate k: (2w:x:y:z), (w:2x:y:z), ...
  const Quat<S> u(q.coeffs() / q.norm());
  for (int c = 1; c <= 4; ++c) {
    Quat<S> expect(u.coeffs());
    const int idx = c == 1 ? 3 : c - 2;  // Eigen stores (x, y, z, w)
    expect.coeffs()(idx) *= S(2);
    const S qk = c == 1 ? u.w() : u.vec()(c - 2);
    CHECK(maxAbs(Vec4<S>(chartAsPrinted(c).coeffs() -
                         S(2) * qk * expect.coeffs())) <= S(4) * tol);
  }
  // Half-turns (w = 0, chart 1 is 0): Shepperd picks another chart.
  Mat3<S> half;
  half << -1, 0, 0, 0, 1, 0, 0, 0, -1;  // π about y
  CHECK(shepperdChart(half) == 3);
  const Quat<S> hq = quaternionFromRotation(half);
  CHECK(maxAbs(Vec4<S>(hq.coeffs().cwiseAbs() - Vec4<S>(0, 1, 0, 0))) <= tol);
  CHECK_THROWS_WITH(quaternionFromRotationChart(R, 5), Contains("chart must be"));
  const S nan = std::numeric_limits<S>::quiet_NaN();
  CHECK_THROWS_WITH(rotationFromQuaternion(Quat<S>(nan, S(0), S(0), S(1))), Contains("NaN"));
}

}  // namespace SOMA_UNITY_ID
