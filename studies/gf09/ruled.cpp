// Studies of GF §9.4: lines as unit dual vectors, the dual angle and common perpendicular, the
// striction curve and dual Frenet frame of a ruled surface, the regulus, ruled helicoid and
// cylindroid invariants (E9.4–E9.6), and Fig. 9.1 (double). The 6-vector (Plücker) machinery of
// geometry/lines gives the second method everywhere.
#include "gf06/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/render.hpp"

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using D = DualNumber<double>;
using DV = DualVec3<double>;

DV scaleDV(const DV& a, const D& k) { return {V3(k.re * a.re), V3(k.re * a.du + k.du * a.re)}; }
DV addDV(const DV& a, const DV& b) { return {V3(a.re + b.re), V3(a.du + b.du)}; }
DV subDV(const DV& a, const DV& b) { return {V3(a.re - b.re), V3(a.du - b.du)}; }
double normDV(const DV& a) { return std::sqrt(a.re.squaredNorm() + a.du.squaredNorm()); }

// Dual Frenet invariants at λ by central differences of the frame (ň, ť): τ̌ = (dň/dλ)·ť (E9.4).
struct Invariants {
  D kappa, tau;
  double frenetN = 0, frenetT = 0, printedTau = 0;
};
Invariants invariants(const RuledSurface<double>& rs, double lam) {
  const RuledFrame<double> f = rs.frame(lam);
  const double h = 1e-5;
  const DV l = DV::of(f.l), n = DV::of(f.n), t = DV::of(f.t);
  const DV np = DV::of(rs.frame(lam + h).n), nm = DV::of(rs.frame(lam - h).n);
  const DV tp = DV::of(rs.frame(lam + h).t), tm = DV::of(rs.frame(lam - h).t);
  const DV dn = {V3((np.re - nm.re) / (2 * h)), V3((np.du - nm.du) / (2 * h))};
  const DV dt = {V3((tp.re - tm.re) / (2 * h)), V3((tp.du - tm.du) / (2 * h))};
  Invariants r;
  r.kappa = D(f.kappa0, f.kappa1);
  r.tau = dn.dot(t);
  // dň/dλ = −κ̌ľ + τ̌ť, dť/dλ = −τ̌ň.
  r.frenetN = normDV(subDV(dn, addDV(scaleDV(l, D(-r.kappa.re, -r.kappa.du)), scaleDV(t, r.tau))));
  r.frenetT = normDV(addDV(dt, scaleDV(n, r.tau)));
  const D pt = dt.dot(t);
  r.printedTau = std::abs(pt.re) + std::abs(pt.du);
  return r;
}

// GF §9.4, GF-9.4-lines-as-dual-vectors
void dualVectors(Context& c) {
  auto g = rng(101);
  double unit = 0, onSurface = 0;
  for (int k = 0; k < 100; ++k) {
    const L l = L::pointDirection(rv(g, -3, 3), rv(g)).normalized();
    const D n = DV::of(l).dot(DV::of(l));
    unit = std::max(unit, std::abs(n.re - 1) + std::abs(n.du));
  }
  c.checkResidual("unit line: v̌·v̌ = 1 ⇔ v₀·v₀ = 1, v₀·v₁ = 0 (100 random)", unit, tolId(64));
  // ľ(λ) = v(λ) + ε r(λ) × v(λ): points r + μv lie on the generator.
  const auto rs = RuledSurface<double>::fromDirectrix([](const double& x) { return V3(std::cos(x), std::sin(x), 0.3 * x); },
                                                      [](const double& x) { return V3(-std::sin(x), std::cos(x), 0.3); },
                                                      [](const double& x) { return V3(0.2, std::sin(2 * x), 1.0); },
                                                      [](const double& x) { return V3(0, 2 * std::cos(2 * x), 0); });
  for (const double lam : {0.1, 0.8, 2.0})
    for (const double mu : {-1.0, 2.0}) {
      const V3 p = V3(std::cos(lam), std::sin(lam), 0.3 * lam) + mu * V3(0.2, std::sin(2 * lam), 1.0);
      onSurface = std::max(onSurface, rs.generator(lam).distanceTo(p));
    }
  c.checkResidual("x(λ, μ) = r(λ) + μv(λ) lies on ľ(λ)", onSurface, tolId(64));
  const auto cyl = RuledSurface<double>::fromDirectrix([](const double& x) { return V3(std::cos(x), std::sin(x), 0); },
                                                       [](const double& x) { return V3(-std::sin(x), std::cos(x), 0); },
                                                       [](const double&) { return V3(0, 0, 1); }, [](const double&) { return V3(0, 0, 0); });
  c.checkEqual("dv/dλ = 0: a cylinder (cylindric); dv/dλ ≠ 0: non-cylindric", "cylindric/non-cylindric",
               std::string(cyl.isCylindrical(0.4) ? "cylindric" : "?") + "/" + (rs.isCylindrical(0.4) ? "?" : "non-cylindric"));
}

// GF §9.4, GF-9.4-common-perpendicular-dual-angle
void dualAngleStudy(Context& c) {
  auto g = rng(102);
  double meetsRight = 0, sinRe = 0, sinDu = 0, vsPlucker = 0;
  for (int k = 0; k < 100; ++k) {
    const L a = L::pointDirection(rv(g, -2, 2), rv(g)), b = L::pointDirection(rv(g, -2, 2), rv(g));
    const L n = commonPerpendicularDual(a, b);
    const D da = DV::of(a).dot(DV::of(n)), db = DV::of(b).dot(DV::of(n));
    meetsRight = std::max(meetsRight, std::abs(da.re) + std::abs(da.du) + std::abs(db.re) + std::abs(db.du));
    const D al = dualAngle(a, b);
    const LineRelation<double> r = relation(a, b);
    // ľ₁ × ľ₂ = sin(α̌) ň: compare with sin(α + εd) = sin α + εd cos α.
    const DV cr = DV::of(a).cross(DV::of(b));
    const D s = D(al.re, al.du).sin();
    sinRe = std::max(sinRe, (cr.re - s.re * n.direction()).norm());
    sinDu = std::max(sinDu, (cr.du - (s.re * n.moment() + s.du * n.direction())).norm());
    vsPlucker = std::max(vsPlucker, std::abs(al.re - r.angle) + std::abs(al.du - r.signedDistance) +
                                        (n.coords() - r.commonPerpendicular().normalized().coords()).norm());
  }
  c.checkResidual("ň = (ľ₁ × ľ₂)/|ľ₁ × ľ₂| meets both at right angles: ľᵢ·ň = 0 (dual, 100 random)", meetsRight, tolId(256));
  c.checkResidual("ľ₁ × ľ₂ = sin(α̌) ň: real part", sinRe, tolId(256));
  c.checkResidual("… dual part (d cos α)", sinDu, tolId(1024));
  c.checkResidual("dual angle and ň agree with the Plücker relation() (angle, signed d, common perpendicular)", vsPlucker, tolId(4096));
  const L x = L::pointDirection(V3::Zero(), V3::UnitX());
  c.checkNear("parallel lines 2 apart: dual sine pure dual, d = 2", 2.0, dualAngle(x, L::pointDirection(V3(0, 2, 0), V3::UnitX())).du, tolId());
  c.checkNear("intersecting lines: d = 0", 0.0, dualAngle(x, L::pointDirection(V3(3, 0, 0), V3(1, 1, 0))).du, tolId());
  const L perp = L::pointDirection(V3(0, 0, 1.5), V3::UnitY());
  const DV cr = DV::of(x).cross(DV::of(perp));
  c.checkNear("perpendicular lines: d cos α = 0 (dual part of |ľ₁ × ľ₂|)", 0.0, cr.re.dot(cr.du), tolId());
  c.checkNear("… d = 1.5 from the dual angle", 1.5, dualAngle(x, perp).du, tolId());
}

// GF §9.4, GF-9.4-striction-and-dual-frenet (E9.4)
void strictionFrenet(Context& c) {
  // A general ruled surface: directrix r(λ) and direction v(λ) (unit not required).
  const auto rs = RuledSurface<double>::fromDirectrix([](const double& x) { return V3(std::cos(x), 0.5 * std::sin(x), 0.2 * x); },
                                                      [](const double& x) { return V3(-std::sin(x), 0.5 * std::cos(x), 0.2); },
                                                      [](const double& x) { return V3(std::sin(x), 0.3, std::cos(x)); },
                                                      [](const double& x) { return V3(std::cos(x), 0, -std::sin(x)); });
  double two = 0, strictTangent = 0, frenetN = 0, frenetT = 0, printed = 0, striction2 = 0;
  for (const double lam : {0.3, 1.1, 2.0}) {
    const Invariants iv = invariants(rs, lam);
    frenetN = std::max(frenetN, iv.frenetN);
    frenetT = std::max(frenetT, iv.frenetT);
    printed = std::max(printed, iv.printedTau);
    two = std::max(two, std::abs(rs.distributionParameter(lam) - rs.frame(lam).distributionParameter));
    striction2 = std::max(striction2, (rs.strictionPoint(lam) - rs.frame(lam).striction).norm());
    // ds/dλ · dv/dλ = 0 (v unit).
    const double h = 1e-5;
    const V3 ds = (rs.strictionPoint(lam + h) - rs.strictionPoint(lam - h)) / (2 * h);
    const V3 dv = (rs.generator(lam + h).direction() - rs.generator(lam - h).direction()) / (2 * h);
    strictTangent = std::max(strictTangent, std::abs(ds.dot(dv)));
  }
  c.checkResidual("distribution parameter: det[u, u', r']/|u'|² = pitch of dľ/dλ (two methods)", two, tolId(256));
  c.checkResidual("striction point: classical formula = foot of the axis of dľ/dλ on ľ (two methods)", striction2, tolId(1024));
  c.checkResidual("dň/dλ = −κ̌ľ + τ̌ť with τ̌ = (dň/dλ)·ť (finite differences)", frenetN, 1e-8);
  c.checkResidual("dť/dλ = −τ̌ň", frenetT, 1e-8);
  c.checkResidual("striction curve: ds/dλ · dv/dλ = 0", strictTangent, 1e-8);
  c.record("printed τ̌ = (dť/dλ)·ť is identically 0 (E9.4)", "0 (so it cannot be τ̌)", num(printed), printed, 1e-8, printed <= 1e-8);
  // Tangent developable: ľ = ṙ + ε r × ṙ ⇒ dľ/dλ = r̈ + ε r × r̈ is a line: κ₁ = 0.
  const auto dev = RuledSurface<double>::fromDirectrix([](const double& x) { return V3(std::cos(x), std::sin(x), 0.4 * x); },
                                                       [](const double& x) { return V3(-std::sin(x), std::cos(x), 0.4); },
                                                       [](const double& x) { return V3(-std::sin(x), std::cos(x), 0.4); },
                                                       [](const double& x) { return V3(-std::cos(x), -std::sin(x), 0); });
  c.checkNear("tangent developable of a helix: κ₁ = 0", 0.0, dev.frame(0.7).kappa1, tolId(64));
  // Zero pitch whenever ṙ ∈ span(v, v̇), e.g. ṙ = v + v̇ (none of the book's three cases holds).
  const auto span = RuledSurface<double>::fromDirectrix(
      [](const double& x) { return V3(std::sin(x) + std::cos(x), std::cos(x) - std::sin(x), x); },
      [](const double& x) { return V3(std::cos(x) - std::sin(x), -std::sin(x) - std::cos(x), 1.0); },
      [](const double& x) { return V3(std::cos(x), -std::sin(x), 1.0); },
      [](const double& x) { return V3(-std::sin(x), -std::cos(x), 0.0); });
  c.checkNear("ṙ = v + v̇ (ṙ ≠ 0, v̇ ∦ ṙ, v ∦ ṙ): κ₁ = 0 — the book's list of zero-pitch cases is incomplete", 0.0,
              span.frame(0.5).kappa1, tolId(64));
}

Regulus<double> bookRegulus(double d, double al) {
  return Regulus<double>(L::pointDirection(V3::Zero(), V3::UnitZ()), L::pointDirection(V3(d, 0, 0), V3(0, std::sin(al), std::cos(al))));
}

// GF §9.4, GF-9.4-hyperboloid-regulus-invariants (E9.5, E9.6)
void regulusInvariants(Context& c) {
  const double d = 0.8, al = 0.6;
  const Regulus<double> r = bookRegulus(d, al);
  const Invariants iv = invariants(r.surface(), 0.4);
  c.checkNear("κ₀ = sin α (α = 0.6, d = 0.8)", std::sin(al), iv.kappa.re, tolId(64));
  c.checkNear("|κ₁| = d cos α", d * std::cos(al), std::abs(iv.kappa.du), tolId(64));
  // Reparametrise to κ₀ = 1: λ' = λ sin α (E9.6), so every invariant is divided by sin α.
  const double k1 = iv.kappa.du / iv.kappa.re, t0 = iv.tau.re / iv.kappa.re, t1 = iv.tau.du / iv.kappa.re;
  c.checkNear("κ₁ = −d cot α (this hand; the book's +d cot α is the mirror regulus)", -d / std::tan(al), k1, 1e-9);
  c.checkNear("τ₀ = cot α", 1 / std::tan(al), t0, 1e-9);
  c.checkNear("τ₁ = +d (book −d, mirror hand)", d, t1, 1e-9);
  c.checkNear("hand-free relation κ₁ = −τ₁ cot α", -t1 / std::tan(al), k1, 1e-9);
  c.checkNear("λ' = λ sin α gives κ₀' = 1 (E9.6)", 1.0, iv.kappa.re / std::sin(al), tolId(64));
  c.record("the printed λ' = λ/sin α gives κ₀' = sin²α ≠ 1 (E9.6)", "≠ 1", num(iv.kappa.re * std::sin(al)), 0, 0,
           std::abs(iv.kappa.re * std::sin(al) - 1) > 0.1);
  c.checkResidual("Frenet equations hold (finite differences)", std::max(iv.frenetN, iv.frenetT), 1e-8);
  // E9.5: with τ̌ = cot α − εd and dť/dλ = −τ̌ň, the printed dť/dλ' = +(cot α − εd)ň has the wrong sign
  // for one of the two; soma's frame: dť/dλ' = −τ̌ň with τ̌ = cot α + εd.
  c.note("E9.5: the printed dť/dλ' = +(cot α − εd)ň contradicts dť/dλ = −τ̌ň with τ̌ = cot α − εd. Measured (this hand): "
         "τ̌/κ₀ = " + num(t0) + " + ε" + num(t1) + ", Frenet residuals " + num(iv.frenetN) + ", " + num(iv.frenetT) + ".");
  // The striction curve is the throat circle.
  double throat = 0;
  for (const double th : {0.0, 1.0, 2.5}) {
    const V3 s = r.surface().strictionPoint(th);
    throat = std::max(throat, std::abs(s.norm() - d) + std::abs(s.z()));
  }
  c.checkResidual("striction curve = throat circle (radius d, z = 0)", throat, tolId(64));
  c.checkNear("d = 0 (cone): κ₁ = 0", 0.0, bookRegulus(0.0, al).surface().frame(0.3).kappa1, tolId());
  c.checkNear("α = π/2 (plane): κ₁ = 0", 0.0, bookRegulus(d, pi<double>() / 2).surface().frame(0.3).kappa1, tolId());
  c.checkEqual("α → 0 (generator ∥ axis): cylindrical, α = 1e-9 rejected / α = 1e-6 accepted", "cyl/non",
               std::string(bookRegulus(d, 1e-9).surface().isCylindrical(0.0) ? "cyl" : "non") + "/" +
                   (bookRegulus(d, 1e-6).surface().isCylindrical(0.0) ? "cyl" : "non"));
}

// GF §9.4, GF-9.4-ruled-helicoid
void ruledHelicoid(Context& c) {
  const double d = 0.8, al = 0.6, p = 0.25;
  const auto rs = RuledSurface<double>::sweep(six(V3(0, 0, 1), V3(0, 0, p)), L::pointDirection(V3(d, 0, 0), V3(0, std::sin(al), std::cos(al))));
  const Invariants iv = invariants(rs, 0.7);
  const double k1 = iv.kappa.du / iv.kappa.re, t0 = iv.tau.re / iv.kappa.re, t1 = iv.tau.du / iv.kappa.re;
  c.checkNear("κ₁ = p − d cot α (book p + d cot α, mirror hand: d → −d)", p - d / std::tan(al), k1, 1e-9);
  c.checkNear("τ₀ = cot α", 1 / std::tan(al), t0, 1e-9);
  c.checkNear("τ₁ = p cot α + d (book p cot α − d, mirror hand)", p / std::tan(al) + d, t1, 1e-9);
  c.checkNear("invariants = regulus values × (1 + εp): κ₁ − κ₁(p = 0) = p·κ₀/κ₀", p, k1 - (-d / std::tan(al)), 1e-9);
  double helix = 0;
  for (const double th : {0.0, 1.0, 3.0}) {
    const V3 s = rs.strictionPoint(th);
    helix = std::max(helix, (s - V3(d * std::cos(th), d * std::sin(th), p * th)).norm());
  }
  c.checkResidual("striction curve = helix (d cos θ, d sin θ, pθ)", helix, tolId(256));
}

// GF §9.4, GF-9.4-cylindroid-invariants
void cylindroidInvariants(Context& c) {
  const double r = 0.6;
  const RuledSurface<double> rs(
      [r](const double& t) { return six(V3(std::cos(t), std::sin(t), 0), V3(r * std::cos(2 * t) * V3(-std::sin(t), std::cos(t), 0))); },
      [r](const double& t) {
        return six(V3(-std::sin(t), std::cos(t), 0), V3(-r * V3(std::cos(t) * std::cos(2 * t) - 2 * std::sin(t) * std::sin(2 * t),
                                                                std::sin(t) * std::cos(2 * t) + 2 * std::cos(t) * std::sin(2 * t), 0)));
      });
  double k0 = 0, k1 = 0, nn = 0, st = 0, tt = 0, tau = 0, moment = 0, fd = 0, same = 0;
  for (const double th : {0.2, 0.9, 1.4, 2.7}) {
    const Invariants iv = invariants(rs, th);
    const RuledFrame<double> f = rs.frame(th);
    k0 = std::max(k0, std::abs(iv.kappa.re - 1));
    k1 = std::max(k1, std::abs(iv.kappa.du + 2 * r * std::sin(2 * th)));
    const V6 nBook = six(V3(-std::sin(th), std::cos(th), 0), V3(-r * V3(std::cos(th) * std::cos(2 * th), std::sin(th) * std::cos(2 * th), 0)));
    nn = std::max(nn, (f.n.coords() - nBook).norm());
    st = std::max(st, (f.striction - V3(0, 0, r * std::cos(2 * th))).norm());
    tt = std::max(tt, (f.t.coords() - six(V3(0, 0, 1), V3::Zero())).norm());
    tau = std::max(tau, std::abs(iv.tau.re) + std::abs(iv.tau.du));
    moment = std::max(moment, (V3(0, 0, r * std::cos(2 * th)).cross(V3(std::cos(th), std::sin(th), 0)) - rs.coords(th).tail<3>()).norm());
    const double h = 1e-6;
    fd = std::max(fd, ((rs.coords(th + h) - rs.coords(th - h)) / (2 * h) - rs.derivative(th)).norm());
    // Same surface as GF-6.5.2-cylindroid-principal-form with r_x = r, r_y = −r.
    const Cylindroid<double> cy(six(V3(1, 0, 0), V3(0, r, 0)), six(V3(0, 1, 0), V3(r, 0, 0)));
    // Cylindroid angles are measured from its principal screw (here at 45°): use angleOf.
    same = std::max(same, cy.axis(cy.angleOf(rs.coords(th))).sameAs(rs.generator(th), tolId(1024)) ? 0.0 : 1.0);
  }
  c.checkResidual("moment = s × v with s = (0, 0, r cos 2θ) (convention A)", moment, tolId(64));
  c.checkResidual("printed dľ/dθ (finite differences, h = 1e-6)", fd, 1e-8);
  c.checkResidual("κ₀ = 1", k0, tolId(256));
  c.checkResidual("κ₁ = −2r sin 2θ", k1, tolId(256));
  c.checkResidual("ň = (−sin θ, cos θ, 0) − εr(cos θ cos 2θ, sin θ cos 2θ, 0)", nn, tolId(256));
  c.checkResidual("striction point (0, 0, r cos 2θ)", st, tolId(256));
  c.checkResidual("ť = (0, 0, 1)", tt, tolId(256));
  c.checkResidual("τ₀ = τ₁ = 0 (finite differences)", tau, 1e-8);
  c.checkResidual("same surface as the cylindroid with r_x = r, r_y = −r (GF-6.5.2-cylindroid-principal-form)", same, 0.0);
}

// GF Fig. 9.1, GF-9.4-fig9.1-line-sweeps-regulus
void fig91(Context& c) {
  const double d = 0.8, al = 0.6;
  const Regulus<double> r = bookRegulus(d, al);
  const RuledFrame<double> f = r.surface().frame(0.0);
  c.checkResidual("drawn frame: ľ, ň, ť pairwise perpendicular and meeting at the striction point",
                  std::abs(f.l.direction().dot(f.n.direction())) + std::abs(f.l.direction().dot(f.t.direction())) +
                      std::abs(f.n.direction().dot(f.t.direction())) + f.l.distanceTo(f.striction) + f.n.distanceTo(f.striction) +
                      f.t.distanceTo(f.striction),
                  tolId(64));
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
  auto seg = [&](const L& l, rd::Color col, double rad) {
    const L u = l.normalized();
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

// §9.4 uses ch. 6's helpers (namespace gf06) but reports under ch. 9.
constexpr const char* kChapter = kChapter9;
SOMA_STUDY_DOUBLE("GF-9.4-lines-as-dual-vectors", "Lines as unit dual vectors; ruled surfaces ľ(λ) = v + εr × v", "GF §9.4", dualVectors);
SOMA_STUDY_DOUBLE("GF-9.4-common-perpendicular-dual-angle", "Dual angle α + εd and the common perpendicular ľ₁ × ľ₂ = sin(α̌)ň", "GF §9.4", dualAngleStudy);
SOMA_STUDY_DOUBLE("GF-9.4-striction-and-dual-frenet", "Striction point, distribution parameter and the dual Frenet frame (E9.4)", "GF §9.4", strictionFrenet);
SOMA_STUDY_DOUBLE("GF-9.4-hyperboloid-regulus-invariants", "Invariants of a regulus: κ₁ = ∓d cot α, τ̌ = cot α ± εd (E9.5, E9.6)", "GF §9.4", regulusInvariants);
SOMA_STUDY_DOUBLE("GF-9.4-ruled-helicoid", "Ruled helicoid: regulus invariants times (1 + εp), helical striction curve", "GF §9.4", ruledHelicoid);
SOMA_STUDY_DOUBLE("GF-9.4-cylindroid-invariants", "Cylindroid as a ruled surface: κ₁ = −2r sin 2θ, striction on the nodal line", "GF §9.4", cylindroidInvariants);
SOMA_STUDY_DOUBLE("GF-9.4-fig9.1-line-sweeps-regulus", "Fig. 9.1: a line sweeps out a cylindrical regulus", "GF §9.4", fig91);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
