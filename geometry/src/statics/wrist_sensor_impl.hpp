#pragma once
// The four-beam wrist force sensor, GF §12.3, GF-12.3-wrist-force-sensor.
#include "soma/geometry/statics/wrist_sensor.hpp"

#include <Eigen/Cholesky>

namespace soma {

template <class S> std::array<SensorGauge<S>, 8> wristSensorGauges(const S& l) {
  const Vec3<S> i = Vec3<S>::UnitX(), j = Vec3<S>::UnitY(), k = Vec3<S>::UnitZ();
  const Vec3<S> px = l * i, py = l * j, mx = -l * i, my = -l * j;
  return {{{px, j}, {px, k}, {py, i}, {py, k}, {mx, j}, {mx, k}, {my, i}, {my, k}}};
}

// GF §12.3, GF-12.3-wrist-force-sensor: 𝒲_i = w_i (r_i × d_i, d_i).
template <class S> std::array<Wrench<S>, 8> wristSensorWrenches(const S& l, const Vec8<S>& w) {
  const auto g = wristSensorGauges<S>(l);
  std::array<Wrench<S>, 8> out;
  for (int n = 0; n < 8; ++n) out[std::size_t(n)] = Wrench<S>::ofForce(g[std::size_t(n)].point, Vec3<S>(w(n) * g[std::size_t(n)].direction));
  return out;
}

// GF §12.3, GF-12.3-wrist-force-sensor (corrected, erratum E12.1: entry (2,6) is +l).
template <class S> Mat68<S> resolvedForceMatrix(const S& l) {
  Mat68<S> a = Mat68<S>::Zero();
  a(0, 3) = l, a(0, 7) = -l;
  a(1, 1) = -l, a(1, 5) = l;
  a(2, 0) = l, a(2, 2) = -l, a(2, 4) = -l, a(2, 6) = l;
  a(3, 2) = S(1), a(3, 6) = S(1);
  a(4, 0) = S(1), a(4, 4) = S(1);
  a(5, 1) = S(1), a(5, 3) = S(1), a(5, 5) = S(1), a(5, 7) = S(1);
  return a;
}

template <class S> Vec8<S> wristSensorSignals(const S& l, const Wrench<S>& W) {
  if (!isFinite(l) || !(l > S(0)))
    throw InvalidInput("wristSensorSignals: beam length l = " + toString(l) +
                       " is not positive (the moment rows vanish: rank 3)");
  if (!allFinite(W.coeffs())) throw InvalidInput("wristSensorSignals: the wrench has a NaN or infinite entry");
  const Mat68<S> a = resolvedForceMatrix<S>(l);
  const Mat6<S> aat = a * a.transpose();  // diag-dominant, SPD for l > 0
  const Vec6<S> y = Eigen::LLT<Mat6<S>>(aat).solve(W.coeffs());
  return a.transpose() * y;
}

#define SOMA_STATICS_SENSOR_INST(S)                                                          \
  template std::array<SensorGauge<S>, 8> wristSensorGauges<S>(const S&);                     \
  template std::array<Wrench<S>, 8> wristSensorWrenches<S>(const S&, const Vec8<S>&);         \
  template Mat68<S> resolvedForceMatrix<S>(const S&);                                         \
  template Vec8<S> wristSensorSignals<S>(const S&, const Wrench<S>&);

}  // namespace soma
