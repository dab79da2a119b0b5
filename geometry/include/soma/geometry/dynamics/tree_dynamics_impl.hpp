#pragma once
// Definitions for tree_dynamics.hpp (included only by its instantiations, soma_instantiate (cmake/SomaInstantiate.cmake)).
#include "soma/geometry/dynamics/tree_dynamics.hpp"

#include <Eigen/Cholesky>

namespace soma {

// GF §14.4 lines 9112–9124, GF-14.4-planar-inertia
template <class S> Eigen::Matrix<S, 3, 3> planarInertia(const S& m, const S& cx, const S& cy, const S& ic) {
  Eigen::Matrix<S, 3, 3> N;
  const S mk2 = ic + m * (cx * cx + cy * cy);
  N << mk2, -m * cy, m * cx, -m * cy, m, S(0), m * cx, S(0), m;
  return N;
}

template <class S> Mat6<S> planarBodyInertia(const S& m, const S& cx, const S& cy, const S& izz) {
  Mat3<S> Ic = Mat3<S>::Zero();
  Ic(0, 0) = izz / S(2);
  Ic(1, 1) = izz / S(2);
  Ic(2, 2) = izz;
  return SpatialInertia<S>(m, Vec3<S>(cx, cy, S(0)), Ic).matrix();
}

template <class S>
TreeDynamics<S>::TreeDynamics(TreeTopology topology, std::vector<Vec6<S>> homeScrews, std::vector<Mat6<S>> homeInertias,
                              const Vec3<S>& gravity)
    : topology_(std::move(topology)), s0_(std::move(homeScrews)), N0_(std::move(homeInertias)), g_(gravity) {
  using std::abs;
  const int n = topology_.size();
  if (int(s0_.size()) != n || int(N0_.size()) != n)
    throw InvalidInput("TreeDynamics: " + std::to_string(s0_.size()) + " screws and " + std::to_string(N0_.size()) +
                       " inertias for a tree of " + std::to_string(n) + " links");
  if (!allFinite(g_)) throw InvalidInput("TreeDynamics: gravity has a NaN or infinite entry");
  for (int i = 0; i < n; ++i) {
    const Vec6<S>& s = s0_[std::size_t(i)];
    if (!allFinite(s)) throw InvalidInput("TreeDynamics: screw of joint " + std::to_string(i) + " has a NaN entry");
    const S w2 = s.template head<3>().squaredNorm(), v2 = s.template tail<3>().squaredNorm();
    const bool unit = (abs(w2 - S(1)) <= Tolerance<S>::input()) || (w2 <= Tolerance<S>::input() && abs(v2 - S(1)) <= Tolerance<S>::input());
    if (!unit) throw InvalidInput("TreeDynamics: screw of joint " + std::to_string(i) + " is not unit (|ω| = 1 or ω = 0, |v| = 1)");
    const Mat6<S>& N = N0_[std::size_t(i)];
    if (!allFinite(N)) throw InvalidInput("TreeDynamics: inertia of link " + std::to_string(i) + " has a NaN entry");
    const S sc = N.cwiseAbs().maxCoeff();
    if ((N - N.transpose()).cwiseAbs().maxCoeff() > Tolerance<S>::input() * (sc > S(1) ? sc : S(1)))
      throw InvalidInput("TreeDynamics: inertia of link " + std::to_string(i) + " is not symmetric");
  }
}

template <class S> Vec6<S> TreeDynamics<S>::gravityScrew() const {
  Vec6<S> g = Vec6<S>::Zero();
  g.template tail<3>() = g_;
  return g;
}

template <class S> void TreeDynamics<S>::checkState(const DynVector<S>& v, const char* what) const {
  if (v.size() != dof())
    throw InvalidInput(std::string("TreeDynamics: ") + what + " has " + std::to_string(v.size()) + " entries, the tree has " +
                       std::to_string(dof()) + " joints");
  if (!allFinite(v)) throw InvalidInput(std::string("TreeDynamics: ") + what + " has a NaN or infinite entry");
}

// GF §14.1.2 lines 8766–8784 (POE along the ancestry), GF-14.1.2-tree-kinematics
template <class S> TreeConfiguration<S> TreeDynamics<S>::configuration(const DynVector<S>& theta) const {
  checkState(theta, "θ");
  const int n = dof();
  TreeConfiguration<S> c;
  c.placements.resize(static_cast<std::size_t>(n));
  c.screws.resize(static_cast<std::size_t>(n));
  c.inertias.resize(static_cast<std::size_t>(n));
  for (int i : topology_.breadthFirst()) {
    const std::size_t k = std::size_t(i);
    const int p = topology_.parent(i);
    const SE3<S> Kp = p < 0 ? SE3<S>::Identity() : c.placements[std::size_t(p)];
    c.placements[k] = Kp * SE3Tangent<S>(Vec6<S>(theta(i) * s0_[k])).exp();
    c.screws[k] = Kp.adjoint() * s0_[k];
    c.inertias[k] = coadjointTransform(c.placements[k], N0_[k]);
  }
  return c;
}

template <class S>
std::vector<Vec6<S>> TreeDynamics<S>::linkVelocities(const TreeConfiguration<S>& c, const DynVector<S>& thetaDot) const {
  checkState(thetaDot, "θ̇");
  std::vector<Vec6<S>> v(static_cast<std::size_t>(dof()));
  for (int i : topology_.breadthFirst()) {
    const int p = topology_.parent(i);
    v[std::size_t(i)] = (p < 0 ? Vec6<S>::Zero() : v[std::size_t(p)]) + thetaDot(i) * c.screws[std::size_t(i)];
  }
  return v;
}

// GF §14.1.2 line 8796, GF-14.1.2-tree-velocities-accelerations
template <class S>
std::vector<Vec6<S>> TreeDynamics<S>::linkAccelerations(const TreeConfiguration<S>& c, const DynVector<S>& thetaDot,
                                                        const DynVector<S>& thetaDDot) const {
  checkState(thetaDDot, "θ̈");
  const std::vector<Vec6<S>> v = linkVelocities(c, thetaDot);
  std::vector<Vec6<S>> a(static_cast<std::size_t>(dof()));
  for (int i : topology_.breadthFirst()) {
    const std::size_t k = std::size_t(i);
    const int p = topology_.parent(i);
    a[k] = (p < 0 ? Vec6<S>::Zero() : a[std::size_t(p)]) + thetaDDot(i) * c.screws[k] +
           thetaDot(i) * screwBracket(v[k], c.screws[k]);
  }
  return a;
}

// GF §14.1.1 line 8740 (corrected, erratum 1: Σ over i ⪯ j), GF-14.1.1-tree-joint-equations
template <class S>
DynVector<S> TreeDynamics<S>::inverseDynamicsSpatial(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                     const DynVector<S>& thetaDDot) const {
  const TreeConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> v = linkVelocities(c, thetaDot), a = linkAccelerations(c, thetaDot, thetaDDot);
  const Vec6<S> g = gravityScrew();
  const int n = dof();
  DynVector<S> tau = DynVector<S>::Zero(n);
  for (int i = 0; i < n; ++i) {
    const Vec6<S>& si = c.screws[std::size_t(i)];
    for (int j : topology_.subtree(i)) {
      const std::size_t k = std::size_t(j);
      const Mat6<S>& N = c.inertias[k];
      tau(i) += Vec6<S>(a[k] - g).dot(N * si) + v[k].dot(N * screwBracket(si, v[k]));
    }
  }
  return tau;
}

// GF §14.1.3 (box, lines 8808–8844), GF-14.1.3-tree-recursive-dynamics (corrected, errata 2, 3):
// up pass  q̇_i⁰ = θ̇_i s_i⁰ + Ad(−θ_i s_i⁰) q̇_p⁰,  q̈_i⁰ = θ̈_i s_i⁰ + θ̇_i[q̇_i⁰, s_i⁰] + Ad(−θ_i s_i⁰) q̈_p⁰,
//          Q_i⁰ = N_i⁰ q̈_i⁰ + {q̇_i⁰, N_i⁰ q̇_i⁰},  with q̈_ground = −g;
// down pass P_i⁰ = Q_i⁰ + Σ_children c Ad(−θ_c s_c⁰)ᵀ P_c⁰,  τ_i = P_i⁰ᵀ s_i⁰.
template <class S>
DynVector<S> TreeDynamics<S>::inverseDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                              const DynVector<S>& thetaDDot) const {
  checkState(theta, "θ");
  checkState(thetaDot, "θ̇");
  checkState(thetaDDot, "θ̈");
  const int n = dof();
  std::vector<Mat6<S>> Hinv(static_cast<std::size_t>(n));  // Ad(−θ_i s_i⁰)
  std::vector<Vec6<S>> v(static_cast<std::size_t>(n)), a(static_cast<std::size_t>(n)), P(static_cast<std::size_t>(n));
  const Vec6<S> ground = -gravityScrew();
  for (int i : topology_.breadthFirst()) {
    const std::size_t k = std::size_t(i);
    const int p = topology_.parent(i);
    Hinv[k] = SE3Tangent<S>(Vec6<S>(-theta(i) * s0_[k])).exp().adjoint();
    const Vec6<S> vp = p < 0 ? Vec6<S>::Zero() : v[std::size_t(p)];
    const Vec6<S> ap = p < 0 ? ground : a[std::size_t(p)];
    v[k] = thetaDot(i) * s0_[k] + Hinv[k] * vp;
    a[k] = thetaDDot(i) * s0_[k] + thetaDot(i) * screwBracket(v[k], s0_[k]) + Hinv[k] * ap;
    const Vec6<S> h = N0_[k] * v[k];
    P[k] = N0_[k] * a[k] + coadjoint(SE3Tangent<S>(v[k]), h);
  }
  DynVector<S> tau(n);
  const std::vector<int>& order = topology_.breadthFirst();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const std::size_t k = std::size_t(*it);
    for (int c : topology_.children(*it)) P[k] += Hinv[std::size_t(c)].transpose() * P[std::size_t(c)];
    tau(*it) = P[k].dot(s0_[k]);
  }
  return tau;
}

template <class S> DynMatrix<S> TreeDynamics<S>::massMatrix(const TreeConfiguration<S>& c) const {
  const int n = dof();
  std::vector<Mat6<S>> bar(static_cast<std::size_t>(n));
  const std::vector<int>& order = topology_.breadthFirst();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    Mat6<S> sum = c.inertias[std::size_t(*it)];
    for (int ch : topology_.children(*it)) sum += bar[std::size_t(ch)];
    bar[std::size_t(*it)] = sum;
  }
  DynMatrix<S> A = DynMatrix<S>::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (topology_.precedes(i, j))
        A(i, j) = c.screws[std::size_t(i)].dot(bar[std::size_t(j)] * c.screws[std::size_t(j)]);
      else if (topology_.precedes(j, i))
        A(i, j) = c.screws[std::size_t(j)].dot(bar[std::size_t(i)] * c.screws[std::size_t(i)]);
    }
  return A;
}

template <class S>
DynVector<S> TreeDynamics<S>::forwardDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                              const DynVector<S>& tau) const {
  checkState(tau, "τ");
  const DynVector<S> bias = inverseDynamics(theta, thetaDot, DynVector<S>::Zero(dof()));
  const DynMatrix<S> A = massMatrix(theta);
  Eigen::LLT<DynMatrix<S>> llt(A);
  if (llt.info() != Eigen::Success)
    throw InvalidInput("TreeDynamics::forwardDynamics: the mass matrix is not positive definite (a joint moves no mass)");
  return llt.solve(DynVector<S>(tau - bias));
}

template <class S> S TreeDynamics<S>::kineticEnergy(const DynVector<S>& theta, const DynVector<S>& thetaDot) const {
  const TreeConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> v = linkVelocities(c, thetaDot);
  S e(0);
  for (int i = 0; i < dof(); ++i) e += v[std::size_t(i)].dot(c.inertias[std::size_t(i)] * v[std::size_t(i)]);
  return e / S(2);
}

template <class S> S TreeDynamics<S>::potentialEnergy(const DynVector<S>& theta) const {
  const TreeConfiguration<S> c = configuration(theta);
  S e(0);
  for (int i = 0; i < dof(); ++i) {
    const Mat6<S>& N = c.inertias[std::size_t(i)];
    const Vec3<S> mc(N(2, 4), N(0, 5), N(1, 3));  // m ad(c) block: (mC)_{21}, (mC)_{02}, (mC)_{10}
    e -= g_.dot(mc);
  }
  return e;
}

template <class S> Vec6<S> TreeDynamics<S>::momentum(const DynVector<S>& theta, const DynVector<S>& thetaDot) const {
  const TreeConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> v = linkVelocities(c, thetaDot);
  Vec6<S> P = Vec6<S>::Zero();
  for (int i = 0; i < dof(); ++i) P += c.inertias[std::size_t(i)] * v[std::size_t(i)];
  return P;
}

// GF §14.3.2 line 9102, GF-14.3.2-shaking-wrench; §14.1.1 line 8746 (star root equation)
template <class S>
Vec6<S> TreeDynamics<S>::totalWrench(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                     const DynVector<S>& thetaDDot) const {
  const TreeConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> v = linkVelocities(c, thetaDot), a = linkAccelerations(c, thetaDot, thetaDDot);
  const Vec6<S> g = gravityScrew();
  Vec6<S> W = Vec6<S>::Zero();
  for (int i = 0; i < dof(); ++i) {
    const std::size_t k = std::size_t(i);
    const Mat6<S>& N = c.inertias[k];
    W += N * Vec6<S>(a[k] - g) + coadjoint(SE3Tangent<S>(v[k]), Vec6<S>(N * v[k]));
  }
  return W;
}

}  // namespace soma

// Explicit instantiation for one scalar (the rule: cmake/SomaInstantiate.cmake).
#define SOMA_INSTANTIATE_TREE_DYNAMICS(S)                                                        \
  template class TreeDynamics<S>;                                                                \
  template Eigen::Matrix<S, 3, 3> planarInertia<S>(const S&, const S&, const S&, const S&);     \
  template Mat6<S> planarBodyInertia<S>(const S&, const S&, const S&, const S&);
