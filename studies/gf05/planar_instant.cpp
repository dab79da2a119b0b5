// Studies of GF §5.3.1–5.3.5: instantaneous invariants of a planar motion on the catalogue
// 4-bar's coupler motion, each against a second method; errata E5.9–E5.15 shown failing as
// printed and passing corrected.
#include "gf05/planar_common.hpp"

namespace soma::studies::gf05p::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

struct Setup {
  FourBar<double> fb = catalogueBar();
  MotionJet<double> jet = catalogueJet();
  InstantInvariants<double> inv = InstantInvariants<double>::fromJet(catalogueJet());
  V2 c2 = catalogueBar().solve(1.0, 1)->c2, c3 = catalogueBar().solve(1.0, 1)->c3;
};

double worstDerivative(const Setup& s, int k, const std::vector<V2>& pts) {
  double w = 0;
  for (const V2& p : pts) {
    const auto a = s.jet.pointDerivatives(p), b = s.inv.pointDerivatives(p);
    w = std::max(w, (a[k] - b[k]).norm() / (1 + a[k].norm()));
  }
  return w;
}
std::vector<V2> samplePoints() { return {V2(0.4, 1.7), V2(-1, 2), V2(2.5, -0.5), V2(1, 1), V2(-3, -2)}; }

// GF §5.3.1, GF-5.3.1-lamina-derivatives (erratum E5.9)
void lamina(Context& c) {
  Setup s;
  c.checkResidual("(P1) ṗ = −ωE₂(p − r) vs the coupler motion's jet (5 points, relative)", worstDerivative(s, 1, samplePoints()), tol(256));
  c.checkResidual("(P2) p̈ = −ω̇E₂(p − r) + 2ωE₂ṙ − ω²(p − r)", worstDerivative(s, 2, samplePoints()), tol(1024));
  // r(t) is the centre of the finite displacement M(t)M(0)⁻¹: compare with SE2::centre at small t
  const double h = 1e-3;
  const SE2<double> M0 = s.fb.solve(1.0, 1)->coupler;
  auto theta = [&](double t) { return 1.0 + t + 0.15 * t * t - 0.2 * t * t * t / 6; };
  const V2 rp = (s.fb.solve(theta(h), 1)->coupler * M0.inverse()).centre();
  const V2 rm = (s.fb.solve(theta(-h), 1)->coupler * M0.inverse()).centre();
  c.checkResidual("ṙ of soma = (centre(M(h)M(0)⁻¹) − centre(M(−h)M(0)⁻¹))/2h (h = 1e-3, O(h²))",
                  ((rp - rm) / (2 * h) - s.inv.r(1)).norm(), 1e-5);
  // the classical fixed centrode (locus of instantaneous centres) moves twice as fast (E5.9)
  const auto q = fixedCentrode(s.jet);
  const V2 q1(q[0].derivative(1), q[1].derivative(1)), q2(q[0].derivative(2), q[1].derivative(2));
  c.checkResidual("classical centrode: q̇ = 2ṙ", (q1 - 2 * s.inv.r(1)).norm(), tol(1024));
  const V2 rd = s.inv.r(1);
  c.checkResidual("classical centrode: q̈ = 3r̈ − (ω̇/ω)ṙ − ωE₂ṙ",
                  (q2 - (3 * s.inv.r(2) - s.inv.omega(1) / s.inv.omega() * rd - s.inv.omega() * E2(rd))).norm(), tol(4096));
  c.checkPrintedFails("\"t ↦ r(t) is called the fixed centrode\": |q̇ − ṙ| should be 0", "E5.9", (q1 - rd).norm(), 1e-6);
  // the moving centrode: the pole in body coordinates
  const auto mc = movingCentrode(s.jet);
  c.checkResidual("moving centrode at t = 0 = M(0)⁻¹ r", (V2(mc[0].a[0], mc[1].a[0]) - M0.inverse().act(s.inv.pole())).norm(), tol(256));
  c.note("soma computes r(t) = ½t_A + ½cot(θ/2)Jt_A of the relative motion A(t) = M(t)M(0)⁻¹ by Taylor arithmetic "
         "(exact derivatives); the classical fixed centrode q(t) = d + Jḋ/ω is a different curve through the same point.");
}

// GF §5.3.1, GF-5.3.1-euler-savary
void eulerSavary(Context& c) {
  Setup s;
  const V2 p(0.4, 1.7);
  const auto d = s.jet.pointDerivatives(p);
  V2 cc, ce;
  curvatureCentre<double>(p, d[1], d[2], cc);
  s.inv.eulerSavaryCentre(p, ce);
  c.checkResidual("Euler–Savary centre = curvature centre from (C1), (C2) at p = (0.4, 1.7)", (cc - ce).norm(), tol(1024));
  const V2 r = s.inv.pole();
  c.checkResidual("r, p, c collinear", std::abs(cross2<double>(p - r, p - cc)), tol(256));
  const double v = s.inv.r(1).norm();
  const double psi = std::atan2(cross2<double>(p - cc, s.inv.r(1)), (p - cc).dot(s.inv.r(1)));
  const double lhs = 2 * (p - cc).norm() / ((r - p).norm() * (r - cc).norm()) * std::sin(psi);
  c.checkNear("2|p − c| sin ψ /(|r − p||r − c|) (catalogue value)", 0.0802736695293, lhs, 1e-12);
  c.checkNear("… = −ω/v", -s.inv.omega() / v, lhs, tol(4096));
  c.checkResidual("unsigned form −2v|p − c| sin ψ − ω(r − p)·(r − c) = 0",
                  std::abs(-2 * v * (p - cc).norm() * std::sin(psi) - s.inv.omega() * (r - p).dot(r - cc)), tol(1024));
  // with the classical pole speed u = 2v the book's form is off by 2 (E5.9)
  c.checkPrintedFails("Euler–Savary with v = |q̇| (classical centrode speed)", "E5.9", std::abs(lhs + s.inv.omega() / (2 * v)), tol(4096));
  // r between p and c: a point near the pole on the other side
  const V2 p2 = r + 0.3 * (r - p).normalized();
  const auto d2 = s.jet.pointDerivatives(p2);
  V2 c2_, ce2;
  curvatureCentre<double>(p2, d2[1], d2[2], c2_);
  s.inv.eulerSavaryCentre(p2, ce2);
  c.checkResidual("second point (other side of the pole): centres agree", (c2_ - ce2).norm() / (1 + c2_.norm()), tol(4096));
}

// GF §5.3.2, GF-5.3.2-inflection-circle
void inflection(Context& c) {
  Setup s;
  const Circle<double> ci = s.inv.inflectionCircle();
  c.checkNear("centre x (catalogue, world frame)", -9.186780624, ci.centre(0), 5e-9);
  c.checkNear("centre y", 1.363498014, ci.centre(1), 5e-9);
  c.checkNear("radius |ṙ|/|ω|", 12.45738492, ci.radius, 5e-8);
  const V2 ip = s.inv.inflectionPole();
  c.checkNear("inflection pole x", -21.24863767, ip(0), 5e-8);
  c.checkNear("inflection pole y", -1.750670195, ip(1), 5e-9);
  // second method 1: the direct polynomial det[ṗ, p̈] = ω²·(p − r)ᵀ(ω(p − r) − 2E₂ṙ)
  const Poly2<double> P = inflectionCurve(s.jet);
  double worst = 0;
  for (const V2& p : samplePoints())
    worst = std::max(worst, std::abs(P(p(0), p(1)) - s.inv.omega() * s.inv.omega() * s.inv.inflectionResidual(p)) /
                                P.magnitude(p(0), p(1)));
  c.checkResidual("det[ṗ, p̈] (jet) = ω²(p − r)ᵀ(ω(p − r) − 2E₂ṙ) at 5 points (relative)", worst, tol(1024));
  // second method 2: coupler points whose finite-difference path curvature vanishes
  const SE2<double> M0 = s.fb.solve(1.0, 1)->coupler;
  double worstFD = 0;
  int found = 0;
  for (double ang : {0.3, 1.1, 2.0, 4.0}) {
    const V2 dir(std::cos(ang), std::sin(ang));
    const double sStar = 2 * (ci.centre - s.inv.pole()).dot(dir);
    if (sStar <= 0.5) continue;
    double a = 0.5 * sStar, b = 1.5 * sStar;
    auto f = [&](double t) { return fdCurvature(s.fb, 1.0, 1, M0.inverse().act(V2(s.inv.pole() + t * dir))); };
    double fa = f(a);
    if (fa * f(b) > 0) continue;
    for (int it = 0; it < 50; ++it) {
      const double m = 0.5 * (a + b), fm = f(m);
      if (fa * fm <= 0) b = m;
      else {
        a = m;
        fa = fm;
      }
    }
    const V2 p = s.inv.pole() + 0.5 * (a + b) * dir;
    worstFD = std::max(worstFD, std::abs((p - ci.centre).norm() - ci.radius) / ci.radius);
    ++found;
  }
  c.checkEqual("rays from the pole (of 4) on which the sampled-path curvature changes sign: at least 2", 1, found >= 2 ? 1 : 0);
  c.checkResidual("those zero-curvature points lie on the inflection circle (relative, finite differences h = 1e-3)", worstFD, 1e-7);
}

// GF §5.3.3, GF-5.3.3-third-derivative-P3
void p3(Context& c) {
  Setup s;
  c.checkResidual("(P3) vs the jet (5 points, relative)", worstDerivative(s, 3, samplePoints()), tol(4096));
}

// GF §5.3.3, GF-5.3.3-ball-point (errata E5.10, E5.11)
void ball(Context& c) {
  Setup s;
  const double w = s.inv.omega(), wd = s.inv.omega(1);
  const V2 r = s.inv.pole(), rd = s.inv.r(1), rdd = s.inv.r(2);
  auto und = [&](const V2& p, double& d2, double& d3) {
    const auto d = s.jet.pointDerivatives(p);
    d2 = cross2<double>(d[1], d[2]);
    d3 = cross2<double>(d[1], d[3]);
  };
  double a, b;
  und(s.inv.ballPoint(), a, b);
  c.checkResidual("corrected Ball point: det[ṗ, p̈] = 0 (on the inflection circle)", std::abs(a), tol(4096));
  c.checkResidual("corrected Ball point: det[ṗ, p⃛] = 0 (undulation: 4-point contact with its tangent)", std::abs(b), tol(16384));
  // the printed ṗᵀE₂p⃛ has +3ω³(p − r)ᵀṙ (E5.10): compare with the jet at a point
  const V2 p(0.4, 1.7), u = p - r;
  const auto d = s.jet.pointDerivatives(p);
  const double direct = cross2<double>(d[1], d[3]);
  const double corr = 3 * w * w * wd * u.squaredNorm() - 3 * w * w * w * u.dot(rd) - 3 * w * wd * cross2<double>(u, rd) -
                      3 * w * w * cross2<double>(u, rdd);
  const double printed = corr + 6 * w * w * w * u.dot(rd);
  c.checkResidual("ṗᵀE₂p⃛ = 3ω²ω̇|u|² − 3ω³uᵀṙ − 3ωω̇uᵀE₂ṙ − 3ω²uᵀE₂r̈ (corrected sign)", std::abs(direct - corr), tol(4096));
  c.checkPrintedFails("ṗᵀE₂p⃛ with +3ω³(p − r)ᵀṙ", "E5.10", std::abs(direct - printed), tol(4096));
  // printed x and λ (E5.11): catalogue residuals −3.92 and 20.1
  const V2 xP = w * w * rd + wd * E2(rd) - w * E2(rdd);
  const double lamP = 2 * cross2<double>(xP, rd) / (w * xP.squaredNorm());
  double pa, pb;
  und(r + lamP * E2(xP), pa, pb);
  c.checkNear("printed x, λ: det[ṗ, p̈] (catalogue −3.92)", -3.92, pa, 0.01);
  c.checkNear("printed x, λ: det[ṗ, p⃛] (catalogue 20.1)", 20.1, pb, 0.1);
  c.checkPrintedFails("Ball point from the printed x = ω²ṙ + ω̇E₂ṙ − ωE₂r̈ and λ = 2xᵀE₂ṙ/ωx²", "E5.11", std::abs(pa) + std::abs(pb), 1e-6);
}

// GF §5.3.4, GF-5.3.4-cubic-stationary-curvature
void cubic(Context& c) {
  Setup s;
  const Poly2<double> det = stationaryCurvatureCurve(s.jet);
  c.checkEqual("(ṗ·ṗ)det[ṗ, p⃛] − 3(p̈·ṗ)det[ṗ, p̈]: degree after the quartic terms cancel", 3, det.degree(tol(64)));
  double worst = 0;
  for (const V2& p : samplePoints())
    worst = std::max(worst, std::abs(det(p(0), p(1)) - s.inv.stationaryCurvatureCubic(p)) / det.magnitude(p(0), p(1)));
  c.checkResidual("book's cubic (with r̈ of the finite-pole curve) = the determinant (5 points, relative)", worst, tol(1024));
  const double m = det.magnitude(s.c2(0), s.c2(1));
  c.checkResidual("crank pin c2 is on the cubic (relative)", std::abs(s.inv.stationaryCurvatureCubic(s.c2)) / m, tol(1024));
  c.checkResidual("rocker pin c3 is on the cubic (relative)", std::abs(s.inv.stationaryCurvatureCubic(s.c3)) / m, tol(1024));
  // with the classical centrode's q̈ in place of r̈ (E5.9): catalogue 12.37
  const auto q = fixedCentrode(s.jet);
  std::array<V2, 4> rr{s.inv.r(0), s.inv.r(1), V2(q[0].derivative(2), q[1].derivative(2)), s.inv.r(3)};
  const InstantInvariants<double> wrong({s.inv.omega(0), s.inv.omega(1), s.inv.omega(2), s.inv.omega(3)}, rr);
  c.checkNear("cubic at c2 with q̈ in place of r̈ (catalogue 12.37)", 12.37, wrong.stationaryCurvatureCubic(s.c2), 0.01);
  c.checkPrintedFails("cubic with the classical centrode's q̈", "E5.9", std::abs(wrong.stationaryCurvatureCubic(s.c2)) / m, 1e-6);
  // second method: a point of the cubic has stationary path curvature (sampled: κ(θ₁ ± h) symmetric)
  const auto bp = burmesterPoints(s.jet);
  (void)bp;
  const SE2<double> M0 = s.fb.solve(1.0, 1)->coupler;
  const auto pts = sampleCurve(det, -6.0, 6.0, -6.0, 6.0, 24);
  // rate dκ/dθ₁ / κ on the cubic vs at the same points shifted 0.5 off it (control)
  std::vector<double> on, off;
  auto rate = [&](const V2& p) {
    const V2 body = M0.inverse().act(p);
    const double h = 2e-3;
    const double k1 = fdCurvature(s.fb, 1.0 + h, 1, body), k0 = fdCurvature(s.fb, 1.0 - h, 1, body);
    return std::abs(k1 - k0) / (2 * h) / (std::abs(fdCurvature(s.fb, 1.0, 1, body)) + 1e-3);
  };
  const Poly2<double> gx = det.dx(), gy = det.dy();
  for (const V2& p : pts) {
    if ((p - s.inv.pole()).norm() < 0.5) continue;
    const V2 n = V2(gx(p(0), p(1)), gy(p(0), p(1))).normalized();
    on.push_back(rate(p));
    off.push_back(rate(p + 0.5 * n));
  }
  std::sort(on.begin(), on.end());
  std::sort(off.begin(), off.end());
  c.checkEqual("sampled points of the cubic in [−6, 6]² (≥ 30)", 1, on.size() >= 30 ? 1 : 0);
  c.record("median |dκ/dθ₁|/κ on the cubic (sampled paths) ≪ median 0.5 off it", "< 0.01 × off-cubic median",
           toString(on[on.size() / 2], 3) + " vs " + toString(off[off.size() / 2], 3), on[on.size() / 2],
           0.01 * off[off.size() / 2], on[on.size() / 2] < 0.01 * off[off.size() / 2]);
  if (c.makeFigures()) {
    render::Plot plot;
    plot.title = "Cubic of stationary curvature, catalogue 4-bar at θ₁ = 1";
    plot.equalAspect = true;
    plot.x.label = "x";
    plot.y.label = "y";
    plot.x.min = -6;
    plot.x.max = 5;
    plot.y.min = -4;
    plot.y.max = 6;
    std::vector<double> xs, ys;
    for (const V2& p : sampleCurve(det, -7.0, 6.0, -5.0, 7.0, 400)) {
      xs.push_back(p(0));
      ys.push_back(p(1));
    }
    auto& cu = plot.add("cubic of stationary curvature", xs, ys, render::palette::blue);
    cu.line = false;
    cu.markers = true;
    cu.markerRadius = 1.6;
    const auto pose = s.fb.solve(1.0, 1);
    plot.add("4-bar", {s.fb.c1()(0), pose->c2(0), pose->c3(0), s.fb.c4()(0)}, {s.fb.c1()(1), pose->c2(1), pose->c3(1), s.fb.c4()(1)},
             render::palette::black)
        .markers = true;
    std::vector<double> bx, by;
    for (int k = 0; k < 4; ++k)
      if (bp.isReal[k]) {
        bx.push_back(bp.x[k].re);
        by.push_back(bp.y[k].re);
      }
    auto& bs = plot.add("real Burmester points (= c2, c3)", bx, by, render::palette::vermillion);
    bs.line = false;
    bs.markers = true;
    bs.markerRadius = 9;
    auto& pl = plot.add("pole r", {s.inv.pole()(0)}, {s.inv.pole()(1)}, render::palette::bluishGreen);
    pl.line = false;
    pl.markers = true;
    pl.markerRadius = 8;
    plot.texts.push_back({s.inv.pole()(0), s.inv.pole()(1), "r (node)"});
    plot.texts.push_back({s.c2(0), s.c2(1), "c2"});
    plot.texts.push_back({s.c3(0), s.c3(1), "c3"});
    render::renderPlotPngAndSvg(plot, c.figurePath("GF-5.3.4-cubic.png"), 1100, 1000);
    c.figure("GF-5.3.4-cubic.png",
             "The cubic of stationary curvature of the catalogue 4-bar's coupler motion (node at the pole r, tangents "
             "along ṙ and its normal); the moving pivots c2, c3 lie on it and are the two real Burmester points.");
  }
}

// GF §5.3.4, GF-5.3.4-cubic-normal-form (erratum E5.12)
void normalForm(Context& c) {
  Setup s;
  const CubicNormalForm<double> nf = s.inv.cubicNormalForm();
  const double w = s.inv.omega(), v = nf.frame.v;
  double worst = 0;
  for (const V2& p : samplePoints()) {
    const V2 l = nf.frame.local(p);
    worst = std::max(worst, std::abs(s.inv.stationaryCurvatureCubic(p) + 12 * std::pow(w, 4) * v * v * nf(l(0), l(1))) /
                                (1 + std::abs(s.inv.stationaryCurvatureCubic(p))));
  }
  c.checkResidual("cubic = −12ω⁴v²·((x² + y²)(x/μ + y/ν) − xy) with corrected μ (5 points)", worst, tol(4096));
  for (const V2& pin : {s.c2, s.c3}) {
    const V2 l = nf.frame.local(pin);
    c.checkResidual("normal form with corrected μ = 4v²/(a sin θ − ωv) at a moving pivot", std::abs(nf(l(0), l(1))), tol(1024));
  }
  // printed μ = 4v²/(3a sin θ − ωv): catalogue −4.39, −1.37
  CubicNormalForm<double> pr = nf;
  pr.invMu = (3 * nf.frame.a * nf.frame.sinTheta - w * v) / (4 * v * v);
  const V2 l2 = nf.frame.local(s.c2), l3 = nf.frame.local(s.c3);
  c.checkNear("printed μ: normal form at c2 (catalogue −4.39)", -4.39, pr(l2(0), l2(1)), 0.01);
  c.checkNear("printed μ: normal form at c3 (catalogue −1.37)", -1.37, pr(l3(0), l3(1)), 0.01);
  c.checkPrintedFails("normal form with μ = 4v²/(3a sin θ − ωv)", "E5.12", std::abs(pr(l2(0), l2(1))), 1e-6);
  // node at r with tangents along ṙ and its normal: the quadratic part is −xy
  c.note("μ = " + toString(1 / nf.invMu, 10) + ", ν = " + toString(1 / nf.invNu, 10) +
         "; the asymptote x/μ + y/ν + μν/(μ² + ν²) = 0 follows from the points at infinity.");
}

// GF §5.3.5, GF-5.3.5-fourth-derivative-P4 (erratum E5.13)
void p4(Context& c) {
  Setup s;
  c.checkResidual("(P4) corrected (−4ω³, 12ω̇ω, 6ω²) vs the jet (5 points, relative)", worstDerivative(s, 4, samplePoints()), tol(16384));
  const double w = s.inv.omega(), wd = s.inv.omega(1);
  const V2 rd = s.inv.r(1), rdd = s.inv.r(2);
  const V2 p(0.4, 1.7);
  const V2 corr = s.inv.pointDerivatives(p)[4];
  const V2 printed = corr + (-2 * w * w * w + 4 * w * w * w) * E2(rd) + (9 - 12) * wd * w * rd + (3 - 6) * w * w * rdd;
  const V2 diff = printed - corr, expect = w * (2 * w * w * E2(rd) - 3 * wd * rd - 3 * w * rdd);
  c.checkResidual("printed − true = ω(2ω²E₂ṙ − 3ω̇ṙ − 3ωr̈)", (diff - expect).norm(), tol(64));
  c.checkPrintedFails("(P4) with (−2ω³, 9ω̇ω, 3ω²)", "E5.13", (printed - s.jet.pointDerivatives(p)[4]).norm(), 1e-6);
}

// GF §5.3.5, GF-5.3.5-burmester-cubic (erratum E5.14)
void burmesterCubic(Context& c) {
  Setup s;
  const BurmesterCubic<double> bc = s.inv.burmesterCubic();
  const NormalFrame<double> fr = s.inv.normalFrame();
  const Poly2<double> five = fivePointContactCurve(s.jet);
  double worst = 0;
  for (const V2& p : samplePoints()) {
    const V2 l = fr.local(p);
    worst = std::max(worst, std::abs(five(p(0), p(1)) + bc(l(0), l(1))) / five.magnitude(p(0), p(1)));
  }
  c.checkResidual("corrected α…ξ cubic = −[(ṗ·ṗ)det[ṗ, p⁗] − (4p⃛·ṗ + 3p̈·p̈)det[ṗ, p̈]] (5 points, relative)", worst, tol(4096));
  const double scale = std::abs(bc(fr.local(V2(0.4, 1.7))(0), fr.local(V2(0.4, 1.7))(1)));
  for (const V2& pin : {s.c2, s.c3}) {
    const V2 l = fr.local(pin);
    c.checkResidual("corrected second cubic vanishes at a moving pivot (relative to a generic point)", std::abs(bc(l(0), l(1))) / scale,
                    tol(4096));
  }
  c.checkNear("… and not at a generic coupler point (0.4, 1.7) (catalogue 3.26)", 3.26, scale, 0.01);
  // printed coefficients (dimensionally inconsistent)
  const double w = s.inv.omega(), wd = s.inv.omega(1), wdd = s.inv.omega(2), v = fr.v, a = fr.a, th = std::atan2(fr.sinTheta, fr.cosTheta),
               b = fr.b, ph = std::atan2(fr.sinPhi, fr.cosPhi);
  BurmesterCubic<double> pr;
  pr.alpha = std::pow(w, 3) * (6 * a * wd * std::sin(th) - 12 * a * w * w * std::cos(th) + 4 * b * w * w * std::sin(ph) - 15 * v * w * w * wd);
  pr.beta = 2 * w * w * (3 * v * wd * wd + 2 * v * w * wdd - 72 * v * v * std::pow(w, 8) * std::sin(th) - 36 * v * std::pow(w, 6) * wd -
                         2 * b * w * w * std::cos(ph));
  pr.gamma = 12 * v * v * std::pow(w, 5);
  pr.eta = -48 * v * v * w * (wd + 6 * v * std::pow(w, 8) * std::cos(th));
  pr.zeta = 288 * v * v * v * std::pow(w, 9) * std::sin(th);
  pr.xi = 24 * v * v * v * std::pow(w, 4);
  const V2 l2 = fr.local(s.c2);
  c.checkPrintedFails("printed α, β, η, ζ at c2 (relative)", "E5.14", std::abs(pr(l2(0), l2(1))) / scale, 1e-6);
  c.checkNear("γ = 12v²ω⁵ as printed", pr.gamma, bc.gamma, tol(64) * std::abs(bc.gamma));
  c.checkNear("ξ = 24v³ω⁴ as printed", pr.xi, bc.xi, tol(64) * std::abs(bc.xi));
}

// GF §5.3.5, GF-5.3.5-burmester-count
void burmesterCount(Context& c) {
  Setup s;
  const BurmesterPoints<double> bp = burmesterPoints(s.jet);
  c.checkEqual("directions through the pole: degree of F₂²G₃ − F₂F₃G₂ + F₃²G₁ (9 intersections − node)", 7, bp.formDegree);
  c.checkResidual("it is divisible by c² + s² (the two circular points at infinity, spurious)", bp.circularRemainder, tol(1024));
  c.checkResidual("… and by G₁ (the second cubic touches a branch at the pole: multiplicity 3 there)", bp.tangentRemainder, tol(1024));
  c.checkEqual("Burmester points = 9 − 2 − 3", 4, int(bp.x.size()));
  c.checkEqual("real Burmester points (c2 and c3)", 2, bp.realCount);
  const NormalFrame<double> fr = s.inv.normalFrame();
  std::vector<std::pair<double, double>> got;
  for (int k = 0; k < 4; ++k) {
    const Cx<double> X = (bp.x[k] - Cx<double>(fr.origin(0))) * fr.ex(0) + (bp.y[k] - Cx<double>(fr.origin(1))) * fr.ex(1);
    const Cx<double> Y = (bp.x[k] - Cx<double>(fr.origin(0))) * fr.ey(0) + (bp.y[k] - Cx<double>(fr.origin(1))) * fr.ey(1);
    if (bp.isReal[k]) {
      const V2 l(X.re, Y.re);
      const double e = std::min((l - fr.local(s.c2)).norm(), (l - fr.local(s.c3)).norm());
      c.checkResidual("real Burmester point = a moving pivot (local frame " + toString(X.re, 7) + ", " + toString(Y.re, 7) + ")", e, 1e-11);
    } else {
      c.checkNear("complex pair (catalogue, sympy resultant): Re x = −2.61127", -2.61127, X.re, 5e-6);
      c.checkNear("|Im x| = 15.911875", 15.911875, std::abs(X.im), 5e-6);
      c.checkNear("Re y = −12.962441", -12.962441, Y.re, 5e-6);
      c.checkNear("|Im y| = 1.276809", 1.276809, std::abs(Y.im), 5e-6);
    }
  }
  // both cubics pass through the circular points (1 : ±i : 0): their cubic parts contain x² + y²
  const Poly2<double> F = stationaryCurvatureCurve(s.jet), G = fivePointContactCurve(s.jet);
  auto circular = [](const Poly2<double>& P) {
    const Poly1<double> f = P.homogeneousPart(3);
    const Cx<double> v = evalForm(f, Cx<double>(1), Cx<double>(0, 1));
    double m = 0;
    for (double x : f) m = std::max(m, std::abs(x));
    return v.abs() / m;
  };
  c.checkResidual("first cubic at (1 : i : 0)", circular(F), tol(64));
  c.checkResidual("second cubic at (1 : i : 0)", circular(G), tol(64));
  c.note("Method: both cubics from the jet, translated to the pole and rotated to the normal frame; on the line through "
         "the pole in direction (c, s) the first gives ρ = −F₂/F₃, and substituting in the second gives a binary form of "
         "degree 7 = (c² + s²)·G₁·Q₄. Q₄'s roots are the four Burmester directions. The complex pair matches the catalogue's "
         "independent sympy resultant.");
  finitePositionSynthesis(c);
}

}  // namespace

SOMA_STUDY({.id = "GF-5.3.1-lamina-derivatives", .title = "(P1), (P2) and the book's r(t) vs the classical centrodes (E5.9)",
            .source = "GF §5.3.1", .chapter = kChapter, .scalarGeneric = false, .run = lamina});
SOMA_STUDY({.id = "GF-5.3.1-euler-savary", .title = "Euler–Savary equation", .source = "GF §5.3.1", .chapter = kChapter,
            .scalarGeneric = false, .run = eulerSavary});
SOMA_STUDY({.id = "GF-5.3.2-inflection-circle", .title = "Inflection circle (three methods)", .source = "GF §5.3.2", .chapter = kChapter,
            .scalarGeneric = false, .run = inflection});
SOMA_STUDY({.id = "GF-5.3.3-third-derivative-P3", .title = "Third derivative of a point path (P3)", .source = "GF §5.3.3",
            .chapter = kChapter, .scalarGeneric = false, .run = p3});
SOMA_STUDY({.id = "GF-5.3.3-ball-point", .title = "Ball's point (errata E5.10, E5.11)", .source = "GF §5.3.3", .chapter = kChapter,
            .scalarGeneric = false, .run = ball});
SOMA_STUDY({.id = "GF-5.3.4-cubic-stationary-curvature", .title = "Cubic of stationary curvature", .source = "GF §5.3.4",
            .chapter = kChapter, .scalarGeneric = false, .run = cubic});
SOMA_STUDY({.id = "GF-5.3.4-cubic-normal-form", .title = "Normal form of the cubic (erratum E5.12)", .source = "GF §5.3.4",
            .chapter = kChapter, .scalarGeneric = false, .run = normalForm});
SOMA_STUDY({.id = "GF-5.3.5-fourth-derivative-P4", .title = "Fourth derivative (P4) (erratum E5.13)", .source = "GF §5.3.5",
            .chapter = kChapter, .scalarGeneric = false, .run = p4});
SOMA_STUDY({.id = "GF-5.3.5-burmester-cubic", .title = "The second (5-point contact) cubic (erratum E5.14)", .source = "GF §5.3.5",
            .chapter = kChapter, .scalarGeneric = false, .run = burmesterCubic});
SOMA_STUDY({.id = "GF-5.3.5-burmester-count", .title = "Burmester points: 9 = 2 + 3 + 4", .source = "GF §5.3.5", .chapter = kChapter,
            .scalarGeneric = false, .run = burmesterCount});

}  // namespace soma::studies::gf05p::SOMA_UNITY_ID
