#pragma once
// Screws as 6-vectors s = (ω; v) of se(3) (GF §6.4): pitch h = ω·v/ω·ω (per radian), axis the
// line (ω; v − hω), and the inverse construction s = |s|(u; m + h u) from a unit axis (u; m).
// Infinite pitch: ω = 0, s = (0; v) is a pure translation along v. Convention A (v = q × ω + hω).
// The Chasles decomposition of a finite motion is algebra/screw.hpp (screwOf); the axis of
// exp(s) found there agrees with screwAxis(s) (tests/geometry/lines/screw_axis.cpp).
#include "soma/geometry/lines/line.hpp"

#include <limits>

namespace soma {

/// Axis, pitch and amplitude of a screw. For an infinite-pitch screw (ω = 0) `axis` is the line
/// at infinity (0; v) (the direction of translation names it), pitch = +∞ and amplitude = |v|.
template <class S> struct ScrewAxis {
  PluckerLine<S> axis;            ///< unit line (|ω| = 1) through the axis, same orientation as ω
  S pitch{0};              ///< h = ω·v/ω·ω per radian; +∞ when infinitePitch
  S amplitude{0};          ///< |ω| (|v| for infinite pitch)
  bool infinitePitch = false;
};

/// Pitch ω·v/ω·ω (+∞ for ω = 0; throws for s = 0). GF §6.4, GF-6.4-pitch-quadrics
template <class S> S screwPitch(const Vec6<S>& s) {
  const S ww = s.template head<3>().squaredNorm();
  if (ww == S(0)) {
    if (s.template tail<3>().squaredNorm() == S(0)) throw InvalidInput("screwPitch: the zero screw has no pitch");
    return std::numeric_limits<S>::infinity();
  }
  return kleinValue(s) / ww;
}

/// Axis, pitch and amplitude of a screw (ω; v). Throws for a NaN or the zero screw.
// GF §6.4, GF-6.4-pitch-quadrics (form (ω, r × ω + pω))
template <class S> ScrewAxis<S> screwAxis(const Vec6<S>& s) {
  using std::sqrt;
  if (!allFinite(s)) throw InvalidInput("screwAxis: a coordinate is NaN or infinite");
  const Vec3<S> w = s.template head<3>(), v = s.template tail<3>();
  const S ww = w.squaredNorm();
  if (ww == S(0)) {
    if (v.squaredNorm() == S(0)) throw InvalidInput("screwAxis: the zero screw has no axis");
    return {PluckerLine<S>::atInfinity(v), std::numeric_limits<S>::infinity(), sqrt(v.squaredNorm()), true};
  }
  const S h = w.dot(v) / ww, n = sqrt(ww);
  // The axis through its foot q = ω × v/|ω|² (convention A): q × u is perpendicular to u up to
  // rounding relative to |q|, even when the axis passes within rounding of the origin (the
  // moment v − hω would be pure rounding noise along ω there).
  const Vec3<S> q = w.cross(v) / ww;
  return {PluckerLine<S>::pointDirection(q, Vec3<S>(w / n)), h, n, false};
}

/// The screw of amplitude a about a finite axis with pitch h: a·(u; m + h u), (u; m) the unit axis.
// GF §6.4, GF-6.4-pitch-quadrics
template <class S> Vec6<S> screwFromAxis(const PluckerLine<S>& axis, const S& pitch, const S& amplitude = S(1)) {
  if (!isFinite(pitch)) throw InvalidInput("screwFromAxis: pitch is not finite (use screwTranslation)");
  const PluckerLine<S> u = axis.normalized();  // throws for a line at infinity
  Vec6<S> s;
  s << u.direction(), Vec3<S>(u.moment() + pitch * u.direction());
  return amplitude * s;
}

/// The infinite-pitch screw (0; d): a translation along d. GF §6.4, GF-6.4-pitch-quadrics
template <class S> Vec6<S> screwTranslation(const Vec3<S>& d) {
  if (!allFinite(d) || d.squaredNorm() == S(0)) throw InvalidInput("screwTranslation: direction d is zero or not finite");
  Vec6<S> s;
  s << Vec3<S>::Zero(), d;
  return s;
}

#define SOMA_SCREW_AXIS_EXTERN(S)                                        \
  extern template S screwPitch<S>(const Vec6<S>&);                       \
  extern template ScrewAxis<S> screwAxis<S>(const Vec6<S>&);             \
  extern template Vec6<S> screwFromAxis<S>(const PluckerLine<S>&, const S&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_SCREW_AXIS_EXTERN)
#undef SOMA_SCREW_AXIS_EXTERN

}  // namespace soma
