#pragma once
// A free (or forced) rigid body integrated on SE(3) × se(3) with the Runge–Kutta–Munthe-Kaas
// method of order 4 (RKMK4, classical RK4 tableau in the Lie algebra, exact dexp⁻¹ = J_l⁻¹).
//
// State: pose g ∈ SE(3) (body frame → fixed frame) and the spatial velocity s = (ω, v) with
// ġ = ŝ g (velocities in the fixed frame, as SB §1 and GF ch. 13 use them). The acceleration ṡ
// comes from a callback (the 6×6 screw formulation or SB's Cl(0,6,2) E-form), so the same
// integrator drives both formulations. The method is order 4 in the step h: a conserved quantity
// (energy, spatial momentum) drifts by O(T h⁴) until rounding (O(n ε)) takes over.
#include "soma/algebra/se3.hpp"

namespace soma {

template <class S> struct RigidBodyState {
  SE3<S> pose;
  SE3Tangent<S> velocity;  ///< spatial velocity s = (ω, v), ġ = ŝ g
};

/// One RKMK4 step of length h for ġ = ŝ g, ṡ = accel(g, s). g(t) = exp(u(t)) g₀ with
/// u̇ = J_l(u)⁻¹ s (the left Jacobian is dexp_u), and s integrated by RK4 alongside.
template <class S, class Accel>
RigidBodyState<S> rkmk4Step(const RigidBodyState<S>& y, const S& h, Accel&& accel) {
  using T = SE3Tangent<S>;
  const S half = h / S(2);
  const SE3<S>& g0 = y.pose;
  const T& s0 = y.velocity;
  const T k1u = s0;
  const T k1s = accel(g0, s0);
  const T u2 = k1u * half;
  const T s2 = s0 + k1s * half;
  const SE3<S> g2 = u2.exp().compose(g0);
  const T k2u(Vec6<S>(u2.ljacinv() * s2.coeffs()));
  const T k2s = accel(g2, s2);
  const T u3 = k2u * half;
  const T s3 = s0 + k2s * half;
  const SE3<S> g3 = u3.exp().compose(g0);
  const T k3u(Vec6<S>(u3.ljacinv() * s3.coeffs()));
  const T k3s = accel(g3, s3);
  const T u4 = k3u * h;
  const T s4 = s0 + k3s * h;
  const SE3<S> g4 = u4.exp().compose(g0);
  const T k4u(Vec6<S>(u4.ljacinv() * s4.coeffs()));
  const T k4s = accel(g4, s4);
  const S sixth = h / S(6);
  const T u = (k1u + k2u * S(2) + k3u * S(2) + k4u) * sixth;
  const T s = s0 + (k1s + k2s * S(2) + k3s * S(2) + k4s) * sixth;
  return {u.exp().compose(g0), s};
}

}  // namespace soma
