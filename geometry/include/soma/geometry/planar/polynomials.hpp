#pragma once
// The small polynomial toolkit of planar kinematics: bivariate polynomials of degree ≤ 6 in
// (x, y) (inflection circle, cubics of stationary curvature, the sextic coupler curve,
// centre-point curves), binary forms (directions through a node), and all complex roots of a
// univariate polynomial (Aberth–Ehrlich iteration, then Newton polishing).
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <array>
#include <vector>

namespace soma::planar {

/// A complex number over any rung of the scalar ladder (std::complex is not specified for
/// __float128 or mpreal).
template <class S> struct Cx {
  S re{0}, im{0};
  Cx() = default;
  Cx(const S& r, const S& i = S(0)) : re(r), im(i) {}
  Cx operator+(const Cx& o) const { return {re + o.re, im + o.im}; }
  Cx operator-(const Cx& o) const { return {re - o.re, im - o.im}; }
  Cx operator-() const { return {-re, -im}; }
  Cx operator*(const Cx& o) const { return {re * o.re - im * o.im, re * o.im + im * o.re}; }
  Cx operator*(const S& k) const { return {re * k, im * k}; }
  Cx operator/(const Cx& o) const {
    const S d = o.re * o.re + o.im * o.im;
    return {(re * o.re + im * o.im) / d, (im * o.re - re * o.im) / d};
  }
  S norm2() const { return re * re + im * im; }
  S abs() const {
    using std::sqrt;
    return sqrt(norm2());
  }
  Cx conj() const { return {re, -im}; }
};

/// Univariate polynomial, coefficients from the constant term up.
template <class S> using Poly1 = std::vector<S>;

/// All complex roots of p (degree = last nonzero coefficient). Aberth–Ehrlich simultaneous
/// iteration from points on a circle of the Cauchy-bound radius, then Newton polishing of each
/// root; `residuals` (optional) receives |p(z)| / Σ|a_k||z|^k per root (backward error).
/// Throws InvalidInput for the zero polynomial or a non-finite coefficient.
template <class S> std::vector<Cx<S>> polynomialRoots(const Poly1<S>& p, std::vector<S>* residuals = nullptr);

/// p(z) for complex z (Horner).
template <class S> Cx<S> evalPoly(const Poly1<S>& p, const Cx<S>& z) {
  Cx<S> v(S(0));
  for (int k = int(p.size()) - 1; k >= 0; --k) v = v * z + Cx<S>(p[k]);
  return v;
}
template <class S> S evalPoly(const Poly1<S>& p, const S& x) {
  S v(0);
  for (int k = int(p.size()) - 1; k >= 0; --k) v = v * x + p[k];
  return v;
}
template <class S> Poly1<S> polyMul(const Poly1<S>& a, const Poly1<S>& b) {
  if (a.empty() || b.empty()) return {};
  Poly1<S> r(a.size() + b.size() - 1, S(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
template <class S> Poly1<S> polyAdd(const Poly1<S>& a, const Poly1<S>& b) {
  Poly1<S> r(std::max(a.size(), b.size()), S(0));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += b[i];
  return r;
}
/// Quotient of a / b (long division from the top); the remainder goes to *rem.
template <class S> Poly1<S> polyDiv(const Poly1<S>& a, const Poly1<S>& b, Poly1<S>* rem = nullptr) {
  int db = int(b.size()) - 1;
  while (db >= 0 && b[db] == S(0)) --db;
  if (db < 0) throw InvalidInput("polynomial division by zero");
  Poly1<S> r = a;
  const int da = int(a.size()) - 1;
  Poly1<S> q(std::max(1, da - db + 1), S(0));
  for (int k = da - db; k >= 0; --k) {
    const S c = r[k + db] / b[db];
    q[k] = c;
    for (int j = 0; j <= db; ++j) r[k + j] -= c * b[j];
  }
  if (rem) {
    r.resize(std::max(0, db));
    *rem = r;
  }
  return q;
}

/// Bivariate polynomial Σ c_ij x^i y^j of total degree ≤ 6.
template <class S> struct Poly2 {
  static constexpr int kMax = 6;
  std::array<S, (kMax + 1) * (kMax + 1)> c;

  Poly2() { c.fill(S(0)); }
  explicit Poly2(const S& k) {
    c.fill(S(0));
    c[0] = k;
  }
  /// a + b x + c y.
  static Poly2 affine(const S& a, const S& bx, const S& cy) {
    Poly2 p(a);
    p.at(1, 0) = bx;
    p.at(0, 1) = cy;
    return p;
  }
  S& at(int i, int j) { return c[i * (kMax + 1) + j]; }
  const S& at(int i, int j) const { return c[i * (kMax + 1) + j]; }

  Poly2 operator+(const Poly2& o) const {
    Poly2 r;
    for (std::size_t k = 0; k < c.size(); ++k) r.c[k] = c[k] + o.c[k];
    return r;
  }
  Poly2 operator-(const Poly2& o) const {
    Poly2 r;
    for (std::size_t k = 0; k < c.size(); ++k) r.c[k] = c[k] - o.c[k];
    return r;
  }
  Poly2 operator*(const S& k) const {
    Poly2 r;
    for (std::size_t i = 0; i < c.size(); ++i) r.c[i] = c[i] * k;
    return r;
  }
  friend Poly2 operator*(const S& k, const Poly2& p) { return p * k; }
  /// Product; throws InvalidInput if the result would exceed degree 6 with nonzero terms.
  Poly2 operator*(const Poly2& o) const {
    Poly2 r;
    for (int i = 0; i <= kMax; ++i)
      for (int j = 0; i + j <= kMax; ++j) {
        const S& a = at(i, j);
        if (a == S(0)) continue;
        for (int k = 0; k <= kMax; ++k)
          for (int l = 0; k + l <= kMax; ++l) {
            const S& b = o.at(k, l);
            if (b == S(0)) continue;
            if (i + k + j + l > kMax) throw InvalidInput("Poly2: product exceeds degree 6");
            r.at(i + k, j + l) += a * b;
          }
      }
    return r;
  }
  S operator()(const S& x, const S& y) const {
    S v(0);
    for (int i = kMax; i >= 0; --i) {
      S row(0);
      for (int j = kMax - i; j >= 0; --j) row = row * y + at(i, j);
      v = v * x + row;
    }
    return v;
  }
  Cx<S> operator()(const Cx<S>& x, const Cx<S>& y) const {
    Cx<S> v(S(0));
    for (int i = kMax; i >= 0; --i) {
      Cx<S> row(S(0));
      for (int j = kMax - i; j >= 0; --j) row = row * y + Cx<S>(at(i, j));
      v = v * x + row;
    }
    return v;
  }
  /// Σ |c_ij| |x|^i |y|^j: the scale against which a value p(x, y) is judged zero.
  S magnitude(const S& x, const S& y) const {
    using std::abs;
    S v(0);
    for (int i = 0; i <= kMax; ++i)
      for (int j = 0; i + j <= kMax; ++j) {
        if (at(i, j) == S(0)) continue;
        S t = abs(at(i, j));
        for (int k = 0; k < i; ++k) t *= abs(x);
        for (int k = 0; k < j; ++k) t *= abs(y);
        v += t;
      }
    return v;
  }
  /// Largest |coefficient| of the homogeneous part of degree d.
  S partNorm(int d) const {
    using std::abs;
    S m(0);
    for (int i = 0; i <= d; ++i) m = std::max<S>(m, abs(at(i, d - i)));
    return m;
  }
  S maxCoeff() const {
    using std::abs;
    S m(0);
    for (const S& v : c) m = std::max<S>(m, abs(v));
    return m;
  }
  /// Degree: the highest d whose homogeneous part exceeds tol·maxCoeff (−1 for zero).
  int degree(const S& relTol) const {
    const S m = maxCoeff();
    for (int d = kMax; d >= 0; --d)
      if (partNorm(d) > relTol * m) return d;
    return -1;
  }
  /// The homogeneous part of degree d as a binary form: coefficients of x^{d−k} y^k, k = 0..d.
  Poly1<S> homogeneousPart(int d) const {
    Poly1<S> f(d + 1);
    for (int k = 0; k <= d; ++k) f[k] = at(d - k, k);
    return f;
  }
  /// ∂p/∂x and ∂p/∂y.
  Poly2 dx() const {
    Poly2 r;
    for (int i = 1; i <= kMax; ++i)
      for (int j = 0; i + j <= kMax; ++j) r.at(i - 1, j) = S(i) * at(i, j);
    return r;
  }
  Poly2 dy() const {
    Poly2 r;
    for (int i = 0; i <= kMax; ++i)
      for (int j = 1; i + j <= kMax; ++j) r.at(i, j - 1) = S(j) * at(i, j);
    return r;
  }
  /// q(x, y) = p(x + x0, y + y0).
  Poly2 translated(const S& x0, const S& y0) const {
    Poly2 r;
    // powers of (x + x0) and (y + y0)
    std::array<Poly2, kMax + 1> px, py;
    px[0] = Poly2(S(1));
    py[0] = Poly2(S(1));
    for (int k = 1; k <= kMax; ++k) {
      px[k] = Poly2();
      py[k] = Poly2();
      for (int j = 0; j < k; ++j) {  // (x + x0)^k coefficients by the binomial recurrence
        px[k].at(j + 1, 0) += px[k - 1].at(j, 0);
        px[k].at(j, 0) += x0 * px[k - 1].at(j, 0);
        py[k].at(0, j + 1) += py[k - 1].at(0, j);
        py[k].at(0, j) += y0 * py[k - 1].at(0, j);
      }
    }
    for (int i = 0; i <= kMax; ++i)
      for (int j = 0; i + j <= kMax; ++j) {
        if (at(i, j) == S(0)) continue;
        for (int a = 0; a <= i; ++a)
          for (int b = 0; b <= j; ++b) r.at(a, b) += at(i, j) * px[i].at(a, 0) * py[j].at(0, b);
      }
    return r;
  }
  /// q(x, y) = p(x cos α − y sin α, x sin α + y cos α) given (cos α, sin α): p in a rotated frame.
  Poly2 rotated(const S& ca, const S& sa) const {
    const Poly2 X = affine(S(0), ca, -sa), Y = affine(S(0), sa, ca);
    std::array<Poly2, kMax + 1> px, py;
    px[0] = py[0] = Poly2(S(1));
    for (int k = 1; k <= kMax; ++k) {
      px[k] = px[k - 1] * X;
      py[k] = py[k - 1] * Y;
    }
    Poly2 r;
    for (int i = 0; i <= kMax; ++i)
      for (int j = 0; i + j <= kMax; ++j)
        if (at(i, j) != S(0)) r = r + (px[i] * py[j]) * at(i, j);
    return r;
  }
};

/// Binary form Σ f_k c^{d−k} s^k evaluated at a complex direction (c, s).
template <class S> Cx<S> evalForm(const Poly1<S>& f, const Cx<S>& c, const Cx<S>& s) {
  const int d = int(f.size()) - 1;
  Cx<S> v(S(0));
  for (int k = 0; k <= d; ++k) {
    Cx<S> t(f[k]);
    for (int j = 0; j < d - k; ++j) t = t * c;
    for (int j = 0; j < k; ++j) t = t * s;
    v = v + t;
  }
  return v;
}

}  // namespace soma::planar
