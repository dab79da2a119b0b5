// Free motion of a serial robot under gravity (τ = 0): energy E_K + E_P (GF §13.4, erratum 3
// corrected) is conserved by the exact flow. We measure the energy error of the two integrators
// of joint_integrators.hpp and assert bounds DERIVED from their theory:
//  * RK4 (order 4): the energy error after time T is e(h) = K T h⁴ + O(h⁵), so halving h divides it
//    by 16; we assert 8 ≤ e(h)/e(h/2) ≤ 32 (the order within ±1).
//  * implicit midpoint on (θ, π) (symplectic, symmetric, order 2): the energy error is O(h²) and
//    bounded — no secular drift. We assert 2 ≤ e(h)/e(h/2) ≤ 8 over [0, T] and over [0, 4T].
//  * in float the rounding floor dominates: each step commits at most c·ε·E_ref in energy with
//    c = 64 (a few hundred flops, errors O(ε) each, partly cancelling), so after N steps the error is
//    bounded by the double-precision truncation error plus N · 64 ε E_ref (worst case, linear).
#include "soma/geometry/dynamics/joint_integrators.hpp"
#include "soma/geometry/dynamics/robot_dynamics.hpp"

#include "serial_dynamics_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

namespace {
/// Largest |E(t) − E(0)| over `steps` steps of h, and at the end.
template <class S>
S rk4EnergyError(const SerialDynamics<S>& r, JointState<S> y, const S& h, int steps, S* eRef = nullptr) {
  const DynVector<S> tau = DynVector<S>::Zero(r.dof());
  const S e0 = totalEnergy(r, y);
  S worst = S(0);
  using std::abs;
  using std::max;
  for (int k = 0; k < steps; ++k) {
    y = rk4Step(r, y, h, tau);
    worst = max(worst, S(abs(totalEnergy(r, y) - e0)));
  }
  if (eRef) *eRef = r.kineticEnergy(y.theta, y.thetaDot) + abs(r.potentialEnergy(y.theta));
  return worst;
}
template <class S> S midpointEnergyError(const SerialDynamics<S>& r, const JointState<S>& y0, const S& h, int steps) {
  const DynVector<S> tau = DynVector<S>::Zero(r.dof());
  CanonicalState<S> y{y0.theta, r.momentum(y0.theta, y0.thetaDot)};
  const S e0 = r.hamiltonian(y.theta, y.momentum);
  S worst = S(0);
  using std::abs;
  using std::max;
  for (int k = 0; k < steps; ++k) {
    y = implicitMidpointStep(r, y, h, tau);
    worst = max(worst, S(abs(r.hamiltonian(y.theta, y.momentum) - e0)));
  }
  return worst;
}
}  // namespace

TEST_CASE("integrators: RK4 energy error is order 4, implicit midpoint order 2 without drift (double)",
          "[dynamics][integrators]") {
  auto& g = rng(1340);
  const RobotSpec spec = randomRobot(g, 3);
  const SerialDynamics<double> r = build<double>(spec);
  const JointState<double> y0{randomJoints<double>(g, 3), randomJoints<double>(g, 3)};
  const double T = 0.5;
  const double e1 = rk4EnergyError(r, y0, T / 64, 64), e2 = rk4EnergyError(r, y0, T / 128, 128);
  INFO("RK4 energy error over 0.5 s: h = T/64: " << e1 << " J, h = T/128: " << e2 << " J, ratio " << e1 / e2);
  CHECK(e1 / e2 >= 8);
  CHECK(e1 / e2 <= 32);
  const double m1 = midpointEnergyError(r, y0, T / 64, 64), m2 = midpointEnergyError(r, y0, T / 128, 128);
  // over 4T the error is still h²·(H₂(y(t)) − H₂(y₀)) + O(h⁴) (modified Hamiltonian: no term growing with t
  // beyond the state's own excursion), so the ratio at h and h/2 stays 4
  const double m4 = midpointEnergyError(r, y0, T / 64, 256), m8 = midpointEnergyError(r, y0, T / 128, 512);
  INFO("midpoint energy error: h = T/64: " << m1 << " J, h = T/128: " << m2 << " J, ratio " << m1 / m2
                                           << "; over 4T: " << m4 << " J and " << m8 << " J, ratio " << m4 / m8);
  CHECK(m1 / m2 >= 2);
  CHECK(m1 / m2 <= 8);
  CHECK(m4 / m8 >= 2);
  CHECK(m4 / m8 <= 8);
}

TEMPLATE_TEST_CASE("integrators: energy drift per scalar below the derived bound", "[dynamics][integrators][scalars]",
                   float, double, long double, __float128) {
  using S = TestType;
  auto& g = rng(1341);
  const RobotSpec spec = randomRobot(g, 3);
  const JointState<double> y0{randomJoints<double>(g, 3), randomJoints<double>(g, 3)};
  const int steps = 64;
  const double h = 0.5 / steps;
  double eRef = 0;
  const double truncation = rk4EnergyError(build<double>(spec), y0, h, steps, &eRef);
  const SerialDynamics<S> r = build<S>(spec);
  const JointState<S> ys{castVec<S>(y0.theta), castVec<S>(y0.thetaDot)};
  const double got = toDouble(rk4EnergyError(r, ys, scalarCast<S>(h), steps));
  const double bound = 2 * truncation + steps * 64 * toDouble(Tolerance<S>::epsilon()) * eRef;
  INFO("RK4 energy error " << got << " J, bound " << bound << " J (truncation " << truncation << ")");
  CHECK(got <= bound);
  const double gotMid = toDouble(midpointEnergyError(r, ys, scalarCast<S>(h), steps));
  const double midTrunc = midpointEnergyError(build<double>(spec), y0, h, steps);
  const double midBound = 2 * midTrunc + steps * 64 * toDouble(Tolerance<S>::epsilon()) * eRef;
  INFO("midpoint energy error " << gotMid << " J, bound " << midBound << " J");
  CHECK(gotMid <= midBound);
}

TEST_CASE("integrators: mpfr runs a few steps and agrees with __float128", "[dynamics][integrators][scalars]") {
  auto& g = rng(1342);
  const RobotSpec spec = randomRobot(g, 3);
  const JointState<double> y0{randomJoints<double>(g, 3), randomJoints<double>(g, 3)};
  const SerialDynamics<mpfr::mpreal> rm = build<mpfr::mpreal>(spec);
  const SerialDynamics<__float128> rq = build<__float128>(spec);
  JointState<mpfr::mpreal> ym{castVec<mpfr::mpreal>(y0.theta), castVec<mpfr::mpreal>(y0.thetaDot)};
  JointState<__float128> yq{castVec<__float128>(y0.theta), castVec<__float128>(y0.thetaDot)};
  const DynVector<mpfr::mpreal> zm = DynVector<mpfr::mpreal>::Zero(3);
  const DynVector<__float128> zq = DynVector<__float128>::Zero(3);
  for (int k = 0; k < 4; ++k) {
    ym = rk4Step(rm, ym, mpfr::mpreal(1) / 128, zm);
    yq = rk4Step(rq, yq, __float128(1) / 128, zq);
  }
  for (int i = 0; i < 3; ++i) CHECK(std::abs(toDouble(ym.theta(i)) - double(yq.theta(i))) <= 1e-15);
  CHECK_THROWS_AS(rk4Step(rq, yq, __float128(-1), zq), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
