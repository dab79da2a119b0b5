#pragma once
// The 6×6 screw formulation of rigid-body dynamics (GF §13.1–13.2.1, SB §2): spatial inertia N,
// its transformation under SE(3) (the symmetric square of the coadjoint representation), momentum,
// kinetic energy, the coadjoint action {s, P} and the equation of motion N ṡ + {s, N s} = W.
//
// Conventions (fixed for soma): screws/twists s = (ω, v) with v the velocity of the point at the
// origin (v = q × ω for a pure rotation about a line through q); co-screws (momenta, wrenches)
// P = (l, p), l the angular part about the origin; the pairing P(s) = Pᵀ s = l·ω + p·v.
// Everything is in one fixed inertial frame, so N changes as the body moves (SB §1, §2).
//
// SpatialInertia is the reusable part for GF ch. 13 serial-robot dynamics: it keeps (m, c, I_c)
// — mass, centre of mass and the 3×3 inertia about the centre of mass — and produces the 6×6
// matrix about the origin; bodies add (composite inertia) and move rigidly.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/so3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <string>

namespace soma {

template <class S> class SpatialInertia {
 public:
  /// A rigid body of mass m > 0, centre of mass c and 3×3 inertia tensor I_c about c (symmetric,
  /// positive definite). InvalidInput names the defect otherwise.
  SpatialInertia(const S& mass, const Vec3<S>& centreOfMass, const Mat3<S>& inertiaAboutCentre)
      : m_(mass), c_(centreOfMass), ic_(inertiaAboutCentre) {
    validate();
  }
  /// Body with principal moments d = (d_x, d_y, d_z) along the axes, centre of mass at the origin:
  /// SB §5's diagonal inertia (d_i = m k_i², k_i the radius of gyration).
  static SpatialInertia diagonal(const S& mass, const Vec3<S>& d) {
    return SpatialInertia(mass, Vec3<S>::Zero(), Mat3<S>(d.asDiagonal()));
  }
  /// Read back (m, c, I_c) from a 6×6 matrix of the form [[I, mC], [mCᵀ, m I₃]] (GF §13.1).
  /// InvalidInput if it is not symmetric or not of that block form (within Tolerance::input()).
  static SpatialInertia fromMatrix(const Mat6<S>& N);

  const S& mass() const { return m_; }
  const Vec3<S>& centreOfMass() const { return c_; }
  const Mat3<S>& inertiaAboutCentre() const { return ic_; }
  /// The 3×3 block I of N: the inertia about the ORIGIN, I_c − m C² (C = ad(c)). SB §2 calls it
  /// "the usual 3×3 inertia matrix"; it is the usual one only when c = 0 (catalogue erratum 8).
  Mat3<S> inertiaAboutOrigin() const {
    const Mat3<S> C = skew(c_);
    return ic_ - m_ * C * C;
  }
  /// N = [[I, mC], [mCᵀ, m I₃]] with I about the origin. GF §13.1, SB-2-inertia-coadjoint-eom
  Mat6<S> matrix() const {
    Mat6<S> N;
    const Mat3<S> C = skew(c_);
    N << inertiaAboutOrigin(), m_ * C, m_ * C.transpose(), m_ * Mat3<S>::Identity();
    return N;
  }

  /// Momentum co-screw P = N s = (l, p): l = I ω + m c × v, p = m v + m ω × c. GF §13.1
  Vec6<S> momentum(const SE3Tangent<S>& s) const {
    const Vec3<S> w = s.ang(), v = s.lin();
    Vec6<S> P;
    P.template head<3>() = inertiaAboutOrigin() * w + m_ * c_.cross(v);
    P.template tail<3>() = m_ * v + m_ * w.cross(c_);
    return P;
  }
  /// E_K = ½ sᵀ N s = ½ (ω·l + v·p). GF §13.1, SB-2-screws-coscrews-transform
  S kineticEnergy(const SE3Tangent<S>& s) const { return s.coeffs().dot(momentum(s)) / S(2); }

  /// The same body after the rigid motion g (R, t): c' = R c + t, I_c' = R I_c Rᵀ. Computed
  /// directly (no 6×6 algebra); equals H⁻ᵀ N H⁻¹ (coadjointTransform), the "skew axis theorem"
  /// that contains the parallel-axis theorem. GF §13.1
  SpatialInertia transformed(const SE3<S>& g) const {
    const Mat3<S> R = g.rotation();
    return SpatialInertia(m_, Vec3<S>(R * c_ + g.translation()), Mat3<S>(R * ic_ * R.transpose()));
  }
  /// Composite body (two bodies rigidly joined): masses add, the centre of mass is the weighted
  /// mean, and the inertias about the new centre add by the parallel-axis theorem. N₁ + N₂ = N.
  SpatialInertia operator+(const SpatialInertia& o) const {
    const S M = m_ + o.m_;
    const Vec3<S> c = (m_ * c_ + o.m_ * o.c_) / M;
    const Mat3<S> d1 = skew(Vec3<S>(c_ - c)), d2 = skew(Vec3<S>(o.c_ - c));
    return SpatialInertia(M, c, Mat3<S>(ic_ - m_ * d1 * d1 + o.ic_ - o.m_ * d2 * d2));
  }

  template <class T> SpatialInertia<T> cast() const {
    return SpatialInertia<T>(scalarCast<T>(m_), castMatrix<T>(c_), castMatrix<T>(ic_));
  }

 private:
  void validate() const;
  S m_;
  Vec3<S> c_;
  Mat3<S> ic_;
};

/// N ↦ H⁻ᵀ N H⁻¹ with H = Ad(g) = [[R, 0], [T R, R]], H⁻ᵀ = [[R, T R], [0, R]]
/// (GF §13.1, SB-2-inertia-coadjoint-eom). Works for any 6×6 form that transforms like an inertia
/// (stiffness, damping: SB §7).
template <class S> Mat6<S> coadjointTransform(const SE3<S>& g, const Mat6<S>& N) {
  const Mat6<S> Hinv = g.inverse().adjoint();
  return Hinv.transpose() * N * Hinv;
}
/// Co-screw P ↦ H⁻ᵀ P (coadjoint representation). SB-2-screws-coscrews-transform
template <class S> Vec6<S> coadjointAct(const SE3<S>& g, const Vec6<S>& P) {
  return g.inverse().adjoint().transpose() * P;
}
/// Coadjoint action of a screw on a co-screw, {s, P} = −ad(s)ᵀ P = (ω×l + v×p, ω×p).
/// GF §13.1, SB-2-inertia-coadjoint-eom
template <class S> Vec6<S> coadjoint(const SE3Tangent<S>& s, const Vec6<S>& P) {
  const Vec3<S> w = s.ang(), v = s.lin(), l = P.template head<3>(), p = P.template tail<3>();
  Vec6<S> out;
  out.template head<3>() = w.cross(l) + v.cross(p);
  out.template tail<3>() = w.cross(p);
  return out;
}

/// Acceleration ṡ of a free rigid body from N ṡ + {s, N s} = W (GF §13.2.1, SB §2, SB-2-inertia-
/// coadjoint-eom): ṡ = N⁻¹ (W − {s, N s}), N solved by Cholesky (N symmetric positive definite).
/// N is the inertia in the fixed frame at the current pose. InvalidInput if N is not positive
/// definite.
template <class S>
SE3Tangent<S> rigidBodyAcceleration(const Mat6<S>& N, const SE3Tangent<S>& s, const Vec6<S>& W);

// ---------------------------------------------------------------------------------------------

template <class S> void SpatialInertia<S>::validate() const {
  using std::abs;
  if (!isFinite(m_) || !(m_ > S(0)))
    throw InvalidInput("SpatialInertia: mass " + toString(m_) + " is not a positive number");
  if (!allFinite(c_)) throw InvalidInput("SpatialInertia: centre of mass has a NaN or infinite entry");
  if (!allFinite(ic_)) throw InvalidInput("SpatialInertia: inertia tensor has a NaN or infinite entry");
  const S scale = ic_.cwiseAbs().maxCoeff();
  if ((ic_ - ic_.transpose()).cwiseAbs().maxCoeff() > Tolerance<S>::input() * scale)
    throw InvalidInput("SpatialInertia: inertia tensor about the centre of mass is not symmetric");
  Eigen::LLT<Mat3<S>> llt(ic_);
  if (llt.info() != Eigen::Success || !(scale > S(0)))
    throw InvalidInput("SpatialInertia: inertia tensor about the centre of mass is not positive "
                       "definite");
}

template <class S> SpatialInertia<S> SpatialInertia<S>::fromMatrix(const Mat6<S>& N) {
  if (!allFinite(N)) throw InvalidInput("SpatialInertia::fromMatrix: N has a NaN or infinite entry");
  const S scale = N.cwiseAbs().maxCoeff();
  const S tol = Tolerance<S>::input() * (scale > S(1) ? scale : S(1));
  if ((N - N.transpose()).cwiseAbs().maxCoeff() > tol)
    throw InvalidInput("SpatialInertia::fromMatrix: N is not symmetric");
  const S m = N.template bottomRightCorner<3, 3>().trace() / S(3);
  if ((N.template bottomRightCorner<3, 3>() - m * Mat3<S>::Identity()).cwiseAbs().maxCoeff() > tol)
    throw InvalidInput("SpatialInertia::fromMatrix: lower-right block is not m·I₃");
  if (!(m > S(0))) throw InvalidInput("SpatialInertia::fromMatrix: mass " + toString(m) + " ≤ 0");
  const Mat3<S> mC = N.template topRightCorner<3, 3>();
  if ((mC + mC.transpose()).cwiseAbs().maxCoeff() > tol)
    throw InvalidInput("SpatialInertia::fromMatrix: upper-right block is not skew (m·ad(c))");
  const Vec3<S> c = Vec3<S>(mC(2, 1), mC(0, 2), mC(1, 0)) / m;
  const Mat3<S> C = skew(c);
  const Mat3<S> I = N.template topLeftCorner<3, 3>();
  return SpatialInertia(m, c, Mat3<S>(I + m * C * C));
}

template <class S>
SE3Tangent<S> rigidBodyAcceleration(const Mat6<S>& N, const SE3Tangent<S>& s, const Vec6<S>& W) {
  Eigen::LLT<Mat6<S>> llt(N);
  if (llt.info() != Eigen::Success)
    throw InvalidInput("rigidBodyAcceleration: inertia N is not positive definite");
  const Vec6<S> rhs = W - coadjoint(s, Vec6<S>(N * s.coeffs()));
  return SE3Tangent<S>(Vec6<S>(llt.solve(rhs)));
}

#define SOMA_SPATIAL_INERTIA_EXTERN(S)                                                     \
  extern template class SpatialInertia<S>;                                                 \
  extern template SE3Tangent<S> rigidBodyAcceleration<S>(const Mat6<S>&, const SE3Tangent<S>&, \
                                                         const Vec6<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_SPATIAL_INERTIA_EXTERN)
#undef SOMA_SPATIAL_INERTIA_EXTERN

}  // namespace soma
