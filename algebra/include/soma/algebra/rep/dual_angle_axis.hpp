#pragma once
// The dual angle θ̌ = θ + εd and dual axis v̌ = v + εu of an SO(3, 𝔻) matrix Ř = R + εTR (GF §7.6):
// the motion is the screw about the line (v; u = r × v) by θ with slide d, and
// Tr Ř = 1 + 2cos θ̌ = 1 + 2cos θ − 2εd sin θ, Ř − Řᵀ = 2 sin θ̌ V̌ = 2 sin θ V + 2ε(sin θ U + d cos θ V).
// Solving those equations divides by sin θ (fails at θ = 0 and θ = π); soma instead reads the
// screw from the se(3) logarithm (atan2-based, screwOf), valid for every θ ∈ [0, π].
#include "soma/algebra/rep/transference.hpp"
#include "soma/algebra/screw.hpp"

namespace soma::rep {

template <class S> struct DualAngleAxis {
  DualNumber<S> angle;                  ///< θ + εd (θ ∈ [0, π], d the slide along the axis)
  Vec3<S> direction{Vec3<S>::Zero()};   ///< v, unit (translation direction for a pure translation)
  Vec3<S> moment{Vec3<S>::Zero()};      ///< u = r × v (zero for a pure translation: no axis line)
  bool pureTranslation{false};          ///< θ = 0: the dual angle is εd, the axis only a direction
};

/// Dual angle and axis of Ř = R + εTR. Throws InvalidInput when R is not a rotation or the dual
/// part is not of the form TR (T skew) to input tolerance.
// GF §7.6, GF-7.6-dual-killing-and-dual-angle
template <class S> DualAngleAxis<S> dualAngleAxis(const DualMat3<S>& r) {
  const SO3<S> rot = SO3<S>::fromMatrix(r.re);  // validates R
  const Mat3<S> t = r.du * r.re.transpose();
  const S scale = S(1) + t.template lpNorm<Eigen::Infinity>();
  if (Mat3<S>(t + t.transpose()).template lpNorm<Eigen::Infinity>() > Tolerance<S>::input() * scale)
    throw InvalidInput("dualAngleAxis: the dual part is not T·R with T skew-symmetric");
  const Screw<S> sc = screwOf(SE3<S>(rot, Vec3<S>(t(2, 1), t(0, 2), t(1, 0))));
  DualAngleAxis<S> out;
  if (sc.pureTranslation) {
    out.pureTranslation = true;
    out.angle = {S(0), sc.translationDistance};
    out.direction = sc.translationDirection;
    return out;
  }
  out.angle = {sc.theta, sc.theta * sc.pitch};
  out.direction = sc.axis;
  out.moment = sc.point.cross(sc.axis);
  return out;
}

}  // namespace soma::rep
