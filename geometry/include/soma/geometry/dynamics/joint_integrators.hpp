#pragma once
// Time integrators for the free (or forced) motion of a serial robot (GF §13.4–13.5):
//  * rk4Step: the classical explicit Runge–Kutta method of order 4 on the state (θ, θ̇), with θ̈
//    from SerialDynamics::forwardDynamics. Not symplectic: the energy error grows like T·h⁴.
//  * implicitMidpointStep: the implicit midpoint rule on Hamilton's equations in the canonical
//    coordinates (θ, π) of GF §13.5 (π = A θ̇). It is symplectic (a Gauss–Legendre collocation
//    method with one stage) and symmetric, so the energy error stays bounded, O(h²), with no
//    secular drift. The stage equation k = f(y + h k / 2) is solved by simplified Newton
//    iteration (Jacobian of f by forward differences once per step) to Tolerance<S>::identity(64).
// Instantiated for the five scalars in geometry/src/dynamics/joint_integrators.cpp.
#include "soma/geometry/dynamics/serial_dynamics.hpp"

namespace soma {

template <class S> struct JointState {
  DynVector<S> theta, thetaDot;
};
template <class S> struct CanonicalState {
  DynVector<S> theta, momentum;  ///< (θ, π), π = A(θ) θ̇
};

/// One RK4 step of length h with constant joint torques τ.
template <class S>
JointState<S> rk4Step(const SerialDynamics<S>& robot, const JointState<S>& y, const S& h, const DynVector<S>& tau);

/// One implicit-midpoint step in (θ, π) with constant τ. `iterations` (optional) receives the
/// number of Newton sweeps. InvalidInput if h is not finite and positive; std::runtime_error
/// if the iteration does not converge in 200 sweeps (h too large for this state).
template <class S>
CanonicalState<S> implicitMidpointStep(const SerialDynamics<S>& robot, const CanonicalState<S>& y, const S& h,
                                       const DynVector<S>& tau, int* iterations = nullptr);

/// Total energy E_K + E_P of a joint state (GF §13.4, E_P corrected).
template <class S> S totalEnergy(const SerialDynamics<S>& robot, const JointState<S>& y);

#define SOMA_JOINT_INTEGRATORS_EXTERN(S)                                                                       \
  extern template JointState<S> rk4Step<S>(const SerialDynamics<S>&, const JointState<S>&, const S&,           \
                                           const DynVector<S>&);                                              \
  extern template CanonicalState<S> implicitMidpointStep<S>(const SerialDynamics<S>&, const CanonicalState<S>&, \
                                                            const S&, const DynVector<S>&, int*);             \
  extern template S totalEnergy<S>(const SerialDynamics<S>&, const JointState<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_JOINT_INTEGRATORS_EXTERN)
#undef SOMA_JOINT_INTEGRATORS_EXTERN

}  // namespace soma
