// Complex roots of univariate polynomials (Aberth–Ehrlich, Newton polishing), five scalars.
#pragma once
#include "soma/geometry/planar/polynomials.hpp"

#include <cmath>

namespace soma::planar {

template <class S> std::vector<Cx<S>> polynomialRoots(const Poly1<S>& pin, std::vector<S>* residuals) {
  using std::abs;
  using std::exp;
  using std::log;
  for (const S& v : pin)
    if (!isFinite(v)) throw InvalidInput("polynomialRoots: a coefficient is NaN or infinite");
  int n = int(pin.size()) - 1;
  while (n >= 0 && pin[n] == S(0)) --n;
  if (n < 0) throw InvalidInput("polynomialRoots: the zero polynomial has no finite root set");
  std::vector<Cx<S>> roots;
  int z0 = 0;  // exact roots at 0
  while (z0 < n && pin[z0] == S(0)) ++z0;
  for (int k = 0; k < z0; ++k) roots.push_back(Cx<S>(S(0)));
  Poly1<S> p(pin.begin() + z0, pin.begin() + n + 1);
  const int m = n - z0;
  if (m > 0) {
    // Initial points on a circle of radius |a0/an|^(1/m), angles offset from the axes.
    const S rad = exp(log(abs(p[0] / p[m])) / S(m));
    std::vector<Cx<S>> z(m);
    for (int k = 0; k < m; ++k) {
      const double ang = 2 * 3.14159265358979323846 * k / m + 0.4;
      z[k] = Cx<S>(rad * scalarCast<S>(std::cos(ang)), rad * scalarCast<S>(std::sin(ang)));
    }
    Poly1<S> dp(std::max(1, m), S(0));
    for (int k = 1; k <= m; ++k) dp[k - 1] = S(k) * p[k];
    const S eps = Tolerance<S>::epsilon();
    for (int it = 0; it < 800; ++it) {
      bool done = true;
      for (int k = 0; k < m; ++k) {
        const Cx<S> pv = evalPoly(p, z[k]), dv = evalPoly(dp, z[k]);
        if (pv.norm2() == S(0)) continue;
        const Cx<S> w = pv / dv;
        Cx<S> sum(S(0));
        for (int j = 0; j < m; ++j)
          if (j != k) sum = sum + Cx<S>(S(1)) / (z[k] - z[j]);
        const Cx<S> corr = w / (Cx<S>(S(1)) - w * sum);
        z[k] = z[k] - corr;
        if (corr.abs() > S(4) * eps * (S(1) + z[k].abs())) done = false;
      }
      if (done) break;
    }
    // Newton polishing (a few steps; stop when a step does not reduce |p|).
    for (int k = 0; k < m; ++k) {
      for (int it = 0; it < 4; ++it) {
        const Cx<S> pv = evalPoly(p, z[k]), dv = evalPoly(dp, z[k]);
        if (dv.norm2() == S(0)) break;
        const Cx<S> zn = z[k] - pv / dv;
        if (evalPoly(p, zn).norm2() < pv.norm2()) z[k] = zn;
        else break;
      }
      roots.push_back(z[k]);
    }
  }
  if (residuals) {
    residuals->clear();
    for (const Cx<S>& r : roots) {
      S mag(0), pw(1);
      const S ar = r.abs();
      for (int k = 0; k <= n; ++k) {
        mag += abs(pin[k]) * pw;
        pw *= ar;
      }
      residuals->push_back(evalPoly(pin, r).abs() / mag);
    }
  }
  return roots;
}

#define SOMA_INSTANTIATE_POLYNOMIALS(T) namespace planar { template std::vector<Cx<T>> polynomialRoots<T>(const Poly1<T>&, std::vector<T>*); }

}  // namespace soma::planar
