#pragma once
// The planar 4-bar of GF §14.4 (Fig. 14.2): ground joint 1 at the origin, crank d₁ at angle θ₁,
// coupler d₂ at relative angle θ₂, rocker d₃, ground link d₄ along x to joint 4 at (d₄, 0).
// Planar screws s = (ω_z, v_x, v_y), a joint at p: s = (1, p_y, −p_x); planar inertia of
// GF-14.4-planar-inertia. The book's equation of motion (star rooted at the coupler, driving torque
// on joint 1, no gravity) uses the null vector α of the loop Σα_i s_i = 0 (corrected: erratum 8,
// α₁ = d₁d₂ sin θ₂ − d₂d₄ sin(θ₁+θ₂)) and the rocker twist q̇₃ = −θ̇₄ s₄ (erratum 9). The same
// mechanism as a ConstrainedTree (crank and rocker trees, the coupler–rocker pin cut open) gives
// an independent Lagrange-multiplier solution. Five scalars, geometry/src/dynamics/fourbar_dynamics.cpp.
#include "soma/geometry/dynamics/constrained_tree.hpp"

#include <array>

namespace soma {

template <class S> using PVec = Eigen::Matrix<S, 3, 1>;  ///< planar screw / co-screw (ω_z, v_x, v_y)
template <class S> using PMat = Eigen::Matrix<S, 3, 3>;

/// Planar [a, b] = (0, −a₀b₂ + b₀a₂, a₀b₁ − b₀a₁) (the (ω_z, v_x, v_y) part of ad(a) b).
template <class S> PVec<S> planarBracket(const PVec<S>& a, const PVec<S>& b) {
  return PVec<S>(S(0), -a(0) * b(2) + b(0) * a(2), a(0) * b(1) - b(0) * a(1));
}
/// Planar {q, P} = −ad(q)ᵀP = (v_x P_y − v_y P_x, −ω P_y, ω P_x).
template <class S> PVec<S> planarCoadjoint(const PVec<S>& q, const PVec<S>& P) {
  return PVec<S>(q(1) * P(2) - q(2) * P(1), -q(0) * P(2), q(0) * P(1));
}
/// The screw of a revolute joint at p: (1, p_y, −p_x). GF §14.4 line 9124
template <class S> PVec<S> planarJointScrew(const S& px, const S& py) { return PVec<S>(S(1), py, -px); }

/// A planar link: mass, centre of mass in the link frame (along the link, normal to it), I_zz about the centre.
template <class S> struct PlanarLink {
  S mass, along, normal, inertia;
};

template <class S> struct FourBarPosture {
  S theta1, theta2, theta3, theta4;  ///< joint angles (θ₁ + θ₂ + θ₃ + θ₄ ≡ 0 mod 2π)
  S rocker;                          ///< absolute rocker angle φ₃ (direction P₄ → P₃)
  std::array<Eigen::Matrix<S, 2, 1>, 4> joints;  ///< P₁ (origin), P₂, P₃, P₄ = (d₄, 0)
};

/// θ̇ and θ̈ of all four joints and the link twists/accelerations (crank, coupler, rocker).
template <class S> struct FourBarMotion {
  FourBarPosture<S> posture;
  Eigen::Matrix<S, 4, 1> rate, acc;
  std::array<PVec<S>, 3> twist, twistDot;
  std::array<PMat<S>, 3> inertia;  ///< planar N_i at the posture
};

template <class S> class FourBarDynamics {
 public:
  /// Lengths d₁ (crank), d₂ (coupler), d₃ (rocker), d₄ (ground) > 0, three links, assembly
  /// branch +1 (P₃ to the left of P₂→P₄) or −1. InvalidInput for non-positive or NaN data.
  FourBarDynamics(S d1, S d2, S d3, S d4, std::array<PlanarLink<S>, 3> links, int branch = 1);

  const std::array<S, 4>& lengths() const { return d_; }
  /// The posture at crank angle θ₁. InvalidInput if the loop cannot close there (|P₂P₄| outside
  /// [|d₂ − d₃|, d₂ + d₃]).
  FourBarPosture<S> posture(const S& theta1) const;
  /// s₁ … s₄ (GF lines 9149–9157).
  std::array<PVec<S>, 4> screws(const FourBarPosture<S>& p) const;
  /// The null vector α of (s₁ s₂ s₃ s₄), GF lines 9171–9181, GF-14.4-four-bar-null-vector
  /// (corrected, erratum 8: the book prints α₁ = d₁d₄ sin θ₂ − d₂d₄ sin(θ₁+θ₂); studies/gf14/mechanisms.cpp
  /// computes it).
  Eigen::Matrix<S, 4, 1> alpha(const FourBarPosture<S>& p) const;
  /// |α₁| relative to d₁d₂d₄: 0 at a singular (folded / dead-centre) posture.
  S singularityMeasure(const FourBarPosture<S>& p) const;
  /// Joint rates θ̇_i = θ̇₁ α_i/α₁ and accelerations from the differentiated loop equation.
  /// InvalidInput at a singular posture (|α₁| ≤ Tolerance::input() d₁d₂d₄).
  FourBarMotion<S> motion(const S& theta1, const S& theta1Dot, const S& theta1DDot) const;
  /// The book's equation of motion solved for τ (GF line 9195, GF-14.4-four-bar-eom):
  /// α₁τ = q̈₁ᵀN₁α₁s₁ + q̈₂ᵀN₂(α₁s₁ + α₂s₂) − q̈₃ᵀN₃α₄s₄.
  S torqueAlpha(const S& theta1, const S& theta1Dot, const S& theta1DDot) const;
  /// E_K = ½ Σ q̇_iᵀN_iq̇_i.
  S kineticEnergy(const S& theta1, const S& theta1Dot) const;
  /// The s₁-paired root equation of GF lines 9199–9203 (left side): Σ terms = τ + R₄ᵀs₁,
  /// GF-14.4-four-bar-shaking-moment (corrected, erratum 9: the θ̈₄ term is −θ̈₄s₁ᵀN₃s₄ with
  /// q̇₃ = −θ̇₄s₄; the book prints +θ̈₄s₁ᵀN₃s₄, computed in studies/gf14/mechanisms.cpp).
  S shakingMomentLhs(const S& theta1, const S& theta1Dot, const S& theta1DDot) const;
  /// θ̈₁ of the free or driven mechanism from the α equation (linear in θ̈₁).
  S crankAcceleration(const S& theta1, const S& theta1Dot, const S& tau) const;
  /// One RK4 step of (θ₁, θ̇₁) under constant τ (the other angles follow from θ₁: no drift).
  std::array<S, 2> rk4Step(const std::array<S, 2>& y, const S& h, const S& tau) const;

  /// The same mechanism in 3-D as a ConstrainedTree: crank (joint 0 at the origin), coupler
  /// (joint 1 at P₂, child of the crank), rocker (joint 2 at P₄, on the ground); the pin P₃ cut open
  /// as two point constraints (x, y). Home = the posture at homeTheta1. Gravity zero.
  ConstrainedTree<S> constrainedTree(const S& homeTheta1) const;
  /// (θ, θ̇, θ̈) of that tree for a motion of the crank (tree angles relative to the home posture).
  std::array<DynVector<S>, 3> treeState(const S& homeTheta1, const FourBarMotion<S>& m) const;

 private:
  std::array<S, 4> d_;
  std::array<PlanarLink<S>, 3> links_;
  int branch_;
};

#define SOMA_FOURBAR_EXTERN(S) extern template class FourBarDynamics<S>;
SOMA_FOR_EACH_SCALAR(SOMA_FOURBAR_EXTERN)
#undef SOMA_FOURBAR_EXTERN

}  // namespace soma
