#pragma once
// Lines in Plücker coordinates (GF §6.1–6.4), the 6-vector form s = (ω; v) ∈ PR⁵.
// Convention A of the catalogue (GF ch. 4, erratum E6.1): v = q × ω for any point q on the line,
// so a line through q₁, q₂ is ω = q₂ − q₁, v = q₁ × q₂, the foot of the perpendicular from the
// origin is ω × v / |ω|², and Ad(R, t) = [[R, 0], [T R, R]] with T x = t × x.
// Lines are homogeneous (s and λs, λ ≠ 0, are the same line; λ < 0 reverses a directed line).
// Lines at infinity are (0; n): the line at infinity of the planes with normal n.
// The Cl(0,3,1) form lives in geometry/pga; screw systems in geometry/screws.
#include "soma/algebra/reciprocal_product.hpp"
#include "soma/algebra/errors.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"

#include <string>

namespace soma {

/// The reciprocal (Klein) bilinear form Q₀: ⟨a, b⟩ = ω_a·v_b + v_a·ω_b. GF §6.4, GF-6.4-pitch-quadrics
template <class S> Mat6<S> kleinFormQ0() {
  Mat6<S> q = Mat6<S>::Zero();
  q.template topRightCorner<3, 3>().setIdentity();
  q.template bottomLeftCorner<3, 3>().setIdentity();
  return q;
}
/// The form Q∞ = diag(−2I₃, 0) (−2 × the Killing-form part ω_a·ω_b). GF §6.4, GF-6.4-pitch-quadrics
template <class S> Mat6<S> kleinFormQinf() {
  Mat6<S> q = Mat6<S>::Zero();
  q.template topLeftCorner<3, 3>() = -S(2) * Mat3<S>::Identity();
  return q;
}
/// Pitch quadric Q_p = α Q∞ + β Q₀ with p = α/β, taken with β = 1: sᵀQ_p s = 2|ω|²(h − p) for a
/// screw of pitch h, so its zero set (off ω = 0) is the screws of pitch p. GF §6.4, GF-6.4-pitch-quadrics
template <class S> Mat6<S> pitchQuadric(const S& p) { return p * kleinFormQinf<S>() + kleinFormQ0<S>(); }


/// Value of the Klein quadric ω·v (= ½ sᵀQ₀s); zero exactly on lines. GF §6.2, GF-6.2-klein-quadric
template <class S> S kleinValue(const Vec6<S>& s) {
  return s.template head<3>().dot(s.template tail<3>());
}

/// |ω·v| / (|ω||v|): the scale-free defect of a 6-vector from the Klein quadric (0 on lines,
/// 0 for (0; v) and (ω; 0)). GF §6.2, GF-6.2-klein-quadric
template <class S> S kleinDefect(const Vec6<S>& s) {
  using std::abs;
  using std::sqrt;
  const S ww = s.template head<3>().squaredNorm(), vv = s.template tail<3>().squaredNorm();
  if (ww == S(0) || vv == S(0)) return S(0);
  return abs(kleinValue(s)) / sqrt(ww * vv);
}

/// A line of PR³ in Plücker coordinates (ω; v), convention A (v = q × ω).
template <class S> class PluckerLine {
 public:
  using Scalar = S;

  /// From raw coordinates. Throws InvalidInput for a NaN/inf, for s = 0, or when s is off the
  /// Klein quadric by more than Tolerance::input() (scale-free, kleinDefect). The coordinates
  /// are stored as given (no silent projection).
  // GF §6.2, GF-6.2-klein-quadric
  PluckerLine(const Vec3<S>& w, const Vec3<S>& v) : w_(w), v_(v) { validate("PluckerLine(ω, v)"); }
  explicit PluckerLine(const Vec6<S>& s) : w_(s.template head<3>()), v_(s.template tail<3>()) {
    validate("PluckerLine(s)");
  }

  /// Line through two points: ω = q₂ − q₁, v = q₁ × q₂ (= q₁ × ω), directed from q₁ to q₂.
  /// Throws when the points coincide to working precision (|q₂ − q₁| ≤ ε·max(|q₁|, |q₂|)).
  // GF §6.2, GF-6.2-plucker-two-points (p_ij = x_i y_j − x_j y_i, erratum E6.2; convention A, E6.1)
  static PluckerLine throughPoints(const Vec3<S>& q1, const Vec3<S>& q2) {
    if (!allFinite(q1) || !allFinite(q2))
      throw InvalidInput("PluckerLine::throughPoints: a point has a NaN or infinite component");
    const Vec3<S> w = q2 - q1;
    const S scale2 = std::max(q1.squaredNorm(), q2.squaredNorm());
    const S e = Tolerance<S>::epsilon();
    if (w.squaredNorm() <= e * e * scale2 || w.squaredNorm() == S(0))
      throw InvalidInput("PluckerLine::throughPoints: the two points coincide (to working precision)");
    return PluckerLine(w, Vec3<S>(q1.cross(q2)), Unchecked{});
  }

  /// Line through the homogeneous points (x₀; x), (y₀; y) (x₀ = 0: a point at infinity):
  /// ω = x₀y − y₀x, v = x × y (p_ij = x_i y_j − x_j y_i). Throws if the points coincide in PR³.
  // GF §6.2 / §6.8, GF-6.2-plucker-two-points, GF-6.8-grassmannian-embedding
  static PluckerLine throughHomogeneousPoints(const Vec4<S>& x, const Vec4<S>& y) {
    if (!allFinite(x) || !allFinite(y))
      throw InvalidInput("PluckerLine::throughHomogeneousPoints: a point has a NaN or infinite component");
    const Vec3<S> xv = x.template tail<3>(), yv = y.template tail<3>();
    const Vec3<S> w = x(0) * yv - y(0) * xv, v = xv.cross(yv);
    const S e = Tolerance<S>::epsilon();
    if (w.squaredNorm() + v.squaredNorm() <= e * e * x.squaredNorm() * y.squaredNorm())
      throw InvalidInput("PluckerLine::throughHomogeneousPoints: the two points coincide in PR³");
    return PluckerLine(w, v, Unchecked{});
  }

  /// Line through q with direction d (any length > 0): ω = d, v = q × d.
  // GF §6.1, GF-6.1-point-line-distance
  static PluckerLine pointDirection(const Vec3<S>& q, const Vec3<S>& d) {
    if (!allFinite(q) || !allFinite(d))
      throw InvalidInput("PluckerLine::pointDirection: q or d has a NaN or infinite component");
    if (d.squaredNorm() == S(0)) throw InvalidInput("PluckerLine::pointDirection: direction d is zero");
    return PluckerLine(d, Vec3<S>(q.cross(d)), Unchecked{});
  }

  /// Intersection of the planes n₁·x + δ₁ = 0 and n₂·x + δ₂ = 0: ω = n₁ × n₂, v = δ₁n₂ − δ₂n₁.
  /// Planes parallel to working precision (|n₁ × n₂| ≤ ε|n₁||n₂|) meet in the line at infinity
  /// (0; δ₁n₂ − δ₂n₁), returned with ω = 0 exactly; identical planes throw.
  // GF §6.3 (β-planes: lines in a plane), GF-6.3-klein-2planes
  static PluckerLine fromPlanes(const Vec3<S>& n1, const S& d1, const Vec3<S>& n2, const S& d2) {
    if (!allFinite(n1) || !allFinite(n2) || !isFinite(d1) || !isFinite(d2))
      throw InvalidInput("PluckerLine::fromPlanes: a plane has a NaN or infinite component");
    if (n1.squaredNorm() == S(0) || n2.squaredNorm() == S(0))
      throw InvalidInput("PluckerLine::fromPlanes: a plane normal is zero");
    Vec3<S> w = n1.cross(n2);
    const Vec3<S> v = d1 * n2 - d2 * n1;
    const S e = Tolerance<S>::epsilon();
    const S nn = n1.squaredNorm() * n2.squaredNorm();
    if (w.squaredNorm() <= e * e * nn) {
      w.setZero();
      const S dd = std::max(d1 * d1 * n2.squaredNorm(), d2 * d2 * n1.squaredNorm());
      if (v.squaredNorm() <= S(16) * e * e * dd || v.squaredNorm() == S(0))
        throw InvalidInput("PluckerLine::fromPlanes: the two planes coincide");
    }
    return PluckerLine(w, v, Unchecked{});
  }

  /// The line at infinity (0; n) of the planes with normal n. GF §6.2, GF-6.2-klein-quadric
  static PluckerLine atInfinity(const Vec3<S>& n) {
    if (!allFinite(n) || n.squaredNorm() == S(0))
      throw InvalidInput("PluckerLine::atInfinity: normal n is zero or not finite");
    return PluckerLine(Vec3<S>::Zero(), n, Unchecked{});
  }

  const Vec3<S>& direction() const { return w_; }
  const Vec3<S>& moment() const { return v_; }
  Vec6<S> coords() const {
    Vec6<S> s;
    s << w_, v_;
    return s;
  }
  /// ω = 0 exactly. Constructors from points and planes decide near-parallel planes relative to
  /// their inputs' scale and return ω = 0 exactly; every other ω ≠ 0 gives finite (maybe huge)
  /// feet and distances. GF §6.2
  bool isAtInfinity() const { return w_.squaredNorm() == S(0); }

  /// Unit direction ω/|ω|. Throws for a line at infinity.
  Vec3<S> unitDirection() const {
    using std::sqrt;
    requireFinite("unitDirection");
    return w_ / sqrt(w_.squaredNorm());
  }
  /// The directed unit representative (ω/|ω|; v/|ω|) (λ > 0 keeps the direction).
  // GF §6.4, GF-6.4-directed-lines
  PluckerLine normalized() const {
    using std::sqrt;
    requireFinite("normalized");
    const S n = sqrt(w_.squaredNorm());
    return PluckerLine(Vec3<S>(w_ / n), Vec3<S>(v_ / n), Unchecked{});
  }
  /// The same line with the opposite orientation (−ω; −v). GF §6.4, GF-6.4-directed-lines
  PluckerLine reversed() const { return PluckerLine(Vec3<S>(-w_), Vec3<S>(-v_), Unchecked{}); }

  /// Foot of the perpendicular from the origin: ω × v / |ω|² (convention A; the book's §6.2
  /// (v × ω)/|ω|² is convention B, E6.1). GF §6.2, GF-6.2-points-on-line
  Vec3<S> foot() const {
    requireFinite("foot");
    return w_.cross(v_) / w_.squaredNorm();
  }
  /// The point foot() + λω. GF §6.2, GF-6.2-points-on-line
  Vec3<S> pointAt(const S& lambda) const { return foot() + lambda * w_; }

  /// Distance from a: |a × ω − v| / |ω|. GF §6.1, GF-6.1-point-line-distance
  S distanceTo(const Vec3<S>& a) const {
    using std::sqrt;
    requireFinite("distanceTo");
    return sqrt((a.cross(w_) - v_).squaredNorm() / w_.squaredNorm());
  }
  /// Nearest point of the line to a: foot + ((a − foot)·ω/|ω|²) ω (equals the book's
  /// a + ω × ((q₁ − a) × ω)/|ω|²). GF §6.1, GF-6.1-point-line-distance
  Vec3<S> closestPoint(const Vec3<S>& a) const {
    const Vec3<S> f = foot();
    return f + ((a - f).dot(w_) / w_.squaredNorm()) * w_;
  }
  /// a lies on the line to working precision: |a × ω − v|² ≤ tol²|ω|²(|a|² + |foot|²).
  /// A finite point never lies on a line at infinity.
  bool contains(const Vec3<S>& a, const S& tol = Tolerance<S>::identity()) const {
    if (isAtInfinity()) return false;
    const S r2 = (a.cross(w_) - v_).squaredNorm();
    return r2 <= tol * tol * w_.squaredNorm() * (a.squaredNorm() + foot().squaredNorm());
  }

  /// The line moved by g: Ad(g) s (= line through R q + t with direction R ω).
  // GF §6.4, GF-6.4-adjoint-on-lines (T x = t × x, convention A, E6.1)
  PluckerLine transformed(const SE3<S>& g) const {
    const Mat3<S> r = g.rotation();
    const Vec3<S> w = r * w_;
    return PluckerLine(w, Vec3<S>(r * v_ + g.translation().cross(w)), Unchecked{});
  }

  /// Same line (any nonzero scale, including negative: rank [s_a s_b] = 1), to tolerance tol
  /// relative to |s_a||s_b|. GF §6.1, GF-6.1-same-line
  bool sameAs(const PluckerLine& o, const S& tol = Tolerance<S>::identity()) const {
    // |s_a ∧ s_b|² = Σ_{i<j} (a_i b_j − a_j b_i)², summed term by term: the Gram form
    // |a|²|b|² − (a·b)² cancels catastrophically (rounding ε|a|²|b|² ≫ tol²|a|²|b|²).
    const Vec6<S> a = coords(), b = o.coords();
    S w2(0);
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j) {
        const S t = a(i) * b(j) - a(j) * b(i);
        w2 += t * t;
      }
    return w2 <= tol * tol * a.squaredNorm() * b.squaredNorm();
  }

  template <class T> PluckerLine<T> cast() const {
    return PluckerLine<T>(castMatrix<T>(w_), castMatrix<T>(v_));
  }

 private:
  struct Unchecked {};
  PluckerLine(const Vec3<S>& w, const Vec3<S>& v, Unchecked) : w_(w), v_(v) {}
  template <class T> friend class PluckerLine;

  void validate(const char* who) const {
    if (!allFinite(w_) || !allFinite(v_))
      throw InvalidInput(std::string(who) + ": a coordinate is NaN or infinite");
    if (w_.squaredNorm() == S(0) && v_.squaredNorm() == S(0))
      throw InvalidInput(std::string(who) + ": the zero 6-vector is not a line");
    if (kleinDefect(coords()) > Tolerance<S>::input())
      throw InvalidInput(std::string(who) + ": not on the Klein quadric (ω·v/(|ω||v|) = " +
                         toString(kleinDefect(coords())) + ")");
  }
  void requireFinite(const char* what) const {
    if (isAtInfinity())
      throw InvalidInput(std::string("PluckerLine::") + what + ": the line is at infinity (ω = 0)");
  }

  Vec3<S> w_, v_;
};

/// How two lines lie. GF §6.1, §6.4, §9.4
enum class LineRelationKind { Skew, Intersecting, Parallel, Coincident, AtInfinity };

/// The relative position of two finite lines a, b (GF §6.1, GF-6.1-meet-condition,
/// GF-6.4-reciprocal-product-example, GF-9.4-common-perpendicular-dual-angle):
/// angle α = atan2(|u_a × u_b|, u_a·u_b) ∈ [0, π] between the unit directions; for non-parallel
/// lines the common perpendicular along n = u_a × u_b/|…| from footA (on a) to footB (on b) and the
/// signed distance d = (footB − footA)·n, so that for unit lines ⟨a, b⟩ = −d sin α.
/// Parallel when sin α ≤ √ε (beyond that the common perpendicular's feet are not determined to
/// better than |q|·√ε); then distance is the distance between the parallel lines and footA is
/// a's foot from the origin, footB its projection on b.
template <class S> struct LineRelation {
  LineRelationKind kind = LineRelationKind::Skew;
  S angle{0};
  S distance{0};        ///< ≥ 0
  S signedDistance{0};  ///< along n (non-parallel); = distance for parallel lines
  Vec3<S> footA{Vec3<S>::Zero()}, footB{Vec3<S>::Zero()};
  Vec3<S> perpendicularDirection{Vec3<S>::Zero()};  ///< unit n (zero for parallel lines)
  /// The common perpendicular as a line (direction n through footA); only when not parallel.
  PluckerLine<S> commonPerpendicular() const { return PluckerLine<S>::pointDirection(footA, perpendicularDirection); }
};

/// Relative position of two lines; at least one at infinity gives kind AtInfinity (angle and
/// distance undefined, zero). Intersecting when |d| sin α ≤ Tolerance::identity()·(|q_a|+|q_b|)
/// (the rounding level of the reciprocal product); Coincident parallel lines when the distance is
/// at that level. GF §6.1, GF-6.1-meet-condition; GF §9.4, GF-9.4-common-perpendicular-dual-angle
template <class S> LineRelation<S> relation(const PluckerLine<S>& a, const PluckerLine<S>& b);

/// Distance between two lines (0 for intersecting). Throws for a line at infinity.
template <class S> S distance(const PluckerLine<S>& a, const PluckerLine<S>& b);
/// Angle in [0, π] between the directed lines. Throws for a line at infinity.
template <class S> S angle(const PluckerLine<S>& a, const PluckerLine<S>& b);
/// The lines meet (possibly at infinity: parallel lines meet at infinity, GF §6.1): the
/// reciprocal product is 0 to tol·(|ω_a||v_b| + |v_a||ω_b|). GF §6.1, GF-6.1-meet-condition
template <class S> bool meet(const PluckerLine<S>& a, const PluckerLine<S>& b, const S& tol = Tolerance<S>::identity());

/// Ad(g) as the 6×6 matrix [[R, 0], [T R, R]] acting on Plücker coordinates (reuses SE3::adjoint).
// GF §6.4, GF-6.4-adjoint-on-lines
template <class S> Mat6<S> lineAction(const SE3<S>& g) { return g.adjoint(); }

// ---- implementation ---------------------------------------------------------------------------
template <class S> LineRelation<S> relation(const PluckerLine<S>& a, const PluckerLine<S>& b) {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  LineRelation<S> r;
  if (a.isAtInfinity() || b.isAtInfinity()) {
    r.kind = LineRelationKind::AtInfinity;
    return r;
  }
  const Vec3<S> ua = a.unitDirection(), ub = b.unitDirection();
  const Vec3<S> c = ua.cross(ub);
  const S s2 = c.squaredNorm();
  const S sinA = sqrt(s2);
  r.angle = atan2(sinA, ua.dot(ub));
  const Vec3<S> qa = a.foot(), qb = b.foot();
  const S scale = sqrt(qa.squaredNorm()) + sqrt(qb.squaredNorm());
  const S tolId = Tolerance<S>::identity();
  if (s2 <= Tolerance<S>::epsilon()) {  // sin α ≤ √ε: parallel
    const Vec3<S> dq = qb - qa;
    const Vec3<S> perp = dq - dq.dot(ua) * ua;
    r.distance = sqrt(perp.squaredNorm());
    r.signedDistance = r.distance;
    r.footA = qa;
    r.footB = b.closestPoint(qa);
    r.kind = r.distance <= tolId * scale ? LineRelationKind::Coincident : LineRelationKind::Parallel;
    return r;
  }
  const Vec3<S> rr = qb - qa;
  const S ta = rr.cross(ub).dot(c) / s2, tb = rr.cross(ua).dot(c) / s2;
  r.footA = qa + ta * ua;
  r.footB = qb + tb * ub;
  r.perpendicularDirection = c / sinA;
  // Signed distance from the reciprocal product of the unit lines: ⟨â, b̂⟩ = −d sin α.
  const S recip = reciprocalProduct(a.normalized().coords(), b.normalized().coords());
  r.signedDistance = -recip / sinA;
  r.distance = abs(r.signedDistance);
  r.kind = abs(recip) <= tolId * scale ? LineRelationKind::Intersecting : LineRelationKind::Skew;
  if (r.kind == LineRelationKind::Intersecting) {
    r.footB = r.footA = (r.footA + r.footB) / S(2);
  }
  return r;
}

template <class S> S distance(const PluckerLine<S>& a, const PluckerLine<S>& b) {
  if (a.isAtInfinity() || b.isAtInfinity())
    throw InvalidInput("distance(PluckerLine, PluckerLine): a line is at infinity");
  return relation(a, b).distance;
}
template <class S> S angle(const PluckerLine<S>& a, const PluckerLine<S>& b) {
  if (a.isAtInfinity() || b.isAtInfinity())
    throw InvalidInput("angle(PluckerLine, PluckerLine): a line is at infinity");
  return relation(a, b).angle;
}
template <class S> bool meet(const PluckerLine<S>& a, const PluckerLine<S>& b, const S& tol) {
  using std::abs;
  using std::sqrt;
  const S wa = sqrt(a.direction().squaredNorm()), wb = sqrt(b.direction().squaredNorm());
  const S va = sqrt(a.moment().squaredNorm()), vb = sqrt(b.moment().squaredNorm());
  return abs(reciprocalProduct(a.coords(), b.coords())) <= tol * (wa * vb + va * wb);
}

#define SOMA_LINE_EXTERN(S)                                                           \
  extern template class PluckerLine<S>;                                                      \
  extern template LineRelation<S> relation<S>(const PluckerLine<S>&, const PluckerLine<S>&);        \
  extern template S distance<S>(const PluckerLine<S>&, const PluckerLine<S>&);                      \
  extern template S angle<S>(const PluckerLine<S>&, const PluckerLine<S>&);                         \
  extern template bool meet<S>(const PluckerLine<S>&, const PluckerLine<S>&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_LINE_EXTERN)
#undef SOMA_LINE_EXTERN

using Lined = PluckerLine<double>;

}  // namespace soma
