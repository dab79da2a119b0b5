#pragma once
// GF §15.1 (lines 9529–9621): the bi-invariant geometry of SE(3) pulled back to joint space. Definitions; instantiated one scalar per TU by soma_instantiate (cmake/SomaInstantiate.cmake).
#include "soma/geometry/riemannian/joint_space_geometry.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/LU>
#include <string>

namespace soma {
namespace {
template <class S> Vec6<S> br(const Vec6<S>& a, const Vec6<S>& b) { return SE3Tangent<S>(a).ad() * b; }
}  // namespace

template <class S>
JointSpaceGeometry<S>::JointSpaceGeometry(std::vector<Vec6<S>> homeScrews, InvariantMetric<S> metric)
    : home_(std::move(homeScrews)), Q_(metric) {
  if (home_.empty()) throw InvalidInput("JointSpaceGeometry: homeScrews is empty (need at least one joint)");
  for (std::size_t i = 0; i < home_.size(); ++i)
    if (!allFinite(home_[i]))
      throw InvalidInput("JointSpaceGeometry: home screw " + std::to_string(i + 1) + " has a NaN or infinite entry");
}

template <class S> void JointSpaceGeometry<S>::checkTheta(const DgVector<S>& v, const char* what) const {
  if (v.size() != dof())
    throw InvalidInput(std::string("JointSpaceGeometry: ") + what + " has size " + std::to_string(v.size()) +
                       ", expected " + std::to_string(dof()));
  if (!allFinite(v)) throw InvalidInput(std::string("JointSpaceGeometry: ") + what + " has a NaN or infinite entry");
}

template <class S> SE3<S> JointSpaceGeometry<S>::forward(const DgVector<S>& theta) const {
  checkTheta(theta, "theta");
  SE3<S> g = SE3<S>::Identity();
  for (int i = 0; i < dof(); ++i) g = g.compose(SE3Tangent<S>(Vec6<S>(theta(i) * home_[std::size_t(i)])).exp());
  return g;
}

// GF §15.1 line 9547 (corrected, erratum E15.3): s_i(θ) = e^{θ₁ad(s₁)}···e^{θ_{i−1}ad(s_{i−1})} s_i(0)
template <class S> ScrewMatrix<S> JointSpaceGeometry<S>::screws(const DgVector<S>& theta) const {
  checkTheta(theta, "theta");
  ScrewMatrix<S> J(6, dof());
  SE3<S> g = SE3<S>::Identity();
  for (int i = 0; i < dof(); ++i) {
    J.col(i) = g.adjoint() * home_[std::size_t(i)];
    g = g.compose(SE3Tangent<S>(Vec6<S>(theta(i) * home_[std::size_t(i)])).exp());
  }
  return J;
}

// GF §15.1 line 9551: ∂s_j/∂θ_i = [s_i, s_j] (i < j)
template <class S> std::vector<ScrewMatrix<S>> JointSpaceGeometry<S>::screwDerivatives(const ScrewMatrix<S>& J) const {
  const int n = int(J.cols());
  std::vector<ScrewMatrix<S>> D(std::size_t(n), ScrewMatrix<S>::Zero(6, n));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) D[std::size_t(i)].col(j) = br<S>(J.col(i), J.col(j));
  return D;
}

template <class S> DgMatrix<S> JointSpaceGeometry<S>::pullbackMetric(const DgVector<S>& theta) const {
  const ScrewMatrix<S> J = screws(theta);
  return DgMatrix<S>(J.transpose() * Q_.matrix() * J);
}

template <class S>
std::vector<DgMatrix<S>> JointSpaceGeometry<S>::pullbackMetricDerivative(const DgVector<S>& theta) const {
  const ScrewMatrix<S> J = screws(theta);
  const auto D = screwDerivatives(J);
  const Mat6<S> Q = Q_.matrix();
  std::vector<DgMatrix<S>> dG;
  for (const auto& Di : D) {
    const DgMatrix<S> a = Di.transpose() * Q * J;
    dG.push_back(DgMatrix<S>(a + a.transpose()));
  }
  return dG;
}

template <class S> DgMatrix<S> JointSpaceGeometry<S>::coScrews(const ScrewMatrix<S>& J) const {
  if (J.cols() != 6)
    throw InvalidInput("JointSpaceGeometry::coScrews: the co-screws W_i need 6 joints, the robot has " +
                       std::to_string(J.cols()));
  const std::vector<S> sig = detail::smallSingularValues<S>(detail::SmallMat<S>(J));
  if (!(sig.front() > S(0)) || !(sig.back() > Tolerance<S>::rank() * sig.front()))
    throw InvalidInput("JointSpaceGeometry: the Jacobian J(theta) is singular (sigma_min/sigma_max = " +
                       toString(scalarCast<double>(S(sig.back() / sig.front())), 3) +
                       "); the co-screws W_i (rows of J^-1) and the Christoffel symbols do not exist there");
  return DgMatrix<S>(DgMatrix<S>(J).partialPivLu().inverse());
}

// GF §15.1 line 9581 (corrected, erratum E15.1: the case formula is symmetric in j, k)
template <class S>
std::vector<DgMatrix<S>> JointSpaceGeometry<S>::christoffelBook(const DgVector<S>& theta) const {
  const ScrewMatrix<S> J = screws(theta);
  const DgMatrix<S> W = coScrews(J);
  std::vector<DgMatrix<S>> G(6, DgMatrix<S>::Zero(6, 6));
  for (int j = 0; j < 6; ++j)
    for (int k = 0; k < 6; ++k) {
      if (j == k) continue;
      const Vec6<S> b = j < k ? br<S>(J.col(j), J.col(k)) : br<S>(J.col(k), J.col(j));
      const DgVector<S> w = W * b / S(2);
      for (int i = 0; i < 6; ++i) G[std::size_t(i)](j, k) = w(i);
    }
  return G;
}

template <class S> std::vector<DgMatrix<S>> JointSpaceGeometry<S>::christoffelLeviCivita(const DgVector<S>& theta) const {
  const int n = dof();
  const DgMatrix<S> G = pullbackMetric(theta);
  const std::vector<S> sig = detail::smallSingularValues<S>(detail::SmallMat<S>(G));
  if (!(sig.front() > S(0)) || !(sig.back() > Tolerance<S>::rank() * sig.front()))
    throw InvalidInput("JointSpaceGeometry::christoffelLeviCivita: the pull-back metric J^T Q_p J is singular (sigma_min/sigma_max = " +
                       toString(scalarCast<double>(S(sig.front() > S(0) ? S(sig.back() / sig.front()) : S(0))), 3) +
                       "): a singular Jacobian, fewer than 6 joints, or alpha = 0");
  const DgMatrix<S> Gi = G.partialPivLu().inverse();
  const auto dG = pullbackMetricDerivative(theta);
  std::vector<DgMatrix<S>> Gam(std::size_t(n), DgMatrix<S>::Zero(n, n));
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      DgVector<S> lower(n);  // Γ_{l,jk} = ½(∂_jG_lk + ∂_kG_lj − ∂_lG_jk)
      for (int l = 0; l < n; ++l)
        lower(l) = (dG[std::size_t(j)](l, k) + dG[std::size_t(k)](l, j) - dG[std::size_t(l)](j, k)) / S(2);
      const DgVector<S> up = Gi * lower;
      for (int i = 0; i < n; ++i) Gam[std::size_t(i)](j, k) = up(i);
    }
  return Gam;
}

// GF §15.1 line 9567 (corrected, erratum E15.2)
template <class S>
Vec6<S> JointSpaceGeometry<S>::velocityProductTerm(const ScrewMatrix<S>& J, const DgVector<S>& td) const {
  Vec6<S> a = Vec6<S>::Zero();
  for (int i = 0; i < J.cols(); ++i)
    for (int j = i + 1; j < J.cols(); ++j) a += td(i) * td(j) * br<S>(J.col(i), J.col(j));
  return a;
}

template <class S>
Vec6<S> JointSpaceGeometry<S>::endEffectorAcceleration(const DgVector<S>& theta, const DgVector<S>& thetaDot,
                                                     const DgVector<S>& thetaDDot) const {
  checkTheta(thetaDot, "thetaDot");
  checkTheta(thetaDDot, "thetaDDot");
  const ScrewMatrix<S> J = screws(theta);
  return Vec6<S>(J * thetaDDot + velocityProductTerm(J, thetaDot));
}

// GF §15.1 line 9563
template <class S>
Vec6<S> JointSpaceGeometry<S>::covariantDerivative(const DgVector<S>& theta, const DgVector<S>& td,
                                                 const DgVector<S>& pd, const DgVector<S>& pdd) const {
  checkTheta(td, "thetaDot");
  checkTheta(pd, "phiDot");
  checkTheta(pdd, "phiDDot");
  const ScrewMatrix<S> J = screws(theta);
  Vec6<S> r = J * pdd;
  for (int i = 0; i < dof(); ++i)
    for (int k = 0; k < dof(); ++k) {
      if (i == k) continue;
      const Vec6<S> b = br<S>(J.col(i), J.col(k)) * (td(i) * pd(k) / S(2));
      if (i < k) r += b;
      else r -= b;
    }
  return r;
}

// GF §15.1 line 9575
template <class S>
DgVector<S> JointSpaceGeometry<S>::geodesicAcceleration(const DgVector<S>& theta, const DgVector<S>& thetaDot) const {
  checkTheta(thetaDot, "thetaDot");
  const ScrewMatrix<S> J = screws(theta);
  const DgMatrix<S> W = coScrews(J);
  return DgVector<S>(-(W * velocityProductTerm(J, thetaDot)));
}

template <class S> void JointSpaceGeometry<S>::geodesicStep(DgVector<S>& th, DgVector<S>& v, const S& h) const {
  using std::isfinite;
  if (!(h > S(0)))
    throw InvalidInput("JointSpaceGeometry::geodesicStep: step h must be positive and finite");
  const DgVector<S> a1 = geodesicAcceleration(th, v);
  const DgVector<S> v2 = v + h / S(2) * a1;
  const DgVector<S> a2 = geodesicAcceleration(DgVector<S>(th + h / S(2) * v), v2);
  const DgVector<S> v3 = v + h / S(2) * a2;
  const DgVector<S> a3 = geodesicAcceleration(DgVector<S>(th + h / S(2) * v2), v3);
  const DgVector<S> v4 = v + h * a3;
  const DgVector<S> a4 = geodesicAcceleration(DgVector<S>(th + h * v3), v4);
  th += h / S(6) * (v + S(2) * v2 + S(2) * v3 + v4);
  v += h / S(6) * (a1 + S(2) * a2 + S(2) * a3 + a4);
}

// GF §15.1 line 9619 (the right-invariant structure equation, erratum E15.14)
template <class S>
std::vector<std::vector<Vec6<S>>> JointSpaceGeometry<S>::maurerCartanDifferential(const DgVector<S>& theta) const {
  const ScrewMatrix<S> J = screws(theta);
  std::vector<std::vector<Vec6<S>>> d(std::size_t(dof()), std::vector<Vec6<S>>(std::size_t(dof()), Vec6<S>::Zero()));
  for (int i = 0; i < dof(); ++i)
    for (int j = i + 1; j < dof(); ++j) d[std::size_t(i)][std::size_t(j)] = br<S>(J.col(i), J.col(j));
  return d;
}

#define SOMA_INSTANTIATE_JOINT_SPACE_GEOMETRY(S) template class JointSpaceGeometry<S>;

}  // namespace soma
