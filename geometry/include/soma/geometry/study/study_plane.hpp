#pragma once
// The 3-planes in the Study quadric (GF §11.2.2–11.2.3): in the coordinates x = (a + c)/2,
// y = (a − c)/2 the quadric a·c = 0 is x·x = y·y, and its 3-planes are x = M y with M ∈ O(4),
// i.e. (I − M) a + (I + M) c = 0. det M = +1: an A-plane (SO(3)_p, SE(2)_n and their cosets, the
// plane at infinity a = 0); det M = −1: a B-plane (the translations R³ and their cosets).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/study_parameters.hpp"
#include "soma/algebra/tolerance.hpp"

#include <string>

namespace soma {

enum class StudyPlaneKind { A, B };

template <class S> class StudyPlane {
 public:
  using Scalar = S;
  using Mat84 = Eigen::Matrix<S, 8, 4>;
  using Mat48 = Eigen::Matrix<S, 4, 8>;

  /// The plane (I − M) a + (I + M) c = 0 of an orthogonal M (validated: ‖MᵀM − I‖ within
  /// Tolerance::input, finite). GF §11.2.2, GF-11.2.2-three-planes-A-B
  static StudyPlane fromOrthogonal(const Mat4<S>& M);
  /// The plane spanned by four points of PR⁷ (columns). Throws InvalidInput when they do not span
  /// a 3-plane lying in the Study quadric. GF §11.2.2, GF-11.2.2-A-plane-cosets
  static StudyPlane fromSpan(const Mat84& points);

  /// The rotations about the point p: SO(3)_p, an A-plane through the identity with M = diag(1, R),
  /// R the Cayley transform (I + [p]×)(I − [p]×)⁻¹. GF §11.2.2, GF-11.2.2-planes-through-identity
  static StudyPlane rotationsAbout(const Vec3<S>& p);
  /// The planar motions SE(2)_n (rotations about axes parallel to the unit n, translations ⟂ n):
  /// an A-plane through the identity, M = diag(1, R) with R the half-turn about n.
  /// GF §11.2.2, GF-11.2.2-planes-through-identity
  static StudyPlane planarMotions(const Vec3<S>& n);
  /// The translations R³: the B-plane M = diag(1, −I₃). GF §11.2.2, GF-11.2.2-planes-through-identity
  static StudyPlane translations();
  /// The exceptional A-plane a = 0 ("infinite somas"), M = −I₄. GF §11.2.2, GF-11.2.2-planes-through-identity
  static StudyPlane atInfinity();

  const Mat4<S>& M() const { return M_; }
  StudyPlaneKind kind() const { return kind_; }
  /// The four linear equations [I − M | I + M] (rows). GF §11.2.2, GF-11.2.2-three-planes-A-B
  Mat48 equations() const;
  /// A basis of the plane: the columns ((M + I) y; (M − I) y) for y = e₀..e₃. GF §11.2.2
  Mat84 basis() const;
  /// The point a = (M + I) y, c = (M − I) y. GF §11.2.2, GF-11.2.2-three-planes-A-B
  Vec8<S> point(const Vec4<S>& y) const;
  /// |equations · x| / |x| (0 for points of the plane).
  S residual(const Vec8<S>& x) const;
  /// The plane moved by x ↦ g x (a coset g·P). GF §11.2.2, GF-11.2.2-A-plane-cosets
  StudyPlane leftTranslated(const DualQuaternion<S>& g) const;
  /// The plane moved by x ↦ x g.
  StudyPlane rightTranslated(const DualQuaternion<S>& g) const;

 private:
  StudyPlane(const Mat4<S>& M, StudyPlaneKind k) : M_(M), kind_(k) {}
  Mat4<S> M_;
  StudyPlaneKind kind_;
};

/// How two 3-planes of the quadric meet: the projective dimension of the intersection
/// (−1 = empty, 0 = a point, 1 = a line, 2 = a 2-plane, 3 = the same plane), from the corank of
/// the stacked 8×8 system (SVD, threshold Tolerance::rank relative to the largest singular value).
/// GF §11.2.3, GF-11.2.3-intersection-corank
template <class S> int intersectionDimension(const StudyPlane<S>& p, const StudyPlane<S>& q);
/// The same number by the book's shortcut: multiplicity of the eigenvalue 1 of M₁M₂ᵀ, minus 1
/// (for an orthogonal matrix, the dimension of ker(M₁M₂ᵀ − I)). GF §11.2.3, GF-11.2.3-intersection-corank
template <class S> int intersectionDimensionByEigenvalues(const StudyPlane<S>& p, const StudyPlane<S>& q);
/// The Cayley transform (I + [p]×)(I − [p]×)⁻¹ ∈ SO(3). GF §11.2.2, GF-11.2.2-planes-through-identity
template <class S> Mat3<S> cayleyRotation(const Vec3<S>& p);

extern template class StudyPlane<float>;
extern template class StudyPlane<double>;
extern template class StudyPlane<long double>;
extern template class StudyPlane<__float128>;
extern template class StudyPlane<mpfr::mpreal>;

}  // namespace soma
