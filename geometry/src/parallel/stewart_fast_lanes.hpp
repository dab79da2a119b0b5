// The fast double tracker's kernel, kLanes paths at a time (GF §11.5.4, GF-11.5.4-stewart-forty):
// the tracker of stewart_fast_tracker.hpp (Hermite predictor, one LU a step, simplified Newton) with
// every complex number a pack of kLanes lanes, one path per lane, in lockstep: the lanes step
// together (each with its own τ, step size and history), Newton's iterations are masked per lane, a
// lane whose path ends takes the next path. The arithmetic is the same in every lane; only control
// flow (accept, reject, step size) is per lane, in scalar code.
//
// No include guard on purpose: stewart_fast_tracker.cpp includes this file three times, inside
// namespace soma::stewart_fast::portable (the default instruction set: a pack of four is two SSE2
// registers), ::avx2 under a target("avx2,fma") attribute (one AVX2 register, fused multiply–adds)
// and ::avx512 (kLanes = 8, one AVX-512 register), and calls the widest the CPU supports. It needs
// stewart_fast_tracker.hpp first.

#if defined(__clang__)
// Products and sums are fused wherever they meet after inlining (a − f·b in the LU is two FMAs per
// component), not only within one expression: only rounding changes, and only for the better.
#pragma clang fp contract(fast)
#endif

typedef double P __attribute__((vector_size(8 * kLanes)));
typedef long long Mk __attribute__((vector_size(8 * kLanes)));

inline P splat(double v) { return P{} + v; }
inline Mk splatm(long long v) { return Mk{} + v; }
/// The pack of kLanes doubles v[0…].
inline P packOf(const double* v) {
  P r;
  for (int l = 0; l < kLanes; ++l) r[l] = v[l];
  return r;
}
/// m ? a : b lane by lane (m's lanes all ones or all zeros, as a comparison gives them).
inline P sel(Mk m, P a, P b) { return (P)(((Mk)a & m) | ((Mk)b & ~m)); }
inline Mk selm(Mk m, Mk a, Mk b) { return (a & m) | (b & ~m); }
inline bool any(Mk m) {
  long long r = 0;
  for (int l = 0; l < kLanes; ++l) r |= m[l];
  return r != 0;
}
inline P vabs(P a) { return (P)((Mk)a & splatm(0x7fffffffffffffffLL)); }
inline P vmax(P a, P b) { return sel(a > b, a, b); }
inline P vmin(P a, P b) { return sel(a < b, a, b); }
/// The lanes as a mask from per-lane flags.
inline Mk maskOf(const bool* f) {
  Mk m;
  for (int l = 0; l < kLanes; ++l) m[l] = f[l] ? -1LL : 0;
  return m;
}

/// A pack of four complex numbers.
struct C {
  P re, im;
};
inline C operator+(C a, C b) { return {a.re + b.re, a.im + b.im}; }
inline C operator-(C a, C b) { return {a.re - b.re, a.im - b.im}; }
inline C operator-(C a) { return {-a.re, -a.im}; }
inline C operator*(C a, C b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
/// A complex number common to the lanes times a pack.
inline C operator*(Cx a, C b) {
  const P ar = splat(a.re), ai = splat(a.im);
  return {ar * b.re - ai * b.im, ar * b.im + ai * b.re};
}
inline C operator*(double s, C a) { return {splat(s) * a.re, splat(s) * a.im}; }
inline C operator*(P s, C a) { return {s * a.re, s * a.im}; }
inline C cpack(Cx a) { return {splat(a.re), splat(a.im)}; }
inline C csel(Mk m, C a, C b) { return {sel(m, a.re, b.re), sel(m, a.im, b.im)}; }
inline C recip(C a) {
  const P n = a.re * a.re + a.im * a.im;
  return {a.re / n, -a.im / n};
}
inline P mod1(C a) { return vabs(a.re) + vabs(a.im); }

using CV = std::array<C, 8>;
using CM = std::array<std::array<C, 8>, 8>;

/// max_k |x_k|₁ lane by lane (NaN lanes may be lost here: `sumNorm` catches them).
inline P maxNorm(const CV& x) {
  P m = mod1(x[0]);
  for (int k = 1; k < 8; ++k) m = vmax(m, mod1(x[k]));
  return m;
}
inline P sumNorm(const CV& x) {
  P m = mod1(x[0]);
  for (int k = 1; k < 8; ++k) m = m + mod1(x[k]);
  return m;
}

inline Cx lane(const C& z, int l) { return {z.re[l], z.im[l]}; }
inline void setLane(C& z, int l, Cx v) {
  z.re[l] = v.re;
  z.im[l] = v.im;
}

/// LU with threshold pivoting in place, lane by lane, in LINPACK's layout: at column k only columns
/// k…7 of rows k and piv[k] are swapped (the multipliers stay where they were computed; `solve`
/// applies the swaps interleaved with the forward substitution). A lane keeps its diagonal pivot
/// unless it is smaller than `tau` × the column's largest entry, then takes the largest (tau = 1:
/// partial pivoting; tau < 1 bounds the growth by 1 + 1/tau a column and spares most swaps, which
/// cost blends across the lanes); bit k of `swaps` says whether some lane swapped at column k.
/// Returns smallest/largest pivot modulus per lane (0 when singular; such a lane's entries are then
/// not finite).
inline P factor(CM& A, Mk* piv, unsigned& swaps, double tau) {
  P pmax = mod1(A[0][0]), pmin = pmax;
  Mk singular = splatm(0);
  swaps = 0;
  for (int k = 0; k < 8; ++k) {
    const P diag = mod1(A[k][k]);
    P best = diag;
    Mk p = splatm(k);
    for (int r = k + 1; r < 8; ++r) {
      const P v = mod1(A[r][k]);
      const Mk m = v > best;
      best = sel(m, v, best);
      p = selm(m, splatm(r), p);
    }
    const Mk keep = diag >= splat(tau) * best;
    p = selm(keep, splatm(k), p);
    best = sel(keep, diag, best);
    singular = singular | ~(best > splat(0));
    piv[k] = p;
    if (any(p != splatm(k))) {
      swaps |= 1u << k;
      for (int r = k + 1; r < 8; ++r) {
        const Mk m = p == splatm(r);
        if (!any(m)) continue;
        for (int c = k; c < 8; ++c) {
          const C a = A[k][c], b = A[r][c];
          A[k][c] = csel(m, b, a);
          A[r][c] = csel(m, a, b);
        }
      }
    }
    pmax = vmax(pmax, best);
    pmin = vmin(pmin, best);
    const C inv = recip(A[k][k]);
    A[k][k] = inv;
    for (int r = k + 1; r < 8; ++r) {
      const C f = A[r][k] * inv;
      A[r][k] = f;
      for (int c = k + 1; c < 8; ++c) A[r][c] = A[r][c] - f * A[k][c];
    }
  }
  return sel(singular, splat(0), pmin / pmax);
}

/// b[j] ← A⁻¹ b[j] for the N right-hand sides with the factors of `factor`, in one pass (the
/// substitutions of the N are independent chains: interleaved, each waits less on the others' latency).
template <int N> inline void solveN(const CM& A, const Mk* piv, unsigned swaps, CV* const* b) {
  for (int k = 0; k < 8; ++k) {
    if (swaps & (1u << k)) {
      const Mk p = piv[k];
      for (int r = k + 1; r < 8; ++r) {
        const Mk m = p == splatm(r);
        if (!any(m)) continue;
        for (int j = 0; j < N; ++j) {
          CV& x = *b[j];
          const C a = x[k];
          x[k] = csel(m, x[r], a);
          x[r] = csel(m, a, x[r]);
        }
      }
    }
    for (int r = k + 1; r < 8; ++r)
      for (int j = 0; j < N; ++j) (*b[j])[r] = (*b[j])[r] - A[r][k] * (*b[j])[k];
  }
  for (int k = 7; k >= 0; --k) {
    C s[N];
    for (int j = 0; j < N; ++j) s[j] = (*b[j])[k];
    for (int c = k + 1; c < 8; ++c)
      for (int j = 0; j < N; ++j) s[j] = s[j] - A[k][c] * (*b[j])[c];
    for (int j = 0; j < N; ++j) (*b[j])[k] = s[j] * A[k][k];
  }
}
/// b ← A⁻¹ b with the factors of `factor`.
inline void solve(const CM& A, const Mk* piv, unsigned swaps, CV& b) {
  CV* const r[1] = {&b};
  solveN<1>(A, piv, swaps, r);
}
/// b ← A⁻¹ b and c ← A⁻¹ c in one pass.
inline void solve(const CM& A, const Mk* piv, unsigned swaps, CV& b, CV& c) {
  CV* const r[2] = {&b, &c};
  solveN<2>(A, piv, swaps, r);
}

/// The platform of Homotopy at τ, one τ per lane (φ = τ/(τ + γ(1 − τ)) is exactly 1 at τ = 1, and
/// dφ/dτ = γ/(τ + γ(1 − τ))² is γ there, as in Homotopy::at).
struct At {
  C d[6][3], s[6][3], l[6], dphi;
};
inline void at(const Homotopy& H, P t, At& A) {
  const C g = cpack(H.gamma);
  const P u = splat(1) - t;
  const C den{t + u * g.re, u * g.im};
  const C iden = recip(den);
  const C phi = t * iden;
  A.dphi = g * (iden * iden);
  for (int i = 0; i < 6; ++i) {
    const Homotopy::Leg& L = H.leg[i];
    for (int k = 0; k < 3; ++k) {
      A.d[i][k] = cpack(L.d0[k]) + L.dd[k] * phi;
      A.s[i][k] = cpack(L.s0[k]) + L.ds[k] * phi;
    }
    A.l[i] = cpack(L.l0) + L.dl * phi;
  }
}

/// The leg vectors u of one point (GF-11.5.4-stewart-leg-quadric), kept from `eval` for `evalFt`.
struct Us {
  C u[6][4];
};

/// The leg vector u = M x of leg i (d, s its joints' difference and sum at τ): u₀ = −a_v·d + 2c₀,
/// u_v = a₀ d + a_v × s + 2c_v, linear in x.
inline void legU(const CV& x, const C* d, const C* s, C* u) {
  u[0] = 2.0 * x[4] - (x[1] * d[0] + x[2] * d[1] + x[3] * d[2]);
  u[1] = x[0] * d[0] + (x[2] * s[2] - x[3] * s[1]) + 2.0 * x[5];
  u[2] = x[0] * d[1] + (x[3] * s[0] - x[1] * s[2]) + 2.0 * x[6];
  u[3] = x[0] * d[2] + (x[1] * s[1] - x[2] * s[0]) + 2.0 * x[7];
}

/// f = H(x, τ) lane by lane, and (J non-null) J = ∂H/∂x, (U non-null) the leg vectors u for evalFt
/// (u = a q + 2c − p a: u₀ = −a_v·d + 2c₀, u_v = a₀ d + a_v × s + 2c_v; leg i is u·u − L² a·a).
inline void eval(const Homotopy& H, const At& A, const CV& x, CV& f, CM* J, Us* U) {
  const C aa = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
  f[0] = x[0] * x[4] + x[1] * x[5] + x[2] * x[6] + x[3] * x[7];
  if (J)
    for (int k = 0; k < 4; ++k) {
      (*J)[0][k] = x[k + 4];
      (*J)[0][k + 4] = x[k];
    }
  for (int i = 0; i < 6; ++i) {
    const C* d = A.d[i];
    const C* s = A.s[i];
    const C L = A.l[i];
    C uv[4];
    legU(x, d, s, uv);
    const C u0 = uv[0], u1 = uv[1], u2 = uv[2], u3 = uv[3];
    f[i + 1] = u0 * u0 + u1 * u1 + u2 * u2 + u3 * u3 - L * aa;
    if (U) U->u[i][0] = u0, U->u[i][1] = u1, U->u[i][2] = u2, U->u[i][3] = u3;
    if (!J) continue;
    auto& row = (*J)[i + 1];
    row[0] = 2.0 * (u1 * d[0] + u2 * d[1] + u3 * d[2] - L * x[0]);
    row[1] = 2.0 * ((s[1] * u3 - s[2] * u2) - u0 * d[0] - L * x[1]);
    row[2] = 2.0 * ((s[2] * u1 - s[0] * u3) - u0 * d[1] - L * x[2]);
    row[3] = 2.0 * ((s[0] * u2 - s[1] * u1) - u0 * d[2] - L * x[3]);
    row[4] = 4.0 * u0;
    row[5] = 4.0 * u1;
    row[6] = 4.0 * u2;
    row[7] = 4.0 * u3;
  }
  C v = cpack({-1, 0});
  for (int k = 0; k < 8; ++k) {
    v = v + H.h[k] * x[k];
    if (J) (*J)[7][k] = cpack(H.h[k]);
  }
  f[7] = v;
}

/// ft = ∂H/∂τ at x, with the leg vectors U that `eval` computed at x.
inline void evalFt(const Homotopy& H, const At& A, const CV& x, const Us& U, CV& ft) {
  const C aa = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
  ft[0] = cpack({0, 0});
  for (int i = 0; i < 6; ++i) {
    const Homotopy::Leg& g = H.leg[i];
    const C* u = U.u[i];
    const C du0 = -(g.dd[0] * x[1] + g.dd[1] * x[2] + g.dd[2] * x[3]);
    const C du1 = g.dd[0] * x[0] + (g.ds[2] * x[2] - g.ds[1] * x[3]);
    const C du2 = g.dd[1] * x[0] + (g.ds[0] * x[3] - g.ds[2] * x[1]);
    const C du3 = g.dd[2] * x[0] + (g.ds[1] * x[1] - g.ds[0] * x[2]);
    ft[i + 1] = A.dphi * (2.0 * (u[0] * du0 + u[1] * du1 + u[2] * du2 + u[3] * du3) - g.dl * aa);
  }
  ft[7] = cpack({0, 0});
}

/// out = −(J(y₁) − J(y₀)) v, J = ∂H/∂x at one τ, from dy = y₁ − y₀ and the leg vectors U1, U0 that
/// `eval` computed at y₁ and y₀: H is quadratic in x, so J is affine in x and the change is bilinear
/// in (dy, v): for leg i, J_i(x) v = 2 u(x)·(M v) − 2L a(x)·a(v) (u = M x, a = x₀…₃); row 0 is the
/// Study quadric a·b, row 7 the chart (constant). The tangent's refinement residual −∂H/∂τ − J(y₁) v
/// when J(y₀) v = −∂H/∂τ, without forming J(y₁).
inline void jacobianChangeTimes(const At& A, const CV& dy, const Us& U1, const Us& U0, const CV& v, CV& out) {
  const C adv = dy[0] * v[0] + dy[1] * v[1] + dy[2] * v[2] + dy[3] * v[3];
  out[0] = -(dy[4] * v[0] + dy[5] * v[1] + dy[6] * v[2] + dy[7] * v[3] + dy[0] * v[4] + dy[1] * v[5] + dy[2] * v[6] +
             dy[3] * v[7]);
  for (int i = 0; i < 6; ++i) {
    C m[4];
    legU(v, A.d[i], A.s[i], m);
    const C* u1 = U1.u[i];
    const C* u0 = U0.u[i];
    out[i + 1] = -2.0 * ((u1[0] - u0[0]) * m[0] + (u1[1] - u0[1]) * m[1] + (u1[2] - u0[2]) * m[2] +
                         (u1[3] - u0[3]) * m[3] - A.l[i] * adv);
  }
  out[7] = cpack({0, 0});
}

/// Newton at τ = 1 on up to kLanes endpoints (paths[0…count)), as the scalar tracker's polish: until the
/// correction is at the rounding floor (64 eps), or stops decreasing (then it must already be below
/// the tracking accuracy).
inline void polish(const Homotopy& H, const Settings& o, const int* paths, int count, Path* out) {
  const double eps = Tolerance<double>::epsilon();
  At A;
  at(H, splat(1), A);
  CV y, f;
  CM J;
  Mk piv[8];
  bool act[kLanes], conv[kLanes];
  double prev[kLanes], pr[kLanes];
  for (int l = 0; l < kLanes; ++l) {
    const Path& r = out[paths[l < count ? l : 0]];
    for (int k = 0; k < 8; ++k) setLane(y[k], l, r.x[k]);
    act[l] = l < count, conv[l] = false, prev[l] = 0, pr[l] = 0;
  }
  for (int it = 0; it < 10; ++it) {
    eval(H, A, y, f, &J, nullptr);
    unsigned sw;
    const P ratio = factor(J, piv, sw, 1.0);  // partial pivoting: its pivot ratio decides "singular"
    solve(J, piv, sw, f);
    CV z;
    for (int k = 0; k < 8; ++k) z[k] = y[k] - f[k];
    const P fn = maxNorm(f), fs = sumNorm(f), zn = maxNorm(z);
    bool take[kLanes];
    bool more = false;
    for (int l = 0; l < kLanes; ++l) {
      take[l] = false;
      if (!act[l]) continue;
      ++out[paths[l]].lus;
      pr[l] = ratio[l];
      const double dn = fn[l];
      if (!(pr[l] > 0) || !(fs[l] == fs[l])) {
        act[l] = false;
        continue;
      }
      const double scale = std::max(1.0, zn[l]);
      if (it > 0 && dn > prev[l] / 2) {
        conv[l] = prev[l] <= o.accept * scale;
        act[l] = false;
        continue;
      }
      take[l] = true;
      prev[l] = dn;
      if (dn <= 64 * eps * scale) {
        conv[l] = true;
        act[l] = false;
      }
      more = more || act[l];
    }
    const Mk m = maskOf(take);
    for (int k = 0; k < 8; ++k) y[k] = csel(m, z[k], y[k]);
    if (!more) break;
  }
  for (int l = 0; l < count; ++l) {
    Path& r = out[paths[l]];
    for (int k = 0; k < 8; ++k) r.x[k] = lane(y[k], l);
    r.pivotRatio = pr[l];
    r.finite = conv[l] && pr[l] > Tolerance<double>::sqrtEpsilon();
  }
}

/// The Hermite weights of stewart_fast::hermite (n ≤ 3 nodes T at slots ord, evaluated at t) into
/// the lane's slots of wx, wv (0 for an unused slot).
inline void hermiteWeights(int n, const int* ord, const double* T, double t, double* wx, double* wv) {
  for (int s = 0; s < 3; ++s) wx[s] = wv[s] = 0;
  for (int j = 0; j < n; ++j) {
    double l = 1, dl = 0;
    const double tj = T[ord[j]];
    for (int m = 0; m < n; ++m) {
      if (m == j) continue;
      const double inv = 1.0 / (tj - T[ord[m]]);
      l *= (t - T[ord[m]]) * inv;
      dl += inv;
    }
    const double l2 = l * l, dt = t - tj;
    wx[ord[j]] = (1 - 2 * dl * dt) * l2;
    wv[ord[j]] = dt * l2;
  }
}

/// x^(1/(2n)) for the predictor of n nodes (error O(h^(2n))): the step-size factor's root.
inline double orderRoot(double x, int n) {
  if (n == 1) return std::sqrt(x);
  if (n == 2) return std::sqrt(std::sqrt(x));
  return std::sqrt(std::cbrt(x));
}

/// One lane: a path (path < 0: idle), its τ, step and history slots (ord: oldest first).
struct Lane {
  int path = -1;
  double t = 0, h = 0;
  bool justRejected = false;
  int n = 0, ord[3] = {0, 1, 2};
  double T[3] = {0, 0, 0};
};
/// The lanes' shared state: the histories (slot s of every lane in X[s], V[s]) and the queue of paths.
struct Lanes {
  CV X[3], V[3];
  const V8* starts = nullptr;
  const V8* tangent = nullptr;
  const char* started = nullptr;
  int count = 0, next = 0;
  double hstart = 0;
};
/// Gives lane l the next path whose start is regular (a singular start is a failed path), or none.
inline void load(Lanes& Q, Lane& L, int l) {
  L = Lane{};
  while (Q.next < Q.count && !Q.started[Q.next]) ++Q.next;
  if (Q.next >= Q.count) return;
  L.path = Q.next++;
  L.h = Q.hstart, L.n = 1;
  for (int s = 0; s < 3; ++s)
    for (int k = 0; k < 8; ++k) setLane(Q.X[s][k], l, {0, 0}), setLane(Q.V[s][k], l, {0, 0});
  for (int k = 0; k < 8; ++k) {
    setLane(Q.X[0][k], l, Q.starts[L.path][k]);
    setLane(Q.V[0][k], l, Q.tangent[L.path][k]);
  }
}

/// Tracks the paths from `starts` (τ = 0) to τ = 1 and polishes their endpoints: out[i] for start i.
inline void trackAll(const Homotopy& H, const V8* starts, int count, const Settings& o, Path* out) {
  const double hmin = Tolerance<double>::sqrtEpsilon();
  CV f, ft, y, y0, yJ, v, res;
  CM J, J2, T2;
  Us U, U0;
  Mk piv[8], piv2[8];
  unsigned swaps = 0;
  At A;
  // The tangents at the starts, four at a time.
  std::vector<V8> tangent(static_cast<std::size_t>(count));
  std::vector<char> started(static_cast<std::size_t>(count), 0);
  at(H, splat(0), A);
  for (int b = 0; b < count; b += kLanes) {
    for (int l = 0; l < kLanes; ++l) {
      const V8& s = starts[b + l < count ? b + l : b];
      for (int k = 0; k < 8; ++k) setLane(y[k], l, s[k]);
    }
    Us U0;
    eval(H, A, y, f, &J, &U0);
    evalFt(H, A, y, U0, ft);
    unsigned sw;
    const P ratio = factor(J, piv, sw, o.pivotThreshold);
    solve(J, piv, sw, ft);
    for (int l = 0; l < kLanes && b + l < count; ++l) {
      Path& r = out[b + l];
      r = Path{};
      r.lus = 1;
      r.x = starts[b + l];
      started[static_cast<std::size_t>(b + l)] = ratio[l] > 0;
      for (int k = 0; k < 8; ++k) tangent[static_cast<std::size_t>(b + l)][k] = {-ft[k].re[l], -ft[k].im[l]};
    }
  }
  Lane ln[kLanes];
  Lanes Q;
  Q.starts = starts, Q.tangent = tangent.data(), Q.started = started.data(), Q.count = count, Q.hstart = o.hstart;
  for (int s = 0; s < 3; ++s)
    for (int k = 0; k < 8; ++k) Q.X[s][k] = Q.V[s][k] = cpack({0, 0});
  CV(&X)[3] = Q.X;
  CV(&V)[3] = Q.V;
  std::vector<int> ended;  // paths that reached τ = 1, to polish
  for (int l = 0; l < kLanes; ++l) load(Q, ln[l], l);
  for (;;) {
    bool live[kLanes], anyLive = false;
    double tn[kLanes], wx[3][kLanes], wv[3][kLanes];
    for (int l = 0; l < kLanes; ++l) {
      Lane& L = ln[l];
      live[l] = L.path >= 0;
      anyLive = anyLive || live[l];
      double w1[3] = {0, 0, 0}, w2[3] = {0, 0, 0};
      tn[l] = 1;
      if (live[l]) {
        if (L.t + L.h > 1) L.h = 1 - L.t;
        tn[l] = L.h >= 1 - L.t ? 1.0 : L.t + L.h;
        hermiteWeights(L.n, L.ord, L.T, tn[l], w1, w2);
        ++out[L.path].steps;
      }
      for (int s = 0; s < 3; ++s) wx[s][l] = w1[s], wv[s][l] = w2[s];
    }
    if (!anyLive) break;
    P wxp[3], wvp[3];
    for (int s = 0; s < 3; ++s) wxp[s] = packOf(wx[s]), wvp[s] = packOf(wv[s]);
    for (int k = 0; k < 8; ++k)
      y[k] = wxp[0] * X[0][k] + wvp[0] * V[0][k] + wxp[1] * X[1][k] + wvp[1] * V[1][k] + wxp[2] * X[2][k] + wvp[2] * V[2][k];
    at(H, packOf(tn), A);
    // Newton, lanes in lockstep (the rules: Settings in stewart_fast_tracker.hpp).
    bool act[kLanes], ok[kLanes];
    double first[kLanes], prev[kLanes], rate[kLanes];
    int last[kLanes];
    bool refactored[kLanes];
    for (int l = 0; l < kLanes; ++l)
      act[l] = live[l], ok[l] = refactored[l] = false, first[l] = prev[l] = rate[l] = 0, last[l] = 0;
    // The tangents at the new points ride along (v = J⁻¹(−∂H/∂τ) at the second iterate yJ, refined
    // once with the Jacobian there): their right-hand sides are solved together with the Newton corrections
    // of the second and third iterations (one pass of the substitutions for both).
    bool tangentFromNewton = false, resolved = false;
    for (int it = 0; it < o.maxIterations; ++it) {
      if (it == 0) {
        eval(H, A, y, f, &J, &U0);
        y0 = y;
        const P ratio = factor(J, piv, swaps, o.pivotThreshold);
        for (int l = 0; l < kLanes; ++l) {
          if (!act[l]) continue;
          ++out[ln[l].path].lus;
          if (!(ratio[l] > 0)) act[l] = false;
        }
      } else {
        // The leg vectors U at the second iterate yJ (the tangent's ∂H/∂τ and, with U0, its
        // refinement: at yJ, within the second correction of the new point, far below what the
        // predictor needs); the Jacobian J2 there only when a lane refactors.
        bool re[kLanes], anyRe = false;
        for (int l = 0; l < kLanes; ++l) {
          re[l] = act[l] && it >= 2 && rate[l] > o.refactorRate && !refactored[l];  // J2 is factored once
          anyRe = anyRe || re[l];
        }
        if (it == 1) {
          eval(H, A, y, f, nullptr, &U);
          yJ = y;
        } else {
          eval(H, A, y, f, nullptr, nullptr);
          if (anyRe) {  // the Jacobian at yJ, as the refactoring took it before
            CV f2;
            eval(H, A, yJ, f2, &J2, nullptr);
          }
        }
        if (anyRe) {  // slow linear convergence on some lane: a (nearly) full Newton step there
          unsigned swaps2;
          const P ratio = factor(J2, piv2, swaps2, o.pivotThreshold);
          swaps |= swaps2;
          const Mk m = maskOf(re);
          for (int r = 0; r < 8; ++r) {
            for (int c = 0; c < 8; ++c) J[r][c] = csel(m, J2[r][c], J[r][c]);
            piv[r] = selm(m, piv2[r], piv[r]);
          }
          for (int l = 0; l < kLanes; ++l) {
            if (!re[l]) continue;
            refactored[l] = true;
            ++out[ln[l].path].lus;
            if (!(ratio[l] > 0)) act[l] = false;
          }
        }
      }
      if (it == 1) {
        evalFt(H, A, yJ, U, ft);
        for (auto& z : ft) z = -z;
        v = ft;
        solve(J, piv, swaps, f, v);
        CV dy;
        for (int k = 0; k < 8; ++k) dy[k] = yJ[k] - y0[k];
        jacobianChangeTimes(A, dy, U, U0, v, res);  // ft − J(yJ) v, as J(y0) v = ft
        tangentFromNewton = true;
      } else if (it == 2) {
        solve(J, piv, swaps, f, res);
        resolved = true;
      } else {
        solve(J, piv, swaps, f);
      }
      const Mk am = maskOf(act);
      for (int k = 0; k < 8; ++k) y[k] = csel(am, y[k] - f[k], y[k]);
      const P fn = maxNorm(f), fs = sumNorm(f), yn = maxNorm(y);
      bool more = false;
      for (int l = 0; l < kLanes; ++l) {
        if (!act[l]) continue;
        last[l] = it;
        const double dn = fn[l] / std::max(1.0, yn[l]);
        if (!(fs[l] == fs[l]) || !(dn == dn)) {
          act[l] = false;
          continue;
        }
        if (it == 0) {
          first[l] = dn;
          if (dn > o.rejectFactor * o.predErr) {
            act[l] = false;
            continue;
          }
        } else {
          rate[l] = dn / prev[l];
          if (dn > prev[l] / 4) {  // not contracting fast: too far from the path for a safe Newton
            act[l] = false;
            continue;
          }
        }
        prev[l] = dn;
        if (dn <= o.accept) {
          ok[l] = true;
          act[l] = false;
          continue;
        }
        more = true;
      }
      if (!more) break;
    }
    bool anyOk = false, anyFirst = false;
    bool atFirst[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      anyOk = anyOk || ok[l];
      atFirst[l] = ok[l] && last[l] == 0;
      anyFirst = anyFirst || atFirst[l];
    }
    if (anyOk && tangentFromNewton) {
      // The tangents at the new points, begun with the second iteration (above): the refinement's
      // correction, solved with the third iteration's or alone (a lane accepted at once had its
      // ∂H/∂τ and U taken at its new point by the second iteration, which it sat out).
      if (!resolved) solve(J, piv, swaps, res);
      for (int k = 0; k < 8; ++k) v[k] = v[k] + res[k];
    } else if (anyOk) {
      // Every lane stopped at the first iteration: the tangents J⁻¹(−∂H/∂τ) with the step's LU,
      // refined once with the Jacobian J2 (a lane accepted at once gets ∂H/∂τ and J2 at its new point).
      if (anyFirst) {
        CV f3;
        Us U3;
        eval(H, A, y, f3, &T2, &U3);
        const Mk m = maskOf(atFirst);
        for (int r = 0; r < 8; ++r) {
          yJ[r] = csel(m, y[r], yJ[r]);
          for (int c = 0; c < 8; ++c) J2[r][c] = csel(m, T2[r][c], J2[r][c]);
        }
        for (int i = 0; i < 6; ++i)
          for (int k = 0; k < 4; ++k) U.u[i][k] = csel(m, U3.u[i][k], U.u[i][k]);
      }
      evalFt(H, A, yJ, U, ft);
      for (auto& z : ft) z = -z;
      v = ft;
      solve(J, piv, swaps, v);
      res = ft;
      for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 8; ++k) res[i] = res[i] - J2[i][k] * v[k];
      solve(J, piv, swaps, res);
      for (int k = 0; k < 8; ++k) v[k] = v[k] + res[k];
    }
    for (int l = 0; l < kLanes; ++l) {
      if (!live[l]) continue;
      Lane& L = ln[l];
      Path& r = out[L.path];
      const int n = L.n;
      if (ok[l]) {
        int slot;
        if (n == 3) {
          slot = L.ord[0];
          L.ord[0] = L.ord[1], L.ord[1] = L.ord[2], L.ord[2] = slot;
        } else {
          slot = L.ord[n];
          L.n = n + 1;
        }
        for (int k = 0; k < 8; ++k) {
          X[slot][k].re[l] = y[k].re[l], X[slot][k].im[l] = y[k].im[l];
          V[slot][k].re[l] = v[k].re[l], V[slot][k].im[l] = v[k].im[l];
        }
        L.T[slot] = tn[l];
        L.t = tn[l];
        double g = 2;
        if (first[l] > 0) g = std::min(2.0, std::max(0.5, 0.9 * orderRoot(o.predErr / first[l], n)));
        if (L.justRejected && g > 1) g = 1;
        L.h = std::min(o.hmax, L.h * g);
        L.justRejected = false;
        if (L.t >= 1) {
          for (int k = 0; k < 8; ++k) r.x[k] = lane(y[k], l);
          ended.push_back(L.path);
          load(Q, L, l);
        } else if (r.steps >= o.maxSteps) {
          load(Q, L, l);  // failed: finite stays false
        }
      } else {
        double g = 0.5;
        if (first[l] > 0 && first[l] == first[l])
          g = std::min(0.5, std::max(0.125, 0.9 * orderRoot(o.predErr / first[l], n)));
        L.h *= g;
        L.justRejected = true;
        if (L.h < hmin || r.steps >= o.maxSteps) load(Q, L, l);  // failed: finite stays false
      }
    }
  }
  for (std::size_t b = 0; b < ended.size(); b += kLanes)
    polish(H, o, ended.data() + b, static_cast<int>(std::min<std::size_t>(kLanes, ended.size() - b)), out);
}
