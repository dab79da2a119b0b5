#pragma once
// Geodesic (helical) control of a serial robot (GF §15.3, lines 9706–9818): computed-torque laws
// that make the closed loop a geodesic of an invariant metric, so the end effector moves on a
// one-parameter subgroup (a helix):
//  * Geodesic:         τ_i = (B_ijk − A_ilΓ^l_jk)θ̇_jθ̇_k + C_i                 (closed loop ∇_U U = 0)
//  * VelocityTracking: … + λA_ilW_l(s_d − θ̇_js_j)                           (q̈₆ = λ(s_d − q̇₆))
//  * Accelerating:     … + A_ilW_l(γ(1+λt)s_d − λθ̇_js_j)                     (q̈₆ = γs_d + λ(γts_d − q̇₆))
//    (corrected, erratum E15.5: line 9816 prints γ(1−λt) and Γ^l_ik θ̇_jθ̇_k; studies/gf15/control.cpp
//    computes that law and runs it with simulateClosedLoop)
// each with optional compensation μ_iθ̇_i of viscous joint friction (line 9800). Γ are the book's
// joint-space Christoffel symbols (JointSpaceGeometry::christoffelBook), W_l the rows of J⁻¹.
// The plant is SerialDynamics (GF ch. 13, C_i corrected) plus the friction μ_iθ̇_i.
// Definitions and the five-scalar instantiation: geometry/src/riemannian/geodesic_control_impl.hpp (one scalar per TU).
#include "soma/geometry/dynamics/serial_dynamics.hpp"
#include "soma/geometry/riemannian/joint_space_geometry.hpp"

#include <functional>

namespace soma {

enum class GeodesicLaw { Geodesic, VelocityTracking, Accelerating };

template <class S> struct GeodesicController {
  GeodesicLaw law = GeodesicLaw::Geodesic;
  Vec6<S> sd = Vec6<S>::Zero();  ///< desired spatial end-effector twist s_d
  S lambda = S(0);                ///< λ > 0: decay rate of the twist error
  S gamma = S(0);                 ///< γ: acceleration along s_d (Accelerating)
  DgVector<S> friction;           ///< μ_i compensated by the law (empty = none)
};

/// The joint torques of the law at (θ, θ̇, t), evaluated as τ = RNEA(θ, θ̇, θ̈*) + μθ̇ with
/// θ̈* = W(a − Σ_{j<k}θ̇_jθ̇_k[s_j, s_k]) — algebraically the book's (B − AΓ)θ̇θ̇ + C + AWa since
/// Γ^l_jkθ̇_jθ̇_k = W_l(Σ_{j<k}θ̇_jθ̇_k[s_j,s_k]). InvalidInput if J(θ) is singular (no W_l), if the
/// robot does not have 6 joints, or if friction has the wrong size.
/// GF §15.3 lines 9716, 9788, 9800, 9816: GF-15.3-geodesic-control-law, -velocity-tracking-law,
/// -friction-compensation, -accelerating-geodesic
template <class S>
DgVector<S> geodesicControlTorque(const SerialDynamics<S>& robot, const JointSpaceGeometry<S>& geo,
                                  const GeodesicController<S>& c, const DgVector<S>& theta,
                                  const DgVector<S>& thetaDot, const S& t);

/// The robot's joint screws as a JointSpaceGeometry (metric Q₀ unless given).
template <class S> JointSpaceGeometry<S> jointSpaceGeometryOf(const SerialDynamics<S>& robot, InvariantMetric<S> Q = {});

template <class S> struct ClosedLoopSample {
  S t;
  DgVector<S> theta, thetaDot;
  Vec6<S> twist;  ///< spatial end-effector twist q̇₆ = J θ̇
  SE3<S> pose;    ///< ρ(θ)
};
/// A torque law of the closed loop: τ(θ, θ̇, t).
template <class S> using TorqueLaw = std::function<DgVector<S>(const DgVector<S>&, const DgVector<S>&, const S&)>;
/// RK4 (step h) of the plant A θ̈ + Bθ̇θ̇ + C + μ∘θ̇ = τ under any torque law, `steps` steps, a
/// sample every `every` steps (and the first). InvalidInput for h ≤ 0, steps < 0, every < 1, wrong sizes.
template <class S>
std::vector<ClosedLoopSample<S>> simulateClosedLoop(const SerialDynamics<S>& robot, const TorqueLaw<S>& law,
                                                    const DgVector<S>& plantFriction, const DgVector<S>& theta0,
                                                    const DgVector<S>& thetaDot0, const S& h, int steps, int every);
/// simulateClosedLoop under the law of c (geodesicControlTorque).
template <class S>
std::vector<ClosedLoopSample<S>> simulateGeodesicControl(const SerialDynamics<S>& robot, const GeodesicController<S>& c,
                                                         const DgVector<S>& plantFriction, const DgVector<S>& theta0,
                                                         const DgVector<S>& thetaDot0, const S& h, int steps, int every);

#define SOMA_GEODESIC_CONTROL_EXTERN(S)                                                                              \
  extern template DgVector<S> geodesicControlTorque<S>(const SerialDynamics<S>&, const JointSpaceGeometry<S>&,       \
                                                       const GeodesicController<S>&, const DgVector<S>&,             \
                                                       const DgVector<S>&, const S&);                                \
  extern template JointSpaceGeometry<S> jointSpaceGeometryOf<S>(const SerialDynamics<S>&, InvariantMetric<S>);      \
  extern template std::vector<ClosedLoopSample<S>> simulateClosedLoop<S>(                                            \
      const SerialDynamics<S>&, const TorqueLaw<S>&, const DgVector<S>&, const DgVector<S>&, const DgVector<S>&,    \
      const S&, int, int);                                                                                           \
  extern template std::vector<ClosedLoopSample<S>> simulateGeodesicControl<S>(                                       \
      const SerialDynamics<S>&, const GeodesicController<S>&, const DgVector<S>&, const DgVector<S>&,               \
      const DgVector<S>&, const S&, int, int);
SOMA_FOR_EACH_SCALAR(SOMA_GEODESIC_CONTROL_EXTERN)
#undef SOMA_GEODESIC_CONTROL_EXTERN

}  // namespace soma
