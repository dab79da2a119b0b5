#pragma once
// A tree with holonomic loop-closing constraints (GF §14.2–14.3): parallel mechanisms as
// constrained trees and stars. Each constraint k is a wrench W_k that the ground (or another link)
// exerts on link A; the constraint is W_kᵀ(q̇_A − q̇_B) = 0 (B = −1: the ground), i.e. row k of
// the constraint matrix C_kj = W_kᵀ s_j (±, for the joints j on the ancestry of A or of B),
// GF §14.3.1 line 9050 (Σ_{1⪯j⪯l} θ̇_j W_kᵀ s_j = 0). Two kinds:
//   * point constraints: a point of A coincides with a point of B (a ball or pin joint cut open);
//     W_k = (r × e_k, e_k), a force along the fixed direction e_k through the current point r
//     (GF §14.6 lines 9300–9304, GF-14.6-stewart-constraint-wrenches);
//   * fixed-wrench constraints: W_k constant in space, for a subgroup of freedoms (GF §14.2.1,
//     e.g. the pen example: se(2) annihilated by (0, k), (i, 0), (j, 0)).
// The freedom vectors are the null space of C (GF §14.3.1, GF-14.3.1-freedom-vectors); the
// equations of motion are eliminated with them (α, §14.3.2) or the multipliers λ are extracted
// with dual vectors (GF-14.3.2-constraint-magnitude). Forward dynamics is done in the null space
// (θ̈ = θ̈_p + Z u), and a simulation step (RK4) is followed by an optional projection back onto
// the constraint manifold; the drift and the energy are reported by the caller.
// Defined in constrained_tree_impl.hpp, instantiated per scalar in constrained_tree_*.cpp.
#include "soma/geometry/dynamics/tree_dynamics.hpp"

namespace soma {

template <class S> struct LoopConstraint {
  enum class Kind { Point, FixedWrench } kind = Kind::Point;
  int linkA = 0;          ///< the constrained link
  int linkB = -1;         ///< the other link (−1: the ground)
  Vec3<S> homePoint{};    ///< Point: the common point at θ = 0 (the mechanism is assembled at home)
  Vec3<S> direction{};    ///< Point: unit force direction e (fixed frame)
  Vec6<S> wrench{};       ///< FixedWrench: W (fixed frame)

  static LoopConstraint point(int a, int b, const Vec3<S>& p, const Vec3<S>& e) {
    LoopConstraint c;
    c.kind = Kind::Point;
    c.linkA = a;
    c.linkB = b;
    c.homePoint = p;
    c.direction = e;
    return c;
  }
  static LoopConstraint fixedWrench(int a, int b, const Vec6<S>& w) {
    LoopConstraint c;
    c.kind = Kind::FixedWrench;
    c.linkA = a;
    c.linkB = b;
    c.wrench = w;
    return c;
  }
};

/// Actuator forces and multipliers from an inverse-dynamics solve.
template <class S> struct ConstrainedForces {
  DynVector<S> actuators;  ///< τ_a (one per column of the actuation matrix)
  DynVector<S> lambda;     ///< λ_k (one per constraint)
  S residual;              ///< max |Bτ_a + Cᵀλ − τ_ID| (consistency of the solve)
};

template <class S> struct ConstrainedState {
  DynVector<S> theta, thetaDot;
};

template <class S> class ConstrainedTree {
 public:
  /// InvalidInput for a constraint on a link out of range, A = B, or a non-unit direction.
  ConstrainedTree(TreeDynamics<S> tree, std::vector<LoopConstraint<S>> constraints);

  const TreeDynamics<S>& tree() const { return tree_; }
  const std::vector<LoopConstraint<S>>& constraints() const { return cons_; }
  int dof() const { return tree_.dof(); }
  int numConstraints() const { return int(cons_.size()); }

  /// The wrenches W_k(θ).
  std::vector<Vec6<S>> constraintWrenches(const TreeConfiguration<S>& c) const;
  /// C (m × n), C θ̇ = 0 the velocity constraints.
  DynMatrix<S> constraintMatrix(const TreeConfiguration<S>& c) const;
  DynMatrix<S> constraintMatrix(const DynVector<S>& theta) const { return constraintMatrix(tree_.configuration(theta)); }
  /// Numerical rank of C (Tolerance::rank relative to its largest singular value).
  int constraintRank(const DynVector<S>& theta) const;
  /// Smallest nonzero-expected singular value of C over its largest (0 at a singular posture).
  S conditionRatio(const DynVector<S>& theta) const;
  /// The freedom vectors: an orthonormal basis (n × d) of the null space of C, d = n − rank(C).
  /// GF §14.3.1, GF-14.3.1-freedom-vectors
  DynMatrix<S> freedomBasis(const DynVector<S>& theta) const;
  /// Position residual of each constraint: e·(r_A − r_B) (point) or Wᵀ log(K_A K_B⁻¹) (fixed wrench).
  DynVector<S> positionResidual(const DynVector<S>& theta) const;
  /// γ with C θ̈ + γ = 0 (the differentiated constraints, θ̈-free part).
  DynVector<S> accelerationBias(const DynVector<S>& theta, const DynVector<S>& thetaDot) const;

  /// Actuator forces by elimination with the freedom vectors (GF §14.3.2 lines 9070–9086):
  /// Zᵀ B τ_a = Zᵀ τ_ID(θ, θ̇, θ̈), then λ by least squares from Cᵀλ = τ_ID − Bτ_a.
  ConstrainedForces<S> inverseDynamicsAlpha(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                            const DynVector<S>& thetaDDot, const DynMatrix<S>& actuation) const;
  /// The full multiplier system [B, Cᵀ] (τ_a, λ) = τ_ID solved at once (minimum norm if redundant).
  ConstrainedForces<S> inverseDynamicsMultipliers(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                  const DynVector<S>& thetaDDot, const DynMatrix<S>& actuation) const;
  /// λ_k = v_kᵀ(τ_ID − τ) with the dual vector v_k: C v_k = e_k (GF §14.3.2 lines 9088–9100,
  /// GF-14.3.2-constraint-magnitude). InvalidInput if C does not have full row rank.
  DynVector<S> multipliersByDualVectors(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                        const DynVector<S>& thetaDDot, const DynVector<S>& tau) const;
  /// θ̈ from τ: θ̈ = θ̈_p + Z u, C θ̈_p = −γ (minimum norm), (ZᵀAZ) u = Zᵀ(τ − bias − Aθ̈_p).
  DynVector<S> forwardDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& tau) const;
  /// Newton projection of θ onto the constraints (minimum-norm corrections, ≤ digits<S>() + 20 sweeps
  /// to Tolerance::identity) and of θ̇ onto the null space of C.
  ConstrainedState<S> project(const ConstrainedState<S>& y) const;
  /// One classical RK4 step (constant τ) of the null-space dynamics, then project() if asked.
  ConstrainedState<S> rk4Step(const ConstrainedState<S>& y, const S& h, const DynVector<S>& tau, bool projectAfter) const;
  S totalEnergy(const ConstrainedState<S>& y) const {
    return tree_.kineticEnergy(y.theta, y.thetaDot) + tree_.potentialEnergy(y.theta);
  }

 private:
  TreeDynamics<S> tree_;
  std::vector<LoopConstraint<S>> cons_;
};

/// x minimising |x| among the minimisers of |M x − b| (pseudo-inverse by the small SVD, rank by
/// Tolerance::rank). rankOut (optional) receives the numerical rank.
template <class S> DynVector<S> minimumNormSolve(const DynMatrix<S>& M, const DynVector<S>& b, int* rankOut = nullptr);
/// Orthonormal basis of the null space of M (columns).
template <class S> DynMatrix<S> nullSpace(const DynMatrix<S>& M);

#define SOMA_CONSTRAINED_TREE_EXTERN(S)                                                      \
  extern template class ConstrainedTree<S>;                                                 \
  extern template DynVector<S> minimumNormSolve<S>(const DynMatrix<S>&, const DynVector<S>&, int*); \
  extern template DynMatrix<S> nullSpace<S>(const DynMatrix<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_CONSTRAINED_TREE_EXTERN)
#undef SOMA_CONSTRAINED_TREE_EXTERN

}  // namespace soma
