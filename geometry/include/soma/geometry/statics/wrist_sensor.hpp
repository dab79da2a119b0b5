#pragma once
// The four-beam wrist force sensor (GF §12.3, Fig. 12.2): beams of length l end at (±l, 0, 0)
// and (0, ±l, 0); eight strain gauges measure forces w₁…w₈ there. At +x: w₁ along y, w₂ along z;
// at +y: w₃ along x, w₄ along z; at −x: w₅ along y, w₆ along z; at −y: w₇ along x, w₈ along z.
// The total wrench is the resolved force matrix times w.
#include "soma/geometry/statics/wrench.hpp"

#include <array>

namespace soma {

template <class S> using Mat68 = Eigen::Matrix<S, 6, 8>;

/// Gauge i (0-based) of the sensor: the point its force acts at and the unit direction.
/// GF §12.3, GF-12.3-wrist-force-sensor (geometry derived from the eight printed wrenches)
template <class S> struct SensorGauge {
  Vec3<S> point;
  Vec3<S> direction;
};
template <class S> std::array<SensorGauge<S>, 8> wristSensorGauges(const S& l);

/// The eight wrenches 𝒲_i = w_i (r_i × d_i, d_i) of the gauges. GF §12.3, GF-12.3-wrist-force-sensor
template <class S> std::array<Wrench<S>, 8> wristSensorWrenches(const S& l, const Vec8<S>& w);

/// Resolved force matrix, corrected: row 2 = (0, −l, 0, 0, 0, +l, 0, 0), the total l(w₆ − w₂).
/// GF §12.3, GF-12.3-wrist-force-sensor (corrected, erratum E12.1: line 7410 prints −l at (2, 6);
/// studies/gf12/statics.cpp shows that matrix failing)
template <class S> Mat68<S> resolvedForceMatrix(const S& l);

/// Gauge signals that produce the wrench 𝒲: the minimum-norm solution of A w = 𝒲 (A has rank 6
/// for l > 0; 8 gauges, 2 redundant). InvalidInput for l ≤ 0 (rank 3: moments unmeasurable).
template <class S> Vec8<S> wristSensorSignals(const S& l, const Wrench<S>& W);

}  // namespace soma
