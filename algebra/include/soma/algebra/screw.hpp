#pragma once
// Chasles: every rigid motion is a screw motion (GF §2.5.2). The library's pitch is per
// RADIAN (h = ω·v/|ω|², as in GF ch. 4 on); the book's §2.5.2 pitch is per TURN, p = 2πh.
#include "soma/algebra/se3.hpp"

namespace soma {

/// Screw decomposition of a rigid motion: rotation θ about the line through `point` with unit
/// direction `axis`, plus a translation θ·pitch along it. For a pure translation (rotation angle
/// below Tolerance::epsilon(), not representable in a unit-scale matrix) `pureTranslation` is
/// set and the motion is `translationDistance` along the unit `translationDirection`; θ, axis,
/// point and pitch are then zero.
template <class S> struct Screw {
  S theta{0};                     ///< rotation angle, in [0, π]
  Vec3<S> axis{Vec3<S>::Zero()};  ///< unit direction of the screw axis
  Vec3<S> point{Vec3<S>::Zero()}; ///< foot of the perpendicular from the origin (point ⟂ axis)
  S pitch{0};                     ///< advance per radian (the book's per-turn pitch is 2π·pitch)
  bool pureTranslation{false};
  Vec3<S> translationDirection{Vec3<S>::Zero()};  ///< unit, zero for the identity
  S translationDistance{0};       ///< |t| (also θ·pitch when not a pure translation)
};

/// Chasles decomposition through the se(3) logarithm: for log X = (ω; v), θ = |ω|,
/// axis = ω/θ, pitch = ω·v/θ², point = ω × v/θ² (moment convention v = q × ω + pitch·ω).
/// At θ = π the axis sign is the one log() returns (both describe the same motion).
// GF §2.5.2, GF-2.5.2-chasles-decomposition
template <class S> Screw<S> screwOf(const SE3<S>& x) {
  using std::sqrt;
  const SE3Tangent<S> s = x.log();
  const Vec3<S> w = s.ang(), v = s.lin();
  const S theta2 = w.squaredNorm();
  Screw<S> out;
  const S tn2 = x.translation().squaredNorm();
  const S eps = Tolerance<S>::epsilon();
  if (theta2 < eps * eps) {
    out.pureTranslation = true;
    out.translationDistance = sqrt(tn2);
    if (tn2 > S(0)) out.translationDirection = x.translation() / out.translationDistance;
    return out;
  }
  out.theta = sqrt(theta2);
  out.axis = w / out.theta;
  out.pitch = w.dot(v) / theta2;
  out.point = w.cross(v) / theta2;
  out.translationDistance = out.theta * out.pitch;
  out.translationDirection = out.axis;
  return out;
}

/// The book's screw-motion matrix [[R(θ, â), θ·h·â + (I − R)u], [0, 1]] for a unit axis â
/// through any point u, pitch h per radian (book: p = 2πh per turn). Throws InvalidInput for a
/// non-unit axis or non-finite input.
/// (I − R)u is taken from Rodrigues' formula, −sin θ â×u − 2 sin²(θ/2) â×(â×u) (GF §4.4.1, GF-4.4.1-rodrigues),
/// never as u − Ru: at a small angle the axis of an ordinary motion lies far away (|u| ≈ |t|/θ),
/// and u − Ru would lose all but |t|/|u| of u's digits (θ = 1e-8 in double: 8 of 16 left).
// GF §2.5.2, GF-2.5.2-screw-motion-matrix
template <class S>
SE3<S> screwMotion(const Vec3<S>& axis, const Vec3<S>& point, const S& pitchPerRadian,
                   const S& theta) {
  using std::sin;
  using std::sqrt;
  if (!allFinite(point) || !isFinite(pitchPerRadian))
    throw InvalidInput("screwMotion: point or pitch has a NaN or infinite component");
  const SO3<S> r = SO3<S>::fromAxisAngle(axis, theta);  // validates axis and θ
  const Vec3<S> a = axis / sqrt(axis.squaredNorm());
  const Vec3<S> au = a.cross(point);
  const S half = sin(theta / S(2));
  const Vec3<S> t = theta * pitchPerRadian * a - sin(theta) * au - S(2) * half * half * a.cross(au);
  return SE3<S>(r, t);
}

}  // namespace soma
