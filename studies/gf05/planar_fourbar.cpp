// Studies of GF §5.4: the planar 4-bar (loop equation, instant centre, velocity ratios, pole
// velocity, angular acceleration) and coupler curves with their instantaneous invariants.
#include "gf05/planar_common.hpp"

namespace soma::studies::gf05p::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// GF §5.4, GF-5.4-fourbar-loop
void loop(Context& c) {
  const FourBar<double> fb = catalogueBar();
  const auto ref = *fb.solve(1.0, 1);
  double worstLoop = 0, worstCrank = 0, worstRocker = 0, worstCol = 0;
  for (const auto& p : fb.traceCircuit(0, 360)) {
    worstLoop = std::max({worstLoop, std::abs((p.c2 - fb.c1()).norm() - fb.crank()), std::abs((p.c3 - p.c2).norm() - fb.coupler()),
                          std::abs((p.c3 - fb.c4()).norm() - fb.rocker())});
    // the coupler displacement D = M M_ref⁻¹ two ways: rotations about c1 then c2 (home), about c4 then c3
    const SE2<double> D = p.coupler * ref.coupler.inverse();
    const double d1 = p.theta1 - ref.theta1, d4 = p.theta4 - ref.theta4, dpsi = p.psi - ref.psi;
    const SE2<double> viaCrank = SE2<double>::rotationAbout(d1, fb.c1()) * SE2<double>::rotationAbout(dpsi - d1, ref.c2);
    const SE2<double> viaRocker = SE2<double>::rotationAbout(d4, fb.c4()) * SE2<double>::rotationAbout(dpsi - d4, ref.c3);
    worstCrank = std::max(worstCrank, (D.matrix() - viaCrank.matrix()).cwiseAbs().maxCoeff());
    worstRocker = std::max(worstRocker, (D.matrix() - viaRocker.matrix()).cwiseAbs().maxCoeff());
    // r, c2, c1 and r, c3, c4 collinear (homogeneous instant centre)
    const Vec3<double> ic = FourBar<double>::instantCentre(fb.c1(), p.c2, p.c3, fb.c4());
    const Vec3<double> h2(p.c2(0), p.c2(1), 1), h1(fb.c1()(0), fb.c1()(1), 1), h3(p.c3(0), p.c3(1), 1), h4(fb.c4()(0), fb.c4()(1), 1);
    worstCol = std::max(worstCol, std::abs(ic.normalized().dot(h1.cross(h2).normalized())) + std::abs(ic.normalized().dot(h4.cross(h3).normalized())));
  }
  c.checkResidual("loop closure over a full crank turn (360 poses, circuit 0)", worstLoop, tol(64));
  c.checkResidual("e^{θ₁C₁}e^{θ₂C₂}: coupler displacement = rotation about c1 ∘ rotation about c2 (home)", worstCrank, tol(256));
  c.checkResidual("= e^{θ₄C₄}e^{θ₃C₃}: rotation about c4 ∘ rotation about c3 (home)", worstRocker, tol(256));
  c.checkResidual("r, c2, c1 and r, c3, c4 collinear (incidence of the homogeneous pole)", worstCol, tol(64));
  // c2 and c3 are on the cubic and are Burmester points at every sampled instant
  int ok = 0, n = 0;
  for (int k = 0; k < 12; ++k) {
    const double th = 0.1 + 0.5 * k;
    const MotionJet<double> jet = fb.couplerJet(th, 1, {th, 1, 0, 0, 0});
    const auto bp = burmesterPoints(jet);
    const auto p = *fb.solve(th, 1);
    int hits = 0;
    for (int j = 0; j < 4; ++j)
      if (bp.isReal[j]) {
        const V2 q(bp.x[j].re, bp.y[j].re);
        if ((q - p.c2).norm() < 1e-8 || (q - p.c3).norm() < 1e-8) ++hits;
      }
    ++n;
    if (hits == 2) ++ok;
  }
  c.checkEqual("instants (of 12) at which c2 and c3 are two of the Burmester points", n, ok);
  // non-assemblable configurations: beyond the crank range of a triple rocker
  const FourBar<double> tr(V2(0, 0), V2(3, 0), 2, 2.5, 2.2);
  const auto iv = tr.crankIntervals().at(0);
  c.checkEqual("triple rocker: no assembly 1e-6 beyond its crank limit", 0, tr.solve(iv.second + 1e-6, 1) ? 1 : 0);
  c.note("The coupler motion is a curve in SE(2) (an elliptic curve, GF §5.4); soma traces each circuit of the "
         "configuration curve by a closed-form parametrisation that passes turning points and change-point nodes along the "
         "smooth branch.");
}

// GF §5.4, GF-5.4-fourbar-instant-centre (E5.16)
void instantCentre(Context& c) {
  const FourBar<double> fb = catalogueBar();
  const auto p = *fb.solve(1.0, 1);
  const InstantInvariants<double> inv = InstantInvariants<double>::fromJet(catalogueJet());
  const auto rat = FourBar<double>::velocityRatios(fb.c1(), p.c2, p.c3, fb.c4());
  c.checkNear("ω (catalogue −0.291174739311)", -0.291174739311, inv.omega(), 1e-12);
  c.checkNear("ω4 (catalogue 0.360970565066)", 0.360970565066, rat.second, 1e-12);
  const V2 rA = p.c2 + (1.0 / inv.omega()) * (fb.c1() - p.c2), rB = p.c3 + (rat.second / inv.omega()) * (fb.c4() - p.c3);
  c.checkResidual("r = c2 + (ω₁/ω)(c1 − c2) = pole of the jet", (rA - inv.pole()).norm(), tol(256));
  c.checkResidual("r = c3 + (ω₄/ω)(c4 − c3) (printed with ω₃, E5.16)", (rB - inv.pole()).norm(), tol(256));
  c.checkResidual("ω₁(c1 − c2) + ω₄(c3 − c4) + ω(c2 − c3) = 0",
                  (1.0 * (fb.c1() - p.c2) + rat.second * (p.c3 - fb.c4()) + inv.omega() * (p.c2 - p.c3)).norm(), tol(64));
  // extreme ω = 0: the coupler instantaneously translates (c1c2 ∥ c4c3); find it by bisection
  auto omegaAt = [&](double th) {
    const auto q = *fb.solve(th, 1);
    return FourBar<double>::velocityRatios(fb.c1(), q.c2, q.c3, fb.c4()).first;
  };
  double a = 0, b = 0;
  for (int k = 0; k < 360; ++k) {
    const double t0 = 2 * 3.14159265358979 * k / 360, t1 = 2 * 3.14159265358979 * (k + 1) / 360;
    if (omegaAt(t0) * omegaAt(t1) < 0) {
      a = t0;
      b = t1;
      break;
    }
  }
  c.checkEqual("a crank angle with ω = 0 exists on the crank-rocker's circuit", 1, b > a ? 1 : 0);
  double fa = omegaAt(a);
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (a + b), fm = omegaAt(m);
    if (fa * fm <= 0) b = m;
    else {
      a = m;
      fa = fm;
    }
  }
  const auto q = *fb.solve(0.5 * (a + b), 1);
  const Vec3<double> ic = FourBar<double>::instantCentre(fb.c1(), q.c2, q.c3, fb.c4());
  c.checkResidual("at ω = 0 the lines c1c2 and c4c3 are parallel: the homogeneous pole has W → 0", std::abs(ic(2)) / ic.head<2>().norm(), 1e-12);
  bool threw = false;
  try {
    (void)InstantInvariants<double>::fromJet(fb.couplerJet(0.5 * (a + b), 1, {0.5 * (a + b), 1, 0, 0, 0}));
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("… and the book's chart reports the pole at infinity (InvalidInput)", 1, threw ? 1 : 0);
  c.note("Crank angle of the instantaneous translation: θ₁ = " + toString(0.5 * (a + b), 12) + " rad.");
}

// GF §5.4, GF-5.4-fourbar-velocity-ratios
void velocityRatios(Context& c) {
  const FourBar<double> fb = catalogueBar();
  double worstJet = 0, worstFD = 0;
  for (int k = 0; k < 24; ++k) {
    const double th = 0.13 + 0.26 * k;
    const auto p = *fb.solve(th, 1);
    const auto rat = FourBar<double>::velocityRatios(fb.c1(), p.c2, p.c3, fb.c4());
    const MotionJet<double> jet = fb.couplerJet(th, 1, {th, 1, 0, 0, 0});
    worstJet = std::max(worstJet, std::abs(jet.angle().derivative(1) - rat.first));
    const double h = 1e-5;
    const auto pp = *fb.solve(th + h, 1), pm = *fb.solve(th - h, 1);
    auto wrap = [](double x) { return std::atan2(std::sin(x), std::cos(x)); };
    worstFD = std::max({worstFD, std::abs(wrap(pp.psi - pm.psi) / (2 * h) - rat.first), std::abs(wrap(pp.theta4 - pm.theta4) / (2 * h) - rat.second)});
  }
  c.checkResidual("ω/ω₁ by the determinant ratio = the jet's ω (24 crank angles)", worstJet, tol(256));
  c.checkResidual("ω/ω₁ and ω₄/ω₁ = central differences of the position analysis (h = 1e-5)", worstFD, 1e-8);
  // dead centre: coupler ∥ rocker on a triple rocker's crank limit
  const FourBar<double> tr(V2(0, 0), V2(3, 0), 2, 2.5, 2.2);
  const double lim = tr.crankIntervals().at(0).second;
  bool threw = false;
  try {
    const auto q = *tr.solve(lim, 1);
    (void)FourBar<double>::velocityRatios(tr.c1(), q.c2, q.c3, tr.c4());
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("at the crank limit (coupler ∥ rocker, a dead centre) the ratios are infinite → InvalidInput", 1, threw ? 1 : 0);
}

// GF §5.4, GF-5.4-fourbar-pole-velocity
void poleVelocity(Context& c) {
  const FourBar<double> fb = catalogueBar();
  const auto p = *fb.solve(1.0, 1);
  const MotionJet<double> jet = catalogueJet();
  const InstantInvariants<double> inv = InstantInvariants<double>::fromJet(jet);
  const auto d3 = jet.bodyPointDerivatives(V2(fb.coupler(), 0));
  const V2 u = p.c3 - fb.c4();
  const double w4 = cross2<double>(u, d3[1]) / u.squaredNorm();
  const double w4d = cross2<double>(u, d3[2]) / u.squaredNorm() - 2 * w4 * u.dot(d3[1]) / u.squaredNorm();
  const V2 r1 = FourBar<double>::poleVelocity(fb.c1(), p.c2, inv.omega(), inv.omega(1), 1.0, 0.3);
  const V2 r4 = FourBar<double>::poleVelocity(fb.c4(), p.c3, inv.omega(), inv.omega(1), w4, w4d);
  c.checkResidual("2ω²ṙ from the crank side = 2ω²·ṙ of the finite-pole curve", (r1 - inv.r(1)).norm(), tol(1024));
  c.checkResidual("2ω²ṙ from the rocker side", (r4 - inv.r(1)).norm(), tol(1024));
  const auto q = fixedCentrode(jet);
  const V2 qd(q[0].derivative(1), q[1].derivative(1));
  c.checkPrintedFails("the formula read as the velocity of the classical centrode (q̇ = 2ṙ)", "E5.9", (r1 - qd).norm(), 1e-6);
}

// GF §5.4, GF-5.4-fourbar-angular-acceleration (E5.17)
void angularAcceleration(Context& c) {
  const FourBar<double> fb = catalogueBar();
  const auto p = *fb.solve(1.0, 1);
  const InstantInvariants<double> inv = InstantInvariants<double>::fromJet(catalogueJet());
  const double wd = FourBar<double>::omegaDot(fb.c1(), p.c2, p.c3, fb.c4(), 1.0, 0.3);
  c.checkNear("ω̇ by the book's closed form (catalogue 0.261021037565)", 0.261021037565, wd, 1e-12);
  c.checkNear("… = ω̇ of the jet", inv.omega(1), wd, tol(1024));
  double worst = 0;
  for (int k = 0; k < 24; ++k) {
    const double th = 0.13 + 0.26 * k;
    const auto q = *fb.solve(th, -1);
    const MotionJet<double> jet = fb.couplerJet(th, -1, {th, 1.3, -0.4, 0, 0});
    worst = std::max(worst, std::abs(FourBar<double>::omegaDot(fb.c1(), q.c2, q.c3, fb.c4(), 1.3, -0.4) - jet.angle().derivative(2)));
  }
  c.checkResidual("ω̇ formula = jet over 24 crank angles, lower branch, ω₁ = 1.3, ω̇₁ = −0.4", worst, tol(4096));
  // E5.17: dotting with E₂(c4 − c2) does not eliminate ω̇₄; E₂(c3 − c4) does
  const V2 r4 = p.c3 - fb.c4();
  c.checkResidual("(c3 − c4)·E₂(c3 − c4) = 0: E₂(c3 − c4) eliminates ω̇₄", std::abs(r4.dot(E2(r4))), tol(4));
  c.checkPrintedFails("\"scalar product with E₂(c4 − c2)\" eliminates ω̇₄: (c3 − c4)·E₂(c4 − c2) should be 0", "E5.17",
              std::abs(r4.dot(E2(V2(fb.c4() - p.c2)))), 1e-6);
}

// GF §5.4, GF-5.4-coupler-curves-and-invariants
void couplerCurves(Context& c) {
  const V2 pc(0.8, 1.1);
  const FourBar<double> fb(V2(0, 0), V2(3, 0), 1.2, 2.5, 2.0, pc);
  c.checkEqual("Grashof class of the catalogue 4-bar", "crank-rocker", grashofName(fb.classify().type));
  // the degree-6 equation on both circuits
  const Poly2<double> sextic = fb.couplerCurve();
  c.checkEqual("degree of the coupler curve", 6, sextic.degree(tol(64)));
  double worst = 0;
  for (int k = 0; k < fb.circuitCount(); ++k)
    for (const auto& p : fb.traceCircuit(k, 360)) {
      const V2 q = fb.couplerPointWorld(p);
      worst = std::max(worst, std::abs(sextic(q(0), q(1))) / sextic.magnitude(q(0), q(1)));
    }
  c.checkResidual("coupler points of both circuits satisfy the sextic (720 points, relative)", worst, tol(1024));
  c.checkResidual("tricircular: degree-6 part ∝ (x² + y²)³",
                  std::abs(sextic.at(4, 2) - 3 * sextic.at(6, 0)) + std::abs(sextic.at(2, 4) - 3 * sextic.at(6, 0)) +
                      std::abs(sextic.at(0, 6) - sextic.at(6, 0)),
                  tol(256) * std::abs(sextic.at(6, 0)));
  // sweep the crank: inflections of the coupler curve (sampled) lie on the inflection circle of that
  // instant. The traced point is one of the inflection circle at θ₁ = 1 (so it has inflections).
  const V2 pcInf = [&] {
    const InstantInvariants<double> i1 = InstantInvariants<double>::fromJet(fb.couplerJet(1.0, 1, {1.0, 1, 0, 0, 0}));
    const Circle<double> c1 = i1.inflectionCircle();
    return V2(fb.solve(1.0, 1)->coupler.inverse().act(V2(c1.centre + c1.radius * V2(std::cos(0.77), std::sin(0.77)))));
  }();
  const int N = 3600;
  std::vector<double> kap(N);
  std::vector<FourBarPose<double>> poses = fb.traceCircuit(0, N);
  for (int k = 0; k < N; ++k) kap[k] = fdCurvature(fb, poses[k].theta1, poses[k].mode, pcInf, 1e-4);
  double worstInf = 0;
  int inflections = 0;
  for (int k = 0; k < N; ++k) {
    const int k2 = (k + 1) % N;
    if (kap[k] * kap[k2] >= 0) continue;
    // bisection in θ₁ between the samples
    double a = poses[k].theta1, b = poses[k2].theta1;
    if (b < a) b += 2 * 3.14159265358979323846;
    double fa = kap[k];
    for (int it = 0; it < 40; ++it) {
      const double m = 0.5 * (a + b), fm = fdCurvature(fb, m, 1, pcInf, 1e-4);
      if (fa * fm <= 0) b = m;
      else {
        a = m;
        fa = fm;
      }
    }
    const double th = 0.5 * (a + b);
    const InstantInvariants<double> inv = InstantInvariants<double>::fromJet(fb.couplerJet(th, 1, {th, 1, 0, 0, 0}));
    const Circle<double> ci = inv.inflectionCircle();
    const V2 q = fb.solve(th, 1)->coupler.act(pcInf);
    worstInf = std::max(worstInf, std::abs((q - ci.centre).norm() - ci.radius) / ci.radius);
    ++inflections;
  }
  c.checkEqual("inflections of the coupler curve found by sampling (even, > 0)", 1, (inflections > 0 && inflections % 2 == 0) ? 1 : 0);
  c.checkResidual("each inflection lies on the inflection circle of its instant (relative)", worstInf, 1e-6);
  c.note("The coupler curve of a point of the inflection circle at θ₁ = 1 has " + std::to_string(inflections) +
         " inflections on circuit 0; at each, P is on that instant's inflection circle.");
  // change-point extreme: the figure-eight circuit passes the node smoothly
  const FourBar<double> cp(V2(0, 0), V2(3, 0), 1, 2.5, 1.5, pc);
  c.checkEqual("change-point 4-bar (3, 1, 2.5, 1.5): class", "change-point", grashofName(cp.classify().type));
  c.checkEqual("… one circuit of period 4π (a figure eight through the node)", 1, cp.circuitCount());
  if (!c.makeFigures()) return;
  // Figure: coupler curve, the 4-bar at θ₁ = 1, pole, inflection circle, inflection pole, Ball's point
  const double th = 1.0;
  const MotionJet<double> jet = fb.couplerJet(th, 1, {th, 1, 0, 0, 0});
  const InstantInvariants<double> inv = InstantInvariants<double>::fromJet(jet);
  const auto pose = *fb.solve(th, 1);
  render::Plot plot;
  plot.legend = render::LegendCorner::BottomRight;  // the top right holds Ball's point
  plot.title = "Coupler curve, pole, inflection circle and Ball's point (crank-rocker, θ₁ = 1)";
  plot.equalAspect = true;
  plot.x.label = "x";
  plot.y.label = "y";
  plot.x.min = -24;
  plot.x.max = 6;
  plot.y.min = -13;
  plot.y.max = 15;
  std::vector<double> xs, ys;
  for (const auto& p : fb.traceCircuit(0, 720)) {
    const V2 q = fb.couplerPointWorld(p);
    xs.push_back(q(0));
    ys.push_back(q(1));
  }
  plot.add("coupler curve of P", xs, ys, render::palette::blue).closed = true;
  const Circle<double> ci = inv.inflectionCircle();
  circlePoints(ci.centre, ci.radius, xs, ys);
  auto& cs = plot.add("inflection circle", xs, ys, render::palette::bluishGreen);
  cs.closed = true;
  cs.dashed = true;
  const V2 P = fb.couplerPointWorld(pose), r = inv.pole(), ip = inv.inflectionPole(), B = inv.ballPoint();
  plot.add("4-bar", {fb.c1()(0), pose.c2(0), pose.c3(0), fb.c4()(0)}, {fb.c1()(1), pose.c2(1), pose.c3(1), fb.c4()(1)}, render::palette::black)
      .markers = true;
  plot.add("", {pose.c2(0), P(0), pose.c3(0)}, {pose.c2(1), P(1), pose.c3(1)}, render::palette::grey);
  // the pole lines c1c2 and c4c3 extended to r
  auto& l1 = plot.add("", {fb.c1()(0), r(0)}, {fb.c1()(1), r(1)}, render::palette::grey);
  l1.dashed = true;
  l1.width = 1.5;
  auto& l2 = plot.add("", {fb.c4()(0), r(0)}, {fb.c4()(1), r(1)}, render::palette::grey);
  l2.dashed = true;
  l2.width = 1.5;
  auto pt = [&](const std::string& name, const V2& q, render::Color col, const std::string& label) {
    auto& s = plot.add(name, {q(0)}, {q(1)}, col);
    s.line = false;
    s.markers = true;
    s.markerRadius = 8;
    plot.texts.push_back({q(0), q(1), label});
  };
  pt("pole r", r, render::palette::vermillion, "r");
  pt("inflection pole", ip, render::palette::bluishGreen, "inflection pole");
  pt("Ball's point", B, render::palette::reddishPurple, "Ball");
  pt("", P, render::palette::blue, "P");
  render::renderPlotPngAndSvg(plot, c.figurePath("GF-5.4-coupler-invariants.png"), 1200, 1120);
  c.figure("GF-5.4-coupler-invariants.png",
           "Crank-rocker (ground (0,0)–(3,0), crank 1.2, coupler 2.5, rocker 2.0) at θ₁ = 1: the coupler curve of "
           "P = (0.8, 1.1), the instantaneous centre r where c1c2 and c4c3 meet, the inflection circle through r with the "
           "inflection pole opposite, and Ball's point (corrected, E5.10/E5.11) on it.");
}

}  // namespace

SOMA_STUDY({.id = "GF-5.4-fourbar-loop", .title = "4-bar loop equation, circuits, c2 and c3 as Burmester points", .source = "GF §5.4",
            .chapter = kChapter, .scalarGeneric = false, .run = loop});
SOMA_STUDY({.id = "GF-5.4-fourbar-instant-centre", .title = "Instant centre of the coupler (E5.16); ω = 0 extreme",
            .source = "GF §5.4", .chapter = kChapter, .scalarGeneric = false, .run = instantCentre});
SOMA_STUDY({.id = "GF-5.4-fourbar-velocity-ratios", .title = "Angular velocity ratios ω/ω₁, ω₄/ω₁", .source = "GF §5.4",
            .chapter = kChapter, .scalarGeneric = false, .run = velocityRatios});
SOMA_STUDY({.id = "GF-5.4-fourbar-pole-velocity", .title = "Velocity of the pole, from both sides", .source = "GF §5.4",
            .chapter = kChapter, .scalarGeneric = false, .run = poleVelocity});
SOMA_STUDY({.id = "GF-5.4-fourbar-angular-acceleration", .title = "Angular acceleration of the coupler (E5.17)",
            .source = "GF §5.4", .chapter = kChapter, .scalarGeneric = false, .run = angularAcceleration});
SOMA_STUDY({.id = "GF-5.4-coupler-curves-and-invariants", .title = "Coupler curves (degree 6) and their invariants along the cycle",
            .source = "GF §5.4", .chapter = kChapter, .scalarGeneric = false, .run = couplerCurves});

}  // namespace soma::studies::gf05p::SOMA_UNITY_ID
