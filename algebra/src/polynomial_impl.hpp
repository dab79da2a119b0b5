// Real roots of polynomials: Aberth–Ehrlich iteration + Newton polish (see polynomial.hpp).
#pragma once
#include "soma/algebra/polynomial.hpp"

#include "soma/algebra/errors.hpp"


#include <algorithm>
#include <string>

namespace soma {

namespace {

/// Coefficients with negligible leading terms dropped; throws on NaN or the zero polynomial.
template <class S> std::vector<S> trimmed(const std::vector<S>& c) {
  using std::abs;
  S big = S(0);
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (!isFinite(c[k]))
      throw InvalidInput("polynomial: coefficient " + std::to_string(k) + " is NaN or infinite");
    big = std::max<S>(big, abs(c[k]));
  }
  if (big == S(0)) throw InvalidInput("polynomial: the zero polynomial (every number is a root)");
  std::vector<S> t = c;
  while (!t.empty() && abs(t.back()) <= Tolerance<S>::epsilon() * big) t.pop_back();
  return t;
}

/// Newton polish of a real root estimate on p, keeping only steps that decrease |p|.
template <class S> S polish(const std::vector<S>& c, S x) {
  using std::abs;
  S px = evalPolynomial(c, x);
  for (int it = 0; it < 16 && px != S(0); ++it) {
    S dp = S(0);
    for (std::size_t k = c.size() - 1; k >= 1; --k) dp = dp * x + S(int(k)) * c[k];
    if (dp == S(0)) break;
    const S xn = x - px / dp;
    const S pn = evalPolynomial(c, xn);
    if (!(abs(pn) < abs(px))) break;
    x = xn;
    px = pn;
  }
  return x;
}

}  // namespace

template <class S> std::vector<std::complex<S>> polynomialRoots(const std::vector<S>& c0) {
  using std::abs;
  using std::cos;
  using std::pow;
  using std::sin;
  using std::sqrt;
  using C = std::complex<S>;
  const std::vector<S> c = trimmed(c0);
  const int n = int(c.size()) - 1;
  std::vector<C> z;
  if (n <= 0) return z;
  // Monic coefficients a_k = c_k / c_n; the roots lie in |x| ≤ 2 max |a_k|^(1/(n-k)) (Fujiwara).
  std::vector<S> a(n + 1);
  for (int k = 0; k <= n; ++k) a[k] = c[k] / c[n];
  S s = S(0);
  for (int k = 0; k < n; ++k)
    if (a[k] != S(0)) s = std::max<S>(s, pow(abs(a[k]), S(1) / S(n - k)));
  if (s == S(0)) return std::vector<C>(n, C(S(0), S(0)));  // x^n = 0
  // Aberth–Ehrlich simultaneous iteration (cubically convergent for simple roots) from points
  // on a circle of radius s, rotated off the real axis so no start is a real critical point.
  // (The companion-matrix QR of Eigen's EigenSolver gives the same roots, but instantiating it
  // for one scalar (soma_instantiate) cost ~10 minutes of compile time; the iteration is a few lines.)
  auto mod2 = [](const C& w) { return w.real() * w.real() + w.imag() * w.imag(); };
  for (int k = 0; k < n; ++k) {
    const S ang = S(2) * pi<S>() * S(k) / S(n) + S(4) / S(10);
    z.emplace_back(s * cos(ang), s * sin(ang));
  }
  const S tol2 = Tolerance<S>::epsilon() * Tolerance<S>::epsilon();
  for (int it = 0; it < 200; ++it) {
    bool done = true;
    for (int k = 0; k < n; ++k) {
      C p(a[n], S(0)), dp(S(0), S(0));
      for (int j = n - 1; j >= 0; --j) {
        dp = dp * z[k] + p;
        p = p * z[k] + C(a[j], S(0));
      }
      if (mod2(p) == S(0)) continue;
      const C w = p / dp;
      C sum(S(0), S(0));
      for (int j = 0; j < n; ++j)
        if (j != k) sum += C(S(1), S(0)) / (z[k] - z[j]);
      const C step = w / (C(S(1), S(0)) - w * sum);
      z[k] -= step;
      const S zz = mod2(z[k]);
      if (mod2(step) > tol2 * (zz > S(1) ? zz : S(1))) done = false;
    }
    if (done) break;
  }
  return z;
}

template <class S> std::vector<S> realRoots(const std::vector<S>& c0) {
  using std::abs;
  const std::vector<S> c = trimmed(c0);
  std::vector<S> out;
  if (c.size() <= 1) return out;
  for (const auto& z : polynomialRoots(c)) {
    const S scale = std::max<S>(S(1), abs(z.real()));
    if (abs(z.imag()) > Tolerance<S>::input() * scale) continue;
    // A candidate is real when, polished, it is a root to round-off: |p(x)| ≤ 256 eps Σ|c_k x^k|.
    // (A double root splits into x ± i√eps under round-off and passes; a genuine complex pair
    // x ± iy with y ~ √eps leaves |p(x)| ~ y² |p''|/2 and is rejected. In float the imaginary
    // pre-filter alone let pairs with y ~ 0.02 through.)
    const S x = polish(c, z.real());
    S mag = S(0), xk = S(1);
    for (const auto& ck : c) {
      mag += abs(ck) * xk;
      xk *= abs(x);
    }
    if (abs(evalPolynomial(c, x)) <= Tolerance<S>::identity(256) * mag) out.push_back(x);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <class S> std::vector<S> quadraticRealRoots(const S& c0, const S& c1, const S& c2) {
  using std::abs;
  using std::sqrt;
  std::vector<S> out;
  const S big = std::max<S>({abs(c0), abs(c1), abs(c2)});
  if (big == S(0)) throw InvalidInput("quadratic: the zero polynomial (every number is a root)");
  if (abs(c2) <= Tolerance<S>::epsilon() * big) {  // linear
    if (abs(c1) > Tolerance<S>::epsilon() * big) out.push_back(-c0 / c1);
    return out;
  }
  S disc = c1 * c1 - S(4) * c2 * c0;
  // A discriminant negative by round-off only (relative to the terms that formed it) is a
  // double root.
  const S discScale = c1 * c1 + abs(S(4) * c2 * c0);
  if (disc < S(0)) {
    if (-disc > Tolerance<S>::identity() * discScale) return out;
    disc = S(0);
  }
  const S sq = sqrt(disc);
  const S q = c1 >= S(0) ? -(c1 + sq) / S(2) : -(c1 - sq) / S(2);
  if (q == S(0)) {  // c1 = 0 and c0 = 0: double root at 0
    out.assign(2, S(0));
    return out;
  }
  S r1 = q / c2, r2 = c0 / q;
  if (r2 < r1) std::swap(r1, r2);
  out.push_back(r1);
  out.push_back(r2);
  return out;
}

template <class S> std::vector<S> quarticRealRoots(const std::array<S, 5>& c) {
  const std::vector<S> t = trimmed(std::vector<S>(c.begin(), c.end()));
  if (t.size() <= 3) {
    if (t.size() <= 1) return {};
    return quadraticRealRoots(t[0], t[1], t.size() == 3 ? t[2] : S(0));
  }
  return realRoots(t);
}

#define SOMA_INSTANTIATE_POLYNOMIAL(S)                                                         \
  template std::vector<std::complex<S>> polynomialRoots<S>(const std::vector<S>&);      \
  template std::vector<S> realRoots<S>(const std::vector<S>&);                          \
  template std::vector<S> quarticRealRoots<S>(const std::array<S, 5>&);                 \
  template std::vector<S> quadraticRealRoots<S>(const S&, const S&, const S&);

}  // namespace soma
