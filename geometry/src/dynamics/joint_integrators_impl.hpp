// RK4 and implicit-midpoint integrators for serial-robot dynamics (joint_integrators.hpp), five scalars.
#pragma once
#include "soma/geometry/dynamics/joint_integrators.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace soma {

// GF §13.4 (free motion by the Euler–Lagrange equations): classical RK4 on (θ, θ̇)
template <class S>
JointState<S> rk4Step(const SerialDynamics<S>& robot, const JointState<S>& y, const S& h, const DynVector<S>& tau) {
  if (!isFinite(h) || !(h > S(0))) throw InvalidInput("rk4Step: step " + toString(h) + " is not finite and positive");
  const S half = h / S(2);
  const DynVector<S> a1 = robot.forwardDynamics(y.theta, y.thetaDot, tau);
  const DynVector<S> q2 = y.theta + half * y.thetaDot, v2 = y.thetaDot + half * a1;
  const DynVector<S> a2 = robot.forwardDynamics(q2, v2, tau);
  const DynVector<S> q3 = y.theta + half * v2, v3 = y.thetaDot + half * a2;
  const DynVector<S> a3 = robot.forwardDynamics(q3, v3, tau);
  const DynVector<S> q4 = y.theta + h * v3, v4 = y.thetaDot + h * a3;
  const DynVector<S> a4 = robot.forwardDynamics(q4, v4, tau);
  const S sixth = h / S(6);
  JointState<S> out;
  out.theta = y.theta + sixth * (y.thetaDot + S(2) * v2 + S(2) * v3 + v4);
  out.thetaDot = y.thetaDot + sixth * (a1 + S(2) * a2 + S(2) * a3 + a4);
  return out;
}

// GF §13.5 (Hamilton's equations in canonical coordinates, erratum 10 corrected): implicit midpoint
// y₁ = y₀ + h k, k = f(y₀ + h k / 2). The stage k is found by simplified Newton iteration on
// F(k) = k − f(y₀ + h k/2) with the Jacobian I − (h/2) f'(y₀ + h k₀/2), f' by forward differences
// (step √ε·max(1, |y|)): it converges for stiff chains (PUMA wrist, A's smallest eigenvalue 1e-4)
// where plain fixed-point iteration needs h·Lip(f) < 2.
template <class S>
CanonicalState<S> implicitMidpointStep(const SerialDynamics<S>& robot, const CanonicalState<S>& y, const S& h,
                                       const DynVector<S>& tau, int* iterations) {
  using std::abs;
  using std::max;
  if (!isFinite(h) || !(h > S(0)))
    throw InvalidInput("implicitMidpointStep: step " + toString(h) + " is not finite and positive");
  const int n = robot.dof();
  const S half = h / S(2);
  auto field = [&](const DynVector<S>& z) {
    DynVector<S> dq, dp, out(2 * n);
    robot.hamiltonField(DynVector<S>(z.head(n)), DynVector<S>(z.tail(n)), tau, dq, dp);
    out << dq, dp;
    return out;
  };
  DynVector<S> y0(2 * n);
  y0 << y.theta, y.momentum;
  DynVector<S> k = field(y0);  // explicit-Euler predictor for the stage
  // Jacobian of f at the predicted midpoint, by forward differences
  const DynVector<S> zm = y0 + half * k;
  const DynVector<S> fm = field(zm);
  DynMatrix<S> J(2 * n, 2 * n);
  const S step0 = Tolerance<S>::sqrtEpsilon();
  for (int j = 0; j < 2 * n; ++j) {
    DynVector<S> z = zm;
    const S d = step0 * max(S(1), S(abs(zm(j))));
    z(j) += d;
    J.col(j) = (field(z) - fm) / d;
  }
  const Eigen::PartialPivLU<DynMatrix<S>> lu(DynMatrix<S>(DynMatrix<S>::Identity(2 * n, 2 * n) - half * J));
  // Stop at 64 ε relative, or once the corrections stop shrinking below √ε relative: A⁻¹ (cond up
  // to 1e5 for the PUMA) puts a rounding floor under F, and Newton cannot go below it.
  const S tol = Tolerance<S>::identity(64), floor = Tolerance<S>::sqrtEpsilon();
  S prev = S(-1);
  for (int it = 1; it <= 200; ++it) {
    const DynVector<S> F = k - field(DynVector<S>(y0 + half * k));
    const DynVector<S> dk = lu.solve(F);
    k -= dk;
    const S d2 = dk.squaredNorm(), k2 = k.squaredNorm();
    const bool stalled = prev >= S(0) && d2 >= prev && d2 <= floor * floor * k2;
    prev = d2;
    if (d2 <= tol * tol * k2 || stalled) {
      if (iterations) *iterations = it;
      const DynVector<S> y1 = y0 + h * k;
      return {DynVector<S>(y1.head(n)), DynVector<S>(y1.tail(n))};
    }
  }
  throw std::runtime_error("implicitMidpointStep: the Newton iteration did not converge in 200 sweeps "
                           "(step " + toString(h) + " too large)");
}

template <class S> S totalEnergy(const SerialDynamics<S>& robot, const JointState<S>& y) {
  return robot.kineticEnergy(y.theta, y.thetaDot) + robot.potentialEnergy(y.theta);
}

#define SOMA_INSTANTIATE_JOINT_INTEGRATORS(S)                                                                          \
  template JointState<S> rk4Step<S>(const SerialDynamics<S>&, const JointState<S>&, const S&,                    \
                                    const DynVector<S>&);                                                       \
  template CanonicalState<S> implicitMidpointStep<S>(const SerialDynamics<S>&, const CanonicalState<S>&, const S&, \
                                                     const DynVector<S>&, int*);                                \
  template S totalEnergy<S>(const SerialDynamics<S>&, const JointState<S>&);

}  // namespace soma
