// Motion jets and the instantaneous invariants of GF §5.3, explicitly instantiated for one scalar (soma_instantiate).
#pragma once
#include "soma/geometry/planar/instant_invariants.hpp"

#include <algorithm>

namespace soma::planar {

namespace {
/// The book's E₂ = [[0, 1], [−1, 0]]: E₂v = (v_y, −v_x) = −Jv.
template <class S> Vec2<S> E2(const Vec2<S>& v) { return Vec2<S>(v(1), -v(0)); }
template <class S> S factorial(int k) {
  S f(1);
  for (int j = 2; j <= k; ++j) f *= S(j);
  return f;
}
/// Affine polynomial u·w for u = (x − r_x, y − r_y) and a constant vector w.
template <class S> Poly2<S> dotU(const Vec2<S>& r, const Vec2<S>& w) {
  return Poly2<S>::affine(-r.dot(w), w(0), w(1));
}
}  // namespace

// ---- MotionJet ------------------------------------------------------------------------------

template <class S> MotionJet<S>::MotionJet(const Series<S>& angle, const Series<S>& x, const Series<S>& y)
    : phi_(angle), x_(x), y_(y) {
  for (int k = 0; k < kJetSize; ++k)
    if (!isFinite(phi_.a[k]) || !isFinite(x_.a[k]) || !isFinite(y_.a[k]))
      throw InvalidInput("motion jet: a derivative of the angle or the origin is NaN or infinite");
  build();
}

template <class S>
MotionJet<S> MotionJet<S>::fromDerivatives(const std::array<S, kJetSize>& angle, const std::array<Vec2<S>, kJetSize>& origin) {
  std::array<S, kJetSize> dx, dy;
  for (int k = 0; k < kJetSize; ++k) {
    dx[k] = origin[k](0);
    dy[k] = origin[k](1);
  }
  return MotionJet(Series<S>::fromDerivatives(angle), Series<S>::fromDerivatives(dx), Series<S>::fromDerivatives(dy));
}

template <class S>
MotionJet<S> MotionJet<S>::screw(const SE2<S>& g, const SE2Tangent<S>& xi, const std::array<S, kJetSize>& timeLaw) {
  // exp(s ξ) g: angle φ0 + s ω; origin = exp(sξ)·d0. For ω ≠ 0 a rotation about c = Jv/ω:
  // c + R(sω)(d0 − c); for ω = 0 the translation d0 + s v.
  const Series<S> s = Series<S>::fromDerivatives(timeLaw);
  const S w = xi.angular();
  const Vec2<S> v = xi.linear(), d0 = g.translation();
  Series<S> ang = s * w + g.angle();
  Series<S> X, Y;
  if (w == S(0)) {
    X = s * v(0) + d0(0);
    Y = s * v(1) + d0(1);
  } else {
    const Vec2<S> c = perp(v) / w;
    Series<S> sn, cs;
    sincos(s * w, sn, cs);
    const Vec2<S> q = d0 - c;
    X = cs * q(0) - sn * q(1) + c(0);
    Y = sn * q(0) + cs * q(1) + c(1);
  }
  return MotionJet(ang, X, Y);
}

template <class S> void MotionJet<S>::build() {
  theta_ = phi_ - phi_.a[0];
  Series<S> sn, cs;
  sincos(theta_, sn, cs);
  const S d0x = x_.a[0], d0y = y_.a[0];
  tx_ = x_ - (cs * d0x - sn * d0y);
  ty_ = y_ - (sn * d0x + cs * d0y);
  for (int k = 0; k < kJetSize; ++k) {
    const S f = factorial<S>(k);
    maps_[k].a = f * cs.a[k];
    maps_[k].b = f * sn.a[k];
    maps_[k].t = Vec2<S>(f * tx_.a[k], f * ty_.a[k]);
  }
  maps_[0].t.setZero();
}

template <class S> SE2<S> MotionJet<S>::pose() const { return SE2<S>(phi_.a[0], Vec2<S>(x_.a[0], y_.a[0])); }

template <class S> MotionJet<S> MotionJet<S>::timeScaled(const S& c) const {
  Series<S> p = phi_, X = x_, Y = y_;
  S ck(1);
  for (int k = 0; k < kJetSize; ++k) {
    p.a[k] *= ck;
    X.a[k] *= ck;
    Y.a[k] *= ck;
    ck *= c;
  }
  return MotionJet(p, X, Y);
}

template <class S> std::array<Vec2<S>, kJetSize> MotionJet<S>::pointDerivatives(const Vec2<S>& p) const {
  std::array<Vec2<S>, kJetSize> out;
  for (int k = 0; k < kJetSize; ++k) out[k] = maps_[k](p);
  return out;
}

template <class S> Vec3<S> MotionJet<S>::instantCentreHomogeneous() const {
  // GF §5.3.1: ẋ = ωJ(x − d) + ḋ vanishes at x = d + Jḋ/ω, homogeneously (ωd + Jḋ, ω).
  const S w = phi_.a[1];
  const Vec2<S> dd(x_.a[1], y_.a[1]), d(x_.a[0], y_.a[0]);
  const Vec2<S> h = w * d + perp(dd);
  return Vec3<S>(h(0), h(1), w);
}

// GF §5.3, GF-5.3-curvature-centre
template <class S> bool curvatureCentre(const Vec2<S>& p, const Vec2<S>& pd, const Vec2<S>& pdd, Vec2<S>& c) {
  using std::abs;
  using std::sqrt;
  const S D = cross2(pd, pdd);
  const S n2 = pd.squaredNorm();
  if (n2 == S(0) || !(abs(D) > Tolerance<S>::rank() * sqrt(n2 * pdd.squaredNorm()))) return false;
  c = p - n2 * E2(pd) / D;
  return true;
}

template <class S> S pathCurvature(const Vec2<S>& pd, const Vec2<S>& pdd) {
  using std::sqrt;
  const S n2 = pd.squaredNorm();
  if (n2 == S(0)) throw InvalidInput("path curvature: the velocity is zero (a cusp: the point is at the pole)");
  return cross2(pd, pdd) / (n2 * sqrt(n2));
}

// ---- InstantInvariants -------------------------------------------------------------------------

// GF §5.3.1, GF-5.3.1-lamina-derivatives (r(t) of the finite displacement, erratum E5.9)
template <class S> InstantInvariants<S> InstantInvariants<S>::fromJet(const MotionJet<S>& jet) {
  using std::abs;
  using std::sqrt;
  const Series<S>& th = jet.relativeAngle();
  const Series<S>& tx = jet.relativeX();
  const Series<S>& ty = jet.relativeY();
  const S w = th.a[1];
  const S speed = sqrt(tx.a[1] * tx.a[1] + ty.a[1] * ty.a[1]);
  const S scale = S(1) + sqrt(jet.x().a[0] * jet.x().a[0] + jet.y().a[0] * jet.y().a[0]);
  if (!(abs(w) * scale > Tolerance<S>::rank() * speed) || w == S(0))
    throw InvalidInput("instantaneous invariants: ω = " + toString(w) +
                       " (pole at infinity: an instantaneous translation, or no motion); the book's chart "
                       "(P1)–(P4) does not exist — use the direct polynomials of the jet");
  // r(t) = ½ t_A + ½ cot(θ/2) J t_A = ½ t_A + ½ (cos(θ/2) J t_A / t) / (sin(θ/2) / t).
  Series<S> sh, ch;
  sincos(th * (S(1) / S(2)), sh, ch);
  const Series<S> Jx = -(ty * ch), Jy = tx * ch;
  const Series<S> den = sh.shiftDown();
  const Series<S> qx = Jx.shiftDown() / den, qy = Jy.shiftDown() / den;
  InstantInvariants out;
  for (int k = 0; k < 4; ++k) {
    const S f = factorial<S>(k);
    out.w_[k] = th.derivative(k + 1);
    out.r_[k] = Vec2<S>(f * (tx.a[k] + qx.a[k]) / S(2), f * (ty.a[k] + qy.a[k]) / S(2));
  }
  return out;
}

// GF §5.3.1 (P1), (P2); §5.3.3 (P3); §5.3.5 (P4 corrected, erratum E5.13)
template <class S> std::array<Vec2<S>, 5> InstantInvariants<S>::pointDerivatives(const Vec2<S>& p) const {
  const S w = w_[0], wd = w_[1], wdd = w_[2], wddd = w_[3];
  const Vec2<S> u = p - r_[0];
  const Vec2<S>&rd = r_[1], &rdd = r_[2], &rddd = r_[3];
  std::array<Vec2<S>, 5> d;
  d[0] = p;
  d[1] = -w * E2(u);
  d[2] = -wd * E2(u) + S(2) * w * E2(rd) - w * w * u;
  d[3] = (w * w * w - wdd) * E2(u) - S(3) * w * wd * u + S(3) * w * w * rd + S(3) * wd * E2(rd) + S(3) * w * E2(rdd);
  d[4] = (S(6) * wd * w * w - wddd) * E2(u) + (w * w * w * w - S(4) * wdd * w - S(3) * wd * wd) * u +
         (S(4) * wdd - S(4) * w * w * w) * E2(rd) + S(12) * wd * w * rd + S(6) * wd * E2(rdd) + S(6) * w * w * rdd +
         S(4) * w * E2(rddd);
  return d;
}

// GF §5.3.1, GF-5.3.1-euler-savary
template <class S> bool InstantInvariants<S>::eulerSavaryCentre(const Vec2<S>& p, Vec2<S>& c) const {
  using std::abs;
  const Vec2<S> u = p - r_[0];
  const S e = S(2) * cross2(u, r_[1]);
  const S q = w_[0] * u.squaredNorm();
  const S den = e - q;
  if (!(abs(den) > Tolerance<S>::rank() * (abs(e) + abs(q)))) return false;
  c = r_[0] + (e / den) * u;
  return true;
}

// GF §5.3.2, GF-5.3.2-inflection-circle
template <class S> Circle<S> InstantInvariants<S>::inflectionCircle() const {
  using std::abs;
  return {r_[0] + E2(r_[1]) / w_[0], r_[1].norm() / abs(w_[0])};
}
template <class S> Vec2<S> InstantInvariants<S>::inflectionPole() const { return r_[0] + S(2) * E2(r_[1]) / w_[0]; }
template <class S> S InstantInvariants<S>::inflectionResidual(const Vec2<S>& p) const {
  const Vec2<S> u = p - r_[0];
  return u.dot(w_[0] * u - S(2) * E2(r_[1]));
}

// GF §5.3.3, GF-5.3.3-ball-point (corrected, errata E5.10, E5.11)
template <class S> Vec2<S> InstantInvariants<S>::undulationVector() const {
  const S w = w_[0], wd = w_[1];
  return w * w * r_[1] - wd * E2(r_[1]) + w * E2(r_[2]);
}
template <class S> Vec2<S> InstantInvariants<S>::ballPoint() const {
  const Vec2<S> x = undulationVector();
  const S xx = x.squaredNorm();
  if (!(xx > S(0))) throw InvalidInput("Ball's point: the undulation vector x = ω²ṙ − ω̇E₂ṙ + ωE₂r̈ is zero (undetermined)");
  const S lambda = S(2) * x.dot(r_[1]) / (w_[0] * xx);
  return r_[0] + lambda * E2(x);
}

// GF §5.3.4, GF-5.3.4-cubic-stationary-curvature (printed form, correct)
template <class S> S InstantInvariants<S>::stationaryCurvatureCubic(const Vec2<S>& p) const {
  const S w = w_[0], wd = w_[1];
  const Vec2<S> u = p - r_[0];
  const S uu = u.squaredNorm(), ur = u.dot(r_[1]), uEr = cross2(u, r_[1]), uErr = cross2(u, r_[2]);
  const S w3 = w * w * w, w4 = w3 * w, w5 = w4 * w;
  return S(3) * w5 * uu * ur + S(3) * w3 * wd * uu * uEr - S(3) * w4 * uu * uErr - S(12) * w4 * ur * uEr;
}
template <class S> Poly2<S> InstantInvariants<S>::stationaryCurvatureCubicPoly() const {
  const S w = w_[0], wd = w_[1];
  const Vec2<S>& r = r_[0];
  const Poly2<S> ux = Poly2<S>::affine(-r(0), S(1), S(0)), uy = Poly2<S>::affine(-r(1), S(0), S(1));
  const Poly2<S> uu = ux * ux + uy * uy;
  const Poly2<S> ur = dotU(r, r_[1]);
  // uᵀE₂w = u_x w_y − u_y w_x = u·(w_y, −w_x)
  const Poly2<S> uEr = dotU(r, E2(r_[1])), uErr = dotU(r, E2(r_[2]));
  const S w3 = w * w * w, w4 = w3 * w, w5 = w4 * w;
  return uu * ur * (S(3) * w5) + uu * uEr * (S(3) * w3 * wd) - uu * uErr * (S(3) * w4) - ur * uEr * (S(12) * w4);
}

// GF §5.3.4, GF-5.3.4-cubic-normal-form
template <class S> NormalFrame<S> InstantInvariants<S>::normalFrame() const {
  using std::abs;
  using std::sqrt;
  const S v2 = r_[1].squaredNorm();
  const S floor = Tolerance<S>::rank() * abs(w_[0]) * (S(1) + sqrt(r_[0].squaredNorm()));
  if (!(v2 > floor * floor)) throw InvalidInput("normal frame: ṙ = 0 (stationary pole): the frame of GF §5.3.4 is undefined");
  NormalFrame<S> f;
  f.v = sqrt(v2);
  f.origin = r_[0];
  f.ex = r_[1] / f.v;
  f.ey = perp(f.ex);
  const S ac = r_[2].dot(f.ex), as = -cross2(r_[2], r_[1]) / f.v;
  f.a = sqrt(r_[2].squaredNorm());
  f.cosTheta = f.a > S(0) ? ac / f.a : S(1);
  f.sinTheta = f.a > S(0) ? as / f.a : S(0);
  f.b = sqrt(r_[3].squaredNorm());
  f.cosPhi = f.b > S(0) ? r_[3].dot(f.ex) / f.b : S(1);
  f.sinPhi = f.b > S(0) ? r_[3].dot(f.ey) / f.b : S(0);
  return f;
}
template <class S> CubicNormalForm<S> InstantInvariants<S>::cubicNormalForm() const {
  CubicNormalForm<S> n;
  n.frame = normalFrame();
  const S v = n.frame.v, w = w_[0], wd = w_[1];
  const S as = n.frame.a * n.frame.sinTheta, ac = n.frame.a * n.frame.cosTheta;
  n.invMu = (as - w * v) / (S(4) * v * v);           // μ = 4v²/(a sinθ − ωv)  (E5.12)
  n.invNu = (wd * v - w * ac) / (S(4) * w * v * v);  // ν = 4ωv²/(ω̇v − ωa cosθ)
  return n;
}

// GF §5.3.5, GF-5.3.5-burmester-cubic (corrected set, erratum E5.14)
template <class S> BurmesterCubic<S> InstantInvariants<S>::burmesterCubic() const {
  const NormalFrame<S> f = normalFrame();
  const S w = w_[0], wd = w_[1], wdd = w_[2], v = f.v;
  const S as = f.a * f.sinTheta, ac = f.a * f.cosTheta, bs = f.b * f.sinPhi, bc = f.b * f.cosPhi;
  const S w2 = w * w, w3 = w2 * w, w4 = w3 * w, w5 = w4 * w;
  BurmesterCubic<S> c;
  c.alpha = S(2) * w3 * (S(3) * as * wd - S(3) * ac * w2 + S(2) * bs * w - S(6) * v * w * wd);
  c.beta = S(2) * w2 * (v * w4 + S(2) * v * w * wdd + S(3) * v * wd * wd - S(3) * as * w3 - S(3) * ac * w * wd - S(2) * bc * w2);
  c.gamma = S(12) * v * v * w5;
  c.eta = -S(24) * v * w3 * (ac * w + S(2) * v * wd);
  c.zeta = -S(24) * as * v * w4;
  c.xi = S(24) * v * v * v * w4;
  return c;
}

// ---- direct polynomials --------------------------------------------------------------------------

namespace {
template <class S> struct PathPolys {
  std::array<Poly2<S>, 5> x, y;  // p^(k)_x, p^(k)_y as affine polynomials in world (x, y)
  explicit PathPolys(const MotionJet<S>& jet) {
    for (int k = 0; k < 5; ++k) {
      x[k] = jet.pointMaps()[k].poly(0);
      y[k] = jet.pointMaps()[k].poly(1);
    }
  }
  Poly2<S> det(int i, int j) const { return x[i] * y[j] - y[i] * x[j]; }
  Poly2<S> dot(int i, int j) const { return x[i] * x[j] + y[i] * y[j]; }
};
}  // namespace

// GF §5.3.2, GF-5.3.2-inflection-circle (second method)
template <class S> Poly2<S> inflectionCurve(const MotionJet<S>& jet) { return PathPolys<S>(jet).det(1, 2); }
// GF §5.3.3, GF-5.3.3-ball-point (second method)
template <class S> Poly2<S> undulationCurve(const MotionJet<S>& jet) { return PathPolys<S>(jet).det(1, 3); }
// GF §5.3.4, GF-5.3.4-cubic-stationary-curvature (second method: the determinant itself)
template <class S> Poly2<S> stationaryCurvatureCurve(const MotionJet<S>& jet) {
  const PathPolys<S> P(jet);
  Poly2<S> q = P.dot(1, 1) * P.det(1, 3) - P.dot(2, 1) * P.det(1, 2) * S(3);
  for (int i = 0; i <= 4; ++i) q.at(i, 4 - i) = S(0);  // the quartic part cancels identically
  return q;
}
// GF §5.3.5, GF-5.3.5-burmester-cubic (second method)
template <class S> Poly2<S> fivePointContactCurve(const MotionJet<S>& jet) {
  const PathPolys<S> P(jet);
  Poly2<S> q = P.dot(1, 1) * P.det(1, 4) - (P.dot(3, 1) * S(4) + P.dot(2, 2) * S(3)) * P.det(1, 2);
  for (int i = 0; i <= 4; ++i) q.at(i, 4 - i) = S(0);
  return q;
}

// GF §5.3.5, GF-5.3.5-burmester-count
template <class S> BurmesterPoints<S> burmesterPoints(const MotionJet<S>& jet) {
  using std::abs;
  using std::sqrt;
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
  const NormalFrame<S> fr = inv.normalFrame();
  // Both cubics in the normal frame (origin at the pole, x along ṙ).
  const Poly2<S> Fw = stationaryCurvatureCurve(jet), Gw = fivePointContactCurve(jet);
  const Poly2<S> F = Fw.translated(fr.origin(0), fr.origin(1)).rotated(fr.ex(0), fr.ex(1));
  const Poly2<S> G = Gw.translated(fr.origin(0), fr.origin(1)).rotated(fr.ex(0), fr.ex(1));
  const Poly1<S> F2 = F.homogeneousPart(2), F3 = F.homogeneousPart(3);
  const Poly1<S> G1 = G.homogeneousPart(1), G2 = G.homogeneousPart(2), G3 = G.homogeneousPart(3);
  S f2n(0);
  for (const S& v : F2) f2n = std::max<S>(f2n, abs(v));
  if (!(f2n > Tolerance<S>::rank() * F.maxCoeff()))
    throw InvalidInput("Burmester points: the cubic of stationary curvature has no node at the pole (degenerate)");
  // On the line through the pole in direction (c, s): F = ρ³F₃ + ρ²F₂ ⇒ ρ = −F₂/F₃; then
  // G/ρ = ρ²G₃ + ρG₂ + G₁ = 0 times F₃²: F₂²G₃ − F₂F₃G₂ + F₃²G₁ (a binary form of degree 7).
  Poly1<S> t1 = polyMul(polyMul(F2, F2), G3);
  Poly1<S> t2 = polyMul(polyMul(F2, F3), G2);
  for (S& v : t2) v = -v;
  const Poly1<S> t3 = polyMul(polyMul(F3, F3), G1);
  const Poly1<S> form7 = polyAdd(polyAdd(t1, t2), t3);
  BurmesterPoints<S> out;
  out.formDegree = int(form7.size()) - 1;
  S scale(0);
  for (const S& v : form7) scale = std::max<S>(scale, abs(v));
  const Poly1<S> circ{S(1), S(0), S(1)};  // c² + s²
  Poly1<S> rem;
  const Poly1<S> q5 = polyDiv(form7, circ, &rem);
  S rc(0);
  for (const S& v : rem) rc = std::max<S>(rc, abs(v));
  out.circularRemainder = rc / scale;
  Poly1<S> rem2;
  const Poly1<S> q4 = polyDiv(q5, G1, &rem2);
  S rt(0), q5n(0);
  for (const S& v : rem2) rt = std::max<S>(rt, abs(v));
  for (const S& v : q5) q5n = std::max<S>(q5n, abs(v));
  out.tangentRemainder = rt / q5n;
  // Roots of the quartic form in the better-conditioned chart.
  const bool chartS = abs(q4.back()) >= abs(q4.front());
  Poly1<S> uni = q4;
  if (!chartS) std::reverse(uni.begin(), uni.end());
  const std::vector<Cx<S>> m = polynomialRoots(uni);
  const S tolIm = Tolerance<S>::sqrtEpsilon() * S(16);
  for (const Cx<S>& root : m) {
    const Cx<S> c = chartS ? Cx<S>(S(1)) : root, s = chartS ? root : Cx<S>(S(1));
    const Cx<S> rho = -(evalForm(F2, c, s) / evalForm(F3, c, s));
    Cx<S> X = rho * c, Y = rho * s;
    const bool real = abs(root.im) <= tolIm * (S(1) + root.abs());
    if (real) {
      X.im = Y.im = S(0);
      // Newton polishing on (F, G) = 0 in the frame.
      const Poly2<S> Fx = F.dx(), Fy = F.dy(), Gx = G.dx(), Gy = G.dy();
      for (int it = 0; it < 4; ++it) {
        const S f = F(X.re, Y.re), g = G(X.re, Y.re);
        const S a = Fx(X.re, Y.re), b = Fy(X.re, Y.re), cc = Gx(X.re, Y.re), d = Gy(X.re, Y.re);
        const S det = a * d - b * cc;
        if (det == S(0)) break;
        const S nx = X.re - (d * f - b * g) / det, ny = Y.re - (a * g - cc * f) / det;
        if (abs(F(nx, ny)) + abs(G(nx, ny)) < abs(f) + abs(g)) {
          X.re = nx;
          Y.re = ny;
        } else {
          break;
        }
      }
    }
    const S rx = X.re, ry = Y.re;
    out.residuals.push_back(std::max<S>(abs(F(rx, ry)) / F.magnitude(rx, ry), abs(G(rx, ry)) / G.magnitude(rx, ry)));
    // back to the world frame: origin + X ex + Y ey
    out.x.push_back(Cx<S>(fr.origin(0)) + X * fr.ex(0) + Y * fr.ey(0));
    out.y.push_back(Cx<S>(fr.origin(1)) + X * fr.ex(1) + Y * fr.ey(1));
    out.isReal.push_back(real);
    if (real) ++out.realCount;
  }
  return out;
}

// GF §5.3.1, GF-5.3.1-lamina-derivatives (the classical centrodes, erratum E5.9)
template <class S> std::array<Series<S>, 2> fixedCentrode(const MotionJet<S>& jet) {
  const Series<S> w = jet.angle().derivativeSeries();
  if (w.a[0] == S(0)) throw InvalidInput("fixed centrode: ω = 0 (the instantaneous centre is at infinity)");
  const Series<S> xd = jet.x().derivativeSeries(), yd = jet.y().derivativeSeries();
  return {jet.x() - yd / w, jet.y() + xd / w};
}
template <class S> std::array<Series<S>, 2> movingCentrode(const MotionJet<S>& jet) {
  const Series<S> w = jet.angle().derivativeSeries();
  if (w.a[0] == S(0)) throw InvalidInput("moving centrode: ω = 0 (the instantaneous centre is at infinity)");
  const Series<S> vx = -(jet.y().derivativeSeries() / w), vy = jet.x().derivativeSeries() / w;
  Series<S> sn, cs;
  sincos(jet.angle(), sn, cs);
  return {cs * vx + sn * vy, cs * vy - sn * vx};
}

#define SOMA_INSTANTIATE_INSTANT_INVARIANTS(T) namespace planar { \
  template class MotionJet<T>;                                                                       \
  template class InstantInvariants<T>;                                                               \
  template bool curvatureCentre<T>(const Vec2<T>&, const Vec2<T>&, const Vec2<T>&, Vec2<T>&);         \
  template T pathCurvature<T>(const Vec2<T>&, const Vec2<T>&);                                       \
  template Poly2<T> inflectionCurve<T>(const MotionJet<T>&);                                         \
  template Poly2<T> undulationCurve<T>(const MotionJet<T>&);                                         \
  template Poly2<T> stationaryCurvatureCurve<T>(const MotionJet<T>&);                                \
  template Poly2<T> fivePointContactCurve<T>(const MotionJet<T>&);                                   \
  template BurmesterPoints<T> burmesterPoints<T>(const MotionJet<T>&);                               \
  template std::array<Series<T>, 2> fixedCentrode<T>(const MotionJet<T>&);                           \
  template std::array<Series<T>, 2> movingCentrode<T>(const MotionJet<T>&); }

}  // namespace soma::planar
