// Finite-position Burmester synthesis (3, 4, 5 positions), explicitly instantiated for one scalar (soma_instantiate).
#pragma once
#include "soma/geometry/planar/burmester_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

namespace soma::planar {

namespace {

/// Solve a small square system; false when singular.
template <class S> bool solveN(std::vector<std::vector<S>> a, std::vector<S> b, std::vector<S>& x) {
  using std::abs;
  const int n = int(a.size());
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (abs(a[i][k]) > abs(a[p][k])) p = i;
    if (a[p][k] == S(0)) return false;
    std::swap(a[p], a[k]);
    std::swap(b[p], b[k]);
    for (int i = k + 1; i < n; ++i) {
      const S f = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] -= f * a[k][j];
      b[i] -= f * b[k];
    }
  }
  x.assign(n, S(0));
  for (int k = n - 1; k >= 0; --k) {
    S s = b[k];
    for (int j = k + 1; j < n; ++j) s -= a[k][j] * x[j];
    x[k] = s / a[k][k];
  }
  return true;
}

template <class S> Poly2<S> det3(const Poly2<S> m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// Coefficients in y of p(x, y) at fixed x: q_j = Σ_i c_ij x^i.
template <class S> Poly1<S> inY(const Poly2<S>& p, const S& x) {
  Poly1<S> q(Poly2<S>::kMax + 1, S(0));
  for (int j = 0; j <= Poly2<S>::kMax; ++j) {
    S v(0);
    for (int i = Poly2<S>::kMax - j; i >= 0; --i) v = v * x + p.at(i, j);
    q[j] = v;
  }
  while (q.size() > 1 && q.back() == S(0)) q.pop_back();
  return q;
}

// ---- Five positions: the Burmester pairs as the intersection of two conics ---------------------
// |M_i z − m|² = r² (i = 1..5) expands to
//   K + |d_i|² − 2 d_i·m + 2 (R_iᵀd_i)·z − 2 (c_i P − s_i Q) = 0,
// K = |z|² + |m|² − r², P = m·z, Q = m_x z_y − m_y z_x: five equations LINEAR in
// v = (h, K, m, z, P, Q) ∈ P⁷ (h the homogenising coordinate). Their null space is a plane
// v = N w, w ∈ P², on which the two quadrics hP = m·z and hQ = m×z cut two conics; these meet in
// exactly four points (Bézout), the four Burmester pairs. The poles and the circular points of
// the centre-point-curve formulation never appear, so nothing has to be divided out.

/// Symmetric 3×3 eigen-decomposition by cyclic Jacobi rotations: A = V diag(w) Vᵀ (columns of V).
template <class W> void jacobi3(W a[3][3], W w[3], W v[3][3]) {
  using std::abs;
  using std::sqrt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v[i][j] = i == j ? W(1) : W(0);
  for (int sweep = 0; sweep < 60; ++sweep) {
    W off(0), tot(0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) (i == j ? tot : off) += a[i][j] * a[i][j];
    if (!(off > Tolerance<W>::epsilon() * Tolerance<W>::epsilon() * (tot + off))) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == W(0)) continue;
        const W theta = (a[q][q] - a[p][p]) / (W(2) * a[p][q]);
        const W t = (theta >= W(0) ? W(1) : W(-1)) / (abs(theta) + sqrt(theta * theta + W(1)));
        const W c = W(1) / sqrt(t * t + W(1)), s = t * c;
        for (int k = 0; k < 3; ++k) {  // A ← A J
          const W akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // A ← Jᵀ A
          const W apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const W vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  for (int i = 0; i < 3; ++i) w[i] = a[i][i];
}

template <class W> Cx<W> csqrt(const Cx<W>& z) {
  using std::abs;
  using std::sqrt;
  const W r = z.abs();
  const W re = sqrt((r + abs(z.re)) / W(2));
  if (re == W(0)) return Cx<W>(W(0));
  if (z.re >= W(0)) return Cx<W>(re, z.im / (W(2) * re));
  return Cx<W>(abs(z.im) / (W(2) * re), z.im >= W(0) ? re : -re);
}

/// Small dense complex solve (partial pivoting); false when singular.
template <class W> bool solveCx(std::vector<std::vector<Cx<W>>> a, std::vector<Cx<W>> b, std::vector<Cx<W>>& x) {
  const int n = int(a.size());
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (a[i][k].norm2() > a[p][k].norm2()) p = i;
    if (a[p][k].norm2() == W(0)) return false;
    std::swap(a[p], a[k]);
    std::swap(b[p], b[k]);
    for (int i = k + 1; i < n; ++i) {
      const Cx<W> f = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] = a[i][j] - f * a[k][j];
      b[i] = b[i] - f * b[k];
    }
  }
  x.assign(n, Cx<W>(W(0)));
  for (int k = n - 1; k >= 0; --k) {
    Cx<W> s = b[k];
    for (int j = k + 1; j < n; ++j) s = s - a[k][j] * x[j];
    x[k] = s / a[k][k];
  }
  return true;
}

/// The bilinear equations e_i = α_i + u_i·m + w_i·z + mᵀD_i z (i = 2..5) of normalised positions.
template <class W> struct BilinearSystem {
  W alpha[4], u[4][2], w[4][2], D[4][2][2];
  explicit BilinearSystem(const std::vector<SE2<W>>& q) {
    const Mat2<W> R1 = q[0].rotation();
    const Vec2<W> d1 = q[0].translation();
    for (int i = 0; i < 4; ++i) {
      const Mat2<W> Ri = q[i + 1].rotation();
      const Vec2<W> di = q[i + 1].translation();
      alpha[i] = di.squaredNorm() - d1.squaredNorm();
      const Vec2<W> uu = W(-2) * (di - d1), ww = W(2) * (Ri.transpose() * di - R1.transpose() * d1);
      const Mat2<W> DD = W(-2) * (Ri - R1);
      for (int k = 0; k < 2; ++k) {
        u[i][k] = uu(k);
        w[i][k] = ww(k);
        for (int l = 0; l < 2; ++l) D[i][k][l] = DD(k, l);
      }
    }
  }
  /// Values and Jacobian (columns m_x, m_y, z_x, z_y) at complex x = (m, z).
  void eval(const Cx<W> x[4], std::vector<Cx<W>>& e, std::vector<std::vector<Cx<W>>>& J) const {
    e.assign(4, Cx<W>(W(0)));
    J.assign(4, std::vector<Cx<W>>(4, Cx<W>(W(0))));
    for (int i = 0; i < 4; ++i) {
      Cx<W> v(alpha[i]);
      for (int k = 0; k < 2; ++k) {
        Cx<W> gm(u[i][k]), gz(w[i][k]);
        for (int l = 0; l < 2; ++l) {
          gm = gm + x[2 + l] * D[i][k][l];  // ∂/∂m_k = u_k + (D z)_k
          gz = gz + x[l] * D[i][l][k];      // ∂/∂z_k = w_k + (Dᵀm)_k
        }
        J[i][k] = gm;
        J[i][2 + k] = gz;
        v = v + x[k] * u[i][k] + x[2 + k] * w[i][k];
        for (int l = 0; l < 2; ++l) v = v + x[k] * x[2 + l] * D[i][k][l];
      }
      e[i] = v;
    }
  }
  /// max_i |e_i| / max(1, |m|, |z|)² (relative to the size of the terms; the frame is normalised).
  W maxAbs(const Cx<W> x[4]) const {
    std::vector<Cx<W>> e;
    std::vector<std::vector<Cx<W>>> J;
    eval(x, e, J);
    W r(0);
    for (const auto& v : e) r = std::max<W>(r, v.abs());
    const W m2 = x[0].norm2() + x[1].norm2(), z2 = x[2].norm2() + x[3].norm2();
    return r / std::max<W>({W(1), m2, z2});
  }
};

/// One algebraic solution (m, z) ∈ C⁴ in the normalised frame.
template <class W> struct AlgebraicSolution {
  Cx<W> x[4];
  W residualBefore{0}, residualAfter{0};
  bool atInfinity = false;
};

/// The four algebraic solutions of five normalised positions, polished by complex Newton.
/// Throws InvalidInput when the linear system has rank < 5 (degenerate positions).
template <class W> std::vector<AlgebraicSolution<W>> burmesterAlgebraic(const std::vector<SE2<W>>& q) {
  using std::abs;
  using std::sqrt;
  // 1. the 5 × 8 linear system in v = (h, K, m_x, m_y, z_x, z_y, P, Q)
  W A[5][8];
  W amax(0);
  for (int i = 0; i < 5; ++i) {
    const W c = q[i].real(), s = q[i].imag();
    const Vec2<W> d = q[i].translation();
    const W row[8] = {d.squaredNorm(), W(1), W(-2) * d(0), W(-2) * d(1), W(2) * (c * d(0) + s * d(1)),
                      W(2) * (-s * d(0) + c * d(1)), W(-2) * c, W(2) * s};
    for (int j = 0; j < 8; ++j) {
      A[i][j] = row[j];
      amax = std::max<W>(amax, abs(row[j]));
    }
  }
  // 2. null space by Gaussian elimination with full pivoting, then orthonormalised
  int col[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  for (int k = 0; k < 5; ++k) {
    int pi = k, pj = k;
    for (int i = k; i < 5; ++i)
      for (int j = k; j < 8; ++j)
        if (abs(A[i][col[j]]) > abs(A[pi][col[pj]])) {
          pi = i;
          pj = j;
        }
    if (!(abs(A[pi][col[pj]]) > Tolerance<W>::rank() * amax))
      throw InvalidInput("Burmester pairs: the five positions are degenerate (the linear system in (K, m, z, m·z, m×z) has rank " +
                         std::to_string(k) + " < 5)");
    for (int j = 0; j < 8; ++j) std::swap(A[pi][j], A[k][j]);
    std::swap(col[pj], col[k]);
    for (int i = k + 1; i < 5; ++i) {
      const W f = A[i][col[k]] / A[k][col[k]];
      for (int j = k; j < 8; ++j) A[i][col[j]] -= f * A[k][col[j]];
    }
  }
  W N[3][8];
  for (int f = 0; f < 3; ++f) {
    W x[8];
    for (int j = 0; j < 8; ++j) x[j] = W(0);
    x[col[5 + f]] = W(1);
    for (int k = 4; k >= 0; --k) {
      W s = A[k][col[5 + f]];
      for (int j = k + 1; j < 5; ++j) s += A[k][col[j]] * x[col[j]];
      x[col[k]] = -s / A[k][col[k]];
    }
    for (int pass = 0; pass < 2; ++pass)
      for (int g = 0; g < f; ++g) {
        W d(0);
        for (int j = 0; j < 8; ++j) d += N[g][j] * x[j];
        for (int j = 0; j < 8; ++j) x[j] -= d * N[g][j];
      }
    W n2(0);
    for (int j = 0; j < 8; ++j) n2 += x[j] * x[j];
    const W n = sqrt(n2);
    for (int j = 0; j < 8; ++j) N[f][j] = x[j] / n;
  }
  // 3. the two conics on the plane: hP − m·z and hQ − m×z as symmetric bilinear forms
  auto b1 = [](const W* u, const W* v) {
    return (u[0] * v[6] + u[6] * v[0] - u[2] * v[4] - u[4] * v[2] - u[3] * v[5] - u[5] * v[3]) / W(2);
  };
  auto b2 = [](const W* u, const W* v) {
    return (u[0] * v[7] + u[7] * v[0] - u[2] * v[5] - u[5] * v[2] + u[3] * v[4] + u[4] * v[3]) / W(2);
  };
  W C[2][3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      C[0][a][b] = b1(N[a], N[b]);
      C[1][a][b] = b2(N[a], N[b]);
    }
  for (auto& Ck : C) {
    W m(0);
    for (auto& r : Ck)
      for (const W& v : r) m = std::max<W>(m, abs(v));
    if (!(m > W(0))) throw InvalidInput("Burmester pairs: a constraint conic vanishes (degenerate positions)");
    for (auto& r : Ck)
      for (W& v : r) v /= m;
  }
  // 4. a degenerate member of the pencil: det(μ C1 + λ C2) = 0, a binary cubic
  auto det3s = [](const W M[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  };
  auto trAdj = [](const W M[3][3], const W B[3][3]) {  // tr(adj(M) B)
    W t(0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        const W cof = M[i1][j1] * M[i2][j2] - M[i1][j2] * M[i2][j1];  // cofactor of (i, j) = adj(j, i)
        t += cof * B[i][j];
      }
    return t;
  };
  const W d0 = det3s(C[0]), d1 = trAdj(C[0], C[1]), d2 = trAdj(C[1], C[0]), d3 = det3s(C[1]);
  const bool inLambda = abs(d3) >= abs(d0);  // member C1 + λ C2, else μ C1 + C2
  const Poly1<W> cubic = inLambda ? Poly1<W>{d0, d1, d2, d3} : Poly1<W>{d3, d2, d1, d0};
  const std::vector<Cx<W>> tr = polynomialRoots(cubic);
  // 5. among the real roots, the member that splits best into two lines (a pair of real lines
  //    always exists among them: the pencil is real and has 4 base points)
  W bestScore(-1), bw[3] = {W(0), W(0), W(0)}, bv[3][3] = {{W(1), W(0), W(0)}, {W(0), W(1), W(0)}, {W(0), W(0), W(1)}};
  W minIm(-1);
  for (const Cx<W>& r : tr) minIm = (minIm < W(0) || abs(r.im) < minIm) ? abs(r.im) : minIm;
  for (const Cx<W>& r : tr) {
    if (abs(r.im) > Tolerance<W>::sqrtEpsilon() * (W(1) + r.abs()) && abs(r.im) > minIm) continue;
    W M[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) M[a][b] = inLambda ? C[0][a][b] + r.re * C[1][a][b] : r.re * C[0][a][b] + C[1][a][b];
    W w[3], v[3][3];
    jacobi3(M, w, v);
    // order by |eigenvalue|, descending: w[0], w[1] the line pair, w[2] ≈ 0
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (abs(w[j]) > abs(w[i])) {
          std::swap(w[i], w[j]);
          for (int k = 0; k < 3; ++k) std::swap(v[k][i], v[k][j]);
        }
    W score = abs(w[1]) / (abs(w[0]) + abs(w[2])) - abs(w[2]) / abs(w[0]);
    if (w[0] * w[1] > W(0)) score /= W(4);  // conjugate complex lines: usable, but prefer real ones
    if (score > bestScore) {
      bestScore = score;
      for (int i = 0; i < 3; ++i) {
        bw[i] = w[i];
        for (int k = 0; k < 3; ++k) bv[k][i] = v[k][i];
      }
    }
  }
  // 6. lines l± = √w0 e0 ± √(−w1) e1; intersect each with the conic (C1 or C2) that is farther from the member
  const Cx<W> al = csqrt(Cx<W>(bw[0])), be = csqrt(Cx<W>(-bw[1]));
  std::vector<AlgebraicSolution<W>> out;
  const BilinearSystem<W> sys(q);
  for (int sgn = -1; sgn <= 1; sgn += 2) {
    Cx<W> l[3];
    for (int k = 0; k < 3; ++k) l[k] = al * bv[k][0] + be * bv[k][1] * W(sgn);
    // two points spanning the line: l × e_a, l × e_b, with e_c the largest |l_c| left out
    int c = 0;
    for (int k = 1; k < 3; ++k)
      if (l[k].norm2() > l[c].norm2()) c = k;
    Cx<W> p[2][3];
    for (int t = 0; t < 2; ++t) {
      const int a = (c + 1 + t) % 3;
      Cx<W> e[3] = {Cx<W>(W(0)), Cx<W>(W(0)), Cx<W>(W(0))};
      e[a] = Cx<W>(W(1));
      p[t][0] = l[1] * e[2] - l[2] * e[1];
      p[t][1] = l[2] * e[0] - l[0] * e[2];
      p[t][2] = l[0] * e[1] - l[1] * e[0];
    }
    // binary quadratic of each conic on the line; use the larger one
    Cx<W> qa, qb, qc;
    W qn(-1);
    for (int k = 0; k < 2; ++k) {
      Cx<W> s[2][2];
      for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y) {
          Cx<W> acc(W(0));
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) acc = acc + p[x][i] * p[y][j] * C[k][i][j];
          s[x][y] = acc;
        }
      const W n = s[0][0].abs() + s[0][1].abs() + s[1][1].abs();
      if (n > qn) {
        qn = n;
        qa = s[0][0];
        qb = s[0][1];
        qc = s[1][1];
      }
    }
    const Cx<W> sq = csqrt(qb * qb - qa * qc);
    const Cx<W> plus = qb + sq, minus = qb - sq;
    const Cx<W> g = plus.norm2() >= minus.norm2() ? -plus : -minus;  // −(b ± √Δ), the larger
    // roots (s : t) of a s² + 2b s t + c t²: (g : a) and (c : g)
    const Cx<W> st[2][2] = {{g, qa}, {qc, g}};
    for (const auto& r : st) {
      Cx<W> wv[3], v8[8];
      for (int i = 0; i < 3; ++i) wv[i] = r[0] * p[0][i] + r[1] * p[1][i];
      for (int j = 0; j < 8; ++j) {
        v8[j] = Cx<W>(W(0));
        for (int i = 0; i < 3; ++i) v8[j] = v8[j] + wv[i] * N[i][j];
      }
      AlgebraicSolution<W> sol;
      W vn(0);
      for (const auto& z : v8) vn = std::max<W>(vn, z.abs());
      if (!(v8[0].abs() > Tolerance<W>::rank() * vn)) {
        sol.atInfinity = true;
        out.push_back(sol);
        continue;
      }
      for (int k = 0; k < 4; ++k) sol.x[k] = v8[2 + k] / v8[0];
      sol.residualBefore = sys.maxAbs(sol.x);
      // complex Newton on the bilinear equations
      Cx<W> best[4] = {sol.x[0], sol.x[1], sol.x[2], sol.x[3]};
      W bestR = sol.residualBefore;
      for (int it = 0; it < 12; ++it) {
        std::vector<Cx<W>> e, dx;
        std::vector<std::vector<Cx<W>>> J;
        sys.eval(sol.x, e, J);
        for (auto& v : e) v = -v;
        if (!solveCx(J, e, dx)) break;
        W step(0), size(1);
        for (int k = 0; k < 4; ++k) {
          sol.x[k] = sol.x[k] + dx[k];
          step += dx[k].abs();
          size += sol.x[k].abs();
        }
        const W r = sys.maxAbs(sol.x);
        if (r < bestR) {
          bestR = r;
          for (int k = 0; k < 4; ++k) best[k] = sol.x[k];
        }
        if (step <= Tolerance<W>::epsilon() * size) break;
      }
      for (int k = 0; k < 4; ++k) sol.x[k] = best[k];
      sol.residualAfter = bestR;
      out.push_back(sol);
    }
  }
  return out;
}

}  // namespace

template <class S> BurmesterSynthesis<S>::BurmesterSynthesis(std::vector<SE2<S>> positions) : pos_(std::move(positions)) {
  using std::sqrt;
  const int n = int(pos_.size());
  if (n < 2 || n > 5)
    throw InvalidInput("Burmester synthesis: need 2 to 5 positions, got " + std::to_string(n));
  Vec2<S> mean = Vec2<S>::Zero();
  for (const auto& p : pos_) {
    if (!allFinite(p.translation()) || !isFinite(p.real()) || !isFinite(p.imag()))
      throw InvalidInput("Burmester synthesis: a position is NaN or infinite");
    mean += p.translation();
  }
  mean /= S(n);
  centroid_ = mean;
  S r2(0);
  for (const auto& p : pos_) r2 = std::max<S>(r2, (p.translation() - mean).squaredNorm());
  scale_ = S(1) + sqrt(r2);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const SE2<S> rel = pos_[j] * pos_[i].inverse();
      const S dt = sqrt(rel.translation().squaredNorm()) / scale_;
      using std::abs;
      if (abs(rel.angle()) <= Tolerance<S>::input() && dt <= Tolerance<S>::input())
        throw InvalidInput("Burmester synthesis: positions " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                           " coincide");
    }
}

// e_i = |p_i|² − |p_1|² evaluated as (p_i − p_1)·(p_i + p_1): p_i − p_1 = M_i z − M_1 z does not
// contain m, so a far centre point (|m| ≫ scale) costs eps·scale·|m| instead of eps·|m|².
template <class S> S BurmesterSynthesis<S>::equation(int i, const Vec2<S>& m, const Vec2<S>& z) const {
  const Vec2<S> wi = pos_[i - 1].act(z), w1 = pos_[0].act(z);
  return (wi - w1).dot(wi + w1 - S(2) * m);
}

template <class S> S BurmesterSynthesis<S>::residual(const Vec2<S>& m, const Vec2<S>& z) const {
  using std::abs;
  S r(0);
  for (int i = 2; i <= size(); ++i) r = std::max<S>(r, abs(equation(i, m, z)));
  const S rho2 = std::max<S>({scale_ * scale_, z.squaredNorm(), (m - centroid_).squaredNorm()});
  return r / rho2;
}

template <class S> Vec2<S> BurmesterSynthesis<S>::pole(int i, int j) const {
  return (pos_[j - 1] * pos_[i - 1].inverse()).centre();
}

// e_i = |d_i|² − |d_1|² − 2m·(d_i − d_1) + 2z·(R_iᵀd_i − R_1ᵀd_1) − 2mᵀ(R_i − R_1)z
template <class S> void BurmesterSynthesis<S>::rowInZ(int i, Poly2<S>& ax, Poly2<S>& ay, Poly2<S>& b) const {
  const Mat2<S> Ri = pos_[i - 1].rotation(), R1 = pos_[0].rotation();
  const Vec2<S> di = pos_[i - 1].translation(), d1 = pos_[0].translation();
  const Vec2<S> k = S(2) * (Ri.transpose() * di - R1.transpose() * d1);
  const Mat2<S> D = S(2) * (Ri - R1);  // coefficient of z in −mᵀD z is −Dᵀm
  ax = Poly2<S>::affine(k(0), -D(0, 0), -D(1, 0));
  ay = Poly2<S>::affine(k(1), -D(0, 1), -D(1, 1));
  const Vec2<S> dd = S(2) * (di - d1);
  b = Poly2<S>::affine(di.squaredNorm() - d1.squaredNorm(), -dd(0), -dd(1));
}

template <class S> void BurmesterSynthesis<S>::rowInM(int i, Poly2<S>& cx, Poly2<S>& cy, Poly2<S>& f) const {
  const Mat2<S> Ri = pos_[i - 1].rotation(), R1 = pos_[0].rotation();
  const Vec2<S> di = pos_[i - 1].translation(), d1 = pos_[0].translation();
  const Vec2<S> k = S(2) * (Ri.transpose() * di - R1.transpose() * d1);
  const Mat2<S> D = S(2) * (Ri - R1);
  const Vec2<S> dd = S(2) * (di - d1);
  // coefficient of m: −dd − D z
  cx = Poly2<S>::affine(-dd(0), -D(0, 0), -D(0, 1));
  cy = Poly2<S>::affine(-dd(1), -D(1, 0), -D(1, 1));
  f = Poly2<S>::affine(di.squaredNorm() - d1.squaredNorm(), k(0), k(1));
}

template <class S> std::optional<Vec2<S>> BurmesterSynthesis<S>::centreForCirclePoint(const Vec2<S>& z) const {
  using std::abs;
  if (size() < 3) throw InvalidInput("centre for a circle point: need at least 3 positions");
  // rows 2, 3 in m: c_i(z)·m = −f_i(z)
  Poly2<S> cx[2], cy[2], f[2];
  for (int r = 0; r < 2; ++r) rowInM(r + 2, cx[r], cy[r], f[r]);
  const S a = cx[0](z(0), z(1)), b = cy[0](z(0), z(1)), c = cx[1](z(0), z(1)), d = cy[1](z(0), z(1));
  const S e = -f[0](z(0), z(1)), g = -f[1](z(0), z(1));
  const S det = a * d - b * c;
  if (!(abs(det) > Tolerance<S>::rank() * (abs(a * d) + abs(b * c)))) return std::nullopt;
  return Vec2<S>((e * d - b * g) / det, (a * g - e * c) / det);
}

template <class S> std::optional<Vec2<S>> BurmesterSynthesis<S>::circlePointForCentre(const Vec2<S>& m) const {
  using std::abs;
  if (size() < 3) throw InvalidInput("circle point for a centre: need at least 3 positions");
  // least squares over rows 2..n: a_i(m)·z = −b_i(m)
  S A00(0), A01(0), A11(0), r0(0), r1(0);
  for (int i = 2; i <= size(); ++i) {
    Poly2<S> ax, ay, b;
    rowInZ(i, ax, ay, b);
    const S u = ax(m(0), m(1)), v = ay(m(0), m(1)), w = -b(m(0), m(1));
    A00 += u * u;
    A01 += u * v;
    A11 += v * v;
    r0 += u * w;
    r1 += v * w;
  }
  const S det = A00 * A11 - A01 * A01;
  if (!(abs(det) > Tolerance<S>::rank() * (A00 * A11 + A01 * A01))) return std::nullopt;
  return Vec2<S>((r0 * A11 - A01 * r1) / det, (A00 * r1 - A01 * r0) / det);
}

template <class S> Poly2<S> BurmesterSynthesis<S>::centrePointCurve(int k) const {
  if (size() < 4 || k < 4 || k > size()) throw InvalidInput("centre-point curve: need 4 positions (k = 4 or 5)");
  Poly2<S> M[3][3];
  const int rows[3] = {2, 3, k};
  for (int r = 0; r < 3; ++r) rowInZ(rows[r], M[r][0], M[r][1], M[r][2]);
  return det3(M);
}

template <class S> Poly2<S> BurmesterSynthesis<S>::circlePointCurve(int k) const {
  if (size() < 4 || k < 4 || k > size()) throw InvalidInput("circle-point curve: need 4 positions (k = 4 or 5)");
  Poly2<S> M[3][3];
  const int rows[3] = {2, 3, k};
  for (int r = 0; r < 3; ++r) rowInM(rows[r], M[r][0], M[r][1], M[r][2]);
  return det3(M);
}

// Five positions, beyond GF §5.3.5 (the finite-position analogue of GF-5.3.5-burmester-count):
// the four Burmester pairs as the intersection of two conics (see burmesterAlgebraic), each
// polished by Newton on the four bilinear equations e_2..e_5 in the working scalar.
template <class S>
std::vector<BurmesterPair<S>> BurmesterSynthesis<S>::burmesterPairs(int* complexCount, S* complexResidual, S* algebraicResidual,
                                                                    std::string* notes, bool escalateFloat) const {
  using std::abs;
  using std::sqrt;
  if (size() != 5) throw InvalidInput("Burmester pairs: need exactly 5 positions, got " + std::to_string(size()));
  // Normalised frame: centred on the mean translation, lengths / scale.
  Vec2<S> mean = Vec2<S>::Zero();
  for (const auto& p : pos_) mean += p.translation();
  mean /= S(5);
  std::vector<SE2<S>> q;
  for (const auto& p : pos_) q.push_back(SE2<S>(p.angle(), Vec2<S>((p.translation() - mean) / scale_)));
  // The algebraic step runs in W: S itself, except float, whose 24-bit conic intersection loses
  // real pairs on ill-conditioned sets; float solves in double and polishes in float (noted),
  // unless escalateFloat is false (the float rung alone: its solutions are carried in W exactly).
  using W = std::conditional_t<std::is_same_v<S, float>, double, S>;
  const bool floatAlone = std::is_same_v<S, float> && !escalateFloat;
  std::vector<AlgebraicSolution<W>> sols;
  if constexpr (std::is_same_v<S, float>) {
    if (floatAlone) {
      for (const AlgebraicSolution<S>& f : burmesterAlgebraic(q)) {
        AlgebraicSolution<W> w;
        for (int k = 0; k < 4; ++k) w.x[k] = Cx<W>(W(f.x[k].re), W(f.x[k].im));
        w.residualBefore = W(f.residualBefore);
        w.residualAfter = W(f.residualAfter);
        w.atInfinity = f.atInfinity;
        sols.push_back(w);
      }
    }
  }
  if (!floatAlone) {
    std::vector<SE2<W>> qw;
    for (const auto& p : q) qw.push_back(SE2<W>(scalarCast<W>(p.angle()), Vec2<W>(scalarCast<W>(p.translation()(0)), scalarCast<W>(p.translation()(1)))));
    sols = burmesterAlgebraic(qw);
  }
  // The real/complex decision at the precision the solutions were computed in.
  const W realTol = floatAlone ? W(Tolerance<S>::sqrtEpsilon()) : Tolerance<W>::sqrtEpsilon();
  if (notes) {
    *notes = !std::is_same_v<S, float> ? ""
             : floatAlone              ? "conic intersection solved in float (no escalation)"
                                       : "conic intersection solved in double, pairs polished in float";
  }
  int complexRoots = 0, infinite = 0;
  S worstComplex(0), worstAlg(0);
  std::vector<BurmesterPair<S>> out;
  for (const auto& sol : sols) {
    if (sol.atInfinity) {
      ++infinite;
      continue;
    }
    worstAlg = std::max<S>(worstAlg, scalarCast<S>(sol.residualBefore));
    W im(0), mag(1);
    for (const auto& v : sol.x) {
      im = std::max<W>(im, abs(v.im));
      mag += v.abs();
    }
    if (im > realTol * W(16) * mag) {
      ++complexRoots;
      worstComplex = std::max<S>(worstComplex, scalarCast<S>(sol.residualAfter));
      continue;
    }
    Vec2<S> m(scalarCast<S>(sol.x[0].re), scalarCast<S>(sol.x[1].re)), z(scalarCast<S>(sol.x[2].re), scalarCast<S>(sol.x[3].re));
    // Newton on e_2..e_5 in (m, z), in S; keep the best iterate.
    auto res = [&](const Vec2<S>& mm, const Vec2<S>& zz) {
      S r(0);
      for (int i = 2; i <= 5; ++i) {
        const Vec2<S> wi = q[i - 1].act(zz), w1 = q[0].act(zz);
        r = std::max<S>(r, abs((wi - w1).dot(wi + w1 - S(2) * mm)));
      }
      return r;
    };
    Vec2<S> bm = m, bz = z;
    S br = res(m, z);
    for (int it = 0; it < 8; ++it) {
      std::vector<std::vector<S>> J(4, std::vector<S>(4));
      std::vector<S> e(4), dx;
      for (int i = 2; i <= 5; ++i) {
        const Mat2<S> Ri = q[i - 1].rotation(), R1 = q[0].rotation();
        const Vec2<S> di = q[i - 1].translation(), d1 = q[0].translation();
        const Vec2<S> wi = Ri * z + di, w1 = R1 * z + d1, pi = wi - m, p1 = w1 - m;
        e[i - 2] = -(wi - w1).dot(wi + w1 - S(2) * m);
        const Vec2<S> gm = S(-2) * (pi - p1);
        const Vec2<S> gz = S(2) * (Ri.transpose() * pi - R1.transpose() * p1);
        J[i - 2] = {gm(0), gm(1), gz(0), gz(1)};
      }
      if (!solveN(J, e, dx)) break;
      m += Vec2<S>(dx[0], dx[1]);
      z += Vec2<S>(dx[2], dx[3]);
      const S r = res(m, z);
      if (r < br) {
        br = r;
        bm = m;
        bz = z;
      }
      if (abs(dx[0]) + abs(dx[1]) + abs(dx[2]) + abs(dx[3]) <= Tolerance<S>::epsilon() * (S(1) + m.norm() + z.norm())) break;
    }
    // back to world: m_world = mean + scale·m, z_body = scale·z (body coordinates are unchanged)
    BurmesterPair<S> bp;
    bp.centre = mean + bm * scale_;
    bp.circle = bz * scale_;
    bp.radius = sqrt((pos_[0].act(bp.circle) - bp.centre).squaredNorm());
    bp.residual = residual(bp.centre, bp.circle);
    out.push_back(bp);
  }
  if (notes && infinite > 0) *notes += std::string(notes->empty() ? "" : "; ") + std::to_string(infinite) + " solution(s) at infinity (slider dyads)";
  if (complexCount) *complexCount = complexRoots;
  if (complexResidual) *complexResidual = worstComplex;
  if (algebraicResidual) *algebraicResidual = worstAlg;
  return out;
}

template <class S> FourBar<S> BurmesterSynthesis<S>::fourBar(const BurmesterPair<S>& a, const BurmesterPair<S>& b) const {
  const SE2<S>& M1 = pos_[0];
  return FourBar<S>::fromJoints(a.centre, M1.act(a.circle), M1.act(b.circle), b.centre, M1.translation());
}

template <class S> DriveCheck<S> BurmesterSynthesis<S>::drive(const BurmesterPair<S>& a, const BurmesterPair<S>& b) const {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  const FourBar<S> fb = fourBar(a, b);
  DriveCheck<S> out;
  // coupler frame in body coordinates: origin z_a, x along z_b − z_a
  const Vec2<S> zb = b.circle - a.circle;
  const SE2<S> K(atan2(zb(1), zb(0)), a.circle);
  for (const SE2<S>& M : pos_) {
    const Vec2<S> c2 = M.act(a.circle), c3 = M.act(b.circle);
    const Vec2<S> v = c2 - a.centre;
    const S th = atan2(v(1), v(0));
    const int mode = cross2<S>(b.centre - c2, c3 - c2) >= S(0) ? 1 : -1;
    out.modes.push_back(mode);
    const auto pose = fb.solve(th, mode);
    if (!pose) {
      out.reached = false;
      out.translationErrors.push_back(S(1));
      out.angleErrors.push_back(pi<S>());
      out.circuits.push_back(-1);
      continue;
    }
    const SE2<S> got = pose->coupler * K.inverse();
    const S et = sqrt((got.translation() - M.translation()).squaredNorm()) / scale_;
    const SE2<S> d = got * M.inverse();
    const S ea = abs(d.angle());
    out.translationErrors.push_back(et);
    out.angleErrors.push_back(ea);
    out.worstTranslation = std::max<S>(out.worstTranslation, et);
    out.worstAngle = std::max<S>(out.worstAngle, ea);
    out.circuits.push_back(fb.circuitOf(*pose));
  }
  for (int c : out.circuits)
    if (c != out.circuits.front()) out.sameCircuit = false;
  return out;
}

template <class S> std::vector<Vec2<S>> sampleCurve(const Poly2<S>& p, const S& x0, const S& x1, const S& y0, const S& y1, int n) {
  using std::abs;
  std::vector<Vec2<S>> out;
  const S tol = Tolerance<S>::sqrtEpsilon();
  for (int k = 0; k <= n; ++k) {
    const S x = x0 + (x1 - x0) * S(k) / S(n);
    const Poly1<S> c = inY(p, x);
    if (c.size() < 2) continue;
    for (const Cx<S>& r : polynomialRoots(c))
      if (abs(r.im) <= tol * (S(1) + r.abs()) && r.re >= y0 && r.re <= y1) out.push_back(Vec2<S>(x, r.re));
  }
  // horizontal lines: swap roles of x and y
  Poly2<S> t;
  for (int i = 0; i <= Poly2<S>::kMax; ++i)
    for (int j = 0; i + j <= Poly2<S>::kMax; ++j) t.at(j, i) = p.at(i, j);
  for (int k = 0; k <= n; ++k) {
    const S y = y0 + (y1 - y0) * S(k) / S(n);
    const Poly1<S> c = inY(t, y);
    if (c.size() < 2) continue;
    for (const Cx<S>& r : polynomialRoots(c))
      if (abs(r.im) <= tol * (S(1) + r.abs()) && r.re >= x0 && r.re <= x1) out.push_back(Vec2<S>(r.re, y));
  }
  return out;
}

#define SOMA_INSTANTIATE_BURMESTER_SYNTHESIS(T) namespace planar { \
  template class BurmesterSynthesis<T>; \
  template std::vector<Vec2<T>> sampleCurve<T>(const Poly2<T>&, const T&, const T&, const T&, const T&, int); }

}  // namespace soma::planar
