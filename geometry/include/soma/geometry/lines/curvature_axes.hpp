#pragma once
// Curvature axes of a surface point (GF §6.5.3): for the local surface k_x x² + k_y y² = 2z, the
// axis of curvature of the normal section in direction (cos φ, sin φ, 0) is the line through
// (0, 0, 1/k_φ), k_φ = k_x cos²φ + k_y sin²φ (Euler), perpendicular to that direction and to z.
// As a rational cubic in (λ, μ) = (cos φ, sin φ), convention A (the book prints convention B, E6.1):
//   s(λ, μ) = (−μK, λK, 0; −λ(λ² + μ²), −μ(λ² + μ²), 0),  K = k_xλ² + k_yμ².
// K = 0 (asymptotic directions of a saddle, k_x k_y < 0) gives a line at infinity exactly.
// The axes fill the cubic surface z(k_x y² + k_y x²) = x² + y².
#include "soma/geometry/lines/ruled_surface.hpp"

namespace soma {

/// The curvature axis in homogeneous Plücker coordinates (convention A). Throws for (λ, μ) = 0.
// GF §6.5.3, GF-6.5.3-curvature-axes (convention A, E6.1)
template <class S> Vec6<S> curvatureAxis(const S& kx, const S& ky, const S& lambda, const S& mu) {
  if (!isFinite(kx) || !isFinite(ky) || !isFinite(lambda) || !isFinite(mu))
    throw InvalidInput("curvatureAxis: a curvature or parameter is NaN or infinite");
  const S q = lambda * lambda + mu * mu;
  if (q == S(0)) throw InvalidInput("curvatureAxis: (λ, μ) = (0, 0) is no direction");
  const S k = kx * lambda * lambda + ky * mu * mu;
  if (k == S(0) && kx == S(0) && ky == S(0))
    throw InvalidInput("curvatureAxis: k_x = k_y = 0 (a flat point has no curvature axes)");
  Vec6<S> s;
  s << -mu * k, lambda * k, S(0), -lambda * q, -mu * q, S(0);
  return s;
}
/// The ruled surface φ ↦ curvature axis, with the exact derivative. GF §6.5.3, GF-6.5.3-curvature-axes
template <class S> RuledSurface<S> curvatureAxesSurface(const S& kx, const S& ky) {
  return RuledSurface<S>(
      [=](const S& phi) {
        using std::cos;
        using std::sin;
        return curvatureAxis(kx, ky, S(cos(phi)), S(sin(phi)));
      },
      [=](const S& phi) {
        using std::cos;
        using std::sin;
        const S l = cos(phi), m = sin(phi), dl = -m, dm = l;
        const S k = kx * l * l + ky * m * m, dk = S(2) * (kx * l * dl + ky * m * dm);
        // q = λ² + μ² = 1, dq = 0.
        Vec6<S> d;
        d << -(dm * k + m * dk), dl * k + l * dk, S(0), -dl, -dm, S(0);
        return d;
      });
}
/// z(k_x y² + k_y x²) − (x² + y²): zero on every curvature axis. GF §6.5.3, GF-6.5.3-curvature-axes
template <class S> S curvatureAxesImplicit(const S& kx, const S& ky, const Vec3<S>& p) {
  const S x = p(0), y = p(1), z = p(2);
  return z * (kx * y * y + ky * x * x) - (x * x + y * y);
}

}  // namespace soma
