#pragma once
// Helpers shared by the studies of GF chapter 7 (gf07/*.cpp): complex matrices (the book works
// over ℂ: J± = Y ± iX), their max-norm, nullities through the real form [[Re, −Im], [Im, Re]]
// (so every rank decision is a real FullPivLU in the working scalar); the random draws are
// chapter 4's (gf04/common.hpp).
// Nothing here is soma library code: the library's representations are in algebra/rep/.
#include "gf04/common.hpp"
#include "soma/algebra/lie_algebra.hpp"
#include "soma/algebra/rep/direct_sum.hpp"
#include "soma/algebra/rep/dual_angle_axis.hpp"
#include "soma/algebra/rep/exterior_power.hpp"
#include "soma/algebra/rep/se3_casimirs.hpp"
#include "soma/algebra/rep/so3_irrep.hpp"
#include "soma/algebra/reciprocal_product.hpp"
#include "soma/algebra/rep/subrepresentation.hpp"
#include "soma/algebra/rep/symmetric_power.hpp"
#include "soma/algebra/screw_bracket.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/riemannian/invariant_metric.hpp"
#include "soma/studies/study.hpp"

#include <Eigen/LU>

#include <complex>
#include <random>
#include <string>

namespace soma::studies::gf07 {

inline constexpr const char* kChapter = "GF 7 — Representation theory";

// Fixed-seed draws and the NaN-propagating max of chapter 4's helpers.
using gf04::maxOf;
using gf04::randomUnit;
using gf04::randomVec;
using gf04::rng;
using gf04::uniform;
using rep::Matrix;
using std::abs;
using std::atan2;
using std::cos;
using std::pow;
using std::sin;
using std::sqrt;

template <class S> using C = std::complex<S>;
template <class S> using CMat = Matrix<std::complex<S>>;
template <class S> using CVec = Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>;

/// |x| for real x, |Re z| + |Im z| (≥ |z|, within √2) for complex z: no complex abs needed.
template <class S> S absOf(const S& x) { return abs(x); }
template <class S> S absOf(const std::complex<S>& z) { return abs(z.real()) + abs(z.imag()); }
template <class T> struct RealOf { using type = T; };
template <class S> struct RealOf<std::complex<S>> { using type = S; };

/// Largest |entry| (NaN if an entry is not finite).
template <class D> typename RealOf<typename D::Scalar>::type maxAbs(const Eigen::MatrixBase<D>& m) {
  using S = typename RealOf<typename D::Scalar>::type;
  S r(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      const S a = absOf(m(i, j));
      if (!isFinite(a)) return a;
      if (a > r) r = a;
    }
  return r;
}
template <class M> M comm(const M& a, const M& b) { return M(a * b - b * a); }

template <class S> C<S> imagUnit() { return C<S>(S(0), S(1)); }
template <class S, int R, int K> CMat<S> toComplex(const Eigen::Matrix<S, R, K>& m) {
  return Matrix<S>(m).template cast<C<S>>();
}

/// [[Re, −Im], [Im, Re]]: the real form of a complex matrix (rank doubles).
template <class S> Matrix<S> realForm(const CMat<S>& m) {
  const Eigen::Index r = m.rows(), k = m.cols();
  Matrix<S> out(2 * r, 2 * k);
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < k; ++j) {
      out(i, j) = m(i, j).real(), out(i, j + k) = -m(i, j).imag();
      out(i + r, j) = m(i, j).imag(), out(i + r, j + k) = m(i, j).real();
    }
  return out;
}
/// Dimension of the null space (columns − rank at Tolerance::rank()).
template <class S> int nullity(const Matrix<S>& m) {
  Eigen::FullPivLU<Matrix<S>> lu(m);
  lu.setThreshold(Tolerance<S>::rank());
  return int(m.cols() - lu.rank());
}
template <class S> int nullity(const CMat<S>& m) { return nullity<S>(realForm<S>(m)) / 2; }
/// Inverse of a complex matrix through its real form.
template <class S> CMat<S> complexInverse(const CMat<S>& m) {
  const Eigen::Index n = m.rows();
  const Matrix<S> inv = Eigen::FullPivLU<Matrix<S>>(realForm<S>(m)).inverse();
  CMat<S> out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) out(i, j) = C<S>(inv(i, j), inv(i + n, j));
  return out;
}
/// Rows stacked: the common null space of several operators is the null space of the stack.
template <class T> Matrix<T> stack(const std::vector<Matrix<T>>& ms) {
  Eigen::Index rows = 0;
  for (const auto& m : ms) rows += m.rows();
  Matrix<T> out(rows, ms.front().cols());
  Eigen::Index r = 0;
  for (const auto& m : ms) out.middleRows(r, m.rows()) = m, r += m.rows();
  return out;
}
/// u ⊗ v of two column vectors (index i·dim v + j).
template <class T> Eigen::Matrix<T, Eigen::Dynamic, 1> kronVec(const Eigen::Matrix<T, Eigen::Dynamic, 1>& u,
                                                               const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) {
  Eigen::Matrix<T, Eigen::Dynamic, 1> out(u.size() * v.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) out.segment(i * v.size(), v.size()) = u(i) * v;
  return out;
}

/// The book's so(3) generators X, Y, Z (3×3, [X, Y] = Z cyclic) and its ladder basis J₃ = Z,
/// J± = Y ± iX (GF §7.3).
template <class S> std::array<Matrix<S>, 3> so3Generators() {
  return {Matrix<S>(skew(Vec3<S>(Vec3<S>::UnitX()))), Matrix<S>(skew(Vec3<S>(Vec3<S>::UnitY()))),
          Matrix<S>(skew(Vec3<S>(Vec3<S>::UnitZ())))};
}
template <class S> struct Ladder {
  CMat<S> J3, Jp, Jm;
};
template <class S> Ladder<S> ladderOf(const Matrix<S>& X, const Matrix<S>& Y, const Matrix<S>& Z) {
  const C<S> i = imagUnit<S>();
  return {toComplex<S>(Z), CMat<S>(toComplex<S>(Y) + i * toComplex<S>(X)), CMat<S>(toComplex<S>(Y) - i * toComplex<S>(X))};
}

template <class S> std::string str(const S& x, int digits = 3) { return toString(x, digits); }

/// GF §6.4's invariant forms on se(3): Q₀ = [[0, I], [I, 0]] (the Klein form) and
/// Q_∞ = [[−2I, 0], [0, 0]] (the book's normalisation; soma's killingMatrixQinf is diag(I, 0)).
template <class S> Mat6<S> bookQ0() { return reciprocalProductMatrix<S>(); }
template <class S> Mat6<S> bookQinf() { return Mat6<S>(S(-2) * killingMatrixQinf<S>()); }

}  // namespace soma::studies::gf07
