// Studies of GF §5.3 (opening part): SE(2) as 3×3 matrices, its Lie algebra, dexp, the
// closed-form BCH, the circle conditions (C1)–(C4) and the centre of curvature.
#include "gf05/planar_common.hpp"

namespace soma::studies::gf05p::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using M3 = Mat3<double>;

// GF §5.3, GF-5.3-se2-rotation-about-point
void rotationAboutPoint(Context& c) {
  double worst = 0, worstC = 0;
  for (int k = 0; k < 12; ++k) {
    const double th = -3.0 + 0.5 * k + 0.01, cx = 0.3 * k - 1.1, cy = 0.7 - 0.2 * k;
    M3 book;
    book << std::cos(th), -std::sin(th), cx - cx * std::cos(th) + cy * std::sin(th), std::sin(th), std::cos(th),
        cy - cx * std::sin(th) - cy * std::cos(th), 0, 0, 1;
    const SE2<double> g = SE2<double>::rotationAbout(th, V2(cx, cy));
    worst = std::max(worst, (g.matrix() - book).cwiseAbs().maxCoeff());
    // c = (I − Rᵀ)t/Δ, Δ = 2 − 2cos θ (printed "1/Λ": OCR, E5.8)
    const Mat2<double> R = g.rotation();
    // Δ·c = (I − Rᵀ)t (the division by Δ = 2 − 2cos θ amplifies rounding by 1/Δ as θ → 0)
    worstC = std::max(worstC, ((2 - 2 * std::cos(th)) * V2(cx, cy) - (Mat2<double>::Identity() - R.transpose()) * g.translation()).norm());
  }
  c.checkResidual("explicit matrix of a rotation about c = SE2::rotationAbout (12 angles in (−π, π])", worst, tol(16));
  c.checkResidual("centre: Δc = (I − Rᵀ)t, Δ = 2 − 2cos θ", worstC, tol(64));
  // θ = π and θ → 0
  const SE2<double> half = SE2<double>::rotationAbout(3.14159265358979323846, V2(0.25, -0.5));
  c.checkResidual("θ = π: centre recovered", (half.centre() - V2(0.25, -0.5)).norm(), tol(16));
  const SE2<double> small(1e-6, V2(1e-6, 0));  // t/θ = (1, 0): centre ≈ (0.5, 500000)
  c.checkNear("θ = 1e-6, t = (1e-6, 0): centre_y = ½cot(θ/2)·t_x ≈ 1/θ (far away)", 0.5 / std::tan(0.5e-6) * 1e-6,
              small.centre()(1), 1e-3);
  bool threw = false;
  try {
    (void)SE2<double>(0.0, V2(1, 0)).centre();
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("θ = 0 (pure translation): the centre is undefined → InvalidInput", 1, threw ? 1 : 0);
}

// GF §5.3, GF-5.3-se2-algebra-exp-ad
void algebraExpAd(Context& c) {
  const V2 cc(1.0 / 3, -0.4);
  M3 C;
  C << 0, -1, cc(1), 1, 0, -cc(0), 0, 0, 0;
  c.checkResidual("C³ + C = 0", (C * C * C + C).cwiseAbs().maxCoeff(), tol(8));
  double worst = 0;
  for (double th : {-3.0, -1.0, 1e-8, 0.5, 3.14159265358979}) {
    const M3 e = M3::Identity() + std::sin(th) * C + (1 - std::cos(th)) * C * C;
    worst = std::max(worst, (e - SE2<double>::rotationAbout(th, cc).matrix()).cwiseAbs().maxCoeff());
  }
  c.checkResidual("e^{θC} = I + sin θ C + (1 − cos θ)C² = rotation about c (5 angles incl. 1e-8, π)", worst, tol(16));
  // L ↔ l = (a_x, a_y, θ): L = [[−θE₂, E₂a],[0, 0]]; soma's tangent (ω, v) with v = E₂a.
  const V2 a1(0.3, -1.2), a2(-0.7, 0.4);
  const double t1 = 0.9, t2 = -0.35;
  auto L = [](const V2& a, double th) {
    M3 m = M3::Zero();
    m.block<2, 2>(0, 0) << 0, -th, th, 0;  // −θE₂
    m.block<2, 1>(0, 2) = E2(a);
    return m;
  };
  const SE2Tangent<double> x1(t1, E2(a1)), x2(t2, E2(a2));
  c.checkResidual("book's L(l) = soma's hat(ω, v = E₂a)", (L(a1, t1) - x1.hat()).cwiseAbs().maxCoeff(), tol(4));
  const M3 br = L(a1, t1) * L(a2, t2) - L(a2, t2) * L(a1, t1);
  c.checkResidual("ad(l₁) l₂ = vee[L₁, L₂]", (SE2Tangent<double>::vee(br).coeffs() - x1.ad() * x2.coeffs()).cwiseAbs().maxCoeff(), tol(8));
  // θ = 0: a translation generator [[0, a],[0, 0]] (C undefined: centre at infinity)
  const SE2Tangent<double> tr(0.0, 0.6, -0.2);
  c.checkResidual("θ = 0: exp of a translation generator is the translation", (tr.exp().translation() - V2(0.6, -0.2)).norm(), tol(4));
}

// GF §5.3, GF-5.3-se2-dexp (erratum E5.7: L_d = (de^L/dt)e^{−L}, not (de^L/dt)L^{−1})
void dexp(Context& c) {
  const SE2Tangent<double> l(1.1, 0.4, -0.9), ld(-0.3, 0.8, 0.5);
  const double h = 1e-5;
  const M3 dE = ((l + ld * h).exp().matrix() - (l - ld * h).exp().matrix()) / (2 * h);
  const M3 Ld = dE * l.exp().inverse().matrix();
  const SE2Tangent<double> ldBook(l.ljac() * ld.coeffs());
  c.checkResidual("l_d = (I + (1−cosθ)/θ² L + (θ−sinθ)/θ³ L²) l̇ equals vee((de^L/dt) e^{−L}) (central differences, h = 1e-5)",
                  (SE2Tangent<double>::vee(Ld).coeffs() - ldBook.coeffs()).cwiseAbs().maxCoeff(), 1e-9);
  c.checkNear("\"(de^L/dt)L⁻¹\" cannot be meant: det L = 0 (L is singular, E5.7)", 0.0, l.hat().determinant(), 0.0);
  // θ → 0: the coefficients' Taylor branch; θ → 2π: dexp singular
  const SE2Tangent<double> s(1e-9, 0.4, -0.9);
  c.checkResidual("θ = 1e-9: Jl = I + ad/2 + ad²/6 (series)",
                  (s.ljac() - (M3::Identity() + s.ad() / 2 + s.ad() * s.ad() / 6)).cwiseAbs().maxCoeff(), tol(8));
  bool threw = false;
  try {
    (void)SE2Tangent<double>(2 * 3.14159265358979323846, 0.1, 0.2).ljacinv();
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("θ = 2π: dexp is singular → InvalidInput from ljacinv", 1, threw ? 1 : 0);
}

// GF §5.3, GF-5.3-se2-bch (catalogue instance)
void bch(Context& c) {
  const V2 c1(1.0 / 3, -0.4), c2(0.75, 0.5);
  const double t1 = 0.7, t2 = -1.1;
  auto gen = [](const V2& cc) {
    M3 C;
    C << 0, -1, cc(1), 1, 0, -cc(0), 0, 0, 0;
    return C;
  };
  const M3 C1 = gen(c1), C2 = gen(c2);
  const double T1 = std::tan(t1 / 2), T2 = std::tan(t2 / 2), den = T1 + T2;
  const double al = T1 / den, be = T2 / den, ga = T1 * T2 / den, phi = t1 + t2;
  const M3 X = phi * (al * C1 + be * C2 + ga * (C1 * C2 - C2 * C1));
  const SE2<double> lhs = SE2<double>::rotationAbout(t1, c1) * SE2<double>::rotationAbout(t2, c2);
  const SE2<double> rhs = SE2Tangent<double>::vee(X).exp();
  c.checkResidual("e^{θ₁C₁}e^{θ₂C₂} = e^{φ(αC₁ + βC₂ + γ[C₁, C₂])} (c₁ = (1/3, −2/5), c₂ = (3/4, 1/2), θ = 0.7, −1.1)",
                  (lhs.matrix() - rhs.matrix()).cwiseAbs().maxCoeff(), tol(64));
  // the composite centre is the third vertex of the pole triangle: angles −θ₁/2 at c₁, −θ₂/2 at c₂
  const V2 cc = lhs.centre();
  const double a1 = std::atan2(cross2<double>(c2 - c1, cc - c1), (c2 - c1).dot(cc - c1));
  const double a2 = std::atan2(cross2<double>(cc - c2, c1 - c2), (cc - c2).dot(c1 - c2));
  auto modPi = [](double x) { return x - 3.14159265358979323846 * std::round(x / 3.14159265358979323846); };
  c.checkResidual("pole triangle: line c₁c is line c₁c₂ turned by θ₁/2 (mod π)", std::abs(modPi(a1 - t1 / 2)), tol(64));
  c.checkResidual("pole triangle: line c₂c is line c₂c₁ turned by −θ₂/2 (mod π)", std::abs(modPi(-a2 + t2 / 2)), tol(64));
  // θ₁ + θ₂ = 0: a translation, tan sum 0 (the formula is singular)
  const SE2<double> tr = SE2<double>::rotationAbout(0.5, c1) * SE2<double>::rotationAbout(-0.5, c2);
  c.checkResidual("θ₁ + θ₂ = 0: the composite is a translation (angle 0), where the formula divides by 0", std::abs(tr.angle()), tol(4));
}

// GF §5.3, GF-5.3-circle-derivative-conditions: the crank pin of the catalogue 4-bar
void circleConditions(Context& c) {
  const MotionJet<double> jet = catalogueJet();
  const FourBar<double> fb = catalogueBar();
  const V2 pin = fb.solve(1.0, 1)->c2, cen = fb.c1();
  const auto d = jet.pointDerivatives(pin);  // analytic (Taylor arithmetic through the position analysis)
  const V2 u = pin - cen;
  c.checkResidual("(C1) ṗ·(p − c) = 0 (crank pin, analytic derivatives)", std::abs(d[1].dot(u)), tol(64));
  c.checkResidual("(C2) p̈·(p − c) + ṗ·ṗ = 0", std::abs(d[2].dot(u) + d[1].dot(d[1])), tol(64));
  c.checkResidual("(C3) p⃛·(p − c) + 3p̈·ṗ = 0", std::abs(d[3].dot(u) + 3 * d[2].dot(d[1])), tol(256));
  c.checkResidual("(C4) p⁗·(p − c) + 4p⃛·ṗ + 3p̈·p̈ = 0", std::abs(d[4].dot(u) + 4 * d[3].dot(d[1]) + 3 * d[2].dot(d[2])), tol(1024));
  // rotation about a fixed c with a non-uniform law: the printed p, ṗ, p̈, p⃛
  const V2 cc(0.2, -0.4), p(1.3, 0.9);
  const std::array<double, 5> law{0, 0.8, 0.5, -0.3, 0.2};
  const MotionJet<double> rot = MotionJet<double>::screw(SE2<double>(), SE2Tangent<double>(1.0, cc(1), -cc(0)), law);
  const auto r = rot.pointDerivatives(p);
  const double w = law[1], wd = law[2], wdd = law[3];
  const V2 q = p - cc;
  c.checkResidual("ṗ = −ωE₂(p − c)", (r[1] + w * E2(q)).norm(), tol(16));
  c.checkResidual("p̈ = −ω̇E₂(p − c) − ω²(p − c)", (r[2] - (-wd * E2(q) - w * w * q)).norm(), tol(16));
  c.checkResidual("p⃛ = −ω̈E₂(p − c) − 3ω̇ω(p − c) + ω³E₂(p − c)", (r[3] - (-wdd * E2(q) - 3 * wd * w * q + w * w * w * E2(q))).norm(),
                  tol(64));
  c.note("Derivatives come from Taylor-series arithmetic pushed through the closed-form position analysis (exact to "
         "rounding), so the fourth-order conditions hold to ~1e-14 instead of the 1e-8 of finite differences.");
}

// GF §5.3, GF-5.3-curvature-centre: the evolute of an ellipse
void curvatureCentreStudy(Context& c) {
  const double a = 2, b = 1;
  double worst = 0;
  for (int k = 0; k < 16; ++k) {
    const double t = 0.1 + 0.39 * k;
    const V2 p(a * std::cos(t), b * std::sin(t)), pd(-a * std::sin(t), b * std::cos(t)), pdd(-a * std::cos(t), -b * std::sin(t));
    V2 cc;
    if (!curvatureCentre<double>(p, pd, pdd, cc)) continue;
    const V2 evolute((a * a - b * b) / a * std::pow(std::cos(t), 3), (b * b - a * a) / b * std::pow(std::sin(t), 3));
    worst = std::max(worst, (cc - evolute).norm());
  }
  c.checkResidual("centre from (C1), (C2) = evolute of the ellipse x²/4 + y² = 1 (16 points)", worst, tol(64));
  V2 cc;
  const bool ok = curvatureCentre<double>(V2(0, 0), V2(1, 2), V2(2, 4), cc);
  c.checkEqual("inflection (det[ṗ, p̈] = 0): the centre is at infinity → reported as none", 0, ok ? 1 : 0);
}

}  // namespace

SOMA_STUDY({.id = "GF-5.3-se2-rotation-about-point", .title = "Rotation about a point as a 3×3 matrix; its centre (I − Rᵀ)t/Δ",
            .source = "GF §5.3", .chapter = kChapter, .scalarGeneric = false, .run = rotationAboutPoint});
SOMA_STUDY({.id = "GF-5.3-se2-algebra-exp-ad", .title = "se(2): C³ + C = 0, e^{θC}, L ↔ (a, θ), ad", .source = "GF §5.3",
            .chapter = kChapter, .scalarGeneric = false, .run = algebraExpAd});
SOMA_STUDY({.id = "GF-5.3-se2-dexp", .title = "dexp of SE(2) (erratum E5.7)", .source = "GF §5.3", .chapter = kChapter,
            .scalarGeneric = false, .run = dexp});
SOMA_STUDY({.id = "GF-5.3-se2-bch", .title = "Closed-form BCH of two planar rotations; the pole triangle", .source = "GF §5.3",
            .chapter = kChapter, .scalarGeneric = false, .run = bch});
SOMA_STUDY({.id = "GF-5.3-circle-derivative-conditions", .title = "Derivatives of a point on a circle, (C1)–(C4)",
            .source = "GF §5.3", .chapter = kChapter, .scalarGeneric = false, .run = circleConditions});
SOMA_STUDY({.id = "GF-5.3-curvature-centre", .title = "Centre of curvature from (C1), (C2)", .source = "GF §5.3",
            .chapter = kChapter, .scalarGeneric = false, .run = curvatureCentreStudy});

}  // namespace soma::studies::gf05p::SOMA_UNITY_ID
