#pragma once
// Holonomic (scleronomic) constraints on a rigid body and on a serial robot (GF §14.2): the
// freedom-screw system and the dual constraint-wrench system (W_iᵀz_j = 0, corrected index ranges:
// erratum 4), dual bases, the quadric-surface example (corrected quartics: errata 5, 6), the
// constrained rigid body with the multipliers λ eliminated (reduced equations) or extracted with
// a dual basis, and the constrained serial robot as a ConstrainedTree with fixed constraint wrenches.
// Five scalars in geometry/src/dynamics/holonomic_constraints.cpp.
#include "soma/geometry/dynamics/constrained_tree.hpp"

#include <array>

namespace soma {

template <class S> using Mat6X = Eigen::Matrix<S, 6, Eigen::Dynamic>;

/// Constraint wrenches W (6 × (6 − n)) with Wᵀz_j = 0 for the n freedoms z_j (columns of Z):
/// an orthonormal basis of the annihilator. GF §14.2.1 line 8866 (corrected, erratum 4),
/// GF-14.2.1-freedom-constraint-duality. InvalidInput if the z_j are dependent or NaN.
template <class S> Mat6X<S> constraintWrenchBasis(const Mat6X<S>& Z);
/// Complementary screws Z_c (6 × (6 − n)) dual to W: W_iᵀ z_cj = δ_ij (Z_c = W (WᵀW)⁻¹);
/// z_c + any freedom combination is dual too. GF §14.2.2 lines 8966–8976, GF-14.2.2-dual-basis-multipliers
template <class S> Mat6X<S> dualComplement(const Mat6X<S>& W);

/// GF §14.2.1 lines 8928–8942, GF-14.2.1-quadric-surface-freedoms-wrenches: freedoms z₁, z₂, z₃
/// and constraint wrenches W₄, W₅, W₆ of a body point on k_x x² + k_y y² − 2z = 0 with a body line
/// along the normal, at the surface point (x, y).
template <class S> Mat6X<S> quadricSurfaceFreedoms(const S& kx, const S& ky, const S& x, const S& y);
template <class S> Mat6X<S> quadricSurfaceWrenches(const S& kx, const S& ky, const S& x, const S& y);
/// The three quartics of GF lines 8908, 8922, 8924 on the Study parameters (a₀..a₃, b₀..b₃) of a
/// pose (h₀ + εh₁, point image (1 + ε(x i + y j + z k)) with x = 2X …): surface k_xX² + k_yY² − Z|a|²
/// and the alignment quartics k_x n₃ X + (a₀a₂ + a₁a₃)|a|², k_y n₃ Y + (a₂a₃ − a₀a₁)|a|²
/// (corrected, errata 5, 6: the book prints factors 2, computed in studies/gf14/constraints.cpp).
/// GF-14.2.1-quadric-surface-constraint-variety
template <class S>
Vec3<S> quadricSurfaceQuartics(const S& kx, const S& ky, const Eigen::Matrix<S, 4, 1>& a, const Eigen::Matrix<S, 4, 1>& b);

/// A rigid body whose freedoms form a Lie subalgebra span(Z) (a subgroup: fixed point, planar
/// motion), so the constraint wrenches W are constant in space. GF §14.2.2, GF-14.2.2-constrained-rigid-body
template <class S> class ConstrainedRigidBody {
 public:
  /// homeInertia N⁰ (at g = identity), freedoms Z (6 × n, independent). InvalidInput otherwise.
  ConstrainedRigidBody(SpatialInertia<S> homeInertia, Mat6X<S> freedoms);
  const Mat6X<S>& freedoms() const { return Z_; }
  const Mat6X<S>& wrenches() const { return W_; }
  /// q̈ ∈ span Z from the reduced equations q̈ᵀNz_i + q̇ᵀN[z_i, q̇] = Fᵀz_i (GF lines 8958–8964).
  Vec6<S> acceleration(const SE3<S>& pose, const Vec6<S>& qdot, const Vec6<S>& F) const;
  /// The DAE N q̈ + {q̇, N q̇} = F + Σ λ_j W_j, W_jᵀq̈ = 0 solved at once (q̈, λ): 6 + (6 − n) unknowns.
  std::pair<Vec6<S>, DynVector<S>> solveMultipliers(const SE3<S>& pose, const Vec6<S>& qdot, const Vec6<S>& F) const;
  /// λ_j = z_cjᵀ(N q̈ + {q̇, N q̇} − F) with complementary screws dual to W (GF lines 8970–8976).
  DynVector<S> multipliersByDualBasis(const SE3<S>& pose, const Vec6<S>& qdot, const Vec6<S>& qddot, const Vec6<S>& F,
                                      const Mat6X<S>& complement) const;
  Mat6<S> inertia(const SE3<S>& pose) const { return coadjointTransform(pose, N0_.matrix()); }

 private:
  SpatialInertia<S> N0_;
  Mat6X<S> Z_, W_;
};

/// A serial robot whose last link is held to a subgroup by constant wrenches W_k (e.g. the pen
/// on a table: (0, k), (i, 0), (j, 0)): a ConstrainedTree (chain topology, gravity −z).
/// GF §14.2.3, GF-14.2.3-constrained-serial-robot
template <class S> ConstrainedTree<S> constrainedSerialRobot(const SerialDynamics<S>& robot, const std::vector<Vec6<S>>& wrenches);

#define SOMA_HOLONOMIC_EXTERN(S)                                                                                   \
  extern template Mat6X<S> constraintWrenchBasis<S>(const Mat6X<S>&);                                             \
  extern template Mat6X<S> dualComplement<S>(const Mat6X<S>&);                                                    \
  extern template Mat6X<S> quadricSurfaceFreedoms<S>(const S&, const S&, const S&, const S&);                     \
  extern template Mat6X<S> quadricSurfaceWrenches<S>(const S&, const S&, const S&, const S&);                     \
  extern template Vec3<S> quadricSurfaceQuartics<S>(const S&, const S&, const Eigen::Matrix<S, 4, 1>&,            \
                                                    const Eigen::Matrix<S, 4, 1>&);                               \
  extern template class ConstrainedRigidBody<S>;                                                                 \
  extern template ConstrainedTree<S> constrainedSerialRobot<S>(const SerialDynamics<S>&, const std::vector<Vec6<S>>&);
SOMA_FOR_EACH_SCALAR(SOMA_HOLONOMIC_EXTERN)
#undef SOMA_HOLONOMIC_EXTERN

}  // namespace soma
