#pragma once
// GF §15.3: geodesic, velocity-tracking and accelerating control laws, and their closed loop. Definitions; instantiated one scalar per TU by soma_instantiate (cmake/SomaInstantiate.cmake).
#include "soma/geometry/riemannian/geodesic_control.hpp"

#include "soma/algebra/errors.hpp"

namespace soma {

template <class S> JointSpaceGeometry<S> jointSpaceGeometryOf(const SerialDynamics<S>& robot, InvariantMetric<S> Q) {
  std::vector<Vec6<S>> s;
  for (const auto& x : robot.homeScrews()) s.push_back(x.coeffs());
  return JointSpaceGeometry<S>(s, Q);
}

// GF §15.3 lines 9716, 9788, 9800, 9816 (corrected, erratum E15.5)
template <class S>
DgVector<S> geodesicControlTorque(const SerialDynamics<S>& robot, const JointSpaceGeometry<S>& geo,
                                  const GeodesicController<S>& c, const DgVector<S>& theta,
                                  const DgVector<S>& thetaDot, const S& t) {
  const int n = robot.dof();
  if (geo.dof() != n) throw InvalidInput("geodesicControlTorque: geometry and robot have different joint counts");
  if (c.friction.size() != 0 && c.friction.size() != n)
    throw InvalidInput("geodesicControlTorque: friction must be empty or have one coefficient per joint");
  const ScrewMatrix<S> J = geo.screws(theta);
  const DgMatrix<S> W = geo.coScrews(J);  // InvalidInput at a singular J
  const Vec6<S> q6 = J * thetaDot;
  Vec6<S> a = Vec6<S>::Zero();  // the commanded q̈₆ beyond the geodesic part
  switch (c.law) {
    case GeodesicLaw::Geodesic: break;
    case GeodesicLaw::VelocityTracking: a = c.lambda * (c.sd - q6); break;
    case GeodesicLaw::Accelerating: a = c.gamma * (S(1) + c.lambda * t) * c.sd - c.lambda * q6; break;
  }
  const DgVector<S> acc = W * (a - geo.velocityProductTerm(J, thetaDot));
  DgVector<S> tau = robot.inverseDynamics(theta, thetaDot, acc);
  if (c.friction.size() == n) tau += c.friction.cwiseProduct(thetaDot);
  return tau;
}

template <class S>
std::vector<ClosedLoopSample<S>> simulateClosedLoop(const SerialDynamics<S>& robot, const TorqueLaw<S>& law,
                                                    const DgVector<S>& mu, const DgVector<S>& theta0,
                                                    const DgVector<S>& thetaDot0, const S& h, int steps, int every) {
  const int n = robot.dof();
  if (!(h > S(0)) || steps < 0 || every < 1)
    throw InvalidInput("simulateClosedLoop: need h > 0, steps >= 0, every >= 1");
  if ((mu.size() != 0 && mu.size() != n) || theta0.size() != n || thetaDot0.size() != n)
    throw InvalidInput("simulateClosedLoop: plantFriction, theta0, thetaDot0 must have one entry per joint");
  const JointSpaceGeometry<S> geo = jointSpaceGeometryOf(robot);
  auto accel = [&](const DgVector<S>& th, const DgVector<S>& v, const S& t) {
    DgVector<S> tau = law(th, v, t);
    if (mu.size() == n) tau -= mu.cwiseProduct(v);
    return DgVector<S>(robot.forwardDynamics(th, v, tau));
  };
  std::vector<ClosedLoopSample<S>> out;
  DgVector<S> th = theta0, v = thetaDot0;
  auto sample = [&](const S& t) {
    out.push_back({t, th, v, Vec6<S>(geo.screws(th) * v), geo.forward(th)});
  };
  sample(S(0));
  for (int k = 0; k < steps; ++k) {
    const S t = S(k) * h;
    const DgVector<S> a1 = accel(th, v, t);
    const DgVector<S> v2 = v + h / S(2) * a1;
    const DgVector<S> a2 = accel(DgVector<S>(th + h / S(2) * v), v2, t + h / S(2));
    const DgVector<S> v3 = v + h / S(2) * a2;
    const DgVector<S> a3 = accel(DgVector<S>(th + h / S(2) * v2), v3, t + h / S(2));
    const DgVector<S> v4 = v + h * a3;
    const DgVector<S> a4 = accel(DgVector<S>(th + h * v3), v4, t + h);
    th += h / S(6) * (v + S(2) * v2 + S(2) * v3 + v4);
    v += h / S(6) * (a1 + S(2) * a2 + S(2) * a3 + a4);
    if ((k + 1) % every == 0) sample(S(k + 1) * h);
  }
  return out;
}

template <class S>
std::vector<ClosedLoopSample<S>> simulateGeodesicControl(const SerialDynamics<S>& robot, const GeodesicController<S>& c,
                                                         const DgVector<S>& mu, const DgVector<S>& theta0,
                                                         const DgVector<S>& thetaDot0, const S& h, int steps, int every) {
  const JointSpaceGeometry<S> geo = jointSpaceGeometryOf(robot);
  const TorqueLaw<S> law = [&](const DgVector<S>& th, const DgVector<S>& v, const S& t) {
    return geodesicControlTorque(robot, geo, c, th, v, t);
  };
  return simulateClosedLoop(robot, law, mu, theta0, thetaDot0, h, steps, every);
}

#define SOMA_INSTANTIATE_GEODESIC_CONTROL(S)                                                                         \
  template DgVector<S> geodesicControlTorque<S>(const SerialDynamics<S>&, const JointSpaceGeometry<S>&,       \
                                                const GeodesicController<S>&, const DgVector<S>&,             \
                                                const DgVector<S>&, const S&);                                \
  template JointSpaceGeometry<S> jointSpaceGeometryOf<S>(const SerialDynamics<S>&, InvariantMetric<S>);      \
  template std::vector<ClosedLoopSample<S>> simulateClosedLoop<S>(                                            \
      const SerialDynamics<S>&, const TorqueLaw<S>&, const DgVector<S>&, const DgVector<S>&, const DgVector<S>&, \
      const S&, int, int);                                                                                    \
  template std::vector<ClosedLoopSample<S>> simulateGeodesicControl<S>(                                       \
      const SerialDynamics<S>&, const GeodesicController<S>&, const DgVector<S>&, const DgVector<S>&,        \
      const DgVector<S>&, const S&, int, int);

}  // namespace soma
