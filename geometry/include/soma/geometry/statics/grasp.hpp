#pragma once
// Gripping and friction (GF §12.5–12.6). Contacts are points p on the object with the unit
// normal n pointing INTO the object (the direction a finger pushes). The wrench of a unit normal
// force is 𝒩 = (p × n, n). Wrench sets are matrices whose columns are co-screws (6 rows in space,
// 3 rows (moment, f_x, f_y) in the plane).
//  - force closure, bilateral fingers: the 𝒩_i span se*(3) (rank 6)       — GF-12.5-force-closure-frictionless
//  - force closure, positive fingers: the 𝒩_i POSITIVELY span (LP)       — GF-12.5-positive-grasp-seven
//  - form closure: the feasible velocities {s : 𝒩_i(s) ≥ 0} are {0} (dual LP) — GF-12.5-form-closure
//  - friction: linearised cones; their edge wrenches positively span       — GF-12.6-*
#include "soma/geometry/statics/linear_program.hpp"
#include "soma/geometry/statics/wrench.hpp"

#include <vector>

namespace soma {

template <class S> using WrenchSet = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// The wrench of a unit force along the contact normal: (p × n, n). InvalidInput if n is not unit
/// (to Tolerance::input()). GF §12.5, GF-12.5-force-closure-frictionless
template <class S> Wrench<S> contactNormalWrench(const Vec3<S>& point, const Vec3<S>& normal);
/// Columns = the contact normal wrenches of the given contacts.
template <class S> WrenchSet<S> contactNormalWrenches(const std::vector<Vec3<S>>& points,
                                                      const std::vector<Vec3<S>>& normals);

/// Linear span of a wrench set: rank (Tolerance::rank relative to σ_max), the singular values,
/// and the screws annihilated by every wrench (the null space of Wᵀ: a velocity the set cannot
/// resist, e.g. the symmetry screw of an ungrippable surface). GF §12.5, GF-12.5-ungrippable-surfaces
template <class S> struct WrenchSpan {
  int rank = 0;
  std::vector<S> singularValues;  ///< descending, min(rows, cols) of them
  std::vector<Eigen::Matrix<S, Eigen::Dynamic, 1>> annihilatedScrews;  ///< unit, Wᵀ s ≈ 0
};
template <class S> WrenchSpan<S> wrenchSpan(const WrenchSet<S>& W);

/// Positive spanning (every wrench is a NON-NEGATIVE combination of the columns): rank = rows and
/// a strictly positive w with W w = 0 exists. margin = max_w min_i w_i over Σ w_i = 1 with the
/// columns normalised (0 when not positively spanning). GF §12.5, GF-12.5-positive-grasp-seven
template <class S> struct PositiveSpan {
  int rank = 0;
  S margin = S(0);
  bool spans = false;
};
template <class S> PositiveSpan<S> positiveSpan(const WrenchSet<S>& W);

/// Form closure by the dual problem: maximise Σ_i 𝒲_i(s) over feasible velocities
/// {s : 𝒲_i(s) ≥ 0, |s_j| ≤ 1}. Form closed iff rank = rows and that maximum is 0; otherwise
/// `escape` is a feasible velocity that breaks (or keeps) every contact. GF §12.5, GF-12.5-form-closure
template <class S> struct FormClosure {
  bool closed = false;
  int rank = 0;
  S escapeValue = S(0);
  Eigen::Matrix<S, Eigen::Dynamic, 1> escape;
};
template <class S> FormClosure<S> formClosure(const WrenchSet<S>& W);

/// Linearised friction cone at a contact: the k ≥ 3 edge wrenches of unit normal force,
/// (p × f_j, f_j), f_j = n + μ (cos θ_j t₁ + sin θ_j t₂), θ_j = 2πj/k (inscribed pyramid;
/// μ ≥ 0, any size — μ > 1 is physical, erratum E12.4). GF §12.6, GF-12.6-friction-cone,
/// GF-12.6-polyhedral-approximation
template <class S> WrenchSet<S> frictionConeEdges(const Vec3<S>& point, const Vec3<S>& normal,
                                                  const S& mu, int k);
/// The friction cone in standard form (contact at the origin, normal z): (0,0,0, γF cos θ,
/// γF sin θ, F), F ≥ 0, 0 ≤ γ ≤ μ. GF §12.6, GF-12.6-friction-cone
template <class S> Wrench<S> standardFrictionWrench(const S& F, const S& gamma, const S& theta);
/// Membership of the DUAL of the standard friction cone, corrected: ω arbitrary and
/// v_z ≥ μ √(v_x² + v_y²). GF §12.6, GF-12.6-dual-friction-cone (corrected, erratum E12.2: the
/// book's dual, only ω = 0 and |v_t| ≤ v_z/μ, is a strict subset; studies/gf12/grasp.cpp shows it)
template <class S> bool inDualFrictionCone(const SE3Tangent<S>& s, const S& mu);

/// Planar wrench (moment about the origin, f_x, f_y) of a force f at p. GF §12.6
template <class S> Vec3<S> planarWrench(const Vec2<S>& point, const Vec2<S>& force);
/// The two edge wrenches of a planar friction cone (n ± μ t), as the columns of a 3 × 2 set.
template <class S> WrenchSet<S> planarFrictionConeEdges(const Vec2<S>& point, const Vec2<S>& normal,
                                                        const S& mu);
/// The geometric two-finger criterion: the segment joining the contacts lies strictly inside
/// both friction cones, which point towards each other or both away. GF §12.6,
/// GF-12.6-planar-two-finger-grasp
template <class S> bool planarTwoFingerForceClosure(const Vec2<S>& p1, const Vec2<S>& n1,
                                                    const Vec2<S>& p2, const Vec2<S>& n2, const S& mu);

/// Second-order contact (GF §12.5, GF-12.5-second-order-contact): surface k_x x² + k_y y² = 2z
/// at the origin with normal z; the finger (or, with the sign of s changed, the object) moves
/// along s = (ω, v). First order: v_z; second order: k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x.
template <class S> S secondOrderContactForm(const S& kx, const S& ky, const SE3Tangent<S>& s);

/// What a small motion e^{εs} of the OBJECT does to a fixed finger at the contact (finger above
/// the surface: k_x x² + k_y y² − 2z ≤ 0). GF §12.5, GF-12.5-curved-feasible-regions (corrected,
/// erratum E12.3: v_z ≤ 0 with the second order deciding v_z = 0).
enum class ContactMotion { Separates, Penetrates, ThirdOrder };
template <class S> ContactMotion classifyObjectMotion(const S& kx, const S& ky, const SE3Tangent<S>& s);

}  // namespace soma
