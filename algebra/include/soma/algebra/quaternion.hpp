#pragma once
// Quaternions as in GF §2.1–2.2: the product, the map to SO(3) and its four-chart inverse.
// Quat<S> is Eigen::Quaternion<S>: constructed (w, x, y, z), stored (x, y, z, w).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <string>

namespace soma {

/// Quaternion product written out as in the book (independent of Eigen's operator*).
// GF §2.1, GF-2.1-quaternion-product
template <class S> Quat<S> quaternionProduct(const Quat<S>& a, const Quat<S>& b) {
  return Quat<S>(a.w() * b.w() - a.x() * b.x() - a.y() * b.y() - a.z() * b.z(),
                 a.w() * b.x() + b.w() * a.x() + a.y() * b.z() - b.y() * a.z(),
                 a.w() * b.y() + b.w() * a.y() - a.x() * b.z() + b.x() * a.z(),
                 a.w() * b.z() + b.w() * a.z() + a.x() * b.y() - b.x() * a.y());
}

/// Rotation matrix of the point (w:x:y:z) of PR³, the scale-free 1/Δ form (any non-zero,
/// finite q; q and λq give the same matrix). Throws InvalidInput for q = 0 or non-finite q.
// GF §2.2.2, GF-2.2.2-SO3-from-quaternion
template <class S> Mat3<S> rotationFromQuaternion(const Quat<S>& q) {
  using std::abs;
  if (!allFinite(q.coeffs()))
    throw InvalidInput("rotationFromQuaternion: quaternion has a NaN or infinite component");
  // Scale by the largest component first so the squares neither overflow nor underflow.
  S m = abs(q.w());
  for (int i = 0; i < 3; ++i)
    if (abs(q.vec()(i)) > m) m = abs(q.vec()(i));
  if (m == S(0)) throw InvalidInput("rotationFromQuaternion: the zero quaternion is not a rotation");
  const S w = q.w() / m, x = q.x() / m, y = q.y() / m, z = q.z() / m;
  const S d = w * w + x * x + y * y + z * z;
  Mat3<S> r;
  r << w * w + x * x - y * y - z * z, S(2) * (x * y - w * z), S(2) * (x * z + w * y),
      S(2) * (x * y + w * z), w * w - x * x + y * y - z * z, S(2) * (y * z - w * x),
      S(2) * (x * z - w * y), S(2) * (y * z + w * x), w * w - x * x - y * y + z * z;
  return r / d;
}

/// One of the book's four charts SO(3) → PR³ (chart = 1..4), as homogeneous coordinates
/// (w:x:y:z), NOT normalised, with the diagonal-type entry halved like the others, so chart k
/// returns 2·q_k·(w:x:y:z). The book prints the full diagonal-type entry (erratum E2.2) and
/// r21 − r21 in chart 1 (erratum E2.1); the study GF-2.2.2-SO3-to-quaternion-charts
/// (studies/gf02/matrix_groups.cpp) computes those printed charts and shows them failing.
// GF §2.2.2, GF-2.2.2-SO3-to-quaternion-charts (corrected: errata E2.1, E2.2)
template <class S> Quat<S> quaternionFromRotationChart(const Mat3<S>& r, int chart) {
  const S h = S(1) / S(2);
  switch (chart) {
    case 1:
      return Quat<S>(h * (S(1) + r(0, 0) + r(1, 1) + r(2, 2)), h * (r(2, 1) - r(1, 2)),
                     h * (r(0, 2) - r(2, 0)), h * (r(1, 0) - r(0, 1)));
    case 2:
      return Quat<S>(h * (r(2, 1) - r(1, 2)), h * (S(1) + r(0, 0) - r(1, 1) - r(2, 2)),
                     h * (r(0, 1) + r(1, 0)), h * (r(0, 2) + r(2, 0)));
    case 3:
      return Quat<S>(h * (r(0, 2) - r(2, 0)), h * (r(0, 1) + r(1, 0)),
                     h * (S(1) - r(0, 0) + r(1, 1) - r(2, 2)), h * (r(1, 2) + r(2, 1)));
    case 4:
      return Quat<S>(h * (r(1, 0) - r(0, 1)), h * (r(0, 2) + r(2, 0)), h * (r(1, 2) + r(2, 1)),
                     h * (S(1) - r(0, 0) - r(1, 1) + r(2, 2)));
    default: break;
  }
  throw InvalidInput("quaternionFromRotationChart: chart must be 1, 2, 3 or 4, got " +
                     std::to_string(chart));
}

/// The diagonal-type entries 1+r11+r22+r33, 1+r11−r22−r33, 1−r11+r22−r33, 1−r11−r22+r33
/// (= 4w², 4x², 4y², 4z² for a rotation) and the chart (1..4) with the largest one.
template <class S> int shepperdChart(const Mat3<S>& r) {
  const S d[4] = {S(1) + r(0, 0) + r(1, 1) + r(2, 2), S(1) + r(0, 0) - r(1, 1) - r(2, 2),
                  S(1) - r(0, 0) + r(1, 1) - r(2, 2), S(1) - r(0, 0) - r(1, 1) + r(2, 2)};
  int best = 0;
  for (int k = 1; k < 4; ++k)
    if (d[k] > d[best]) best = k;
  return best + 1;
}

/// Unit quaternion (w ≥ 0) of a rotation matrix: the corrected chart whose diagonal-type
/// entry is largest (Shepperd's rule), normalised. Assumes r is a rotation (validate with
/// SO3::fromMatrix for user input). At w = 0 (half-turns) ±q are both returned as-is.
// GF §2.2.2, GF-2.2.2-SO3-to-quaternion-charts (corrected, errata E2.1, E2.2)
template <class S> Quat<S> quaternionFromRotation(const Mat3<S>& r) {
  Quat<S> q = quaternionFromRotationChart(r, shepperdChart(r));
  q.coeffs() /= q.coeffs().norm();
  if (q.w() < S(0)) q.coeffs() = -q.coeffs();
  return q;
}

}  // namespace soma
