#pragma once
// sin and cos of one argument by one libm call (sincos: one range reduction for both, ~20 % less
// time than sin and cos apart in glibc) for float, double and long double; std::sin and std::cos
// for the other scalars of the ladder (rotations about an axis need both).
#include "soma/algebra/scalar.hpp"  // sin and cos of __float128 and mpreal

#include <cmath>
#include <type_traits>

namespace soma {

/// s = sin x, c = cos x.
template <class S> inline void sinCos(const S& x, S& s, S& c) {
  if constexpr (std::is_same_v<S, double>) {
    ::sincos(x, &s, &c);
  } else if constexpr (std::is_same_v<S, float>) {
    ::sincosf(x, &s, &c);
  } else if constexpr (std::is_same_v<S, long double>) {
    ::sincosl(x, &s, &c);
  } else {
    using std::cos;
    using std::sin;
    s = sin(x);
    c = cos(x);
  }
}

}  // namespace soma
