#pragma once
// How accurate is SE(3) log in a given rung of the scalar ladder? worstLogError<S>(samples)
// sweeps the rotation angle over (0, π] — log-spaced towards 0, dense towards π (down to
// π − ε), uniform in between, plus θ = π itself — with random axes and translations, builds the
// element in S, and compares SE3<S>::log with a reference computed in mpfr (≥ 320 bits) from the
// SAME element (its quaternion and translation converted exactly). The reference does not reuse
// the library's log: ω = 2·atan2(|q_v|, q_w)·q_v/|q_v| of the normalised quaternion (w ≥ 0), and
// v solves Jl(ω) v = t with Jl = Σ ad(ω)^k/(k+1)! summed as a power series (GF §4.5.3,
// GF-4.5.3-so3-dexp-and-inverse; GF §4.4.2, GF-4.4.2-se3-log-4x4).
//
// Errors are normwise, in units of ε_S (= ulp of 1): ‖ω − ω_ref‖∞ / (ε_S ‖ω_ref‖∞) for the
// rotation part and ‖v − v_ref‖∞ / (ε_S ‖v_ref‖∞) for the translation part.
#include "soma/algebra/se3.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace soma {

/// Result of worstLogError: the worst errors (in ε_S) and the angles where they occurred.
struct LogAccuracy {
  double worstUlps = 0;          ///< max of the two parts below
  double worstTheta = 0;         ///< θ of the worst sample
  double rotationUlps = 0;       ///< worst ‖Δω‖∞ / (ε‖ω‖∞)
  double rotationTheta = 0;
  double translationUlps = 0;    ///< worst ‖Δv‖∞ / (ε‖v‖∞)
  double translationTheta = 0;
  double meanUlps = 0;           ///< mean over samples of max(rotation, translation)
  int samples = 0;               ///< samples evaluated (including θ = π)
  int referenceBits = 0;         ///< mpfr precision of the reference
};

namespace detail::logacc {

/// x converted exactly to an mpreal of `bits` bits (bits ≥ the digits of S).
template <class S> mpreal exact(const S& x, int bits) {
  mpreal r = scalarCast<mpreal>(x);  // exact at any precision ≥ digits<S>()
  r.setPrecision(bits);              // widening: exact
  return r;
}

/// Reference log of (q, t) at the current mpfr precision, independent of SE3::log.
inline void referenceLog(Quat<mpreal> q, const Vec3<mpreal>& t, Vec3<mpreal>& w, Vec3<mpreal>& v) {
  q.coeffs() /= sqrt(q.coeffs().squaredNorm());
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const mpreal n = sqrt(q.vec().squaredNorm());
  if (n == 0) {
    w.setZero();
    v = t;
    return;
  }
  const mpreal theta = 2 * atan2(n, q.w());
  w = q.vec() * (theta / n);
  // Jl(ω) = Σ W^k/(k+1)!, terms until they drop below 2^-(bits+8) relative (|W| ≤ π).
  const Mat3<mpreal> W = skew<mpreal>(w);
  Mat3<mpreal> term = Mat3<mpreal>::Identity(), J = Mat3<mpreal>::Identity();
  const mpreal tiny = pow(mpreal(2), -int(mpreal::get_default_prec()) - 8);
  for (int k = 1; k < 2000; ++k) {
    term = (term * W / mpreal(k + 1)).eval();
    J += term;
    if (term.cwiseAbs().maxCoeff() < tiny) break;
  }
  v = J.fullPivLu().solve(t);
}

}  // namespace detail::logacc

/// Sweep θ ∈ (0, π] with `samples` random elements of SE3<S> (fixed seed) and return the worst
/// error of SE3<S>::log against an mpfr reference. One third of the angles are log-spaced in
/// [ε_S, 1], one third are π − δ with δ log-spaced in [ε_S, 1], one third uniform in (0, π];
/// the last sample is θ = pi<S>(). Translations are uniform in [−1, 1]³. For S = mpreal the
/// library runs at the current default precision and the reference at twice that plus 64 bits.
template <class S>
LogAccuracy worstLogError(int samples, std::uint64_t seed = 20261130, int referenceBits = 0) {
  using std::abs;
  using std::log10;
  using std::pow;
  using std::sqrt;
  const int sBits = digits<S>();
  const int bits = referenceBits > 0 ? referenceBits : std::max(320, 2 * sBits + 64);
  const int oldBits = mpfrBits();
  const S eps = Tolerance<S>::epsilon();  // at the working precision of S
  const double epsD = toDouble(eps);
  const double logEps = std::log10(epsD);

  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u01(0, 1), u11(-1, 1);
  std::normal_distribution<double> nd;

  LogAccuracy out;
  out.referenceBits = bits;
  double sum = 0;
  const int n = samples < 4 ? 4 : samples;
  for (int i = 0; i < n; ++i) {
    // ---- the element, built in S -------------------------------------------------------
    S theta;
    if (i == n - 1) {
      theta = pi<S>();
    } else {
      const double x = u01(g);
      switch (i % 3) {
        case 0: theta = scalarCast<S>(std::pow(10.0, logEps * x)); break;           // (ε, 1]
        case 1: theta = pi<S>() - scalarCast<S>(std::pow(10.0, logEps * x)); break; // π − δ
        default: theta = pi<S>() * scalarCast<S>(1 - x); break;                     // (0, π]
      }
    }
    Vec3<S> axis;
    do {
      axis = Vec3<S>(scalarCast<S>(nd(g)), scalarCast<S>(nd(g)), scalarCast<S>(nd(g)));
    } while (axis.squaredNorm() < S(1) / S(100));
    axis /= sqrt(axis.squaredNorm());
    const double tx = u11(g), ty = u11(g), tz = u11(g);
    const Vec3<S> t(scalarCast<S>(tx), scalarCast<S>(ty), scalarCast<S>(tz));
    const SE3<S> X(SO3Tangent<S>(Vec3<S>(axis * theta)).exp(), t);

    // ---- log in S ------------------------------------------------------------------------
    const SE3Tangent<S> s = X.log();

    // ---- reference -----------------------------------------------------------------------
    setMpfrBits(bits);
    Quat<mpreal> q;
    q.coeffs() << detail::logacc::exact(X.quaternion().x(), bits),
        detail::logacc::exact(X.quaternion().y(), bits),
        detail::logacc::exact(X.quaternion().z(), bits),
        detail::logacc::exact(X.quaternion().w(), bits);
    Vec3<mpreal> tr;
    for (int k = 0; k < 3; ++k) tr(k) = detail::logacc::exact(X.translation()(k), bits);
    Vec3<mpreal> wRef, vRef;
    detail::logacc::referenceLog(q, tr, wRef, vRef);
    const mpreal e = detail::logacc::exact(eps, bits);
    mpreal dw = 0, dv = 0;
    for (int k = 0; k < 3; ++k) {
      const mpreal a = abs(detail::logacc::exact(s.coeffs()(k), bits) - wRef(k));
      const mpreal b = abs(detail::logacc::exact(s.coeffs()(k + 3), bits) - vRef(k));
      if (a > dw) dw = a;
      if (b > dv) dv = b;
    }
    const mpreal wn = wRef.cwiseAbs().maxCoeff(), vn = vRef.cwiseAbs().maxCoeff();
    const double ew = wn > 0 ? (dw / (e * wn)).toDouble() : (dw / e).toDouble();
    const double ev = vn > 0 ? (dv / (e * vn)).toDouble() : (dv / e).toDouble();
    const double th = toDouble(theta);
    setMpfrBits(oldBits);

    if (ew > out.rotationUlps) {
      out.rotationUlps = ew;
      out.rotationTheta = th;
    }
    if (ev > out.translationUlps) {
      out.translationUlps = ev;
      out.translationTheta = th;
    }
    const double worst = ew > ev ? ew : ev;
    if (worst > out.worstUlps) {
      out.worstUlps = worst;
      out.worstTheta = th;
    }
    sum += worst;
    ++out.samples;
  }
  out.meanUlps = sum / out.samples;
  return out;
}

}  // namespace soma
