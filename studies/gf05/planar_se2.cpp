// Studies of GF §5.3 (opening part): SE(2) as 3×3 matrices, its Lie algebra, dexp, the
// closed-form BCH, the circle conditions (C1)–(C4) and the centre of curvature. Every study runs in
// the asked scalar (--scalar); the book's and the catalogue's numbers are exact fractions in S.
#include "gf05/planar_common.hpp"

namespace soma::studies::gf05p::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::atan2;
using std::cos;
using std::sin;
using std::tan;

// GF §5.3, GF-5.3-se2-rotation-about-point
template <class S> void rotationAboutPoint(Context& c) {
  using M3 = Mat3<S>;
  using P = Vec2<S>;
  S worst(0), worstC(0);
  for (int k = 0; k < 12; ++k) {
    const S th = frac<S>(-299 + 50 * k, 100), cx = frac<S>(3 * k - 11, 10), cy = frac<S>(7 - 2 * k, 10);
    M3 book;
    book << cos(th), -sin(th), cx - cx * cos(th) + cy * sin(th), sin(th), cos(th), cy - cx * sin(th) - cy * cos(th), S(0), S(0), S(1);
    const SE2<S> g = SE2<S>::rotationAbout(th, P(cx, cy));
    worst = maxOf(worst, S((g.matrix() - book).cwiseAbs().maxCoeff()));
    // c = (I − Rᵀ)t/Δ, Δ = 2 − 2cos θ (printed "1/Λ": OCR, E5.8)
    const Mat2<S> R = g.rotation();
    // Δ·c = (I − Rᵀ)t (the division by Δ = 2 − 2cos θ amplifies rounding by 1/Δ as θ → 0)
    worstC = maxOf(worstC, S(((S(2) - S(2) * cos(th)) * P(cx, cy) - (Mat2<S>::Identity() - R.transpose()) * g.translation()).norm()));
  }
  c.checkResidual("explicit matrix of a rotation about c = SE2::rotationAbout (12 angles in (−π, π]; 16 ε)", worst, tol<S>(16));
  c.checkResidual("centre: Δc = (I − Rᵀ)t, Δ = 2 − 2cos θ (64 ε)", worstC, tol<S>(64));
  // θ = π and θ → 0
  const P half0(frac<S>(1, 4), frac<S>(-1, 2));
  const SE2<S> half = SE2<S>::rotationAbout(pi<S>(), half0);
  c.checkResidual("θ = π: centre recovered (16 ε)", S((half.centre() - half0).norm()), tol<S>(16));
  const S tiny = frac<S>(1, 1000000);
  if (tiny > Tolerance<S>::sqrtEpsilon()) {
    const SE2<S> small(tiny, P(tiny, S(0)));  // t/θ = (1, 0): centre = (1/2, ½cot(θ/2)·t_x ≈ 1)
    const S want = cos(tiny / S(2)) / sin(tiny / S(2)) / S(2) * tiny;
    c.checkNear("θ = 1e-6, t = (1e-6, 0): centre_y = ½cot(θ/2)·t_x (64 ε)", want, S(small.centre()(1)), tol<S>(64));
  } else {
    c.note("Skipped in this scalar: the centre at θ = 1e-6 (below √ε = " + toString(toDouble(Tolerance<S>::sqrtEpsilon()), 3) +
           ", SE2::centre treats the motion as a pure translation).");
  }
  bool threw = false;
  try {
    (void)SE2<S>(S(0), P(S(1), S(0))).centre();
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("θ = 0 (pure translation): the centre is undefined → InvalidInput", 1, threw ? 1 : 0);
}

template <class S> Mat3<S> generator(const Vec2<S>& cc) {
  Mat3<S> C;
  C << S(0), S(-1), cc(1), S(1), S(0), -cc(0), S(0), S(0), S(0);
  return C;
}

// GF §5.3, GF-5.3-se2-algebra-exp-ad
template <class S> void algebraExpAd(Context& c) {
  using M3 = Mat3<S>;
  using P = Vec2<S>;
  const P cc(frac<S>(1, 3), frac<S>(-4, 10));
  const M3 C = generator(cc);
  c.checkResidual("C³ + C = 0 (8 ε)", S((C * C * C + C).cwiseAbs().maxCoeff()), tol<S>(8));
  S worst(0);
  for (const S th : {S(-3), S(-1), frac<S>(1, 100000000), frac<S>(1, 2), pi<S>()}) {
    const M3 e = M3::Identity() + sin(th) * C + (S(1) - cos(th)) * C * C;
    worst = maxOf(worst, S((e - SE2<S>::rotationAbout(th, cc).matrix()).cwiseAbs().maxCoeff()));
  }
  c.checkResidual("e^{θC} = I + sin θ C + (1 − cos θ)C² = rotation about c (5 angles incl. 1e-8, π; 16 ε)", worst, tol<S>(16));
  // L ↔ l = (a_x, a_y, θ): L = [[−θE₂, E₂a],[0, 0]]; soma's tangent (ω, v) with v = E₂a.
  const P a1(frac<S>(3, 10), frac<S>(-12, 10)), a2(frac<S>(-7, 10), frac<S>(4, 10));
  const S t1 = frac<S>(9, 10), t2 = frac<S>(-35, 100);
  auto L = [](const P& a, const S& th) {
    M3 m = M3::Zero();
    m.template block<2, 2>(0, 0) << S(0), -th, th, S(0);  // −θE₂
    m.template block<2, 1>(0, 2) = E2(a);
    return m;
  };
  const SE2Tangent<S> x1(t1, E2(a1)), x2(t2, E2(a2));
  c.checkResidual("book's L(l) = soma's hat(ω, v = E₂a) (4 ε)", S((L(a1, t1) - x1.hat()).cwiseAbs().maxCoeff()), tol<S>(4));
  const M3 br = L(a1, t1) * L(a2, t2) - L(a2, t2) * L(a1, t1);
  c.checkResidual("ad(l₁) l₂ = vee[L₁, L₂] (8 ε)", S((SE2Tangent<S>::vee(br).coeffs() - x1.ad() * x2.coeffs()).cwiseAbs().maxCoeff()),
                  tol<S>(8));
  // θ = 0: a translation generator [[0, a],[0, 0]] (C undefined: centre at infinity)
  const SE2Tangent<S> tr(S(0), frac<S>(6, 10), frac<S>(-2, 10));
  c.checkResidual("θ = 0: exp of a translation generator is the translation (4 ε)",
                  S((tr.exp().translation() - P(frac<S>(6, 10), frac<S>(-2, 10))).norm()), tol<S>(4));
}

// GF §5.3, GF-5.3-se2-dexp (erratum E5.7: L_d = (de^L/dt)e^{−L}, not (de^L/dt)L^{−1})
template <class S> void dexp(Context& c) {
  using M3 = Mat3<S>;
  const SE2Tangent<S> l(frac<S>(11, 10), frac<S>(4, 10), frac<S>(-9, 10)), ld(frac<S>(-3, 10), frac<S>(8, 10), frac<S>(5, 10));
  // Central differences: truncation h²·|d³e^L| ≈ 1e-10, rounding 16 ε/h; tolerance 1e-9.
  const S fdTol = frac<S>(1, 1000000000);
  if (fdResolves<S>(c, "l_d by central differences", 1e-5, 1, fdTol)) {
    const S h = frac<S>(1, 100000);
    const M3 dE = ((l + ld * h).exp().matrix() - (l - ld * h).exp().matrix()) / (S(2) * h);
    const M3 Ld = dE * l.exp().inverse().matrix();
    const SE2Tangent<S> ldBook(l.ljac() * ld.coeffs());
    c.checkResidual("l_d = (I + (1−cosθ)/θ² L + (θ−sinθ)/θ³ L²) l̇ equals vee((de^L/dt) e^{−L}) (central differences, h = 1e-5)",
                    S((SE2Tangent<S>::vee(Ld).coeffs() - ldBook.coeffs()).cwiseAbs().maxCoeff()), fdTol);
  }
  c.checkNear("\"(de^L/dt)L⁻¹\" cannot be meant: det L = 0 (L is singular, E5.7)", S(0), S(l.hat().determinant()), S(0));
  // θ → 0: the coefficients' Taylor branch; θ → 2π: dexp singular
  const SE2Tangent<S> s(frac<S>(1, 1000000000), frac<S>(4, 10), frac<S>(-9, 10));
  // The series Σ ad^k/(k+1)!: ad^k is O(θ^(k−1)) for k ≥ 2, so twelve terms reach 1e-99, below ε of every rung.
  M3 series = M3::Identity(), term = M3::Identity();
  for (int k = 1; k <= 12; ++k) {
    term = term * s.ad() / S(k + 1);
    series += term;
  }
  c.checkResidual("θ = 1e-9: Jl = I + ad/2 + ad²/6 + … (the series Σ ad^k/(k+1)!, twelve terms; 8 ε)",
                  S((s.ljac() - series).cwiseAbs().maxCoeff()), tol<S>(8));
  bool threw = false;
  try {
    (void)SE2Tangent<S>(S(2) * pi<S>(), frac<S>(1, 10), frac<S>(2, 10)).ljacinv();
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("θ = 2π: dexp is singular → InvalidInput from ljacinv", 1, threw ? 1 : 0);
}

// GF §5.3, GF-5.3-se2-bch (catalogue instance)
template <class S> void bch(Context& c) {
  using M3 = Mat3<S>;
  using P = Vec2<S>;
  const P c1(frac<S>(1, 3), frac<S>(-4, 10)), c2(frac<S>(3, 4), frac<S>(1, 2));
  const S t1 = frac<S>(7, 10), t2 = frac<S>(-11, 10);
  const M3 C1 = generator(c1), C2 = generator(c2);
  const S T1 = tan(t1 / S(2)), T2 = tan(t2 / S(2)), den = T1 + T2;
  const S al = T1 / den, be = T2 / den, ga = T1 * T2 / den, phi = t1 + t2;
  const M3 X = phi * (al * C1 + be * C2 + ga * (C1 * C2 - C2 * C1));
  const SE2<S> lhs = SE2<S>::rotationAbout(t1, c1) * SE2<S>::rotationAbout(t2, c2);
  const SE2<S> rhs = SE2Tangent<S>::vee(X).exp();
  c.checkResidual("e^{θ₁C₁}e^{θ₂C₂} = e^{φ(αC₁ + βC₂ + γ[C₁, C₂])} (c₁ = (1/3, −2/5), c₂ = (3/4, 1/2), θ = 0.7, −1.1; 64 ε)",
                  S((lhs.matrix() - rhs.matrix()).cwiseAbs().maxCoeff()), tol<S>(64));
  // the composite centre is the third vertex of the pole triangle: angles −θ₁/2 at c₁, −θ₂/2 at c₂
  const P cc = lhs.centre();
  const S a1 = atan2(cross2<S>(c2 - c1, cc - c1), (c2 - c1).dot(cc - c1));
  const S a2 = atan2(cross2<S>(cc - c2, c1 - c2), (cc - c2).dot(c1 - c2));
  // equal mod π: |sin(difference)| = 0
  c.checkResidual("pole triangle: line c₁c is line c₁c₂ turned by θ₁/2 (mod π: |sin| of the difference; 64 ε)",
                  S(abs(sin(a1 - t1 / S(2)))), tol<S>(64));
  c.checkResidual("pole triangle: line c₂c is line c₂c₁ turned by −θ₂/2 (mod π: |sin| of the difference; 64 ε)",
                  S(abs(sin(-a2 + t2 / S(2)))), tol<S>(64));
  // θ₁ + θ₂ = 0: a translation, tan sum 0 (the formula is singular)
  const SE2<S> tr = SE2<S>::rotationAbout(frac<S>(1, 2), c1) * SE2<S>::rotationAbout(frac<S>(-1, 2), c2);
  c.checkResidual("θ₁ + θ₂ = 0: the composite is a translation (angle 0), where the formula divides by 0 (4 ε)", S(abs(tr.angle())),
                  tol<S>(4));
}

// GF §5.3, GF-5.3-circle-derivative-conditions: the crank pin of the catalogue 4-bar
template <class S> void circleConditions(Context& c) {
  using P = Vec2<S>;
  const MotionJet<S> jet = catalogueJet<S>();
  const FourBar<S> fb = catalogueBar<S>();
  const P pin = fb.solve(S(1), 1)->c2, cen = fb.c1();
  const auto d = jet.pointDerivatives(pin);  // analytic (Taylor arithmetic through the position analysis)
  const P u = pin - cen;
  c.checkResidual("(C1) ṗ·(p − c) = 0 (crank pin, analytic derivatives; 64 ε)", S(abs(d[1].dot(u))), tol<S>(64));
  c.checkResidual("(C2) p̈·(p − c) + ṗ·ṗ = 0 (64 ε)", S(abs(d[2].dot(u) + d[1].dot(d[1]))), tol<S>(64));
  c.checkResidual("(C3) p⃛·(p − c) + 3p̈·ṗ = 0 (256 ε)", S(abs(d[3].dot(u) + S(3) * d[2].dot(d[1]))), tol<S>(256));
  c.checkResidual("(C4) p⁗·(p − c) + 4p⃛·ṗ + 3p̈·p̈ = 0 (1024 ε)",
                  S(abs(d[4].dot(u) + S(4) * d[3].dot(d[1]) + S(3) * d[2].dot(d[2]))), tol<S>(1024));
  // rotation about a fixed c with a non-uniform law: the printed p, ṗ, p̈, p⃛
  const P cc(frac<S>(2, 10), frac<S>(-4, 10)), p(frac<S>(13, 10), frac<S>(9, 10));
  const std::array<S, 5> law{S(0), frac<S>(8, 10), frac<S>(5, 10), frac<S>(-3, 10), frac<S>(2, 10)};
  const MotionJet<S> rot = MotionJet<S>::screw(SE2<S>(), SE2Tangent<S>(S(1), cc(1), -cc(0)), law);
  const auto r = rot.pointDerivatives(p);
  const S w = law[1], wd = law[2], wdd = law[3];
  const P q = p - cc;
  c.checkResidual("ṗ = −ωE₂(p − c) (16 ε)", S((r[1] + w * E2(q)).norm()), tol<S>(16));
  c.checkResidual("p̈ = −ω̇E₂(p − c) − ω²(p − c) (16 ε)", S((r[2] - (-wd * E2(q) - w * w * q)).norm()), tol<S>(16));
  c.checkResidual("p⃛ = −ω̈E₂(p − c) − 3ω̇ω(p − c) + ω³E₂(p − c) (64 ε)",
                  S((r[3] - (-wdd * E2(q) - S(3) * wd * w * q + w * w * w * E2(q))).norm()), tol<S>(64));
  c.note("Derivatives come from Taylor-series arithmetic pushed through the closed-form position analysis (exact to "
         "rounding), so the fourth-order conditions hold to rounding instead of the 1e-8 of finite differences.");
}

// GF §5.3, GF-5.3-curvature-centre: the evolute of an ellipse
template <class S> void curvatureCentreStudy(Context& c) {
  using P = Vec2<S>;
  const S a(2), b(1);
  S worst(0);
  for (int k = 0; k < 16; ++k) {
    const S t = frac<S>(10 + 39 * k, 100);
    const S ct = cos(t), st = sin(t);
    const P p(a * ct, b * st), pd(-a * st, b * ct), pdd(-a * ct, -b * st);
    P cc;
    if (!curvatureCentre<S>(p, pd, pdd, cc)) continue;
    const P evolute((a * a - b * b) / a * ct * ct * ct, (b * b - a * a) / b * st * st * st);
    worst = maxOf(worst, S((cc - evolute).norm()));
  }
  c.checkResidual("centre from (C1), (C2) = evolute of the ellipse x²/4 + y² = 1 (16 points; 64 ε)", worst, tol<S>(64));
  P cc;
  const bool ok = curvatureCentre<S>(P(S(0), S(0)), P(S(1), S(2)), P(S(2), S(4)), cc);
  c.checkEqual("inflection (det[ṗ, p̈] = 0): the centre is at infinity → reported as none", 0, ok ? 1 : 0);
}

}  // namespace

SOMA_STUDY_SCALAR("GF-5.3-se2-rotation-about-point", "Rotation about a point as a 3×3 matrix; its centre (I − Rᵀ)t/Δ", "GF §5.3",
                  rotationAboutPoint);
SOMA_STUDY_SCALAR("GF-5.3-se2-algebra-exp-ad", "se(2): C³ + C = 0, e^{θC}, L ↔ (a, θ), ad", "GF §5.3", algebraExpAd);
SOMA_STUDY_SCALAR("GF-5.3-se2-dexp", "dexp of SE(2) (erratum E5.7)", "GF §5.3", dexp);
SOMA_STUDY_SCALAR("GF-5.3-se2-bch", "Closed-form BCH of two planar rotations; the pole triangle", "GF §5.3", bch);
SOMA_STUDY_SCALAR("GF-5.3-circle-derivative-conditions", "Derivatives of a point on a circle, (C1)–(C4)", "GF §5.3", circleConditions);
SOMA_STUDY_SCALAR("GF-5.3-curvature-centre", "Centre of curvature from (C1), (C2)", "GF §5.3", curvatureCentreStudy);

}  // namespace soma::studies::gf05p::SOMA_UNITY_ID
