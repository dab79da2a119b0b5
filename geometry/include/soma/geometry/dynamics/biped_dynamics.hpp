#pragma once
// The planar biped of GF §14.5 (Fig. 14.3) with both feet on the ground: torso (the root of a
// star, here a tree with a massless planar root x, y, rotation about the hip), two thighs (hip
// joints), two shanks (knee joints), the ankles pinned to the ground (constraint wrenches
// W_x = (−y_a, 1, 0), W_y = (x_a, 0, 1) in planar (τ_z, F_x, F_y) components). The vertical ankle
// force λ_Ry by the book's dual velocities α (corrected: erratum 10, x and y swapped) and by the
// full multiplier system; lift-off where λ_Ry falls to 0. Plane = xy, gravity along −y.
// Five scalars in geometry/src/dynamics/biped_dynamics.cpp.
#include "soma/geometry/dynamics/constrained_tree.hpp"

#include <array>

namespace soma {

template <class S> struct BipedParameters {
  S torsoMass, torsoCom, torsoInertia;   ///< c.o.m. torsoCom above the hip (along the torso)
  S thighLength, thighMass, thighInertia;  ///< thigh c.o.m. at mid-length
  S shankLength, shankMass, shankInertia;  ///< shank c.o.m. at mid-length
  S gravity;                               ///< g ≥ 0 along −y
};

/// Hip position, torso angle (from vertical), and the two ankle points on the ground.
template <class S> struct BipedPose {
  Eigen::Matrix<S, 2, 1> hip, rightAnkle, leftAnkle;
  S torsoAngle;
};

template <class S> class PlanarBiped {
 public:
  /// Tree joints: 0 hip x (slide), 1 hip y (slide), 2 torso (revolute at the hip), 3 right hip,
  /// 4 right knee, 5 left hip, 6 left knee; home = `home` (knees bent forward, +x).
  /// InvalidInput if a leg cannot reach its ankle or parameters are not positive.
  PlanarBiped(BipedParameters<S> p, BipedPose<S> home);
  const ConstrainedTree<S>& model() const { return model_; }
  const BipedPose<S>& home() const { return home_; }
  /// The knee of a leg from hip to ankle (forward branch). InvalidInput if out of reach.
  Eigen::Matrix<S, 2, 1> knee(const Eigen::Matrix<S, 2, 1>& hip, const Eigen::Matrix<S, 2, 1>& ankle) const;
  /// Tree angles of a pose (hip, torso, knees from knee()).
  DynVector<S> angles(const BipedPose<S>& pose) const;
  /// θ̇ and θ̈ completing given hip velocity/acceleration (ẋ_h, ẏ_h, torso rate) with the
  /// constraints (C θ̇ = 0, C θ̈ = −γ) for the four leg joints.
  DynVector<S> completeRates(const DynVector<S>& theta, const Eigen::Matrix<S, 3, 1>& hipRates) const;
  DynVector<S> completeAccelerations(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                     const Eigen::Matrix<S, 3, 1>& hipAccelerations) const;
  /// Joint centres at θ: hip, right knee, right ankle, left knee, left ankle.
  std::array<Eigen::Matrix<S, 2, 1>, 5> jointCentres(const DynVector<S>& theta) const;
  /// (α_Rh, α_Rk) with W_Rxᵀq̇_Rk = 0, W_Ryᵀq̇_Rk = 1 for q̇_Rk = α_Rh s_h + α_Rk s_Rk (torso and left
  /// leg fixed). GF lines 9268–9282, GF-14.5-biped-vertical-foot-force (corrected, erratum 10:
  /// α_Rh = (y_Ra − y_Rk)/D, α_Rk = (y_h − y_Ra)/D; the book prints x-based weights, computed in
  /// studies/gf14/mechanisms.cpp). InvalidInput for a straight leg (D = 0).
  Eigen::Matrix<S, 2, 1> verticalForceAlpha(const DynVector<S>& theta) const;
  /// λ_Ry = α_Rh(E_Rh − τ_Rh) + α_Rk(E_Rk − τ_Rk), E the left sides of the hip and knee joint equations.
  S verticalFootForceAlpha(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& thetaDDot,
                           const DynVector<S>& tau) const;
  /// All four multipliers (λ_Rx, λ_Ry, λ_Lx, λ_Ly) from the seven joint equations (least squares,
  /// consistent when τ is).
  DynVector<S> footForces(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& thetaDDot,
                          const DynVector<S>& tau) const;
  /// Hip and knee torques (τ_Rh, τ_Rk, τ_Lh, τ_Lk) realising a motion, minimum norm over (τ, λ)
  /// (the four actuators of a closed 3-dof chain leave one internal force free), as a 7-vector τ.
  DynVector<S> torquesForMotion(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& thetaDDot) const;

 private:
  BipedParameters<S> p_;
  BipedPose<S> home_;
  ConstrainedTree<S> model_;
};

#define SOMA_BIPED_EXTERN(S) extern template class PlanarBiped<S>;
SOMA_FOR_EACH_SCALAR(SOMA_BIPED_EXTERN)
#undef SOMA_BIPED_EXTERN

}  // namespace soma
