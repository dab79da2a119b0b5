#pragma once
// Inverse dynamics and computed-force control of the Stewart platform (GF §14.6, Fig. 14.4): a
// star rooted at the platform P (here a tree whose massless root chain of six basis joints gives
// the platform's six freedoms), each leg hanging from the platform by a 2-dof joint (screws s_Ui1,
// s_Ui2 through U_i, perpendicular to the leg: rotation about the leg axis suppressed), an upper
// part, the prismatic actuator s_Li = (0, (U_i − L_i)/M) (erratum 13: the OCR-damaged vector) and a
// lower part whose end is held at the ground ball joint L_i by W_ix, W_iy, W_iz = (r_L × e, e)
// (GF-14.6-stewart-constraint-wrenches). 18 constraint equations in 24 joint rates.
// Leg forces F_i (the generalised forces of the prismatic joints) by the book's α elimination
// (option 2: platform α's set to unit twists, one 3 × 3 system per leg, then the 6 × 6 α matrix
// inverted; GF-14.6-stewart-alpha-system, -inverse-dynamics-algorithm) and by the full 24 × 24
// multiplier system. Five scalars in geometry/src/dynamics/stewart_dynamics.cpp.
#include "soma/geometry/dynamics/constrained_tree.hpp"

#include <array>

namespace soma {

template <class S> struct StewartLegInertia {
  S upperMass, upperCom, upperInertia;  ///< c.o.m. upperCom from U_i along the leg; transverse inertia about it
  S lowerMass, lowerCom, lowerInertia;  ///< c.o.m. lowerCom from L_i along the leg
  bool massless() const { return !(upperMass > S(0)) && !(lowerMass > S(0)); }
};

template <class S> struct StewartInverseDynamics {
  Eigen::Matrix<S, 6, 1> forcesAlpha;        ///< F by the α elimination (book, option 2)
  Eigen::Matrix<S, 6, 1> forcesMultipliers;  ///< F by the 24 × 24 multiplier system
  DynVector<S> lambda;                       ///< the 18 multipliers (λ_ix, λ_iy, λ_iz per leg)
  Mat6<S> alphaMatrix;                       ///< α_{k, L_i}: row k = platform unit twist k
  Vec6<S> platformWrench;                    ///< N_P q̈_P + {q̇_P, N_P q̇_P} − G_P
  DynVector<S> theta, thetaDot, thetaDDot;   ///< the 24 joint coordinates of the tree
  S residual;                                ///< of the multiplier solve
};

template <class S> class StewartDynamics {
 public:
  /// Ground points L_i, platform points u_i in the platform frame, platform inertia in the
  /// platform frame, leg inertias (all legs alike), gravity g ≥ 0 along −z.
  StewartDynamics(std::array<Vec3<S>, 6> base, std::array<Vec3<S>, 6> platform, SpatialInertia<S> platformInertia,
                  StewartLegInertia<S> leg, S gravity);
  /// The tree with home = `pose` (θ = 0): joints 0–5 the platform root (translations x, y, z,
  /// rotations about x, y, z through the platform origin; link 5 carries the platform), then per
  /// leg i: 6+3i (U1, massless), 7+3i (U2, upper part), 8+3i (prismatic, lower part).
  ConstrainedTree<S> model(const SE3<S>& pose) const;
  /// Leg forces for a platform twist q̇_P and acceleration q̈_P (spatial, about the origin) at `pose`:
  /// the 5-step algorithm of GF lines 9383–9410. InvalidInput near a singular posture (the 6 × 6
  /// α matrix or the leg systems lose rank).
  StewartInverseDynamics<S> inverseDynamics(const SE3<S>& pose, const Vec6<S>& platformTwist, const Vec6<S>& platformAcceleration) const;
  /// Leg forces at any state (θ, θ̇) of a fixed model for a commanded platform acceleration, by
  /// the multiplier system (the computed-force controller; θ̈ returned through thetaDDot).
  Eigen::Matrix<S, 6, 1> forcesAt(const ConstrainedTree<S>& model, const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                  const Vec6<S>& platformAcceleration, DynVector<S>* thetaDDot = nullptr) const;
  /// The unit leg line wrenches (U_i × d_i, d_i), d_i = (U_i − L_i)/|U_i − L_i|, at `pose`.
  std::array<Vec6<S>, 6> legLines(const SE3<S>& pose) const;
  const SpatialInertia<S>& platformInertia() const { return platformInertia_; }
  const std::array<Vec3<S>, 6>& base() const { return base_; }
  const std::array<Vec3<S>, 6>& platformPoints() const { return platform_; }

 private:
  std::array<Vec3<S>, 6> base_, platform_;
  SpatialInertia<S> platformInertia_;
  StewartLegInertia<S> leg_;
  S g_;
};

#define SOMA_STEWART_DYNAMICS_EXTERN(S) extern template class StewartDynamics<S>;
SOMA_FOR_EACH_SCALAR(SOMA_STEWART_DYNAMICS_EXTERN)
#undef SOMA_STEWART_DYNAMICS_EXTERN

}  // namespace soma
