#pragma once
// One trait for every threshold in soma (DESIGN §2). No bare literals inside algorithms:
// a branch near a singularity or a small angle takes its threshold from here.
#include "soma/algebra/scalar.hpp"

namespace soma {

template <class S> struct Tolerance {
  /// Machine epsilon of S (for mpreal: at the current default precision).
  static S epsilon() { return std::numeric_limits<S>::epsilon(); }

  /// Pinocchio-style switch for a Taylor branch: eps^(1/(degree+1)). A series kept to
  /// order `degree` in θ has truncation error below eps for |θ| < precision(degree).
  static S precision(int degree) {
    using std::pow;
    return pow(epsilon(), S(1) / S(degree + 1));
  }

  /// sqrt(eps): the scale of error left by one cancellation (e.g. 1 - cos θ).
  static S sqrtEpsilon() {
    using std::sqrt;
    return sqrt(epsilon());
  }

  /// Accepted defect of user input that must be unit / orthogonal / on a quadric
  /// (|q|-1, |RᵀR - I|, Study condition), relative to its scale. Input further off is
  /// rejected with a message, never silently renormalised.
  static S input() { return S(64) * sqrtEpsilon(); }

  /// Default tolerance of an identity check in tests and studies: k ulps of unit-scale data.
  static S identity(int ulps = 64) { return S(ulps) * epsilon(); }

  /// Relative threshold for a numerical rank decision (singular value / largest).
  static S rank() { return S(1024) * epsilon(); }
};

}  // namespace soma
