#pragma once
// Template bodies of the general-6R solver (general_6r.hpp). Included only by the
// instantiating TUs (soma_instantiate, cmake/SomaInstantiate.cmake) and general_6r_{ceres,nlopt}.cpp.
#include "soma/algebra/cpu_dispatch.hpp"
#include "soma/algebra/sin_cos.hpp"
#include "soma/algebra/small_eigenvalues.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/sub_scaled4.hpp"
#include "soma/algebra/taylor.hpp"
#include "soma/geometry/serial/general_6r.hpp"
#include "soma/algebra/wrap_angle.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <chrono>
#include <complex>
#include <random>
#include <type_traits>

namespace soma {
namespace detail6r {

template <class S> using V14 = Eigen::Matrix<S, 14, 1>;
template <class S> using M14x9 = Eigen::Matrix<S, 14, 9>;
template <class S> using M14x8 = Eigen::Matrix<S, 14, 8>;
template <class S> using M6x9 = Eigen::Matrix<S, 6, 9>;
template <class S> using M12 = Eigen::Matrix<S, 12, 12>;
template <class S> using M24 = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S> using MX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S> using VX = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// The next rung of the scalar ladder (mpfr is the last).
template <class S> struct NextScalar { using type = void; };
template <> struct NextScalar<float> { using type = double; };
template <> struct NextScalar<double> { using type = long double; };
template <> struct NextScalar<long double> { using type = __float128; };
template <> struct NextScalar<__float128> { using type = mpfr::mpreal; };

/// Constant part of a link: Tz(d)·Tx(a)·Rx(α).
template <class S> struct Link {
  S a, d, ca, sa;
};
template <class S> Link<S> linkOf(const DHRow<S>& r) {
  Link<S> k{r.a, r.d, S(0), S(0)};
  sinCos(r.alpha, k.sa, k.ca);
  return k;
}
template <class S> Vec3<S> rx(const Link<S>& k, const Vec3<S>& v) {
  return Vec3<S>(v.x(), k.ca * v.y() - k.sa * v.z(), k.sa * v.y() + k.ca * v.z());
}
template <class S> Vec3<S> rxT(const Link<S>& k, const Vec3<S>& v) {
  return Vec3<S>(v.x(), k.ca * v.y() + k.sa * v.z(), -k.sa * v.y() + k.ca * v.z());
}
/// Rz(g·π/2) and Rz(−g·π/2) for g = 0, 1, 2: exact (the interpolation grid).
template <class S> Vec3<S> rotGrid(const Vec3<S>& v, int g) {
  if (g == 0) return v;
  if (g == 1) return Vec3<S>(-v.y(), v.x(), v.z());
  return Vec3<S>(-v.x(), -v.y(), v.z());
}
template <class S> Vec3<S> rotGridInv(const Vec3<S>& v, int g) {
  if (g == 0) return v;
  if (g == 1) return Vec3<S>(v.y(), -v.x(), v.z());
  return Vec3<S>(-v.x(), -v.y(), v.z());
}

/// Raghavan–Roth's 14 quantities of a line through p with direction l:
/// p, l, p·p, p·l, p×l, (p·p)l − 2(p·l)p. Closed under rigid motions, linearly in R.
template <class S> V14<S> lineQuantities(const Vec3<S>& p, const Vec3<S>& l) {
  V14<S> f;
  const S pp = p.dot(p), pl = p.dot(l);
  f.template segment<3>(0) = p;
  f.template segment<3>(3) = l;
  f(6) = pp;
  f(7) = pl;
  f.template segment<3>(8) = p.cross(l);
  f.template segment<3>(11) = pp * l - S(2) * pl * p;
  return f;
}

/// Values at θ = 0, π/2, π of a + b cos θ + c sin θ → (a, b, c), in place along one axis.
template <class S, std::size_t N> void gridToTrig(std::array<V14<S>, N>& F, int stride, int n) {
  for (int base = 0; base < n; ++base) {
    if ((base / stride) % 3 != 0) continue;
    const V14<S> v0 = F[base], v1 = F[base + stride], v2 = F[base + 2 * stride];
    const V14<S> a = (v0 + v2) / S(2);
    F[base] = a;
    F[base + stride] = (v0 - v2) / S(2);
    F[base + 2 * stride] = v1 - a;
  }
}

/// Coefficients of the half-angle substitution: (1, cos, sin)·(1 + x²) = rows of powers 1, x, x².
template <class S> S halfAngle(int trig, int power) {
  static const int t[3][3] = {{1, 0, 1}, {1, 0, -1}, {0, 2, 0}};
  return S(t[trig][power]);
}

/// 6×9 trigonometric rows in (θ4, θ5) → the 12×12 polynomial block: rows r and 6 + r hold the
/// row polynomial in x4^j x5^k and x4 times it (column j*3 + k, j ≤ 3, k ≤ 2).
template <class S> M12<S> toPolynomialBlock(const M6x9<S>& X) {
  M12<S> M = M12<S>::Zero();
  for (int r = 0; r < 6; ++r)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        S y = S(0);
        for (int i4 = 0; i4 < 3; ++i4) {
          const S h4 = halfAngle<S>(i4, j);
          if (h4 == S(0)) continue;
          for (int i5 = 0; i5 < 3; ++i5) {
            const S h5 = halfAngle<S>(i5, k);
            if (h5 != S(0)) y += h4 * h5 * X(r, i4 * 3 + i5);
          }
        }
        M(r, j * 3 + k) = y;
        M(6 + r, (j + 1) * 3 + k) = y;
      }
  return M;
}

/// Six joint angles with the cosines and sines of the angles they stand for (the joint variables
/// plus any fixed offsets), formed together: the back-substitution gets the cosines and sines
/// from ratios (no sin/cos call), and the polish turns them by each Newton step (no sin/cos call
/// per evaluation of the chain). The angles themselves are only added to.
template <class S> struct Posture6 {
  std::array<S, 6> q, c, s;
};

/// (cos 2φ, sin 2φ) for φ = atan2(n, d), from the ratio: ((d² − n²), 2nd) / (n² + d²), with n and
/// d scaled by the larger first (no overflow); (1, 0) when n = d = 0, as atan2(0, 0) = 0.
template <class S> void doubleAngleOf(const S& n, const S& d, S& c, S& s) {
  using std::abs;
  const S m = std::max<S>(abs(n), abs(d));
  if (!(m > S(0))) {
    c = S(1), s = S(0);
    return;
  }
  const S a = n / m, b = d / m, h = S(1) / (a * a + b * b);
  c = (b - a) * (b + a) * h;
  s = S(2) * a * b * h;
}

/// (cos φ, sin φ) for φ = atan2(y, x): (x, y) / |(x, y)|, scaled first; (1, 0) at the origin.
template <class S> void unitAngleOf(const S& y, const S& x, S& c, S& s) {
  using std::abs;
  using std::sqrt;
  const S m = std::max<S>(abs(x), abs(y));
  if (!(m > S(0))) {
    c = S(1), s = S(0);
    return;
  }
  const S a = x / m, b = y / m, h = S(1) / sqrt(a * a + b * b);
  c = a * h;
  s = b * h;
}

/// sin and cos of a Newton step's angle δ. For |δ| ≤ 1 (the range of the series in
/// algebra/taylor.hpp, summed to the scalar's precision) sin δ = δ − δ³·(δ − sin δ)/δ³ and
/// cos δ = √((1 − sin δ)(1 + sin δ)) (cos δ > 0.54 there: no cancellation), a few multiply-adds
/// and a square root instead of a library sincos; sinCos beyond.
template <class S> void stepSinCos(const S& d, S& sd, S& cd) {
  using std::abs;
  using std::sqrt;
  if (abs(d) <= S(1)) {
    const S d2 = d * d;
    sd = d - d * d2 * detail::thetaMinusSinOverCube(d2);
    cd = sqrt(S((S(1) - sd) * (S(1) + sd)));
    return;
  }
  sinCos(d, sd, cd);
}

/// What the eigenproblem produced: candidate total joint angles (θ_i + q_i) in the unit-scaled
/// problem, and its diagnostics.
template <class S> struct Core {
  std::vector<Posture6<S>> phi;
  std::vector<S> x3;  ///< the real eigenvalue each candidate came from
  int complexCount = 0;
  double rcond = 0, beta = 0, minGap = 0, qRank = 0;
  double deflationDefect = 0;  ///< |lower-left block| / |K| after deflating x3 = ±i
  bool deflated = false;       ///< the eigenvalues came from the deflated 16×16 block
  bool suspicious = false;
  std::vector<std::string> notes;
};

/// Angle of the ratio of consecutive entries of a vector ∝ (1, x, x², …): θ = 2·atan(x),
/// least squares over all pairs, θ = π when x = ∞.
template <class S> S halfAngleFromPairs(const S& num, const S& den) {
  using std::atan2;
  return S(2) * atan2(num, den);
}

/// LU factorisation with partial pivoting of a 12×12 matrix in row-major fixed arrays, factored
/// once and solved several times (the inverse iteration of each real root): Eigen's PartialPivLU
/// takes ~9k instructions to factor at this size, this ~2k; detail::smallSolveInPlace eliminates
/// again for every right-hand side. `ok` is false when a pivot is exactly zero.
template <class S> struct Lu12 {
  S a[12][12];  ///< U (zero below the diagonal)
  S l[12][12];  ///< the multipliers of L below the diagonal (unit diagonal implied)
  S rdiag[12];  ///< 1 / U(i, i): solves multiply (divisions are slow)
  int perm[12];
  bool ok = true;
  S w[12];    ///< during the factorisation: the moduli searched for the next pivot
  int pNext;  ///< during the factorisation: the next pivot row
  Lu12() = default;
  explicit Lu12(const M12<S>& m) { factor(m); }
  /// Factors m; in double on a CPU with AVX2 and FMA by the AVX2 + FMA build of factorBody.
  void factor(const M12<S>& m) {
#ifdef SOMA_X86_AVX2_DISPATCH
    if constexpr (std::is_same_v<S, double>)
      if (detail::cpuHasAvx2Fma()) return factorAvx2(m);
#endif
    factorBody(m);
  }
#ifdef SOMA_X86_AVX2_DISPATCH
  SOMA_TARGET_AVX2_FMA void factorAvx2(const M12<S>& m) { factorBody(m); }
#endif
  [[gnu::always_inline]] inline void factorBody(const M12<S>& m) {
    begin(m);
    for (int c = 0; c < 12; ++c) column(c);
  }
  /// The pivot row: the first of the largest of v[r], r = c..11, compared in two interleaved
  /// chains (even and odd rows) joined at the end (one chain of 11 compares was a third of the
  /// factorisation's critical path).
  [[gnu::always_inline]] static inline int firstLargest(const S* v, int c) {
    S b0 = v[c], b1 = S(-1);
    int i0 = c, i1 = c;
    int r = c + 1;
    for (; r + 1 < 12; r += 2) {
      if (v[r] > b1) b1 = v[r], i1 = r;
      if (v[r + 1] > b0) b0 = v[r + 1], i0 = r + 1;
    }
    if (r < 12 && v[r] > b1) b1 = v[r], i1 = r;
    return b1 > b0 || (b1 == b0 && i1 < i0) ? i1 : i0;
  }
  /// The factorisation in steps (factorTogether runs several in lockstep): the copy and the first
  /// pivot, then column c's elimination.
  [[gnu::always_inline]] inline void begin(const M12<S>& m) {
    using std::abs;
    ok = true;
    for (int i = 0; i < 12; ++i) {
      perm[i] = i;
      for (int j = 0; j < 12; ++j) a[i][j] = m(i, j);
    }
    for (int r = 0; r < 12; ++r) w[r] = abs(a[r][0]);
    pNext = firstLargest(w, 0);
  }
  [[gnu::always_inline]] inline void column(int c) {
    using std::abs;
    // In hardware floating point every row update runs over whole vectors of four columns, from
    // the one that holds the pivot's column (the entries left of the pivot are zeros on both
    // rows): trip counts that vectorise without a remainder, ~2× fewer instructions than the
    // shrinking loop, which software scalars keep.
    constexpr bool fullRows = std::is_same_v<S, double> || std::is_same_v<S, float>;
    if (!ok) return;
    int p = pNext;
    // p was chosen (below) from the entries of column c times the pivot before them, formed
    // without 1/pivot: the search overlaps the division and the row updates. The entry it
    // chose is the largest up to rounding; if it is exactly zero, the entries are searched.
    if (a[p][c] == S(0)) {
      for (int r = c; r < 12; ++r) w[r] = abs(a[r][c]);
      p = firstLargest(w, c);
      if (a[p][c] == S(0)) {
        ok = false;
        return;
      }
    }
    if (p != c) {
      for (int j = 0; j < 12; ++j) std::swap(a[p][j], a[c][j]);
      for (int j = 0; j < c; ++j) std::swap(l[p][j], l[c][j]);
      std::swap(perm[p], perm[c]);
    }
    rdiag[c] = S(1) / a[c][c];
    if (c + 1 < 12) {  // column c + 1 after this elimination, times the pivot u = a[c][c]
      const S u = a[c][c], h = a[c][c + 1];
      for (int r = c + 1; r < 12; ++r) w[r] = abs(S(a[r][c + 1] * u - a[r][c] * h));
      pNext = firstLargest(w, c + 1);
    }
    for (int r = c + 1; r < 12; ++r) {
      const S f = a[r][c] * rdiag[c];
      l[r][c] = f;
      if constexpr (fullRows) {  // from the vector of four that holds column c (zeros before it)
        for (int j = c & ~3; j < 12; j += 4) detail::subScaled4(&a[r][j], &a[c][j], f);
      } else {
        for (int j = c + 1; j < 12; ++j) a[r][j] -= f * a[c][j];
      }
      a[r][c] = S(0);
    }
  }
  /// b ← M⁻ᵀ b (PM = LU: Uᵀ z = b, Lᵀ w = z, b(perm) = w).
  void solveTransposed(Eigen::Matrix<S, 12, 1>& b) const {
    S z[12];
    for (int i = 0; i < 12; ++i) {
      S v = b(i);
      for (int k = 0; k < i; ++k) v -= a[k][i] * z[k];
      z[i] = v * rdiag[i];
    }
    for (int i = 11; i >= 0; --i) {
      S v = z[i];
      for (int k = i + 1; k < 12; ++k) v -= l[k][i] * z[k];
      z[i] = v;
    }
    for (int i = 0; i < 12; ++i) b(perm[i]) = z[i];
  }
  /// Reciprocal condition number in the 1-norm, 1 / (‖M‖₁ · est ‖M⁻¹‖₁), by Hager's estimator with
  /// Higham's alternating-sign safeguard: the algorithm of Eigen's PartialPivLU::rcond()
  /// (ConditionEstimator.h, step for step), on this factorisation (Eigen's LU + rcond cost ~20k
  /// instructions here, this ~3k). `l1` = ‖M‖₁; 0 when the factorisation failed.
  S rcond(const S& l1) const {
    using std::abs;
    if (!ok || !(l1 > S(0))) return S(0);
    using V = Eigen::Matrix<S, 12, 1>;
    auto norm1 = [](const V& x) {
      S t = S(0);
      for (int i = 0; i < 12; ++i) t += abs(x(i));
      return t;
    };
    V v = V::Constant(S(1) / S(12));
    solve(v);
    S lower = norm1(v), oldLower = lower;
    V sign, oldSign;
    int vmax = -1, oldVmax = -1;
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < 12; ++i) sign(i) = v(i) < S(0) ? S(-1) : S(1);
      if (k > 0 && sign == oldSign) break;
      v = sign;
      solveTransposed(v);
      vmax = 0;
      for (int i = 1; i < 12; ++i)
        if (abs(v(i)) > abs(v(vmax))) vmax = i;
      if (vmax == oldVmax) break;
      v = V::Unit(vmax);
      solve(v);
      lower = norm1(v);
      if (lower <= oldLower) break;
      oldSign = sign;
      oldVmax = vmax;
      oldLower = lower;
    }
    S alt = S(1);
    for (int i = 0; i < 12; ++i) {
      v(i) = alt * (S(1) + S(i) / S(11));
      alt = -alt;
    }
    solve(v);
    const S inv = std::max<S>(lower, S(2) * norm1(v) / S(36));
    return inv == S(0) ? S(0) : S(S(1) / inv / l1);
  }
  /// X ← M⁻¹ X for K right-hand sides at once, row by row (each row update runs along the K
  /// columns: no dependency chain; the same operations in the same order as `solve` on each column).
  template <int K> void solveColumns(Eigen::Matrix<S, 12, K>& X) const {
#ifdef SOMA_X86_AVX2_DISPATCH
    if constexpr (std::is_same_v<S, double>)
      if (detail::cpuHasAvx2Fma()) return solveColumnsAvx2<K>(X);
#endif
    solveColumnsBody<K>(X);
  }
#ifdef SOMA_X86_AVX2_DISPATCH
  template <int K> SOMA_TARGET_AVX2_FMA void solveColumnsAvx2(Eigen::Matrix<S, 12, K>& X) const {
    solveColumnsBody<K>(X);
  }
#endif
  // Plain loops over the K columns, not Eigen's row expressions: those are built for the TU's
  // instruction set (SSE2), these are vectorised for the function's (AVX2 + FMA in solveColumnsAvx2).
  template <int K> [[gnu::always_inline]] inline void solveColumnsBody(Eigen::Matrix<S, 12, K>& X) const {
    S y[12][K];
    for (int i = 0; i < 12; ++i) {
      for (int c = 0; c < K; ++c) y[i][c] = X(perm[i], c);
      for (int k = 0; k < i; ++k) {
        const S f = l[i][k];
        for (int c = 0; c < K; ++c) y[i][c] -= f * y[k][c];
      }
    }
    for (int i = 11; i >= 0; --i) {
      for (int k = i + 1; k < 12; ++k) {
        const S f = a[i][k];
        for (int c = 0; c < K; ++c) y[i][c] -= f * y[k][c];
      }
      const S r = rdiag[i];
      for (int c = 0; c < K; ++c) X(i, c) = y[i][c] *= r;
    }
  }
  /// b ← M⁻¹ b (forward substitution with the unit lower factor, then back substitution).
  void solve(Eigen::Matrix<S, 12, 1>& b) const {
    S y[12];
    for (int i = 0; i < 12; ++i) {
      S v = b(perm[i]);
      for (int k = 0; k < i; ++k) v -= l[i][k] * y[k];
      y[i] = v;
    }
    for (int i = 11; i >= 0; --i) {
      S v = y[i];
      for (int k = i + 1; k < 12; ++k) v -= a[i][k] * b(k);
      b(i) = v * rdiag[i];
    }
  }
};

/// Factors m[0..n) into lu[0..n) in lockstep, column after column across the matrices: each
/// factorisation is a chain of 12 dependent pivot steps (search, division, update), and the
/// independent chains of the back-substitution's matrices (one per real root) overlap in the CPU.
/// The same operations as Lu12::factor on each. In double on a CPU with AVX2 and FMA by its AVX2 +
/// FMA build.
template <class S> [[gnu::always_inline]] inline void factorTogetherBody(Lu12<S>* lu, const M12<S>* m, int n) {
  for (int i = 0; i < n; ++i) lu[i].begin(m[i]);
  for (int c = 0; c < 12; ++c)
    for (int i = 0; i < n; ++i) lu[i].column(c);
}
#ifdef SOMA_X86_AVX2_DISPATCH
template <class S> SOMA_TARGET_AVX2_FMA void factorTogetherAvx2(Lu12<S>* lu, const M12<S>* m, int n) {
  factorTogetherBody<S>(lu, m, n);
}
#endif
template <class S> void factorTogether(Lu12<S>* lu, const M12<S>* m, int n) {
#ifdef SOMA_X86_AVX2_DISPATCH
  if constexpr (std::is_same_v<S, double>)
    if (detail::cpuHasAvx2Fma()) return factorTogetherAvx2<S>(lu, m, n);
#endif
  factorTogetherBody<S>(lu, m, n);
}

/// Householder QR with column pivoting of a 14×8 matrix, Q·R = M·P: Eigen's ColPivHouseholderQR
/// (3.4, computeInPlace) step for step — the largest remaining column norm as pivot, the reflector
/// of makeHouseholderInPlace, the norm downdate of LAPACK working note 176 with its recomputation,
/// nonzero pivots counted against the same threshold — on fixed arrays (Eigen's runs on dynamic
/// blocks at this size: 11.5k instructions a pose, this 6.9k). It differs from Eigen's only in
/// rounding (a reciprocal where Eigen divides, another summation order). Layout as Eigen's
/// matrixQR(): R on and above the diagonal, reflector k's essential part below it (its first
/// entry 1 implied). Tested against ColPivHouseholderQR (tests/geometry/serial/general_6r_kernels.cpp).
template <class S> struct Qr14x8 {
  M14x8<S> qr;
  S tau[8];        ///< reflector k is I − τ_k v vᵀ
  int perm[8];     ///< column i of M·P is column perm[i] of M
  int nonzero = 8; ///< Eigen's nonzeroPivots()
  explicit Qr14x8(const M14x8<S>& m) : qr(m) {
    using std::abs;
    using std::sqrt;
    constexpr int rows = 14, cols = 8;
    const S eps = Tolerance<S>::epsilon();
    S normU[cols], normD[cols];
    S maxNorm = S(0);
    for (int j = 0; j < cols; ++j) {
      S t = S(0);
      for (int i = 0; i < rows; ++i) t += qr(i, j) * qr(i, j);
      normD[j] = normU[j] = sqrt(t);
      if (j == 0 || normU[j] > maxNorm) maxNorm = normU[j];
      perm[j] = j;
    }
    const S thresholdHelper = (maxNorm * eps) * (maxNorm * eps) / S(rows);
    const S downdate = sqrt(eps);
    for (int k = 0; k < cols; ++k) {
      int big = k;
      for (int j = k + 1; j < cols; ++j)
        if (normU[j] > normU[big]) big = j;
      if (nonzero == cols && normU[big] * normU[big] < thresholdHelper * S(rows - k)) nonzero = k;
      if (big != k) {
        for (int i = 0; i < rows; ++i) std::swap(qr(i, k), qr(i, big));
        std::swap(normU[k], normU[big]);
        std::swap(normD[k], normD[big]);
        std::swap(perm[k], perm[big]);
      }
      // makeHouseholderInPlace on rows k..13 of column k
      S tail = S(0);
      for (int i = k + 1; i < rows; ++i) tail += qr(i, k) * qr(i, k);
      const S c0 = qr(k, k);
      S beta;
      if (tail <= std::numeric_limits<S>::min()) {
        tau[k] = S(0);
        beta = c0;
        for (int i = k + 1; i < rows; ++i) qr(i, k) = S(0);
      } else {
        beta = sqrt(c0 * c0 + tail);
        if (c0 >= S(0)) beta = -beta;
        const S inv = S(1) / (c0 - beta);
        for (int i = k + 1; i < rows; ++i) qr(i, k) *= inv;
        tau[k] = (beta - c0) / beta;
      }
      qr(k, k) = beta;
      // applyHouseholderOnTheLeft on rows k..13 of columns k+1..7, with v padded by zeros above
      // row k: every loop runs over the 14 rows (a fixed trip count; the zeros add nothing).
      if (tau[k] != S(0)) {
        S v[rows];
        for (int i = 0; i < rows; ++i) v[i] = i > k ? S(qr(i, k)) : S(i == k ? 1 : 0);
        for (int j = k + 1; j < cols; ++j) {
          S* c = &qr(0, j);
          S d = S(0);
          for (int i = 0; i < rows; ++i) d += v[i] * c[i];
          d *= tau[k];
          for (int i = 0; i < rows; ++i) c[i] -= d * v[i];
        }
      }
      for (int j = k + 1; j < cols; ++j) {  // norm downdate (LAWN 176, as xGEQPF)
        if (normU[j] == S(0)) continue;
        S t = abs(qr(k, j)) / normU[j];
        t = (S(1) + t) * (S(1) - t);
        if (t < S(0)) t = S(0);
        const S ratio = normU[j] / normD[j];
        if (t * (ratio * ratio) <= downdate) {
          S sq = S(0);
          for (int i = k + 1; i < rows; ++i) sq += qr(i, j) * qr(i, j);
          normD[j] = normU[j] = sqrt(sq);
        } else {
          normU[j] *= sqrt(t);
        }
      }
    }
  }
  const M14x8<S>& matrixQR() const { return qr; }
};

/// Working storage of the small eigenproblems: a fixed 24×24 array, the active size n ≤ 24.
template <class S> using Work24 = Eigen::Matrix<S, 24, 24>;

/// Deflation of the extraneous eigenvalues x3 = ±i of the companion matrix K of
/// M(x) = A x² + B x + C (K is 24×24 in the first block of `H`; on success the 16×16 block
/// with the genuine eigenvalues is left in the first block of `H`). M(i) = (C − A) + iB has a
/// 4-dimensional kernel (the factor (1 + x3²)⁴ of det M), found by Gaussian elimination with
/// complete pivoting on the 12×12 complex matrix (in real arithmetic; its rank must be 8, pivots
/// above √eps of the first): the kernel basis v_1..v_4 gives the 8-dimensional real kernel of
/// Z = [[C − A, −B], [B, C − A]] acting on (Re w, Im w), w = v_j and i v_j (before: a full-pivot LU
/// of that 24×24 real Z, 5× the work).
/// The eigenvectors of K are (v, x v), so {(Re v, −Im v)} spans the real invariant subspace of
/// ±i; an elementary (Gauss) similarity T with T·basis = [I; 0] (complete pivoting, below) makes
/// TKT⁻¹ block upper triangular, its trailing 16×16 block carrying the 16 genuine eigenvalues
/// (before: 8 Householder reflectors on both sides of K, 8× the work). `defect` = (1 + ‖G‖)²
/// |lower-left 16×8 block| / |K|, the backward error of dropping that block: the deflation is used
/// when it is at round-off (Tolerance::identity(4096)); otherwise false and H still holds K.
// Manocha & Canny (1994) eigenproblem; GF §11.5 (16 postures)
template <class S>
[[gnu::always_inline]] inline bool deflateExtraneousBody(Work24<S>& H, const M12<S>& A, const M12<S>& B,
                                                         const M12<S>& C, S& defect) {
  using std::abs;
  using std::sqrt;
  M12<S> zr = C - A, zi = B;  // M(i) = zr + i zi, eliminated in place
  std::array<int, 12> col;    // col[c]: the original column now at position c
  for (int c = 0; c < 12; ++c) col[c] = c;
  defect = S(1);
  const S thr2 = Tolerance<S>::epsilon();  // (√eps)²: pivots compared in squared modulus
  // The pivot is the first entry of largest squared modulus in column-major order, found from
  // the columns' maxima (each column's a short chain of its own; one chain through the whole
  // block kept the search on the critical path): the same pivot as a search entry by entry.
  std::array<S, 12> colMax;
  std::array<int, 12> colArg;
  auto pivotOf = [&](int k, int& p, int& q) {
    S best = S(-1);
    q = k;
    for (int j = k; j < 12; ++j)
      if (colMax[j] > best) best = colMax[j], q = j;
    p = colArg[q];
    return best;
  };
  for (int j = 0; j < 12; ++j) {
    S m = S(-1);
    int a = 0;
    for (int i = 0; i < 12; ++i) {
      const S m2 = zr(i, j) * zr(i, j) + zi(i, j) * zi(i, j);
      const bool g = m2 > m;
      m = g ? m2 : m;
      a = g ? i : a;
    }
    colMax[j] = m;
    colArg[j] = a;
  }
  S first2 = S(0);
  int rank = 0;
  int p = 0, q = 0;
  S best = pivotOf(0, p, q);
  for (int k = 0; k < 12; ++k) {
    if (k == 0) first2 = best;
    if (!(best > thr2 * first2) || !(best > S(0))) break;
    zr.row(k).swap(zr.row(p));
    zi.row(k).swap(zi.row(p));
    zr.col(k).swap(zr.col(q));
    zi.col(k).swap(zi.col(q));
    std::swap(col[k], col[q]);
    std::swap(colMax[k], colMax[q]);
    std::swap(colArg[k], colArg[q]);
    const S pr = zr(k, k), pim = zi(k, k), inv = S(1) / best;  // 1 / pivot = conj(pivot) / |pivot|²
    std::array<S, 12> fr{}, fi{};
    for (int i = k + 1; i < 12; ++i) {
      fr[i] = (zr(i, k) * pr + zi(i, k) * pim) * inv;
      fi[i] = (zi(i, k) * pr - zr(i, k) * pim) * inv;
      zr(i, k) = zi(i, k) = S(0);
    }
    rank = k + 1;
    if (k == 11) break;
    if constexpr (std::is_same_v<S, double>) {
      // Four rows at a time from the vector of four that holds row k + 1 (the rows above it have
      // multipliers zero: left as they are, and out of the search); per lane the first largest,
      // then the first largest of the four lanes: the same pivot as row after row.
      using V4 = detail::Double4;
      typedef long long I4 __attribute__((vector_size(32)));
      const int c0 = (k + 1) >> 2;
      const I4 lane = {0, 1, 2, 3};
      for (int j = k + 1; j < 12; ++j) {
        const double ur = zr(k, j), ui = zi(k, j);
        V4 bestV = {-1.0, -1.0, -1.0, -1.0};
        I4 argV = {k + 1, k + 1, k + 1, k + 1};
        for (int c = c0; c < 3; ++c) {
          V4& xr = *reinterpret_cast<V4*>(&zr(4 * c, j));
          V4& xi = *reinterpret_cast<V4*>(&zi(4 * c, j));
          const V4 vr = *reinterpret_cast<const V4*>(&fr[4 * c]);
          const V4 vi = *reinterpret_cast<const V4*>(&fi[4 * c]);
          const V4 r = xr - (vr * ur - vi * ui), t = xi - (vr * ui + vi * ur);
          xr = r;
          xi = t;
          V4 m2 = r * r + t * t;
          const I4 row = lane + 4 * c;
          const V4 none = {-1.0, -1.0, -1.0, -1.0};
          if (c == c0) m2 = row > k ? m2 : none;
          const I4 g = m2 > bestV;
          bestV = g ? m2 : bestV;
          argV = g ? row : argV;
        }
        double m = bestV[0];
        int a = int(argV[0]);
        for (int l = 1; l < 4; ++l)
          if (bestV[l] > m || (bestV[l] == m && int(argV[l]) < a)) m = bestV[l], a = int(argV[l]);
        colMax[j] = m;
        colArg[j] = a;
      }
      best = pivotOf(k + 1, p, q);
      continue;
    }
    for (int j = k + 1; j < 12; ++j) {
      const S ur = zr(k, j), ui = zi(k, j);
      S m = S(-1);
      int a = k + 1;
      for (int i = k + 1; i < 12; ++i) {
        const S r = zr(i, j) - (fr[i] * ur - fi[i] * ui), t = zi(i, j) - (fr[i] * ui + fi[i] * ur);
        zr(i, j) = r;
        zi(i, j) = t;
        const S m2 = r * r + t * t;
        const bool g = m2 > m;
        m = g ? m2 : m;
        a = g ? i : a;
      }
      colMax[j] = m;
      colArg[j] = a;
    }
    best = pivotOf(k + 1, p, q);
  }
  if (rank != 8) return false;
  // The kernel: y_{8+j} = 1, the others of 8..11 zero, y_0..7 from U11 y = −U12 e_j, the four
  // right-hand sides together, each pivot's reciprocal conj(u)/|u|² formed once.
  std::array<S, 8> ur, ui;
  for (int r = 0; r < 8; ++r) {
    const S d2 = S(1) / (zr(r, r) * zr(r, r) + zi(r, r) * zi(r, r));
    ur[r] = zr(r, r) * d2;
    ui[r] = -zi(r, r) * d2;
  }
  S yr[4][12] = {}, yi[4][12] = {};
  for (int j = 0; j < 4; ++j) yr[j][8 + j] = S(1);
  for (int r = 7; r >= 0; --r)
    for (int j = 0; j < 4; ++j) {
      S sr = -zr(r, 8 + j), si = -zi(r, 8 + j);
      for (int c = r + 1; c < 8; ++c) {
        sr -= zr(r, c) * yr[j][c] - zi(r, c) * yi[j][c];
        si -= zr(r, c) * yi[j][c] + zi(r, c) * yr[j][c];
      }
      yr[j][r] = sr * ur[r] - si * ui[r];
      yi[j][r] = sr * ui[r] + si * ur[r];
    }
  Eigen::Matrix<S, 24, 8> W;  // columns 2j, 2j + 1: (Re w, −Im w) for w = v_j and i v_j
  for (int j = 0; j < 4; ++j)
    for (int c = 0; c < 12; ++c) {
      const int i = col[c];
      W(i, 2 * j) = yr[j][c];
      W(12 + i, 2 * j) = -yi[j][c];
      W(i, 2 * j + 1) = -yi[j][c];
      W(12 + i, 2 * j + 1) = -yr[j][c];
    }
  // Gauss–Jordan with complete pivoting on the columns of W: W Z1⁻¹ = [I; G] on its pivot rows
  // (8 rows p_k; G the 16×8 rest, |G| small by the pivoting). With Π the permutation putting the
  // pivot rows first and T = [[I, 0], [−G, I]]Π, T W = [I; 0]: T K T⁻¹ is block upper triangular,
  // its trailing block N = K22 − G K12 (16×16) carries the 16 genuine eigenvalues and its
  // lower-left block D = N G + K21 − G K11 vanishes up to round-off. This elementary similarity
  // costs ~2k multiply-adds where the 8 Householder reflectors on both sides of K cost ~16k.
  // A pivot row is zero in every column not yet used (set so below): the search needs no mask.
  std::array<int, 8> prow, pcol;
  std::array<bool, 24> isPivot{};
  std::array<bool, 8> usedCol{};
  for (int k = 0; k < 8; ++k) {
    int c = -1;
    S bestW = S(0);
    for (int j = 0; j < 8; ++j) {
      if (usedCol[j]) continue;
      S m = S(0);
      if constexpr (std::is_same_v<S, double>) {
        // six vectors of four, maxima in a tree (a running max is one chain of 24 dependent
        // compares: the compiler may not reorder it), then across the lanes; the same maximum
        using V4 = detail::Double4;
        V4 v[6];
        for (int b = 0; b < 6; ++b) {
          const V4 x = *reinterpret_cast<const V4*>(&W(4 * b, j)), y = -x;
          v[b] = x > y ? x : y;
        }
        for (int b = 0; b < 3; ++b) v[b] = v[b + 3] > v[b] ? v[b + 3] : v[b];
        v[0] = v[1] > v[0] ? v[1] : v[0];
        v[0] = v[2] > v[0] ? v[2] : v[0];
        for (int l = 0; l < 4; ++l) m = std::max<S>(m, v[0][l]);
      } else {
        for (int i = 0; i < 24; ++i) m = std::max<S>(m, abs(W(i, j)));
      }
      if (m > bestW) bestW = m, c = j;
    }
    if (c < 0) return false;
    int pr = 0;
    while (pr < 23 && !(abs(W(pr, c)) == bestW)) ++pr;
    isPivot[pr] = usedCol[c] = true;
    prow[k] = pr;
    pcol[k] = c;
    const S inv = S(1) / W(pr, c);
    for (int i = 0; i < 24; ++i) W(i, c) *= inv;
    W(pr, c) = S(1);
    for (int j = 0; j < 8; ++j) {
      if (j == c) continue;
      const S f = W(pr, j);
      if (f == S(0)) continue;
      for (int i = 0; i < 24; ++i) W(i, j) -= f * W(i, c);
      W(pr, j) = S(0);
    }
  }
  std::array<int, 16> rest;
  for (int i = 0, r = 0; i < 24; ++i)
    if (!isPivot[i]) rest[r++] = i;
  // The blocks of Π K Πᵀ, contiguous (the products below vectorise).
  Eigen::Matrix<S, 16, 8> G, K21;
  Eigen::Matrix<S, 8, 16> K12;
  Eigen::Matrix<S, 8, 8> K11;
  Eigen::Matrix<S, 16, 16> K22;
  for (int k = 0; k < 8; ++k)
    for (int r = 0; r < 16; ++r) G(r, k) = W(rest[r], pcol[k]);
  for (int s = 0; s < 16; ++s)
    for (int r = 0; r < 16; ++r) K22(r, s) = H(rest[r], rest[s]);
  for (int s = 0; s < 16; ++s)
    for (int k = 0; k < 8; ++k) K12(k, s) = H(prow[k], rest[s]);
  for (int l = 0; l < 8; ++l) {
    for (int r = 0; r < 16; ++r) K21(r, l) = H(rest[r], prow[l]);
    for (int k = 0; k < 8; ++k) K11(k, l) = H(prow[k], prow[l]);
  }
  const S gn = G.norm(), kn = H.norm();
  // Plain loops, not Eigen's products: those are built for the TU's instruction set (SSE2), these
  // are vectorised by the compiler for this function's (AVX2 + FMA in deflateExtraneousAvx2). The
  // rows of K with a pivot in the upper half are unit vectors (K = [[0, I], [·, ·]]): their zeros
  // are skipped.
  Eigen::Matrix<S, 16, 16> Nm = K22;
  for (int s = 0; s < 16; ++s)
    for (int k = 0; k < 8; ++k) {
      const S f = K12(k, s);
      if (f != S(0))
        for (int r = 0; r < 16; ++r) Nm(r, s) -= G(r, k) * f;
    }
  // D = N G + K21 − G K11, measured as the backward error it stands for in K's coordinates:
  // ‖T⁻¹ [[0, 0], [D, 0]] T‖ ≤ (1 + ‖G‖)² ‖D‖.
  S dn = S(0), dn2[16] = {};  // sums of squares by row: no chain through one sum
  for (int l = 0; l < 8; ++l) {
    S d[16];
    for (int r = 0; r < 16; ++r) d[r] = K21(r, l);
    for (int s = 0; s < 16; ++s) {
      const S g = G(s, l);
      for (int r = 0; r < 16; ++r) d[r] += Nm(r, s) * g;
    }
    for (int k = 0; k < 8; ++k) {
      const S f = K11(k, l);
      if (f != S(0))
        for (int r = 0; r < 16; ++r) d[r] -= G(r, k) * f;
    }
    for (int r = 0; r < 16; ++r) dn2[r] += d[r] * d[r];
  }
  for (int r = 0; r < 16; ++r) dn += dn2[r];
  const S grow = (S(1) + gn) * (S(1) + gn);
  defect = kn > S(0) ? S(grow * sqrt(dn) / kn) : S(1);
  if (!(defect <= Tolerance<S>::identity(4096))) return false;
  H.template topLeftCorner<16, 16>() = Nm;
  return true;
}
#ifdef SOMA_X86_AVX2_DISPATCH
template <class S>
SOMA_TARGET_AVX2_FMA bool deflateExtraneousAvx2(Work24<S>& H, const M12<S>& A, const M12<S>& B, const M12<S>& C,
                                                S& defect) {
  return deflateExtraneousBody<S>(H, A, B, C, defect);
}
#endif
/// deflateExtraneousBody; in double on a CPU with AVX2 and FMA by its AVX2 + FMA build
/// (soma/algebra/cpu_dispatch.hpp).
template <class S>
bool deflateExtraneous(Work24<S>& H, const M12<S>& A, const M12<S>& B, const M12<S>& C, S& defect) {
#ifdef SOMA_X86_AVX2_DISPATCH
  if constexpr (std::is_same_v<S, double>)
    if (detail::cpuHasAvx2Fma()) return deflateExtraneousAvx2<S>(H, A, B, C, defect);
#endif
  return deflateExtraneousBody<S>(H, A, B, C, defect);
}

/// The closed loop Rz(φ1)·K1·Rz(φ2)·K2···Rz(φ6)·K6 = I of a 6R chain reaching T: K_i = G_i =
/// Tz(d_i)·Tx(a_i)·Rx(α_i) for i < 6 and K6 = G6·T⁻¹ (each K: v ↦ R v + t).
template <class S> struct Loop6R {
  std::array<Mat3<S>, 6> R;
  std::array<Vec3<S>, 6> t;
};
template <class S> Loop6R<S> loopOf(const Robot6R<S>& rb, const Mat3<S>& RT, const Vec3<S>& tT) {
  Loop6R<S> K;
  for (int i = 0; i < 6; ++i) {
    const Link<S> k = linkOf(rb[i]);
    K.R[i] << S(1), S(0), S(0), S(0), k.ca, -k.sa, S(0), k.sa, k.ca;
    K.t[i] = Vec3<S>(k.a, S(0), k.d);
  }
  K.R[5] = (K.R[5] * RT.transpose()).eval();
  K.t[5] = K.t[5] - K.R[5] * tT;
  return K;
}

/// The same loop read from joint `shift` + 1 on (a cyclic relabelling), backwards when
/// `reverse` (the inverse loop Rz(−φ6)·K5⁻¹···Rz(−φ1)·K6⁻¹ = I): each eliminates another joint
/// last. Joint i' of the relabelled loop is joint jointOf(i') of the chain, its angle negated
/// when reversed.
template <class S> Loop6R<S> relabelled(const Loop6R<S>& K, int shift, bool reverse) {
  Loop6R<S> C;
  for (int i = 0; i < 6; ++i) {
    C.R[i] = K.R[(i + shift) % 6];
    C.t[i] = K.t[(i + shift) % 6];
  }
  if (!reverse) return C;
  Loop6R<S> V;
  for (int i = 0; i < 6; ++i) {
    const int j = (10 - i) % 6;  // K'_i = K_{5−i}⁻¹ (0-based, K_{−1} = K_5)
    V.R[i] = C.R[j].transpose();
    V.t[i] = -(V.R[i] * C.t[j]);
  }
  return V;
}
inline int relabelledJoint(int i, int shift, bool reverse) { return ((reverse ? 5 - i : i) + shift) % 6; }

// GF §11.5 (16 postures of the general 6R); Raghavan–Roth elimination, Manocha–Canny eigenproblem.
template <class S>
Core<S> eigenCore(const Loop6R<S>& K, bool probe = false) {
  using std::abs;
  using std::atan;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  Core<S> out;
  const Vec3<S> ez(S(0), S(0), S(1));

  // Left side G2·Rz(θ3)·G3·Rz(θ4)·G4·Rz(θ5)·G5 applied to (origin, e_z), on the 3×3×3 grid.
  std::array<V14<S>, 27> F;
  {
    const Vec3<S> p5 = K.t[4], l5 = K.R[4].col(2);
    for (int g5 = 0; g5 < 3; ++g5) {
      const Vec3<S> p4 = K.R[3] * rotGrid(p5, g5) + K.t[3];
      const Vec3<S> l4 = K.R[3] * rotGrid(l5, g5);
      for (int g4 = 0; g4 < 3; ++g4) {
        const Vec3<S> p3 = K.R[2] * rotGrid(p4, g4) + K.t[2];
        const Vec3<S> l3 = K.R[2] * rotGrid(l4, g4);
        for (int g3 = 0; g3 < 3; ++g3) {
          const Vec3<S> p2 = K.R[1] * rotGrid(p3, g3) + K.t[1];
          const Vec3<S> l2 = K.R[1] * rotGrid(l3, g3);
          F[g3 * 9 + g4 * 3 + g5] = lineQuantities(p2, l2);
        }
      }
    }
  }
  gridToTrig(F, 1, 27);
  gridToTrig(F, 3, 27);
  gridToTrig(F, 9, 27);

  // Right side Rz(−θ2)·K1⁻¹·Rz(−θ1)·K6⁻¹ applied to (origin, e_z), on the 3×3 grid
  // (K6⁻¹ = T·G6⁻¹ for the chain as given).
  std::array<V14<S>, 9> H;
  {
    const Vec3<S> pT = -(K.R[5].transpose() * K.t[5]), lT = K.R[5].row(2).transpose();
    for (int g1 = 0; g1 < 3; ++g1) {
      const Vec3<S> p1 = K.R[0].transpose() * Vec3<S>(rotGridInv(pT, g1) - K.t[0]);
      const Vec3<S> l1 = K.R[0].transpose() * rotGridInv(lT, g1);
      for (int g2 = 0; g2 < 3; ++g2)
        H[g1 * 3 + g2] = lineQuantities(rotGridInv(p1, g2), rotGridInv(l1, g2));
    }
  }
  gridToTrig(H, 1, 9);
  gridToTrig(H, 3, 9);

  // P_k (k = 1, cos θ3, sin θ3): 14×9 in the monomials of θ4, θ5; Q: 14×8 in those of θ1, θ2.
  std::array<M14x9<S>, 3> P;
  for (int i3 = 0; i3 < 3; ++i3)
    for (int c = 0; c < 9; ++c) P[i3].col(c) = F[i3 * 9 + c];
  P[0].col(0) -= H[0];
  M14x8<S> Q;
  for (int c = 0; c < 8; ++c) Q.col(c) = H[c + 1];

  // Left null space of Q (6×14): the last 6 columns of the Householder Q of Q.
  const Qr14x8<S> qr(Q);
  const S r00 = abs(qr.matrixQR()(0, 0)), r77 = abs(qr.matrixQR()(7, 7));
  out.qRank = r00 > S(0) ? toDouble(r77 / r00) : 0.0;
  if (!(r77 > Tolerance<S>::rank() * r00)) {
    out.suspicious = true;
    out.notes.push_back("the 14×8 matrix of the θ1, θ2 monomials is rank-deficient (|r88/r11| = " +
                        toString(toDouble(out.qRank), 3) +
                        "): special geometry, θ1 and θ2 are not determined by elimination");
  }
  // Only the last 6 columns of Q (the reflectors applied to [0; I6]), and coefficient-based
  // products: Eigen's blocked GEMM packs its operands for these 6×14×9 products (~11k
  // instructions a pose), the full 14×14 Q costs twice the 14×6 one.
  Eigen::Matrix<S, 14, 6> Q6 = Eigen::Matrix<S, 14, 6>::Zero();
  Q6.template bottomRows<6>().setIdentity();
  // Reflector k of the QR: I − τ_k v vᵀ with v = (1, matrixQR(k+1.., k)) on rows k..13; applied
  // here by hand (Eigen's HouseholderSequence on these dynamic-length blocks cost ~4k instructions
  // per application, this ~0.3k).
  const M14x8<S>& qrm = qr.matrixQR();
  auto reflect = [&](int k, S* x) {  // x ← (I − τ_k v vᵀ) x, x of length 14
    // vᵀx as two partial sums (odd and even i: two chains of dependent adds, each half as long)
    S d = x[k], d1 = S(0);
    int i = k + 1;
    for (; i + 1 < 14; i += 2) {
      d += qrm(i, k) * x[i];
      d1 += qrm(i + 1, k) * x[i + 1];
    }
    if (i < 14) d += qrm(i, k) * x[i];
    d = (d + d1) * qr.tau[k];
    x[k] -= d;
    for (int j = k + 1; j < 14; ++j) x[j] -= d * qrm(j, k);
  };
  // Reflector after reflector, each on the 6 columns (6 independent dot products in flight; column
  // after column, each column's 8 applications are one chain of dependent sums).
  for (int k = 7; k >= 0; --k)
    for (int j = 0; j < 6; ++j) reflect(k, &Q6(0, j));
  // 1 / R(i, i) for the back-substitutions of every real root (no division on their chains)
  std::array<S, 8> rInv{};
  for (int i = 0; i < qr.nonzero; ++i) rInv[i] = S(1) / qrm(i, i);
  const Eigen::Matrix<S, 6, 14> N = Q6.transpose();
  std::array<M6x9<S>, 3> Sig;
  for (int k = 0; k < 3; ++k) Sig[k].noalias() = N.lazyProduct(P[k]);

  // θ3 = β + ψ, x3 = tan(ψ/2): M(x3) = (Σ1 − Σc')x3² + 2Σs'x3 + (Σ1 + Σc'). Pick β so that the
  // leading matrix is invertible (β = 0 unless θ3 = π is, nearly, a root: the root at infinity).
  M12<S> A, B, C;
  S rc = S(-1), beta = S(0), cBeta = S(1), sBeta = S(0);
  Lu12<S> luA;
  auto build = [&](const S& b) {
    const S cb = cos(b), sb = sin(b);
    const M6x9<S> Sc = Sig[1] * cb + Sig[2] * sb, Ss = Sig[2] * cb - Sig[1] * sb;
    A = toPolynomialBlock<S>(M6x9<S>(Sig[0] - Sc));
    B = toPolynomialBlock<S>(M6x9<S>(S(2) * Ss));
    C = toPolynomialBlock<S>(M6x9<S>(Sig[0] + Sc));
    // Row scaling (does not move the eigenvalues).
    for (int r = 0; r < 12; ++r) {
      S m = S(0);
      for (int c = 0; c < 12; ++c) m = std::max<S>(m, std::max<S>(abs(A(r, c)), std::max<S>(abs(B(r, c)), abs(C(r, c)))));
      if (m > S(0)) {  // one division a row (36 divisions a row took ~1 µs a pose)
        const S im = S(1) / m;
        A.row(r) *= im;
        B.row(r) *= im;
        C.row(r) *= im;
      }
    }
    luA.factor(A);
    S l1 = S(0);
    for (int c = 0; c < 12; ++c) l1 = std::max<S>(l1, A.col(c).cwiseAbs().sum());
    return luA.rcond(l1);
  };
  rc = build(S(0));
  const S rcGood = Tolerance<S>::precision(2);
  if (!(rc > rcGood)) {
    // Möbius change of the half-angle variable: try offsets, keep the best conditioned.
    S bestRc = rc, bestBeta = S(0);
    for (int k = 1; k <= 6; ++k) {
      const S b = pi<S>() * S(2 * k - 1) / S(7);
      const S r = build(b);
      if (r > bestRc) {
        bestRc = r;
        bestBeta = b;
      }
    }
    out.notes.push_back("leading matrix nearly singular at θ3 offset 0 (rcond " +
                        toString(toDouble(rc), 3) + "): θ3 = π is near a root; half-angle "
                        "variable rotated by β = " + toString(toDouble(bestBeta), 4) +
                        " (rcond " + toString(toDouble(bestRc), 3) + ")");
    rc = build(bestBeta);
    beta = bestBeta;
    sinCos(beta, sBeta, cBeta);
  }
  out.rcond = toDouble(rc);
  out.beta = toDouble(beta);
  if (probe) return out;

  std::vector<std::complex<S>> lambdas;
  lambdas.reserve(24);  // one allocation, not one per doubling (the vectors here are per pose)
  if (rc > Tolerance<S>::rank()) {
    // The companion matrix K = [[0, I], [−A⁻¹C, −A⁻¹B]] in H, then its 8 extraneous eigenvalues
    // x3 = ±i deflated (the QR iteration on 16×16 costs about (16/24)³ ≈ 0.3 of the 24×24 one);
    // when the deflation is not clean the full matrix is used. Eigenvalues by a fixed-size Francis
    // QR; Eigen's EigenSolver if that does not converge, on the same matrix formed again (not a
    // copy kept ahead of every QR).
    S defect = S(0);
    auto formK = [&](Work24<S>& H) {
      H.template topRows<12>().setZero();
      H.template topRightCorner<12, 12>().setIdentity();
      {  // −A⁻¹[C B] with the LU of A factored for its rcond (rc > 0: no zero pivot), the 24
         // right-hand sides together (Eigen's blocked solve cost ~50k instructions here; 24 solves
         // of one column each are chains of dependent multiply-adds)
        Eigen::Matrix<S, 12, 24> y;
        y.template leftCols<12>() = C;
        y.template rightCols<12>() = B;
        luA.solveColumns(y);
        H.template bottomRows<12>() = -y;
      }
      return deflateExtraneous<S>(H, A, B, C, defect);
    };
    Work24<S> H;
    const bool deflated = formK(H);
    const int n = deflated ? 16 : 24;
    out.deflationDefect = toDouble(defect);
    out.deflated = deflated;
    if (!deflated)
      out.notes.push_back("deflation of x3 = ±i not clean (defect " + toString(toDouble(defect), 3) +
                          "): full 24×24 eigenproblem");
    if (!detail::smallEigenvalues<S, 24>(H, n, lambdas)) {
      formK(H);
      const MX<S> Kn = H.topLeftCorner(n, n);
      out.notes.push_back("Francis QR did not converge on the " + std::to_string(n) + "×" +
                          std::to_string(n) + " matrix: Eigen's EigenSolver used");
      lambdas.clear();
      Eigen::EigenSolver<M24<S>> es(Kn, false);
      if (es.info() != Eigen::Success) {
        out.suspicious = true;
        out.notes.push_back("eigenvalue iteration did not converge");
        return out;
      }
      for (int i = 0; i < es.eigenvalues().size(); ++i) lambdas.push_back(es.eigenvalues()(i));
    }
  } else {
    // Leading matrix singular for every offset: the generalized eigenproblem of the pencil
    // [[0, I], [−C, −B]] − x [[I, 0], [0, A]] (infinite eigenvalues are dropped).
    M24<S> L0 = M24<S>::Zero(24, 24), L1 = M24<S>::Zero(24, 24);
    L0.topRightCorner(12, 12).setIdentity();
    L0.bottomLeftCorner(12, 12) = -C;
    L0.bottomRightCorner(12, 12) = -B;
    L1.topLeftCorner(12, 12).setIdentity();
    L1.bottomRightCorner(12, 12) = A;
    out.notes.push_back("leading matrix singular for every θ3 offset: generalized eigenproblem "
                        "(QZ) of the 24×24 pencil");
    out.suspicious = true;
    // One RealQZ, its eigenvalues read off the generalized Schur pair (S, T) below. Not
    // GeneralizedEigenSolver: its values are unusable when the QZ did not converge (its info()
    // asserts), and a second QZ on the same pencil to ask first is not the same iteration: after 23
    // iterations on one eigenvalue Eigen's RealQZ takes "extremely ad hoc" shifts from std::rand(),
    // so one run converges and the next may not (found by the sanitized build in float128: 98 and
    // 734 iterations on one pencil). Reached only when every θ3 offset leaves the leading matrix
    // singular.
    const Eigen::RealQZ<M24<S>> qz(L0, L1, false);
    if (qz.info() != Eigen::Success) {
      out.notes.push_back("the QZ iteration did not converge: no eigenvalues");
      return out;
    }
    const M24<S>& Sm = qz.matrixS();
    const M24<S>& Tm = qz.matrixT();
    auto keep = [&](const std::complex<S>& al, const S& be) {  // infinite eigenvalues dropped
      if (abs(be) > Tolerance<S>::rank() * (abs(al) + abs(be)))
        lambdas.push_back(std::complex<S>(al.real() / be, al.imag() / be));
    };
    for (int i = 0; i < 24;) {
      if (i == 23 || Sm(i + 1, i) == S(0)) {  // a 1×1 block: a real eigenvalue
        keep(std::complex<S>(Sm(i, i)), Tm(i, i));
        ++i;
        continue;
      }
      // A 2×2 block of S over a diagonal 2×2 block of T (RealQZ makes it so on success): with
      // β = t00·t11 the pair is α/β, α the eigenvalues of S₂·diag(t11, t00) (as Eigen's solver).
      const S t0 = Tm(i, i), t1 = Tm(i + 1, i + 1), be = t0 * t1;
      const S s00 = Sm(i, i) * t1, s01 = Sm(i, i + 1) * t0, s10 = Sm(i + 1, i) * t1,
              s11 = Sm(i + 1, i + 1) * t0;
      const S p = S(0.5) * (s00 - s11);
      const S z = sqrt(abs(S(p * p + s10 * s01)));
      keep(std::complex<S>(s11 + p, be > S(0) ? z : S(-z)), be);
      keep(std::complex<S>(s11 + p, be > S(0) ? S(-z) : z), be);
      i += 2;
    }
  }

  // The extraneous factor (1 + x3²)⁴: 4 eigenvalues at +i and 4 at −i (invariant under β).
  const S extTol = Tolerance<S>::precision(3);  // a 4-fold root moves by eps^(1/4)
  const S realTol = Tolerance<S>::precision(2);
  const S clusterTol = S(16) * Tolerance<S>::precision(3);  // a 4-fold cluster spreads by eps^(1/4)
  int nExtra = 0;
  std::vector<S> reals;
  reals.reserve(24);
  // the roots besides ±i, and those of them off the real axis by less than clusterTol (no heap:
  // at most 24 eigenvalues)
  std::array<std::complex<S>, 24> roots, nearReal;
  int nRoots = 0, nNear = 0;
  // The moduli |z ∓ i| and |z| (hypot, ~40 cycles a call) only where a component bound cannot
  // decide: max(|a|, |b|) ≤ |a + ib| ≤ |a| + |b|, and the rounding is monotone, so the bounds give
  // the decisions of the moduli themselves.
  const S extR = extTol * S(16);
  auto nearUnit = [&](const S& re, const S& imMinus) {  // |re + i·imMinus| < extR
    const S ar = abs(re), ai = abs(imMinus);
    if (!(ar < extR) || !(ai < extR)) return false;
    return abs(std::complex<S>(ar, ai)) < extR;
  };
  for (const auto& z : lambdas) {
    if (nearUnit(z.real(), S(z.imag() - S(1))) || nearUnit(z.real(), S(z.imag() + S(1)))) {
      ++nExtra;
      continue;
    }
    roots[nRoots++] = z;
    const S ai = abs(z.imag()), ar = abs(z.real());
    if (ai <= realTol * (S(1) + ar)) reals.push_back(z.real());
    else if (!(ai > realTol * (S(1) + S(ar + ai))) && ai <= realTol * (S(1) + abs(z)))
      reals.push_back(z.real());
    else if (!(ai > clusterTol * (S(1) + S(ar + ai))) && ai <= clusterTol * (S(1) + abs(z)))
      nearReal[nNear++] = z;
  }
  // A k-fold cluster of real roots comes out of the eigensolver as points spread by eps^(1/k),
  // complex pairs among them. realTol = eps^(1/3) covers double and triple roots; a 4-fold cluster
  // needs eps^(1/4): a nearly Pieper robot (axes that miss meeting by 1e-9 of the length scale) has
  // two (the shoulder and wrist postures share x), which long double returned as 6 complex pairs in two
  // clusters, |Im| from 8.8e-7 to 9.2e-5 relative (5 eps^(1/4)): 0 real postures and no warning.
  // An eigenvalue off the axis by less than 16 eps^(1/4) with 3 others within that distance is
  // such a cluster: the answer is suspect and the caller re-solves in the next wider scalar. (A lone
  // near-real pair is a double root, decided by realTol, and is not flagged.)
  int inCluster = 0;
  for (int i = 0; i < nNear; ++i) {
    const std::complex<S>& z = nearReal[i];
    int near = 0;
    for (int j = 0; j < nRoots; ++j) near += roots[j] != z && abs(roots[j] - z) <= clusterTol * (S(1) + abs(z));
    inCluster += near >= 3;
  }
  if (inCluster > 0) {
    out.suspicious = true;
    out.notes.push_back(std::to_string(inCluster) + " complex eigenvalue(s) in a cluster of 4 or more within 16 eps^(1/4) of the real axis (some may be real postures)");
  }
  out.complexCount = int(lambdas.size()) - nExtra;
  if (out.deflated) out.complexCount = 16 - nExtra;  // lambdas holds the 16 after deflation
  if (out.complexCount != 16) {
    out.suspicious = true;
    out.notes.push_back(std::to_string(out.complexCount) +
                        " eigenvalues besides x3 = ±i (16 expected)");
  }
  std::sort(reals.begin(), reals.end());
  S minGap = S(1);
  for (std::size_t i = 1; i < reals.size(); ++i) {
    const S g = abs(reals[i] - reals[i - 1]) / (S(1) + abs(reals[i]));
    minGap = std::min<S>(minGap, g);
  }
  out.minGap = toDouble(minGap);
  if (reals.size() > 1 && minGap < Tolerance<S>::precision(2)) {
    out.suspicious = true;
    out.notes.push_back("clustered real eigenvalues (relative gap " + toString(toDouble(minGap), 3) +
                        ")");
  }

  // Back-substitution for each real x3.
  out.phi.reserve(reals.size());
  out.x3.reserve(reals.size());
  // The kernel of M(x) by two steps of inverse iteration from (1, …, 1), for up to four roots
  // together (their factorisations in lockstep, their solves one after the other: independent
  // chains that overlap).
  constexpr int kBatch = 4;
  std::array<M12<S>, kBatch> Mb;
  std::array<Lu12<S>, kBatch> lub;
  std::array<Eigen::Matrix<S, 12, 1>, kBatch> vb;
  for (std::size_t b0 = 0; b0 < reals.size(); b0 += kBatch) {
    const int nb = int(std::min<std::size_t>(kBatch, reals.size() - b0));
    for (int i = 0; i < nb; ++i) Mb[i] = (A * reals[b0 + i] + B) * reals[b0 + i] + C;
    factorTogether<S>(lub.data(), Mb.data(), nb);
    std::array<bool, kBatch> going{};
    for (int i = 0; i < nb; ++i) {
      vb[i].setOnes();
      going[i] = lub[i].ok;
    }
    for (int it = 0; it < 2; ++it)
      for (int i = 0; i < nb; ++i) {
        if (!going[i]) continue;
        lub[i].solve(vb[i]);
        const S n2 = vb[i].squaredNorm();
        if (!(n2 > S(0)) || !isFinite(n2)) {
          going[i] = false;
          continue;
        }
        vb[i] /= sqrt(n2);
      }
    for (int ib = 0; ib < nb; ++ib) {
      const S& x = reals[b0 + ib];
      const M12<S>& M = Mb[ib];
      const Lu12<S>& lu = lub[ib];
      Eigen::Matrix<S, 12, 1>& v = vb[ib];
      if (!lu.ok || !allFinite(v)) {  // an exact zero pivot: the kernel from a full-pivot LU
        Eigen::FullPivLU<MX<S>> flu{MX<S>(M)};
        flu.setThreshold(Tolerance<S>::sqrtEpsilon());
        const auto ker = flu.kernel();
        if (ker.cols() < 1) continue;
        v = ker.col(0);
      }
      S n4 = S(0), d4 = S(0), n5 = S(0), d5 = S(0);
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 3; ++k) {
          const S vj = v(j * 3 + k);
          if (j < 3) {
            n4 += v((j + 1) * 3 + k) * vj;
            d4 += vj * vj;
          }
          if (k < 2) {
            n5 += v(j * 3 + k + 1) * vj;
            d5 += vj * vj;
          }
        }
      // Angles by atan and atan2; their cosines and sines from the same ratios (no sin/cos call).
      Posture6<S> phi;
      phi.q[2] = beta + S(2) * atan(x);
      phi.q[3] = halfAngleFromPairs(n4, d4);
      phi.q[4] = halfAngleFromPairs(n5, d5);
      S c3, s3, t4[3] = {S(1), S(0), S(0)}, t5[3] = {S(1), S(0), S(0)};
      {
        S ca, sa;  // of 2·atan(x) = 2·atan2(x, 1) = 2·atan2(1, 1/x) ± 2π
        if (abs(x) <= S(1)) doubleAngleOf(x, S(1), ca, sa);
        else doubleAngleOf(S(1), S(S(1) / x), ca, sa);
        c3 = cBeta * ca - sBeta * sa;
        s3 = sBeta * ca + cBeta * sa;
      }
      doubleAngleOf(n4, d4, t4[1], t4[2]);
      doubleAngleOf(n5, d5, t5[1], t5[2]);
      Eigen::Matrix<S, 9, 1> m45;
      for (int i4 = 0; i4 < 3; ++i4)
        for (int i5 = 0; i5 < 3; ++i5) m45(i4 * 3 + i5) = t4[i4] * t5[i5];
      const V14<S> rhs = (P[0] + P[1] * c3 + P[2] * s3) * m45;
      // u = qr.solve(rhs) (Eigen's ColPivHouseholderQR::solve, by hand: Qᵀ rhs with the first
      // nonzeroPivots reflectors, R⁻¹ on those rows, the column permutation; the rest zero).
      Eigen::Matrix<S, 8, 1> u = Eigen::Matrix<S, 8, 1>::Zero();
      {
        V14<S> c = rhs;
        const int nz = qr.nonzero;
        for (int k = 0; k < nz; ++k) reflect(k, c.data());
        for (int i = nz - 1; i >= 0; --i) {
          S v = c(i);
          for (int k = i + 1; k < nz; ++k) v -= qrm(i, k) * c(k);
          c(i) = v * rInv[i];
        }
        for (int i = 0; i < nz; ++i) u(qr.perm[i]) = c(i);
      }
      // u = (c2, s2, c1, c1c2, c1s2, s1, s1c2, s1s2)
      phi.q[0] = atan2(u(5), u(2));
      phi.q[1] = atan2(u(1), u(0));
      unitAngleOf(u(5), u(2), phi.c[0], phi.s[0]);
      unitAngleOf(u(1), u(0), phi.c[1], phi.s[1]);
      phi.c[2] = c3, phi.s[2] = s3;
      phi.c[3] = t4[1], phi.s[3] = t4[2];
      phi.c[4] = t5[1], phi.s[4] = t5[2];
      // θ6 from the loop: Rz(θ6) = (Rz(θ1)K1···Rz(θ5)K5)ᵀ-rotation · K6ᵀ-rotation.
      Mat3<S> R = Mat3<S>::Identity();
      for (int i = 0; i < 5; ++i) {
        const S c = phi.c[i], s = phi.s[i];
        Mat3<S> Z;
        Z << c, -s, S(0), s, c, S(0), S(0), S(0), S(1);
        R = (R * Z * K.R[i]).eval();
      }
      const Mat3<S> R6 = R.transpose() * K.R[5].transpose();
      phi.q[5] = atan2(R6(1, 0), R6(0, 0));
      unitAngleOf(R6(1, 0), R6(0, 0), phi.c[5], phi.s[5]);
      out.phi.push_back(phi);
      out.x3.push_back(x);
    }
  }
  return out;
}

/// Forward chain of DH links with rotation matrices only (dh.hpp's convention
/// Rz(θ)·Tz(d)·Tx(a)·Rx(α), translation (a cos θ, a sin θ, d)), θ_i = offset_i + q_i; the axes
/// z_i and origins o_i of the joints when asked (the spatial Jacobian's columns). GF §3.4 / §4.5
template <class S>
void chainForwardTrig(const std::array<Link<S>, 6>& L, const std::array<S, 6>& cs, const std::array<S, 6>& sn,
                      Mat3<S>& R, Vec3<S>& t, std::array<Vec3<S>, 6>* z = nullptr,
                      std::array<Vec3<S>, 6>* o = nullptr) {
  R.setIdentity();
  t.setZero();
  for (int i = 0; i < 6; ++i) {
    if (z) (*z)[i] = R.col(2);
    if (o) (*o)[i] = t;
    const S c = cs[i], s = sn[i];
    t += R * Vec3<S>(L[i].a * c, L[i].a * s, L[i].d);
    Mat3<S> Ai;
    Ai << c, -s * L[i].ca, s * L[i].sa, s, c * L[i].ca, -c * L[i].sa, S(0), L[i].sa, L[i].ca;
    R = (R * Ai).eval();
  }
}
/// A Posture6 of the joint variables q (angles offset_i + q_i), by sinCos.
template <class S> Posture6<S> posture6Of(const std::array<S, 6>& offset, const std::array<S, 6>& q) {
  Posture6<S> x;
  x.q = q;
  for (int i = 0; i < 6; ++i) sinCos(S(offset[i] + q[i]), x.s[i], x.c[i]);
  return x;
}

/// chainForwardTrig at the angles θ_i = offset_i + q_i.
template <class S>
void chainForward(const std::array<Link<S>, 6>& L, const std::array<S, 6>& offset,
                  const std::array<S, 6>& q, Mat3<S>& R, Vec3<S>& t, std::array<Vec3<S>, 6>* z = nullptr,
                  std::array<Vec3<S>, 6>* o = nullptr) {
  const Posture6<S> x = posture6Of(offset, q);
  chainForwardTrig(L, x.c, x.s, R, t, z, o);
}

/// general6rResidual on precomputed links: max(|R(q) − R*|_F, |t(q) − t*| / scale).
template <class S>
S residualOf(const Mat3<S>& R, const Vec3<S>& t, const Mat3<S>& RT, const Vec3<S>& tT, const S& scale) {
  using std::sqrt;
  const S er2 = (R - RT).squaredNorm(), et2 = (t - tT).squaredNorm() / (scale * scale);
  return sqrt(std::max<S>(er2, et2));
}

/// Newton steps on the pose equations (spatial Jacobian, GF §4.5), each kept only while the
/// error falls; none when the posture's residual is already ≤ `stop`, and none after it is.
/// Each step δ adds to the angles and turns their cosines and sines by δ (stepSinCos).
/// Returns the residual of the final posture.
template <class S>
S polishLinks(const std::array<Link<S>, 6>& L, const Mat3<S>& RT, const Vec3<S>& tT, const S& scale,
              Posture6<S>& q, int iterations, const S& stop) {
  using std::abs;
  using M6 = Eigen::Matrix<S, 6, 6>;
  auto evaluate = [&](const Posture6<S>& qq, M6* J, S& res) {
    Mat3<S> R;
    Vec3<S> t;
    std::array<Vec3<S>, 6> z, o;
    chainForwardTrig(L, qq.c, qq.s, R, t, &z, &o);
    res = residualOf(R, t, RT, tT, scale);
    const Mat3<S> E = RT * R.transpose();
    Vec6<S> e;
    e << (E(2, 1) - E(1, 2)) / S(2), (E(0, 2) - E(2, 0)) / S(2), (E(1, 0) - E(0, 1)) / S(2),
        (tT - t) / scale;
    if (J)
      for (int i = 0; i < 6; ++i) {
        J->col(i).template head<3>() = z[i];
        J->col(i).template tail<3>() = z[i].cross(t - o[i]) / scale;
      }
    return e;
  };
  M6 J;
  S res;
  Vec6<S> e = evaluate(q, &J, res);
  if (res <= stop) return res;
  S err = e.squaredNorm();
  for (int it = 0; it < iterations; ++it) {
    // One right-hand side: Gaussian elimination with partial pivoting in place (Eigen's
    // PartialPivLU of this 6×6 costs ~7k instructions a posture, this ~1k); a zero pivot stops.
    Vec6<S> dq = e;
    if (!(detail::smallSolveInPlace<S, 6>(J, dq) > S(0)) || !allFinite(dq)) break;
    Posture6<S> qn;
    for (int i = 0; i < 6; ++i) {
      // A step beyond ±π is taken modulo 2π (the same point of the circle), so that the angle
      // stays small and keeps the accuracy of its cosine and sine (a step of 6e10 rad, from a
      // singular Jacobian, left the angle 1e-5 rad off them).
      S d = dq(i);
      if (!(abs(d) <= pi<S>())) d = wrapAngle(d);
      S sd, cd;
      stepSinCos(d, sd, cd);
      qn.q[i] = q.q[i] + d;
      qn.c[i] = q.c[i] * cd - q.s[i] * sd;
      qn.s[i] = q.s[i] * cd + q.c[i] * sd;
    }
    M6 Jn;
    S resn;
    const Vec6<S> en = evaluate(qn, &Jn, resn);
    const S errn = en.squaredNorm();
    if (!(errn < err)) break;
    q = qn;
    e = en;
    J = Jn;
    err = errn;
    res = resn;
    if (res <= stop) break;
  }
  return res;
}

template <class S> std::array<Link<S>, 6> linksOf(const Robot6R<S>& robot, std::array<S, 6>* offset) {
  std::array<Link<S>, 6> L;
  for (int i = 0; i < 6; ++i) {
    L[i] = linkOf(robot[i]);
    if (offset) (*offset)[i] = robot[i].theta;
  }
  return L;
}

/// The polish stops at 16 ulps of unit-scale data (the round-off floor of the residual is a few
/// ulps; a further Newton step cannot improve on it).
template <class S> S polishStop() { return Tolerance<S>::identity(16); }

template <class S> S lengthScale(const Robot6R<S>& robot, const Vec3<S>& t) {
  using std::abs;
  S L = t.template lpNorm<Eigen::Infinity>();
  for (const auto& r : robot) L = std::max<S>(L, std::max<S>(abs(r.a), abs(r.d)));
  return L > S(0) ? L : S(1);
}

}  // namespace detail6r

// GF §3.4 / §4.5 (forward kinematics of a DH chain)
template <class S> SE3<S> general6rForward(const Robot6R<S>& robot, const std::array<S, 6>& q) {
  SE3<S> T = SE3<S>::Identity();
  for (int i = 0; i < 6; ++i) T = T * dhTransform(robot[i], q[i]);
  return T;
}

template <class S>
S general6rResidual(const Robot6R<S>& robot, const SE3<S>& target, const std::array<S, 6>& q) {
  std::array<S, 6> off;
  const auto L = detail6r::linksOf(robot, &off);
  Mat3<S> R;
  Vec3<S> t;
  detail6r::chainForward(L, off, q, R, t);
  return detail6r::residualOf(R, t, target.rotation(), target.translation(),
                              detail6r::lengthScale(robot, target.translation()));
}

// Newton steps on the pose equations (spatial Jacobian, GF §4.5).
template <class S>
std::array<S, 6> polishGeneral6R(const Robot6R<S>& robot, const SE3<S>& target,
                                 std::array<S, 6> q, int iterations) {
  std::array<S, 6> off;
  const auto L = detail6r::linksOf(robot, &off);
  detail6r::Posture6<S> x = detail6r::posture6Of(off, q);
  detail6r::polishLinks(L, target.rotation(), target.translation(),
                        detail6r::lengthScale(robot, target.translation()), x, iterations,
                        detail6r::polishStop<S>());
  return x.q;
}

template <class S>
General6RSolution<S> solveGeneral6R(const Robot6R<S>& robot, const SE3<S>& target,
                                    const General6ROptions& options) {
  using std::abs;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 6; ++i) {
    const auto& r = robot[i];
    if (r.type != JointType::Revolute)
      throw InvalidInput("general 6R: joint " + std::to_string(i + 1) +
                         " is prismatic (the general-6R solver needs six revolute joints)");
    if (!isFinite(r.a) || !isFinite(r.alpha) || !isFinite(r.d) || !isFinite(r.theta))
      throw InvalidInput("general 6R: DH row " + std::to_string(i + 1) +
                         " has a NaN or infinite entry");
  }
  if (!allFinite(target.translation()) || !allFinite(target.quaternion().coeffs()))
    throw InvalidInput("general 6R: target pose has a NaN or infinite entry");

  General6RSolution<S> sol;
  sol.method = "general6r";
  sol.expected_count = 16;
  sol.solved_in = std::string(scalarName<S>());

  // Unit length scale: angles are unchanged.
  const S L = detail6r::lengthScale(robot, target.translation());
  Robot6R<S> rn = robot;
  for (auto& r : rn) {
    r.a /= L;
    r.d /= L;
    r.theta = S(0);
  }
  const Mat3<S> RT = target.rotation();
  const Vec3<S> tT = target.translation() / L;
  const SE3<S> Tn(target.so3(), tT);

  const detail6r::Loop6R<S> loop = detail6r::loopOf(rn, RT, tT);
  detail6r::Core<S> core = detail6r::eigenCore(loop);
  sol.elimination = "theta3 last";
  // A leading matrix singular for every θ3 offset is structural for this split (a PUMA whose
  // wrist axes nearly meet, a UR whose axis 4 is nearly parallel to 2, 3): another joint is
  // eliminated last, on a cyclic relabelling of the closed loop or the reversed loop, the one
  // whose leading matrix is best conditioned (Raghavan & Roth 1993, any joint may be eliminated
  // last; Manocha & Canny 1994; GF §11.5).
  const double rcGood = toDouble(Tolerance<S>::precision(2));
  const double qGood = toDouble(Tolerance<S>::rank());
  auto score = [&](const detail6r::Core<S>& c) { return c.qRank > qGood ? c.rcond : 0.0; };
  if (options.choose_elimination && !(score(core) > rcGood)) {
    double best = score(core);
    int bestShift = 0;
    bool bestReverse = false;
    for (int f = 1; f < 12 && !(best > rcGood); ++f) {
      const int shift = f % 6;
      const bool reverse = f >= 6;
      const double sc = score(detail6r::eigenCore(detail6r::relabelled(loop, shift, reverse), true));
      if (sc > best) {
        best = sc;
        bestShift = shift;
        bestReverse = reverse;
      }
    }
    const int last = detail6r::relabelledJoint(2, bestShift, bestReverse) + 1;
    sol.notes.push_back("leading matrix ill-conditioned for every θ3 offset (rcond " +
                        toString(core.rcond, 3) + ")" +
                        (bestShift == 0 && !bestReverse
                             ? std::string(": no other elimination does better")
                             : ": eliminating θ" + std::to_string(last) + " last" +
                                   (bestReverse ? " on the reversed loop" : "") + " (rcond " +
                                   toString(best, 3) + ")"));
    if (bestShift != 0 || bestReverse) {
      detail6r::Core<S> alt = detail6r::eigenCore(detail6r::relabelled(loop, bestShift, bestReverse));
      for (auto& phi : alt.phi) {
        const detail6r::Posture6<S> p = phi;
        for (int i = 0; i < 6; ++i) {
          const int j = detail6r::relabelledJoint(i, bestShift, bestReverse);
          phi.q[j] = bestReverse ? S(-p.q[i]) : p.q[i];
          phi.c[j] = p.c[i];
          phi.s[j] = bestReverse ? S(-p.s[i]) : p.s[i];
        }
      }
      core = std::move(alt);
      sol.elimination = "theta" + std::to_string(last) + " last" + (bestReverse ? ", reversed loop" : "");
    }
  }
  sol.complex_count = core.complexCount;
  sol.leading_rcond = core.rcond;
  sol.theta3_offset = core.beta;
  sol.min_gap = core.minGap;
  for (const auto& n : core.notes) sol.notes.push_back(n);

  const S accept = Tolerance<S>::sqrtEpsilon();
  const S full = Tolerance<S>::identity(4096);
  const S same = Tolerance<S>::precision(2);
  std::vector<detail6r::Posture6<S>> found;  // totals φ in the unit-scaled problem, wrapped
  std::vector<S> res;
  found.reserve(core.phi.size());
  res.reserve(core.phi.size());
  int failed = 0, merged = 0;
  const std::array<S, 6> zero{};  // rn has θ offsets 0
  const auto Ln = detail6r::linksOf<S>(rn, nullptr);
  const S scaleN = detail6r::lengthScale(rn, tT);
  auto addCandidate = [&](const detail6r::Posture6<S>& phi0) {
    detail6r::Posture6<S> x = phi0;
    const S r = detail6r::polishLinks(Ln, RT, tT, scaleN, x, options.polish_iterations,
                                      detail6r::polishStop<S>());
    for (int i = 0; i < 6; ++i) x.q[i] = wrapAngle(x.q[i]);
    if (!(r <= accept)) return 1;
    for (std::size_t k = 0; k < found.size(); ++k) {
      // |a − b| mod 2π for a, b in [−π, π] (|a − b| ≤ 2π): no trigonometric call
      S d = S(0);
      for (int i = 0; i < 6; ++i) {
        S e = abs(S(x.q[i] - found[k].q[i]));
        if (e > pi<S>()) e = S(2) * pi<S>() - e;
        d = std::max<S>(d, e);
      }
      if (d < same) {
        if (r < res[k]) {
          found[k] = x;
          res[k] = r;
        }
        return 2;
      }
    }
    found.push_back(x);
    res.push_back(r);
    return 0;
  };
  for (const auto& phi : core.phi) {
    const int k = addCandidate(phi);
    failed += k == 1;
    merged += k == 2;
  }
  bool shortAnswer = core.suspicious || failed > 0 || merged > 0 || found.size() % 2 == 1;
  if (failed > 0)
    sol.notes.push_back(std::to_string(failed) + " real eigenvalue(s) did not polish to a posture");
  if (merged > 0)
    sol.notes.push_back(std::to_string(merged) + " real eigenvalue(s) polished onto another posture");
  if (found.size() % 2 == 1) sol.notes.push_back("odd real count " + std::to_string(found.size()));

  using Next = typename detail6r::NextScalar<S>::type;
  if constexpr (!std::is_void_v<Next>) {
    if (shortAnswer && options.escalate) {
      Robot6R<Next> rh;
      for (int i = 0; i < 6; ++i) rh[i] = rn[i].template cast<Next>();
      const General6RSolution<Next> hi = solveGeneral6R<Next>(rh, Tn.template cast<Next>(), options);
      sol.notes.push_back("re-solved in " + std::string(scalarName<Next>()) + ": " +
                          std::to_string(hi.count()) + " real postures (" +
                          std::to_string(found.size()) + " in " + std::string(scalarName<S>()) + ")");
      for (const auto& n : hi.notes) sol.notes.push_back("  [" + std::string(scalarName<Next>()) + "] " + n);
      sol.solved_in = hi.solved_in;
      sol.complex_count = hi.complex_count;
      const std::size_t before = found.size();
      for (const auto& p : hi.postures) {
        std::array<S, 6> phi;
        for (int i = 0; i < 6; ++i) phi[i] = scalarCast<S>(p(i));
        addCandidate(detail6r::posture6Of(zero, phi));
      }
      if (found.size() > before)
        sol.notes.push_back(std::to_string(found.size() - before) + " posture(s) added by the re-solve");
      shortAnswer = false;
    }
  }
  if (shortAnswer && std::is_void_v<Next>)
    sol.notes.push_back("no higher precision left: the answer above may be short");

  std::array<S, 6> off;
  const auto Lr = detail6r::linksOf(robot, &off);
  sol.postures.reserve(found.size());
  sol.residuals.reserve(found.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    JointVector<S> q(6);
    std::array<S, 6> qa;
    for (int i = 0; i < 6; ++i) {
      qa[i] = wrapAngle(S(found[k].q[i] - robot[i].theta));
      q(i) = qa[i];
    }
    // The residual of the returned q itself (not of the cosines and sines the polish carried,
    // which agree with it only up to the rounding of the steps added to the angles).
    Mat3<S> Rq;
    Vec3<S> tq;
    detail6r::chainForward(Lr, off, qa, Rq, tq);
    const S r = detail6r::residualOf(Rq, tq, target.rotation(), target.translation(), L);
    if (r > full) sol.notes.push_back("posture " + std::to_string(k + 1) + " residual " +
                                      toString(toDouble(r), 3) + " above 4096 ulps");
    sol.postures.push_back(q);
    sol.residuals.push_back(r);
  }
  sol.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sol;
}

template <class S>
General6RSolution<S> solveGeneral6R(const Robot6R<S>& robot, const Mat4<S>& target,
                                    const General6ROptions& options) {
  SE3<S> T;
  try {
    T = SE3<S>::fromMatrix(target);
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string("general 6R: target pose is not a rigid motion: ") + e.what());
  }
  return solveGeneral6R(robot, T, options);
}

}  // namespace soma

#define SOMA_INSTANTIATE_GENERAL_6R(S)                                                          \
  template SE3<S> general6rForward<S>(const Robot6R<S>&, const std::array<S, 6>&);             \
  template S general6rResidual<S>(const Robot6R<S>&, const SE3<S>&, const std::array<S, 6>&);  \
  template General6RSolution<S> solveGeneral6R<S>(const Robot6R<S>&, const SE3<S>&,            \
                                                  const General6ROptions&);                    \
  template General6RSolution<S> solveGeneral6R<S>(const Robot6R<S>&, const Mat4<S>&,           \
                                                  const General6ROptions&);                    \
  template std::array<S, 6> polishGeneral6R<S>(const Robot6R<S>&, const SE3<S>&,              \
                                               std::array<S, 6>, int);

namespace soma::detail6r {

/// The 12 residuals (R(q) − R*, row-major, and (t(q) − t*)/scale) and their 12×6 Jacobian
/// (∂R/∂q_i = [z_i]× R, ∂t/∂q_i = z_i × (t − o_i)), for the numerical methods. GF §4.5
template <class S>
void poseResidual12(const Robot6R<S>& robot, const Mat3<S>& RT, const Vec3<S>& tT, const S& scale,
                    const S* q, S* r, S* J /* 12×6 row-major or nullptr */) {
  Mat3<S> R = Mat3<S>::Identity();
  Vec3<S> t = Vec3<S>::Zero();
  std::array<Vec3<S>, 6> z, o;
  for (int i = 0; i < 6; ++i) {
    z[i] = R.col(2);
    o[i] = t;
    const SE3<S> A = dhTransform(robot[i], q[i]);
    t = t + R * A.translation();
    R = R * A.rotation();
  }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) r[a * 3 + b] = R(a, b) - RT(a, b);
  for (int a = 0; a < 3; ++a) r[9 + a] = (t(a) - tT(a)) / scale;
  if (!J) return;
  for (int i = 0; i < 6; ++i) {
    Mat3<S> Z;
    Z << S(0), -z[i].z(), z[i].y(), z[i].z(), S(0), -z[i].x(), -z[i].y(), z[i].x(), S(0);
    const Mat3<S> dR = Z * R;
    const Vec3<S> dt = z[i].cross(t - o[i]) / scale;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) J[(a * 3 + b) * 6 + i] = dR(a, b);
    for (int a = 0; a < 3; ++a) J[(9 + a) * 6 + i] = dt(a);
  }
}

/// Multi-start driver shared by the numerical methods: `local(q)` refines a start in place and
/// returns false when it failed; converged points are polished by Newton and clustered.
template <class Local>
General6RSolution<double> multiStart6R(const Robot6R<double>& robot, const SE3<double>& target,
                                       const General6RNumericOptions& opt, const char* method,
                                       Local&& local) {
  const auto start = std::chrono::steady_clock::now();
  General6RSolution<double> sol;
  sol.method = method;
  sol.expected_count = 16;
  sol.solved_in = "double";
  std::mt19937_64 g(opt.seed);
  std::uniform_real_distribution<double> u(-pi<double>(), pi<double>());
  const double accept = Tolerance<double>::sqrtEpsilon();
  const double same = Tolerance<double>::precision(2);
  int converged = 0, duplicates = 0;
  for (int s = 0; s < opt.starts; ++s) {
    std::array<double, 6> q;
    for (auto& x : q) x = u(g);
    if (!local(q)) continue;
    q = polishGeneral6R(robot, target, q, 12);
    for (auto& x : q) x = wrapAngle(x);
    const double r = general6rResidual(robot, target, q);
    if (!(r <= accept)) continue;
    ++converged;
    bool dup = false;
    for (const auto& p : sol.postures) {
      double d = 0;
      for (int i = 0; i < 6; ++i) d = std::max(d, std::abs(wrapAngle(q[i] - p(i))));
      if (d < same) dup = true;
    }
    if (dup) {
      ++duplicates;
      continue;
    }
    JointVector<double> v(6);
    for (int i = 0; i < 6; ++i) v(i) = q[i];
    sol.postures.push_back(v);
    sol.residuals.push_back(r);
  }
  sol.notes.push_back(std::to_string(opt.starts) + " starts, " + std::to_string(converged) +
                      " converged, " + std::to_string(duplicates) +
                      " duplicates clustered: a multi-start search cannot certify completeness");
  sol.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sol;
}

}  // namespace soma::detail6r
