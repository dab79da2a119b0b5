#pragma once
// Ruled surfaces as curves on the Klein quadric (GF §6.5, §9.4): λ ↦ s(λ) = (ω(λ); v(λ)) with
// its derivative s'(λ). Striction (central) point, distribution parameter and the dual Frenet
// frame (l, n, t) of §9.4. Lines as unit dual vectors l̂ = u + ε m (|u| = 1, u·m = 0) with the
// dual dot and cross products, the dual angle α + εd of two lines and their common perpendicular.
#include "soma/algebra/dual_quaternion.hpp"
#include "soma/geometry/lines/screw_axis.hpp"

#include <functional>

namespace soma {

// ---- dual vectors (GF §9.4) -------------------------------------------------------------------

/// A dual vector a + εb (a line (u; m) when |u| = 1, u·m = 0). GF §9.4, GF-9.4-lines-as-dual-vectors
template <class S> struct DualVec3 {
  Vec3<S> re{Vec3<S>::Zero()}, du{Vec3<S>::Zero()};
  static DualVec3 of(const PluckerLine<S>& l) {
    const PluckerLine<S> u = l.normalized();
    return {u.direction(), u.moment()};
  }
  static DualVec3 of(const Vec6<S>& s) { return {s.template head<3>(), s.template tail<3>()}; }
  Vec6<S> coords() const {
    Vec6<S> s;
    s << re, du;
    return s;
  }
  /// (a + εb)·(c + εd) = a·c + ε(a·d + b·c). GF §9.4
  DualNumber<S> dot(const DualVec3& o) const { return {re.dot(o.re), re.dot(o.du) + du.dot(o.re)}; }
  /// (a + εb) × (c + εd) = a × c + ε(a × d + b × c). GF §9.4
  DualVec3 cross(const DualVec3& o) const {
    return {re.cross(o.re), Vec3<S>(re.cross(o.du) + du.cross(o.re))};
  }
};

/// Dual angle α + εd between two directed lines (α ∈ [0, π] from atan2 of the dual sine and
/// cosine, d signed along n = u₁ × u₂ — the same d as relation()). For parallel lines
/// (sin α ≤ √ε) the dual sine is pure dual and d = |dual part| ≥ 0.
// GF §9.4, GF-9.4-common-perpendicular-dual-angle
template <class S> DualNumber<S> dualAngle(const PluckerLine<S>& a, const PluckerLine<S>& b) {
  using std::atan2;
  using std::sqrt;
  const DualVec3<S> la = DualVec3<S>::of(a), lb = DualVec3<S>::of(b);
  const DualVec3<S> c = la.cross(lb);
  const DualNumber<S> co = la.dot(lb);
  const S c0sq = c.re.squaredNorm();
  const S c0 = sqrt(c0sq);
  const S alpha = atan2(c0, co.re);
  if (c0sq <= Tolerance<S>::epsilon()) return {alpha, sqrt(c.du.squaredNorm())};
  const S c1 = c.re.dot(c.du) / c0;  // dual part of |c|: d cos α
  return {alpha, (co.re * c1 - c0 * co.du) / (c0sq + co.re * co.re)};
}

/// Common perpendicular of two non-parallel lines as the unit dual vector ň = (l₁ × l₂)/|l₁ × l₂|
/// (dual division). Throws for parallel lines (sin α ≤ √ε). GF §9.4, GF-9.4-common-perpendicular-dual-angle
template <class S> PluckerLine<S> commonPerpendicularDual(const PluckerLine<S>& a, const PluckerLine<S>& b) {
  using std::sqrt;
  const DualVec3<S> c = DualVec3<S>::of(a).cross(DualVec3<S>::of(b));
  const S c0sq = c.re.squaredNorm();
  if (c0sq <= Tolerance<S>::epsilon())
    throw InvalidInput("commonPerpendicularDual: the lines are parallel (no unique common perpendicular)");
  const S c0 = sqrt(c0sq), c1 = c.re.dot(c.du) / c0;
  // (c.re + ε c.du)/(c0 + ε c1) = c.re/c0 + ε (c.du c0 − c.re c1)/c0²; built through its foot
  // u × m so that a perpendicular passing near the origin stays exactly a line.
  const Vec3<S> u = c.re / c0, m = (c.du * c0 - c.re * c1) / c0sq;
  return PluckerLine<S>::pointDirection(Vec3<S>(u.cross(m)), u);
}

// ---- ruled surfaces ---------------------------------------------------------------------------

/// Invariants of a ruled surface at one generator (GF §9.4, GF-9.4-striction-and-dual-frenet):
/// κ̌ = κ₀ + εκ₁ with dl̂/dλ = κ̌ň, the central normal ň (unit line through the striction point,
/// direction u'/|u'|), the central tangent ť = l̂ × ň, and the distribution parameter κ₁/κ₀.
template <class S> struct RuledFrame {
  PluckerLine<S> l, n, t;
  S kappa0{0}, kappa1{0};
  Vec3<S> striction{Vec3<S>::Zero()};
  S distributionParameter{0};
};

template <class S> class RuledSurface {
 public:
  using Curve = std::function<Vec6<S>(const S&)>;
  /// A curve s(λ) on the Klein quadric (any scale, ω ≠ 0) and its derivative s'(λ).
  // GF §6.5, GF-6.5.2-fixed-axode; GF §9.4, GF-9.4-lines-as-dual-vectors
  RuledSurface(Curve s, Curve ds) : s_(std::move(s)), ds_(std::move(ds)) {}

  /// From a directrix r(λ) and a direction field u(λ) (with derivatives): s = (u; r × u).
  // GF §9.4, GF-9.4-lines-as-dual-vectors
  static RuledSurface fromDirectrix(std::function<Vec3<S>(const S&)> r, std::function<Vec3<S>(const S&)> dr,
                                    std::function<Vec3<S>(const S&)> u, std::function<Vec3<S>(const S&)> du) {
    return RuledSurface(
        [=](const S& x) {
          const Vec3<S> uu = u(x);
          Vec6<S> s;
          s << uu, Vec3<S>(r(x).cross(uu));
          return s;
        },
        [=](const S& x) {
          const Vec3<S> uu = u(x), duu = du(x), rr = r(x), drr = dr(x);
          Vec6<S> s;
          s << duu, Vec3<S>(drr.cross(uu) + rr.cross(duu));
          return s;
        });
  }
  /// The orbit of a line under the one-parameter subgroup exp(λξ): s(λ) = Ad(exp(λξ)) l₀,
  /// s'(λ) = ad(ξ) s(λ). A pure rotation about a line not meeting l₀ sweeps a regulus, a
  /// finite-pitch screw a ruled helicoid. GF §6.5.1, GF-6.5.1-conic-to-quadric; GF §9.4, GF-9.4-ruled-helicoid
  static RuledSurface sweep(const Vec6<S>& xi, const PluckerLine<S>& l0) {
    const Vec6<S> s0 = l0.coords();
    return RuledSurface(
        [=](const S& x) { return Vec6<S>(SE3Tangent<S>(Vec6<S>(xi * x)).exp().adjoint() * s0); },
        [=](const S& x) {
          const Vec6<S> s = SE3Tangent<S>(Vec6<S>(xi * x)).exp().adjoint() * s0;
          return Vec6<S>(SE3Tangent<S>(xi).ad() * s);
        });
  }

  Vec6<S> coords(const S& lambda) const { return s_(lambda); }
  Vec6<S> derivative(const S& lambda) const { return ds_(lambda); }
  /// The unit generator l̂(λ) and the derivative of the unit curve l̂'(λ).
  PluckerLine<S> generator(const S& lambda) const { return PluckerLine<S>(s_(lambda)).normalized(); }
  Vec6<S> unitDerivative(const S& lambda) const;

  /// |u'| ≤ √ε·|l̂'|: the generators are (locally) parallel — a cylinder; the striction point is
  /// then undefined. GF §9.4 (non-cylindric ⇔ du/dλ ≠ 0)
  bool isCylindrical(const S& lambda) const;

  /// Striction (central) point: on l̂ = (u; m) with foot r = u × m, s = r − (r'·u')/(u'·u') u.
  /// Throws on a cylindrical generator. GF §9.4, GF-9.4-striction-and-dual-frenet
  Vec3<S> strictionPoint(const S& lambda) const;
  /// Distribution parameter det[u, u', r']/|u'|² (classical form). GF §9.4, GF-9.4-striction-and-dual-frenet
  S distributionParameter(const S& lambda) const;
  /// Second method: pitch and axis of the derivative screw l̂' — its pitch is the distribution
  /// parameter and its axis the central normal ň, meeting l̂ at the striction point.
  /// GF §9.4, GF-9.4-striction-and-dual-frenet (dl̂/dλ = κ̌ň)
  RuledFrame<S> frame(const S& lambda) const;

 private:
  Curve s_, ds_;
};

template <class S> Vec6<S> RuledSurface<S>::unitDerivative(const S& lambda) const {
  using std::sqrt;
  const Vec6<S> s = s_(lambda), ds = ds_(lambda);
  const S ww = s.template head<3>().squaredNorm();
  if (ww == S(0)) throw InvalidInput("RuledSurface: the generator is at infinity");
  const S n = sqrt(ww);
  const S wdw = s.template head<3>().dot(ds.template head<3>());
  return Vec6<S>(ds / n - s * (wdw / (ww * n)));
}

template <class S> bool RuledSurface<S>::isCylindrical(const S& lambda) const {
  const Vec6<S> dl = unitDerivative(lambda);
  return dl.template head<3>().squaredNorm() <= Tolerance<S>::epsilon() * dl.squaredNorm() ||
         dl.squaredNorm() == S(0);
}

template <class S> Vec3<S> RuledSurface<S>::strictionPoint(const S& lambda) const {
  if (isCylindrical(lambda)) throw InvalidInput("RuledSurface::strictionPoint: cylindrical generator (u' = 0)");
  const PluckerLine<S> l = generator(lambda);
  const Vec6<S> dl = unitDerivative(lambda);
  const Vec3<S> u = l.direction(), m = l.moment(), du = dl.template head<3>(), dm = dl.template tail<3>();
  const Vec3<S> r = u.cross(m), dr = du.cross(m) + u.cross(dm);
  return r - (dr.dot(du) / du.squaredNorm()) * u;
}

template <class S> S RuledSurface<S>::distributionParameter(const S& lambda) const {
  if (isCylindrical(lambda)) throw InvalidInput("RuledSurface::distributionParameter: cylindrical generator (u' = 0)");
  const PluckerLine<S> l = generator(lambda);
  const Vec6<S> dl = unitDerivative(lambda);
  const Vec3<S> u = l.direction(), m = l.moment(), du = dl.template head<3>(), dm = dl.template tail<3>();
  const Vec3<S> dr = du.cross(m) + u.cross(dm);
  return u.dot(du.cross(dr)) / du.squaredNorm();
}

template <class S> RuledFrame<S> RuledSurface<S>::frame(const S& lambda) const {
  using std::sqrt;
  if (isCylindrical(lambda)) throw InvalidInput("RuledSurface::frame: cylindrical generator (u' = 0)");
  const PluckerLine<S> l = generator(lambda);
  const Vec6<S> dl = unitDerivative(lambda);
  const ScrewAxis<S> ax = screwAxis(dl);  // axis = central normal, pitch = κ₁/κ₀
  const LineRelation<S> rel = relation(l, ax.axis);
  // Orient ň along u' (the axis from screwAxis already has direction u'/|u'|).
  const PluckerLine<S> n = PluckerLine<S>::pointDirection(rel.footA, ax.axis.direction());
  // ť = ľ × ň: the line through the striction point along u × n.
  const PluckerLine<S> t = PluckerLine<S>::pointDirection(rel.footA, Vec3<S>(l.direction().cross(n.direction())));
  RuledFrame<S> f{l, n, t, ax.amplitude, ax.amplitude * ax.pitch, rel.footA, ax.pitch};
  return f;
}

#define SOMA_RULED_EXTERN(S)                                                      \
  extern template class RuledSurface<S>;                                          \
  extern template DualNumber<S> dualAngle<S>(const PluckerLine<S>&, const PluckerLine<S>&);     \
  extern template PluckerLine<S> commonPerpendicularDual<S>(const PluckerLine<S>&, const PluckerLine<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_RULED_EXTERN)
#undef SOMA_RULED_EXTERN

}  // namespace soma
