// Inverse dynamics of the Stewart platform, GF §14.6 (stewart_dynamics.hpp), five scalars.
#pragma once
#include "soma/geometry/dynamics/stewart_dynamics.hpp"

#include "soma/algebra/small_linalg.hpp"

namespace soma {
namespace {
template <class S> Vec6<S> lineScrew(const Vec3<S>& w, const Vec3<S>& r) {
  Vec6<S> s;
  s << w, r.cross(w);
  return s;
}
template <class S> Vec6<S> slide(const Vec3<S>& d) {
  Vec6<S> s;
  s << Vec3<S>::Zero(), d;
  return s;
}
template <class S> Mat6<S> rodInertia(const S& m, const Vec3<S>& c, const Vec3<S>& d, const S& It) {
  if (!(m > S(0))) return Mat6<S>::Zero();
  const Mat3<S> I = It * (Mat3<S>::Identity() - d * d.transpose()) + (It / S(10)) * d * d.transpose();
  return SpatialInertia<S>(m, c, I).matrix();
}
/// Rows `rows`, columns `cols` of M.
template <class S> DynMatrix<S> block(const DynMatrix<S>& M, int r0, int nr, int c0, int nc) { return M.block(r0, c0, nr, nc); }
}  // namespace

template <class S>
StewartDynamics<S>::StewartDynamics(std::array<Vec3<S>, 6> base, std::array<Vec3<S>, 6> platform, SpatialInertia<S> platformInertia,
                                    StewartLegInertia<S> leg, S gravity)
    : base_(base), platform_(platform), platformInertia_(std::move(platformInertia)), leg_(leg), g_(gravity) {
  for (int i = 0; i < 6; ++i)
    if (!allFinite(base_[std::size_t(i)]) || !allFinite(platform_[std::size_t(i)]))
      throw InvalidInput("StewartDynamics: joint point of leg " + std::to_string(i + 1) + " has a NaN entry");
  if (!isFinite(g_) || g_ < S(0)) throw InvalidInput("StewartDynamics: gravity is negative or not finite");
  if (leg_.upperMass < S(0) || leg_.lowerMass < S(0)) throw InvalidInput("StewartDynamics: negative leg mass");
}

template <class S> std::array<Vec6<S>, 6> StewartDynamics<S>::legLines(const SE3<S>& pose) const {
  std::array<Vec6<S>, 6> out;
  for (std::size_t i = 0; i < 6; ++i) {
    const Vec3<S> U = pose * platform_[i], d = (U - base_[i]).normalized();
    out[i] << U.cross(d), d;
  }
  return out;
}

// GF §14.6 lines 9288–9335: the star rooted at the platform, legs U (2 dof), prismatic L
template <class S> ConstrainedTree<S> StewartDynamics<S>::model(const SE3<S>& pose) const {
  using std::abs;
  const Vec3<S> p = pose.translation();
  std::vector<int> parent{-1, 0, 1, 2, 3, 4};
  std::vector<Vec6<S>> s{slide<S>(Vec3<S>::UnitX()), slide<S>(Vec3<S>::UnitY()), slide<S>(Vec3<S>::UnitZ()),
                         lineScrew<S>(Vec3<S>::UnitX(), p), lineScrew<S>(Vec3<S>::UnitY(), p), lineScrew<S>(Vec3<S>::UnitZ(), p)};
  std::vector<Mat6<S>> N(5, Mat6<S>::Zero());
  N.push_back(platformInertia_.transformed(pose).matrix());
  std::vector<LoopConstraint<S>> cons;
  for (int i = 0; i < 6; ++i) {
    const Vec3<S> U = pose * platform_[std::size_t(i)], L = base_[std::size_t(i)];
    const Vec3<S> D = U - L;
    if (!(D.squaredNorm() > Tolerance<S>::input())) throw InvalidInput("StewartDynamics: leg " + std::to_string(i + 1) + " has zero length");
    const Vec3<S> d = D.normalized();
    int kmin = 0;
    for (int k = 1; k < 3; ++k)
      if (abs(d(k)) < abs(d(kmin))) kmin = k;
    const Vec3<S> a = d.cross(Vec3<S>::Unit(kmin)).normalized(), b = d.cross(a);
    const int base = 6 + 3 * i;
    parent.push_back(5);
    parent.push_back(base);
    parent.push_back(base + 1);
    s.push_back(lineScrew<S>(a, U));
    s.push_back(lineScrew<S>(b, U));
    s.push_back(slide<S>(d));  // erratum 13: s_L = (0, (U − L)/M)
    N.push_back(Mat6<S>::Zero());
    N.push_back(rodInertia<S>(leg_.upperMass, Vec3<S>(U - leg_.upperCom * d), d, leg_.upperInertia));
    N.push_back(rodInertia<S>(leg_.lowerMass, Vec3<S>(L + leg_.lowerCom * d), d, leg_.lowerInertia));
    for (int k = 0; k < 3; ++k) cons.push_back(LoopConstraint<S>::point(base + 2, -1, L, Vec3<S>::Unit(k)));
  }
  return ConstrainedTree<S>(TreeDynamics<S>(TreeTopology(parent), s, N, Vec3<S>(S(0), S(0), -g_)), cons);
}

template <class S>
Eigen::Matrix<S, 6, 1> StewartDynamics<S>::forcesAt(const ConstrainedTree<S>& m, const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                    const Vec6<S>& platformAcc, DynVector<S>* thetaDDotOut) const {
  const TreeConfiguration<S> c = m.tree().configuration(theta);
  DynMatrix<S> Sroot(6, 6);
  for (int k = 0; k < 6; ++k) Sroot.col(k) = c.screws[std::size_t(k)];
  const DynMatrix<S> C = m.constraintMatrix(c);
  // the platform part of θ̈ from q̈_P = Σ θ̈_k s_k + bias₅, then the legs from C θ̈ = −γ
  DynVector<S> dd = DynVector<S>::Zero(24);
  const Vec6<S> bias5 = m.tree().linkAccelerations(c, thetaDot, dd)[5];
  dd.head(6) = minimumNormSolve<S>(Sroot, DynVector<S>(platformAcc - bias5));
  const DynVector<S> gam = m.accelerationBias(theta, thetaDot);
  int rank = 0;
  dd.tail(18) = minimumNormSolve<S>(block<S>(C, 0, 18, 6, 18), DynVector<S>(-gam - block<S>(C, 0, 18, 0, 6) * dd.head(6)), &rank);
  if (rank < 18) throw InvalidInput("StewartDynamics: a leg's 3 × 3 constraint system is singular (leg joint axes degenerate)");
  DynMatrix<S> B = DynMatrix<S>::Zero(24, 6);
  for (int i = 0; i < 6; ++i) B(8 + 3 * i, i) = S(1);
  const ConstrainedForces<S> f = m.inverseDynamicsMultipliers(theta, thetaDot, dd, B);
  if (thetaDDotOut) *thetaDDotOut = dd;
  return f.actuators;
}

// GF §14.6 lines 9337–9410, GF-14.6-stewart-alpha-system, GF-14.6-stewart-inverse-dynamics-algorithm
template <class S>
StewartInverseDynamics<S> StewartDynamics<S>::inverseDynamics(const SE3<S>& pose, const Vec6<S>& qd, const Vec6<S>& qdd) const {
  const ConstrainedTree<S> m = model(pose);
  StewartInverseDynamics<S> out;
  out.theta = DynVector<S>::Zero(24);
  const TreeConfiguration<S> c = m.tree().configuration(out.theta);
  DynMatrix<S> Sroot(6, 6);
  for (int k = 0; k < 6; ++k) Sroot.col(k) = c.screws[std::size_t(k)];
  const DynMatrix<S> C = m.constraintMatrix(c);
  // step 1: α's — for each platform unit twist e_k one 3 × 3 system per leg (option 2)
  DynMatrix<S> V(24, 6);
  for (int k = 0; k < 6; ++k) {
    V.col(k).head(6) = minimumNormSolve<S>(Sroot, DynVector<S>(DynVector<S>::Unit(6, k)));
    for (int i = 0; i < 6; ++i) {
      int rank = 0;
      V.col(k).segment(6 + 3 * i, 3) = minimumNormSolve<S>(block<S>(C, 3 * i, 3, 6 + 3 * i, 3),
                                                           DynVector<S>(-block<S>(C, 3 * i, 3, 0, 6) * V.col(k).head(6)), &rank);
      if (rank < 3) throw InvalidInput("StewartDynamics::inverseDynamics: leg " + std::to_string(i + 1) + " has a singular 3 × 3 system");
    }
  }
  // joint rates θ̇ = Σ_k q̇_P,k v_k (GF line 9363) and the accelerations (differentiated constraints)
  out.thetaDot = V * qd;
  out.forcesMultipliers = forcesAt(m, out.theta, out.thetaDot, qdd, &out.thetaDDot);
  // steps 2–5: recursive left-hand sides, combined with the α's, solved for F
  const DynVector<S> tid = m.tree().inverseDynamics(out.theta, out.thetaDot, out.thetaDDot);
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 6; ++i) out.alphaMatrix(k, i) = V(8 + 3 * i, k);
  int rank = 0;
  out.forcesAlpha = minimumNormSolve<S>(DynMatrix<S>(out.alphaMatrix), DynVector<S>(V.transpose() * tid), &rank);
  if (rank < 6) throw InvalidInput("StewartDynamics::inverseDynamics: the 6 × 6 α matrix is singular (a singular posture of the platform)");
  DynMatrix<S> B = DynMatrix<S>::Zero(24, 6);
  for (int i = 0; i < 6; ++i) B(8 + 3 * i, i) = S(1);
  const ConstrainedForces<S> f = m.inverseDynamicsMultipliers(out.theta, out.thetaDot, out.thetaDDot, B);
  out.lambda = f.lambda;
  out.residual = f.residual;
  const Mat6<S> NP = platformInertia_.transformed(pose).matrix();
  Vec6<S> g = Vec6<S>::Zero();
  g(5) = -g_;
  out.platformWrench = NP * Vec6<S>(qdd - g) + coadjoint(SE3Tangent<S>(qd), Vec6<S>(NP * qd));
  return out;
}

#define SOMA_INSTANTIATE_STEWART_DYNAMICS(S) template class StewartDynamics<S>;

}  // namespace soma
