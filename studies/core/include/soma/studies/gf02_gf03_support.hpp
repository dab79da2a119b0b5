#pragma once
// Local helpers shared by the studies of GF chapters 2 and 3 (studies/gf02/*.cpp,
// gf03/*.cpp): fixed-seed random draws on any rung of the scalar ladder, a minimal complex
// number and complex matrix (for U(n), SU(2) and the Hopf map; std::complex is not reliable
// for __float128 and mpreal), homogeneous 4×4 helpers and a numerical rank. These are study
// scaffolding, not library concepts.
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/scalar_draws.hpp"

#include <Eigen/LU>

#include <random>
#include <string>
#include <vector>

namespace soma::studies::gf23 {

template <class S> using MatX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S> using VecX = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// Fixed-seed generator: every study draws from its own seed so runs are reproducible.
inline std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }

using draws::uni;  // soma/studies/scalar_draws.hpp
template <class S> S gauss(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  return scalarCast<S>(n(g));
}
template <class S> Vec3<S> uniVec3(std::mt19937_64& g, double a = -1, double b = 1) {
  const S x = uni<S>(g, a, b), y = uni<S>(g, a, b), z = uni<S>(g, a, b);
  return Vec3<S>(x, y, z);
}
template <class S> MatX<S> uniMat(std::mt19937_64& g, int rows, int cols) {
  MatX<S> m(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) m(i, j) = uni<S>(g);
  return m;
}

/// Largest absolute entry.
template <class Derived> typename Derived::Scalar maxAbs(const Eigen::MatrixBase<Derived>& m) {
  using std::abs;
  typename Derived::Scalar r(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (abs(m(i, j)) > r) r = abs(m(i, j));
  return r;
}

/// Numerical rank: FullPivLU with the relative threshold Tolerance<S>::rank() (× `factor`).
template <class S> int numericalRank(const MatX<S>& m, S factor = S(1)) {
  Eigen::FullPivLU<MatX<S>> lu(m);
  lu.setThreshold(Tolerance<S>::rank() * factor);
  return int(lu.rank());
}

/// Homogeneous 4×4 matrix [[R, t], [0, 1]] (GF §2.5.1).
template <class S> Mat4<S> hom(const Mat3<S>& r, const Vec3<S>& t) {
  Mat4<S> m = Mat4<S>::Identity();
  m.template topLeftCorner<3, 3>() = r;
  m.template topRightCorner<3, 1>() = t;
  return m;
}
template <class S> Mat4<S> translation4(const Vec3<S>& t) { return hom<S>(Mat3<S>::Identity(), t); }

/// Rotation about the x-axis (the book's joint-matrix axis).
template <class S> Mat3<S> rotX(const S& th) {
  using std::cos;
  using std::sin;
  Mat3<S> r;
  r << S(1), S(0), S(0), S(0), cos(th), -sin(th), S(0), sin(th), cos(th);
  return r;
}
template <class S> Mat3<S> rotZ(const S& th) {
  using std::cos;
  using std::sin;
  Mat3<S> r;
  r << cos(th), -sin(th), S(0), sin(th), cos(th), S(0), S(0), S(0), S(1);
  return r;
}

// ---- a minimal complex arithmetic on any rung --------------------------------------------
template <class S> struct Cx {
  S re{0}, im{0};
  Cx() = default;
  Cx(const S& r, const S& i = S(0)) : re(r), im(i) {}
  Cx operator+(const Cx& o) const { return {re + o.re, im + o.im}; }
  Cx operator-(const Cx& o) const { return {re - o.re, im - o.im}; }
  Cx operator-() const { return {-re, -im}; }
  Cx operator*(const Cx& o) const { return {re * o.re - im * o.im, re * o.im + im * o.re}; }
  Cx operator*(const S& s) const { return {re * s, im * s}; }
  Cx conj() const { return {re, -im}; }
  S abs2() const { return re * re + im * im; }
  Cx operator/(const Cx& o) const {
    const S d = o.abs2();
    return {(re * o.re + im * o.im) / d, (im * o.re - re * o.im) / d};
  }
};
template <class S> S cabs(const Cx<S>& z) {
  using std::sqrt;
  return sqrt(z.abs2());
}
template <class S> Cx<S> cexpi(const S& th) {
  using std::cos;
  using std::sin;
  return {cos(th), sin(th)};
}
template <class S> S carg(const Cx<S>& z) {
  using std::atan2;
  return atan2(z.im, z.re);
}

/// Dense n×n complex matrix, row-major.
template <class S> struct CMat {
  int n = 0;
  std::vector<Cx<S>> a;
  CMat() = default;
  explicit CMat(int n_) : n(n_), a(std::size_t(n_ * n_)) {}
  static CMat identity(int n) {
    CMat m(n);
    for (int i = 0; i < n; ++i) m(i, i) = Cx<S>(S(1));
    return m;
  }
  Cx<S>& operator()(int i, int j) { return a[std::size_t(i * n + j)]; }
  const Cx<S>& operator()(int i, int j) const { return a[std::size_t(i * n + j)]; }
  CMat operator*(const CMat& o) const {
    CMat r(n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        Cx<S> s;
        for (int k = 0; k < n; ++k) s = s + (*this)(i, k) * o(k, j);
        r(i, j) = s;
      }
    return r;
  }
  CMat operator*(const Cx<S>& z) const {
    CMat r(n);
    for (std::size_t k = 0; k < a.size(); ++k) r.a[k] = a[k] * z;
    return r;
  }
  CMat operator+(const CMat& o) const {
    CMat r(n);
    for (std::size_t k = 0; k < a.size(); ++k) r.a[k] = a[k] + o.a[k];
    return r;
  }
  CMat operator-(const CMat& o) const {
    CMat r(n);
    for (std::size_t k = 0; k < a.size(); ++k) r.a[k] = a[k] - o.a[k];
    return r;
  }
  CMat operator-() const { return *this * Cx<S>(S(-1)); }
  /// Hermitian conjugate M†.
  CMat adjoint() const {
    CMat r(n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) r(i, j) = (*this)(j, i).conj();
    return r;
  }
  /// Largest |entry|.
  S maxAbs() const {
    S m(0);
    for (const auto& z : a) {
      const S v = cabs(z);
      if (v > m) m = v;
    }
    return m;
  }
  /// Determinant by Gaussian elimination with partial pivoting.
  Cx<S> det() const {
    CMat m = *this;
    Cx<S> d(S(1));
    for (int c = 0; c < n; ++c) {
      int p = c;
      for (int r = c + 1; r < n; ++r)
        if (m(r, c).abs2() > m(p, c).abs2()) p = r;
      if (m(p, c).abs2() == S(0)) return Cx<S>(S(0));
      if (p != c) {
        for (int j = 0; j < n; ++j) std::swap(m(p, j), m(c, j));
        d = -d;
      }
      d = d * m(c, c);
      for (int r = c + 1; r < n; ++r) {
        const Cx<S> f = m(r, c) / m(c, c);
        for (int j = c; j < n; ++j) m(r, j) = m(r, j) - f * m(c, j);
      }
    }
    return d;
  }
};

/// Modified Gram–Schmidt on the columns of m (the QR route of the catalogue,
/// GF-2.2.4-unitary). Throws InvalidInput if a column is numerically dependent on the previous.
template <class S> CMat<S> gramSchmidt(CMat<S> m) {
  using std::sqrt;
  const int n = m.n;
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < j; ++k) {
      Cx<S> dot;  // <q_k, m_j> = Σ conj(q_ik) m_ij
      for (int i = 0; i < n; ++i) dot = dot + m(i, k).conj() * m(i, j);
      for (int i = 0; i < n; ++i) m(i, j) = m(i, j) - m(i, k) * dot;
    }
    S nn(0);
    for (int i = 0; i < n; ++i) nn += m(i, j).abs2();
    if (nn <= Tolerance<S>::rank())
      throw InvalidInput("gramSchmidt: column " + std::to_string(j) +
                         " is numerically dependent on the previous ones");
    const S inv = S(1) / sqrt(nn);
    for (int i = 0; i < n; ++i) m(i, j) = m(i, j) * inv;
  }
  return m;
}

/// Random unitary matrix: Gram–Schmidt on a complex Gaussian matrix.
template <class S> CMat<S> randomUnitary(std::mt19937_64& g, int n) {
  CMat<S> m(n);
  for (auto& z : m.a) {
    const S re = gauss<S>(g), im = gauss<S>(g);
    z = Cx<S>(re, im);
  }
  return gramSchmidt(m);
}

/// The book's SU(2) matrix [[a+ib, c+id], [−c+id, a−ib]] (GF §2.2.5).
template <class S> CMat<S> su2(const S& a, const S& b, const S& c, const S& d) {
  CMat<S> m(2);
  m(0, 0) = Cx<S>(a, b);
  m(0, 1) = Cx<S>(c, d);
  m(1, 0) = Cx<S>(-c, d);
  m(1, 1) = Cx<S>(a, -b);
  return m;
}
/// The quaternion (a, b, c, d) read back from an SU(2)-shaped matrix (first row).
template <class S> Vec4<S> su2Params(const CMat<S>& m) {
  return Vec4<S>(m(0, 0).re, m(0, 0).im, m(0, 1).re, m(0, 1).im);
}

/// The book's double cover π: SU(2) → SO(3), written out as printed (GF §2.3), in terms of
/// the parameters (a, b, c, d) of the SU(2) matrix.
// GF §2.3, GF-2.3-SU2-double-cover
template <class S> Mat3<S> piSU2(const S& a, const S& b, const S& c, const S& d) {
  Mat3<S> r;
  r << a * a + b * b - c * c - d * d, S(2) * (b * c - a * d), S(2) * (a * c + b * d),
      S(2) * (b * c + a * d), a * a - b * b + c * c - d * d, S(2) * (c * d - a * b),
      S(2) * (b * d - a * c), S(2) * (c * d + a * b), a * a - b * b - c * c + d * d;
  return r;
}
template <class S> Mat3<S> piSU2(const CMat<S>& m) {
  const Vec4<S> p = su2Params(m);
  return piSU2<S>(p(0), p(1), p(2), p(3));
}

/// Projective distance of two vectors: max |u_i v_j − u_j v_i| after normalising both (0 iff
/// u ∝ v). The 2×2-minor test of the catalogue's checks.
template <class S, int N> S projectiveDefect(const Eigen::Matrix<S, N, 1>& u0,
                                            const Eigen::Matrix<S, N, 1>& v0) {
  using std::abs;
  using std::sqrt;
  const auto u = (u0 / sqrt(u0.squaredNorm())).eval();
  const auto v = (v0 / sqrt(v0.squaredNorm())).eval();
  S m(0);
  for (Eigen::Index i = 0; i < u.size(); ++i)
    for (Eigen::Index j = i + 1; j < u.size(); ++j) {
      const S e = abs(u(i) * v(j) - u(j) * v(i));
      if (e > m) m = e;
    }
  return m;
}

}  // namespace soma::studies::gf23
