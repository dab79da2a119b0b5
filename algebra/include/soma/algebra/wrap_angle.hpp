#pragma once
// An angle brought into [−π, π]: joint angles, their differences and the angles of a mechanism's
// links compared modulo 2π, in every scalar of the ladder.
#include "soma/algebra/scalar.hpp"  // pi<S>(), sin/cos/atan2 of __float128 and mpreal

#include <cmath>

namespace soma {

/// a mod 2π in [−π, π] (atan2's range; an angle already in (−π, π] is returned unchanged, bit for bit).
template <class S> S wrapAngle(const S& a) {
  using std::atan2;
  using std::cos;
  using std::sin;
  if (a > -pi<S>() && a <= pi<S>()) return a;
  return atan2(sin(a), cos(a));
}

}  // namespace soma
