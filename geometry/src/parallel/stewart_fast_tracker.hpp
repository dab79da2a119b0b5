#pragma once
// The fast path of the Stewart forward kinematics (GF §11.5.4, GF-11.5.4-stewart-forty): the same
// parameter homotopy as stewart_impl.hpp's general tracker (start platform, γ, chart h·x = 1, the
// leg quadrics and the Study quadric), its 40 paths tracked in double by a tracker written for
// speed only:
//   - hand-written complex arithmetic (std::complex<double>'s product follows C99 Annex G: it tests
//     its result for NaN and may call __muldc3; its quotient calls __divdc3),
//   - fixed-size storage, the platform at τ formed once per τ (not once per evaluation),
//   - ONE LU per step and no other: the Newton iterations after the first reuse the first's LU
//     (simplified Newton), the tangent dx/dτ = −J⁻¹ ∂H/∂τ at the accepted point comes from that LU
//     refined once with the last Jacobian, and the predictor is the Hermite interpolant through the
//     last three accepted points and their tangents (degree 5, local error O(h⁶)), extrapolated to
//     τ + h; the general tracker's RK4 factors four more Jacobians per step (and each Newton one).
// It is double only (that is its purpose: the ≤ 1 ms median of issue 21); every other scalar, and
// double whenever this tracker is in doubt (a path that fails, ends singular or at infinity, or two
// endpoints that coincide), uses the general tracker, and solveStewartForward says so in its notes.
#include "soma/algebra/tolerance.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <vector>

namespace soma::stewart_fast {

/// A complex number with the plain products (no NaN/Inf recovery: a non-finite value is caught by
/// the tracker's own `dn == dn` test).
struct Cx {
  double re, im;
};
inline Cx operator+(Cx a, Cx b) { return {a.re + b.re, a.im + b.im}; }
inline Cx operator-(Cx a, Cx b) { return {a.re - b.re, a.im - b.im}; }
inline Cx operator-(Cx a) { return {-a.re, -a.im}; }
inline Cx operator*(Cx a, Cx b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
inline Cx operator*(double s, Cx a) { return {s * a.re, s * a.im}; }
inline Cx recip(Cx a) {
  const double n = a.re * a.re + a.im * a.im;
  return {a.re / n, -a.im / n};
}
inline double mod1(Cx a) { return std::abs(a.re) + std::abs(a.im); }
inline Cx cx(const std::complex<double>& z) { return {z.real(), z.imag()}; }

using V8 = std::array<Cx, 8>;
using M8 = std::array<std::array<Cx, 8>, 8>;

inline double maxNorm(const V8& x) {
  double m = 0;
  for (const Cx& z : x) m = std::max(m, mod1(z));
  return m;
}

/// LU with partial pivoting in place (multipliers below the diagonal, reciprocal pivots on it, the
/// row swaps in piv). Returns the ratio smallest/largest pivot modulus (0 when singular).
inline double factor(M8& A, std::array<int, 8>& piv) {
  double pmax = 0, pmin = 0;
  for (int k = 0; k < 8; ++k) {
    int p = k;
    double best = mod1(A[k][k]);
    for (int r = k + 1; r < 8; ++r) {
      const double v = mod1(A[r][k]);
      if (v > best) best = v, p = r;
    }
    if (!(best > 0)) return 0;
    piv[k] = p;
    if (p != k) std::swap(A[p], A[k]);
    if (k == 0) pmax = pmin = best;
    pmax = std::max(pmax, best);
    pmin = std::min(pmin, best);
    const Cx inv = recip(A[k][k]);
    A[k][k] = inv;
    for (int r = k + 1; r < 8; ++r) {
      const Cx f = A[r][k] * inv;
      A[r][k] = f;
      for (int c = k + 1; c < 8; ++c) A[r][c] = A[r][c] - f * A[k][c];
    }
  }
  return pmin / pmax;
}

/// b ← A⁻¹ b with the factors of `factor` (whole rows were swapped, multipliers included: P A = L U,
/// so every swap is applied to b before the forward substitution).
inline void solve(const M8& A, const std::array<int, 8>& piv, V8& b) {
  for (int k = 0; k < 8; ++k)
    if (piv[k] != k) std::swap(b[k], b[piv[k]]);
  for (int k = 0; k < 8; ++k)
    for (int r = k + 1; r < 8; ++r) b[r] = b[r] - A[r][k] * b[k];
  for (int k = 7; k >= 0; --k) {
    Cx s = b[k];
    for (int c = k + 1; c < 8; ++c) s = s - A[k][c] * b[c];
    b[k] = s * A[k][k];
  }
}

/// The parameter homotopy P(τ) = P0 + φ(τ) (P1 − P0), φ(τ) = τ / (τ + γ(1 − τ)), of
/// stewart_detail::ParameterHomotopy, with the chart row h·x − 1 as row 7. Per leg, the
/// difference d = q − p and sum s = q + p of its joints and L², each affine in φ.
struct Homotopy {
  struct Leg {
    Cx d0[3], s0[3], l0, dd[3], ds[3], dl;
  };
  std::array<Leg, 6> leg;
  Cx gamma;
  V8 h;
  /// The platform at one τ (and dφ/dτ), formed once per τ.
  struct At {
    Cx d[6][3], s[6][3], l[6], dphi;
  };
  At at(double t) const {
    At A;
    Cx phi{1, 0};
    A.dphi = {0, 0};
    if (t < 1) {
      const Cx den = Cx{t, 0} + (1 - t) * gamma;
      const Cx iden = recip(den);
      phi = Cx{t, 0} * iden;
      A.dphi = gamma * (iden * iden);
    } else {
      // dφ/dτ at τ = 1 is γ (den = 1); the tangent is not needed there but stays defined.
      A.dphi = gamma;
    }
    for (int i = 0; i < 6; ++i) {
      const Leg& g = leg[i];
      for (int k = 0; k < 3; ++k) {
        A.d[i][k] = g.d0[k] + phi * g.dd[k];
        A.s[i][k] = g.s0[k] + phi * g.ds[k];
      }
      A.l[i] = g.l0 + phi * g.dl;
    }
    return A;
  }
  /// f = H(x, τ), J = ∂H/∂x and ft = ∂H/∂τ (GF-11.5.4-stewart-leg-quadric: u = a q + 2c − p a,
  /// u₀ = −a_v·d + 2c₀, u_v = a₀ d + a_v × s + 2c_v; leg i is u·u − L² a·a).
  void eval(const At& A, const V8& x, V8& f, M8& J, V8& ft, bool wantFt = true) const {
    const Cx aa = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    f[0] = x[0] * x[4] + x[1] * x[5] + x[2] * x[6] + x[3] * x[7];
    for (int k = 0; k < 4; ++k) {
      J[0][k] = x[k + 4];
      J[0][k + 4] = x[k];
    }
    ft[0] = {0, 0};
    for (int i = 0; i < 6; ++i) {
      const Cx* d = A.d[i];
      const Cx* s = A.s[i];
      const Cx L = A.l[i];
      const Cx u0 = 2.0 * x[4] - (x[1] * d[0] + x[2] * d[1] + x[3] * d[2]);
      const Cx u1 = x[0] * d[0] + (x[2] * s[2] - x[3] * s[1]) + 2.0 * x[5];
      const Cx u2 = x[0] * d[1] + (x[3] * s[0] - x[1] * s[2]) + 2.0 * x[6];
      const Cx u3 = x[0] * d[2] + (x[1] * s[1] - x[2] * s[0]) + 2.0 * x[7];
      f[i + 1] = u0 * u0 + u1 * u1 + u2 * u2 + u3 * u3 - L * aa;
      auto& row = J[i + 1];
      row[0] = 2.0 * (u1 * d[0] + u2 * d[1] + u3 * d[2] - L * x[0]);
      row[1] = 2.0 * ((s[1] * u3 - s[2] * u2) - u0 * d[0] - L * x[1]);
      row[2] = 2.0 * ((s[2] * u1 - s[0] * u3) - u0 * d[1] - L * x[2]);
      row[3] = 2.0 * ((s[0] * u2 - s[1] * u1) - u0 * d[2] - L * x[3]);
      row[4] = 4.0 * u0;
      row[5] = 4.0 * u1;
      row[6] = 4.0 * u2;
      row[7] = 4.0 * u3;
      if (!wantFt) continue;
      const Leg& g = leg[i];
      const Cx du0 = -(x[1] * g.dd[0] + x[2] * g.dd[1] + x[3] * g.dd[2]);
      const Cx du1 = x[0] * g.dd[0] + (x[2] * g.ds[2] - x[3] * g.ds[1]);
      const Cx du2 = x[0] * g.dd[1] + (x[3] * g.ds[0] - x[1] * g.ds[2]);
      const Cx du3 = x[0] * g.dd[2] + (x[1] * g.ds[1] - x[2] * g.ds[0]);
      ft[i + 1] = A.dphi * (2.0 * (u0 * du0 + u1 * du1 + u2 * du2 + u3 * du3) - g.dl * aa);
    }
    Cx v{-1, 0};
    for (int k = 0; k < 8; ++k) {
      v = v + h[k] * x[k];
      J[7][k] = h[k];
    }
    f[7] = v;
    ft[7] = {0, 0};
  }
};

/// How one path ended.
struct Path {
  V8 x;
  bool finite = false;  ///< reached τ = 1 and Newton converged there to the rounding floor
  double pivotRatio = 0;
  int steps = 0, lus = 0;
};

/// Step control of the fast tracker (relative to max(1, |x|∞)), chosen on the 32 platforms of
/// bench/stewart.cpp (papers/benchmarks/stewart.md: 64 steps a path at target 2.5e-3 and three
/// simplified Newton iterations, 53.6 at 5.8e-3 with the fourth and the refactoring; accepting
/// after one Newton step, or at 1.2e-4, lost paths):
struct Settings {
  /// the predictor's target error (the first Newton correction): eps^(1/7) ≈ 5.8e-3;
  double predErr = Tolerance<double>::precision(6);
  /// a step is accepted when a Newton correction falls below this (the point is then exact to
  /// ~ its square: 1e-12 and below): eps^(1/3) ≈ 6e-6;
  double accept = Tolerance<double>::precision(2);
  /// a step is rejected when the first correction exceeds this multiple of predErr (the
  /// prediction left the path's neighbourhood: Newton might converge to another path);
  double rejectFactor = 8;
  /// Newton iterations a step at most; from the third on, the Jacobian is factored afresh when the
  /// last iteration contracted by less than this factor (the simplified Newton converges linearly,
  /// at a rate ~ cond · first: with the predictor's target above ~2e-3 it alone did not reach
  /// `accept` in three iterations on many steps, which were then rejected);
  int maxIterations = 4;
  double refactorRate = 1.0 / 16;
  double hmax = 0.25, hstart = 0.05;
  int maxSteps = 2000;
};

/// Hermite extrapolation through n ≤ 3 points (τ_j, x_j) with tangents v_j, evaluated at t: with
/// the Lagrange basis l_j of the nodes, x(t) = Σ_j [1 − 2 l_j'(τ_j)(t − τ_j)] l_j(t)² x_j
/// + (t − τ_j) l_j(t)² v_j, l_j'(τ_j) = Σ_{m≠j} 1/(τ_j − τ_m). The weights are scalars, computed
/// once; the eight coordinates are then sums.
inline V8 hermite(int n, const double* T, const V8* X, const V8* V, double t) {
  double wx[3], wv[3];
  for (int j = 0; j < n; ++j) {
    double l = 1, dl = 0;
    for (int m = 0; m < n; ++m) {
      if (m == j) continue;
      const double inv = 1.0 / (T[j] - T[m]);
      l *= (t - T[m]) * inv;
      dl += inv;
    }
    const double l2 = l * l, dt = t - T[j];
    wx[j] = (1 - 2 * dl * dt) * l2;
    wv[j] = dt * l2;
  }
  V8 out;
  for (int c = 0; c < 8; ++c) {
    Cx r{0, 0};
    for (int j = 0; j < n; ++j) r = r + wx[j] * X[j][c] + wv[j] * V[j][c];
    out[c] = r;
  }
  return out;
}

/// Tracks one path from τ = 0 to 1 and polishes its endpoint at τ = 1 by Newton to the rounding
/// floor. A path that does not get there comes back with finite = false (the caller falls back).
inline Path track(const Homotopy& H, const V8& start, const Settings& o) {
  Path r;
  const double eps = Tolerance<double>::epsilon();
  const double hmin = Tolerance<double>::sqrtEpsilon();
  V8 f, ft;
  M8 J, J2;
  std::array<int, 8> piv;
  // History: the last three accepted points, oldest first.
  double T[3];
  V8 X[3], V[3];
  int n = 0;
  const auto push = [&](double t, const V8& x, const V8& v) {
    if (n == 3) {
      T[0] = T[1], T[1] = T[2];
      X[0] = X[1], X[1] = X[2];
      V[0] = V[1], V[1] = V[2];
      n = 2;
    }
    T[n] = t, X[n] = x, V[n] = v;
    ++n;
  };
  // The tangent at the start.
  {
    const Homotopy::At A = H.at(0);
    H.eval(A, start, f, J, ft);
    ++r.lus;
    if (!(factor(J, piv) > 0)) return r;
    solve(J, piv, ft);
    for (auto& z : ft) z = -z;
    push(0, start, ft);
  }
  double t = 0, h = o.hstart;
  bool justRejected = false;
  for (int step = 0; step < o.maxSteps && t < 1; ++step) {
    r.steps = step + 1;
    if (t + h > 1) h = 1 - t;
    const double tn = h >= 1 - t ? 1.0 : t + h;
    V8 y = hermite(n, T, X, V, tn);
    const Homotopy::At A = H.at(tn);
    double first = 0, prev = 0;
    bool ok = false;
    int last = 0;
    // Newton with the Jacobian of the predicted point (one LU a step, mostly): the later iterations
    // reuse its LU (the "simplified" Newton, contraction ~ cond · first, as fast as Newton's second
    // step; refactored when it converges slowly, see Settings); their Jacobian J2 refines the
    // tangent below.
    double rate = 0;  // the last iteration's contraction
    for (int it = 0; it < o.maxIterations; ++it) {
      last = it;
      if (it == 0) {
        H.eval(A, y, f, J, ft, false);  // ∂H/∂τ is needed at the last iterate only
        ++r.lus;
        if (!(factor(J, piv) > 0)) break;
      } else {
        H.eval(A, y, f, J2, ft);
        if (it >= 2 && rate > o.refactorRate) {  // slow linear convergence: a full Newton step
          J = J2;
          ++r.lus;
          if (!(factor(J, piv) > 0)) break;
        }
      }
      solve(J, piv, f);
      for (int k = 0; k < 8; ++k) y[k] = y[k] - f[k];
      const double scale = std::max(1.0, maxNorm(y));
      const double dn = maxNorm(f) / scale;
      if (!(dn == dn)) break;
      if (it == 0) {
        first = dn;
        if (dn > o.rejectFactor * o.predErr) break;
      } else {
        rate = dn / prev;
        if (dn > prev / 4) break;  // not contracting fast: too far from the path for a safe Newton
      }
      prev = dn;
      if (dn <= o.accept) {
        ok = true;
        break;
      }
    }
    // The predictor's order: Hermite through n points is exact to degree 2n − 1, error O(h^(2n)).
    const double expo = 1.0 / double(2 * n);
    if (ok) {
      // The tangent at the new point: J⁻¹(−∂H/∂τ) with the LU of the predicted point, refined once
      // with the Jacobian J2 of the last iterate (error ~ (cond · first)², and ≤ accept away from
      // the new point).
      if (last == 0) H.eval(A, y, f, J2, ft);  // accepted at once (rare): ∂H/∂τ at the new point
      for (auto& z : ft) z = -z;
      V8 v = ft;
      solve(J, piv, v);
      if (last > 0) {
        V8 res = ft;
        for (int i = 0; i < 8; ++i)
          for (int k = 0; k < 8; ++k) res[i] = res[i] - J2[i][k] * v[k];
        solve(J, piv, res);
        for (int k = 0; k < 8; ++k) v[k] = v[k] + res[k];
      }
      ft = v;
      push(tn, y, ft);
      t = tn;
      double g = 2;
      if (first > 0) g = std::min(2.0, std::max(0.5, 0.9 * std::pow(o.predErr / first, expo)));
      if (justRejected && g > 1) g = 1;
      h = std::min(o.hmax, h * g);
      justRejected = false;
    } else {
      double g = 0.5;
      if (first > 0 && first == first) g = std::min(0.5, std::max(0.125, 0.9 * std::pow(o.predErr / first, expo)));
      h *= g;
      justRejected = true;
      if (h < hmin) return r;
    }
  }
  if (t < 1) return r;
  // Polish at τ = 1: Newton until the correction is at the rounding floor (64 eps), or stops
  // decreasing (then it must already be below the tracking accuracy).
  const Homotopy::At A = H.at(1);
  V8 y = X[n - 1];
  double prev = 0, pr = 0;
  bool conv = false;
  for (int it = 0; it < 10; ++it) {
    H.eval(A, y, f, J, ft);
    ++r.lus;
    pr = factor(J, piv);
    if (!(pr > 0)) break;
    solve(J, piv, f);
    const double dn = maxNorm(f);
    if (!(dn == dn)) break;
    V8 z = y;
    for (int k = 0; k < 8; ++k) z[k] = z[k] - f[k];
    const double scale = std::max(1.0, maxNorm(z));
    if (it > 0 && dn > prev / 2) {
      conv = prev <= o.accept * scale;
      break;
    }
    y = z;
    prev = dn;
    if (dn <= 64 * eps * scale) {
      conv = true;
      break;
    }
  }
  r.x = y;
  r.pivotRatio = pr;
  r.finite = conv && pr > Tolerance<double>::sqrtEpsilon();
  return r;
}

}  // namespace soma::stewart_fast
