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
      if (hm != S(0))
        for (int i = i0; i < n; ++i) H(i, j) -= y[i] * hm;
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
/// scaled otherwise. Returns
/// false when an eigenvalue needed more than 60 iterations (lambda then incomplete).
template <class S, int N>
[[gnu::always_inline]] inline bool smallHessenbergEigenvaluesBody(Eigen::Matrix<S, N, N>& H, int n,
                                                                  std::vector<std::complex<S>>& lambda) {
  using std::abs;
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
      lambda.emplace_back(x + shiftTotal, S(0));
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
        lambda.emplace_back(e1 + shiftTotal, S(0));
        lambda.emplace_back(e2 + shiftTotal, S(0));
      } else {
        lambda.emplace_back(x + p + shiftTotal, z);
        lambda.emplace_back(x + p + shiftTotal, -z);
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
      S ss = p * p + q * q + r * r;
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
      p += sn;
      const S isn = S(1) / sn, ip = S(1) / p;
      const S vx = p * isn, vy = q * isn, vz = r * isn;
      q *= ip;
      r *= ip;
      if (!last) {
        S* __restrict c0 = &H(0, k);
        S* __restrict c1 = &H(0, k + 1);
        S* __restrict c2 = &H(0, k + 2);
        // The 3×3 diagonal block and row k+3 updated in registers first: the next step's p, q, r
        // come from them, so the bulge's dependency chain never waits on a store to memory.
        S a00 = c0[k], a10 = c0[k + 1], a20 = c0[k + 2];
        S a01 = c1[k], a11 = c1[k + 1], a21 = c1[k + 2];
        S a02 = c2[k], a12 = c2[k + 1], a22 = c2[k + 2];
        {
          S d = a00 + q * a10 + r * a20;
          a00 -= d * vx, a10 -= d * vy, a20 -= d * vz;
          d = a01 + q * a11 + r * a21;
          a01 -= d * vx, a11 -= d * vy, a21 -= d * vz;
          d = a02 + q * a12 + r * a22;
          a02 -= d * vx, a12 -= d * vy, a22 -= d * vz;
          d = vx * a00 + vy * a01 + vz * a02;
          a00 -= d, a01 -= d * q, a02 -= d * r;
          d = vx * a10 + vy * a11 + vz * a12;
          a10 -= d, a11 -= d * q, a12 -= d * r;
          d = vx * a20 + vy * a21 + vz * a22;
          a20 -= d, a21 -= d * q, a22 -= d * r;
        }
        S rn = S(0);
        if (k + 3 <= hi) {  // H(k+3, k) = H(k+3, k+1) = 0 (zeroed above, untouched since)
          const S h = c2[k + 3], d = vz * h;
          c0[k + 3] = -d;
          c1[k + 3] = -d * q;
          c2[k + 3] = h - d * r;
          rn = -d;
        }
        c0[k] = a00, c0[k + 1] = a10, c0[k + 2] = a20;
        c1[k] = a01, c1[k + 1] = a11, c1[k + 2] = a21;
        c2[k] = a02, c2[k + 1] = a12, c2[k + 2] = a22;
        // Rows k..k+2 from column k+3 to hi, then columns k..k+2 from row lo to k−1 (eigenvalues
        // only: nothing outside the active block).
        int j = k + 3;
        if constexpr (std::is_same_v<S, double>) {  // two columns at a time in SSE2 registers
          typedef double V2 __attribute__((vector_size(16)));
          for (; j + 1 <= hi; j += 2) {
            double* a = &H(k, j);
            double* b = a + N;
            V2 h0 = {a[0], b[0]}, h1 = {a[1], b[1]}, h2 = {a[2], b[2]};
            const V2 d = h0 + q * h1 + r * h2;
            h0 -= d * vx;
            h1 -= d * vy;
            h2 -= d * vz;
            a[0] = h0[0], b[0] = h0[1], a[1] = h1[0], b[1] = h1[1], a[2] = h2[0], b[2] = h2[1];
          }
        }
        for (; j <= hi; ++j) {
          S* h = &H(k, j);
          const S d = h[0] + q * h[1] + r * h[2];
          h[0] -= d * vx;
          h[1] -= d * vy;
          h[2] -= d * vz;
        }
        for (int i = lo; i < k; ++i) {
          const S d = vx * c0[i] + vy * c1[i] + vz * c2[i];
          c0[i] -= d;
          c1[i] -= d * q;
          c2[i] -= d * r;
        }
        p = a10, q = a20, r = rn;
        carried = true;
      } else {
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
