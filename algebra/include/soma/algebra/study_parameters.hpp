#pragma once
// Study parameters (a0:a1:a2:a3:c0:c1:c2:c3) ∈ PR⁷ of a rigid motion (GF §9.3, §11.1–11.2).
//
// CONVENTION (the book's, see dual_quaternion.hpp): the motion p ↦ R p + t is the projective
// class of the dual quaternion ȟ = a + εc with a the quaternion of R and c = ½ t a
// (GF §9.3, seed 5657–5730: "g + ½tge", h1 h0* = t/2). Every rigid motion lies on the Study
// quadric a·c = a0c0 + a1c1 + a2c2 + a3c3 = 0; the points of the quadric with a = 0 form the
// exceptional 3-plane (an A-plane, "infinite somas", GF §11.2.2), which are not motions.
// ȟ and −ȟ (indeed every λȟ, λ ≠ 0) give the same point, which removes the double cover.
//
// A StudyParameters object holds any point of PR⁷ (geometry code needs points off the quadric
// and on the exceptional plane). Conversions to a motion (toSE3, toDualQuaternion, normalized,
// matrix) and the validated factory fromCoordinates check the input and throw InvalidInput with
// a message naming the defect: a NaN or infinite coordinate, the zero vector, a = 0 (to the
// rounding level of the coordinates, |a| ≤ eps·|v|: the exceptional 3-plane), or a point off
// the quadric by more than Tolerance::input() in the scale-free residual |a·c|/(|a||c|).
// Input is never projected onto the quadric.
#include "soma/algebra/dual_quaternion.hpp"

namespace soma {

template <class S> class StudyParameters {
 public:
  using Scalar = S;

  /// The identity (1:0:0:0:0:0:0:0).
  StudyParameters() : v_(Vec8<S>::Zero()) { v_(0) = S(1); }
  /// Any point (a0, a1, a2, a3, c0, c1, c2, c3) of PR⁷, unchecked (may be off the quadric or on
  /// the exceptional plane). Use fromCoordinates for user input that must be a rigid motion.
  explicit StudyParameters(const Vec8<S>& v) : v_(v) {}
  StudyParameters(const Vec4<S>& a, const Vec4<S>& c) { v_ << a, c; }

  /// Validated: v must be a rigid motion (see the header comment); throws InvalidInput.
  /// The coordinates are kept as given (not rescaled). GF §9.3, GF-9.3-study-quadric
  static StudyParameters fromCoordinates(const Vec8<S>& v);
  /// (a : ½ t a) with a the quaternion of R. GF §9.3, GF-9.3-dual-quaternion-isomorphism
  static StudyParameters fromSE3(const SE3<S>& g) {
    return StudyParameters(DualQuaternion<S>::fromSE3(g).coeffs());
  }
  /// The point of PR⁷ of a dual quaternion (its 8 coefficients). GF §9.3, GF-9.3-study-quadric
  static StudyParameters fromDualQuaternion(const DualQuaternion<S>& h) {
    return StudyParameters(h.coeffs());
  }
  /// From a 4×4 homogeneous matrix (validated by SE3::fromMatrix). GF §2.5.1, GF-2.5.1-homogeneous
  static StudyParameters fromMatrix(const Mat4<S>& m) { return fromSE3(SE3<S>::fromMatrix(m)); }

  const Vec8<S>& coeffs() const { return v_; }
  Vec4<S> a() const { return v_.template head<4>(); }
  Vec4<S> c() const { return v_.template tail<4>(); }

  /// a·c = a0c0 + a1c1 + a2c2 + a3c3, the raw Study form (zero on the quadric; it scales with
  /// the coordinates). GF §9.3, GF-9.3-study-quadric; GF §11.1, GF-11.1-SO4-is-whole-study-quadric
  S studyCondition() const { return a().dot(c()); }
  /// |a·c|/(|a||c|) (0 if a = 0 or c = 0): the residual compared with tolerances, invariant
  /// under a ↦ αa, c ↦ γc (projective scale and unit of length). GF §9.3, GF-9.3-study-quadric
  S studyDefect() const { return detail::studyDefect(a(), c()); }
  /// Finite and studyDefect() ≤ tol. GF §9.3, GF-9.3-study-quadric
  bool onStudyQuadric(const S& tol = Tolerance<S>::input()) const {
    return allFinite(v_) && studyDefect() <= tol;
  }
  /// |a| ≤ tol·|v| (a = 0 to relative precision tol): the exceptional 3-plane a = 0 of ideal
  /// points. The default tol = eps is the test toSE3 applies. GF §9.3, GF-9.3-study-quadric;
  /// GF §11.2.2, GF-11.2.2-planes-through-identity (the A-plane at infinity, M = −I₄)
  bool inExceptionalPlane(const S& tol = Tolerance<S>::epsilon()) const;

  /// The same point scaled to a·a = 1 (positive factor 1/|a|, so signs are kept). Validated as
  /// fromCoordinates. GF §9.3, GF-9.3-study-quadric
  StudyParameters normalized() const;
  /// The unit dual quaternion a/|a| + ε c/|a| (validated). GF §9.3, GF-9.3-study-quadric
  DualQuaternion<S> toDualQuaternion() const { return DualQuaternion<S>(normalized().v_); }
  /// The rigid motion (validated): R from a, t = 2 c a*/(a·a). GF §9.3, GF-9.3-study-quadric
  SE3<S> toSE3() const { return toDualQuaternion().toSE3(); }
  Mat4<S> matrix() const { return toSE3().matrix(); }

  /// Same point of PR⁷: v/|v| = ±o/|o| within tol (max-norm).
  bool isApprox(const StudyParameters& o, const S& tol) const;
  template <class T> StudyParameters<T> cast() const {
    return StudyParameters<T>(castMatrix<T>(v_));
  }

  /// Throws InvalidInput (prefixed by `who`) unless this point is a rigid motion.
  void requireMotion(const std::string& who) const;

 private:
  Vec8<S> v_;
};

// ---------------------------------------------------------------------------------------------
// Implementation

template <class S> bool StudyParameters<S>::inExceptionalPlane(const S& tol) const {
  const S m = v_.cwiseAbs().maxCoeff();
  if (!(m > S(0))) return true;  // the zero vector (not a point of PR⁷) has a = 0
  const Vec8<S> w = v_ / m;
  return w.template head<4>().squaredNorm() <= tol * tol * w.squaredNorm();
}

template <class S> void StudyParameters<S>::requireMotion(const std::string& who) const {
  const std::string p = who + ": ";
  if (!allFinite(v_))
    throw InvalidInput(p + "Study parameters have a NaN or infinite coordinate");
  if (v_.cwiseAbs().maxCoeff() == S(0))
    throw InvalidInput(p + "Study parameters are the zero vector (not a point of PR⁷)");
  if (inExceptionalPlane())
    throw InvalidInput(p + "Study parameters have a = (a0, a1, a2, a3) = 0: the point lies in the "
                           "exceptional 3-plane of the Study quadric (an ideal point, not a rigid "
                           "motion)");
  const S d = studyDefect();
  if (d > Tolerance<S>::input())
    throw InvalidInput(p + "Study parameters are off the Study quadric: |a·c|/(|a||c|) = " +
                       toString(d, 3) + " exceeds " + toString(Tolerance<S>::input(), 3) +
                       " (not projected; correct the input)");
}

template <class S> StudyParameters<S> StudyParameters<S>::fromCoordinates(const Vec8<S>& v) {
  const StudyParameters p(v);
  p.requireMotion("StudyParameters::fromCoordinates");
  return p;
}

template <class S> StudyParameters<S> StudyParameters<S>::normalized() const {
  using std::sqrt;
  requireMotion("StudyParameters::normalized");
  const Vec8<S> w = v_ / v_.cwiseAbs().maxCoeff();  // no overflow or underflow in |a|²
  return StudyParameters(Vec8<S>(w / sqrt(w.template head<4>().squaredNorm())));
}

template <class S> bool StudyParameters<S>::isApprox(const StudyParameters& o, const S& tol) const {
  using std::sqrt;
  const S m1 = v_.cwiseAbs().maxCoeff(), m2 = o.v_.cwiseAbs().maxCoeff();
  if (!(m1 > S(0)) || !(m2 > S(0))) return false;
  Vec8<S> u = v_ / m1, w = o.v_ / m2;
  u /= sqrt(u.squaredNorm());
  w /= sqrt(w.squaredNorm());
  const S d1 = (u - w).template lpNorm<Eigen::Infinity>();
  const S d2 = (u + w).template lpNorm<Eigen::Infinity>();
  return (d1 < d2 ? d1 : d2) <= tol;
}

using StudyParametersf = StudyParameters<float>;
using StudyParametersd = StudyParameters<double>;
using StudyParametersld = StudyParameters<long double>;
using StudyParametersq = StudyParameters<__float128>;
using StudyParametersmp = StudyParameters<mpreal>;

#define SOMA_STUDY_EXTERN(S) extern template class StudyParameters<S>;
SOMA_FOR_EACH_SCALAR(SOMA_STUDY_EXTERN)
#undef SOMA_STUDY_EXTERN

}  // namespace soma
