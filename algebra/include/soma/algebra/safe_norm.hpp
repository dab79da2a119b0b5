#pragma once
// The Euclidean norm of a vector that neither overflows nor underflows (issue 24): |x| computed as
// m·sqrt(Σ (x_i/m)²) with m = max |x_i|, the scaling of LAPACK's xNRM2 and of hypot. The plain
// sqrt(x.squaredNorm()) overflows to infinity once a component exceeds sqrt(max) (1.3e154 in
// double: link lengths of 1e160 gave a length scale of infinity and rank 3 for a rank-6 arm) and
// underflows to 0 below sqrt(min) (1.5e-154 in double).
#include "soma/algebra/scalar.hpp"

#include <Eigen/Core>

namespace soma {

/// |x| for any scalar of the ladder: finite whenever the norm itself is representable, correct to
/// a few ulps (one division, one square and one sum per component, one square root). 0 for the zero
/// vector; infinity or NaN when a component is.
template <class Derived> typename Derived::Scalar safeNorm(const Eigen::MatrixBase<Derived>& x) {
  using S = typename Derived::Scalar;
  using std::abs;
  using std::sqrt;
  S m = S(0);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const S a = abs(x.derived().coeff(i));
    if (a != a) return a;  // NaN
    if (a > m) m = a;
  }
  if (m == S(0) || !isFinite(m)) return m;
  S s2 = S(0);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const S q = x.derived().coeff(i) / m;
    s2 += q * q;
  }
  return m * sqrt(s2);
}

}  // namespace soma
