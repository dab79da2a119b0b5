// Studies of GF §5.4: the planar 4-bar (loop equation, instant centre, velocity ratios, pole
// velocity, angular acceleration) and coupler curves with their instantaneous invariants. Every
// study runs in the asked scalar (--scalar); the figure of GF-5.4-coupler-curves-and-invariants is
// drawn in double (soma::render).
#include "gf05/planar_common.hpp"

namespace soma::studies::gf05p::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::atan2;
using std::cos;
using std::sin;

template <class S> Vec2<S> pt(long x10, long y10) { return Vec2<S>(frac<S>(x10, 10), frac<S>(y10, 10)); }
/// The triple rocker (ground 3, crank 2, coupler 2.5, rocker 2.2) of the extremes.
template <class S> FourBar<S> tripleRocker() { return FourBar<S>(pt<S>(0, 0), pt<S>(30, 0), S(2), frac<S>(25, 10), frac<S>(22, 10)); }

// GF §5.4, GF-5.4-fourbar-loop
template <class S> void loop(Context& c) {
  using P = Vec2<S>;
  const FourBar<S> fb = catalogueBar<S>();
  const auto ref = *fb.solve(S(1), 1);
  S worstLoop(0), worstCrank(0), worstRocker(0), worstCol(0);
  for (const auto& p : fb.traceCircuit(0, 360)) {
    worstLoop = maxOf(worstLoop, S(abs((p.c2 - fb.c1()).norm() - fb.crank())));
    worstLoop = maxOf(worstLoop, S(abs((p.c3 - p.c2).norm() - fb.coupler())));
    worstLoop = maxOf(worstLoop, S(abs((p.c3 - fb.c4()).norm() - fb.rocker())));
    // the coupler displacement D = M M_ref⁻¹ two ways: rotations about c1 then c2 (home), about c4 then c3
    const SE2<S> D = p.coupler * ref.coupler.inverse();
    const S d1 = p.theta1 - ref.theta1, d4 = p.theta4 - ref.theta4, dpsi = p.psi - ref.psi;
    const SE2<S> viaCrank = SE2<S>::rotationAbout(d1, fb.c1()) * SE2<S>::rotationAbout(S(dpsi - d1), ref.c2);
    const SE2<S> viaRocker = SE2<S>::rotationAbout(d4, fb.c4()) * SE2<S>::rotationAbout(S(dpsi - d4), ref.c3);
    worstCrank = maxOf(worstCrank, S((D.matrix() - viaCrank.matrix()).cwiseAbs().maxCoeff()));
    worstRocker = maxOf(worstRocker, S((D.matrix() - viaRocker.matrix()).cwiseAbs().maxCoeff()));
    // r, c2, c1 and r, c3, c4 collinear (homogeneous instant centre)
    const Vec3<S> ic = FourBar<S>::instantCentre(fb.c1(), p.c2, p.c3, fb.c4());
    const Vec3<S> h2(p.c2(0), p.c2(1), S(1)), h1(fb.c1()(0), fb.c1()(1), S(1)), h3(p.c3(0), p.c3(1), S(1)), h4(fb.c4()(0), fb.c4()(1), S(1));
    worstCol = maxOf(worstCol, S(abs(ic.normalized().dot(h1.cross(h2).normalized())) + abs(ic.normalized().dot(h4.cross(h3).normalized()))));
  }
  c.checkResidual("loop closure over a full crank turn (360 poses, circuit 0; 64 ε)", worstLoop, tol<S>(64));
  c.checkResidual("e^{θ₁C₁}e^{θ₂C₂}: coupler displacement = rotation about c1 ∘ rotation about c2 (home; 256 ε)", worstCrank, tol<S>(256));
  c.checkResidual("= e^{θ₄C₄}e^{θ₃C₃}: rotation about c4 ∘ rotation about c3 (home; 256 ε)", worstRocker, tol<S>(256));
  c.checkResidual("r, c2, c1 and r, c3, c4 collinear (incidence of the homogeneous pole; 64 ε)", worstCol, tol<S>(64));
  // c2 and c3 are on the cubic and are Burmester points at every sampled instant (matched within √ε)
  int ok = 0, n = 0;
  for (int k = 0; k < 12; ++k) {
    const S th = frac<S>(1 + 5 * k, 10);
    const MotionJet<S> jet = fb.couplerJet(th, 1, {th, S(1), S(0), S(0), S(0)});
    const auto bp = burmesterPoints(jet);
    const auto p = *fb.solve(th, 1);
    int hits = 0;
    for (int j = 0; j < 4; ++j)
      if (bp.isReal[j]) {
        const P q(bp.x[j].re, bp.y[j].re);
        if ((q - p.c2).norm() < Tolerance<S>::sqrtEpsilon() || (q - p.c3).norm() < Tolerance<S>::sqrtEpsilon()) ++hits;
      }
    ++n;
    if (hits == 2) ++ok;
  }
  c.checkEqual("instants (of 12) at which c2 and c3 are two of the Burmester points", n, ok);
  // non-assemblable configurations: beyond the crank range of a triple rocker
  const FourBar<S> tr = tripleRocker<S>();
  const auto iv = tr.crankIntervals().at(0);
  // solve() accepts |c4 − c2|² within rank·(Σl)² of the limit (0.012 in float, 2e-11 in double): the
  // step beyond the limit is 1e-6, or 100 × the rank tolerance where that is larger (float: 0.012).
  const S beyond = maxOf(frac<S>(1, 1000000), S(S(100) * Tolerance<S>::rank()));
  c.checkEqual("triple rocker: no assembly max(1e-6, 100·1024 ε) beyond its crank limit", 0, tr.solve(S(iv.second + beyond), 1) ? 1 : 0);
  c.note("The coupler motion is a curve in SE(2) (an elliptic curve, GF §5.4); soma traces each circuit of the "
         "configuration curve by a closed-form parametrisation that passes turning points and change-point nodes along the "
         "smooth branch.");
}

// GF §5.4, GF-5.4-fourbar-instant-centre (E5.16)
template <class S> void instantCentre(Context& c) {
  using P = Vec2<S>;
  const FourBar<S> fb = catalogueBar<S>();
  const auto p = *fb.solve(S(1), 1);
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(catalogueJet<S>());
  const auto rat = FourBar<S>::velocityRatios(fb.c1(), p.c2, p.c3, fb.c4());
  // catalogue values to 12 decimals: half a unit of the last + 1024 ε
  c.checkNear("ω (catalogue −0.291174739311)", fromString<S>("-0.291174739311"), inv.omega(), printedTol<S>(12, 1024));
  c.checkNear("ω4 (catalogue 0.360970565066)", fromString<S>("0.360970565066"), rat.second, printedTol<S>(12, 1024));
  const P rA = p.c2 + (S(1) / inv.omega()) * (fb.c1() - p.c2), rB = p.c3 + (rat.second / inv.omega()) * (fb.c4() - p.c3);
  c.checkResidual("r = c2 + (ω₁/ω)(c1 − c2) = pole of the jet (256 ε)", S((rA - inv.pole()).norm()), tol<S>(256));
  c.checkResidual("r = c3 + (ω₄/ω)(c4 − c3) (printed with ω₃, E5.16; 256 ε)", S((rB - inv.pole()).norm()), tol<S>(256));
  c.checkResidual("ω₁(c1 − c2) + ω₄(c3 − c4) + ω(c2 − c3) = 0 (64 ε)",
                  S((S(1) * (fb.c1() - p.c2) + rat.second * (p.c3 - fb.c4()) + inv.omega() * (p.c2 - p.c3)).norm()), tol<S>(64));
  // extreme ω = 0: the coupler instantaneously translates (c1c2 ∥ c4c3); find it by bisection
  auto omegaAt = [&](const S& th) {
    const auto q = *fb.solve(th, 1);
    return FourBar<S>::velocityRatios(fb.c1(), q.c2, q.c3, fb.c4()).first;
  };
  S a(0), b(0);
  for (int k = 0; k < 360; ++k) {
    const S t0 = S(2) * pi<S>() * S(k) / S(360), t1 = S(2) * pi<S>() * S(k + 1) / S(360);
    if (omegaAt(t0) * omegaAt(t1) < S(0)) {
      a = t0;
      b = t1;
      break;
    }
  }
  c.checkEqual("a crank angle with ω = 0 exists on the crank-rocker's circuit", 1, b > a ? 1 : 0);
  S fa = omegaAt(a);
  for (int it = 0; it < digits<S>() + 8; ++it) {  // down to the rounding of S
    const S m = (a + b) / S(2), fm = omegaAt(m);
    if (fa * fm <= S(0)) b = m;
    else {
      a = m;
      fa = fm;
    }
  }
  const S mid = (a + b) / S(2);
  const auto q = *fb.solve(mid, 1);
  const Vec3<S> ic = FourBar<S>::instantCentre(fb.c1(), q.c2, q.c3, fb.c4());
  c.checkResidual("at ω = 0 the lines c1c2 and c4c3 are parallel: the homogeneous pole has W → 0 (1024 ε)",
                  S(abs(ic(2)) / ic.template head<2>().norm()), tol<S>(1024));
  bool threw = false;
  try {
    (void)InstantInvariants<S>::fromJet(fb.couplerJet(mid, 1, {mid, S(1), S(0), S(0), S(0)}));
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("… and the book's chart reports the pole at infinity (InvalidInput)", 1, threw ? 1 : 0);
  c.note("Crank angle of the instantaneous translation: θ₁ = " + toString(toDouble(mid), 12) + " rad.");
}

// GF §5.4, GF-5.4-fourbar-velocity-ratios
template <class S> void velocityRatios(Context& c) {
  using P = Vec2<S>;
  const FourBar<S> fb = catalogueBar<S>();
  // central differences: truncation h² ≈ 1e-10, rounding 16 ε/h; tolerance 1e-8
  const S fdTol = frac<S>(1, 100000000);
  const bool fd = fdResolves<S>(c, "ω/ω₁, ω₄/ω₁ by central differences", 1e-5, 1, fdTol);
  S worstJet(0), worstFD(0);
  for (int k = 0; k < 24; ++k) {
    const S th = frac<S>(13 + 26 * k, 100);
    const auto p = *fb.solve(th, 1);
    const auto rat = FourBar<S>::velocityRatios(fb.c1(), p.c2, p.c3, fb.c4());
    const MotionJet<S> jet = fb.couplerJet(th, 1, {th, S(1), S(0), S(0), S(0)});
    worstJet = maxOf(worstJet, S(abs(jet.angle().derivative(1) - rat.first)));
    if (!fd) continue;
    const S h = frac<S>(1, 100000);
    const auto pp = *fb.solve(th + h, 1), pm = *fb.solve(th - h, 1);
    auto wrap = [](const S& x) { return S(atan2(sin(x), cos(x))); };
    worstFD = maxOf(worstFD, S(abs(wrap(pp.psi - pm.psi) / (S(2) * h) - rat.first)));
    worstFD = maxOf(worstFD, S(abs(wrap(pp.theta4 - pm.theta4) / (S(2) * h) - rat.second)));
  }
  c.checkResidual("ω/ω₁ by the determinant ratio = the jet's ω (24 crank angles; 256 ε)", worstJet, tol<S>(256));
  if (fd) c.checkResidual("ω/ω₁ and ω₄/ω₁ = central differences of the position analysis (h = 1e-5)", worstFD, fdTol);
  // dead centre: coupler ∥ rocker on a triple rocker's crank limit
  const FourBar<S> tr = tripleRocker<S>();
  const S lim = tr.crankIntervals().at(0).second;
  // The limit angle carries a rounding of ε, which the position analysis's square root (a double
  // root at the limit) turns into a coupler off the rocker line by up to √ε: in mpfr-256 the pose
  // solve(lim) returns passes the rank test 1024 ε (no InvalidInput). So the dead centre is built
  // with h = 0: c3 on the line c2c4 at the distance a = (d² + l2² − l3²)/2d from c2.
  const P c2 = tr.c1() + tr.crank() * P(cos(lim), sin(lim));
  const S d = (tr.c4() - c2).norm();
  const P c3 = c2 + (d * d + tr.coupler() * tr.coupler() - tr.rocker() * tr.rocker()) / (S(2) * d) * (tr.c4() - c2) / d;
  bool threw = false;
  try {
    (void)FourBar<S>::velocityRatios(tr.c1(), c2, c3, tr.c4());
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("at the crank limit (coupler ∥ rocker, a dead centre) the ratios are infinite → InvalidInput", 1, threw ? 1 : 0);
}

// GF §5.4, GF-5.4-fourbar-pole-velocity
template <class S> void poleVelocity(Context& c) {
  using P = Vec2<S>;
  const FourBar<S> fb = catalogueBar<S>();
  const auto p = *fb.solve(S(1), 1);
  const MotionJet<S> jet = catalogueJet<S>();
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(jet);
  const auto d3 = jet.bodyPointDerivatives(P(fb.coupler(), S(0)));
  const P u = p.c3 - fb.c4();
  const S w4 = cross2<S>(u, d3[1]) / u.squaredNorm();
  const S w4d = cross2<S>(u, d3[2]) / u.squaredNorm() - S(2) * w4 * u.dot(d3[1]) / u.squaredNorm();
  const P r1 = FourBar<S>::poleVelocity(fb.c1(), p.c2, inv.omega(), inv.omega(1), S(1), frac<S>(3, 10));
  const P r4 = FourBar<S>::poleVelocity(fb.c4(), p.c3, inv.omega(), inv.omega(1), w4, w4d);
  c.checkResidual("2ω²ṙ from the crank side = 2ω²·ṙ of the finite-pole curve (1024 ε)", S((r1 - inv.r(1)).norm()), tol<S>(1024));
  c.checkResidual("2ω²ṙ from the rocker side (1024 ε)", S((r4 - inv.r(1)).norm()), tol<S>(1024));
  const auto q = fixedCentrode(jet);
  const P qd(q[0].derivative(1), q[1].derivative(1));
  c.checkPrintedFails("the formula read as the velocity of the classical centrode (q̇ = 2ṙ)", "E5.9", S((r1 - qd).norm()), tol<S>(1024));
}

// GF §5.4, GF-5.4-fourbar-angular-acceleration (E5.17)
template <class S> void angularAcceleration(Context& c) {
  using P = Vec2<S>;
  const FourBar<S> fb = catalogueBar<S>();
  const auto p = *fb.solve(S(1), 1);
  const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(catalogueJet<S>());
  const S wd = FourBar<S>::omegaDot(fb.c1(), p.c2, p.c3, fb.c4(), S(1), frac<S>(3, 10));
  c.checkNear("ω̇ by the book's closed form (catalogue 0.261021037565; 12 decimals + 1024 ε)", fromString<S>("0.261021037565"), wd,
              printedTol<S>(12, 1024));
  c.checkNear("… = ω̇ of the jet (1024 ε)", inv.omega(1), wd, tol<S>(1024));
  S worst(0);
  for (int k = 0; k < 24; ++k) {
    const S th = frac<S>(13 + 26 * k, 100);
    const auto q = *fb.solve(th, -1);
    const MotionJet<S> jet = fb.couplerJet(th, -1, {th, frac<S>(13, 10), frac<S>(-4, 10), S(0), S(0)});
    worst = maxOf(worst, S(abs(FourBar<S>::omegaDot(fb.c1(), q.c2, q.c3, fb.c4(), frac<S>(13, 10), frac<S>(-4, 10)) - jet.angle().derivative(2))));
  }
  c.checkResidual("ω̇ formula = jet over 24 crank angles, lower branch, ω₁ = 1.3, ω̇₁ = −0.4 (4096 ε)", worst, tol<S>(4096));
  // E5.17: dotting with E₂(c4 − c2) does not eliminate ω̇₄; E₂(c3 − c4) does
  const P r4 = p.c3 - fb.c4();
  c.checkResidual("(c3 − c4)·E₂(c3 − c4) = 0: E₂(c3 − c4) eliminates ω̇₄ (4 ε)", S(abs(r4.dot(E2(r4)))), tol<S>(4));
  c.checkPrintedFails("\"scalar product with E₂(c4 − c2)\" eliminates ω̇₄: (c3 − c4)·E₂(c4 − c2) should be 0", "E5.17",
                      S(abs(r4.dot(E2(P(fb.c4() - p.c2))))), tol<S>(4));
}

/// The figure of GF-5.4-coupler-curves-and-invariants, drawn in double (soma::render).
void couplerFigure(Context& c) {
  const FourBar<double> fb(V2(0, 0), V2(3, 0), 1.2, 2.5, 2.0, V2(0.8, 1.1));
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

// GF §5.4, GF-5.4-coupler-curves-and-invariants
template <class S> void couplerCurves(Context& c) {
  using P = Vec2<S>;
  const P pc = pt<S>(8, 11);
  const FourBar<S> fb = catalogueBar<S>(pc);
  c.checkEqual("Grashof class of the catalogue 4-bar", "crank-rocker", grashofName(fb.classify().type));
  // the degree-6 equation on both circuits
  const Poly2<S> sextic = fb.couplerCurve();
  c.checkEqual("degree of the coupler curve", 6, sextic.degree(tol<S>(64)));
  S worst(0);
  for (int k = 0; k < fb.circuitCount(); ++k)
    for (const auto& p : fb.traceCircuit(k, 360)) {
      const P q = fb.couplerPointWorld(p);
      worst = maxOf(worst, S(abs(sextic(q(0), q(1))) / sextic.magnitude(q(0), q(1))));
    }
  c.checkResidual("coupler points of both circuits satisfy the sextic (720 points, relative; 1024 ε)", worst, tol<S>(1024));
  c.checkResidual("tricircular: degree-6 part ∝ (x² + y²)³ (256 ε)",
                  S(abs(sextic.at(4, 2) - S(3) * sextic.at(6, 0)) + abs(sextic.at(2, 4) - S(3) * sextic.at(6, 0)) +
                    abs(sextic.at(0, 6) - sextic.at(6, 0))),
                  S(tol<S>(256) * abs(sextic.at(6, 0))));
  // sweep the crank: inflections of the coupler curve (sampled) lie on the inflection circle of that
  // instant. The traced point is one of the inflection circle at θ₁ = 1 (so it has inflections).
  // Sampled curvature by the 5-point stencil with h = 1e-4: truncation h⁴ ≈ 1e-16, rounding 16 ε/h²
  // (3.5e-7 in double), tolerance 1e-6.
  const S fdTol = frac<S>(1, 1000000);
  if (fdResolves<S>(c, "the inflections of the coupler curve found by sampled curvature (two checks)", 1e-4, 2, fdTol)) {
    const S h = frac<S>(1, 10000);
    const P pcInf = [&] {
      const InstantInvariants<S> i1 = InstantInvariants<S>::fromJet(fb.couplerJet(S(1), 1, {S(1), S(1), S(0), S(0), S(0)}));
      const Circle<S> c1 = i1.inflectionCircle();
      const S a = frac<S>(77, 100);
      return P(fb.solve(S(1), 1)->coupler.inverse().act(P(c1.centre + c1.radius * P(cos(a), sin(a)))));
    }();
    const int N = 3600;
    std::vector<S> kap(N);
    std::vector<FourBarPose<S>> poses = fb.traceCircuit(0, N);
    for (int k = 0; k < N; ++k) kap[k] = fdCurvature<S>(fb, poses[k].theta1, poses[k].mode, pcInf, h);
    S worstInf(0);
    int inflections = 0;
    for (int k = 0; k < N; ++k) {
      const int k2 = (k + 1) % N;
      if (kap[k] * kap[k2] >= S(0)) continue;
      // bisection in θ₁ between the samples
      S a = poses[k].theta1, b = poses[k2].theta1;
      if (b < a) b += S(2) * pi<S>();
      S fa = kap[k];
      for (int it = 0; it < 40; ++it) {
        const S m = (a + b) / S(2), fm = fdCurvature<S>(fb, m, 1, pcInf, h);
        if (fa * fm <= S(0)) b = m;
        else {
          a = m;
          fa = fm;
        }
      }
      const S th = (a + b) / S(2);
      const InstantInvariants<S> inv = InstantInvariants<S>::fromJet(fb.couplerJet(th, 1, {th, S(1), S(0), S(0), S(0)}));
      const Circle<S> ci = inv.inflectionCircle();
      const P q = fb.solve(th, 1)->coupler.act(pcInf);
      worstInf = maxOf(worstInf, S(abs((q - ci.centre).norm() - ci.radius) / ci.radius));
      ++inflections;
    }
    c.checkEqual("inflections of the coupler curve found by sampling (even, > 0)", 1, (inflections > 0 && inflections % 2 == 0) ? 1 : 0);
    c.checkResidual("each inflection lies on the inflection circle of its instant (relative)", worstInf, fdTol);
    c.note("The coupler curve of a point of the inflection circle at θ₁ = 1 has " + std::to_string(inflections) +
           " inflections on circuit 0; at each, P is on that instant's inflection circle.");
  }
  // change-point extreme: the figure-eight circuit passes the node smoothly
  const FourBar<S> cp(pt<S>(0, 0), pt<S>(30, 0), S(1), frac<S>(25, 10), frac<S>(15, 10), pc);
  c.checkEqual("change-point 4-bar (3, 1, 2.5, 1.5): class", "change-point", grashofName(cp.classify().type));
  c.checkEqual("… one circuit of period 4π (a figure eight through the node)", 1, cp.circuitCount());
  if (c.makeFigures()) couplerFigure(c);
}

}  // namespace

SOMA_STUDY_SCALAR("GF-5.4-fourbar-loop", "4-bar loop equation, circuits, c2 and c3 as Burmester points", "GF §5.4", loop);
SOMA_STUDY_SCALAR("GF-5.4-fourbar-instant-centre", "Instant centre of the coupler (E5.16); ω = 0 extreme", "GF §5.4", instantCentre);
SOMA_STUDY_SCALAR("GF-5.4-fourbar-velocity-ratios", "Angular velocity ratios ω/ω₁, ω₄/ω₁", "GF §5.4", velocityRatios);
SOMA_STUDY_SCALAR("GF-5.4-fourbar-pole-velocity", "Velocity of the pole, from both sides", "GF §5.4", poleVelocity);
SOMA_STUDY_SCALAR("GF-5.4-fourbar-angular-acceleration", "Angular acceleration of the coupler (E5.17)", "GF §5.4", angularAcceleration);
SOMA_STUDY_SCALAR("GF-5.4-coupler-curves-and-invariants", "Coupler curves (degree 6) and their invariants along the cycle", "GF §5.4",
                  couplerCurves);

}  // namespace soma::studies::gf05p::SOMA_UNITY_ID
