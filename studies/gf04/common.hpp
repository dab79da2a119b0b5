#pragma once
// Helpers shared by the studies of GF chapter 4 (gf04/*.cpp): independent reference methods
// (matrix exponential by its power series, complex matrices as real pairs for the book's
// idempotent calculus, Richardson finite differences, small complex linear solves for the
// book's Lagrange/Hermite interpolation), fixed-seed random draws and norms.
// Nothing here is soma library code: these are the "other method" a study compares against.
#include "soma/algebra/lie_algebra.hpp"
#include "soma/algebra/screw.hpp"
#include "soma/algebra/se2.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <random>
#include <string>
#include <vector>

namespace soma::studies::gf04 {

inline constexpr const char* kChapter = "GF 4 — Lie algebra";

// ADL finds mpfr's overloads; these bring in the std ones for the built-in rungs.
using std::abs;
using std::atan2;
using std::cos;
using std::exp;
using std::log;
using std::sinh;
using std::tan;
using std::pow;
using std::sin;
using std::sqrt;

template <class S> using MatX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// Fixed-seed generator: every study draws the same inputs on every run and every scalar.
inline std::mt19937_64 rng(std::uint64_t seed = 44) { return std::mt19937_64(seed); }

/// Uniform in [lo, hi], drawn in double (exact in every rung of the ladder) and cast to S.
template <class S> S uniform(std::mt19937_64& g, double lo = -1, double hi = 1) { return draws::uni<S>(g, lo, hi); }
template <class S, int N> Eigen::Matrix<S, N, 1> randomVec(std::mt19937_64& g, double lo = -1,
                                                           double hi = 1) {
  Eigen::Matrix<S, N, 1> v;
  for (int i = 0; i < N; ++i) v(i) = uniform<S>(g, lo, hi);
  return v;
}
template <class S> Vec3<S> randomUnit(std::mt19937_64& g) {
  using std::sqrt;
  Vec3<S> v;
  do v = randomVec<S, 3>(g);
  while (v.squaredNorm() < S(1) / S(10));
  return v / sqrt(v.squaredNorm());
}

/// Largest absolute entry (max-norm) of a matrix expression; NaN or infinity if any entry is
/// not finite (a comparison-based max would silently skip a NaN).
template <class D> typename D::Scalar maxAbs(const Eigen::MatrixBase<D>& m) {
  using std::abs;
  typename D::Scalar r(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      const typename D::Scalar a = abs(m(i, j));
      if (!isFinite(a)) return a;
      if (a > r) r = a;
    }
  return r;
}
using draws::maxOf;  // max(a, b), propagating NaN: soma/studies/scalar_draws.hpp
using draws::ipow;  // xⁿ in S: soma/studies/scalar_draws.hpp
template <class S> S minOfPair(const S& a, const S& b) { return a < b ? a : b; }

/// Matrix exponential by its power series, with scaling and squaring: the reference method
/// "Σ Xⁿ/n!" of GF §4.4, summed until the terms fall below epsilon. Independent of every
/// closed form in soma.
template <class M> M expSeries(const M& a) {
  using S = typename M::Scalar;
  S norm(0);
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    S col(0);
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      using std::abs;
      col += abs(a(i, j));
    }
    if (col > norm) norm = col;
  }
  int squarings = 0;
  S scale(1);
  while (norm * scale > S(1) / S(2)) {
    scale /= S(2);
    ++squarings;
  }
  const M x = a * scale;
  M term = M::Identity(a.rows(), a.cols()), sum = term;
  const S eps = Tolerance<S>::epsilon();
  for (int n = 1; n < 400; ++n) {
    term = (term * x) / S(n);
    sum += term;
    if (maxAbs(term) <= eps * eps) break;
  }
  for (int k = 0; k < squarings; ++k) sum = sum * sum;
  return sum;
}

/// The power series evaluated in mpfr at ≥ 2·digits(S) + 64 bits and rounded back to S: a
/// reference whose own error (≤ ½ ulp) is below any round-off of S.
template <int N, class S> Eigen::Matrix<S, N, N> expReference(const Eigen::Matrix<S, N, N>& a) {
  const int old = mpfrBits();
  setMpfrBits(std::max(320, 2 * digits<S>() + 64));
  Eigen::Matrix<mpreal, N, N> hi;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) hi(i, j) = scalarCast<mpreal>(a(i, j));
  const Eigen::Matrix<mpreal, N, N> e = expSeries(hi);
  Eigen::Matrix<S, N, N> out;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) out(i, j) = scalarCast<S>(e(i, j));
  setMpfrBits(old);
  return out;
}

/// A complex scalar as a pair of reals (std::complex is unspecified for mpreal and __float128).
template <class S> struct Cx {
  S re{0}, im{0};
  Cx() = default;
  Cx(const S& r, const S& i = S(0)) : re(r), im(i) {}
  friend Cx operator+(const Cx& a, const Cx& b) { return {a.re + b.re, a.im + b.im}; }
  friend Cx operator-(const Cx& a, const Cx& b) { return {a.re - b.re, a.im - b.im}; }
  friend Cx operator-(const Cx& a) { return {-a.re, -a.im}; }
  friend Cx operator*(const Cx& a, const Cx& b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
  }
  friend Cx operator/(const Cx& a, const Cx& b) {
    const S d = b.re * b.re + b.im * b.im;
    return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
  }
  S abs() const {
    using std::sqrt;
    return sqrt(re * re + im * im);
  }
  static Cx expi(const S& t) {  // e^{it}
    using std::cos;
    using std::sin;
    return {cos(t), sin(t)};
  }
};

/// A complex matrix as (re, im) real matrices: what the book's idempotents P± = … ± iθ… need.
template <class M> struct CMat {
  M re, im;
  static CMat real(const M& r) { return {r, M::Zero(r.rows(), r.cols())}; }
  friend CMat operator+(const CMat& a, const CMat& b) { return {a.re + b.re, a.im + b.im}; }
  friend CMat operator-(const CMat& a, const CMat& b) { return {a.re - b.re, a.im - b.im}; }
  friend CMat operator*(const CMat& a, const CMat& b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
  }
  template <class S> friend CMat operator*(const Cx<S>& z, const CMat& a) {
    return {z.re * a.re - z.im * a.im, z.re * a.im + z.im * a.re};
  }
  typename M::Scalar maxAbs() const { return maxOf(gf04::maxAbs(re), gf04::maxAbs(im)); }
};

/// Solve a small complex linear system A x = b by Gaussian elimination with partial pivoting
/// (the book's interpolation systems; independent of its printed closed forms).
template <class S> std::vector<Cx<S>> solveComplex(std::vector<std::vector<Cx<S>>> a,
                                                   std::vector<Cx<S>> b) {
  const int n = int(b.size());
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (a[i][k].abs() > a[p][k].abs()) p = i;
    std::swap(a[k], a[p]);
    std::swap(b[k], b[p]);
    for (int i = k + 1; i < n; ++i) {
      const Cx<S> f = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] = a[i][j] - f * a[k][j];
      b[i] = b[i] - f * b[k];
    }
  }
  std::vector<Cx<S>> x(n);
  for (int i = n - 1; i >= 0; --i) {
    Cx<S> s = b[i];
    for (int j = i + 1; j < n; ++j) s = s - a[i][j] * x[j];
    x[i] = s / a[i][i];
  }
  return x;
}

/// Central difference with one Richardson step, (4 D(h/2) − D(h))/3, h = scale·eps^(1/5):
/// truncation O(h⁴) and round-off O(eps/h) are both O(eps^(4/5)) (the FD tolerance below).
template <class S, class F> auto derivative(const F& f) {
  const S h = Tolerance<S>::precision(4);
  auto d = [&](const S& hh) { return ((f(hh) - f(-hh)) / (S(2) * hh)).eval(); };
  return ((S(4) * d(h / S(2)) - d(h)) / S(3)).eval();
}
/// Error bound of derivative(): C·eps^(4/5) for derivatives of unit size (C = 64 covers the
/// fifth-derivative constant of the smooth maps differentiated in these studies).
template <class S> S fdTolerance(const S& scale = S(1)) {
  using std::pow;
  return S(64) * pow(Tolerance<S>::epsilon(), S(4) / S(5)) * scale;
}

/// The bracket of any tangent type: lie_algebra's bracket(), or SE2Tangent's member.
template <class T> T lieBracket(const T& a, const T& b) {
  if constexpr (requires { a.bracket(b); }) return a.bracket(b);
  else return bracket(a, b);
}

/// The book's su(2) element [[ai, b+ci], [−b+ci, −ai]] (GF §4.1, §4.4) as a complex 2×2.
template <class S> CMat<Mat2<S>> su2Element(const S& a, const S& b, const S& c) {
  Mat2<S> re, im;
  re << S(0), b, -b, S(0);
  im << a, c, c, -a;
  return {re, im};
}
/// Real 4×4 form [[Re, −Im], [Im, Re]] of a complex 2×2 (for the power-series exponential).
template <class S> Mat4<S> realForm(const CMat<Mat2<S>>& m) {
  Mat4<S> r;
  r << m.re, -m.im, m.im, m.re;
  return r;
}
template <class S> CMat<Mat2<S>> fromRealForm(const Mat4<S>& r) {
  return {r.template topLeftCorner<2, 2>(), r.template bottomLeftCorner<2, 2>()};
}

template <class S> struct AdjointSpectral {
  CMat<Mat6<S>> P0, Pp, Np, Pm, Nm;
};
/// The book's idempotents and nilpotents of Z = ad(s) (expanded forms; the printed "I₆θ³Z"
/// in N₋ read as iθ³Z). GF §4.4.3, GF-4.4.3-adjoint-exp
template <class S> AdjointSpectral<S> adjointSpectral(const Mat6<S>& Z, const S& th) {
  using CM = CMat<Mat6<S>>;
  const Mat6<S> I = Mat6<S>::Identity(), Z2 = Z * Z, Z3 = Z2 * Z, Z4 = Z3 * Z;
  const S t2 = th * th, t3 = t2 * th, t4 = t2 * t2;
  AdjointSpectral<S> r;
  r.P0 = CM::real(Mat6<S>((Z4 + S(2) * t2 * Z2 + t4 * I) / t4));
  r.Pp = {Mat6<S>(-(S(2) * Z4 + S(4) * t2 * Z2) / (S(4) * t4)), Mat6<S>(-(-th * Z3 - S(3) * t3 * Z) / (S(4) * t4))};
  r.Np = {Mat6<S>((Z4 + t2 * Z2) / (S(4) * t4)), Mat6<S>((-th * Z3 - t3 * Z) / (S(4) * t4))};
  r.Pm = {Mat6<S>(-(S(2) * Z4 + S(4) * t2 * Z2) / (S(4) * t4)), Mat6<S>(-(th * Z3 + S(3) * t3 * Z) / (S(4) * t4))};
  r.Nm = {Mat6<S>((Z4 + t2 * Z2) / (S(4) * t4)), Mat6<S>((th * Z3 + t3 * Z) / (S(4) * t4))};
  return r;
}
/// θ of a rotation block R (of G = [[R, t], [0, 1]] or H = [[R, 0], [TR, R]]) from Tr G = 2(1 + cos θ) and sin θ = |vee(R − Rᵀ)|/2 (atan2).
template <class S> S angleOf(const Mat3<S>& R) {
  const S st = sqrt(SO3Tangent<S>::vee(Mat3<S>(R - R.transpose())).coeffs().squaredNorm()) / S(2);
  return atan2(st, (R.trace() - S(1)) / S(2));
}
/// Short decimal text for notes.
template <class S> std::string str(const S& x, int digits = 3) { return toString(x, digits); }

/// A twist whose rotation has angle θ about a random axis, with a random unit-scale moment.
template <class S> SE3Tangent<S> randomTwistWithAngle(std::mt19937_64& g, const S& theta) {
  const Vec3<S> a = randomUnit<S>(g);
  const Vec3<S> v = randomVec<S, 3>(g);
  return SE3Tangent<S>(Vec3<S>(a * theta), v);
}

}  // namespace soma::studies::gf04
