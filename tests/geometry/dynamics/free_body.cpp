// A free tumbling body in the 6×6 screw formulation (GF §13.2.1, SB §2) integrated with RKMK4
// (free_body.hpp): energy and spatial-momentum drift against the order-4 bound, all five scalars.
#include "soma/geometry/dynamics/free_body.hpp"
#include "soma/geometry/dynamics/spatial_inertia.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {
/// Max relative drift of energy and spatial momentum over a free flight of n steps of size h.
template <class S> std::pair<S, S> freeFlightDrift(const SpatialInertia<S>& body, const SE3Tangent<S>& s0,
                                                   const S& h, int n) {
  auto accel = [&](const SE3<S>& g, const SE3Tangent<S>& s) {
    return rigidBodyAcceleration(coadjointTransform(g, body.matrix()), s, Vec6<S>(Vec6<S>::Zero()));
  };
  RigidBodyState<S> y{SE3<S>::Identity(), s0};
  const S E0 = body.kineticEnergy(s0);
  const Vec6<S> P0 = body.momentum(s0);
  S dE(0), dP(0);
  for (int i = 0; i < n; ++i) {
    y = rkmk4Step(y, h, accel);
    const SpatialInertia<S> bi = body.transformed(y.pose);
    using std::abs;
    const S e = abs(bi.kineticEnergy(y.velocity) - E0) / E0;
    const S p = (bi.momentum(y.velocity) - P0).norm() / P0.norm();
    if (e > dE) dE = e;
    if (p > dP) dP = p;
  }
  return {dE, dP};
}
}  // namespace

TEMPLATE_TEST_CASE("free tumbling body (6x6): drift follows the order-4 bound of RKMK4", "[dynamics]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  // A body off its centre of mass with unequal moments, tumbling about an unstable-ish axis.
  const SpatialInertia<S> body(S(2), Vec3<S>(S(3) / S(10), S(-2) / S(10), S(1) / S(10)),
                               Mat3<S>(Vec3<S>(S(1), S(2), S(3)).asDiagonal()));
  const SE3Tangent<S> s0(Vec3<S>(S(1) / S(10), S(2), S(1) / S(10)), Vec3<S>(S(1) / S(2), S(0), S(-1) / S(4)));
  const S T(8);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 40 : 80;
  const S h = T / S(n);
  const auto [dE1, dP1] = freeFlightDrift(body, s0, h, n);
  const auto [dE2, dP2] = freeFlightDrift(body, s0, S(h / S(2)), 2 * n);
  // Order-4 method: halving h divides the truncation drift by 16. Bound: drift(h/2) ≤ drift(h)/2^3.5
  // plus a rounding floor of (steps)·64 ε (the 0.5 in the exponent is the allowance for the
  // next-order term at this h; no tolerance depends on the measured values themselves).
  using std::pow;
  const S floor2 = S(2 * n) * Tolerance<S>::identity();
  const S shrink = pow(S(2), S(7) / S(2));
  INFO("dE(h) = " << toDouble(dE1) << "  dE(h/2) = " << toDouble(dE2) << "  dP(h) = " << toDouble(dP1)
                  << "  dP(h/2) = " << toDouble(dP2));
  REQUIRE(dE2 <= dE1 / shrink + floor2);
  REQUIRE(dP2 <= dP1 / shrink + floor2);
  // a priori: RK4 truncation per unit time ≤ (h Ω)^4 Ω with Ω = |ω₀| + |v₀| (rates of the flow)
  const S Om = s0.ang().norm() + s0.lin().norm();
  const S apriori = pow(h * Om, 4) * Om * T + S(n) * Tolerance<S>::identity();
  REQUIRE(dE1 <= apriori);
  REQUIRE(dP1 <= apriori);
}

}  // namespace SOMA_UNITY_ID
