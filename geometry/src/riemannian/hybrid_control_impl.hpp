#pragma once
// GF §15.4: coordinate-free hybrid force/position control. Definitions; instantiated one scalar per TU by soma_instantiate (cmake/SomaInstantiate.cmake).
#include "soma/geometry/riemannian/hybrid_control.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace soma {
namespace {
template <class S> Vec6<S> br(const Vec6<S>& a, const Vec6<S>& b) { return SE3Tangent<S>(a).ad() * b; }
template <class S> void checkFreedoms(const DgMatrix<S>& Z, const char* fn) {
  if (Z.rows() != 6 || Z.cols() < 1 || Z.cols() > 5)
    throw InvalidInput(std::string(fn) + ": freedoms must be 6 x n with 0 < n < 6");
  if (!allFinite(Z)) throw InvalidInput(std::string(fn) + ": freedoms has a NaN or infinite entry");
}
}  // namespace

// GF §15.4.3 lines 9868–9936
template <class S> HybridProjectors<S> dualBasisProjectors(const DgMatrix<S>& Z, const DgMatrix<S>& Sp) {
  checkFreedoms(Z, "dualBasisProjectors");
  const Eigen::Index n = Z.cols();
  if (Sp.rows() != 6 || Sp.cols() != 6 - n || !allFinite(Sp))
    throw InvalidInput("dualBasisProjectors: complement must be a finite 6 x (6 - n) matrix");
  DgMatrix<S> M(6, 6);
  M << Z, Sp;
  const std::vector<S> sig = detail::smallSingularValues<S>(M);
  if (!(sig.back() > Tolerance<S>::rank() * S(64) * sig.front()))
    throw InvalidInput("dualBasisProjectors: [freedoms complement] is singular: the complement is not independent of the freedoms");
  const DgMatrix<S> D = M.partialPivLu().inverse().transpose();  // columns W₁..W₆, W_iᵀz_j = δ_ij
  return {Z, DgMatrix<S>(D.leftCols(n).transpose()), DgMatrix<S>(D.rightCols(6 - n)), DgMatrix<S>(Sp.transpose())};
}

// GF §15.4.3 lines 9946–9954
template <class S> HybridProjectors<S> transformedProjectors(const HybridProjectors<S>& p, const Mat6<S>& H) {
  const Mat6<S> Hi = H.inverse();
  return {DgMatrix<S>(Hi * p.A), DgMatrix<S>(p.B * H), DgMatrix<S>(H.transpose() * p.X),
          DgMatrix<S>(p.Y * Hi.transpose())};
}

// GF §15.4.4 lines 10004–10018: N₆-Gram–Schmidt (twice) on the freedoms, then on the unit vectors
template <class S> HybridProjectors<S> n6Projectors(const DgMatrix<S>& Z, const Mat6<S>& N6) {
  using std::sqrt;
  checkFreedoms(Z, "n6Projectors");
  if (!allFinite(N6) || !((N6 - N6.transpose()).cwiseAbs().maxCoeff() <= Tolerance<S>::input() * N6.cwiseAbs().maxCoeff()))
    throw InvalidInput("n6Projectors: N6 must be a finite symmetric matrix");
  const Eigen::LLT<Mat6<S>> llt(N6);
  if (llt.info() != Eigen::Success) throw InvalidInput("n6Projectors: N6 is not positive definite");
  const Eigen::Index n = Z.cols();
  const S scale = N6.cwiseAbs().maxCoeff();
  DgMatrix<S> basis(6, 6);
  Eigen::Index k = 0;
  auto tryAdd = [&](Vec6<S> x) {
    const S n0 = x.dot(N6 * x);
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index j = 0; j < k; ++j) x -= basis.col(j) * (basis.col(j).dot(N6 * x));
    const S nx = x.dot(N6 * x);
    if (!(nx > S(64) * Tolerance<S>::rank() * n0) || !(nx > S(0))) return false;
    basis.col(k++) = x / sqrt(nx);
    return true;
  };
  (void)scale;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!tryAdd(Vec6<S>(Z.col(i))))
      throw InvalidInput("n6Projectors: the freedom screws are linearly dependent");
  for (int e = 0; e < 6 && k < 6; ++e) tryAdd(Vec6<S>(Vec6<S>::Unit(e)));
  HybridProjectors<S> p;
  p.A = basis.leftCols(n);
  p.B = p.A.transpose() * N6;
  p.Y = basis.rightCols(6 - n).transpose();
  p.X = N6 * p.Y.transpose();
  return p;
}

template <class S> Vec6<S> coadjointBrace(const Vec6<S>& V, const Vec6<S>& P) {
  return Vec6<S>(-(SE3Tangent<S>(V).ad().transpose() * P));
}
// GF §15.4.4 line 9990
template <class S> Vec6<S> rigidBodyWrench(const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot) {
  return Vec6<S>(N6 * Vdot + coadjointBrace<S>(V, Vec6<S>(N6 * V)));
}
// GF §15.4.4 line 10022
template <class S>
Vec6<S> secondFundamentalWrench(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot) {
  return Vec6<S>(p.X * (p.Y * rigidBodyWrench(N6, V, Vdot)));  // XXᵀN₆⁻¹ = N₆YᵀY, applied as X(Y w)
}
// GF §15.4.4 lines 10026, 10034 (corrected, erratum E15.9)
template <class S>
DgVector<S> constraintMultipliers(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot) {
  const Eigen::Index m = p.Y.rows();
  DgVector<S> lam(m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const Vec6<S> zj = p.Y.row(j).transpose();
    lam(j) = zj.dot(N6 * Vdot) + V.dot(N6 * br<S>(zj, V));
  }
  return lam;
}

template <class S>
Vec6<S> hybridVelocityError(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& qdDesired, const Vec6<S>& qd) {
  return Vec6<S>(p.A * (p.A.transpose() * (N6 * (qdDesired - qd))));
}
template <class S>
Vec6<S> hybridAccelerationError(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& qddDesired,
                                const Vec6<S>& qdd, const Vec6<S>& qe) {
  return Vec6<S>(p.A * (p.A.transpose() * (N6 * (qddDesired - qdd) + coadjointBrace<S>(qe, Vec6<S>(N6 * qe)))));
}
// GF §15.4.4 line 10065 (corrected: j = n+1..6)
template <class S> DgVector<S> forceControlTorque(const HybridProjectors<S>& p, const Vec6<S>& Wd, const DgMatrix<S>& J) {
  if (J.rows() != 6 || !allFinite(J)) throw InvalidInput("forceControlTorque: J must be a finite 6 x m matrix of joint screws");
  // Σ_j (W_dᵀz_j) W_j = X (Y W_d); τ^f_i = s_iᵀ X Y W_d
  return DgVector<S>(J.transpose() * (p.X * (p.Y * Wd)));
}

#define SOMA_INSTANTIATE_HYBRID_CONTROL(S)                                                                             \
  template HybridProjectors<S> dualBasisProjectors<S>(const DgMatrix<S>&, const DgMatrix<S>&);                 \
  template HybridProjectors<S> transformedProjectors<S>(const HybridProjectors<S>&, const Mat6<S>&);            \
  template HybridProjectors<S> n6Projectors<S>(const DgMatrix<S>&, const Mat6<S>&);                           \
  template Vec6<S> coadjointBrace<S>(const Vec6<S>&, const Vec6<S>&);                                         \
  template Vec6<S> rigidBodyWrench<S>(const Mat6<S>&, const Vec6<S>&, const Vec6<S>&);                        \
  template Vec6<S> secondFundamentalWrench<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&,      \
                                              const Vec6<S>&);                                                 \
  template DgVector<S> constraintMultipliers<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&,     \
                                                const Vec6<S>&);                                               \
  template Vec6<S> hybridVelocityError<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&,          \
                                          const Vec6<S>&);                                                     \
  template Vec6<S> hybridAccelerationError<S>(const HybridProjectors<S>&, const Mat6<S>&, const Vec6<S>&,      \
                                              const Vec6<S>&, const Vec6<S>&);                                 \
  template DgVector<S> forceControlTorque<S>(const HybridProjectors<S>&, const Vec6<S>&, const DgMatrix<S>&);

}  // namespace soma
