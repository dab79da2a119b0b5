#pragma once
// Closed-form inverse kinematics: 3R wrists (GF §5.1), 3R arms (GF §5.2), Pieper robots (GF §10.3).
// Private implementation header: soma_instantiate (cmake/SomaInstantiate.cmake) instantiates it once per scalar (one TU
// each, so the five build in parallel; together they took ~3 min of CPU as one TU).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/joint_limits.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/polynomial.hpp"
#include "soma/algebra/sin_cos.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace soma {

namespace {

using Clock = std::chrono::steady_clock;


/// w rotated about the unit axis v by the angle with cosine c and sine s (Rodrigues' formula
/// c w + s v × w + (1 − c)(v·w) v, without forming the matrix).
template <class S> Vec3<S> rotateAbout(const Vec3<S>& v, const S& c, const S& s, const Vec3<S>& w) {
  return c * w + s * v.cross(w) + ((S(1) - c) * v.dot(w)) * v;
}


/// An angle with its cosine and sine, carried together so that later steps need no sin or cos.
template <class S> struct Angle {
  S th = S(0), c = S(1), s = S(0);
};
/// The angle of the vector (x, y) with (cos, sin) = (x, y) / |(x, y)|; angle 0 for the zero vector.
template <class S> Angle<S> angleOf(const S& y, const S& x) {
  using std::atan2;
  using std::hypot;
  using std::sqrt;
  const S r2 = x * x + y * y;
  // |(x, y)|² in range: one square root; else (underflow or overflow of the squares) hypot.
  const S r = r2 > std::numeric_limits<S>::min() && r2 < std::numeric_limits<S>::max() ? sqrt(r2) : hypot(x, y);
  if (!(r > S(0))) return {};
  const S ir = S(1) / r;
  return {atan2(y, x), x * ir, y * ir};
}
/// An angle given by its value: (θ, cos θ, sin θ).
template <class S> Angle<S> angleFrom(const S& th) {
  Angle<S> a;
  a.th = th;
  sinCos(th, a.s, a.c);
  return a;
}
/// σ·φ for σ = ±1.
template <class S> Angle<S> signedAngle(int sigma, const Angle<S>& a) {
  return sigma > 0 ? a : Angle<S>{S(-a.th), a.c, S(-a.s)};
}

/// Signed angle of the rotation about unit v taking a to b (both taken relative to a point of
/// the axis and projected on the plane ⟂ v), with its cosine and sine. `degenerate` when a lies on the axis.
// GF §5.2.1, GF-5.2.1-theta2-recovery (corrected, erratum E5.6: |v×(a−r)|² and b − r)
template <class S> Angle<S> angleAbout(const Vec3<S>& v, const Vec3<S>& a, const Vec3<S>& b,
                                      bool* degenerate, const S& scale2) {
  const Vec3<S> ap = a - v * v.dot(a), bp = b - v * v.dot(b);
  // On the axis when |a′| ≤ √eps · scale: the accuracy of a point computed from a double root of
  // the positioning quartic (a pose on the singularity). (|a′|² ≤ 1024 eps · scale², i.e. 32√eps,
  // flagged genuine postures within 1 % of the axis in float; 1024 eps · scale missed the T³
  // singularity of GF-10.3-closing-remarks in double.)
  // A pose known to k ulps (forward kinematics composes six motions of ≤ 4 ulps each: k ≈ 16 is typical,
  // measured 2026-12-02 after the faster SE(3) compose of 3-4 ulps) splits a double root by √(k ε), so
  // the test is |a′|² ≤ 16 eps · scale² (√(16 eps) = 4√eps: 6e-8 in double, 0.14 % of the scale in float).
  if (degenerate) *degenerate = ap.squaredNorm() <= S(16) * Tolerance<S>::epsilon() * scale2;
  return angleOf<S>(v.dot(ap.cross(bp)), ap.dot(bp));
}

/// A point (or a plane) turning about a line: x(φ) = c0 + cc cos φ + cs sin φ.
template <class S> struct Circle {
  Vec3<S> c0, cc, cs;
  Vec3<S> at(const Angle<S>& phi) const { return c0 + cc * phi.c + cs * phi.s; }
};

/// x turned about the line (v, r) by σφ, σ = ±1. GF §5.2.1, GF-5.2.1-revolute-joint-exp
template <class S> Circle<S> circleOf(const Vec3<S>& v, const Vec3<S>& r, const Vec3<S>& x, int sigma) {
  const Vec3<S> u = x - r;
  const Vec3<S> vvu = v * v.dot(u);
  return {Vec3<S>(r + vvu), Vec3<S>(u - vvu), Vec3<S>(S(sigma) * v.cross(u))};
}

/// One side of the circle-pair problem: its two invariants under the middle rotation, as
/// coefficients of (1, cos φ, sin φ).
template <class S> using InvRows = Eigen::Matrix<S, 2, 3>;

/// Point x(φ) about middle axis (vm, rm): f1 = vm·x, f2 = |x − rm|² (the cos², sin² terms
/// combine to |cs|² because cc ⟂ cs and |cc| = |cs|). GF §5.2.1, GF-5.2.1-3r-ik-procedure
template <class S> InvRows<S> pointInvariants(const Circle<S>& c, const Vec3<S>& vm, const Vec3<S>& rm) {
  InvRows<S> f;
  const Vec3<S> d = c.c0 - rm;
  f << vm.dot(c.c0), vm.dot(c.cc), vm.dot(c.cs),  //
      d.squaredNorm() + c.cs.squaredNorm(), S(2) * d.dot(c.cc), S(2) * d.dot(c.cs);
  return f;
}

/// Plane {y : n·y = d} turned about the line (v, r) by σφ: n(φ) is the circle `nc` of the
/// normal (about the origin) and d(φ) − n(φ)·rm = d − n·r + n(φ)·(r − rm).
// GF §10.3.1 (parallel case: ℓ6 ∧ (a5* π a5), the plane of the three parallel axes), GF-10.3.2-T3-robot
template <class S> InvRows<S> planeInvariants(const Vec3<S>& v, const Vec3<S>& r, const Vec3<S>& n,
                                             const S& d, int sigma, const Vec3<S>& vm,
                                             const Vec3<S>& rm, Circle<S>* normal) {
  const Circle<S> nc = circleOf<S>(v, Vec3<S>::Zero(), n, sigma);
  if (normal) *normal = nc;
  const Vec3<S> w = r - rm;
  InvRows<S> f;
  f << vm.dot(nc.c0), vm.dot(nc.cc), vm.dot(nc.cs),  //
      d - n.dot(r) + nc.c0.dot(w), nc.cc.dot(w), nc.cs.dot(w);
  return f;
}

/// Real roots among the roots z of the polynomial t (ascending coefficients, degree ≥ 3), by
/// realRoots' rule (polynomial.cpp): |Im z| ≤ Tolerance::input()·max(1, |Re z|), Newton-polished
/// (steps kept while |p| falls), and accepted when |p(x)| ≤ 256 eps Σ|c_k x^k|; sorted.
template <class S> std::vector<S> realRootsOf(const std::vector<S>& t, const std::vector<std::complex<S>>& zs) {
  using std::abs;
  const int n = int(t.size()) - 1;
  auto eval = [&](const S& x) {
    S p = t[n];
    for (int k = n - 1; k >= 0; --k) p = p * x + t[k];
    return p;
  };
  std::vector<S> out;
  out.reserve(zs.size());
  for (const auto& z : zs) {
    const S scale = std::max<S>(S(1), abs(z.real()));
    if (abs(z.imag()) > Tolerance<S>::input() * scale) continue;
    S x = z.real(), px = eval(x);
    for (int it = 0; it < 16 && px != S(0); ++it) {
      S dp = S(0);
      for (int k = n; k >= 1; --k) dp = dp * x + S(k) * t[k];
      if (dp == S(0)) break;
      const S xn = x - px / dp, pn = eval(xn);
      if (!(abs(pn) < abs(px))) break;
      x = xn;
      px = pn;
    }
    S mag = S(0), xk = S(1);
    for (int k = 0; k <= n; ++k) {
      mag += abs(t[k]) * xk;
      xk *= abs(x);
    }
    if (abs(px) <= Tolerance<S>::identity(256) * mag) out.push_back(x);
  }
  std::sort(out.begin(), out.end());
  return out;
}


/// Up to two roots of p cos φ + q sin φ = k with their cosines and sines (solveLinearTrig's rule).
template <class S> struct TrigPair {
  std::array<Angle<S>, 2> a;
  int n = 0;
  bool free = false;
  bool doubleRoot = false;
};
// GF §5.1, GF-5.1-wrist-theta2: φ = β ∓ h with β = atan2(q, p), h = atan2(√disc, k); the cosine and
// sine of β ∓ h by the sum formulas, (p k ± q √disc, q k ∓ p √disc) / ρ², without sin or cos.
template <class S> TrigPair<S> linearTrig(const S& p, const S& q, const S& k) {
  using std::abs;
  using std::sqrt;
  using std::atan2;
  TrigPair<S> out;
  const S rho2 = p * p + q * q;
  const S scale2 = std::max<S>(rho2, k * k);  // scale² with scale = max(ρ, |k|)
  if (rho2 <= Tolerance<S>::rank() * Tolerance<S>::rank() * scale2 || scale2 == S(0)) {
    const S scale = sqrt(scale2);
    out.free = abs(k) <= Tolerance<S>::rank() * (scale > S(0) ? scale : S(1)) || scale == S(0);
    return out;  // p = q = 0: no solution unless k = 0 too
  }
  S disc = rho2 - k * k;
  bool clamped = false;
  if (disc < S(0)) {
    if (-disc > Tolerance<S>::rank() * rho2) return out;  // unreachable
    disc = S(0);
    clamped = true;
  }
  if (disc <= Tolerance<S>::rank() * rho2) out.doubleRoot = true;
  const S sd = sqrt(disc);
  const S x0 = p * k + q * sd, y0 = q * k - p * sd, x1 = p * k - q * sd, y1 = q * k + p * sd;
  if (clamped) {  // k² slightly above ρ²: normalise each pair by its length
    out.a[0] = angleOf<S>(y0, x0);
    out.a[1] = angleOf<S>(y1, x1);
  } else {  // |(x, y)|² = ρ² (k² + disc) = ρ⁴: the pair over ρ² is (cos φ, sin φ)
    const S inv = S(1) / rho2;
    out.a[0] = {atan2(y0, x0), x0 * inv, y0 * inv};
    out.a[1] = {atan2(y1, x1), x1 * inv, y1 * inv};
  }
  out.n = 2;
  return out;
}

/// The real (φA, φB) of a circle pair (at most 4; capacity for the near-real candidates too).
template <class S> struct PairRoots {
  static constexpr int kMax = 8;
  std::array<Angle<S>, kMax> a, b;
  std::array<char, kMax> nearReal{};  ///< from a near-real complex pair (a candidate)
  int n = 0;
  bool continuum = false;
  bool doubleRoot = false;
  void add(const Angle<S>& x, const Angle<S>& y, bool candidate) {
    if (n == kMax) throw std::logic_error("closed form: more circle-pair roots than a quartic has");
    a[n] = x;
    b[n] = y;
    nearReal[n] = candidate ? 1 : 0;
    ++n;
  }
};

/// Smallest-singular left vector y of a 2×2 matrix (yᵀM ≈ 0 when M is singular).
template <class S> Vec2<S> leftNull(const Mat2<S>& M) {
  using std::sqrt;
  const Mat2<S> A = M * M.transpose();
  const S a = A(0, 0), b = A(0, 1), c = A(1, 1);
  const S h = (a - c) / S(2);
  const S lam = (a + c) / S(2) - sqrt(h * h + b * b);
  Vec2<S> y1(b, lam - a), y2(lam - c, b);
  Vec2<S> y = y1.squaredNorm() >= y2.squaredNorm() ? y1 : y2;
  if (y.squaredNorm() == S(0)) return Vec2<S>(S(1), S(0));
  return y.normalized();
}


/// FA·(1, cos φA, sin φA) = FB·(1, cos φB, sin φB): up to 4 real (φA, φB). The 2×2 block of the
/// better-conditioned side is inverted and c² + s² = 1 of the other side gives a quartic in
/// t = tan(ψ/2), φ = φ0 + ψ with φ0 chosen so that ψ = π is far from a root (the quartic's
/// leading coefficient is the conic's value there). When one block is singular (to a rank
/// decision) its left null vector gives an equation in the other angle alone, and each of its
/// roots one equation in the first (the UR case: axes 5, 6 meet); when both blocks are singular
/// the system decouples into one equation per angle (the PUMA case: axes 1, 2 meet and 2 ∥ 3).
/// Notes go to `notes`.
// GF §5.2.1, GF-5.2.1-3r-ik-procedure (pencil of conics → tan-half-angle quartic; singular 2×2
// system → eliminate the other angle)
template <class S> PairRoots<S> solveCirclePair(InvRows<S> FA, InvRows<S> FB, std::vector<std::string>& notes) {
  using std::abs;
  using std::cos;
  using std::sin;
  PairRoots<S> out;
  for (int i = 0; i < 2; ++i) {  // rows to unit scale (f1 is a length, f2 a squared length)
    const S s = std::max<S>(FA.row(i).cwiseAbs().maxCoeff(), FB.row(i).cwiseAbs().maxCoeff());
    if (s == S(0)) {
      out.continuum = true;
      notes.push_back("invariant equation " + std::to_string(i + 1) + " vanishes identically");
      return out;
    }
    FA.row(i) /= s;
    FB.row(i) /= s;
  }
  const Mat2<S> MA = FA.template rightCols<2>(), MB = FB.template rightCols<2>();
  const Vec2<S> k = FB.col(0) - FA.col(0);
  auto rel = [](const Mat2<S>& M) {
    const S n2 = M.squaredNorm();
    return n2 > S(0) ? S(abs(M.determinant()) / n2) : S(0);
  };
  const S condA = rel(MA), condB = rel(MB);
  const bool bothSingular = !(std::max<S>(condA, condB) > Tolerance<S>::sqrtEpsilon());
  if (!bothSingular && std::min<S>(condA, condB) <= Tolerance<S>::rank()) {
    // Triangular: the singular side's left null vector y eliminates its angle (yᵀM_sing = 0), giving
    // an equation in the other angle alone; for each root the rest, projected on z ⟂ y (the range of
    // M_sing), is one equation in the singular side's angle. MA uA − MB uB = k.
    const bool singA = condA <= condB;
    const Mat2<S>& Ms = singA ? MA : MB;  // singular block
    const Mat2<S>& Mr = singA ? MB : MA;  // regular block
    // singA: MA uA = k + MB uB → yᵀMB uB = −yᵀk.  singB: MB uB = MA uA − k → yᵀMA uA = yᵀk.
    const S sr = singA ? S(-1) : S(1);  // the sign of yᵀk in the regular side's equation
    const Vec2<S> y = leftNull(Ms), z(-y(1), y(0));
    const Vec2<S> wr = Mr.transpose() * y;
    const TrigPair<S> rr = linearTrig<S>(wr(0), wr(1), S(sr * y.dot(k)));
    TrigPair<S> rrUse = rr;
    if (rr.free) {
      out.continuum = true;
      notes.push_back(singA ? "the second angle is free (0 returned)" : "the first angle is free (0 returned)");
      rrUse.n = 1;
      rrUse.a[0] = Angle<S>{};
    }
    out.doubleRoot = rr.doubleRoot;
    const Vec2<S> ws = Ms.transpose() * z;
    for (int i = 0; i < rrUse.n; ++i) {
      const Angle<S>& ur = rrUse.a[i];
      const Vec2<S> uRegular(ur.c, ur.s);
      // singA: rhs = k + MB uB; singB: rhs = MA uA − k.
      const Vec2<S> rhs = singA ? Vec2<S>(k + Mr * uRegular) : Vec2<S>(Mr * uRegular - k);
      const TrigPair<S> rs = linearTrig<S>(ws(0), ws(1), z.dot(rhs));
      if (rs.doubleRoot) out.doubleRoot = true;
      if (rs.free) {
        out.continuum = true;
        notes.push_back(singA ? "the first angle is free (0 returned)" : "the second angle is free (0 returned)");
        out.add(singA ? Angle<S>{} : ur, singA ? ur : Angle<S>{}, false);
        continue;
      }
      for (int j = 0; j < rs.n; ++j) out.add(singA ? rs.a[j] : ur, singA ? ur : rs.a[j], false);
    }
    return out;
  }
  if (!bothSingular) {
    // u_free = (cos, sin) of the quartic's angle, u_dep = P u_free + m.
    const bool freeIsB = condA >= condB;
    Mat2<S> P;
    Vec2<S> m;
    if (freeIsB) {
      const Mat2<S> inv = MA.inverse();
      P = inv * MB;
      m = inv * k;
    } else {
      const Mat2<S> inv = MB.inverse();
      P = inv * MA;
      m = -(inv * k);
    }
    const Mat2<S> G = P.transpose() * P;
    const Vec2<S> h = P.transpose() * m;
    const S e = m.squaredNorm() - S(1);
    auto f = [&](const Vec2<S>& u) { return S(u.dot(G * u) + S(2) * h.dot(u) + e); };
    S phi0 = S(0), best = S(-1);
    for (int j = 0; j < 8; ++j) {
      const S ph = pi<S>() * S(j) / S(4);
      const S val = abs(f(Vec2<S>(-cos(ph), -sin(ph))));
      if (val > best) {
        best = val;
        phi0 = ph;
      }
    }
    S c0, s0;
    sinCos(phi0, s0, c0);
    Mat2<S> R0;
    R0 << c0, -s0, s0, c0;
    const Mat2<S> Gp = R0.transpose() * G * R0;
    const Vec2<S> hp = R0.transpose() * h;
    const std::array<S, 5> c = {Gp(0, 0) + S(2) * hp(0) + e, S(4) * Gp(0, 1) + S(4) * hp(1),
                                S(-2) * Gp(0, 0) + S(4) * Gp(1, 1) + S(2) * e,
                                S(-4) * Gp(0, 1) + S(4) * hp(1), Gp(0, 0) - S(2) * hp(0) + e};
    S cmax = S(0);
    for (const auto& ci : c) cmax = std::max<S>(cmax, abs(ci));
    const S cscale = S(1) + G.cwiseAbs().maxCoeff() + h.cwiseAbs().maxCoeff() + abs(e);
    std::vector<S> ts;
    std::size_t strict = 0;  // ts[0..strict) are roots to round-off, the rest near-real candidates
    if (cmax <= Tolerance<S>::rank() * cscale) {
      out.continuum = true;
      notes.push_back("the conic vanishes on the whole circle: one angle is free (0 returned)");
      ts.push_back(S(0));  // ψ = 0: φ = φ0
    } else {
      // The quartic's roots are computed once (Aberth) and split here as quarticRealRoots does
      // (polynomial.cpp: trimmed degree ≥ 3 → realRoots); degree ≤ 2 goes through it.
      int deg = 4;
      while (deg >= 0 && abs(c[deg]) <= Tolerance<S>::epsilon() * cmax) --deg;
      std::vector<std::complex<S>> zs;
      if (deg >= 3) {
        const std::vector<S> t(c.begin(), c.begin() + deg + 1);
        zs = polynomialRoots<S>(t);
        ts = realRootsOf<S>(t, zs);
      } else {
        ts = quarticRealRoots<S>(c);
      }
      strict = ts.size();
      // A double root (a pose on a singularity) splits under the rounding of the coefficients
      // into a pair x ± iy with |y| up to ~√(coefficient error): keep the real parts of such
      // near-real pairs as candidates too; finish() keeps a candidate only if Newton brings its
      // posture onto the pose (residual ≤ √eps), so a genuine complex pair is dropped there.
      if (ts.size() < 4) {
        if (deg < 3) zs = polynomialRoots<S>(std::vector<S>(c.begin(), c.end()));
        for (const auto& z : zs) {
          const S scale = std::max<S>(S(1), abs(z.real()));
          if (!(z.imag() > S(0)) || z.imag() > Tolerance<S>::input() * scale) continue;
          bool known = false;
          for (const S& t : ts) known = known || abs(t - z.real()) <= Tolerance<S>::input() * scale;
          if (!known) ts.push_back(z.real());
        }
      }
    }
    for (std::size_t i = 0; i < ts.size(); ++i) {
      // ψ = 2 atan t: (cos ψ, sin ψ) = (1 − t², 2t) / (1 + t²) (in u = 1/t for |t| > 1), turned by φ0.
      const S t = ts[i];
      S cp, sp;
      if (abs(t) <= S(1)) {
        const S d = S(1) + t * t;
        cp = (S(1) - t * t) / d;
        sp = S(2) * t / d;
      } else {
        const S u = S(1) / t, d = S(1) + u * u;
        cp = (u * u - S(1)) / d;
        sp = S(2) * u / d;
      }
      const Angle<S> phiFree = angleOf<S>(s0 * cp + c0 * sp, c0 * cp - s0 * sp);
      const Vec2<S> ud = P * Vec2<S>(phiFree.c, phiFree.s) + m;
      const Angle<S> phiDep = angleOf<S>(ud(1), ud(0));
      if (i > 0 && abs(ts[i] - ts[i - 1]) <= Tolerance<S>::input() * (S(1) + abs(ts[i])))
        out.doubleRoot = true;
      out.add(freeIsB ? phiDep : phiFree, freeIsB ? phiFree : phiDep, i >= strict && !out.continuum);
    }
    return out;
  }
  // Decoupled: yᵀ MA = 0 gives an equation in φB alone, zᵀ MB = 0 one in φA alone.
  const Vec2<S> y = leftNull(MA), z = leftNull(MB);
  const Vec2<S> wB = MB.transpose() * y, wA = MA.transpose() * z;
  TrigPair<S> rB = linearTrig<S>(wB(0), wB(1), -y.dot(k));
  TrigPair<S> rA = linearTrig<S>(wA(0), wA(1), z.dot(k));
  notes.push_back("the invariant equations decouple (each involves one angle)");
  if (rA.free) {
    rA.n = 1;
    rA.a[0] = Angle<S>{};
    out.continuum = true;
    notes.push_back("the first angle is free (0 returned)");
  }
  if (rB.free) {
    rB.n = 1;
    rB.a[0] = Angle<S>{};
    out.continuum = true;
    notes.push_back("the second angle is free (0 returned)");
  }
  out.doubleRoot = rA.doubleRoot || rB.doubleRoot;
  for (int i = 0; i < rA.n; ++i)
    for (int j = 0; j < rB.n; ++j) out.add(rA.a[i], rB.a[j], false);
  return out;
}

enum class ResidualMode { Pose, Position, Rotation };

/// A fixed-size joint vector inside the solvers (3 or 6 joints used; no allocation).
template <class S> using Joints6 = Eigen::Matrix<S, 6, 1>;

/// The raw postures of one solve (joint values before the offsets), with the candidate flags.
/// With `trig` set, c and s hold the cosine and sine each angle was computed from (q = atan2(s, c)),
/// which the residual's forward kinematics uses instead of calling sin and cos again.
template <class S> struct Raws {
  static constexpr int kMax = 16;
  std::array<Joints6<S>, kMax> q, c, s;
  std::array<char, kMax> cand{}, trig{};
  int n = 0;
  Joints6<S>& push(bool candidate) {
    if (n == kMax) throw std::logic_error("closed form: more raw postures than the class has");
    cand[n] = candidate ? 1 : 0;
    trig[n] = 0;
    q[n].setZero();
    return q[n++];
  }
  /// A posture given by its angles with their cosines and sines (joints 0..size−1).
  template <std::size_t N> void push(bool candidate, const std::array<Angle<S>, N>& a) {
    push(candidate);
    const int k = n - 1;
    trig[k] = 1;
    for (std::size_t i = 0; i < N; ++i) {
      q[k](int(i)) = a[i].th;
      c[k](int(i)) = a[i].c;
      s[k](int(i)) = a[i].s;
    }
  }
  /// Joints reversed (a posture of the reversed robot: same values, same cosines and sines).
  void reverse(int k) {
    q[k].reverseInPlace();
    c[k].reverseInPlace();
    s[k].reverseInPlace();
  }
};

/// The target and home pose as matrices, computed once per solve; RTM = R* R_Mᵀ, the rotation the
/// joints' product must reach (‖R(q) R_M − R*‖_F = ‖R(q) − R* R_Mᵀ‖_F, R_M orthogonal).
template <class S> struct PoseMatrices {
  Mat3<S> RT, RM, RTM;
  Vec3<S> tT, tM;
  S invL, invL2;  ///< 1 / L and 1 / L² of the robot's length scale
  PoseMatrices(const SerialRobot<S>& robot, const SE3<S>& target)
      : RT(target.rotation()), RM(robot.home().rotation()), tT(target.translation()),
        tM(robot.home().translation()), invL(S(1) / robot.lengthScale()), invL2(invL * invL) {
    RTM.noalias() = RT * RM.transpose();
  }
};

/// Forward kinematics of the joints' product e^{(q1 + o1) ξ1} ··· e^{(qn + on) ξn} (SerialRobot::fk's
/// product of exponentials, GF §4.5) in rotation matrices, for the residuals. Each revolute factor is
/// Rodrigues' R_i = c I + s [v]× + (1 − c) v vᵀ with the translation p − R_i p = (1 − c) p⊥ − s v × p
/// (p⊥ = p − v (v·p)), from one sincos. The product is kept in two parts, the joints before `split`
/// (from the base) and from `split` on (from the tool), each with its partial products: the next
/// posture that shares leading or trailing joint values (bit for bit: the postures of one arm solution,
/// which differ only in the three joints of the Pieper triple) starts from them. Plain scalar arrays
/// (3×3 products in Eigen's packets cost twice as much here).
template <class S> class FkChain {
 public:
  FkChain(const SerialRobot<S>& robot, int split) : n_(robot.dof()), split_(std::clamp(split, 0, robot.dof())) {
    const auto& J = robot.joints();
    for (int i = 0; i < n_ && i < 6; ++i) {
      const Vec3<S>& v = J[i].axis;
      const Vec3<S>& p = J[i].point;
      Joint& j = j_[i];
      for (int k = 0; k < 3; ++k) j.v[k] = v(k);
      j.vv[0] = v.x() * v.x(), j.vv[1] = v.y() * v.y(), j.vv[2] = v.z() * v.z();
      j.vv[3] = v.x() * v.y(), j.vv[4] = v.x() * v.z(), j.vv[5] = v.y() * v.z();
      const Vec3<S> pp = p - v * v.dot(p), w = v.cross(p);
      for (int k = 0; k < 3; ++k) j.pp[k] = pp(k), j.w[k] = w(k);
      j.offset = J[i].offset;
      j.prismatic = J[i].type == JointType::Prismatic;
    }
    for (int k = 0; k < 9; ++k) PR_[0][k] = SR_[n_][k] = k % 4 == 0 ? S(1) : S(0);
    for (int k = 0; k < 3; ++k) Pt_[0][k] = St_[n_][k] = S(0);
    validS_ = n_;
  }
  /// The product's rotation R (row-major) and translation t for the joint values q.
  /// `c`, `s` (optional): cos and sin of each q_i + o_i, else computed here.
  template <class Vec> void eval(const Vec& q, S (&R)[9], S (&t)[3], const S* c = nullptr, const S* s = nullptr) {
    int m = 0;  // leading joints shared with the cached prefix
    while (m < validP_ && q(m) == qp_[m]) ++m;
    for (int i = m; i < split_; ++i) {
      qp_[i] = q(i);
      S Ri[9], d[3];
      factor(i, q(i), Ri, d, c, s);
      const S *A = PR_[i], *ta = Pt_[i];
      S *B = PR_[i + 1], *tb = Pt_[i + 1];
      for (int r = 0; r < 3; ++r) {  // (A, ta)·(Ri, d) = (A Ri, A d + ta)
        const S a0 = A[3 * r], a1 = A[3 * r + 1], a2 = A[3 * r + 2];
        tb[r] = ta[r] + a0 * d[0] + a1 * d[1] + a2 * d[2];
        B[3 * r] = a0 * Ri[0] + a1 * Ri[3] + a2 * Ri[6];
        B[3 * r + 1] = a0 * Ri[1] + a1 * Ri[4] + a2 * Ri[7];
        B[3 * r + 2] = a0 * Ri[2] + a1 * Ri[5] + a2 * Ri[8];
      }
    }
    validP_ = split_;
    int k = n_;  // trailing joints k..n−1 shared with the cached suffix
    while (k > split_ && k - 1 >= validS_ && q(k - 1) == qs_[k - 1]) --k;
    for (int i = k - 1; i >= split_; --i) {
      qs_[i] = q(i);
      S Ri[9], d[3];
      factor(i, q(i), Ri, d, c, s);
      const S *A = SR_[i + 1], *ta = St_[i + 1];
      S *B = SR_[i], *tb = St_[i];
      for (int r = 0; r < 3; ++r) {  // (Ri, d)·(A, ta) = (Ri A, Ri ta + d)
        tb[r] = d[r] + Ri[3 * r] * ta[0] + Ri[3 * r + 1] * ta[1] + Ri[3 * r + 2] * ta[2];
        for (int c = 0; c < 3; ++c)
          B[3 * r + c] = Ri[3 * r] * A[c] + Ri[3 * r + 1] * A[3 + c] + Ri[3 * r + 2] * A[6 + c];
      }
    }
    validS_ = split_;
    const S *PR = PR_[split_], *Pt = Pt_[split_], *SR = SR_[split_], *St = St_[split_];
    if (split_ == n_) {
      for (int i = 0; i < 9; ++i) R[i] = PR[i];
      for (int i = 0; i < 3; ++i) t[i] = Pt[i];
      return;
    }
    for (int r = 0; r < 3; ++r) {
      t[r] = Pt[r] + PR[3 * r] * St[0] + PR[3 * r + 1] * St[1] + PR[3 * r + 2] * St[2];
      for (int c = 0; c < 3; ++c) R[3 * r + c] = PR[3 * r] * SR[c] + PR[3 * r + 1] * SR[3 + c] + PR[3 * r + 2] * SR[6 + c];
    }
  }

 private:
  struct Joint {
    S v[3], vv[6], pp[3], w[3], offset;
    bool prismatic;
  };
  /// The factor of joint i at joint value q: x ↦ Ri x + d.
  SOMA_ALWAYS_INLINE void factor(int i, const S& q, S (&Ri)[9], S (&d)[3], const S* cq, const S* sq) const {
    const Joint& j = j_[i];
    const S th = q + j.offset;
    if (j.prismatic) {
      for (int k = 0; k < 9; ++k) Ri[k] = k % 4 == 0 ? S(1) : S(0);
      for (int k = 0; k < 3; ++k) d[k] = th * j.v[k];
      return;
    }
    S s, c;
    if (cq) {
      c = cq[i];
      s = sq[i];
    } else {
      sinCos(th, s, c);
    }
    const S c1 = S(1) - c;
    Ri[0] = c + c1 * j.vv[0], Ri[1] = c1 * j.vv[3] - s * j.v[2], Ri[2] = c1 * j.vv[4] + s * j.v[1];
    Ri[3] = c1 * j.vv[3] + s * j.v[2], Ri[4] = c + c1 * j.vv[1], Ri[5] = c1 * j.vv[5] - s * j.v[0];
    Ri[6] = c1 * j.vv[4] - s * j.v[1], Ri[7] = c1 * j.vv[5] + s * j.v[0], Ri[8] = c + c1 * j.vv[2];
    for (int k = 0; k < 3; ++k) d[k] = c1 * j.pp[k] - s * j.w[k];
  }
  int n_, split_;
  Joint j_[6];
  S PR_[7][9], Pt_[7][3], SR_[7][9], St_[7][3], qp_[6], qs_[6];
  int validP_ = 0, validS_ = 0;
};

template <class S, class Vec>
S residualOf(const Vec& q, const PoseMatrices<S>& pm, FkChain<S>& fk,
             ResidualMode mode, const S* c = nullptr, const S* s = nullptr) {
  using std::sqrt;
  S R[9], t[3];
  fk.eval(q, R, t, c, s);
  S r2 = S(0), t2 = S(0);
  if (mode != ResidualMode::Position)
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) {
        const S e = R[3 * r + k] - pm.RTM(r, k);
        r2 += e * e;
      }
  if (mode != ResidualMode::Rotation)
    for (int r = 0; r < 3; ++r) {  // t + R t_M − t*
      const S e = t[r] + R[3 * r] * pm.tM(0) + R[3 * r + 1] * pm.tM(1) + R[3 * r + 2] * pm.tM(2) - pm.tT(r);
      t2 += e * e;
    }
  // poseResidual (serial_robot.hpp): sqrt(max(|R − R*|², |t − t*|² / L²))
  switch (mode) {
    case ResidualMode::Position: return sqrt(t2) * pm.invL;
    case ResidualMode::Rotation: return sqrt(r2);
    case ResidualMode::Pose: break;
  }
  return sqrt(std::max<S>(r2, t2 * pm.invL2));
}

/// Revolute joints wrapped to (−π, π] (SerialRobot::wrap without its copy; in-range values kept).
template <class S, class Vec> void wrapInPlace(const SerialRobot<S>& robot, Vec& q) {
  using std::atan2;
  for (int i = 0; i < robot.dof() && i < int(q.size()); ++i)
    if (robot.joints()[i].type == JointType::Revolute && !(q(i) > -pi<S>() && q(i) <= pi<S>())) {
      S s, c;
      sinCos(S(q(i)), s, c);
      q(i) = atan2(s, c);
    }
}

/// Newton steps on the posture (full pose: body Jacobian and the SE(3) log; position: the tool
/// point's velocity columns; rotation: the angular rows), kept only while the residual falls.
/// Closed forms are exact up to rounding: the caller runs it only when the residual is above 64 ulps.
template <class S>
void polish(const SerialRobot<S>& robot, JointVector<S>& q, const SE3<S>& target, const PoseMatrices<S>& pm,
            FkChain<S>& fk, ResidualMode mode, S& res) {
  for (int it = 0; it < 4 && res > Tolerance<S>::identity(); ++it) {
    const JacobianMatrix<S> Js = robot.spatialJacobian(q);
    const SE3<S> t = robot.fk(q);
    JointVector<S> dq;
    if (mode == ResidualMode::Pose && robot.dof() == 6) {
      const Vec6<S> e = t.inverse().compose(target).log().coeffs();
      const Mat6<S> Jb = t.inverse().adjoint() * Js;
      dq = Jb.partialPivLu().solve(e);
    } else if (robot.dof() == 3) {
      Mat3<S> J;
      Vec3<S> e;
      if (mode == ResidualMode::Rotation) {
        J = Js.template topRows<3>();
        e = SO3<S>::fromMatrix(target.rotation() * t.rotation().transpose()).log().coeffs();
      } else {
        const Vec3<S> p = t.translation();
        for (int i = 0; i < 3; ++i)  // v + ω × p
          J.col(i) = Js.col(i).template tail<3>() + Js.col(i).template head<3>().cross(p);
        e = target.translation() - p;
      }
      dq = J.partialPivLu().solve(e);
    } else {
      return;
    }
    if (!allFinite(dq)) return;
    const JointVector<S> qn = q + dq;
    const S rn = residualOf(qn, pm, fk, mode);
    if (!(rn < res)) return;
    q = qn;
    res = rn;
  }
}

template <class S>
void finish(const SerialRobot<S>& robot, const SE3<S>& target, const PoseMatrices<S>& pm, ResidualMode mode,
            const Raws<S>& raws, Solution<S>& sol, Clock::time_point t0, int split) {
  int outside = 0, missed = 0;
  const int n = robot.dof();
  FkChain<S> fk(robot, split);
  sol.postures.reserve(std::size_t(raws.n));
  sol.residuals.reserve(std::size_t(raws.n));
  std::array<S, 6> offset{};
  bool limited = false;  // some joint has a finite limit
  for (int i = 0; i < n && i < 6; ++i) {
    const auto& j = robot.joints()[i];
    offset[i] = j.offset;
    limited = limited || j.lower > -std::numeric_limits<S>::infinity() || j.upper < std::numeric_limits<S>::infinity();
  }
  for (int k = 0; k < raws.n; ++k) {
    Joints6<S> q = raws.q[k];
    for (int i = 0; i < n; ++i) q(i) -= offset[i];
    wrapInPlace(robot, q);
    // The residual's forward kinematics at q, with cos and sin of q_i + o_i taken from the pair each
    // angle was computed from when the solver kept it (q_i + o_i = atan2(s_i, c_i) up to the rounding
    // of the offset and the wrap by 2π: the pair is cos and sin of it to about 1 ulp, as sin and cos
    // themselves are).
    S res = raws.trig[k] ? residualOf(q, pm, fk, mode, raws.c[k].data(), raws.s[k].data())
                         : residualOf(q, pm, fk, mode);
    if (res > Tolerance<S>::identity()) {
      JointVector<S> qd = q.head(n);
      polish(robot, qd, target, pm, fk, mode, res);
      q.head(n) = qd;
      wrapInPlace(robot, q);
    }
    // A candidate (the real part of a complex pair near the real axis, see solveCirclePair) that
    // Newton cannot bring onto the pose is not a posture.
    if (raws.cand[k] && !(res <= Tolerance<S>::sqrtEpsilon())) {
      ++missed;
      continue;
    }
    // θ + 2πk where the limits lie off (−π, π]
    if (limited && !shiftIntoLimitsInPlace(robot, q)) {
      ++outside;
      continue;
    }
    JointVector<S>& out = sol.postures.emplace_back(n);
    for (int i = 0; i < n; ++i) out(i) = q(i);
    sol.residuals.push_back(res);
  }
  if (outside)
    sol.notes.push_back(std::to_string(outside) + " posture(s) outside the joint limits dropped");
  if (missed)
    sol.notes.push_back(std::to_string(missed) + " candidate(s) from near-real roots did not reach the pose and were dropped");
  sol.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
}

template <class S> void requireRevolute(const SerialRobot<S>& robot, int n, const char* method) {
  if (robot.dof() != n)
    throw InvalidInput(std::string("ik method ") + method + ": needs a robot with " + std::to_string(n) +
                       " joints, this one has " + std::to_string(robot.dof()));
  for (int i = 0; i < n; ++i)
    if (robot.joints()[i].type != JointType::Revolute)
      throw InvalidInput(std::string("ik method ") + method + ": joint " + std::to_string(i + 1) +
                         " is prismatic (closed forms here are for revolute joints)");
}

/// Common point of three lines (least squares) and the largest distance from it.
template <class S> bool concurrentPoint(const std::array<Vec3<S>, 3>& v, const std::array<Vec3<S>, 3>& r,
                                        const S& tol, Vec3<S>& c) {
  using std::abs;
  Mat3<S> A = Mat3<S>::Zero();
  Vec3<S> b = Vec3<S>::Zero();
  for (int i = 0; i < 3; ++i) {
    const Mat3<S> P = Mat3<S>::Identity() - v[i] * v[i].transpose();
    A += P;
    b += P * r[i];
  }
  // A = Σ (I − v vᵀ) is 3×3 symmetric: its determinant and inverse by cofactors (Eigen's fixed-size path).
  const S det = A.determinant();
  if (!(abs(det) > Tolerance<S>::input())) return false;  // parallel axes
  c = A.inverse() * b;
  for (int i = 0; i < 3; ++i) {
    const Vec3<S> d = (c - r[i]) - v[i] * v[i].dot(c - r[i]);
    if (d.squaredNorm() > tol * tol) return false;
  }
  return true;
}


/// A rigid motion as a rotation matrix and a translation: x ↦ R x + t.
template <class S> struct RigidMatrix {
  Mat3<S> R = Mat3<S>::Identity();
  Vec3<S> t = Vec3<S>::Zero();
  Vec3<S> act(const Vec3<S>& x) const { return R * x + t; }
  RigidMatrix operator*(const RigidMatrix& o) const { return {R * o.R, R * o.t + t}; }
  RigidMatrix inverse() const {
    const Mat3<S> Rt = R.transpose();
    return {Rt, -(Rt * t)};
  }
};
/// e^{θ ξ} of a revolute joint (unit axis v through r) from cos θ and sin θ: Rodrigues and r − R r.
// GF §5.2.1, GF-5.2.1-revolute-joint-exp
template <class S> RigidMatrix<S> jointMatrix(const SerialJoint<S>& j, const Angle<S>& a) {
  const Vec3<S>& v = j.axis;
  const S c = a.c, s = a.s, c1 = S(1) - c;
  RigidMatrix<S> m;
  m.R << c + c1 * v.x() * v.x(), c1 * v.x() * v.y() - s * v.z(), c1 * v.x() * v.z() + s * v.y(),  //
      c1 * v.y() * v.x() + s * v.z(), c + c1 * v.y() * v.y(), c1 * v.y() * v.z() - s * v.x(),      //
      c1 * v.z() * v.x() - s * v.y(), c1 * v.z() * v.y() + s * v.x(), c + c1 * v.z() * v.z();
  m.t = j.point - m.R * j.point;
  return m;
}

/// A unit vector ⟂ v (v × i, or v × j when v is near i): the reference direction of an angle about v.
template <class S> Vec3<S> normalTo(const Vec3<S>& v) {
  Vec3<S> x = v.cross(Vec3<S>::UnitX());
  if (x.squaredNorm() < S(1) / S(4)) x = v.cross(Vec3<S>::UnitY());
  return x;
}

/// Planar 3R with parallel axes (joint indices j, j+1, j+2 of `robot`): E_j E_{j+1} E_{j+2} = X.
/// Up to 2 solutions (raw angles) in `out`. GF §10.3.2 (the planar arm after the T³ reduction:
/// cosine rule for θ3, erratum E10.7; θ2 from X, Y, erratum E10.8)
template <class S> int planar3R(const SerialRobot<S>& robot, int j, const RigidMatrix<S>& X,
                                std::array<std::array<Angle<S>, 3>, 2>& out, bool& doubleRoot, bool& degenerate) {
  const auto& J = robot.joints();
  const Vec3<S> u = J[j].axis;
  auto P = [&](const Vec3<S>& x) { return Vec3<S>(x - u * u.dot(x)); };
  const Vec3<S> r1 = J[j].point, r2 = J[j + 1].point, r3 = J[j + 2].point;
  const Vec3<S> w = X.act(r3);
  const Vec3<S> e = P(r2 - r1), f = P(r3 - r2);
  const S D2 = P(w - r1).squaredNorm();
  const Vec3<S> v2 = J[j + 1].axis;
  TrigPair<S> t2 = linearTrig<S>(S(2) * e.dot(f), S(2) * e.dot(v2.cross(f)), D2 - e.squaredNorm() - f.squaredNorm());
  doubleRoot = t2.doubleRoot;
  if (t2.free) {
    degenerate = true;
    t2.n = 1;
    t2.a[0] = Angle<S>{};
  }
  const S L2 = robot.lengthScale() * robot.lengthScale();
  const Vec3<S> v3 = J[j + 2].axis, x = normalTo(v3), RXx = X.R * x, g3 = v3.cross(x);
  for (int i = 0; i < t2.n; ++i) {
    const Angle<S>& a2 = t2.a[i];
    const Vec3<S> a = r2 + rotateAbout<S>(v2, a2.c, a2.s, Vec3<S>(r3 - r2));  // E_{j+1}(θ2) r3
    bool deg = false;
    const Angle<S> a1 = angleAbout<S>(J[j].axis, Vec3<S>(a - r1), Vec3<S>(w - r1), &deg, L2);
    if (deg) degenerate = true;
    // R3 x = R2ᵀ R1ᵀ RX x
    const Vec3<S> R3x = rotateAbout<S>(v2, a2.c, S(-a2.s), rotateAbout<S>(J[j].axis, a1.c, S(-a1.s), RXx));
    out[i] = {a1, a2, angleOf<S>(R3x.dot(g3), R3x.dot(x))};  // v3·(x × R3x) = R3x·(v3 × x)
  }
  return t2.n;
}

/// wrist3R without allocation: up to 2 (θ1, θ2, θ3) in `out`, their count returned.
// GF §5.1, GF-5.1-wrist-theta2, GF-5.1-wrist-theta1-theta3 (corrected sign, erratum E5.1)
template <class S> int wristCore(const Vec3<S>& v1, const Vec3<S>& v2, const Vec3<S>& v3, const Mat3<S>& R,
                                 std::array<std::array<Angle<S>, 3>, 2>& out, bool& gimbal, bool& doubleRoot) {
  // v1ᵀ e^{θ2 v2} v3 = (v1·v2)(v2·v3) + cos θ2 [v1·v3 − (v1·v2)(v2·v3)] + sin θ2 v1·(v2×v3).
  const S c12 = v1.dot(v2) * v2.dot(v3);
  const Vec3<S> z = R * v3;
  TrigPair<S> t2 = linearTrig<S>(v1.dot(v3) - c12, v1.dot(v2.cross(v3)), S(v1.dot(z)) - c12);
  doubleRoot = t2.doubleRoot;
  gimbal = false;
  if (t2.free) {  // v1 = ±v3 and v2 ⟂ both or equal: degenerate wrist
    t2.n = 1;
    t2.a[0] = Angle<S>{};
  }
  // θ1 is the angle about v1 from y to z (projections y′, z′ ⟂ v1): v1·(y′ × z′) = y·(z′ × v1) and
  // y′·z′ = y·z′, so z′ and z′ × v1 are formed once. θ3 is the angle about v3 from x (⟂ v3) to R3 x:
  // v3·(x × R3x) = R3x·(v3 × x).
  const Vec3<S> zp = z - v1 * v1.dot(z), g1 = zp.cross(v1);
  const Vec3<S> x = normalTo(v3), Rx = R * x, g3 = v3.cross(x);
  for (int i = 0; i < t2.n; ++i) {
    const Angle<S>& a2 = t2.a[i];
    const Vec3<S> y = rotateAbout<S>(v2, a2.c, a2.s, v3);  // the book's y = e^{θ2 ad v2} v3
    const Vec3<S> yp = y - v1 * v1.dot(y);
    const bool g = yp.squaredNorm() <= Tolerance<S>::identity(64);
    // y'·z' = |y'|² cos θ1 and v1·(y'×z') = |y'|² sin θ1, i.e. −(y×v1)ᵀ R v3 (E5.1).
    const Angle<S> a1 = g ? Angle<S>{} : angleOf<S>(y.dot(g1), y.dot(zp));
    if (g) gimbal = true;
    // R3 x = e^{−θ2 v2} e^{−θ1 v1} R x
    const Vec3<S> R3x = rotateAbout<S>(v2, a2.c, S(-a2.s), rotateAbout<S>(v1, a1.c, S(-a1.s), Rx));
    out[i] = {a1, a2, angleOf<S>(R3x.dot(g3), R3x.dot(x))};
  }
  return t2.n;
}

}  // namespace

template <class S> TrigRoots<S> solveLinearTrig(const S& p, const S& q, const S& k) {
  const TrigPair<S> r = linearTrig<S>(p, q, k);
  TrigRoots<S> out;
  out.free = r.free;
  out.doubleRoot = r.doubleRoot;
  for (int i = 0; i < r.n; ++i) out.angles.push_back(r.a[i].th);
  return out;
}

template <class S>
WristAngles<S> wrist3R(const Vec3<S>& v1, const Vec3<S>& v2, const Vec3<S>& v3, const Mat3<S>& R) {
  WristAngles<S> out;
  std::array<std::array<Angle<S>, 3>, 2> a;
  const int n = wristCore<S>(v1, v2, v3, R, a, out.gimbal, out.doubleRoot);
  for (int i = 0; i < n; ++i) out.angles.emplace_back(a[i][0].th, a[i][1].th, a[i][2].th);
  return out;
}

template <class S> PieperTriple<S> findPieperTriple(const SerialRobot<S>& robot) {
  PieperTriple<S> out;
  if (robot.dof() != 6 || !robot.allRevolute()) return out;
  const auto& J = robot.joints();
  const S tol = Tolerance<S>::input();
  for (int first : {3, 0, 1, 2}) {
    std::array<Vec3<S>, 3> v, r;
    for (int i = 0; i < 3; ++i) {
      v[i] = J[first + i].axis;
      r[i] = J[first + i].point;
    }
    const bool parallel = v[0].cross(v[1]).squaredNorm() <= tol * tol &&
                          v[0].cross(v[2]).squaredNorm() <= tol * tol;
    if (parallel) {
      out.first = first;
      out.concurrent = false;
      out.direction = v[0];
      using std::sqrt;
      out.defect = sqrt(std::max<S>(v[0].cross(v[1]).squaredNorm(), v[0].cross(v[2]).squaredNorm()));
      return out;
    }
    // Concurrent axes are pairwise within 2 tol·L of each other (each is within tol·L of the common
    // point): two skew axes farther apart rule the triple out before the least-squares point.
    bool skew = false;
    for (int a = 0; a < 3 && !skew; ++a) {
      const int b = (a + 1) % 3;
      const Vec3<S> n = v[a].cross(v[b]);
      const S nn = n.norm();
      using std::abs;
      skew = nn > tol && abs(S((r[b] - r[a]).dot(n))) > S(2) * tol * robot.lengthScale() * nn;
    }
    if (skew) continue;
    Vec3<S> c;
    if (concurrentPoint<S>(v, r, tol * robot.lengthScale(), c)) {
      out.first = first;
      out.concurrent = true;
      out.point = c;
      S worst2(0);
      for (int i = 0; i < 3; ++i) {
        const Vec3<S> d = (c - r[i]) - v[i] * v[i].dot(c - r[i]);
        worst2 = std::max<S>(worst2, d.squaredNorm());
      }
      using std::sqrt;
      out.defect = sqrt(worst2) / robot.lengthScale();
      return out;
    }
  }
  return out;
}

template <class S> bool isWrist(const SerialRobot<S>& robot) {
  if (robot.dof() != 3 || !robot.allRevolute()) return false;
  std::array<Vec3<S>, 3> v, r;
  for (int i = 0; i < 3; ++i) {
    v[i] = robot.joints()[i].axis;
    r[i] = robot.joints()[i].point;
  }
  Vec3<S> c;
  return concurrentPoint<S>(v, r, Tolerance<S>::input() * robot.lengthScale(), c);
}

template <class S> IkMethod classifyRobot(const SerialRobot<S>& robot) {
  if (!robot.allRevolute())
    throw InvalidInput("ik: the robot has a prismatic joint; the closed forms and the 6R solver "
                       "need revolute joints");
  if (robot.dof() == 3) return isWrist(robot) ? IkMethod::Wrist3R : IkMethod::Arm3R;
  if (robot.dof() == 6) return findPieperTriple(robot).first >= 0 ? IkMethod::Pieper : IkMethod::General6R;
  throw InvalidInput("ik: no method for a robot with " + std::to_string(robot.dof()) +
                     " joints (3R wrists and arms, 6R robots)");
}


template <class S> Solution<S> solveWrist3R(const SerialRobot<S>& robot, const SE3<S>& target) {
  const auto t0 = Clock::now();
  requireRevolute(robot, 3, "wrist3r");
  if (!isWrist(robot)) throw InvalidInput("ik method wrist3r: the three axes do not meet in a point");
  Solution<S> sol;
  sol.method = "wrist3r";
  sol.expected_count = 2;
  const auto& J = robot.joints();
  const Mat3<S> R = target.rotation() * robot.home().rotation().transpose();
  std::array<std::array<Angle<S>, 3>, 2> w;
  bool gimbal = false, doubleRoot = false;
  const int n = wristCore<S>(J[0].axis, J[1].axis, J[2].axis, R, w, gimbal, doubleRoot);
  if (gimbal) {
    sol.continuum = true;
    sol.notes.push_back("gimbal singularity: θ1 and θ3 determined only in combination (θ1 = 0 returned)");
  }
  if (doubleRoot) sol.notes.push_back("double root: the two postures merge (boundary of the reachable set)");
  Raws<S> raws;
  for (int i = 0; i < n; ++i) raws.push(false, w[i]);
  finish(robot, target, PoseMatrices<S>(robot, target), ResidualMode::Rotation, raws, sol, t0, 3);
  return sol;
}

template <class S> Solution<S> solveArm3R(const SerialRobot<S>& robot, const SE3<S>& target) {
  const auto t0 = Clock::now();
  requireRevolute(robot, 3, "arm3r");
  Solution<S> sol;
  sol.method = "arm3r";
  sol.expected_count = 4;
  const auto& J = robot.joints();
  const Vec3<S> p0 = robot.home().translation(), p = target.translation();
  // a = e^{θ3 S3} p0, b = e^{−θ1 S1} p; invariants of the rotation about axis 2.
  const Circle<S> ca = circleOf<S>(J[2].axis, J[2].point, p0, +1);
  const Circle<S> cb = circleOf<S>(J[0].axis, J[0].point, p, -1);
  const PairRoots<S> pr = solveCirclePair<S>(pointInvariants(ca, J[1].axis, J[1].point),
                                             pointInvariants(cb, J[1].axis, J[1].point), sol.notes);
  sol.continuum = pr.continuum;
  if (pr.doubleRoot) sol.notes.push_back("double root: two postures merge (on a bifurcation surface)");
  Raws<S> raws;
  const S L2 = robot.lengthScale() * robot.lengthScale();
  for (int k = 0; k < pr.n; ++k) {
    const Angle<S>&a3 = pr.a[k], &a1 = pr.b[k];
    const Vec3<S> a = ca.at(a3), b = cb.at(a1);
    bool deg = false;
    const Angle<S> a2 = angleAbout<S>(J[1].axis, Vec3<S>(a - J[1].point), Vec3<S>(b - J[1].point), &deg, L2);
    if (deg) {
      sol.continuum = true;
      sol.notes.push_back("the point lies on axis 2: θ2 is free (θ2 = 0 returned)");
    }
    raws.push(pr.nearReal[k], std::array<Angle<S>, 3>{a1, deg ? Angle<S>{} : a2, a3});
  }
  finish(robot, target, PoseMatrices<S>(robot, target), ResidualMode::Position, raws, sol, t0, 3);
  return sol;
}

namespace {

/// Pieper robot with the special triple at joints 4-6 (first = 3) or 2-4 (first = 1); the raw
/// postures are appended to `raws`.
template <class S>
void pieperCore(const SerialRobot<S>& robot, const PieperTriple<S>& tri, const PoseMatrices<S>& pm, Solution<S>& sol,
                Raws<S>& raws) {
  const auto& J = robot.joints();
  // A = target · home⁻¹ = E1 ··· E6, as matrices.
  const RigidMatrix<S> A{pm.RTM, Vec3<S>(pm.tT - pm.RTM * pm.tM)};
  const S L2 = robot.lengthScale() * robot.lengthScale();
  // Sides of the circle pair: (joint, sign, transformed-by-A⁻¹?) and the middle joint.
  int ja, jb, jm, sa, sb, sm;
  if (tri.first == 3) {
    ja = 2, sa = +1, jb = 0, sb = -1, jm = 1, sm = +1;  // E2 E3 x = E1⁻¹ A x
  } else {
    ja = 4, sa = -1, jb = 0, sb = +1, jm = 5, sm = -1;  // E6⁻¹ E5⁻¹ x = A⁻¹ E1 x
  }
  // Line of joint jb as seen on the b side (through A⁻¹ when the triple is 2-4); the b-side object
  // is Xobj applied.
  const RigidMatrix<S> Ainv = A.inverse();
  const RigidMatrix<S>& Xobj = tri.first == 3 ? A : Ainv;
  const Vec3<S> vb = tri.first == 3 ? J[jb].axis : Vec3<S>(Ainv.R * J[jb].axis);
  const Vec3<S> rb = tri.first == 3 ? J[jb].point : Ainv.act(J[jb].point);
  const Vec3<S> vm = J[jm].axis, rm = J[jm].point;
  PairRoots<S> pr;
  Circle<S> ca, cb;
  if (tri.concurrent) {
    ca = circleOf<S>(J[ja].axis, J[ja].point, tri.point, sa);
    cb = circleOf<S>(vb, rb, Xobj.act(tri.point), sb);
    pr = solveCirclePair<S>(pointInvariants(ca, vm, rm), pointInvariants(cb, vm, rm), sol.notes);
  } else {
    const Vec3<S> n0 = tri.direction;
    const Vec3<S> nb = Xobj.R * n0;
    const S db = nb.dot(Xobj.t);  // plane n0·y = 0 moved by Xobj
    pr = solveCirclePair<S>(planeInvariants<S>(J[ja].axis, J[ja].point, n0, S(0), sa, vm, rm, &ca),
                            planeInvariants<S>(vb, rb, nb, db, sb, vm, rm, &cb), sol.notes);
  }
  if (pr.continuum) sol.continuum = true;
  if (pr.doubleRoot) sol.notes.push_back("double root in the positioning quartic (postures merge)");
  const int j0 = tri.first;
  for (int k = 0; k < pr.n; ++k) {
    const Angle<S>&phA = pr.a[k], &phB = pr.b[k];
    const Vec3<S> a = ca.at(phA), b = cb.at(phB);
    bool deg = false;
    const Angle<S> psi = tri.concurrent ? angleAbout<S>(vm, Vec3<S>(a - rm), Vec3<S>(b - rm), &deg, L2)
                                        : angleAbout<S>(vm, a, b, &deg, S(1));
    if (deg) {
      sol.continuum = true;
      sol.notes.push_back("wrist-type singularity: joint " + std::to_string(jm + 1) + " is free (0 returned)");
    }
    // The circles already carry the sign of their joint (a = e^{σφ S} x with σφ = σθ), so θ = φ.
    std::array<Angle<S>, 6> th;
    th[ja] = phA;
    th[jb] = phB;
    th[jm] = deg ? Angle<S>{} : signedAngle(sm, psi);
    std::array<std::array<Angle<S>, 3>, 2> tr;
    int ntr;
    if (tri.concurrent) {  // the wrist needs only the rotation
      // first = 3: RX = (R1 R2 R3)ᵀ RA; first = 1: RX = R1ᵀ RA R6ᵀ R5ᵀ.
      Mat3<S> RX;
      for (int col = 0; col < 3; ++col) {
        Vec3<S> w = A.R.col(col);
        const int last = tri.first == 3 ? 3 : 1;
        for (int i = 0; i < last; ++i) w = rotateAbout<S>(J[i].axis, th[i].c, S(-th[i].s), w);
        RX.col(col) = w;
      }
      if (tri.first == 1) {  // RX ← RX R6ᵀ R5ᵀ: rows rotated, i.e. (R5 R6 RXᵀ)ᵀ
        Mat3<S> T = RX.transpose();
        for (int col = 0; col < 3; ++col) {
          Vec3<S> w = T.col(col);
          w = rotateAbout<S>(J[5].axis, th[5].c, th[5].s, w);
          w = rotateAbout<S>(J[4].axis, th[4].c, th[4].s, w);
          T.col(col) = w;
        }
        RX = T.transpose();
      }
      bool gimbal = false, dbl = false;
      ntr = wristCore<S>(J[j0].axis, J[j0 + 1].axis, J[j0 + 2].axis, RX, tr, gimbal, dbl);
      if (gimbal) {
        sol.continuum = true;
        sol.notes.push_back("wrist gimbal singularity: joints " + std::to_string(j0 + 1) + " and " +
                            std::to_string(j0 + 3) + " determined only in combination");
      }
      if (dbl) sol.notes.push_back("wrist double root (postures merge)");
    } else {
      RigidMatrix<S> X;
      if (tri.first == 3) {
        X = (jointMatrix(J[0], th[0]) * jointMatrix(J[1], th[1]) * jointMatrix(J[2], th[2])).inverse() * A;
      } else {
        X = jointMatrix(J[0], th[0]).inverse() * A * jointMatrix(J[5], th[5]).inverse() *
            jointMatrix(J[4], th[4]).inverse();
      }
      bool dbl = false, dg = false;
      ntr = planar3R<S>(robot, j0, X, tr, dbl, dg);
      if (dbl) sol.notes.push_back("planar arm double root (elbow straight: postures merge)");
      if (dg) {
        sol.continuum = true;
        sol.notes.push_back("planar arm degenerate (a point on an axis)");
      }
    }
    for (int i = 0; i < ntr; ++i) {
      for (int m = 0; m < 3; ++m) th[j0 + m] = tr[i][m];
      raws.push(pr.nearReal[k], th);
    }
  }
}

}  // namespace

template <class S> Solution<S> solvePieper(const SerialRobot<S>& robot, const SE3<S>& target) {
  const auto t0 = Clock::now();
  requireRevolute(robot, 6, "pieper");
  const PieperTriple<S> tri = findPieperTriple(robot);
  if (tri.first < 0)
    throw InvalidInput("ik method pieper: no three consecutive axes meet in a point or are parallel");
  Solution<S> sol;
  sol.method = "pieper";
  sol.expected_count = 8;
  sol.notes.reserve(4);
  {
    std::string note = "axes 1-3";
    note[5] = char('1' + tri.first);
    note[7] = char('3' + tri.first);
    note += tri.concurrent ? " meet in a point" : " are parallel";
    sol.notes.push_back(std::move(note));
  }
  Raws<S> raws;
  const PoseMatrices<S> pm(robot, target);
  if (tri.first == 3 || tri.first == 1) {
    pieperCore(robot, tri, pm, sol, raws);
  } else {  // 1-3 or 3-5: solve the reversed robot (T⁻¹ with joints 6..1), where they are 4-6 / 2-4
    const SerialRobot<S> rev = robot.reversed();
    PieperTriple<S> rt = tri;
    rt.first = 3 - tri.first;
    // the reversed robot's coordinates are the tool-home frame: point p ↦ M⁻¹ p
    rt.point = robot.home().inverse().act(tri.point);
    rt.direction = robot.home().inverse().so3().act(tri.direction);
    pieperCore(rev, rt, PoseMatrices<S>(rev, SE3<S>(target.inverse())), sol, raws);
    for (int k = 0; k < raws.n; ++k) raws.reverse(k);
  }
  // The postures of one arm solution differ only in the triple's joints: the residuals' forward
  // kinematics keeps the product of the joints before the triple and of those after it.
  finish(robot, target, pm, ResidualMode::Pose, raws, sol, t0, tri.first + 3);
  return sol;
}

template <class S>
Solution<S> solveClosedForm(const SerialRobot<S>& robot, const SE3<S>& target, IkMethod method) {
  if (method == IkMethod::Auto) method = classifyRobot(robot);
  switch (method) {
    case IkMethod::Wrist3R: return solveWrist3R(robot, target);
    case IkMethod::Arm3R: return solveArm3R(robot, target);
    case IkMethod::Pieper: return solvePieper(robot, target);
    default: break;
  }
  if (method == IkMethod::General6R)
    throw InvalidInput("ik: method general6r is not a closed form (this robot has no three "
                       "consecutive axes meeting or parallel)");
  throw InvalidInput("ik: method " + std::string(ikMethodName(method)) + " is not a closed form (solveIk runs it)");
}

#define SOMA_INSTANTIATE_CLOSED_FORM_IK(S)                                                               \
  template TrigRoots<S> solveLinearTrig<S>(const S&, const S&, const S&);                     \
  template WristAngles<S> wrist3R<S>(const Vec3<S>&, const Vec3<S>&, const Vec3<S>&,           \
                                     const Mat3<S>&);                                          \
  template PieperTriple<S> findPieperTriple<S>(const SerialRobot<S>&);                         \
  template bool isWrist<S>(const SerialRobot<S>&);                                             \
  template IkMethod classifyRobot<S>(const SerialRobot<S>&);                                   \
  template Solution<S> solveWrist3R<S>(const SerialRobot<S>&, const SE3<S>&);                  \
  template Solution<S> solveArm3R<S>(const SerialRobot<S>&, const SE3<S>&);                    \
  template Solution<S> solvePieper<S>(const SerialRobot<S>&, const SE3<S>&);                   \
  template Solution<S> solveClosedForm<S>(const SerialRobot<S>&, const SE3<S>&, IkMethod);

}  // namespace soma

