#pragma once
// Template bodies of parallel/stewart.hpp, instantiated once per scalar by soma_instantiate (cmake/SomaInstantiate.cmake).
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/stewart_class.hpp"
#include "stewart_fast_tracker.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/safe_norm.hpp"
#include "soma/algebra/study_parameters.hpp"
#include "soma/algebra/tolerance.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <map>
#include <mutex>
#include <random>
#include <stdexcept>
#include <tuple>

namespace soma {

namespace stewart_detail {

template <class S> using C = std::complex<S>;
template <class S> using X = std::array<C<S>, 8>;
template <class S> using M = std::array<std::array<C<S>, 8>, 8>;

/// |re| + |im|: a norm without a square root.
template <class S> S mod1(const C<S>& z) {
  using std::abs;
  return abs(z.real()) + abs(z.imag());
}
template <class S> S maxNorm(const X<S>& x) {
  S m = S(0);
  for (const auto& z : x) m = std::max(m, mod1(z));
  return m;
}
template <class S> S maxNormA(const X<S>& x) {
  S m = S(0);
  for (int k = 0; k < 4; ++k) m = std::max(m, mod1(x[k]));
  return m;
}

/// The tolerance of path tracking: √eps of S, but never below √eps of double (tracking more
/// tightly buys nothing on a well-separated path; the endpoints are polished to the precision
/// of S). The fine mode of an escalation tracks to √eps of S, never below √eps of float128.
template <class S> S trackEps(bool fine = false) {
  if (fine) return std::max(Tolerance<S>::sqrtEpsilon(), scalarCast<S>(Tolerance<__float128>::sqrtEpsilon()));
  return std::max(Tolerance<S>::sqrtEpsilon(), scalarCast<S>(Tolerance<double>::sqrtEpsilon()));
}

/// Solves A y = b in place (b ← y) by Gaussian elimination with partial pivoting. Returns the
/// ratio smallest/largest pivot modulus (0 when singular): a cheap conditioning indicator.
template <class S> S solve8(M<S>& A, X<S>& b) {
  S pmax = S(0), pmin = S(0);
  for (int k = 0; k < 8; ++k) {
    int piv = k;
    S best = mod1(A[k][k]);
    for (int r = k + 1; r < 8; ++r) {
      const S v = mod1(A[r][k]);
      if (v > best) best = v, piv = r;
    }
    if (!(best > S(0))) return S(0);
    if (piv != k) {
      std::swap(A[piv], A[k]);
      std::swap(b[piv], b[k]);
    }
    if (k == 0) pmax = pmin = best;
    pmax = std::max(pmax, best);
    pmin = std::min(pmin, best);
    const C<S> inv = C<S>(S(1)) / A[k][k];
    for (int r = k + 1; r < 8; ++r) {
      const C<S> f = A[r][k] * inv;
      if (f == C<S>(S(0))) continue;
      for (int c = k + 1; c < 8; ++c) A[r][c] -= f * A[k][c];
      b[r] -= f * b[k];
    }
    A[k][k] = inv;  // keep the reciprocal for the back substitution
  }
  for (int k = 7; k >= 0; --k) {
    C<S> s = b[k];
    for (int c = k + 1; c < 8; ++c) s -= A[k][c] * b[c];
    b[k] = s * A[k][k];
  }
  return pmin / pmax;
}

template <class S> using CP = StewartComplexPlatform<S>;

/// u = a q + 2c − p a for one leg (q, p pure quaternions): with d = q − p, s = q + p,
/// u₀ = −a_v·d + 2c₀, u_v = a₀ d + a_v × s + 2c_v. GF §11.5.4, GF-11.5.4-stewart-leg-quadric
template <class S>
void legU(const std::array<C<S>, 3>& d, const std::array<C<S>, 3>& s, const X<S>& x, std::array<C<S>, 4>& u) {
  u[0] = -(x[1] * d[0] + x[2] * d[1] + x[3] * d[2]) + S(2) * x[4];
  u[1] = x[0] * d[0] + (x[2] * s[2] - x[3] * s[1]) + S(2) * x[5];
  u[2] = x[0] * d[1] + (x[3] * s[0] - x[1] * s[2]) + S(2) * x[6];
  u[3] = x[0] * d[2] + (x[1] * s[1] - x[2] * s[0]) + S(2) * x[7];
}

/// Values (rows 0..6: Study, six legs) and, if J, the Jacobian rows 0..6 of the leg system at x
/// for the platform P; if dP (a direction in parameter space), the derivative dF·dP in dF.
template <class S>
void evalSystem(const CP<S>& P, const X<S>& x, X<S>& f, M<S>* J, const CP<S>* dP, X<S>* dF) {
  const C<S> aa = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
  f[0] = x[0] * x[4] + x[1] * x[5] + x[2] * x[6] + x[3] * x[7];
  if (J) {
    for (int k = 0; k < 4; ++k) {
      (*J)[0][k] = x[k + 4];
      (*J)[0][k + 4] = x[k];
    }
  }
  if (dF) (*dF)[0] = C<S>(S(0));
  for (int i = 0; i < 6; ++i) {
    std::array<C<S>, 3> d, s;
    for (int k = 0; k < 3; ++k) {
      d[k] = P.q[i][k] - P.p[i][k];
      s[k] = P.q[i][k] + P.p[i][k];
    }
    std::array<C<S>, 4> u;
    legU<S>(d, s, x, u);
    f[i + 1] = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + u[3] * u[3] - P.L2[i] * aa;
    if (J) {
      auto& row = (*J)[i + 1];
      const C<S> two(S(2));
      row[0] = two * (u[1] * d[0] + u[2] * d[1] + u[3] * d[2] - P.L2[i] * x[0]);
      // −2u₀ d + 2 (s × u_v) − 2 L² a_v
      row[1] = two * (-u[0] * d[0] + (s[1] * u[3] - s[2] * u[2]) - P.L2[i] * x[1]);
      row[2] = two * (-u[0] * d[1] + (s[2] * u[1] - s[0] * u[3]) - P.L2[i] * x[2]);
      row[3] = two * (-u[0] * d[2] + (s[0] * u[2] - s[1] * u[1]) - P.L2[i] * x[3]);
      for (int k = 0; k < 4; ++k) row[k + 4] = S(4) * u[k];
    }
    if (dF) {
      std::array<C<S>, 3> dd, ds;
      for (int k = 0; k < 3; ++k) {
        dd[k] = dP->q[i][k] - dP->p[i][k];
        ds[k] = dP->q[i][k] + dP->p[i][k];
      }
      const C<S> du0 = -(x[1] * dd[0] + x[2] * dd[1] + x[3] * dd[2]);
      const C<S> du1 = x[0] * dd[0] + (x[2] * ds[2] - x[3] * ds[1]);
      const C<S> du2 = x[0] * dd[1] + (x[3] * ds[0] - x[1] * ds[2]);
      const C<S> du3 = x[0] * dd[2] + (x[1] * ds[1] - x[2] * ds[0]);
      (*dF)[i + 1] = S(2) * (u[0] * du0 + u[1] * du1 + u[2] * du2 + u[3] * du3) - dP->L2[i] * aa;
    }
  }
}

/// The fixed random chart h (h·x = 1) and gammas, from a seeded engine (double → S exactly).
inline std::array<std::complex<double>, 8> chartDouble() {
  std::mt19937_64 g(0x5e3a7b11u);
  std::normal_distribution<double> n;
  std::array<std::complex<double>, 8> h;
  for (auto& z : h) z = {n(g), n(g)};
  return h;
}
template <class S> X<S> chart() {
  const auto hd = chartDouble();
  X<S> h;
  for (int k = 0; k < 8; ++k) h[k] = C<S>(scalarCast<S>(hd[k].real()), scalarCast<S>(hd[k].imag()));
  return h;
}
template <class S> C<S> gammaOf(std::uint64_t seed) {
  std::mt19937_64 g(0x9a3f00u + seed);
  std::uniform_real_distribution<double> u(0.0, 2.0 * 3.14159265358979323846);
  const double th = u(g);
  return C<S>(scalarCast<S>(std::cos(th)), scalarCast<S>(std::sin(th)));
}

/// A homotopy H(x, τ) with the chart row h·x − 1 appended as row 7.
template <class S> struct ParameterHomotopy {
  // P(τ) = P0 + φ(τ) (P1 − P0), φ(τ) = τ / (τ + γ(1 − τ)) (gamma trick: a complex arc from 0
  // to 1 that misses the discriminant of the real segment).
  CP<S> P0, D;
  C<S> gamma;
  X<S> h;
  C<S> phi(const S& t) const { return C<S>(t) / (C<S>(t) + gamma * (S(1) - t)); }
  C<S> dphi(const S& t) const {
    const C<S> den = C<S>(t) + gamma * (S(1) - t);
    return gamma / (den * den);
  }
  CP<S> at(const C<S>& s) const {
    CP<S> P;
    for (int i = 0; i < 6; ++i) {
      for (int k = 0; k < 3; ++k) {
        P.p[i][k] = P0.p[i][k] + s * D.p[i][k];
        P.q[i][k] = P0.q[i][k] + s * D.q[i][k];
      }
      P.L2[i] = P0.L2[i] + s * D.L2[i];
    }
    return P;
  }
  void eval(const X<S>& x, const S& t, X<S>& f, M<S>& J, X<S>* ft) const {
    const C<S> s = t >= S(1) ? C<S>(S(1)) : phi(t);
    const CP<S> P = at(s);
    evalSystem<S>(P, x, f, &J, ft ? &D : nullptr, ft);
    if (ft) {
      const C<S> ds = dphi(t);
      for (int k = 0; k < 7; ++k) (*ft)[k] *= ds;
      (*ft)[7] = C<S>(S(0));
    }
    chartRow(x, f, J);
  }
  void chartRow(const X<S>& x, X<S>& f, M<S>& J) const {
    C<S> v(S(-1));
    for (int k = 0; k < 8; ++k) {
      v += h[k] * x[k];
      J[7][k] = h[k];
    }
    f[7] = v;
  }
};

/// Total-degree homotopy (1 − τ) γ G + τ F with G_j = x_j² − x₇² (j = 0..6).
template <class S> struct TotalDegreeHomotopy {
  CP<S> P;
  C<S> gamma;
  X<S> h;
  void eval(const X<S>& x, const S& t, X<S>& f, M<S>& J, X<S>* ft) const {
    X<S> F;
    M<S> JF;
    evalSystem<S>(P, x, F, &JF, nullptr, nullptr);
    const C<S> a = gamma * (S(1) - t);
    for (int j = 0; j < 7; ++j) {
      const C<S> G = x[j] * x[j] - x[7] * x[7];
      f[j] = a * G + t * F[j];
      for (int k = 0; k < 8; ++k) J[j][k] = t * JF[j][k];
      J[j][j] += a * S(2) * x[j];
      J[j][7] -= a * S(2) * x[7];
      if (ft) (*ft)[j] = F[j] - gamma * G;
    }
    if (ft) (*ft)[7] = C<S>(S(0));
    C<S> v(S(-1));
    for (int k = 0; k < 8; ++k) {
      v += h[k] * x[k];
      J[7][k] = h[k];
    }
    f[7] = v;
  }
};

enum class PathEnd { Finite, Singular, Failed };

struct TrackOptions {
  double hmax = 0.25;
  double hstart = 0.05;
  int maxSteps = 3000;
  bool fine = false;  ///< track to √eps of the scalar (an escalation), not to √eps of double
};

template <class S> struct PathResult {
  X<S> x;
  PathEnd end = PathEnd::Failed;
  S tau = S(0);
  S pivotRatio = S(0);
  int steps = 0;
  int rejects = 0;
};

/// Newton steps on H(·, τ): returns true when the correction fell below tol·max(1, |x|) within
/// maxIt steps, each at most half the previous one.
template <class S, class H>
bool correct(const H& hom, X<S>& x, const S& t, int maxIt, const S& tol, S* pivot = nullptr, S* first = nullptr) {
  S prev = S(0);
  for (int it = 0; it < maxIt; ++it) {
    X<S> f;
    M<S> J;
    hom.eval(x, t, f, J, nullptr);
    const S pr = solve8<S>(J, f);
    if (pivot) *pivot = pr;
    if (!(pr > S(0))) return false;
    for (int k = 0; k < 8; ++k) x[k] -= f[k];
    const S dn = maxNorm<S>(f);
    if (!(dn == dn)) return false;
    if (it == 0 && first) *first = dn;
    const S scale = std::max(S(1), maxNorm<S>(x));
    if (dn <= tol * scale) return true;
    if (it > 0 && dn > prev / S(2)) return false;
    prev = dn;
  }
  return false;
}

/// dx/dτ = −J⁻¹ ∂H/∂τ at (x, τ).
template <class S, class H> bool tangent(const H& hom, const X<S>& x, const S& t, X<S>& v) {
  X<S> f;
  M<S> J;
  hom.eval(x, t, f, J, &v);
  if (!(solve8<S>(J, v) > S(0))) return false;
  for (auto& z : v) z = -z;
  return true;
}

/// Tracks one path from τ = 0 to τ = 1 (RK4 predictor, Newton corrector, adaptive step), then
/// polishes the endpoint by Newton in S.
template <class S, class H> PathResult<S> trackPath(const H& hom, const X<S>& start, const TrackOptions& o) {
  PathResult<S> r;
  r.x = start;
  const S tol = trackEps<S>(o.fine);
  const S hmin = tol;
  S t = S(0), h = scalarCast<S>(o.hstart);
  const S hmax = scalarCast<S>(o.hmax);
  // The predictor's target relative error, eps(double)^¼ ≈ 1.2e-4 in every scalar: the corrector
  // (≤ 3 Newton steps) then reaches tol in any scalar; a finer target only adds steps.
  const S predErr = scalarCast<S>(Tolerance<double>::precision(3));
  bool justRejected = false;
  for (int step = 0; step < o.maxSteps && t < S(1); ++step) {
    r.steps = step + 1;
    if (t + h > S(1)) h = S(1) - t;
    X<S> k1, k2, k3, k4, y;
    bool ok = tangent<S>(hom, r.x, t, k1);
    if (ok) {
      for (int k = 0; k < 8; ++k) y[k] = r.x[k] + (h / S(2)) * k1[k];
      ok = tangent<S>(hom, y, t + h / S(2), k2);
    }
    if (ok) {
      for (int k = 0; k < 8; ++k) y[k] = r.x[k] + (h / S(2)) * k2[k];
      ok = tangent<S>(hom, y, t + h / S(2), k3);
    }
    if (ok) {
      for (int k = 0; k < 8; ++k) y[k] = r.x[k] + h * k3[k];
      ok = tangent<S>(hom, y, t + h, k4);
    }
    if (ok) {
      for (int k = 0; k < 8; ++k) y[k] = r.x[k] + (h / S(6)) * (k1[k] + S(2) * (k2[k] + k3[k]) + k4[k]);
      S first = S(0);
      ok = correct<S>(hom, y, t + h, 3, tol, nullptr, &first);
      if (ok) {
        r.x = y;
        t += h;
        // Step control from the predictor's error (the first Newton correction, ~h⁵ for RK4):
        // aim at predErr, within a factor 2 per step.
        const S rel = first / std::max(S(1), maxNorm<S>(y));
        S f = S(2);
        if (rel > S(0)) {
          using std::pow;
          f = std::min(S(2), std::max(S(1) / S(2), pow(predErr / rel, S(1) / S(5))));
        }
        if (justRejected && f > S(1)) f = S(1);  // no growth right after a rejection
        h = std::min(hmax, h * f);
        justRejected = false;
      }
    }
    if (!ok) {
      ++r.rejects;
      justRejected = true;
      h /= S(2);
      if (h < hmin) break;
    }
  }
  r.tau = t;
  if (t < S(1)) {
    r.end = PathEnd::Failed;
    return r;
  }
  // Polish at τ = 1 to the precision of S: Newton until the correction is at the rounding floor
  // (64 eps, or where it stops decreasing: eps times the condition of the endpoint).
  X<S> y = r.x;
  S piv = S(0), prev = S(0), dn = S(0);
  bool conv = false;
  for (int it = 0; it < 60; ++it) {
    X<S> f;
    M<S> J;
    hom.eval(y, S(1), f, J, nullptr);
    piv = solve8<S>(J, f);
    if (!(piv > S(0))) break;
    X<S> z = y;
    for (int k = 0; k < 8; ++k) z[k] -= f[k];
    dn = maxNorm<S>(f);
    if (!(dn == dn)) break;
    const S scale = std::max(S(1), maxNorm<S>(z));
    if (it > 0 && dn > prev / S(2)) {  // stagnation: the rounding floor (or a multiple root)
      conv = prev <= tol * scale;
      break;
    }
    y = z;
    prev = dn;
    if (dn <= S(64) * Tolerance<S>::epsilon() * scale) {
      conv = true;
      break;
    }
  }
  r.pivotRatio = piv;
  r.x = y;
  r.end = conv && piv > Tolerance<S>::sqrtEpsilon() ? PathEnd::Finite : PathEnd::Singular;
  return r;
}

/// Same point of CP⁷ (both in the chart h·x = 1, where a point has one representative).
template <class S> bool samePoint(const X<S>& x, const X<S>& y, const S& tol) {
  S d = S(0);
  for (int k = 0; k < 8; ++k) d = std::max(d, mod1(x[k] - y[k]));
  return d <= tol * std::max(S(1), std::max(maxNorm<S>(x), maxNorm<S>(y)));
}

/// |z|² (phase-invariant, unlike |re| + |im|).
template <class S> S abs2(const C<S>& z) { return z.real() * z.real() + z.imag() * z.imag(); }

/// The representative whose largest coordinate (by modulus) is 1.
template <class S> X<S> normalizedMax(const X<S>& x) {
  int m = 0;
  for (int k = 1; k < 8; ++k)
    if (abs2(x[k]) > abs2(x[m])) m = k;
  const C<S> inv = C<S>(S(1)) / x[m];
  X<S> y;
  for (int k = 0; k < 8; ++k) y[k] = x[k] * inv;
  return y;
}

/// Distance of two points of CP⁷: both scaled to 1 at the largest coordinate of x.
template <class S> S projectiveDistance(const X<S>& x, const X<S>& y) {
  int m = 0;
  for (int k = 1; k < 8; ++k)
    if (abs2(x[k]) > abs2(x[m])) m = k;
  if (!(abs2(y[m]) > S(0))) return S(1);
  const C<S> ix = C<S>(S(1)) / x[m], iy = C<S>(S(1)) / y[m];
  S d = S(0);
  for (int k = 0; k < 8; ++k) d = std::max(d, mod1(x[k] * ix - y[k] * iy));
  return d;
}

template <class S> CP<S> castPlatform(const CP<double>& P) {
  CP<S> Q;
  auto cc = [](const std::complex<double>& z) { return C<S>(scalarCast<S>(z.real()), scalarCast<S>(z.imag())); };
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) {
      Q.p[i][k] = cc(P.p[i][k]);
      Q.q[i][k] = cc(P.q[i][k]);
    }
    Q.L2[i] = cc(P.L2[i]);
  }
  return Q;
}

inline CP<double> startPlatformDouble() {
  std::mt19937_64 g(20261130u);
  std::normal_distribution<double> n;
  CP<double> P;
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) P.p[i][k] = {n(g), n(g)};
    for (int k = 0; k < 3; ++k) P.q[i][k] = {n(g), n(g)};
    P.L2[i] = {n(g), n(g)};
  }
  return P;
}

/// Real Newton polish of a real solution x (Study + six legs + the chart x·x₀ = x₀·x₀) on the
/// real platform P (centred, scaled). Returns false when it does not converge.
template <class S> bool realPolish(const CP<S>& P, Vec8<S>& xr) {
  X<S> x0;
  for (int k = 0; k < 8; ++k) x0[k] = C<S>(xr(k));
  const Vec8<S> ref = xr;
  S prev = S(0);
  for (int it = 0; it < 60; ++it) {
    X<S> x, f;
    M<S> J;
    for (int k = 0; k < 8; ++k) x[k] = C<S>(xr(k));
    evalSystem<S>(P, x, f, &J, nullptr, nullptr);
    f[7] = C<S>(xr.dot(ref) - ref.dot(ref));
    for (int k = 0; k < 8; ++k) J[7][k] = C<S>(ref(k));
    if (!(solve8<S>(J, f) > S(0))) return false;
    S dn = S(0);
    for (int k = 0; k < 8; ++k) {
      xr(k) -= f[k].real();
      using std::abs;
      dn = std::max(dn, abs(f[k].real()));
    }
    if (!(dn == dn)) return false;
    if (dn <= S(64) * Tolerance<S>::epsilon() * xr.template lpNorm<Eigen::Infinity>()) return true;
    if (it > 2 && dn > prev / S(2)) return dn <= Tolerance<S>::sqrtEpsilon() * xr.template lpNorm<Eigen::Infinity>();
    prev = dn;
  }
  return false;
}

}  // namespace stewart_detail

template <class S> void validateStewartPlatform(const StewartPlatform<S>& P) {
  auto finite = [](const S& v) { return isFinite(v); };  // in S: 1e400 is finite in long double
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!finite(P.base[i](k))) throw InvalidInput("stewart: base point " + std::to_string(i + 1) + " is not finite");
      if (!finite(P.platform[i](k)))
        throw InvalidInput("stewart: platform point " + std::to_string(i + 1) + " is not finite");
    }
    if (!finite(P.legs[i])) throw InvalidInput("stewart: leg length " + std::to_string(i + 1) + " is not finite");
    if (P.legs[i] < S(0)) throw InvalidInput("stewart: leg length " + std::to_string(i + 1) + " is negative");
  }
  // Spreads and lengths as norms, not squares (safeNorm): a platform of size 1e200 is the
  // platform of size 1, not one whose squared spreads overflow to infinity.
  using std::abs;
  S sb = S(0), sp = S(0), sl = S(0);
  for (int i = 0; i < 6; ++i) {
    sb = std::max(sb, safeNorm(Vec3<S>(P.base[i] - P.base[0])));
    sp = std::max(sp, safeNorm(Vec3<S>(P.platform[i] - P.platform[0])));
    sl = std::max(sl, abs(P.legs[i]));
  }
  if (!isFinite(sb)) throw InvalidInput("stewart: the base points lie farther apart than " + std::string(scalarName<S>()) + " holds");
  if (!isFinite(sp))
    throw InvalidInput("stewart: the platform points lie farther apart than " + std::string(scalarName<S>()) + " holds");
  const S big = std::max(sb, std::max(sp, sl));
  const S eps = Tolerance<S>::epsilon();
  auto spread = [&](const S& s) {
    return " (they lie within " + toString(s, 3) + " of each other, at the rounding level of the platform's size " +
           toString(big, 3) + ")";
  };
  if (!(sb > eps * big)) throw InvalidInput("stewart: the six base points coincide" + spread(sb));
  if (!(sp > eps * big)) throw InvalidInput("stewart: the six platform points coincide" + spread(sp));
}

template <class S> std::array<S, 6> stewartLegLengths(const StewartPlatform<S>& P, const SE3<S>& g) {
  std::array<S, 6> L;
  for (int i = 0; i < 6; ++i) L[i] = safeNorm(Vec3<S>(g.act(P.platform[i]) - P.base[i]));
  return L;
}

template <class S> S stewartScale(const StewartPlatform<S>& P) {
  Vec3<S> pb = Vec3<S>::Zero(), qb = Vec3<S>::Zero();
  for (int i = 0; i < 6; ++i) {
    pb += P.base[i];
    qb += P.platform[i];
  }
  pb /= S(6);
  qb /= S(6);
  using std::abs;
  S s = S(0);
  for (int i = 0; i < 6; ++i) {
    s = std::max(s, safeNorm(Vec3<S>(P.base[i] - pb)));
    s = std::max(s, safeNorm(Vec3<S>(P.platform[i] - qb)));
    s = std::max(s, abs(P.legs[i]));
  }
  return s;
}

template <class S> S stewartResidual(const StewartPlatform<S>& P, const SE3<S>& g) {
  const auto L = stewartLegLengths<S>(P, g);
  S r = S(0);
  using std::abs;
  for (int i = 0; i < 6; ++i) r = std::max(r, abs(L[i] - P.legs[i]));
  return r / stewartScale<S>(P);
}

template <class S>
std::array<std::complex<S>, 7> stewartSystem(const StewartComplexPlatform<S>& P, const StudyPointC<S>& x) {
  stewart_detail::X<S> f;
  stewart_detail::evalSystem<S>(P, x, f, nullptr, nullptr, nullptr);
  std::array<std::complex<S>, 7> r;
  for (int k = 0; k < 7; ++k) r[k] = f[k];
  return r;
}

template <class S> StewartComplexPlatform<S> stewartComplexPlatform(const StewartPlatform<S>& P) {
  StewartComplexPlatform<S> Q;
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) {
      Q.p[i][k] = std::complex<S>(P.base[i](k));
      Q.q[i][k] = std::complex<S>(P.platform[i](k));
    }
    Q.L2[i] = std::complex<S>(P.legs[i] * P.legs[i]);
  }
  return Q;
}

template <class S> StewartComplexPlatform<S> stewartStartPlatform() {
  return stewart_detail::castPlatform<S>(stewart_detail::startPlatformDouble());
}

/// Total-degree solve in S (the body of stewartTotalDegreeSolve, which is instantiated for
/// double only: the start solutions are computed once in double and polished in S).
template <class S>
std::vector<StudyPointC<S>> totalDegreeSolve(const StewartComplexPlatform<S>& P, std::uint64_t seed) {
  using namespace stewart_detail;
  const X<S> h = chart<S>();
  std::vector<X<S>> found;
  int lastCount = -1, agreeing = 0;
  for (std::uint64_t run = 0; run < 6 && agreeing < 2; ++run) {
    TotalDegreeHomotopy<S> hom{P, gammaOf<S>(seed * 101 + run), h};
    int runCount = 0;
    std::vector<X<S>> runFound;
    for (int m = 0; m < 128; ++m) {
      X<S> v;
      for (int j = 0; j < 7; ++j) v[j] = C<S>((m >> j) & 1 ? S(-1) : S(1));
      v[7] = C<S>(S(1));
      C<S> hv(S(0));
      for (int k = 0; k < 8; ++k) hv += h[k] * v[k];
      const C<S> inv = C<S>(S(1)) / hv;
      for (auto& z : v) z *= inv;
      TrackOptions o;
      o.hmax = 0.05;
      const PathResult<S> r = trackPath<S>(hom, v, o);
      if (r.end != PathEnd::Finite) continue;
      if (maxNormA<S>(r.x) <= Tolerance<S>::sqrtEpsilon() * maxNorm<S>(r.x)) continue;  // at infinity
      bool dup = false;
      for (const auto& y : runFound) dup = dup || samePoint<S>(y, r.x, Tolerance<S>::input());
      if (!dup) runFound.push_back(r.x), ++runCount;
    }
    for (const auto& x : runFound) {
      bool dup = false;
      for (const auto& y : found) dup = dup || samePoint<S>(y, x, Tolerance<S>::input());
      if (!dup) found.push_back(x);
    }
    if (runCount == static_cast<int>(found.size()) && runCount == lastCount) ++agreeing;
    else agreeing = runCount == static_cast<int>(found.size()) ? 1 : 0;
    lastCount = runCount;
  }
  return found;
}

template <class S> const std::vector<StudyPointC<S>>& stewartStartSolutions() {
  using namespace stewart_detail;
  static std::mutex mu;
  static std::map<int, std::vector<X<S>>> cache;  // keyed by mpfr bits (0 for the others)
  std::lock_guard<std::mutex> lock(mu);
  int key = 0;
  if constexpr (std::is_same_v<S, mpfr::mpreal>) key = mpfrBits();
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  std::vector<X<S>> sols;
  if constexpr (std::is_same_v<S, double>) {
    sols = stewartTotalDegreeSolve(stewartStartPlatform<double>(), 1);
  } else {
    const auto& d = stewartStartSolutions<double>();
    ParameterHomotopy<S> hom;
    hom.P0 = stewartStartPlatform<S>();
    hom.D = hom.P0;
    for (int i = 0; i < 6; ++i) {
      for (int k = 0; k < 3; ++k) hom.D.p[i][k] = hom.D.q[i][k] = C<S>(S(0));
      hom.D.L2[i] = C<S>(S(0));
    }
    hom.gamma = C<S>(S(1));
    hom.h = chart<S>();
    for (const auto& xd : d) {
      X<S> x;
      for (int k = 0; k < 8; ++k) x[k] = C<S>(scalarCast<S>(xd[k].real()), scalarCast<S>(xd[k].imag()));
      correct<S>(hom, x, S(1), 60, S(64) * Tolerance<S>::epsilon());
      sols.push_back(x);
    }
  }
  if (sols.size() != 40)
    throw std::logic_error("stewart: the start platform gave " + std::to_string(sols.size()) +
                           " finite solutions instead of 40");
  return cache.emplace(key, std::move(sols)).first->second;
}

template <class S>
bool containsConjugate(const std::vector<StudyPointC<S>>& set, const StudyPointC<S>& x, const S& tol) {
  using namespace stewart_detail;
  X<S> xc;
  for (int k = 0; k < 8; ++k) xc[k] = std::conj(x[k]);
  for (const auto& y : set)
    if (projectiveDistance<S>(xc, y) <= tol) return true;
  return false;
}

namespace stewart_detail {

template <class S> std::string sci(const S& v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", toDouble(v));
  return buf;
}

/// The parameter homotopy from the start platform to the (centred, scaled) real platform Pn.
/// The fast tracker (stewart_fast_tracker.hpp) on the general tracker's homotopy hom (γ of attempt
/// 0): true with the 40 endpoints in `ends` when every path reached a finite nonsingular endpoint
/// and the 40 are distinct (within dupTol); otherwise false and a note saying what was wrong.
inline bool fastTrack(const ParameterHomotopy<double>& hom, const std::vector<X<double>>& starts,
                      std::vector<X<double>>& ends, std::string& why, int& steps) {
  namespace F = stewart_fast;
  F::Homotopy H;
  for (int i = 0; i < 6; ++i) {
    auto& g = H.leg[i];
    for (int k = 0; k < 3; ++k) {
      g.d0[k] = F::cx(hom.P0.q[i][k] - hom.P0.p[i][k]);
      g.s0[k] = F::cx(hom.P0.q[i][k] + hom.P0.p[i][k]);
      g.dd[k] = F::cx(hom.D.q[i][k] - hom.D.p[i][k]);
      g.ds[k] = F::cx(hom.D.q[i][k] + hom.D.p[i][k]);
    }
    g.l0 = F::cx(hom.P0.L2[i]);
    g.dl = F::cx(hom.D.L2[i]);
  }
  H.gamma = F::cx(hom.gamma);
  for (int k = 0; k < 8; ++k) H.h[k] = F::cx(hom.h[k]);
  const F::Settings o;
  int failed = 0, infinite = 0, coincide = 0;
  ends.clear();
  std::vector<F::V8> x0(starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i)
    for (int k = 0; k < 8; ++k) x0[i][k] = F::cx(starts[i][k]);
  std::vector<F::Path> paths;
  F::trackAll(H, x0, o, paths);
  for (const F::Path& r : paths) {
    steps += r.steps;
    X<double> x;
    for (int k = 0; k < 8; ++k) x[k] = {r.x[k].re, r.x[k].im};
    if (!r.finite) {
      ++failed;
      continue;
    }
    if (maxNormA<double>(x) <= Tolerance<double>::sqrtEpsilon() * maxNorm<double>(x)) {
      ++infinite;
      continue;
    }
    bool dup = false;
    for (const auto& y : ends) dup = dup || samePoint<double>(y, x, Tolerance<double>::input());
    if (dup) {
      ++coincide;
      continue;
    }
    ends.push_back(x);
  }
  if (failed + infinite + coincide == 0) return true;
  why = "fast double tracker: " + std::to_string(failed) + " paths failed or ended singular, " +
        std::to_string(infinite) + " at infinity, " + std::to_string(coincide) +
        " endpoints coincided with another; re-solved by the general tracker";
  return false;
}

template <class S>
StewartForwardSolution<S> forwardCore(const StewartPlatform<S>& user, bool fine, int expected, bool fast = false) {
  StewartForwardSolution<S> out;
  // Centre and scale: p' = (p − p̄)/σ, q' = (q − q̄)/σ, L' = L/σ.
  Vec3<S> pb = Vec3<S>::Zero(), qb = Vec3<S>::Zero();
  for (int i = 0; i < 6; ++i) {
    pb += user.base[i];
    qb += user.platform[i];
  }
  pb /= S(6);
  qb /= S(6);
  const S sigma = stewartScale<S>(user);
  StewartPlatform<S> Pn;
  for (int i = 0; i < 6; ++i) {
    Pn.base[i] = (user.base[i] - pb) / sigma;
    Pn.platform[i] = (user.platform[i] - qb) / sigma;
    Pn.legs[i] = user.legs[i] / sigma;
  }
  const CP<S> P1 = stewartComplexPlatform<S>(Pn);
  const auto& starts = stewartStartSolutions<S>();
  ParameterHomotopy<S> hom;
  hom.P0 = stewartStartPlatform<S>();
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) {
      hom.D.p[i][k] = P1.p[i][k] - hom.P0.p[i][k];
      hom.D.q[i][k] = P1.q[i][k] - hom.P0.q[i][k];
    }
    hom.D.L2[i] = P1.L2[i] - hom.P0.L2[i];
  }
  hom.h = chart<S>();
  const S dupTol = Tolerance<S>::input();
  using std::sqrt;

  std::vector<X<S>> finite;
  int atInfinity = 0, singular = 0, failed = 0;
  std::vector<int> todo(starts.size());
  for (std::size_t k = 0; k < starts.size(); ++k) todo[k] = static_cast<int>(k);
  if constexpr (std::is_same_v<S, double>) {
    // The fast tracker first (double, general 6-6; solveStewartForward decides): the general
    // tracker's loop below runs only when it is in doubt.
    if (fast && !fine) {
      hom.gamma = gammaOf<S>(1);
      std::string why;
      out.paths_tracked += static_cast<int>(starts.size());
      if (fastTrack(hom, starts, finite, why, out.steps)) {
        todo.clear();
        out.tracker = "fast";
      } else {
        finite.clear();
        out.notes.push_back(why);
      }
    }
  }
  // attempt 0: γ₁, hmax 0.1; 1: same γ, hmax 0.0125 on the failed and colliding paths;
  // 2: another γ, hmax 0.0125, every path not yet accounted for.
  const double hmaxes[3] = {0.25, 0.03, 0.03};
  const std::uint64_t gseeds[3] = {1, 1, 2};
  std::vector<int> finiteFrom;  // start index of each finite solution
  std::vector<X<S>> singularEnds;  // endpoints at singular points (the last attempt's)
  std::vector<int> failedPaths;     // the last attempt's failed paths
  int lastAttempt = 0;
  for (int attempt = 0; attempt < 3 && !todo.empty(); ++attempt) {
    hom.gamma = gammaOf<S>(gseeds[attempt]);
    lastAttempt = attempt;
    failedPaths.clear();
    if (attempt == 2) {
      // With a new gamma the start ↔ end correspondence changes: track every path again and
      // keep whatever is new.
      todo.clear();
      for (std::size_t k = 0; k < starts.size(); ++k) todo.push_back(static_cast<int>(k));
    }
    TrackOptions o;
    o.fine = fine;
    o.hmax = hmaxes[attempt];
    o.hstart = std::min(o.hstart, o.hmax);
    std::vector<int> again;
    atInfinity = singular = failed = 0;
    if (attempt != 1) singularEnds.clear();  // attempts 0 and 2 track every path
    for (int k : todo) {
      ++out.paths_tracked;
      const PathResult<S> r = trackPath<S>(hom, starts[k], o);
      out.steps += r.steps;
      const bool infinite = maxNormA<S>(r.x) <= Tolerance<S>::sqrtEpsilon() * maxNorm<S>(r.x);
      if (r.end == PathEnd::Finite && !infinite) {
        bool dup = false;
        for (const auto& y : finite) dup = dup || samePoint<S>(y, r.x, dupTol);
        if (!dup) {
          finite.push_back(r.x);
          finiteFrom.push_back(k);
        } else if (r.pivotRatio <= Tolerance<S>::input()) {
          ++singular;  // two paths met at a nearly singular point: a multiple root (resolved below)
          singularEnds.push_back(r.x);
        } else if (attempt < 2) {
          again.push_back(k);  // two paths met at a nonsingular point: path jumping
        }
      } else if (infinite) {
        ++atInfinity;
      } else if (r.end == PathEnd::Singular || r.tau >= S(1) - sqrt(trackEps<S>())) {
        // The step collapsed just before τ = 1 (or Newton does not converge quadratically at
        // τ = 1): the endpoint is a singular solution of a degenerate platform; a smaller step
        // or another gamma ends there again.
        if (maxNormA<S>(r.x) <= sqrt(trackEps<S>()) * maxNorm<S>(r.x)) {
          ++atInfinity;
        } else {
          ++singular;
          singularEnds.push_back(r.x);
        }
      } else {
        ++failed;
        failedPaths.push_back(k);
        again.push_back(k);
      }
    }
    if (attempt == 0 && !again.empty())
      out.notes.push_back(std::to_string(again.size()) + " of 40 paths failed or collided; re-tracked with an 8× smaller step");
    if (attempt == 1 && !again.empty() && finite.size() < 40)
      out.notes.push_back(std::to_string(again.size()) + " paths still short; every path re-tracked with another gamma");
    todo = again;
    if (finite.size() >= 40) break;
  }
  // Float: a path whose corrector meets float's rounding floor mid-way (an ill-conditioned stretch,
  // e.g. the paths of a 6-3 platform that go to its singular points: Newton stalls at eps·cond above
  // the tracking tolerance √eps(float) and the step collapses, whatever the smallest step) is
  // re-tracked in double — the same start, γ and target — and its endpoint brought back to float
  // (Newton-polished there); counted in paths_escalated and said in a note.
  if constexpr (std::is_same_v<S, float>) {
    if (!failedPaths.empty()) {
      ParameterHomotopy<double> hd;
      hd.P0 = stewartStartPlatform<double>();
      const CP<double> P1d = stewartComplexPlatform<double>(Pn.template cast<double>());
      for (int i = 0; i < 6; ++i) {
        for (int k = 0; k < 3; ++k) {
          hd.D.p[i][k] = P1d.p[i][k] - hd.P0.p[i][k];
          hd.D.q[i][k] = P1d.q[i][k] - hd.P0.q[i][k];
        }
        hd.D.L2[i] = P1d.L2[i] - hd.P0.L2[i];
      }
      hd.h = chart<double>();
      hd.gamma = gammaOf<double>(gseeds[lastAttempt]);
      TrackOptions od;
      od.hmax = hmaxes[lastAttempt];
      od.hstart = std::min(od.hstart, od.hmax);
      const auto& startsD = stewartStartSolutions<double>();
      int nFinite = 0, nSingular = 0, nInfinite = 0, nFailed = 0;
      for (int k : failedPaths) {
        ++out.paths_tracked;
        ++out.paths_escalated;
        const PathResult<double> r = trackPath<double>(hd, startsD[static_cast<std::size_t>(k)], od);
        X<S> x;
        for (int j = 0; j < 8; ++j) x[j] = C<S>(static_cast<S>(r.x[j].real()), static_cast<S>(r.x[j].imag()));
        const bool infinite = maxNormA<double>(r.x) <= Tolerance<double>::sqrtEpsilon() * maxNorm<double>(r.x);
        if (r.end == PathEnd::Finite && !infinite) {
          correct<S>(hom, x, S(1), 8, S(64) * Tolerance<S>::epsilon());
          bool dup = false;
          for (const auto& y : finite) dup = dup || samePoint<S>(y, x, dupTol);
          if (!dup) finite.push_back(x), ++nFinite;
          else ++nSingular, ++singular, singularEnds.push_back(x);
        } else if (infinite) {
          ++nInfinite, ++atInfinity;
        } else if (r.end == PathEnd::Singular || r.tau >= 1.0 - std::sqrt(trackEps<double>())) {
          if (maxNormA<double>(r.x) <= std::sqrt(trackEps<double>()) * maxNorm<double>(r.x)) {
            ++nInfinite, ++atInfinity;
          } else {
            ++nSingular, ++singular;
            singularEnds.push_back(x);
          }
        } else {
          ++nFailed;
          continue;
        }
        --failed;
      }
      out.notes.push_back(std::to_string(failedPaths.size()) +
                          " paths failed in float (Newton at float's rounding floor on an ill-conditioned stretch); "
                          "re-tracked in double: " + std::to_string(nFinite) + " finite, " + std::to_string(nSingular) +
                          " singular, " + std::to_string(nInfinite) + " at infinity, " + std::to_string(nFailed) +
                          " still failed");
    }
  }
  // Multiple roots: short of the class's count, with singular endpoints that gather at a few points
  // (each within Tolerance::input() of the first of its cluster). When the clusters' sizes make up
  // exactly the missing count, each is one root of that multiplicity — two paths ending together at
  // a double root: a posture on the boundary of the assembly space, where two real postures merge.
  // Otherwise (a degenerate class's surplus paths) they stay singular endpoints.
  std::vector<int> mult(finite.size(), 1);
  if (expected > 0 && static_cast<int>(finite.size()) < expected && !singularEnds.empty() &&
      static_cast<int>(finite.size() + singularEnds.size()) == expected) {
    const std::size_t nFinite = finite.size();
    // A path stopped short of τ = 1 lies ~√(1 − τ) from a double root: Newton at τ = 1 closes that
    // (linearly, halving the error per step, down to ~√eps at a double root).
    for (auto& x : singularEnds) {
      S prev = S(0);
      for (int it = 0; it < 100; ++it) {
        X<S> f;
        M<S> J;
        hom.eval(x, S(1), f, J, nullptr);
        if (!(solve8<S>(J, f) > S(0))) break;
        const S dn = maxNorm<S>(f);
        if (!(dn == dn) || (it > 0 && dn > S(0.9) * prev)) break;
        for (int k = 0; k < 8; ++k) x[k] -= f[k];
        prev = dn;
        if (dn <= S(64) * Tolerance<S>::epsilon() * std::max(S(1), maxNorm<S>(x))) break;
      }
    }
    std::vector<X<S>> reps;
    std::vector<int> sizes, joins(nFinite, 0);
    const auto near = [](const X<S>& x, const X<S>& y) {
      return projectiveDistance<S>(normalizedMax<S>(x), normalizedMax<S>(y)) <= Tolerance<S>::input();
    };
    for (const auto& x : singularEnds) {
      bool joined = false;
      for (std::size_t k = 0; k < nFinite && !joined; ++k)
        if (near(finite[k], x)) ++joins[k], joined = true;
      for (std::size_t k = 0; k < reps.size() && !joined; ++k)
        if (near(reps[k], x)) ++sizes[k], joined = true;
      if (!joined) reps.push_back(x), sizes.push_back(1);
    }
    bool allMultiple = true;
    for (int m : sizes) allMultiple = allMultiple && m >= 2;
    if (allMultiple) {
      const auto say = [&](int m) {
        out.notes.push_back(std::to_string(m) + " paths end together at one singular point: a root of multiplicity " +
                            std::to_string(m) + " (postures merged: the boundary of the assembly space)");
      };
      for (std::size_t k = 0; k < nFinite; ++k)
        if (joins[k] > 0) mult[k] += joins[k], say(mult[k]);
      for (std::size_t k = 0; k < reps.size(); ++k) {
        finite.push_back(reps[k]);
        mult.push_back(sizes[k]);
        say(sizes[k]);
      }
      singular = 0;
    }
  }
  out.paths_failed = failed;
  out.paths_at_infinity = atInfinity;
  out.paths_singular = singular;
  if (atInfinity > 0)
    out.notes.push_back(std::to_string(atInfinity) + " paths ended on the exceptional plane a = 0 (a degenerate platform)");
  if (singular > 0)
    out.notes.push_back(std::to_string(singular) + " paths ended at singular (multiple) solutions");

  // Real solutions: the representative with largest coordinate 1 is real to √eps.
  std::vector<std::tuple<SE3<S>, S, int>> real;
  for (std::size_t f = 0; f < finite.size(); ++f) {
    const X<S>& x = finite[f];
    const X<S> xn = normalizedMax<S>(x);
    out.complex_solutions.push_back(xn);
    out.multiplicity.push_back(mult[f]);
    S im = S(0);
    for (const auto& z : xn) {
      using std::abs;
      im = std::max(im, abs(z.imag()));
    }
    if (im > Tolerance<S>::input()) continue;
    ++out.real_count;
    Vec8<S> xr;
    for (int k = 0; k < 8; ++k) xr(k) = xn[k].real();
    // A multiple root converges only linearly: its real Newton polish stops at √eps.
    if (!realPolish<S>(P1, xr) && mult[f] == 1) {
      out.notes.push_back("a real solution did not converge under the real Newton polish (kept unpolished)");
    }
    try {
      const SE3<S> gn = StudyParameters<S>(xr).toSE3();
      // back to the user's frame: t = σ t' + p̄ − R q̄
      const Mat3<S> R = gn.rotation();
      const Vec3<S> t = sigma * gn.translation() + pb - R * qb;
      const SE3<S> g(gn.so3(), t);
      real.emplace_back(g, stewartResidual<S>(user, g), mult[f]);
    } catch (const InvalidInput& e) {
      out.notes.push_back(std::string("a real solution is not a rigid motion: ") + e.what());
    }
  }
  std::sort(real.begin(), real.end(), [](const auto& A, const auto& B) {
    return std::get<0>(A).translation()(2) > std::get<0>(B).translation()(2);
  });
  for (const auto& [g, r, m] : real) {
    out.postures.push_back(g);
    out.residuals.push_back(r);
    out.posture_multiplicity.push_back(m);
  }
  return out;
}

}  // namespace stewart_detail

namespace stewart_detail {
/// Quaternion product of complex quaternions (w, x, y, z), bilinear: no complex conjugation.
template <class S>
std::array<std::complex<S>, 4> quatMul(const std::array<std::complex<S>, 4>& u, const std::array<std::complex<S>, 4>& v) {
  return {u[0] * v[0] - u[1] * v[1] - u[2] * v[2] - u[3] * v[3], u[0] * v[1] + u[1] * v[0] + u[2] * v[3] - u[3] * v[2],
          u[0] * v[2] + u[2] * v[0] + u[3] * v[1] - u[1] * v[3], u[0] * v[3] + u[3] * v[0] + u[1] * v[2] - u[2] * v[1]};
}
}  // namespace stewart_detail

template <class S> StewartComplexPosture<S> stewartComplexPosture(const StewartPlatform<S>& P, const StudyPointC<S>& x) {
  using C = std::complex<S>;
  // The solve's frame: p' = (p − p̄)/σ, q' = (q − q̄)/σ (forwardCore).
  Vec3<S> pb = Vec3<S>::Zero(), qb = Vec3<S>::Zero();
  for (int i = 0; i < 6; ++i) {
    pb += P.base[i];
    qb += P.platform[i];
  }
  pb /= S(6);
  qb /= S(6);
  const S sigma = stewartScale<S>(P);
  using Q = std::array<C, 4>;
  const auto mul = stewart_detail::quatMul<S>;
  Q a{x[0], x[1], x[2], x[3]}, c{x[4], x[5], x[6], x[7]};
  using std::sqrt;
  C s = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3]);
  int m = 0;
  for (int k = 1; k < 4; ++k)
    if (std::norm(a[k]) > std::norm(a[m])) m = k;
  if ((a[m] / s).real() < S(0)) s = -s;
  for (int k = 0; k < 4; ++k) a[k] /= s, c[k] /= s;
  const Q abar{a[0], -a[1], -a[2], -a[3]};
  // t' = 2 c ā (its scalar part 2 a·c vanishes on the Study quadric); R q̄ = a q̄ ā.
  const Q tn = mul(c, abar);
  const Q rq = mul(mul(a, Q{C(S(0)), C(qb(0)), C(qb(1)), C(qb(2))}), abar);
  StewartComplexPosture<S> g;
  g.rotation = a;
  for (int k = 0; k < 3; ++k) g.translation[k] = sigma * S(2) * tn[k + 1] + pb(k) - rq[k + 1];
  const Q cu = mul(Q{C(S(0)), g.translation[0], g.translation[1], g.translation[2]}, a);
  for (int k = 0; k < 4; ++k) {
    g.study[k] = a[k];
    g.study[k + 4] = cu[k] / S(2);
  }
  S im = S(0);
  for (const auto& z : g.study) {
    using std::abs;
    im = std::max(im, abs(z.imag()));
  }
  g.real = im <= Tolerance<S>::input() * std::max(S(1), stewart_detail::maxNorm<S>(g.study));
  return g;
}

template <class S> S stewartComplexResidual(const StewartPlatform<S>& P, const StewartComplexPosture<S>& g) {
  using C = std::complex<S>;
  using Q = std::array<C, 4>;
  const auto mul = stewart_detail::quatMul<S>;
  const Q& a = g.rotation;
  const Q abar{a[0], -a[1], -a[2], -a[3]};
  const S size = stewartScale<S>(P);
  S worst = S(0);
  for (int i = 0; i < 6; ++i) {
    const Q rq = mul(mul(a, Q{C(S(0)), C(P.platform[i](0)), C(P.platform[i](1)), C(P.platform[i](2))}), abar);
    C d2(S(0));  // in units of the platform's size (no overflow at 1e200)
    S mag = S(0);
    for (int k = 0; k < 3; ++k) {
      const C e = (rq[k + 1] + g.translation[k] - P.base[i](k)) / size;
      d2 += e * e;
      mag += std::norm(e);
    }
    using std::abs;
    const S l = P.legs[i] / size;
    // Relative to the terms' size: a complex posture far out (|t| ≫ size) carries eps·|t|² of rounding.
    worst = std::max(worst, abs(d2 - l * l) / std::max(mag, l * l));
  }
  return worst;
}

template <class S> StewartForwardSolution<S> solveStewartForward(const StewartPlatform<S>& P, StewartTracking tracking) {
  const bool fineTracking = tracking == StewartTracking::Fine;
  validateStewartPlatform<S>(P);
  // The class decides the expected count (stewart_class.hpp); an architecturally singular platform
  // is refused with the defect named.
  const StewartClassification cls = classifyStewart<S>(P);
  if (!cls.singular_reason.empty())
    throw InvalidInput("stewart: architecturally singular platform: " + cls.singular_reason);
  const int expected = cls.expected_count.value_or(0);
  const auto t0 = std::chrono::steady_clock::now();
  // The fast tracker: double (it exists for speed; the other scalars keep the general tracker) on a
  // general 6-6 platform (six distinct joints on each side, 40 postures).
  const bool fast = std::is_same_v<S, double> && tracking == StewartTracking::Auto && expected == 40 &&
                    cls.base_distinct == 6 && cls.platform_distinct == 6 && !cls.similar && !cls.threefold;
  StewartForwardSolution<S> out = stewart_detail::forwardCore<S>(P, fineTracking, expected, fast);
  out.expected_count = expected;
  out.platform_class = cls.name;
  out.pattern = cls.pattern;
  if (expected == 0)
    out.notes.push_back("a " + cls.name + " platform (pattern " + cls.pattern + (cls.similar ? ", similar base and platform" : "") +
                        "): no tabulated count for its class, so the count is not certified");
  else if (expected < 40)
    out.notes.push_back("a " + cls.name + " platform (pattern " + cls.pattern + "): " + std::to_string(expected) +
                        " postures for its class (stewart_class.hpp); the other paths of the 40 end at singular points or at infinity");
  const int found = out.complexCount();
  // Short with failed paths, or short by a few (two solutions close together, a platform near a
  // singular configuration): re-solve in a wider scalar and say so — float in double (which itself
  // goes on to float128 if still short), double and long double in float128 with fine tracking
  // (10⁹ times tighter).
  const auto escalate = [&]<class W>(bool fine, int paths) {
    const StewartPlatform<W> Q = P.template cast<W>();
    const auto hi = solveStewartForward<W>(Q, fine ? StewartTracking::Fine : StewartTracking::Auto);
    if (hi.complexCount() <= found) return;
    StewartForwardSolution<S> esc;
    esc.notes = out.notes;
    esc.notes.push_back("found " + std::to_string(found) + " of " + std::to_string(expected) + " in " +
                        std::string(scalarName<S>()) + " (" + std::to_string(out.paths_failed) + " paths failed, " +
                        std::to_string(out.paths_singular) + " singular); re-solved in " + std::string(scalarName<W>()) +
                        (fine ? " (paths tracked to 1e-17)" : "") + ": " + std::to_string(hi.complexCount()));
    for (const auto& n : hi.notes) esc.notes.push_back(std::string(scalarName<W>()) + ": " + n);
    for (const auto& x : hi.complex_solutions) {
      StudyPointC<S> y;
      for (int k = 0; k < 8; ++k) y[k] = std::complex<S>(scalarCast<S>(x[k].real()), scalarCast<S>(x[k].imag()));
      esc.complex_solutions.push_back(y);
    }
    esc.multiplicity = hi.multiplicity;
    for (std::size_t k = 0; k < hi.postures.size(); ++k) {
      const SE3<S> g = hi.postures[k].template cast<S>();
      esc.postures.push_back(g);
      esc.residuals.push_back(stewartResidual<S>(P, g));
    }
    esc.posture_multiplicity = hi.posture_multiplicity;
    esc.real_count = hi.real_count;
    esc.expected_count = out.expected_count;
    esc.platform_class = out.platform_class;
    esc.pattern = out.pattern;
    esc.paths_tracked = out.paths_tracked + hi.paths_tracked;
    esc.paths_failed = hi.paths_failed;
    esc.paths_at_infinity = hi.paths_at_infinity;
    esc.paths_singular = hi.paths_singular;
    esc.paths_escalated = out.paths_escalated + paths;
    esc.tracker = hi.tracker;
    out = esc;
  };
  if (expected > 0 && found < expected && (out.paths_failed > 0 || expected - found <= 8)) {
    const int paths = out.paths_failed + out.paths_singular;
    if constexpr (std::is_same_v<S, float>)
      escalate.template operator()<double>(false, paths);
    else if constexpr (std::is_same_v<S, double> || std::is_same_v<S, long double>)
      escalate.template operator()<__float128>(true, paths);
  }
  if (expected > 0 && out.complexCount() < expected)
    out.notes.push_back("SHORT: " + std::to_string(out.complexCount()) + " of " + std::to_string(expected) +
                        " complex solutions found (" + std::to_string(out.paths_failed) + " paths failed, " +
                        std::to_string(out.paths_singular) + " singular, " + std::to_string(out.paths_at_infinity) +
                        " at infinity)");
  if (expected > 0 && out.complexCount() > expected)
    out.notes.push_back("MORE: " + std::to_string(out.complexCount()) + " complex solutions found, " +
                        std::to_string(expected) + " expected for the class " + cls.name);
  if (out.postures.empty())
    out.notes.push_back("no real posture: all " + std::to_string(out.complexCount()) +
                        " solutions are complex (these leg lengths cannot be assembled)");
  for (std::size_t k = 0; k < out.complex_solutions.size(); ++k) {
    StewartComplexPosture<S> g = stewartComplexPosture<S>(P, out.complex_solutions[k]);
    g.multiplicity = k < out.multiplicity.size() ? out.multiplicity[k] : 1;
    out.complex_postures.push_back(g);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

#define SOMA_INSTANTIATE_STEWART(S)                                                                       \
  template void validateStewartPlatform<S>(const StewartPlatform<S>&);                                    \
  template std::array<S, 6> stewartLegLengths<S>(const StewartPlatform<S>&, const SE3<S>&);               \
  template S stewartScale<S>(const StewartPlatform<S>&);                                                  \
  template S stewartResidual<S>(const StewartPlatform<S>&, const SE3<S>&);                                \
  template std::array<std::complex<S>, 7> stewartSystem<S>(const StewartComplexPlatform<S>&,              \
                                                           const StudyPointC<S>&);                        \
  template StewartComplexPlatform<S> stewartComplexPlatform<S>(const StewartPlatform<S>&);                \
  template StewartComplexPlatform<S> stewartStartPlatform<S>();                                           \
  template const std::vector<StudyPointC<S>>& stewartStartSolutions<S>();                                 \
  template StewartForwardSolution<S> solveStewartForward<S>(const StewartPlatform<S>&, StewartTracking);             \
  template StewartComplexPosture<S> stewartComplexPosture<S>(const StewartPlatform<S>&, const StudyPointC<S>&);       \
  template S stewartComplexResidual<S>(const StewartPlatform<S>&, const StewartComplexPosture<S>&);               \
  template bool containsConjugate<S>(const std::vector<StudyPointC<S>>&, const StudyPointC<S>&, const S&);

}  // namespace soma
