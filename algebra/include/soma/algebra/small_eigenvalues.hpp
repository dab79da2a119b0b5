#pragma once
// Eigenvalues of a small real matrix (n ≤ N, fixed-size storage), eigenvalues only: Gaussian
// reduction to upper Hessenberg form with row interchanges (EISPACK ELMHES; Wilkinson & Reinsch,
// Handbook for Automatic Computation II, 1971), then Francis double-shift QR steps with deflation at
// negligible subdiagonal entries (EISPACK HQR; Golub & Van Loan, Matrix Computations, Alg. 7.5.1–7.5.2).
// Hand-written for speed, not for want of a library: the general-6R solver (GF §11.5, its 16
// postures are the eigenvalues of a 16×16 matrix) spends most of its time here, and Eigen's
// dynamic-size EigenSolver cost ~2.5× this; the stabilised elementary (Gauss) reduction takes half
// the flops of Householder's and is the EISPACK RG path's. Checked against Eigen's EigenSolver
// (tests/algebra/small_eigenvalues.cpp).
#include "soma/algebra/cpu_dispatch.hpp"
#include "soma/algebra/sub_scaled4.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <complex>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace soma::detail {

/// Upper Hessenberg form of the leading n×n block of H by stabilised elementary similarity
/// transformations (partial pivoting on the subdiagonal column, ELMHES); entries below the
/// subdiagonal are set to zero. Same eigenvalues, ~(5/6)n³ multiply-adds.
template <class S, int N>
[[gnu::always_inline]] inline void smallHessenbergGaussBody(Eigen::Matrix<S, N, N>& H, int n) {
  using std::abs;
  S y[N];
  for (int m = 1; m + 1 < n; ++m) {
    int piv = m;
    S best = abs(H(m, m - 1));
    for (int i = m + 1; i < n; ++i)
      if (abs(H(i, m - 1)) > best) best = abs(H(i, m - 1)), piv = i;
    if (best == S(0)) continue;
    if (piv != m) {  // P H P with P swapping rows/columns piv and m
      for (int j = m - 1; j < n; ++j) std::swap(H(piv, j), H(m, j));
      for (int i = 0; i < n; ++i) std::swap(H(i, piv), H(i, m));
    }
    const S ix = S(1) / H(m, m - 1);  // one division per column (divisions are slow)
    bool any = false;
    for (int i = m + 1; i < n; ++i) {
      y[i] = H(i, m - 1) * ix;
      H(i, m - 1) = S(0);
      any = any || y[i] != S(0);
    }
    if (!any) continue;
    // Rows i -= y_i · row m, column by column (contiguous). In hardware floating point from the
    // row of four that holds row m + 1 on, with y_i = 0 above it (such a row is left as it was):
    // whole vectors, no scalar remainder when n is a multiple of four (16 and 24 here).
    constexpr bool hw = std::is_same_v<S, double> || std::is_same_v<S, float>;
    const int i0 = hw ? ((m + 1) & ~3) : m + 1;
    for (int i = i0; i <= m; ++i) y[i] = S(0);
    for (int j = m; j < n; ++j) {
      const S hm = H(m, j);
      if (hm == S(0)) continue;
      int i = i0;
      if constexpr (hw)
        for (; i + 4 <= n; i += 4) subScaled4(&H(i, j), &y[i], hm);
      for (; i < n; ++i) H(i, j) -= y[i] * hm;
    }
    // Column m += Σ_i y_i · column i, each entry summed in a register in the order i = m+1, …
    // (the same sums as column after column, without a store and reload per column).
    int r = 0;
    for (; r + 4 <= n; r += 4) {  // four rows at a time: contiguous loads, four sums in flight
      S a0 = H(r, m), a1 = H(r + 1, m), a2 = H(r + 2, m), a3 = H(r + 3, m);
      for (int i = m + 1; i < n; ++i) {
        const S& yi = y[i];
        const S* c = &H(r, i);
        a0 += yi * c[0];
        a1 += yi * c[1];
        a2 += yi * c[2];
        a3 += yi * c[3];
      }
      H(r, m) = a0, H(r + 1, m) = a1, H(r + 2, m) = a2, H(r + 3, m) = a3;
    }
    for (; r < n; ++r) {
      S acc = H(r, m);
      for (int i = m + 1; i < n; ++i) acc += y[i] * H(r, i);
      H(r, m) = acc;
    }
  }
}

/// Eigenvalues of an upper Hessenberg n×n block of H (destroyed) by Francis double-shift QR steps
/// (EISPACK HQR), exceptional shifts at the 10th and 20th iteration of an eigenvalue. Each bulge
/// step's reflector is formed from p² + q² + r² directly when that sum can neither overflow nor
/// underflow (HQR's scaling by |p| + |q| + |r| costs a division on the step's dependency chain),
/// scaled otherwise, and applied as I − β u uᵀ with one division (HQR's form takes two, and the
/// next step's p, q, r waited on both). Returns
/// false when an eigenvalue needed more than 60 iterations (lambda then incomplete).
template <class S, int N>
[[gnu::always_inline]] inline bool smallHessenbergEigenvaluesBody(Eigen::Matrix<S, N, N>& H, int n,
                                                                  std::vector<std::complex<S>>& lambda) {
  using std::abs;
  using std::frexp;
  using std::ldexp;
  using std::sqrt;
  lambda.clear();
  const S eps = Tolerance<S>::epsilon();
  S norm = S(0);
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - 1); j < n; ++j) norm += abs(H(i, j));
  if (norm == S(0)) {
    for (int i = 0; i < n; ++i) lambda.emplace_back(S(0), S(0));
    return true;
  }
  // The bulge steps form products of three entries (T below). A norm 2^e outside 2^±16 (float)
  // or 2^±64 (wider scalars; their products then stay within 2^±200 of the range's ends) is
  // scaled by a power of two (exact) to [1/2, 1) first and the eigenvalues scaled back: in range at
  // any scale of the input (entries below the smallest normal times 2^e, negligible, lose bits).
  // 2^e in two factors: 2^±e alone leaves the range for a norm near the largest or a subnormal one.
  int e = 0;
  if (norm - norm == S(0)) (void)frexp(norm, &e);  // finite
  constexpr int band = std::is_same_v<S, float> ? 16 : 64;
  if (e >= -band && e <= band) e = 0;
  const S up1 = ldexp(S(1), e / 2), up2 = ldexp(S(1), e - e / 2);
  if (e != 0) {
    const S f1 = ldexp(S(1), -(e / 2)), f2 = ldexp(S(1), -(e - e / 2));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i <= std::min(j + 1, n - 1); ++i) H(i, j) = H(i, j) * f1 * f2;
    norm = norm * f1 * f2;
  }
  auto push = [&](const S& re, const S& im) { lambda.emplace_back(re * up1 * up2, im * up1 * up2); };
  // Sums of squares in [tiny, big] are formed without scaling (no division on the bulge's path).
  const S tiny = std::numeric_limits<S>::min() / eps, big = std::numeric_limits<S>::max();
  int hi = n - 1, its = 0;
  S shiftTotal = S(0);  // exceptional shifts applied to the diagonal
  while (hi >= 0) {
    // Active block [lo, hi]: the first negligible subdiagonal entry from the bottom.
    int lo = hi;
    for (; lo > 0; --lo) {
      S sc = abs(H(lo - 1, lo - 1)) + abs(H(lo, lo));
      if (sc == S(0)) sc = norm;
      if (abs(H(lo, lo - 1)) <= eps * sc) {
        H(lo, lo - 1) = S(0);
        break;
      }
    }
    const S x = H(hi, hi);
    if (lo == hi) {  // a real eigenvalue splits off
      push(x + shiftTotal, S(0));
      --hi;
      its = 0;
      continue;
    }
    const S y = H(hi - 1, hi - 1), w = H(hi, hi - 1) * H(hi - 1, hi);
    if (lo == hi - 1) {  // a 2×2 block: two real eigenvalues or a complex pair
      const S p = (y - x) / S(2), q = p * p + w;
      const S z = sqrt(abs(q));
      if (q >= S(0)) {
        const S zz = p >= S(0) ? S(p + z) : S(p - z);
        const S e1 = x + zz, e2 = zz != S(0) ? S(x - w / zz) : e1;
        push(e1 + shiftTotal, S(0));
        push(e2 + shiftTotal, S(0));
      } else {
        push(x + p + shiftTotal, z);
        push(x + p + shiftTotal, -z);
      }
      hi -= 2;
      its = 0;
      continue;
    }
    if (its >= 60) return false;
    S sx = x, sy = y, sw = w;  // shifts: the eigenvalues of the trailing 2×2 block
    if (its == 10 || its == 20) {  // exceptional shift (breaks cycles)
      shiftTotal += x;
      for (int i = 0; i <= hi; ++i) H(i, i) -= x;
      const S sc = abs(H(hi, hi - 1)) + abs(H(hi - 1, hi - 2));
      sx = sy = S(3) / S(4) * sc;
      sw = S(-7) / S(16) * sc * sc;
    }
    ++its;
    // First column of (H − s1)(H − s2) restricted to rows m..m+2, started at the lowest m ≥ lo
    // where the bulge does not disturb the small subdiagonal entry above it. Formed times
    // H(m+1, m) (HQR divides by it and normalises), which changes neither the test nor the
    // reflector: no division per m.
    int m = hi - 2;
    S p, q, r;
    for (;; --m) {
      const S z = H(m, m), h10 = H(m + 1, m);
      const S rr = sx - z, ss = sy - z;
      p = (rr * ss - sw) + H(m, m + 1) * h10;
      q = (H(m + 1, m + 1) - z - rr - ss) * h10;
      r = H(m + 2, m + 1) * h10;
      if (m == lo) break;
      const S u = abs(H(m, m - 1)) * (abs(q) + abs(r));
      const S vv = abs(p) * (abs(H(m - 1, m - 1)) + abs(z) + abs(H(m + 1, m + 1)));
      if (vv >= tiny && vv <= big && u <= eps * vv) break;  // (u, vv ~ |H|³: kept in range)
    }
    for (int i = m + 2; i <= hi; ++i) {
      H(i, i - 2) = S(0);
      if (i != m + 2) H(i, i - 3) = S(0);
    }
    // Chase the bulge with 3-element reflectors (2-element at the bottom).
    bool carried = false;  // p, q, r already hold H(k..k+2, k−1) (from the step before)
    for (int k = m; k < hi; ++k) {
      const bool last = k == hi - 1;
      S scale = S(1);
      if (k != m && !carried) {
        p = H(k, k - 1);
        q = H(k + 1, k - 1);
        r = last ? S(0) : H(k + 2, k - 1);
      }
      carried = false;
      S ss = p * p + (q * q + r * r);  // r first: it is ready before p and q
      if (!(ss >= tiny && ss <= big)) {  // scaled against overflow and underflow
        scale = abs(p) + abs(q) + abs(r);
        if (scale == S(0)) continue;
        const S is = S(1) / scale;
        p *= is;
        q *= is;
        r *= is;
        ss = p * p + q * q + r * r;
      }
      S sn = sqrt(ss);
      if (p < S(0)) sn = -sn;
      if (k == m) {
        if (lo != m) H(k, k - 1) = -H(k, k - 1);
      } else {
        H(k, k - 1) = -sn * scale;
      }
      if (!last) {
        // The reflector I − β u uᵀ, u = (p + sn, q, r), β = 1 / (sn (p + sn)) = 1 / (ss + p·sn)
        // (= 2 / |u|², no cancellation: p and sn share their sign), w = β u. One division, and the
        // products with u need only q and r before the square root is done.
        const S u0 = p + sn, beta = S(1) / (p * sn + ss);
        const S w0 = beta * u0, w1 = beta * q, w2 = beta * r;
        S* __restrict c0 = &H(0, k);
        S* __restrict c1 = &H(0, k + 1);
        S* __restrict c2 = &H(0, k + 2);
        // The 3×3 diagonal block in registers. Left: column j −= t_j w with t_j = u·(column j).
        // Right: row i −= s_i wᵀ with s_i = (row i after the left step)·u = A_i − w_i T,
        // A_i = (row i before)·u and T = Σ_j t_j u_j: the next step's p, q, r (the new entries
        // (k+1, k), (k+2, k), (k+3, k)) wait on the division and three multiply-adds after it, not
        // on the left step's results (the same sums, associated differently).
        const S a00 = c0[k], a10 = c0[k + 1], a20 = c0[k + 2];
        const S a01 = c1[k], a11 = c1[k + 1], a21 = c1[k + 2];
        const S a02 = c2[k], a12 = c2[k + 1], a22 = c2[k + 2];
        const S t0 = u0 * a00 + (q * a10 + r * a20);
        const S t1 = u0 * a01 + (q * a11 + r * a21);
        const S t2 = u0 * a02 + (q * a12 + r * a22);
        const S T = u0 * t0 + (q * t1 + r * t2);
        const S A0 = u0 * a00 + (q * a01 + r * a02);
        const S A1 = u0 * a10 + (q * a11 + r * a12);
        const S A2 = u0 * a20 + (q * a21 + r * a22);
        const S s0 = A0 - w0 * T, s1 = A1 - w1 * T, s2 = A2 - w2 * T;
        // (row i, column j) after both: a_ij − t_j w_i − s_i w_j
        c0[k] = a00 - t0 * w0 - s0 * w0;
        c1[k] = a01 - t1 * w0 - s0 * w1;
        c2[k] = a02 - t2 * w0 - s0 * w2;
        const S b10 = a10 - t0 * w1 - s1 * w0, b20 = a20 - t0 * w2 - s2 * w0;
        c0[k + 1] = b10;
        c1[k + 1] = a11 - t1 * w1 - s1 * w1;
        c2[k + 1] = a12 - t2 * w1 - s1 * w2;
        c0[k + 2] = b20;
        c1[k + 2] = a21 - t1 * w2 - s2 * w1;
        c2[k + 2] = a22 - t2 * w2 - s2 * w2;
        S rn = S(0);
        if (k + 3 <= hi) {  // row k+3: H(k+3, k) = H(k+3, k+1) = 0 (zeroed above, untouched since)
          const S h = c2[k + 3], s3 = h * r;
          rn = -s3 * w0;
          c0[k + 3] = rn;
          c1[k + 3] = -s3 * w1;
          c2[k + 3] = h - s3 * w2;
        }
        // Rows k..k+2 from column k+3 to hi, then columns k..k+2 from row lo to k−1 (eigenvalues
        // only: nothing outside the active block).
        int j = k + 3;
        if constexpr (std::is_same_v<S, double>) {  // two columns at a time in SSE2 registers
          typedef double V2 __attribute__((vector_size(16)));
          for (; j + 1 <= hi; j += 2) {
            double* a = &H(k, j);
            double* b = a + N;
            V2 h0 = {a[0], b[0]}, h1 = {a[1], b[1]}, h2 = {a[2], b[2]};
            const V2 t = u0 * h0 + q * h1 + r * h2;
            h0 -= t * w0;
            h1 -= t * w1;
            h2 -= t * w2;
            a[0] = h0[0], b[0] = h0[1], a[1] = h1[0], b[1] = h1[1], a[2] = h2[0], b[2] = h2[1];
          }
        }
        for (; j <= hi; ++j) {
          S* h = &H(k, j);
          const S t = u0 * h[0] + q * h[1] + r * h[2];
          h[0] -= t * w0;
          h[1] -= t * w1;
          h[2] -= t * w2;
        }
        for (int i = lo; i < k; ++i) {
          const S t = u0 * c0[i] + q * c1[i] + r * c2[i];
          c0[i] -= t * w0;
          c1[i] -= t * w1;
          c2[i] -= t * w2;
        }
        p = b10, q = b20, r = rn;
        carried = true;
      } else {  // the 2-element reflector at the bottom
        p += sn;
        const S isn = S(1) / sn, ip = S(1) / p;
        const S vx = p * isn, vy = q * isn;
        q *= ip;
        const int iMax = std::min(hi, k + 3);
        for (int j = k; j <= hi; ++j) {
          S* h = &H(k, j);
          const S d = h[0] + q * h[1];
          h[0] -= d * vx;
          h[1] -= d * vy;
        }
        S* __restrict c0 = &H(0, k);
        S* __restrict c1 = &H(0, k + 1);
        for (int i = lo; i <= iMax; ++i) {
          const S d = vx * c0[i] + vy * c1[i];
          c0[i] -= d;
          c1[i] -= d * q;
        }
      }
    }
  }
  return true;
}

#ifdef SOMA_X86_AVX2_DISPATCH
template <int N> SOMA_TARGET_AVX2_FMA void smallHessenbergGaussAvx2(Eigen::Matrix<double, N, N>& H, int n) {
  smallHessenbergGaussBody<double, N>(H, n);
}
template <int N>
SOMA_TARGET_AVX2_FMA bool smallHessenbergEigenvaluesAvx2(Eigen::Matrix<double, N, N>& H, int n,
                                                                        std::vector<std::complex<double>>& lambda) {
  return smallHessenbergEigenvaluesBody<double, N>(H, n, lambda);
}
#endif

/// Upper Hessenberg form of the leading n×n block of H (smallHessenbergGaussBody); in double on a
/// CPU with AVX2 and FMA by its AVX2 + FMA build (fused multiply–adds: the same similarity, rounded
/// differently).
template <class S, int N> void smallHessenbergGauss(Eigen::Matrix<S, N, N>& H, int n) {
#ifdef SOMA_X86_AVX2_DISPATCH
  if constexpr (std::is_same_v<S, double>)
    if (cpuHasAvx2Fma()) return smallHessenbergGaussAvx2<N>(H, n);
#endif
  smallHessenbergGaussBody<S, N>(H, n);
}

/// Eigenvalues of an upper Hessenberg block (smallHessenbergEigenvaluesBody); in double on a CPU
/// with AVX2 and FMA by its AVX2 + FMA build (the Francis steps' row and column updates four wide).
template <class S, int N>
bool smallHessenbergEigenvalues(Eigen::Matrix<S, N, N>& H, int n, std::vector<std::complex<S>>& lambda) {
#ifdef SOMA_X86_AVX2_DISPATCH
  if constexpr (std::is_same_v<S, double>)
    if (cpuHasAvx2Fma()) return smallHessenbergEigenvaluesAvx2<N>(H, n, lambda);
#endif
  return smallHessenbergEigenvaluesBody<S, N>(H, n, lambda);
}

/// Eigenvalues of the leading n×n block of H (destroyed), n ≤ N: smallHessenbergGauss, then
/// smallHessenbergEigenvalues. Returns false when the QR iteration did not converge (the caller
/// falls back to Eigen's EigenSolver).
template <class S, int N>
bool smallEigenvalues(Eigen::Matrix<S, N, N>& H, int n, std::vector<std::complex<S>>& lambda) {
  smallHessenbergGauss<S, N>(H, n);
  return smallHessenbergEigenvalues<S, N>(H, n, lambda);
}

}  // namespace soma::detail
