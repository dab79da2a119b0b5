// Studies of GF §9.4: lines as unit dual vectors, the dual angle and common perpendicular, the
// striction curve and dual Frenet frame of a ruled surface, the regulus, ruled helicoid and
// cylindroid invariants (E9.4–E9.6), in the scalar asked for; and Fig. 9.1 (double: soma::render).
// The 6-vector (Plücker) machinery of geometry/lines gives the second method everywhere.
#include "gf09/common.hpp"

#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/lines/regulus.hpp"
#include "soma/geometry/lines/ruled_surface.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/render.hpp"

namespace soma::studies::gf09::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

template <class S> using DN = DualNumber<S>;
template <class S> using DV = DualVec3<S>;
template <class S> using L = PluckerLine<S>;

template <class S> Vec3<S> rv(std::mt19937_64& g, double lo = -1, double hi = 1) {
  const S x = uni<S>(g, lo, hi), y = uni<S>(g, lo, hi), z = uni<S>(g, lo, hi);
  return Vec3<S>(x, y, z);
}
template <class S> Vec6<S> six(const Vec3<S>& a, const Vec3<S>& b) {
  Vec6<S> v;
  v << a, b;
  return v;
}
template <class S> S tolId(int ulps = 64) { return Tolerance<S>::identity(ulps); }
template <class S> std::string num(const S& x) { return toString(toDouble(x), 6); }

template <class S> DV<S> scaleDV(const DV<S>& a, const DN<S>& k) { return {Vec3<S>(k.re * a.re), Vec3<S>(k.re * a.du + k.du * a.re)}; }
template <class S> DV<S> addDV(const DV<S>& a, const DV<S>& b) { return {Vec3<S>(a.re + b.re), Vec3<S>(a.du + b.du)}; }
template <class S> DV<S> subDV(const DV<S>& a, const DV<S>& b) { return {Vec3<S>(a.re - b.re), Vec3<S>(a.du - b.du)}; }
template <class S> S normDV(const DV<S>& a) { return sqrt(a.re.squaredNorm() + a.du.squaredNorm()); }

// Central differences with step h = ε^(1/3) (Tolerance::precision(2)): truncation h²|f'''|/6 plus
// rounding ε|f|/h, both of order ε^(2/3); the checks on them allow fdTol = 256 ε^(2/3) (9.4e-9 in
// double, where h = 1e-5 and a tolerance of 1e-8 were used before).
template <class S> S fdStep() { return Tolerance<S>::precision(2); }
template <class S> S fdTol() { return S(256) * fdStep<S>() * fdStep<S>(); }

// Dual Frenet invariants at λ by central differences of the frame (ň, ť): τ̌ = (dň/dλ)·ť (E9.4).
template <class S> struct Invariants {
  DN<S> kappa, tau;
  S frenetN = 0, frenetT = 0, printedTau = 0;
};
template <class S> Invariants<S> invariants(const RuledSurface<S>& rs, const S& lam) {
  const RuledFrame<S> f = rs.frame(lam);
  const S h = fdStep<S>();
  const DV<S> l = DV<S>::of(f.l), n = DV<S>::of(f.n), t = DV<S>::of(f.t);
  const DV<S> np = DV<S>::of(rs.frame(lam + h).n), nm = DV<S>::of(rs.frame(lam - h).n);
  const DV<S> tp = DV<S>::of(rs.frame(lam + h).t), tm = DV<S>::of(rs.frame(lam - h).t);
  const DV<S> dn = {Vec3<S>((np.re - nm.re) / (2 * h)), Vec3<S>((np.du - nm.du) / (2 * h))};
  const DV<S> dt = {Vec3<S>((tp.re - tm.re) / (2 * h)), Vec3<S>((tp.du - tm.du) / (2 * h))};
  Invariants<S> r;
  r.kappa = DN<S>(f.kappa0, f.kappa1);
  r.tau = dn.dot(t);
  // dň/dλ = −κ̌ľ + τ̌ť, dť/dλ = −τ̌ň.
  r.frenetN = normDV(subDV(dn, addDV(scaleDV(l, DN<S>(-r.kappa.re, -r.kappa.du)), scaleDV(t, r.tau))));
  r.frenetT = normDV(addDV(dt, scaleDV(n, r.tau)));
  const DN<S> pt = dt.dot(t);
  r.printedTau = abs(pt.re) + abs(pt.du);
  return r;
}

// GF §9.4, GF-9.4-lines-as-dual-vectors
template <class S> void dualVectors(Context& c) {
  auto g = rng(101);
  S unit = 0, onSurface = 0;
  for (int k = 0; k < 100; ++k) {
    const L<S> l = L<S>::pointDirection(rv<S>(g, -3, 3), rv<S>(g)).normalized();
    const DN<S> n = DV<S>::of(l).dot(DV<S>::of(l));
    unit = std::max(unit, abs(n.re - 1) + abs(n.du));
  }
  c.checkResidual("unit line: v̌·v̌ = 1 ⇔ v₀·v₀ = 1, v₀·v₁ = 0 (100 random)", unit, tolId<S>(64));
  // ľ(λ) = v(λ) + ε r(λ) × v(λ): points r + μv lie on the generator.
  const auto rs = RuledSurface<S>::fromDirectrix([](const S& x) { return Vec3<S>(cos(x), sin(x), frac<S>(3, 10) * x); },
                                                      [](const S& x) { return Vec3<S>(-sin(x), cos(x), frac<S>(3, 10)); },
                                                      [](const S& x) { return Vec3<S>(frac<S>(1, 5), sin(2 * x), S(1)); },
                                                      [](const S& x) { return Vec3<S>(0, 2 * cos(2 * x), 0); });
  for (const S lam : {frac<S>(1, 10), frac<S>(4, 5), S(2)})
    for (const S mu : {S(-1), S(2)}) {
      const Vec3<S> p = Vec3<S>(cos(lam), sin(lam), frac<S>(3, 10) * lam) + mu * Vec3<S>(frac<S>(1, 5), sin(2 * lam), S(1));
      onSurface = std::max(onSurface, rs.generator(lam).distanceTo(p));
    }
  c.checkResidual("x(λ, μ) = r(λ) + μv(λ) lies on ľ(λ)", onSurface, tolId<S>(64));
  const auto cyl = RuledSurface<S>::fromDirectrix([](const S& x) { return Vec3<S>(cos(x), sin(x), 0); },
                                                       [](const S& x) { return Vec3<S>(-sin(x), cos(x), 0); },
                                                       [](const S&) { return Vec3<S>(0, 0, 1); }, [](const S&) { return Vec3<S>(0, 0, 0); });
  c.checkEqual("dv/dλ = 0: a cylinder (cylindric); dv/dλ ≠ 0: non-cylindric", "cylindric/non-cylindric",
               std::string(cyl.isCylindrical(frac<S>(2, 5)) ? "cylindric" : "?") + "/" + (rs.isCylindrical(frac<S>(2, 5)) ? "?" : "non-cylindric"));
}

// GF §9.4, GF-9.4-common-perpendicular-dual-angle
template <class S> void dualAngleStudy(Context& c) {
  auto g = rng(102);
  S meetsRight = 0, sinRe = 0, sinDu = 0, vsPlucker = 0;
  for (int k = 0; k < 100; ++k) {
    const L<S> a = L<S>::pointDirection(rv<S>(g, -2, 2), rv<S>(g)), b = L<S>::pointDirection(rv<S>(g, -2, 2), rv<S>(g));
    const L<S> n = commonPerpendicularDual(a, b);
    const DN<S> da = DV<S>::of(a).dot(DV<S>::of(n)), db = DV<S>::of(b).dot(DV<S>::of(n));
    meetsRight = std::max(meetsRight, abs(da.re) + abs(da.du) + abs(db.re) + abs(db.du));
    const DN<S> al = dualAngle(a, b);
    const LineRelation<S> r = relation(a, b);
    // ľ₁ × ľ₂ = sin(α̌) ň: compare with sin(α + εd) = sin α + εd cos α.
    const DV<S> cr = DV<S>::of(a).cross(DV<S>::of(b));
    const DN<S> s = DN<S>(al.re, al.du).sin();
    sinRe = std::max(sinRe, (cr.re - s.re * n.direction()).norm());
    sinDu = std::max(sinDu, (cr.du - (s.re * n.moment() + s.du * n.direction())).norm());
    vsPlucker = std::max(vsPlucker, abs(al.re - r.angle) + abs(al.du - r.signedDistance) +
                                        (n.coords() - r.commonPerpendicular().normalized().coords()).norm());
  }
  c.checkResidual("ň = (ľ₁ × ľ₂)/|ľ₁ × ľ₂| meets both at right angles: ľᵢ·ň = 0 (dual, 100 random)", meetsRight, tolId<S>(256));
  c.checkResidual("ľ₁ × ľ₂ = sin(α̌) ň: real part", sinRe, tolId<S>(256));
  c.checkResidual("… dual part (d cos α)", sinDu, tolId<S>(1024));
  c.checkResidual("dual angle and ň agree with the Plücker relation() (angle, signed d, common perpendicular)", vsPlucker, tolId<S>(4096));
  const L<S> x = L<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitX());
  c.checkNear("parallel lines 2 apart: dual sine pure dual, d = 2", S(2), dualAngle(x, L<S>::pointDirection(Vec3<S>(0, 2, 0), Vec3<S>::UnitX())).du, tolId<S>());
  c.checkNear("intersecting lines: d = 0", S(0), dualAngle(x, L<S>::pointDirection(Vec3<S>(3, 0, 0), Vec3<S>(1, 1, 0))).du, tolId<S>());
  const L<S> perp = L<S>::pointDirection(Vec3<S>(0, 0, frac<S>(3, 2)), Vec3<S>::UnitY());
  const DV<S> cr = DV<S>::of(x).cross(DV<S>::of(perp));
  c.checkNear("perpendicular lines: d cos α = 0 (dual part of |ľ₁ × ľ₂|)", S(0), cr.re.dot(cr.du), tolId<S>());
  c.checkNear("… d = 1.5 from the dual angle", frac<S>(3, 2), dualAngle(x, perp).du, tolId<S>());
}

// GF §9.4, GF-9.4-striction-and-dual-frenet (E9.4)
template <class S> void strictionFrenet(Context& c) {
  // A general ruled surface: directrix r(λ) and direction v(λ) (unit not required).
  const auto rs = RuledSurface<S>::fromDirectrix([](const S& x) { return Vec3<S>(cos(x), frac<S>(1, 2) * sin(x), frac<S>(1, 5) * x); },
                                                      [](const S& x) { return Vec3<S>(-sin(x), frac<S>(1, 2) * cos(x), frac<S>(1, 5)); },
                                                      [](const S& x) { return Vec3<S>(sin(x), frac<S>(3, 10), cos(x)); },
                                                      [](const S& x) { return Vec3<S>(cos(x), 0, -sin(x)); });
  S two = 0, strictTangent = 0, frenetN = 0, frenetT = 0, printed = 0, striction2 = 0;
  for (const S lam : {frac<S>(3, 10), frac<S>(11, 10), S(2)}) {
    const Invariants<S> iv = invariants(rs, lam);
    frenetN = std::max(frenetN, iv.frenetN);
    frenetT = std::max(frenetT, iv.frenetT);
    printed = std::max(printed, iv.printedTau);
    two = std::max(two, abs(rs.distributionParameter(lam) - rs.frame(lam).distributionParameter));
    striction2 = std::max(striction2, (rs.strictionPoint(lam) - rs.frame(lam).striction).norm());
    // ds/dλ · dv/dλ = 0 (v unit).
    const S h = fdStep<S>();
    const Vec3<S> ds = (rs.strictionPoint(lam + h) - rs.strictionPoint(lam - h)) / (2 * h);
    const Vec3<S> dv = (rs.generator(lam + h).direction() - rs.generator(lam - h).direction()) / (2 * h);
    strictTangent = std::max(strictTangent, abs(ds.dot(dv)));
  }
  c.checkResidual("distribution parameter: det[u, u', r']/|u'|² = pitch of dľ/dλ (two methods)", two, tolId<S>(256));
  c.checkResidual("striction point: classical formula = foot of the axis of dľ/dλ on ľ (two methods)", striction2, tolId<S>(1024));
  c.checkResidual("dň/dλ = −κ̌ľ + τ̌ť with τ̌ = (dň/dλ)·ť (central differences: 256 ε^(2/3))", frenetN, fdTol<S>());
  c.checkResidual("dť/dλ = −τ̌ň", frenetT, fdTol<S>());
  c.checkResidual("striction curve: ds/dλ · dv/dλ = 0 (central differences)", strictTangent, fdTol<S>());
  c.recordIn("printed τ̌ = (dť/dλ)·ť is identically 0 (E9.4; central differences)", "0 (so it cannot be τ̌)", io::numberText(printed), printed,
             fdTol<S>(), printed <= fdTol<S>());
  // Tangent developable: ľ = ṙ + ε r × ṙ ⇒ dľ/dλ = r̈ + ε r × r̈ is a line: κ₁ = 0.
  const auto dev = RuledSurface<S>::fromDirectrix([](const S& x) { return Vec3<S>(cos(x), sin(x), frac<S>(2, 5) * x); },
                                                       [](const S& x) { return Vec3<S>(-sin(x), cos(x), frac<S>(2, 5)); },
                                                       [](const S& x) { return Vec3<S>(-sin(x), cos(x), frac<S>(2, 5)); },
                                                       [](const S& x) { return Vec3<S>(-cos(x), -sin(x), 0); });
  c.checkNear("tangent developable of a helix: κ₁ = 0", S(0), dev.frame(frac<S>(7, 10)).kappa1, tolId<S>(64));
  // Zero pitch whenever ṙ ∈ span(v, v̇), e.g. ṙ = v + v̇ (none of the book's three cases holds).
  const auto span = RuledSurface<S>::fromDirectrix(
      [](const S& x) { return Vec3<S>(sin(x) + cos(x), cos(x) - sin(x), x); },
      [](const S& x) { return Vec3<S>(cos(x) - sin(x), -sin(x) - cos(x), S(1)); },
      [](const S& x) { return Vec3<S>(cos(x), -sin(x), S(1)); },
      [](const S& x) { return Vec3<S>(-sin(x), -cos(x), S(0)); });
  c.checkNear("ṙ = v + v̇ (ṙ ≠ 0, v̇ ∦ ṙ, v ∦ ṙ): κ₁ = 0 — the book's list of zero-pitch cases is incomplete", S(0),
              span.frame(frac<S>(1, 2)).kappa1, tolId<S>(64));
}

template <class S> Regulus<S> bookRegulus(const S& d, const S& al) {
  return Regulus<S>(L<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitZ()), L<S>::pointDirection(Vec3<S>(d, 0, 0), Vec3<S>(0, sin(al), cos(al))));
}

// GF §9.4, GF-9.4-hyperboloid-regulus-invariants (E9.5, E9.6)
template <class S> void regulusInvariants(Context& c) {
  const S d = frac<S>(4, 5), al = frac<S>(3, 5);
  const Regulus<S> r = bookRegulus(d, al);
  const Invariants<S> iv = invariants(r.surface(), frac<S>(2, 5));
  c.checkNear("κ₀ = sin α (α = 0.6, d = 0.8)", sin(al), iv.kappa.re, tolId<S>(64));
  c.checkNear("|κ₁| = d cos α", d * cos(al), abs(iv.kappa.du), tolId<S>(64));
  // Reparametrise to κ₀ = 1: λ' = λ sin α (E9.6), so every invariant is divided by sin α.
  const S k1 = iv.kappa.du / iv.kappa.re, t0 = iv.tau.re / iv.kappa.re, t1 = iv.tau.du / iv.kappa.re;
  c.checkNear("κ₁ = −d cot α (this hand; the book's +d cot α is the mirror regulus)", -d / tan(al), k1, fdTol<S>());
  c.checkNear("τ₀ = cot α", 1 / tan(al), t0, fdTol<S>());
  c.checkNear("τ₁ = +d (book −d, mirror hand)", d, t1, fdTol<S>());
  c.checkNear("hand-free relation κ₁ = −τ₁ cot α", -t1 / tan(al), k1, fdTol<S>());
  c.checkNear("λ' = λ sin α gives κ₀' = 1 (E9.6)", S(1), iv.kappa.re / sin(al), tolId<S>(64));
  const S printedK0 = iv.kappa.re * sin(al);
  c.recordIn("the printed λ' = λ/sin α gives κ₀' = sin²α ≠ 1 (E9.6): |κ₀' − 1| > 0.1", "≠ 1", io::numberText(printedK0),
             abs(printedK0 - 1), frac<S>(1, 10), abs(printedK0 - 1) > frac<S>(1, 10));
  c.checkResidual("Frenet equations hold (central differences)", maxOf(iv.frenetN, iv.frenetT), fdTol<S>());
  // E9.5: with τ̌ = cot α − εd and dť/dλ = −τ̌ň, the printed dť/dλ' = +(cot α − εd)ň has the wrong sign
  // for one of the two; soma's frame: dť/dλ' = −τ̌ň with τ̌ = cot α + εd.
  c.note("E9.5: the printed dť/dλ' = +(cot α − εd)ň contradicts dť/dλ = −τ̌ň with τ̌ = cot α − εd. Measured (this hand): "
         "τ̌/κ₀ = " + num(t0) + " + ε" + num(t1) + ", Frenet residuals " + num(iv.frenetN) + ", " + num(iv.frenetT) + ".");
  // The striction curve is the throat circle.
  S throat = 0;
  for (const S th : {S(0), S(1), frac<S>(5, 2)}) {
    const Vec3<S> s = r.surface().strictionPoint(th);
    throat = std::max(throat, abs(s.norm() - d) + abs(s.z()));
  }
  c.checkResidual("striction curve = throat circle (radius d, z = 0)", throat, tolId<S>(64));
  c.checkNear("d = 0 (cone): κ₁ = 0", S(0), bookRegulus(S(0), al).surface().frame(frac<S>(3, 10)).kappa1, tolId<S>());
  c.checkNear("α = π/2 (plane): κ₁ = 0", S(0), bookRegulus(d, pi<S>() / 2).surface().frame(frac<S>(3, 10)).kappa1, tolId<S>());
  // isCylindrical: |dv/dλ|² ≤ ε |dľ/dλ|², here about sin²α ≤ ε d² cos²α: the threshold is α ≈ d√ε
  // (1e-9 / 1e-6 in double); two orders of magnitude on either side.
  const S alCyl = sqrt(Tolerance<S>::epsilon()) / 100, alNon = sqrt(Tolerance<S>::epsilon()) * 100;
  c.checkEqual("α → 0 (generator ∥ axis): cylindrical, α = √ε/100 rejected / α = 100√ε accepted", "cyl/non",
               std::string(bookRegulus(d, alCyl).surface().isCylindrical(S(0)) ? "cyl" : "non") + "/" +
                   (bookRegulus(d, alNon).surface().isCylindrical(S(0)) ? "cyl" : "non"));
}

// GF §9.4, GF-9.4-ruled-helicoid
template <class S> void ruledHelicoid(Context& c) {
  const S d = frac<S>(4, 5), al = frac<S>(3, 5), p = frac<S>(1, 4);
  const auto rs = RuledSurface<S>::sweep(six<S>(Vec3<S>(0, 0, 1), Vec3<S>(0, 0, p)), L<S>::pointDirection(Vec3<S>(d, 0, 0), Vec3<S>(0, sin(al), cos(al))));
  const Invariants<S> iv = invariants(rs, frac<S>(7, 10));
  const S k1 = iv.kappa.du / iv.kappa.re, t0 = iv.tau.re / iv.kappa.re, t1 = iv.tau.du / iv.kappa.re;
  c.checkNear("κ₁ = p − d cot α (book p + d cot α, mirror hand: d → −d)", p - d / tan(al), k1, fdTol<S>());
  c.checkNear("τ₀ = cot α", 1 / tan(al), t0, fdTol<S>());
  c.checkNear("τ₁ = p cot α + d (book p cot α − d, mirror hand)", p / tan(al) + d, t1, fdTol<S>());
  c.checkNear("invariants = regulus values × (1 + εp): κ₁ − κ₁(p = 0) = p·κ₀/κ₀", p, k1 - (-d / tan(al)), fdTol<S>());
  S helix = 0;
  for (const S th : {S(0), S(1), S(3)}) {
    const Vec3<S> s = rs.strictionPoint(th);
    helix = std::max(helix, (s - Vec3<S>(d * cos(th), d * sin(th), p * th)).norm());
  }
  c.checkResidual("striction curve = helix (d cos θ, d sin θ, pθ)", helix, tolId<S>(256));
}

// GF §9.4, GF-9.4-cylindroid-invariants
template <class S> void cylindroidInvariants(Context& c) {
  const S r = frac<S>(3, 5);
  const RuledSurface<S> rs(
      [r](const S& t) { return six<S>(Vec3<S>(cos(t), sin(t), 0), Vec3<S>(r * cos(2 * t) * Vec3<S>(-sin(t), cos(t), 0))); },
      [r](const S& t) {
        return six<S>(Vec3<S>(-sin(t), cos(t), 0), Vec3<S>(-r * Vec3<S>(cos(t) * cos(2 * t) - 2 * sin(t) * sin(2 * t),
                                                                sin(t) * cos(2 * t) + 2 * cos(t) * sin(2 * t), 0)));
      });
  S k0 = 0, k1 = 0, nn = 0, st = 0, tt = 0, tau = 0, moment = 0, fd = 0, same = 0;
  for (const S th : {frac<S>(1, 5), frac<S>(9, 10), frac<S>(7, 5), frac<S>(27, 10)}) {
    const Invariants<S> iv = invariants(rs, th);
    const RuledFrame<S> f = rs.frame(th);
    k0 = std::max(k0, abs(iv.kappa.re - 1));
    k1 = std::max(k1, abs(iv.kappa.du + 2 * r * sin(2 * th)));
    const Vec6<S> nBook = six<S>(Vec3<S>(-sin(th), cos(th), 0), Vec3<S>(-r * Vec3<S>(cos(th) * cos(2 * th), sin(th) * cos(2 * th), 0)));
    nn = std::max(nn, (f.n.coords() - nBook).norm());
    st = std::max(st, (f.striction - Vec3<S>(0, 0, r * cos(2 * th))).norm());
    tt = std::max(tt, (f.t.coords() - six<S>(Vec3<S>(0, 0, 1), Vec3<S>::Zero())).norm());
    tau = std::max(tau, abs(iv.tau.re) + abs(iv.tau.du));
    moment = std::max(moment, (Vec3<S>(0, 0, r * cos(2 * th)).cross(Vec3<S>(cos(th), sin(th), 0)) - rs.coords(th).template tail<3>()).norm());
    const S h = fdStep<S>();
    fd = std::max(fd, ((rs.coords(th + h) - rs.coords(th - h)) / (2 * h) - rs.derivative(th)).norm());
    // Same surface as GF-6.5.2-cylindroid-principal-form with r_x = r, r_y = −r.
    const Cylindroid<S> cy(six<S>(Vec3<S>(1, 0, 0), Vec3<S>(0, r, 0)), six<S>(Vec3<S>(0, 1, 0), Vec3<S>(r, 0, 0)));
    // Cylindroid angles are measured from its principal screw (here at 45°): use angleOf.
    same = std::max(same, cy.axis(cy.angleOf(rs.coords(th))).sameAs(rs.generator(th), tolId<S>(1024)) ? S(0) : S(1));
  }
  c.checkResidual("moment = s × v with s = (0, 0, r cos 2θ) (convention A)", moment, tolId<S>(64));
  c.checkResidual("printed dľ/dθ (central differences, h = ε^(1/3))", fd, fdTol<S>());
  c.checkResidual("κ₀ = 1", k0, tolId<S>(256));
  c.checkResidual("κ₁ = −2r sin 2θ", k1, tolId<S>(256));
  c.checkResidual("ň = (−sin θ, cos θ, 0) − εr(cos θ cos 2θ, sin θ cos 2θ, 0)", nn, tolId<S>(256));
  c.checkResidual("striction point (0, 0, r cos 2θ)", st, tolId<S>(256));
  c.checkResidual("ť = (0, 0, 1)", tt, tolId<S>(256));
  c.checkResidual("τ₀ = τ₁ = 0 (central differences)", tau, fdTol<S>());
  c.checkResidual("same surface as the cylindroid with r_x = r, r_y = −r (GF-6.5.2-cylindroid-principal-form)", same, S(0));
}

// GF Fig. 9.1, GF-9.4-fig9.1-line-sweeps-regulus
void fig91(Context& c) {
  using S = double;
  using V3 = Vec3<S>;
  const double d = 0.8, al = 0.6;
  const Regulus<double> r = bookRegulus(d, al);
  const RuledFrame<double> f = r.surface().frame(0.0);
  c.checkResidual("drawn frame: ľ, ň, ť pairwise perpendicular and meeting at the striction point",
                  std::abs(f.l.direction().dot(f.n.direction())) + std::abs(f.l.direction().dot(f.t.direction())) +
                      std::abs(f.n.direction().dot(f.t.direction())) + f.l.distanceTo(f.striction) + f.n.distanceTo(f.striction) +
                      f.t.distanceTo(f.striction),
                  tolId<S>(64));
  if (!c.makeFigures()) return;
  namespace rd = soma::render;
  rd::Scene s;
  s.title = "Fig. 9.1: a line ľ swept about the axis ǎ generates a cylindrical regulus";
  const double zmax = 1.8;
  // Hyperboloid ρ² = d² + z² tan²α.
  rd::Mesh m;
  const int nu = 72, nv = 20;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double t = 2 * pi<double>() * i / nu, z = -zmax + 2 * zmax * j / nv;
      const double rho = std::sqrt(d * d + z * z * std::pow(std::tan(al), 2));
      m.v.push_back(V3(rho * std::cos(t), rho * std::sin(t), z));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * (nu + 1) + i, b = a + 1, cc = a + nu + 1, dd = cc + 1;
      m.tri.push_back(Eigen::Vector3i(a, b, dd));
      m.tri.push_back(Eigen::Vector3i(a, dd, cc));
    }
  m.c = rd::palette::lightGrey.withAlpha(0.3f);
  s.add(m);
  auto seg = [&](const L<S>& l, rd::Color col, double rad) {
    const L<S> u = l.normalized();
    const V3 f0 = u.foot(), dir = u.direction();
    rd::Tube t;
    t.p = {V3(f0 + (-zmax - f0.z()) / dir.z() * dir), V3(f0 + (zmax - f0.z()) / dir.z() * dir)};
    t.c = col;
    t.radius = rad;
    s.add(t);
  };
  for (int k = 1; k < 14; ++k) seg(r.generator(2 * pi<double>() * k / 14), rd::palette::skyBlue, 0.012);
  seg(r.generator(0.0), rd::palette::blue, 0.03);
  rd::Tube axis;
  axis.p = {V3(0, 0, -zmax - 0.3), V3(0, 0, zmax + 0.3)};
  axis.c = rd::palette::black;
  axis.radius = 0.018;
  s.add(axis);
  rd::Polyline throat;
  for (int k = 0; k <= 120; ++k) throat.p.push_back(V3(d * std::cos(2 * pi<double>() * k / 120), d * std::sin(2 * pi<double>() * k / 120), 0));
  throat.c = rd::palette::vermillion;
  throat.width = 3.5;
  s.add(throat);
  const V3 p = f.striction;
  s.add(rd::Arrow{p, V3(p + 0.7 * f.l.direction()), rd::palette::blue, 0.02});
  s.add(rd::Arrow{p, V3(p + 0.7 * f.n.direction()), rd::palette::bluishGreen, 0.02});
  s.add(rd::Arrow{p, V3(p + 0.7 * f.t.direction()), rd::palette::orange, 0.02});
  rd::Polyline nLine;
  nLine.p = {V3::Zero(), p};
  nLine.c = rd::palette::bluishGreen;
  nLine.dashed = true;
  nLine.width = 2;
  s.add(nLine);
  s.add(rd::Points{{p}, rd::palette::vermillion, 0.04});
  auto lab = [&](const V3& at, const std::string& t, rd::Color col, Eigen::Vector2d off = {8, -8}) {
    rd::Label l;
    l.at = at;
    l.text = t;
    l.c = col;
    l.pixelHeight = 28;
    l.offset = off;
    s.add(l);
  };
  lab(V3(0, 0, zmax + 0.3), "ǎ", rd::palette::black);
  lab(V3(p + 0.7 * f.l.direction()), "ľ", rd::palette::blue);
  lab(V3(p + 0.7 * f.n.direction()), "ň", rd::palette::bluishGreen, {8, 18});
  lab(V3(p + 0.7 * f.t.direction()), "ť", rd::palette::orange);
  lab(V3(-d, 0, 0), "striction curve (throat circle)", rd::palette::vermillion, {-8, 26});
  const std::string file = "GF-9.4-fig9.1-line-sweeps-regulus.png";
  rd::renderPng(s, V3(-0.55, -1.0, -0.3), {1100, 1000}, c.figurePath(file));
  c.figure(file, "A line sweeps out a cylindrical regulus (Fig. 9.1): the generator ľ (through (0.8, 0, 0) at α = 0.6 to the axis ǎ = z) "
                 "and 13 of its rotated copies on the hyperboloid ρ² = d² + z² tan²α; the striction curve is the throat circle of "
                 "radius d (vermillion); at the striction point the dual Frenet frame ľ, ň (common perpendicular with the axis, "
                 "dashed to it), ť = ľ × ň.");
}

// Fig. 9.1 stays in double: soma::render draws double geometry.
constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";
SOMA_STUDY_SCALAR("GF-9.4-lines-as-dual-vectors", "Lines as unit dual vectors; ruled surfaces ľ(λ) = v + εr × v", "GF §9.4", dualVectors);
SOMA_STUDY_SCALAR("GF-9.4-common-perpendicular-dual-angle", "Dual angle α + εd and the common perpendicular ľ₁ × ľ₂ = sin(α̌)ň", "GF §9.4", dualAngleStudy);
SOMA_STUDY_SCALAR("GF-9.4-striction-and-dual-frenet", "Striction point, distribution parameter and the dual Frenet frame (E9.4)", "GF §9.4", strictionFrenet);
SOMA_STUDY_SCALAR("GF-9.4-hyperboloid-regulus-invariants", "Invariants of a regulus: κ₁ = ∓d cot α, τ̌ = cot α ± εd (E9.5, E9.6)", "GF §9.4", regulusInvariants);
SOMA_STUDY_SCALAR("GF-9.4-ruled-helicoid", "Ruled helicoid: regulus invariants times (1 + εp), helical striction curve", "GF §9.4", ruledHelicoid);
SOMA_STUDY_SCALAR("GF-9.4-cylindroid-invariants", "Cylindroid as a ruled surface: κ₁ = −2r sin 2θ, striction on the nodal line", "GF §9.4", cylindroidInvariants);
SOMA_STUDY_DOUBLE("GF-9.4-fig9.1-line-sweeps-regulus", "Fig. 9.1: a line sweeps out a cylindrical regulus", "GF §9.4", fig91);

}  // namespace
}  // namespace soma::studies::gf09::SOMA_UNITY_ID
