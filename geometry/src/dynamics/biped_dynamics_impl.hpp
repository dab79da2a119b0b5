// The planar biped of GF §14.5 (biped_dynamics.hpp), five scalars.
#pragma once
#include "soma/geometry/dynamics/biped_dynamics.hpp"

namespace soma {
namespace {
template <class S> using V2 = Eigen::Matrix<S, 2, 1>;

template <class S> V2<S> kneeOf(const BipedParameters<S>& p, const V2<S>& hip, const V2<S>& ankle) {
  using std::sqrt;
  const V2<S> D = ankle - hip;
  const S L2 = D.squaredNorm(), L = sqrt(L2), t = p.thighLength, s = p.shankLength;
  const S a = (t * t - s * s + L2) / (S(2) * L);
  const S h2 = t * t - a * a;
  if (!(L > S(0)) || h2 < -Tolerance<S>::input() * t * t)
    throw InvalidInput("PlanarBiped: the ankle at distance " + toString(L) + " from the hip is out of reach of the leg (" +
                       toString(t) + " + " + toString(s) + ")");
  const S h = h2 > S(0) ? S(sqrt(h2)) : S(0);
  return hip + (a / L) * D + (h / L) * V2<S>(-D(1), D(0));
}

template <class S> ConstrainedTree<S> buildBiped(const BipedParameters<S>& p, const BipedPose<S>& h) {
  using std::cos;
  using std::sin;
  const S vals[] = {p.torsoMass, p.torsoInertia, p.thighLength, p.thighMass, p.thighInertia,
                    p.shankLength, p.shankMass, p.shankInertia};
  for (const S& v : vals)
    if (!isFinite(v) || !(v > S(0))) throw InvalidInput("PlanarBiped: a length, mass or inertia is not positive");
  if (!isFinite(p.gravity) || p.gravity < S(0)) throw InvalidInput("PlanarBiped: gravity is negative or not finite");
  const V2<S> kR = kneeOf<S>(p, h.hip, h.rightAnkle), kL = kneeOf<S>(p, h.hip, h.leftAnkle);
  auto rot = [](const V2<S>& c) {
    Vec6<S> s;
    s << S(0), S(0), S(1), c(1), -c(0), S(0);
    return s;
  };
  Vec6<S> sx = Vec6<S>::Zero(), sy = Vec6<S>::Zero();
  sx(3) = S(1);
  sy(4) = S(1);
  const std::vector<Vec6<S>> screws{sx, sy, rot(h.hip), rot(h.hip), rot(kR), rot(h.hip), rot(kL)};
  const V2<S> tc = h.hip + p.torsoCom * V2<S>(-sin(h.torsoAngle), cos(h.torsoAngle));
  auto body = [](const S& m, const V2<S>& c, const S& I) { return planarBodyInertia<S>(m, c(0), c(1), I); };
  const std::vector<Mat6<S>> N{Mat6<S>::Zero(),
                               Mat6<S>::Zero(),
                               body(p.torsoMass, tc, p.torsoInertia),
                               body(p.thighMass, V2<S>((h.hip + kR) / S(2)), p.thighInertia),
                               body(p.shankMass, V2<S>((kR + h.rightAnkle) / S(2)), p.shankInertia),
                               body(p.thighMass, V2<S>((h.hip + kL) / S(2)), p.thighInertia),
                               body(p.shankMass, V2<S>((kL + h.leftAnkle) / S(2)), p.shankInertia)};
  const Vec3<S> aR(h.rightAnkle(0), h.rightAnkle(1), S(0)), aL(h.leftAnkle(0), h.leftAnkle(1), S(0));
  std::vector<LoopConstraint<S>> cons{
      LoopConstraint<S>::point(4, -1, aR, Vec3<S>::UnitX()), LoopConstraint<S>::point(4, -1, aR, Vec3<S>::UnitY()),
      LoopConstraint<S>::point(6, -1, aL, Vec3<S>::UnitX()), LoopConstraint<S>::point(6, -1, aL, Vec3<S>::UnitY())};
  return ConstrainedTree<S>(TreeDynamics<S>(TreeTopology({-1, 0, 1, 2, 3, 2, 5}), screws, N, Vec3<S>(S(0), -p.gravity, S(0))),
                            cons);
}
}  // namespace

template <class S>
PlanarBiped<S>::PlanarBiped(BipedParameters<S> p, BipedPose<S> home) : p_(p), home_(home), model_(buildBiped<S>(p, home)) {}

template <class S> Eigen::Matrix<S, 2, 1> PlanarBiped<S>::knee(const V2<S>& hip, const V2<S>& ankle) const {
  return kneeOf<S>(p_, hip, ankle);
}

template <class S> DynVector<S> PlanarBiped<S>::angles(const BipedPose<S>& q) const {
  using std::atan2;
  auto ang = [](const V2<S>& d) { return atan2(d(1), d(0)); };
  const V2<S> kR0 = knee(home_.hip, home_.rightAnkle), kL0 = knee(home_.hip, home_.leftAnkle);
  const V2<S> kR = knee(q.hip, q.rightAnkle), kL = knee(q.hip, q.leftAnkle);
  DynVector<S> th(7);
  th(0) = q.hip(0) - home_.hip(0);
  th(1) = q.hip(1) - home_.hip(1);
  th(2) = q.torsoAngle - home_.torsoAngle;
  const S tR = ang(V2<S>(kR - q.hip)) - ang(V2<S>(kR0 - home_.hip)), tL = ang(V2<S>(kL - q.hip)) - ang(V2<S>(kL0 - home_.hip));
  th(3) = tR - th(2);
  th(4) = ang(V2<S>(q.rightAnkle - kR)) - ang(V2<S>(home_.rightAnkle - kR0)) - tR;
  th(5) = tL - th(2);
  th(6) = ang(V2<S>(q.leftAnkle - kL)) - ang(V2<S>(home_.leftAnkle - kL0)) - tL;
  return th;
}

template <class S>
DynVector<S> PlanarBiped<S>::completeRates(const DynVector<S>& theta, const Eigen::Matrix<S, 3, 1>& hipRates) const {
  const DynMatrix<S> C = model_.constraintMatrix(theta);
  DynVector<S> out(7);
  out.head(3) = hipRates;
  out.tail(4) = minimumNormSolve<S>(DynMatrix<S>(C.rightCols(4)), DynVector<S>(-C.leftCols(3) * hipRates));
  return out;
}

template <class S>
DynVector<S> PlanarBiped<S>::completeAccelerations(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                   const Eigen::Matrix<S, 3, 1>& hipAcc) const {
  const DynMatrix<S> C = model_.constraintMatrix(theta);
  DynVector<S> out(7);
  out.head(3) = hipAcc;
  out.tail(4) = minimumNormSolve<S>(DynMatrix<S>(C.rightCols(4)),
                                    DynVector<S>(-model_.accelerationBias(theta, thetaDot) - C.leftCols(3) * hipAcc));
  return out;
}

template <class S> std::array<Eigen::Matrix<S, 2, 1>, 5> PlanarBiped<S>::jointCentres(const DynVector<S>& theta) const {
  const TreeConfiguration<S> c = model_.tree().configuration(theta);
  const V2<S> kR0 = knee(home_.hip, home_.rightAnkle), kL0 = knee(home_.hip, home_.leftAnkle);
  auto at = [&](int link, const V2<S>& p0) {
    const Vec3<S> p = c.placements[std::size_t(link)] * Vec3<S>(p0(0), p0(1), S(0));
    return V2<S>(p(0), p(1));
  };
  return {at(2, home_.hip), at(3, kR0), at(4, home_.rightAnkle), at(5, kL0), at(6, home_.leftAnkle)};
}

// GF §14.5 lines 9256–9284, GF-14.5-biped-vertical-foot-force (corrected, erratum 10)
template <class S> Eigen::Matrix<S, 2, 1> PlanarBiped<S>::verticalForceAlpha(const DynVector<S>& theta) const {
  using std::abs;
  const auto j = jointCentres(theta);
  const S xh = j[0](0), yh = j[0](1), xk = j[1](0), yk = j[1](1), xa = j[2](0), ya = j[2](1);
  const S scale = (p_.thighLength + p_.shankLength) * (p_.thighLength + p_.shankLength);
  const S D = (ya - yk) * (xa - xh) + (yh - ya) * (xa - xk);
  if (!(abs(D) > Tolerance<S>::input() * scale))
    throw InvalidInput("PlanarBiped::verticalForceAlpha: the right leg is straight (D = 0): the foot force is not determined");
  return V2<S>((ya - yk) / D, (yh - ya) / D);
}

template <class S>
S PlanarBiped<S>::verticalFootForceAlpha(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& thetaDDot,
                                         const DynVector<S>& tau) const {
  const V2<S> a = verticalForceAlpha(theta);
  const DynVector<S> E = model_.tree().inverseDynamics(theta, thetaDot, thetaDDot);
  return a(0) * (E(3) - tau(3)) + a(1) * (E(4) - tau(4));
}

template <class S>
DynVector<S> PlanarBiped<S>::footForces(const DynVector<S>& theta, const DynVector<S>& thetaDot, const DynVector<S>& thetaDDot,
                                        const DynVector<S>& tau) const {
  const DynVector<S> E = model_.tree().inverseDynamics(theta, thetaDot, thetaDDot);
  return minimumNormSolve<S>(DynMatrix<S>(model_.constraintMatrix(theta).transpose()), DynVector<S>(E - tau));
}

template <class S>
DynVector<S> PlanarBiped<S>::torquesForMotion(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                              const DynVector<S>& thetaDDot) const {
  DynMatrix<S> B = DynMatrix<S>::Zero(7, 4);
  for (int k = 0; k < 4; ++k) B(3 + k, k) = S(1);
  const ConstrainedForces<S> f = model_.inverseDynamicsMultipliers(theta, thetaDot, thetaDDot, B);
  DynVector<S> tau = DynVector<S>::Zero(7);
  tau.tail(4) = f.actuators;
  return tau;
}

#define SOMA_INSTANTIATE_BIPED_DYNAMICS(S) template class PlanarBiped<S>;

}  // namespace soma
