// The planar 4-bar (GF §5.4), explicitly instantiated for one scalar (soma_instantiate).
#pragma once
#include "soma/geometry/planar/fourbar.hpp"

#include <algorithm>
#include <cmath>

namespace soma::planar {

namespace {
template <class S> Vec2<S> E2(const Vec2<S>& v) { return Vec2<S>(v(1), -v(0)); }
template <class S> S sgn(const S& x) { return x < S(0) ? S(-1) : S(1); }
}  // namespace

template <class S>
FourBar<S>::FourBar(const Vec2<S>& c1, const Vec2<S>& c4, const S& crank, const S& coupler, const S& rocker,
                    const Vec2<S>& couplerPoint)
    : c1_(c1), c4_(c4), pc_(couplerPoint), l1_(crank), l2_(coupler), l3_(rocker) {
  using std::atan2;
  using std::sqrt;
  if (!allFinite(c1) || !allFinite(c4) || !allFinite(couplerPoint) || !isFinite(crank) || !isFinite(coupler) ||
      !isFinite(rocker))
    throw InvalidInput("4-bar: a pivot, a length or the coupler point is NaN or infinite");
  if (!(crank > S(0)) || !(coupler > S(0)) || !(rocker > S(0)))
    throw InvalidInput("4-bar: link lengths must be positive (crank " + toString(crank) + ", coupler " +
                       toString(coupler) + ", rocker " + toString(rocker) + ")");
  l0_ = sqrt((c4 - c1).squaredNorm());
  if (!(l0_ > Tolerance<S>::rank() * (l1_ + l2_ + l3_)))
    throw InvalidInput("4-bar: the ground pivots c1 and c4 coincide");
  gamma_ = atan2(c4(1) - c1(1), c4(0) - c1(0));
  const Range r = range();
  const S kLo = (l0_ * l0_ + l1_ * l1_ - (l2_ + l3_) * (l2_ + l3_)) / (S(2) * l0_ * l1_);
  const S kHi = (l0_ * l0_ + l1_ * l1_ - (l2_ - l3_) * (l2_ - l3_)) / (S(2) * l0_ * l1_);
  if (r.A > r.B || kLo > S(1) + Tolerance<S>::rank() || kHi < S(-1) - Tolerance<S>::rank())
    throw InvalidInput("4-bar: cannot be assembled at any crank angle (ground " + toString(l0_) + ", crank " +
                       toString(l1_) + ", coupler " + toString(l2_) + ", rocker " + toString(l3_) +
                       "): the longest link exceeds the sum of the other three");
}

template <class S>
FourBar<S> FourBar<S>::fromJoints(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4,
                                  const Vec2<S>& pw) {
  using std::sqrt;
  const S l2 = sqrt((c3 - c2).squaredNorm());
  if (!(l2 > S(0))) throw InvalidInput("4-bar from joints: c2 and c3 coincide");
  const Vec2<S> ex = (c3 - c2) / l2, ey = perp(ex);
  const Vec2<S> pc((pw - c2).dot(ex), (pw - c2).dot(ey));
  return FourBar(c1, c4, sqrt((c2 - c1).squaredNorm()), l2, sqrt((c3 - c4).squaredNorm()), pc);
}

// GF §5.4 (Grashof's rule is standard; the book names the 4-bar only)
template <class S> GrashofClass<S> FourBar<S>::classify() const {
  using std::abs;
  const S L[4] = {l0_, l1_, l2_, l3_};
  GrashofClass<S> g;
  for (int i = 1; i < 4; ++i) {
    if (L[i] < L[g.shortest]) g.shortest = i;
    if (L[i] > L[g.longest]) g.longest = i;
  }
  const S total = L[0] + L[1] + L[2] + L[3];
  g.margin = total - S(2) * (L[g.shortest] + L[g.longest]);
  const S tol = Tolerance<S>::rank() * total;
  auto eq = [&](const S& a, const S& b) { return abs(a - b) <= tol; };
  g.parallelogram = eq(l0_, l2_) && eq(l1_, l3_);
  g.deltoid = (eq(l0_, l1_) && eq(l2_, l3_)) || (eq(l0_, l3_) && eq(l1_, l2_));
  if (abs(g.margin) <= tol) g.type = GrashofType::ChangePoint;
  else if (g.margin < S(0)) g.type = GrashofType::TripleRocker;
  else {
    static const GrashofType byShortest[4] = {GrashofType::DoubleCrank, GrashofType::CrankRocker,
                                              GrashofType::DoubleRocker, GrashofType::RockerCrank};
    g.type = byShortest[g.shortest];
  }
  g.crankRotates = range().kind == 0;
  return g;
}

template <class S> typename FourBar<S>::Range FourBar<S>::range() const {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  // |c4 − c2|² = l0² + l1² − 2 l0 l1 cos α must lie in [(l2 − l3)², (l2 + l3)²].
  Range r;
  const S total = l0_ + l1_ + l2_ + l3_;
  const S tol = Tolerance<S>::rank() * total;
  const S kLo = (l0_ * l0_ + l1_ * l1_ - (l2_ + l3_) * (l2_ + l3_)) / (S(2) * l0_ * l1_);
  const S kHi = (l0_ * l0_ + l1_ * l1_ - (l2_ - l3_) * (l2_ - l3_)) / (S(2) * l0_ * l1_);
  const S d0 = abs(l0_ - l1_) - abs(l2_ - l3_);
  const S dPi = (l0_ + l1_) - (l2_ + l3_);
  r.nodeAt0 = abs(d0) <= tol;
  r.nodeAtPi = abs(dPi) <= tol;
  const S pi_ = pi<S>();
  r.A = (r.nodeAt0 || kHi >= S(1)) ? S(0) : atan2(sqrt(S(1) - kHi * kHi), kHi);
  r.B = (r.nodeAtPi || kLo <= S(-1)) ? pi_ : atan2(sqrt(std::max<S>(S(0), S(1) - kLo * kLo)), kLo);
  if (r.A == S(0) && r.B == pi_) r.kind = 0;
  else if (r.A == S(0)) r.kind = 1;
  else if (r.B == pi_) r.kind = 2;
  else r.kind = 3;
  if (r.kind == 1) r.nodeAtPi = false;
  if (r.kind == 2) r.nodeAt0 = false;
  if (r.kind == 3) r.nodeAt0 = r.nodeAtPi = false;
  return r;
}

template <class S> FourBarPose<S> FourBar<S>::poseAt(const S& alpha, const S& hSign) const {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  FourBarPose<S> p;
  p.theta1 = gamma_ + alpha;
  p.c2 = c1_ + l1_ * Vec2<S>(cos(p.theta1), sin(p.theta1));
  const Vec2<S> d = c4_ - p.c2;
  const S dn = sqrt(d.squaredNorm());
  if (!(dn > S(0))) throw InvalidInput("4-bar: the crank pin c2 is on the ground pivot c4 (the rocker is free)");
  const S a = (dn * dn + l2_ * l2_ - l3_ * l3_) / (S(2) * dn);
  const S h2 = l2_ * l2_ - a * a;
  p.h = hSign * sqrt(std::max<S>(S(0), h2));
  const Vec2<S> e = d / dn;
  p.c3 = p.c2 + a * e + p.h * perp(e);
  p.mode = p.h > S(0) ? 1 : (p.h < S(0) ? -1 : 0);
  p.psi = atan2(p.c3(1) - p.c2(1), p.c3(0) - p.c2(0));
  p.theta4 = atan2(p.c3(1) - c4_(1), p.c3(0) - c4_(0));
  p.coupler = SE2<S>(p.psi, p.c2);
  return p;
}

template <class S> std::optional<FourBarPose<S>> FourBar<S>::solve(const S& theta1, int mode) const {
  using std::cos;
  using std::sin;
  if (!isFinite(theta1)) throw InvalidInput("4-bar: crank angle is NaN or infinite");
  if (mode != 1 && mode != -1) throw InvalidInput("4-bar: assembly mode must be +1 or −1");
  const Vec2<S> c2 = c1_ + l1_ * Vec2<S>(cos(theta1), sin(theta1));
  const S dn2 = (c4_ - c2).squaredNorm();
  const S total = l0_ + l1_ + l2_ + l3_;
  const S tol = Tolerance<S>::rank() * total * total;
  // feasibility: (l2 − l3)² ≤ dn² ≤ (l2 + l3)²
  if (dn2 > (l2_ + l3_) * (l2_ + l3_) + tol || dn2 < (l2_ - l3_) * (l2_ - l3_) - tol) return std::nullopt;
  return poseAt(theta1 - gamma_, S(mode));
}

template <class S> int FourBar<S>::circuitCount() const {
  const Range r = range();
  if (r.kind == 0) return (r.nodeAt0 != r.nodeAtPi) ? 1 : 2;
  return r.kind == 3 ? 2 : 1;
}

template <class S> S FourBar<S>::circuitPeriod(int circuit) const {
  if (circuit < 0 || circuit >= circuitCount()) throw InvalidInput("4-bar: no circuit " + std::to_string(circuit));
  const Range r = range();
  return (r.kind == 0 && r.nodeAt0 != r.nodeAtPi) ? S(4) * pi<S>() : S(2) * pi<S>();
}

template <class S> FourBarPose<S> FourBar<S>::circuitPose(int circuit, const S& s) const {
  using std::cos;
  using std::sin;
  if (circuit < 0 || circuit >= circuitCount()) throw InvalidInput("4-bar: no circuit " + std::to_string(circuit));
  const Range r = range();
  const S pi_ = pi<S>();
  const S side = circuit == 0 ? S(1) : S(-1);
  switch (r.kind) {
    case 0:
      if (!r.nodeAt0 && !r.nodeAtPi) return poseAt(s, side);
      if (r.nodeAt0 && r.nodeAtPi) return poseAt(s, side * sgn(sin(s)));
      return poseAt((r.nodeAt0 ? S(0) : pi_) + s, sgn(sin(s / S(2))));  // one node: a figure eight
    case 1: return poseAt(r.B * sin(s), sgn(cos(s)) * (r.nodeAt0 ? sgn(sin(s)) : S(1)));
    case 2: return poseAt(pi_ + (pi_ - r.A) * sin(s), sgn(cos(s)) * (r.nodeAtPi ? sgn(sin(s)) : S(1)));
    default: {
      const S m = (r.A + r.B) / S(2), w = (r.B - r.A) / S(2);
      return poseAt(side * (m + w * sin(s)), sgn(cos(s)));
    }
  }
}

template <class S> std::vector<FourBarPose<S>> FourBar<S>::traceCircuit(int circuit, int samples) const {
  if (samples < 2) throw InvalidInput("4-bar: need at least 2 samples per circuit");
  const S T = circuitPeriod(circuit);
  std::vector<FourBarPose<S>> out;
  out.reserve(samples);
  for (int k = 0; k < samples; ++k) out.push_back(circuitPose(circuit, T * S(k) / S(samples)));
  return out;
}

template <class S> int FourBar<S>::circuitOf(const FourBarPose<S>& p) const {
  using std::atan2;
  using std::cos;
  using std::sin;
  const Range r = range();
  const S alpha = atan2(sin(p.theta1 - gamma_), cos(p.theta1 - gamma_));
  switch (r.kind) {
    case 0:
      if (!r.nodeAt0 && !r.nodeAtPi) return p.h >= S(0) ? 0 : 1;
      if (r.nodeAt0 && r.nodeAtPi) return p.h * sin(alpha) >= S(0) ? 0 : 1;
      return 0;
    case 3: return alpha > S(0) ? 0 : 1;
    default: return 0;
  }
}

template <class S> std::vector<std::pair<S, S>> FourBar<S>::crankIntervals() const {
  const Range r = range();
  const S pi_ = pi<S>();
  switch (r.kind) {
    case 0: return {};
    case 1: return {{gamma_ - r.B, gamma_ + r.B}};
    case 2: return {{gamma_ + r.A, gamma_ + S(2) * pi_ - r.A}};
    default: return {{gamma_ + r.A, gamma_ + r.B}, {gamma_ - r.B, gamma_ - r.A}};
  }
}

// GF §5.4, GF-5.4-coupler-curves-and-invariants: the coupler motion's jet by Taylor arithmetic
// through the closed-form position analysis.
template <class S>
MotionJet<S> FourBar<S>::couplerJet(const S& theta1, int mode, const std::array<S, kJetSize>& law) const {
  if (mode != 1 && mode != -1) throw InvalidInput("4-bar: assembly mode must be +1 or −1");
  std::array<S, kJetSize> l = law;
  l[0] = theta1;
  const Series<S> th = Series<S>::fromDerivatives(l);
  Series<S> sn, cs;
  sincos(th, sn, cs);
  const Series<S> c2x = cs * l1_ + c1_(0), c2y = sn * l1_ + c1_(1);
  const Series<S> dx = Series<S>(c4_(0)) - c2x, dy = Series<S>(c4_(1)) - c2y;
  const Series<S> d2 = dx * dx + dy * dy;
  const Series<S> dn = sqrt(d2);
  const Series<S> a = (d2 + (l2_ * l2_ - l3_ * l3_)) / (dn * S(2));
  const Series<S> h2 = Series<S>(l2_ * l2_) - a * a;
  Series<S> h;
  try {
    h = sqrt(h2) * S(mode);
  } catch (const InvalidInput&) {
    throw InvalidInput("4-bar coupler jet at θ₁ = " + toString(theta1) +
                       ": a branch point (c2, c3, c4 collinear) or not assemblable; the motion is not smooth in θ₁ here");
  }
  const Series<S> ex = dx / dn, ey = dy / dn;
  const Series<S> c3x = c2x + a * ex - h * ey, c3y = c2y + a * ey + h * ex;
  const Series<S> psi = atan2(c3y - c2y, c3x - c2x);
  return MotionJet<S>(psi, c2x, c2y);
}

// GF §5.4 (coupler curves): eliminate ψ from |P + R(ψ)u − c1|² = l1², |P + R(ψ)w − c4|² = l3².
template <class S> Poly2<S> FourBar<S>::couplerCurve() const {
  const Vec2<S> u = -pc_, w = Vec2<S>(l2_, S(0)) - pc_;
  auto lin = [](const Vec2<S>& c, const Vec2<S>& q) {  // (P − c)·q
    return Poly2<S>::affine(-c.dot(q), q(0), q(1));
  };
  auto quad = [](const Vec2<S>& c) {  // |P − c|²
    const Poly2<S> X = Poly2<S>::affine(-c(0), S(1), S(0)), Y = Poly2<S>::affine(-c(1), S(0), S(1));
    return X * X + Y * Y;
  };
  const Poly2<S> A1 = lin(c1_, u) * S(2), B1 = lin(c1_, perp(u)) * S(2);
  const Poly2<S> C1 = Poly2<S>(l1_ * l1_ - u.squaredNorm()) - quad(c1_);
  const Poly2<S> A2 = lin(c4_, w) * S(2), B2 = lin(c4_, perp(w)) * S(2);
  const Poly2<S> C2 = Poly2<S>(l3_ * l3_ - w.squaredNorm()) - quad(c4_);
  const Poly2<S> cn = C1 * B2 - C2 * B1, sn = A1 * C2 - A2 * C1, D = A1 * B2 - A2 * B1;
  return cn * cn + sn * sn - D * D;
}

// GF §5.4, GF-5.4-fourbar-instant-centre
template <class S>
Vec3<S> FourBar<S>::instantCentre(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4) {
  const Vec3<S> l1 = Vec3<S>(c1(0), c1(1), S(1)).cross(Vec3<S>(c2(0), c2(1), S(1)));
  const Vec3<S> l2 = Vec3<S>(c4(0), c4(1), S(1)).cross(Vec3<S>(c3(0), c3(1), S(1)));
  return l1.cross(l2);
}

// GF §5.4, GF-5.4-fourbar-velocity-ratios
template <class S>
std::pair<S, S> FourBar<S>::velocityRatios(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4) {
  using std::abs;
  using std::sqrt;
  const S den = cross2<S>(c3 - c4, c3 - c2);
  if (!(abs(den) > Tolerance<S>::rank() * sqrt((c3 - c4).squaredNorm() * (c3 - c2).squaredNorm())))
    throw InvalidInput("4-bar velocity ratios: coupler and rocker are collinear (a dead centre: the ratios are infinite)");
  return {cross2<S>(c3 - c4, c1 - c2) / den, cross2<S>(c2 - c3, c1 - c2) / cross2<S>(c3 - c2, c3 - c4)};
}

// GF §5.4, GF-5.4-fourbar-angular-acceleration (the final formula is correct; E5.17 is in the text)
template <class S>
S FourBar<S>::omegaDot(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4, const S& w1,
                       const S& w1dot) {
  const S D = cross2<S>(c2 - c3, c3 - c4);
  if (D == S(0)) throw InvalidInput("4-bar ω̇: D = 0 (dead centre)");
  const S p = cross2<S>(c1 - c2, c2 - c3), q = cross2<S>(c1 - c2, c3 - c4);
  return w1dot * cross2<S>(c3 - c4, c1 - c2) / D +
         w1 * w1 / (D * D * D) *
             ((c3 - c4).dot(c1 - c2) * D * D + (c3 - c4).squaredNorm() * p * p + (c2 - c3).dot(c3 - c4) * q * q);
}

// GF §5.4, GF-5.4-fourbar-pole-velocity
template <class S>
Vec2<S> FourBar<S>::poleVelocity(const Vec2<S>& ca, const Vec2<S>& cb, const S& w, const S& wdot, const S& wi,
                                 const S& widot) {
  if (w == S(0)) throw InvalidInput("4-bar pole velocity: ω = 0 (division by 2ω²)");
  const Vec2<S> d = cb - ca;
  return ((wdot * wi - w * widot) * d + (w * wi * wi - w * w * wi) * E2(d)) / (S(2) * w * w);
}

#define SOMA_INSTANTIATE_FOURBAR(T) namespace planar { template class FourBar<T>; }

}  // namespace soma::planar
