// Finite-position Burmester synthesis (3, 4, 5 positions), explicitly instantiated for the five scalars.
#include "soma/geometry/planar/burmester_synthesis.hpp"

#include <algorithm>
#include <cmath>

namespace soma::planar {

namespace {

/// Determinant of a small dense matrix by Gaussian elimination with partial pivoting.
template <class S> S detN(std::vector<std::vector<S>> a) {
  using std::abs;
  const int n = int(a.size());
  S det(1);
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (abs(a[i][k]) > abs(a[p][k])) p = i;
    if (a[p][k] == S(0)) return S(0);
    if (p != k) {
      std::swap(a[p], a[k]);
      det = -det;
    }
    det *= a[k][k];
    for (int i = k + 1; i < n; ++i) {
      const S f = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] -= f * a[k][j];
    }
  }
  return det;
}

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

/// Sylvester resultant of two polynomials (coefficients low → high).
template <class S> S sylvester(const Poly1<S>& f, const Poly1<S>& g) {
  const int m = int(f.size()) - 1, n = int(g.size()) - 1;
  const int N = m + n;
  if (N == 0) return S(1);
  std::vector<std::vector<S>> a(N, std::vector<S>(N, S(0)));
  for (int r = 0; r < n; ++r)
    for (int k = 0; k <= m; ++k) a[r][r + k] = f[m - k];
  for (int r = 0; r < m; ++r)
    for (int k = 0; k <= n; ++k) a[n + r][r + k] = g[n - k];
  return detN(a);
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

template <class S> S BurmesterSynthesis<S>::equation(int i, const Vec2<S>& m, const Vec2<S>& z) const {
  const Vec2<S> pi = pos_[i - 1].act(z) - m, p1 = pos_[0].act(z) - m;
  return pi.squaredNorm() - p1.squaredNorm();
}

template <class S> S BurmesterSynthesis<S>::residual(const Vec2<S>& m, const Vec2<S>& z) const {
  using std::abs;
  S r(0);
  for (int i = 2; i <= size(); ++i) r = std::max<S>(r, abs(equation(i, m, z)));
  return r / (scale_ * scale_);
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

template <class S>
std::vector<BurmesterPair<S>> BurmesterSynthesis<S>::burmesterPairs(int* complexCount, S* leadingDefect, S* poleDefect) const {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (size() != 5) throw InvalidInput("Burmester pairs: need exactly 5 positions, got " + std::to_string(size()));
  // Work in a normalised frame: centred on the mean translation, lengths / scale, rotated by a
  // generic angle so that no two intersections share an x coordinate by accident.
  Vec2<S> mean = Vec2<S>::Zero();
  for (const auto& p : pos_) mean += p.translation();
  mean /= S(5);
  const S ang = S(37) / S(100);
  const SE2<S> N = SE2<S>(ang, Vec2<S>::Zero()) * SE2<S>(S(0), Vec2<S>(-mean));  // world → frame (before scaling)
  std::vector<SE2<S>> q;
  for (const auto& p : pos_) {
    const SE2<S> g = N * p;
    q.push_back(SE2<S>(g.angle(), Vec2<S>(g.translation() / scale_)));
  }
  const BurmesterSynthesis<S> norm(q);
  const Poly2<S> F1 = norm.centrePointCurve(4), F2 = norm.centrePointCurve(5);
  // Resultant in x by interpolation at 10 Chebyshev nodes on [−2, 2] (degree ≤ 9).
  const int K = 10;
  std::vector<S> xs(K), rs(K);
  for (int k = 0; k < K; ++k) {
    xs[k] = S(2) * scalarCast<S>(std::cos(3.14159265358979323846 * (k + 0.5) / K));
    rs[k] = sylvester(inY(F1, xs[k]), inY(F2, xs[k]));
  }
  // Newton divided differences → monomial coefficients.
  std::vector<S> dd = rs;
  for (int j = 1; j < K; ++j)
    for (int k = K - 1; k >= j; --k) dd[k] = (dd[k] - dd[k - 1]) / (xs[k] - xs[k - j]);
  Poly1<S> R{dd[K - 1]};
  for (int k = K - 2; k >= 0; --k) {
    R = polyMul(R, Poly1<S>{-xs[k], S(1)});
    R[0] += dd[k];
  }
  S rmax(0);
  for (const S& v : R) rmax = std::max<S>(rmax, abs(v));
  if (!(rmax > S(0))) throw InvalidInput("Burmester pairs: the centre-point curves share a component (degenerate positions)");
  if (leadingDefect) *leadingDefect = std::max<S>(abs(R[9]), abs(R[8])) / rmax;
  R.resize(8);  // the two top coefficients vanish (the circular points at infinity)
  // Divide out the poles P12, P13, P23.
  S pd(0);
  for (const auto& ij : {std::pair<int, int>{1, 2}, {1, 3}, {2, 3}}) {
    const Vec2<S> P = norm.pole(ij.first, ij.second);
    Poly1<S> rem;
    S rn(0), pw(1);  // the remainder is R(P_x): judge it against Σ|r_k||P_x|^k
    for (const S& v : R) {
      rn += abs(v) * pw;
      pw *= abs(P(0));
    }
    R = polyDiv(R, Poly1<S>{-P(0), S(1)}, &rem);
    pd = std::max<S>(pd, abs(rem.empty() ? S(0) : rem[0]) / rn);
  }
  if (poleDefect) *poleDefect = pd;
  const std::vector<Cx<S>> roots = polynomialRoots(R);
  int complexRoots = 0;
  std::vector<BurmesterPair<S>> out;
  const S tolIm = Tolerance<S>::sqrtEpsilon() * S(16);
  for (const Cx<S>& xr : roots) {
    if (abs(xr.im) > tolIm * (S(1) + xr.abs())) {
      ++complexRoots;
      continue;
    }
    const S x = xr.re;
    // y: the root of F1(x, ·) where F2 also vanishes.
    const std::vector<Cx<S>> ys = polynomialRoots(inY(F1, x));
    S best(-1), y(0);
    for (const Cx<S>& yr : ys) {
      const S v = abs(F2(x, yr.re)) / (F2.magnitude(x, yr.re) + Tolerance<S>::epsilon()) + abs(yr.im) / (S(1) + yr.abs());
      if (best < S(0) || v < best) {
        best = v;
        y = yr.re;
      }
    }
    Vec2<S> m(x, y);
    const auto zo = norm.circlePointForCentre(m);
    if (!zo) continue;
    Vec2<S> z = *zo;
    // Newton on e_2..e_5 in (m, z).
    for (int it = 0; it < 8; ++it) {
      std::vector<std::vector<S>> J(4, std::vector<S>(4));
      std::vector<S> e(4), dx;
      for (int i = 2; i <= 5; ++i) {
        const Mat2<S> Ri = q[i - 1].rotation(), R1 = q[0].rotation();
        const Vec2<S> di = q[i - 1].translation(), d1 = q[0].translation();
        const Vec2<S> pi = Ri * z + di - m, p1 = R1 * z + d1 - m;
        e[i - 2] = -(pi.squaredNorm() - p1.squaredNorm());
        const Vec2<S> gm = S(-2) * (pi - p1);
        const Vec2<S> gz = S(2) * (Ri.transpose() * pi - R1.transpose() * p1);
        J[i - 2] = {gm(0), gm(1), gz(0), gz(1)};
      }
      if (!solveN(J, e, dx)) break;
      m += Vec2<S>(dx[0], dx[1]);
      z += Vec2<S>(dx[2], dx[3]);
      if (abs(dx[0]) + abs(dx[1]) + abs(dx[2]) + abs(dx[3]) <= Tolerance<S>::epsilon() * (S(1) + m.norm() + z.norm())) break;
    }
    // back to world: m_world = N⁻¹(scale·m), z_body = scale·z (body coordinates are unchanged by N)
    BurmesterPair<S> bp;
    bp.centre = N.inverse().act(Vec2<S>(m * scale_));
    bp.circle = z * scale_;
    bp.radius = sqrt((pos_[0].act(bp.circle) - bp.centre).squaredNorm());
    bp.residual = residual(bp.centre, bp.circle);
    out.push_back(bp);
  }
  if (complexCount) *complexCount = complexRoots;
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

#define SOMA_PLANAR_SYNTH(T)            \
  template class BurmesterSynthesis<T>; \
  template std::vector<Vec2<T>> sampleCurve<T>(const Poly2<T>&, const T&, const T&, const T&, const T&, int);
SOMA_FOR_EACH_SCALAR(SOMA_PLANAR_SYNTH)
#undef SOMA_PLANAR_SYNTH

}  // namespace soma::planar
