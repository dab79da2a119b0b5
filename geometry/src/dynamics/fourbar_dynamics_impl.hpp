// The planar 4-bar of GF §14.4 (fourbar_dynamics.hpp), five scalars.
#pragma once
#include "soma/geometry/dynamics/fourbar_dynamics.hpp"

#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/wrap_angle.hpp"

namespace soma {
namespace {
template <class S> PVec<S> solve3(const PMat<S>& A, const PVec<S>& b) {
  Eigen::Matrix<S, 3, 3> a = A;
  Eigen::Matrix<S, 3, 1> x = b;
  detail::smallSolveInPlace<S, 3>(a, x);
  return x;
}
}  // namespace

template <class S>
FourBarDynamics<S>::FourBarDynamics(S d1, S d2, S d3, S d4, std::array<PlanarLink<S>, 3> links, int branch)
    : d_{d1, d2, d3, d4}, links_(links), branch_(branch >= 0 ? 1 : -1) {
  for (int i = 0; i < 4; ++i)
    if (!isFinite(d_[std::size_t(i)]) || !(d_[std::size_t(i)] > S(0)))
      throw InvalidInput("FourBarDynamics: length d" + std::to_string(i + 1) + " = " + toString(d_[std::size_t(i)]) + " is not positive");
  for (int i = 0; i < 3; ++i) {
    const PlanarLink<S>& l = links_[std::size_t(i)];
    if (!isFinite(l.mass) || !(l.mass > S(0)) || !isFinite(l.inertia) || !(l.inertia > S(0)) || !isFinite(l.along) || !isFinite(l.normal))
      throw InvalidInput("FourBarDynamics: link " + std::to_string(i + 1) + " needs a positive mass and inertia and a finite centre");
  }
}

template <class S> FourBarPosture<S> FourBarDynamics<S>::posture(const S& theta1) const {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (!isFinite(theta1)) throw InvalidInput("FourBarDynamics::posture: θ₁ is not finite");
  FourBarPosture<S> p;
  using P2 = Eigen::Matrix<S, 2, 1>;
  p.joints[0] = P2(S(0), S(0));
  p.joints[1] = P2(d_[0] * cos(theta1), d_[0] * sin(theta1));
  p.joints[3] = P2(d_[3], S(0));
  const P2 D = p.joints[3] - p.joints[1];
  const S L2 = D.squaredNorm(), L = sqrt(L2);
  const S a = (d_[1] * d_[1] - d_[2] * d_[2] + L2) / (S(2) * L);
  S h2 = d_[1] * d_[1] - a * a;
  const S tol = Tolerance<S>::input() * d_[1] * d_[1];
  if (h2 < -tol)
    throw InvalidInput("FourBarDynamics::posture: the loop cannot close at θ₁ = " + toString(theta1) + " (|P₂P₄| = " + toString(L) +
                       " outside [|d₂ − d₃|, d₂ + d₃])");
  if (h2 < S(0)) h2 = S(0);
  const S h = sqrt(h2);
  p.joints[2] = p.joints[1] + (a / L) * D + (S(branch_) * h / L) * P2(-D(1), D(0));
  const P2 c = p.joints[2] - p.joints[1], r = p.joints[2] - p.joints[3];
  const S phi2 = atan2(c(1), c(0));
  p.rocker = atan2(r(1), r(0));
  p.theta1 = theta1;
  p.theta2 = wrapAngle<S>(phi2 - theta1);
  p.theta3 = wrapAngle<S>(p.rocker - phi2);
  p.theta4 = wrapAngle<S>(-p.rocker);
  return p;
}

template <class S> std::array<PVec<S>, 4> FourBarDynamics<S>::screws(const FourBarPosture<S>& p) const {
  std::array<PVec<S>, 4> s;
  for (std::size_t i = 0; i < 4; ++i) s[i] = planarJointScrew<S>(p.joints[i](0), p.joints[i](1));
  return s;
}

// GF §14.4 lines 9171–9181, GF-14.4-four-bar-null-vector (corrected, erratum 8)
template <class S> Eigen::Matrix<S, 4, 1> FourBarDynamics<S>::alpha(const FourBarPosture<S>& p) const {
  using std::sin;
  const S d1 = d_[0], d2 = d_[1], d4 = d_[3], t1 = p.theta1, t2 = p.theta2;
  Eigen::Matrix<S, 4, 1> a;
  a(0) = d1 * d2 * sin(t2) - d2 * d4 * sin(t1 + t2);
  a(1) = d1 * d4 * sin(t1) + d2 * d4 * sin(t1 + t2);
  a(2) = -d1 * d4 * sin(t1);
  a(3) = -d1 * d2 * sin(t2);
  return a;
}

template <class S> S FourBarDynamics<S>::singularityMeasure(const FourBarPosture<S>& p) const {
  using std::abs;
  return abs(alpha(p)(0)) / (d_[0] * d_[1] * d_[3]);
}

template <class S> FourBarMotion<S> FourBarDynamics<S>::motion(const S& theta1, const S& theta1Dot, const S& theta1DDot) const {
  using std::cos;
  using std::sin;
  if (!isFinite(theta1Dot) || !isFinite(theta1DDot)) throw InvalidInput("FourBarDynamics::motion: θ̇₁ or θ̈₁ is not finite");
  FourBarMotion<S> m;
  m.posture = posture(theta1);
  const FourBarPosture<S>& p = m.posture;
  if (!(singularityMeasure(p) > Tolerance<S>::input()))
    throw InvalidInput("FourBarDynamics::motion: singular posture at θ₁ = " + toString(theta1) +
                       " (α₁ = 0: coupler and rocker aligned, the crank cannot drive the loop)");
  const std::array<PVec<S>, 4> s = screws(p);
  const Eigen::Matrix<S, 4, 1> al = alpha(p);
  m.rate = theta1Dot * al / al(0);
  // differentiated loop: Σ θ̈_i s_i + Σ θ̇_i [q_i, s_i] = 0, q_i = Σ_{j≤i} θ̇_j s_j
  PVec<S> chain = PVec<S>::Zero(), bias = PVec<S>::Zero();
  for (std::size_t i = 0; i < 4; ++i) {
    chain += m.rate(Eigen::Index(i)) * s[i];
    bias += m.rate(Eigen::Index(i)) * planarBracket<S>(chain, s[i]);
  }
  PMat<S> A;
  A << s[1], s[2], s[3];
  const PVec<S> x = solve3<S>(A, PVec<S>(-theta1DDot * s[0] - bias));
  m.acc << theta1DDot, x(0), x(1), x(2);
  m.twist[0] = theta1Dot * s[0];
  m.twist[1] = theta1Dot * s[0] + m.rate(1) * s[1];
  m.twist[2] = -m.rate(3) * s[3];  // erratum 9: q̇₃ = −θ̇₄ s₄
  m.twistDot[0] = theta1DDot * s[0];
  m.twistDot[1] = theta1DDot * s[0] + m.acc(1) * s[1] + m.rate(1) * planarBracket<S>(m.twist[1], s[1]);
  m.twistDot[2] = -m.acc(3) * s[3];
  const S ang[3] = {p.theta1, p.theta1 + p.theta2, p.rocker};
  for (std::size_t i = 0; i < 3; ++i) {
    const PlanarLink<S>& l = links_[i];
    const Eigen::Matrix<S, 2, 1> o = p.joints[i == 2 ? 3 : i];
    const S c = cos(ang[i]), sn = sin(ang[i]);
    const S cx = o(0) + c * l.along - sn * l.normal, cy = o(1) + sn * l.along + c * l.normal;
    m.inertia[i] = planarInertia<S>(l.mass, cx, cy, l.inertia);
  }
  return m;
}

// GF §14.4 line 9195, GF-14.4-four-bar-eom (corrected α, erratum 8)
template <class S> S FourBarDynamics<S>::torqueAlpha(const S& theta1, const S& theta1Dot, const S& theta1DDot) const {
  const FourBarMotion<S> m = motion(theta1, theta1Dot, theta1DDot);
  const std::array<PVec<S>, 4> s = screws(m.posture);
  const Eigen::Matrix<S, 4, 1> a = alpha(m.posture);
  const S lhs = m.twistDot[0].dot(m.inertia[0] * (a(0) * s[0])) +
                m.twistDot[1].dot(m.inertia[1] * PVec<S>(a(0) * s[0] + a(1) * s[1])) -
                m.twistDot[2].dot(m.inertia[2] * (a(3) * s[3]));
  return lhs / a(0);
}

template <class S> S FourBarDynamics<S>::kineticEnergy(const S& theta1, const S& theta1Dot) const {
  const FourBarMotion<S> m = motion(theta1, theta1Dot, S(0));
  S e(0);
  for (std::size_t i = 0; i < 3; ++i) e += m.twist[i].dot(m.inertia[i] * m.twist[i]);
  return e / S(2);
}

// GF §14.4 lines 9199–9203, GF-14.4-four-bar-shaking-moment (corrected sign of the θ̈₄ term, erratum 9)
template <class S>
S FourBarDynamics<S>::shakingMomentLhs(const S& theta1, const S& theta1Dot, const S& theta1DDot) const {
  const FourBarMotion<S> m = motion(theta1, theta1Dot, theta1DDot);
  const std::array<PVec<S>, 4> s = screws(m.posture);
  const PMat<S>&N1 = m.inertia[0], &N2 = m.inertia[1], &N3 = m.inertia[2];
  const S t1d = m.rate(0), t2d = m.rate(1), t4d = m.rate(3), t1dd = m.acc(0), t2dd = m.acc(1), t4dd = m.acc(3);
  const PVec<S> b12 = planarBracket<S>(s[0], s[1]), b14 = planarBracket<S>(s[0], s[3]);
  return t1dd * s[0].dot(N1 * s[0]) + t1dd * s[0].dot(N2 * s[0]) + t2dd * s[0].dot(N2 * s[1]) - t4dd * s[0].dot(N3 * s[3]) +
         S(2) * t1d * t2d * s[0].dot(N2 * b12) + t2d * t2d * s[1].dot(N2 * b12) + t4d * t4d * s[3].dot(N3 * b14);
}

template <class S> S FourBarDynamics<S>::crankAcceleration(const S& theta1, const S& theta1Dot, const S& tau) const {
  const S t0 = torqueAlpha(theta1, theta1Dot, S(0)), t1 = torqueAlpha(theta1, theta1Dot, S(1));
  return (tau - t0) / (t1 - t0);
}

template <class S> std::array<S, 2> FourBarDynamics<S>::rk4Step(const std::array<S, 2>& y, const S& h, const S& tau) const {
  const S half = h / S(2);
  const S a1 = crankAcceleration(y[0], y[1], tau);
  const S a2 = crankAcceleration(y[0] + half * y[1], y[1] + half * a1, tau);
  const S a3 = crankAcceleration(y[0] + half * (y[1] + half * a1), y[1] + half * a2, tau);
  const S a4 = crankAcceleration(y[0] + h * (y[1] + half * a2), y[1] + h * a3, tau);
  const S v2 = y[1] + half * a1, v3 = y[1] + half * a2, v4 = y[1] + h * a3;
  return {y[0] + h / S(6) * (y[1] + S(2) * v2 + S(2) * v3 + v4), y[1] + h / S(6) * (a1 + S(2) * a2 + S(2) * a3 + a4)};
}

template <class S> ConstrainedTree<S> FourBarDynamics<S>::constrainedTree(const S& homeTheta1) const {
  using std::cos;
  using std::sin;
  const FourBarPosture<S> p = posture(homeTheta1);
  const S ang[3] = {p.theta1, p.theta1 + p.theta2, p.rocker};
  const std::size_t origin[3] = {0, 1, 3};
  std::vector<Vec6<S>> screws;
  std::vector<Mat6<S>> inertias;
  for (std::size_t i = 0; i < 3; ++i) {
    const Eigen::Matrix<S, 2, 1> o = p.joints[origin[i]];
    Vec6<S> sc;
    sc << S(0), S(0), S(1), o(1), -o(0), S(0);
    screws.push_back(sc);
    const PlanarLink<S>& l = links_[i];
    const S c = cos(ang[i]), sn = sin(ang[i]);
    inertias.push_back(planarBodyInertia<S>(l.mass, o(0) + c * l.along - sn * l.normal, o(1) + sn * l.along + c * l.normal, l.inertia));
  }
  const Vec3<S> P3(p.joints[2](0), p.joints[2](1), S(0));
  std::vector<LoopConstraint<S>> cons{LoopConstraint<S>::point(1, 2, P3, Vec3<S>::UnitX()),
                                      LoopConstraint<S>::point(1, 2, P3, Vec3<S>::UnitY())};
  return ConstrainedTree<S>(TreeDynamics<S>(TreeTopology({-1, 0, -1}), screws, inertias, Vec3<S>::Zero()), cons);
}

template <class S> std::array<DynVector<S>, 3> FourBarDynamics<S>::treeState(const S& homeTheta1, const FourBarMotion<S>& m) const {
  const FourBarPosture<S> h = posture(homeTheta1);
  const FourBarPosture<S>& p = m.posture;
  DynVector<S> th(3), thd(3), thdd(3);
  th << wrapAngle<S>(p.theta1 - h.theta1), wrapAngle<S>(p.theta2 - h.theta2), wrapAngle<S>(p.rocker - h.rocker);
  thd << m.rate(0), m.rate(1), -m.rate(3);
  thdd << m.acc(0), m.acc(1), -m.acc(3);
  return {th, thd, thdd};
}

#define SOMA_INSTANTIATE_FOURBAR_DYNAMICS(S) template class FourBarDynamics<S>;

}  // namespace soma
