// GF §12.1–12.3: co-screws and wrenches, the wrist force sensor.
#include "soma/geometry/statics/robot_statics.hpp"
#include "soma/geometry/statics/wrench.hpp"
#include "soma/geometry/statics/wrist_sensor.hpp"
#include "soma/geometry/statics/grasp.hpp"

#include "../../support/scalars.hpp"

#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniformVec;

namespace {
template <class S> S tolId(int k = 256) { return Tolerance<S>::identity(k); }
/// 6 × 6 orthogonal matrix: block-diagonal of two random rotations.
template <class S> Mat6<S> blockRotation(std::mt19937_64& g) {
  Mat6<S> m = Mat6<S>::Zero();
  m.template topLeftCorner<3, 3>() = SO3<S>::Random(g).matrix();
  m.template bottomRightCorner<3, 3>() = SO3<S>::Random(g).matrix();
  return m;
}
template <class S> ScrewColumns<S> withSingularValues(std::mt19937_64& g, const Vec6<S>& sig) {
  return ScrewColumns<S>(blockRotation<S>(g) * sig.asDiagonal() * blockRotation<S>(g));
}
}  // namespace

TEMPLATE_TEST_CASE("GF-12.1 the pairing is invariant: W' = coadjoint(g) W, s' = Ad(g) s", "[statics][coscrew]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1201);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 3 : 25;
  for (int i = 0; i < n; ++i) {
    const SE3<S> x = SE3<S>::Random(g);
    const SE3Tangent<S> s(uniformVec<S, 6>(g));
    const Wrench<S> W(uniformVec<S, 6>(g));
    const SE3Tangent<S> s2(Vec6<S>(x.adjoint() * s.coeffs()));
    const Wrench<S> W2 = W.transformed(x);
    CHECK(abs(W2(s2) - W(s)) <= tolId<S>());
    // [[R, T R], [0, R]] = Ad(g)⁻ᵀ
    const Mat6<S> adInvT = x.inverse().adjoint().transpose();
    CHECK((coadjointMatrix(x) - adInvT).cwiseAbs().maxCoeff() <= tolId<S>());
    CHECK((coadjointMatrix(x) * W.coeffs() - W2.coeffs()).cwiseAbs().maxCoeff() <= tolId<S>());
    // a representation: coadjoint(g h) = coadjoint(g) coadjoint(h)
    const SE3<S> y = SE3<S>::Random(g);
    CHECK((W.transformed(x * y).coeffs() - W.transformed(y).transformed(x).coeffs()).cwiseAbs().maxCoeff() <= tolId<S>());
    // and not the adjoint: a wrench moved like a twist loses the pairing
    const Wrench<S> wrong(Vec6<S>(x.adjoint() * W.coeffs()));
    CHECK(abs(wrong(s2) - W(s)) > S(1000) * tolId<S>());
  }
}

TEMPLATE_TEST_CASE("GF-12.2 wrench of a force, couples, pitch and axis", "[statics][wrench]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1202);
  for (int i = 0; i < 10; ++i) {
    const Vec3<S> r = uniformVec<S, 3>(g), F = uniformVec<S, 3>(g), w = uniformVec<S, 3>(g), v = uniformVec<S, 3>(g);
    const S lam = soma::test::uniform<S>(g, -3, 3);
    const Wrench<S> W = Wrench<S>::ofForce(r, F);
    // power F·(ω × r + v) = W(s)
    const SE3Tangent<S> s(w, v);
    CHECK(abs(F.dot(Vec3<S>(w.cross(r) + v)) - W(s)) <= tolId<S>());
    // any point of the line of action
    CHECK((Wrench<S>::ofForce(Vec3<S>(r + lam * F), F).coeffs() - W.coeffs()).cwiseAbs().maxCoeff() <= tolId<S>());
    // couple: (r × F, F) + ((−r) × (−F), −F) = (2 r × F, 0)
    const Wrench<S> sum = W + Wrench<S>::ofForce(Vec3<S>(-r), Vec3<S>(-F));
    CHECK((sum.moment() - S(2) * r.cross(F)).norm() <= tolId<S>());
    CHECK(sum.force().norm() == S(0));
    CHECK(sum.axis().pureTorque);
    // pitch round trip (r, F, p) → W → (p, axis)
    const S p = soma::test::uniform<S>(g, -2, 2);
    const auto a = Wrench<S>::ofPitch(r, F, p).axis();
    REQUIRE_FALSE(a.pureTorque);
    CHECK(abs(a.pitch - p) <= tolId<S>(1024));
    CHECK(abs(a.point.dot(F)) <= tolId<S>(1024));                    // nearest point to the origin
    CHECK((a.point - r).cross(F).norm() <= tolId<S>(1024));           // on the line through r along F
    CHECK((a.point.cross(F) + p * F - Wrench<S>::ofPitch(r, F, p).moment()).norm() <= tolId<S>(1024));
    CHECK(abs(Wrench<S>::ofForce(r, F).axis().pitch) <= tolId<S>());  // pure force: pitch 0
  }
}

TEMPLATE_TEST_CASE("GF-12.2 pure-torque threshold: both sides, and bad input", "[statics][wrench]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const Vec3<S> tau(S(1), S(2), S(-0.5));
  const S rk = Tolerance<S>::rank() * tau.norm();
  CHECK(Wrench<S>(tau, Vec3<S>(S(0), S(0), rk / S(4))).axis().pureTorque);
  const auto a = Wrench<S>(tau, Vec3<S>(S(0), S(0), rk * S(4))).axis();
  CHECK_FALSE(a.pureTorque);
  CHECK(abs(a.pitch - tau.z() / (rk * S(4))) <= abs(a.pitch) * tolId<S>());
  CHECK_THROWS_AS(Wrench<S>::Zero().axis(), InvalidInput);
  CHECK_THROWS_AS(Wrench<S>(tau, Vec3<S>(std::numeric_limits<S>::quiet_NaN(), S(0), S(0))).axis(), InvalidInput);
}

TEMPLATE_TEST_CASE("GF-12.3 wrist sensor: the gauge wrenches sum to the corrected matrix (erratum E12.1)",
                   "[statics][sensor]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1203);
  const S l = S(3) / S(4);
  const Vec8<S> w = uniformVec<S, 8>(g);
  Wrench<S> tot;
  for (const auto& W : wristSensorWrenches<S>(l, w)) tot += W;
  CHECK((resolvedForceMatrix<S>(l) * w - tot.coeffs()).cwiseAbs().maxCoeff() <= tolId<S>());
  // the printed row 2 differs by 2 l w₆ (GF §12.3 line 7410 as printed, erratum E12.1: −l at (2, 6))
  Mat68<S> asPrinted = resolvedForceMatrix<S>(l);
  asPrinted(1, 5) = -l;
  const Vec6<S> printed = asPrinted * w;
  CHECK(abs(printed(1) - tot.coeffs()(1) + S(2) * l * w(5)) <= tolId<S>());
  CHECK(abs(printed(1) - tot.coeffs()(1)) > S(1000) * tolId<S>());
  // the printed total: (l(w4 − w8), l(w6 − w2), l(w1 − w3 − w5 + w7), w3 + w7, w1 + w5, w2 + w4 + w6 + w8)
  Vec6<S> book;
  book << l * (w(3) - w(7)), l * (w(5) - w(1)), l * (w(0) - w(2) - w(4) + w(6)), w(2) + w(6), w(0) + w(4),
      w(1) + w(3) + w(5) + w(7);
  CHECK((book - tot.coeffs()).cwiseAbs().maxCoeff() <= tolId<S>());
  // calibration: signals for a wrench reproduce it
  const Wrench<S> target(uniformVec<S, 6>(g));
  CHECK((resolvedForceMatrix<S>(l) * wristSensorSignals<S>(l, target) - target.coeffs()).cwiseAbs().maxCoeff() <=
        tolId<S>(1024));
  // rank 6 for l > 0, 3 for l = 0
  CHECK(wrenchSpan<S>(WrenchSet<S>(resolvedForceMatrix<S>(l))).rank == 6);
  CHECK(wrenchSpan<S>(WrenchSet<S>(resolvedForceMatrix<S>(Tolerance<S>::rank() * S(8)))).rank == 6);
  CHECK(wrenchSpan<S>(WrenchSet<S>(resolvedForceMatrix<S>(Tolerance<S>::rank() / S(8)))).rank == 3);
  CHECK(wrenchSpan<S>(WrenchSet<S>(resolvedForceMatrix<S>(S(0)))).rank == 3);
  CHECK_THROWS_AS(wristSensorSignals<S>(S(0), target), InvalidInput);
  CHECK_THROWS_AS(wristSensorSignals<S>(S(-1), target), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
