// RK4 and implicit-midpoint integrators for serial-robot dynamics (joint_integrators.hpp), five scalars.
#include "soma/geometry/dynamics/joint_integrators.hpp"

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
template <class S>
CanonicalState<S> implicitMidpointStep(const SerialDynamics<S>& robot, const CanonicalState<S>& y, const S& h,
                                       const DynVector<S>& tau, int* iterations) {
  if (!isFinite(h) || !(h > S(0)))
    throw InvalidInput("implicitMidpointStep: step " + toString(h) + " is not finite and positive");
  const S half = h / S(2);
  DynVector<S> kq, kp;
  robot.hamiltonField(y.theta, y.momentum, tau, kq, kp);  // explicit-Euler predictor for the stage
  const S tol = Tolerance<S>::identity(64);
  for (int it = 1; it <= 200; ++it) {
    DynVector<S> nq, np;
    robot.hamiltonField(DynVector<S>(y.theta + half * kq), DynVector<S>(y.momentum + half * kp), tau, nq, np);
    const S change = (nq - kq).squaredNorm() + (np - kp).squaredNorm();
    const S size = nq.squaredNorm() + np.squaredNorm();
    kq = nq;
    kp = np;
    if (change <= tol * tol * size) {
      if (iterations) *iterations = it;
      return {DynVector<S>(y.theta + h * kq), DynVector<S>(y.momentum + h * kp)};
    }
  }
  throw std::runtime_error("implicitMidpointStep: the fixed-point iteration did not converge in 200 sweeps "
                           "(step " + toString(h) + " too large)");
}

template <class S> S totalEnergy(const SerialDynamics<S>& robot, const JointState<S>& y) {
  return robot.kineticEnergy(y.theta, y.thetaDot) + robot.potentialEnergy(y.theta);
}

#define SOMA_JOINT_INTEGRATORS_INST(S)                                                                          \
  template JointState<S> rk4Step<S>(const SerialDynamics<S>&, const JointState<S>&, const S&,                    \
                                    const DynVector<S>&);                                                       \
  template CanonicalState<S> implicitMidpointStep<S>(const SerialDynamics<S>&, const CanonicalState<S>&, const S&, \
                                                     const DynVector<S>&, int*);                                \
  template S totalEnergy<S>(const SerialDynamics<S>&, const JointState<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_JOINT_INTEGRATORS_INST)
#undef SOMA_JOINT_INTEGRATORS_INST

}  // namespace soma
