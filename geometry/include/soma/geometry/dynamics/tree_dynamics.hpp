#pragma once
// Dynamics of a tree-structured mechanism (GF §14.1): joint screws and link inertias in ONE fixed
// frame, product of exponentials along the ancestry (§14.1.2), link velocities and accelerations,
// the joint equations accumulated over the subtree (§14.1.1, corrected: erratum 1 — the sums run
// over i ⪯ j, link i included), the recursive up/down Newton–Euler pass over the tree in home
// coordinates (§14.1.3, corrected: errata 2, 3), the mass matrix, forward dynamics and energies.
//
// Conventions as in serial_dynamics.hpp (GF ch. 13): screws s = (ω, v), co-screws (moment, force),
// [a, b] = ad(a) b, {s, P} = −ad(s)ᵀP, N about the origin of the fixed frame. Unlike
// SerialDynamics, gravity is any acceleration vector g (planar models in the xy-plane use
// g = (0, −9.81, 0)), and a link may be MASSLESS (inertia 0): the intermediate links of a
// spherical or universal joint or of a floating root made of six basis joints (GF §14.1.1 lines
// 8752–8762, §14.1.2: a star is a tree with a 6-dof root joint) carry no mass.
// Defined in tree_dynamics_impl.hpp, instantiated per scalar in geometry/src/dynamics/tree_dynamics_*.cpp.
#include "soma/algebra/screw_bracket.hpp"
#include "soma/geometry/dynamics/serial_dynamics.hpp"
#include "soma/geometry/dynamics/tree_topology.hpp"

#include <vector>

namespace soma {

template <class S> struct TreeConfiguration {
  std::vector<SE3<S>> placements;  ///< K_i = K_parent exp(θ_i s_i⁰) (GF §14.1.2)
  std::vector<Vec6<S>> screws;     ///< s_i(θ) = Ad(K_i) s_i⁰
  std::vector<Mat6<S>> inertias;   ///< N_i(θ) = K_i⁻ᵀ N_i⁰ K_i⁻¹
};

/// The planar 3×3 inertia of GF §14.4 (lines 9112–9124), GF-14.4-planar-inertia:
/// [[m k², −m c_y, m c_x], [−m c_y, m, 0], [m c_x, 0, m]], m k² = I_zz about the ORIGIN
/// = I_c + m |c|². It is the (ω_z, v_x, v_y) block of the spatial N.
template <class S> Eigen::Matrix<S, 3, 3> planarInertia(const S& mass, const S& cx, const S& cy, const S& inertiaAboutCentre);
/// The spatial inertia (6×6, about the origin) of a planar body: mass m, centre (c_x, c_y, 0),
/// I_zz = izz about the centre and I_xx = I_yy = izz/2 (a thin plate; out-of-plane terms never act).
template <class S> Mat6<S> planarBodyInertia(const S& mass, const S& cx, const S& cy, const S& izz);

template <class S> class TreeDynamics {
 public:
  /// Home screws s_i⁰ (unit: |ω| = 1, or ω = 0 and |v| = 1), home inertias N_i⁰ (symmetric 6×6,
  /// positive semi-definite; the zero matrix for a massless link), gravity acceleration g.
  /// InvalidInput for mismatched counts, a non-unit or NaN screw, an asymmetric or NaN inertia, a
  /// non-finite g.
  TreeDynamics(TreeTopology topology, std::vector<Vec6<S>> homeScrews, std::vector<Mat6<S>> homeInertias,
               const Vec3<S>& gravity);

  int dof() const { return topology_.size(); }
  const TreeTopology& topology() const { return topology_; }
  const std::vector<Vec6<S>>& homeScrews() const { return s0_; }
  const std::vector<Mat6<S>>& homeInertias() const { return N0_; }
  const Vec3<S>& gravity() const { return g_; }
  /// The gravity screw g = (0, g) (the acceleration the ground "has" in the RNE start, §13.3).
  Vec6<S> gravityScrew() const;

  TreeConfiguration<S> configuration(const DynVector<S>& theta) const;
  /// q̇_i = q̇_parent + θ̇_i s_i (GF §14.1.2 line 8786).
  std::vector<Vec6<S>> linkVelocities(const TreeConfiguration<S>& c, const DynVector<S>& thetaDot) const;
  /// q̈_i = q̈_parent + θ̈_i s_i + θ̇_i [q̇_i, s_i] (GF §14.1.2 line 8796; gravity NOT included).
  std::vector<Vec6<S>> linkAccelerations(const TreeConfiguration<S>& c, const DynVector<S>& thetaDot,
                                         const DynVector<S>& thetaDDot) const;
  /// The joint equations of GF §14.1.1 (line 8740, corrected: erratum 1):
  /// τ_i = Σ_{i⪯j} (q̈_jᵀN_j s_i + q̇_jᵀN_j[s_i, q̇_j] − G_jᵀ s_i), G_j = N_j g. GF-14.1.1-tree-joint-equations
  DynVector<S> inverseDynamicsSpatial(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                      const DynVector<S>& thetaDDot) const;
  /// The recursive up/down pass of GF §14.1.3 (box at lines 8808–8844) in home coordinates
  /// (corrected: errata 2, 3; the printed passes — the parent's angle in the down pass, line 8838,
  /// and the parent's velocity for its acceleration, line 8824 — are computed in
  /// studies/gf14/trees.cpp). GF-14.1.3-tree-recursive-dynamics
  DynVector<S> inverseDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                               const DynVector<S>& thetaDDot) const;
  /// A_ij = s_iᵀ N̄_j s_j for i ⪯ j (N̄_j = Σ_{j⪯k} N_k), 0 for unrelated joints.
  DynMatrix<S> massMatrix(const TreeConfiguration<S>& c) const;
  DynMatrix<S> massMatrix(const DynVector<S>& theta) const { return massMatrix(configuration(theta)); }
  /// θ̈ = A⁻¹(τ − bias). InvalidInput if A is singular (a joint that moves no mass).
  DynVector<S> forwardDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& tau) const;
  /// E_K = ½ Σ q̇_iᵀ N_i q̇_i.
  S kineticEnergy(const DynVector<S>& theta, const DynVector<S>& thetaDot) const;
  /// E_P = −Σ m_i g·c_i (c_i the centre of mass at θ).
  S potentialEnergy(const DynVector<S>& theta) const;
  /// Total spatial momentum Σ N_i q̇_i (a co-screw about the origin).
  Vec6<S> momentum(const DynVector<S>& theta, const DynVector<S>& thetaDot) const;
  /// The wrench the ground must supply, Σ_j (N_j q̈_j + {q̇_j, N_j q̇_j} − G_j): the shaking wrench of
  /// GF §14.3.2 (line 9102) / the star root equation of §14.1.1 (line 8746) summed over all links.
  Vec6<S> totalWrench(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& thetaDDot) const;

  void checkState(const DynVector<S>& v, const char* what) const;

 private:
  TreeTopology topology_;
  std::vector<Vec6<S>> s0_;
  std::vector<Mat6<S>> N0_;
  Vec3<S> g_;
};

#define SOMA_TREE_DYNAMICS_EXTERN(S)                                                                          \
  extern template class TreeDynamics<S>;                                                                     \
  extern template Eigen::Matrix<S, 3, 3> planarInertia<S>(const S&, const S&, const S&, const S&);            \
  extern template Mat6<S> planarBodyInertia<S>(const S&, const S&, const S&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_TREE_DYNAMICS_EXTERN)
#undef SOMA_TREE_DYNAMICS_EXTERN

}  // namespace soma
