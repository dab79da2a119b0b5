#pragma once
// Helpers shared by the studies of GF chapter 1 (gf01/*.cpp): random vectors and matrices of any
// size (on chapter 4's draws), and the finite-difference step and error bound the studies use.
// Nothing here is library code.
#include "gf04/common.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include <random>

namespace soma::studies::gf01 {

inline constexpr const char* kChapter = "GF 1 — Introduction";

// Fixed-seed draws and the NaN-propagating maxima are chapter 4's (gf04/common.hpp).
using gf04::maxAbs;
using gf04::maxOf;
using gf04::uniform;
using std::abs;
using std::cos;
using std::pow;
using std::sin;
using std::sqrt;

template <class S> using VecX = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <class S> using MatX = detail::SmallMat<S>;

template <class S> VecX<S> randomVec(std::mt19937_64& g, Eigen::Index n) {
  VecX<S> v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform<S>(g);
  return v;
}
template <class S> MatX<S> randomMat(std::mt19937_64& g, Eigen::Index r, Eigen::Index c) {
  MatX<S> m(r, c);
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < c; ++j) m(i, j) = uniform<S>(g);
  return m;
}
/// Central-difference step h = ε^{1/3}: truncation h²|f'''|/6 and rounding ε|f|/h are both
/// O(ε^{2/3}) — the error bound the derivative checks state in their names.
template <class S> S fdStep() { return pow(Tolerance<S>::epsilon(), S(1) / S(3)); }
template <class S> S fdBound(int factor) { return S(factor) * fdStep<S>() * fdStep<S>(); }

/// A central difference of f (S → Eigen vector) at 0 against an exact derivative, with its error
/// bound derived from the data: D(h) and D(h/2) have errors ≈ ch², ch²/4, so |D(h) − D(h/2)|/3
/// estimates D(h/2)'s truncation error (Richardson); the bound is twice that plus the rounding of
/// the differences, 64ε‖f‖/(h/2). Returns error / bound (≤ 1 passes; an O(1) mistake in `exact`
/// gives a ratio of order 1/h²).
template <class S, class F, class V> S fdRatio(F f, const V& exact, const S& h) {
  const V f1 = f(h), f2 = f(-h), f3 = f(h / S(2)), f4 = f(-h / S(2));
  const V d1 = (f1 - f2) / (S(2) * h), d2 = (f3 - f4) / h;
  const S fScale = maxOf(maxOf(maxAbs(f1), maxAbs(f2)), S(1));
  const S bound = S(2) * maxAbs(V(d1 - d2)) / S(3) + S(64) * Tolerance<S>::epsilon() * fScale / (h / S(2));
  return maxAbs(V(d2 - exact)) / bound;
}

}  // namespace soma::studies::gf01
