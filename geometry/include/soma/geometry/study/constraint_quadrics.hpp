#pragma once
// Constraint varieties in Study parameters (GF §11.4–11.5): the sphere condition of an S–S leg
// as a quadric of PR⁷ and the 3-plane of a 2R dyad. The book's printed forms of the S–S and
// Stewart-leg quadrics are evaluated literally in studies/gf11/study_quadric.cpp.
#include "soma/algebra/study_parameters.hpp"

namespace soma {

template <class S> using Mat8 = Eigen::Matrix<S, 8, 8>;

/// The motions g with |g(q) − p|² = L² (platform point q, base point p, leg length L) form the
/// quadric xᵀ Q x = 0 of PR⁷, with Q = BᵀB − L² diag(I₄, 0) and B x = a q + 2c − p a (quaternion
/// products, p, q pure): since g(q) − p = (a q + 2c − p a) a*/|a|² when c = ½ t a.
/// GF §11.5.4, GF-11.5.4-stewart-leg-quadric; with p = 0, q = (0, 0, l), L = l it is the S–S
/// variety of GF §11.5.3, GF-11.5.3-SS-link-variety.
template <class S> Mat8<S> sphereConstraintQuadric(const Vec3<S>& p, const Vec3<S>& q, const S& L);

/// The Study quadric a·c = 0 as the symmetric matrix ½ [[0, I], [I, 0]]. GF §11.1
template <class S> Mat8<S> studyQuadricMatrix();

/// xᵀ Q x / |x|² for Study coordinates x (0 on the quadric).
template <class S> S quadricResidual(const Mat8<S>& Q, const Vec8<S>& x);

/// The four linear equations of the 2R dyad (first axis z, second axis through (l, 0, 0) at
/// twist angle α about x): l a₂ − c₃, l a₁ − c₀, l a₁ cos α − c₁ sin α, l a₂ cos α − c₂ sin α.
/// GF §11.4, GF-11.4-2R-three-plane
template <class S> Eigen::Matrix<S, 4, 8> twoRevoluteEquations(const S& l, const S& alpha);

#define SOMA_CONSTRAINT_QUADRICS_EXTERN(S)                                                     \
  extern template Mat8<S> sphereConstraintQuadric<S>(const Vec3<S>&, const Vec3<S>&, const S&); \
  extern template Mat8<S> studyQuadricMatrix<S>();                                              \
  extern template S quadricResidual<S>(const Mat8<S>&, const Vec8<S>&);                         \
  extern template Eigen::Matrix<S, 4, 8> twoRevoluteEquations<S>(const S&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_CONSTRAINT_QUADRICS_EXTERN)
#undef SOMA_CONSTRAINT_QUADRICS_EXTERN

}  // namespace soma
