#pragma once
// The Lie bracket of se(3) on twists written as 6-vectors (ω, v), for code that keeps screws as
// plain Vec6 (screw systems, the Newton–Euler passes of the dynamics): the same product as
// bracket(SE3Tangent, SE3Tangent) in lie_algebra.hpp.
#include "soma/algebra/scalar.hpp"

namespace soma {

/// [(ω₁, v₁), (ω₂, v₂)] = ad(a) b = (ω₁×ω₂, ω₁×v₂ − ω₂×v₁). GF §4.3 (GF §13.1 convention)
template <class S> Vec6<S> screwBracket(const Vec6<S>& a, const Vec6<S>& b) {
  const Vec3<S> w1 = a.template head<3>(), v1 = a.template tail<3>();
  const Vec3<S> w2 = b.template head<3>(), v2 = b.template tail<3>();
  Vec6<S> r;
  r << w1.cross(w2), Vec3<S>(w1.cross(v2) - w2.cross(v1));
  return r;
}

}  // namespace soma
