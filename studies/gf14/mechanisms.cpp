// Studies of GF §14.4–14.6 (in the asked scalar; the figures in double): the planar 4-bar (planar inertia, null vector α — erratum 8,
// equation of motion, shaking moment — erratum 9, torque curve, free motion), the planar biped
// (joint equations — erratum 11, vertical foot force — erratum 10, lift-off, passive fall), the
// Stewart platform (constraint wrenches, leg equations — errata 7, 13, the 18 × 24 α system —
// erratum 14, the 5-step inverse dynamics — erratum 15, computed-force control), Figs. 14.2–14.4.
#include "gf14/common.hpp"

#include "soma/algebra/small_linalg.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

namespace soma::studies::gf14::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;
using V2 = Eigen::Vector2d;

constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";

template <class S> Vec6<S> sv(const S& a, const S& b, const S& c, const S& d, const S& e, const S& f) {
  return (Vec6<S>() << a, b, c, d, e, f).finished();
}
template <class S> Vec6<S> stewartTwist() { return sv<S>(frac<S>(1, 10), frac<S>(-1, 5), frac<S>(1, 20), frac<S>(1, 10), frac<S>(1, 5), frac<S>(-1, 10)); }
template <class S> Vec6<S> stewartAcc() { return sv<S>(frac<S>(1, 2), frac<S>(-3, 10), frac<S>(1, 5), frac<S>(-2, 5), frac<S>(3, 5), S(1)); }

/// The 4-bar null vector with the printed first entry α₁ = d₁d₄ sin θ₂ − d₂d₄ sin(θ₁+θ₂).
// GF §14.4 line 9177 as printed (erratum 8)
template <class S> Eigen::Matrix<S, 4, 1> alphaAsPrinted(const FourBarDynamics<S>& fb, const FourBarPosture<S>& p) {
  using std::sin;
  const auto& d = fb.lengths();
  Eigen::Matrix<S, 4, 1> a = fb.alpha(p);
  a(0) = d[0] * d[3] * S(sin(p.theta2)) - d[1] * d[3] * S(sin(S(p.theta1 + p.theta2)));
  return a;
}

/// α₁τ = q̈₁ᵀN₁α₁s₁ + q̈₂ᵀN₂(α₁s₁ + α₂s₂) − q̈₃ᵀN₃α₄s₄ solved for τ, with the printed α.
// GF §14.4 line 9195 with the α of line 9177 as printed (erratum 8)
template <class S> S torqueAlphaAsPrinted(const FourBarDynamics<S>& fb, const S& theta1, const S& theta1Dot, const S& theta1DDot) {
  const FourBarMotion<S> m = fb.motion(theta1, theta1Dot, theta1DDot);
  const auto s = fb.screws(m.posture);
  const Eigen::Matrix<S, 4, 1> a = alphaAsPrinted(fb, m.posture);
  const S lhs = m.twistDot[0].dot(m.inertia[0] * PVec<S>(a(0) * s[0])) + m.twistDot[1].dot(m.inertia[1] * PVec<S>(a(0) * s[0] + a(1) * s[1])) -
                m.twistDot[2].dot(m.inertia[2] * PVec<S>(a(3) * s[3]));
  return lhs / a(0);
}

/// The s₁-paired root equation (left side) with the printed +θ̈₄s₁ᵀN₃s₄ (from q̇₃ = +θ̇₄s₄, line 9159).
// GF §14.4 line 9203 as printed (erratum 9)
template <class S> S shakingMomentLhsAsPrinted(const FourBarDynamics<S>& fb, const S& theta1, const S& theta1Dot, const S& theta1DDot) {
  const FourBarMotion<S> m = fb.motion(theta1, theta1Dot, theta1DDot);
  const auto s = fb.screws(m.posture);
  const PMat<S>&N1 = m.inertia[0], &N2 = m.inertia[1], &N3 = m.inertia[2];
  const S t1d = m.rate(0), t2d = m.rate(1), t4d = m.rate(3), t1dd = m.acc(0), t2dd = m.acc(1), t4dd = m.acc(3);
  const PVec<S> b12 = planarBracket<S>(s[0], s[1]), b14 = planarBracket<S>(s[0], s[3]);
  return t1dd * s[0].dot(N1 * s[0]) + t1dd * s[0].dot(N2 * s[0]) + t2dd * s[0].dot(N2 * s[1]) + t4dd * s[0].dot(N3 * s[3]) +
         2 * t1d * t2d * s[0].dot(N2 * b12) + t2d * t2d * s[1].dot(N2 * b12) + t4d * t4d * s[3].dot(N3 * b14);
}

/// λ_Ry = α_Rh(E_Rh − τ_Rh) + α_Rk(E_Rk − τ_Rk) with the printed x-based weights
/// α_Rh = (x_Ra − x_Rk)/Δ, α_Rk = (x_h − x_Ra)/Δ, Δ = (x_Ra − x_Rk)(y_Ra − y_h) + (x_h − x_Ra)(y_Ra − y_Rk).
// GF §14.5 lines 9268–9282 as printed (erratum 10)
template <class S>
S verticalFootForceAlphaAsPrinted(const PlanarBiped<S>& b, const DynVector<S>& th, const DynVector<S>& thd, const DynVector<S>& thdd,
                                  const DynVector<S>& tau) {
  const auto j = b.jointCentres(th);
  const S xh = j[0](0), yh = j[0](1), xk = j[1](0), yk = j[1](1), xa = j[2](0), ya = j[2](1);
  const S D = (xa - xk) * (ya - yh) + (xh - xa) * (ya - yk);
  const DynVector<S> E = b.model().tree().inverseDynamics(th, thd, thdd);
  return (xa - xk) / D * (E(3) - tau(3)) + (xh - xa) / D * (E(4) - tau(4));
}

// Thresholds: multiples of ε of S (Tolerance<S>::identity), named in each check, from the size of the
// numbers (unit-scale screws and inertias, torques of O(10) N·m, forces of O(100) N on the biped and the
// platform) and the length of the computation; a printed formula's miss is compared with the corrected
// check's bound (checkPrintedFails asks for 1000× more).

template <class S> void planarInertiaStudy(Context& ctx) {
  using std::abs;
  auto g = std::mt19937_64(1441);
  S worst = S(0), kErr = S(0);
  for (int c = 0; c < 5; ++c) {
    const S m = uni<S>(g, 0.5, 3), cx = uni<S>(g), cy = uni<S>(g), ic = uni<S>(g, 0.05, 0.5);
    const Mat6<S> N = planarBodyInertia<S>(m, cx, cy, ic);
    const PMat<S> P = planarInertia<S>(m, cx, cy, ic);
    const int idx[3] = {2, 3, 4};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) worst = maxOf<S>(worst, S(abs(S(N(idx[i], idx[j]) - P(i, j)))));
    kErr = maxOf<S>(kErr, S(abs(S(P(0, 0) / m - (ic / m + cx * cx + cy * cy)))));
  }
  // the same few products of the body's numbers (≤ 3) by two routes: 64 ε
  ctx.checkResidual("planar N = the (ω_z, v_x, v_y) block of the spatial N (5 random bodies; 64 ε)", worst, tol<S>(64));
  ctx.checkResidual("m k² = I₃₃ about the ORIGIN: k² = k_c² + |c|² (parallel axes; 64 ε)", kErr, tol<S>(64));
  const S px = frac<S>(7, 10), py = frac<S>(-1, 5);
  const PVec<S> s = planarJointScrew<S>(px, py);
  ctx.checkResidual("a joint at p has s = (1, p_y, −p_x): the 3-D screw (k, p × k) restricted (exact)",
                    S(abs(S(s(0) - 1)) + abs(S(s(1) - py)) + abs(S(s(2) + px))), S(0));
}

template <class S> void nullVector(Context& ctx) {
  using std::abs, std::sin;
  const FourBarDynamics<S> fb = crankRocker<S>();
  S fix = S(0), prRes = S(0), prPred = S(0);
  const S dd = S(1) * (frac<S>(25, 10) - frac<S>(22, 10));  // d₁(d₄ − d₂)
  for (int k = 0; k < 12; ++k) {
    const FourBarPosture<S> p = fb.posture(frac<S>(1, 10) + frac<S>(k, 2));
    const auto s = fb.screws(p);
    const Eigen::Matrix<S, 4, 1> a = fb.alpha(p), b = alphaAsPrinted(fb, p);
    fix = maxOf<S>(fix, maxAbsM<S>(PVec<S>(a(0) * s[0] + a(1) * s[1] + a(2) * s[2] + a(3) * s[3])));
    const PVec<S> rb = b(0) * s[0] + b(1) * s[1] + b(2) * s[2] + b(3) * s[3];
    prRes = maxOf<S>(prRes, maxAbsM<S>(rb));
    prPred = maxOf<S>(prPred, S(abs(S(rb(0) - dd * S(sin(p.theta2)))) + abs(rb(1)) + abs(rb(2))));
  }
  // four products of lengths ≤ 2.5 with the joint positions (sums of lengths·cos/sin): 64 ε
  ctx.checkResidual("α₁s₁ + α₂s₂ + α₃s₃ + α₄s₄ = 0 with α₁ = d₁d₂ sin θ₂ − d₂d₄ sin(θ₁+θ₂) (12 postures; 64 ε)", fix, tol<S>(64));
  ctx.checkPrintedFails("α₁ = d₁d₄ sin θ₂ − d₂d₄ sin(θ₁+θ₂) (line 9177)", "8", prRes, tol<S>(64));
  ctx.checkResidual("printed residual = (d₁(d₄ − d₂) sin θ₂, 0, 0) exactly (64 ε)", prPred, tol<S>(64));
  const FourBarDynamics<S> eq = crankRocker<S>(frac<S>(25, 10));  // d₂ = d₄: the printed formula happens to be right
  const FourBarPosture<S> p = eq.posture(S(1));
  ctx.checkResidual("extreme d₂ = d₄: printed α = corrected α (8 ε)", maxAbsM<S>(Eigen::Matrix<S, 4, 1>(eq.alpha(p) - alphaAsPrinted(eq, p))), tol<S>(8));
}

/// The five crank states (θ₁, θ̇₁, θ̈₁) of fourbar_check.py, exact tenths.
constexpr int kCrankStates[5][3] = {{3, 12, -7}, {14, -8, 20}, {26, 25, 3}, {40, 10, 10}, {55, -17, -11}};

template <class S> void fourBarEom(Context& ctx) {
  using std::abs, std::log2;
  using R = Ref<S>;
  const FourBarDynamics<S> fb = crankRocker<S>();
  const ConstrainedTree<S> m = fb.constrainedTree(frac<S>(3, 10));
  DynMatrix<S> B = DynMatrix<S>::Zero(3, 1);
  B(0, 0) = S(1);
  const FourBarDynamics<R> fq = crankRocker<R>();
  // The difference step: E_K along the crank path has a large 9th derivative (|f⁽⁹⁾|/630 ≈ 3.5e5, measured: at
  // d = 1/256 the truncation d⁸|f⁽⁹⁾|/630 was 1.9e-14), so d = 1/2048 in __float128 (truncation 1.1e-21, rounding
  // 2ε|E|/d ≈ 1e-29) and ε^(1/9)/8 in S itself (truncation 0.02 ε^(8/9), rounding 16ε|E|/ε^(1/9) ≈ 160 ε^(8/9),
  // within fdTol = 4096 ε^(8/9)).
  const R d = kWideRef<S> ? R(R(1) / 2048) : R(diffStep<S>() / 8);
  S eMul = S(0), ePow = S(0), ePr = S(0);
  for (const auto& x : kCrankStates) {
    const S t1 = frac<S>(x[0], 10), t1d = frac<S>(x[1], 10), t1dd = frac<S>(x[2], 10);
    const S tau = fb.torqueAlpha(t1, t1d, t1dd);
    const auto st = fb.treeState(frac<S>(3, 10), fb.motion(t1, t1d, t1dd));
    eMul = maxOf<S>(eMul, S(abs(S(m.inverseDynamicsMultipliers(st[0], st[1], st[2], B).actuators(0) - tau))));
    const R q1 = frac<R>(x[0], 10), q1d = frac<R>(x[1], 10), q1dd = frac<R>(x[2], 10);
    const R dE = diff8<R>([&](const R& s) { return fq.kineticEnergy(R(q1 + q1d * s + q1dd * s * s / 2), R(q1d + q1dd * s)); }, d);
    ePow = maxOf<S>(ePow, S(abs(S(scalarCast<S>(R(dE / q1d)) - tau))));
    ePr = maxOf<S>(ePr, S(abs(S(torqueAlphaAsPrinted(fb, t1, t1d, t1dd) - tau))));
  }
  // torques of O(10) N·m: the α equation (closed form) and the 3-D tree's multiplier solve agree to 512 ε;
  // the virtual-work reference adds its difference bound (fdTol; 0 where it is computed in __float128)
  ctx.checkResidual("α₁τ = q̈₁ᵀN₁α₁s₁ + q̈₂ᵀN₂(α₁s₁+α₂s₂) − q̈₃ᵀN₃α₄s₄ = Lagrange multipliers (3-D tree, 5 states of fourbar_check.py; 512 ε)",
                    eMul, tol<S>(512));
  ctx.checkResidual(std::string("= virtual work τθ̇₁ = dE_K/dt (8th-order differences ") + (kWideRef<S> ? "in __float128" : "in S at d = ε^(1/9)") +
                        "; 512 ε + difference bound)",
                    ePow, S(tol<S>(512) + fdTol<S>()));
  ctx.checkPrintedFails("the same equation with the printed α₁ (fourbar_check.py: 0.285; bound: the corrected equation's 512 ε)", "8", ePr,
                        tol<S>(512));
  ctx.note("Printed-α torque error " + toString(toDouble(ePr), 4) + " N·m (the catalogue's script: 0.285). Invented crank–rocker d = (1, 2.2, 1.8, 2.5), "
           "masses 1, 2, 1.5 kg (the book gives no numbers).");
  // free motion: the book's equation integrated (RK4 on θ₁) conserves E_K to the order of the method
  auto run = [&](const S& h, int steps) {
    std::array<S, 2> y{frac<S>(3, 10), S(2)};
    const S e0 = fb.kineticEnergy(y[0], y[1]);
    S w = S(0);
    for (int k = 0; k < steps; ++k) {
      y = fb.rk4Step(y, h, S(0));
      w = maxOf<S>(w, S(abs(S(fb.kineticEnergy(y[0], y[1]) - e0)) / e0));
    }
    return w;
  };
  // The order, fitted over h = 10, 5, 2.5 ms: log₂(e(h)/e(h/4))/2 (the least-squares slope on three
  // equally spaced log h). It differs from 4 by the O(h) next term of the error expansion: the
  // pairwise orders (in the note) put that at 0.02 here, so the margin is 0.05 (2.5×); rounding
  // (ε·steps ≈ 3e-13 relative in double) is far below the smallest error fitted (4e-10) — but not in float.
  const S r1 = run(frac<S>(1, 100), 300), r2 = run(frac<S>(1, 200), 600), r3 = run(frac<S>(1, 400), 1200);
  if (std::is_same_v<S, float>)
    ctx.note("float: the fitted RK4 order is not checked — the energy errors fitted (4e-10 … 1e-7 relative in double) lie below float's "
             "rounding over 300–1200 steps (ε·steps ≈ 1e-4).");
  else
    ctx.checkNear("free 4-bar (τ = 0, 3 s): fitted order of the RK4 energy error, h = 10, 5, 2.5 ms (4 ± 0.05)", S(4), S(log2(S(r1 / r3)) / 2),
                  frac<S>(5, 100));
  ctx.note("Free 4-bar energy error over 3 s: " + toString(toDouble(r1), 3) + " (h = 10 ms), " + toString(toDouble(r2), 3) + " (h = 5 ms), " +
           toString(toDouble(r3), 3) + " (h = 2.5 ms), relative; pairwise orders " + toString(toDouble(S(log2(S(r1 / r2)))), 4) + ", " +
           toString(toDouble(S(log2(S(r2 / r3)))), 4) + ".");
  if (!ctx.makeFigures()) return;
  // the figure in double (soma::render draws double geometry), whatever the scalar of the checks
  const FourBarDynamics<double> fd = crankRocker<double>();
  const ConstrainedTree<double> md = fd.constrainedTree(0.3);
  const DM Bd = castMatrix<double>(B);
  std::vector<double> th, tc, tp, tm;
  for (int k = 0; k <= 360; ++k) {
    const double t1 = k * M_PI / 180;
    th.push_back(k);
    tc.push_back(fd.torqueAlpha(t1, 2 * M_PI, 0.0));
    tp.push_back(torqueAlphaAsPrinted<double>(fd, t1, 2 * M_PI, 0.0));
    if (k % 30 == 0) {
      const auto st = fd.treeState(0.3, fd.motion(t1, 2 * M_PI, 0.0));
      tm.push_back(md.inverseDynamicsMultipliers(st[0], st[1], st[2], Bd).actuators(0));
    }
  }
  rd::Plot p;
  p.title = "4-bar crank torque τ(θ₁) at constant speed θ̇₁ = 2π rad/s (no gravity)";
  p.x.label = "crank angle θ₁ [deg]";
  p.y.label = "τ [N·m]";
  p.add("α equation, corrected α₁ (erratum 8)", th, tc, rd::Color::hex(0x0072B2));
  p.add("α equation, printed α₁", th, tp, rd::Color::hex(0xD55E00)).dashed = true;
  std::vector<double> tk;
  for (int k = 0; k <= 360; k += 30) tk.push_back(k);
  auto& mk = p.add("Lagrange multipliers (3-D constrained tree)", tk, tm, rd::Color::hex(0x009E73));
  mk.line = false;
  mk.markers = true;
  p.legend = rd::LegendCorner::TopRight;
  const std::string file = "GF-14.4-torque-curve.png";
  rd::renderPlotPngAndSvg(p, ctx.figurePath(file));
  ctx.figure(file, "Driving torque of the crank–rocker over one revolution at constant crank speed: the book's α equation with the "
                   "corrected α₁ (line) agrees with the Lagrange-multiplier solution of the 3-D tree (dots); the printed α₁ (dashed) does not.");
}

template <class S> void shakingMoment(Context& ctx) {
  using std::abs;
  const FourBarDynamics<S> fb = crankRocker<S>();
  const ConstrainedTree<S> m = fb.constrainedTree(frac<S>(3, 10));
  S eFix = S(0), ePr = S(0), sc = S(0);
  // 5-point central differences at d = ε^(1/5) (fd4Step; d = 1e-3 before), 2048 ε^(4/5) relative (fd4Tol;
  // 6.4e-10 in double, 1e-8 before)
  const S d = fd4Step<S>();
  for (int t10 : {3, 14, 26, 40, 55}) {
    const S t1 = frac<S>(t10, 10), t1d = frac<S>(13, 10), t1dd = frac<S>(-9, 10);
    auto P = [&](const S& t) {
      const auto st = fb.treeState(frac<S>(3, 10), fb.motion(S(t1 + t1d * t + t1dd * t * t / 2), S(t1d + t1dd * t), t1dd));
      return S(m.tree().momentum(st[0], st[1])(2));  // moment about the origin (s₁ = (1, 0, 0))
    };
    const S dP = (S(8) * S(P(d) - P(S(-d))) - S(P(S(2 * d)) - P(S(-2 * d)))) / S(12 * d);
    sc = maxOf<S>(sc, S(abs(dP)));
    eFix = maxOf<S>(eFix, S(abs(S(fb.shakingMomentLhs(t1, t1d, t1dd) - dP))));
    ePr = maxOf<S>(ePr, S(abs(S(shakingMomentLhsAsPrinted(fb, t1, t1d, t1dd) - dP))));
  }
  const S fdBound = fd4Tol<S>();
  ctx.checkResidual("s₁-paired root equation (7 terms, −θ̈₄s₁ᵀN₃s₄) = s₁ᵀ d(total momentum)/dt (relative; differences at ε^(1/5), 2048 ε^(4/5))",
                    S(eFix / sc), fdBound);
  if (std::is_same_v<S, float>)
    ctx.note("float: the printed display (erratum 9, off by " + toString(toDouble(S(ePr / sc)), 3) + " relative) is not checked — the corrected "
             "equation's difference bound 2048 ε^(4/5) = 5.9e-3 leaves no room for the 1000× an erratum must miss by.");
  else
    ctx.checkPrintedFails("the display at line 9203 with +θ̈₄s₁ᵀN₃s₄ (q̇₃ = +θ̇₄s₄, line 9159; bound: the corrected 2048 ε^(4/5))", "9",
                          S(ePr / sc), fdBound);
}

// ---------------------------------------------------------------------------------------------
template <class S> struct BipedRun {
  std::vector<S> t, lamRy, lamRyAlpha, lamLy, hipX;
  S liftOff = S(-1);
};
/// The weight shift: the hip moves by (−0.36, −0.13) m over T = 2 s along s(t) = (1 − cos(πt/T))/2.
template <class S> BipedRun<S> bipedShift(const PlanarBiped<S>& b) {
  using std::cos, std::sin;
  using V3S = Eigen::Matrix<S, 3, 1>;
  BipedRun<S> r;
  const S T = S(2), x1 = frac<S>(-36, 100), y1 = frac<S>(-13, 100), w = pi<S>() / T;
  for (int k = 0; k <= 200; ++k) {
    const S t = T * S(k) / S(200), s = (S(1) - S(cos(S(w * t)))) / S(2);
    const S sd = w / S(2) * S(sin(S(w * t))), sdd = w * w / S(2) * S(cos(S(w * t)));
    BipedPose<S> pose = bipedHome<S>();
    pose.hip(0) = x1 * s;
    pose.hip(1) += y1 * s;
    const DynVector<S> th = b.angles(pose);
    const DynVector<S> thd = b.completeRates(th, V3S(S(x1 * sd), S(y1 * sd), S(0)));
    const DynVector<S> thdd = b.completeAccelerations(th, thd, V3S(S(x1 * sdd), S(y1 * sdd), S(0)));
    const DynVector<S> tau = b.torquesForMotion(th, thd, thdd);
    const DynVector<S> lam = b.footForces(th, thd, thdd, tau);
    r.t.push_back(t);
    r.hipX.push_back(pose.hip(0));
    r.lamRy.push_back(lam(1));
    r.lamLy.push_back(lam(3));
    r.lamRyAlpha.push_back(b.verticalFootForceAlpha(th, thd, thdd, tau));
    if (r.liftOff < S(0) && lam(1) < S(0)) r.liftOff = t;
  }
  return r;
}
/// A random biped state: the hip displaced within ±8 cm, hip rates and accelerations uniform in [−1, 1].
template <class S> struct BipedState {
  DynVector<S> th, thd, thdd;
};
template <class S> BipedState<S> randomBipedState(const PlanarBiped<S>& b, std::mt19937_64& g, bool tiltTorso) {
  BipedPose<S> pose = bipedHome<S>();
  const S hx = uni<S>(g, -0.08, 0.08), hy = uni<S>(g, -0.08, 0.05);
  pose.hip += Eigen::Matrix<S, 2, 1>(hx, hy);
  if (tiltTorso) pose.torsoAngle = uni<S>(g, -0.3, 0.3);
  BipedState<S> x;
  x.th = b.angles(pose);
  x.thd = b.completeRates(x.th, rv3<S>(g));
  x.thdd = b.completeAccelerations(x.th, x.thd, rv3<S>(g));
  return x;
}

template <class S> void bipedEquations(Context& ctx) {
  using DVS = DynVector<S>;
  using V6S = Vec6<S>;
  using std::abs;
  auto g = std::mt19937_64(1451);
  const PlanarBiped<S> b(bipedParameters<S>(), bipedHome<S>());
  const ConstrainedTree<S>& m = b.model();
  S res = S(0), pr = S(0), sc = S(0);
  for (int c = 0; c < 5; ++c) {
    const BipedState<S> x = randomBipedState<S>(b, g, true);
    const DVS tau = b.torquesForMotion(x.th, x.thd, x.thdd), lam = b.footForces(x.th, x.thd, x.thdd, tau);
    // the seven joint equations (knees, hips, torso root) with the ankle wrenches
    const DVS E = m.tree().inverseDynamics(x.th, x.thd, x.thdd);
    res = maxOf<S>(res, maxAbsS<S>(DVS(E - tau - m.constraintMatrix(x.th).transpose() * lam)));
    sc = maxOf<S>(sc, maxAbsS<S>(E));
    // the torso root equation (all links) = Σ λ_k W_k; printed: Σ W_k without the λ's
    const auto Ws = m.constraintWrenches(m.tree().configuration(x.th));
    const V6S tot = m.tree().totalWrench(x.th, x.thd, x.thdd);
    V6S sumW = V6S::Zero(), sumLW = V6S::Zero();
    for (int k = 0; k < 4; ++k) {
      sumW += Ws[std::size_t(k)];
      sumLW += lam(k) * Ws[std::size_t(k)];
    }
    res = maxOf<S>(res, maxAbsM<S>(V6S(tot - sumLW)));
    pr = maxOf<S>(pr, maxAbsM<S>(V6S(tot - sumW)));
  }
  // seven joint equations and a least-squares λ over a 7-joint tree, relative to the largest torque: 4096 ε
  ctx.checkResidual("knee, hip and torso equations with λ_RxW_Rx + λ_RyW_Ry + λ_LxW_Lx + λ_LyW_Ly hold (relative; 4096 ε)", S(res / sc),
                    tol<S>(4096));
  ctx.checkPrintedFails("root equation with W_Rx + W_Ry + W_Lx + W_Ly (multipliers missing, line 9250; bound: the corrected 4096 ε)", "11",
                        S(pr / sc), tol<S>(4096));
  // passive fall with both feet pinned (τ = 0): RK4 + projection, 0.25 s
  ConstrainedState<S> y{DVS::Zero(7), DVS::Zero(7)};
  const S e0 = m.totalEnergy(y), h = frac<S>(1, 1000);
  const int steps = 250;
  S drift = S(0), de = S(0);
  for (int k = 0; k < steps; ++k) {
    y = m.rk4Step(y, h, DVS::Zero(7), true);
    drift = maxOf<S>(drift, maxAbsS<S>(m.positionResidual(y.theta)));
    de = maxOf<S>(de, S(abs(S(m.totalEnergy(y) - e0))));
  }
  // the projection (Newton to Tolerance::identity) leaves the ankles of the 1 m legs within 4096 ε; the energy:
  // RK4's global error C·h⁴ (h⁴ = 1e-12; C ≤ 1000 for this fall, 10 in double) plus 64 ε of rounding per step
  const S Escale = frac<S>(205, 10) * frac<S>(981, 100) * frac<S>(3, 4);
  ctx.checkResidual("passive fall (τ = 0, feet pinned, 0.25 s, h = 1 ms): ankle drift with projection (4096 ε)", drift, tol<S>(4096));
  ctx.checkResidual("energy conserved to RK4 accuracy (relative to E_P scale m g h; 1000 h⁴ + 250·64 ε)", S(de / Escale),
                    S(S(1000) * h * h * h * h + S(steps) * tol<S>(64)));
  ctx.note("Passive fall: the hip drops " + toString(toDouble(S(-y.theta(1))), 3) + " m in 0.25 s; ankle drift " + toString(toDouble(drift), 3) +
           " m, energy error " + toString(toDouble(de), 3) + " J.");
}

template <class S> void bipedFootForce(Context& ctx) {
  using DVS = DynVector<S>;
  using std::abs;
  auto g = std::mt19937_64(1452);
  const PlanarBiped<S> b(bipedParameters<S>(), bipedHome<S>());
  S eFix = S(0), ePr = S(0), ePrX = S(0);
  for (int c = 0; c < 5; ++c) {
    const BipedState<S> x = randomBipedState<S>(b, g, false);
    const DVS tau = b.torquesForMotion(x.th, x.thd, x.thdd), lam = b.footForces(x.th, x.thd, x.thdd, tau);
    const S pr = verticalFootForceAlphaAsPrinted<S>(b, x.th, x.thd, x.thdd, tau);
    eFix = maxOf<S>(eFix, S(abs(S(b.verticalFootForceAlpha(x.th, x.thd, x.thdd, tau) - lam(1)))));
    ePr = maxOf<S>(ePr, S(abs(S(pr - lam(1)))));
    ePrX = maxOf<S>(ePrX, S(abs(S(pr + lam(0)))));
  }
  // ankle forces of O(100) N (a 20.5 kg biped) by the book's dual velocities and by the least-squares
  // multipliers, with 1/Δ of the leg's joint positions: 65536 ε (1.5e-11 in double; 1e-10 before)
  ctx.checkResidual("λ_Ry by α_Rh = (y_Ra − y_Rk)/D, α_Rk = (y_h − y_Ra)/D = full multiplier system (65536 ε)", eFix, tol<S>(65536));
  ctx.checkPrintedFails("λ_Ry with the printed α (x-based, lines 9268–9282; bound: the corrected 65536 ε)", "10", ePr, tol<S>(65536));
  ctx.checkResidual("the printed weights give −λ_Rx (the horizontal force; 65536 ε)", ePrX, tol<S>(65536));
  const BipedRun<S> r = bipedShift<S>(b);
  S agree = S(0);
  for (std::size_t k = 0; k < r.t.size(); ++k) agree = maxOf<S>(agree, S(abs(S(r.lamRy[k] - r.lamRyAlpha[k]))));
  ctx.checkResidual("along the weight shift: α formula = multipliers at 201 instants (65536 ε)", agree, tol<S>(65536));
  ctx.checkEqual("the right foot's vertical force crosses zero (lift-off) during the shift", "yes", r.liftOff > S(0) ? "yes" : "no");
  ctx.note("Hip moved from (0, 0.75) to (−0.36, 0.62) m (left ankle at x = −0.2) in 2 s, torques of minimum norm: λ_Ry from " +
           toString(toDouble(r.lamRy.front()), 4) + " N to " + toString(toDouble(r.lamRy.back()), 4) + " N; lift-off (λ_Ry = 0) at t = " +
           toString(toDouble(r.liftOff), 3) + " s.");
  if (!ctx.makeFigures()) return;
  // the figure in double (soma::render draws double geometry), whatever the scalar of the checks
  const BipedRun<double> rd_ = bipedShift<double>(PlanarBiped<double>(bipedParameters<double>(), bipedHome<double>()));
  rd::Plot p;
  p.title = "Biped weight shift: vertical ankle forces (lift-off where λ_Ry = 0)";
  p.x.label = "t [s]";
  p.y.label = "vertical force [N]";
  p.add("right foot λ_Ry (multipliers)", rd_.t, rd_.lamRy, rd::Color::hex(0x0072B2));
  auto& al = p.add("right foot, book α (corrected)", rd_.t, rd_.lamRyAlpha, rd::Color::hex(0xE69F00));
  al.dashed = true;
  p.add("left foot λ_Ly", rd_.t, rd_.lamLy, rd::Color::hex(0x009E73));
  p.add("", {0, 2}, {0, 0}, rd::Color::hex(0x888888)).width = 1;
  if (rd_.liftOff > 0) {
    auto& lo = p.add("lift-off", {rd_.liftOff}, {0.0}, rd::Color::hex(0xD55E00));
    lo.line = false;
    lo.markers = true;
    lo.markerRadius = 9;
    p.texts.push_back({rd_.liftOff, 0.0, "lift-off t = " + toString(rd_.liftOff, 3) + " s", rd::Color::hex(0xD55E00), 20});
  }
  p.legend = rd::LegendCorner::TopRight;
  const std::string file = "GF-14.5-foot-force.png";
  rd::renderPlotPngAndSvg(p, ctx.figurePath(file));
  ctx.figure(file, "Vertical ankle forces while the hip moves over the left foot (minimum-norm joint torques): the right foot's force, "
                   "computed by the full multiplier system and by the book's dual velocities α (corrected, erratum 10), falls to zero "
                   "— the foot would lift off there — while the left foot takes the weight.");
}

// ---------------------------------------------------------------------------------------------
template <class S> void stewartWrenches(Context& ctx) {
  using V6S = Vec6<S>;
  const StewartDynamics<S> sd = stewartExample<S>(false);
  const ConstrainedTree<S> m = sd.model(stewartPose<S>());
  const auto W = m.constraintWrenches(m.tree().configuration(DynVector<S>::Zero(24)));
  S e = S(0);
  for (int i = 0; i < 6; ++i) {
    const Vec3<S> L = sd.base()[std::size_t(i)];
    const V6S wx = sv<S>(S(0), L.z(), S(-L.y()), S(1), S(0), S(0)), wy = sv<S>(S(-L.z()), S(0), L.x(), S(0), S(1), S(0)),
              wz = sv<S>(L.y(), S(-L.x()), S(0), S(0), S(0), S(1));
    e = maxOf<S>(e, maxAbsM<S>(V6S(W[std::size_t(3 * i)] - wx)));
    e = maxOf<S>(e, maxAbsM<S>(V6S(W[std::size_t(3 * i + 1)] - wy)));
    e = maxOf<S>(e, maxAbsM<S>(V6S(W[std::size_t(3 * i + 2)] - wz)));
  }
  // (L × e_k, e_k) of the ground point L at θ = 0 (the home placement): one product per entry, 4 ε
  ctx.checkResidual("W_ix = (0, z_L, −y_L, 1, 0, 0), W_iy = (−z_L, 0, x_L, 0, 1, 0), W_iz = (y_L, −x_L, 0, 0, 0, 1) (six legs; 4 ε)", e, tol<S>(4));
}

template <class S> void stewartLegs(Context& ctx) {
  using DVS = DynVector<S>;
  using V6S = Vec6<S>;
  using V3S = Vec3<S>;
  using std::abs;
  const StewartDynamics<S> sd = stewartExample<S>(false);
  const SE3<S> pose = stewartPose<S>();
  const ConstrainedTree<S> m = sd.model(pose);
  const StewartInverseDynamics<S> r = sd.inverseDynamics(pose, stewartTwist<S>(), stewartAcc<S>());
  const TreeConfiguration<S> c = m.tree().configuration(r.theta);
  S es = S(0);
  for (int i = 0; i < 6; ++i) {
    const V3S U = pose * sd.platformPoints()[std::size_t(i)], L = sd.base()[std::size_t(i)];
    es = maxOf<S>(es, maxAbsM<S>(V6S(c.screws[std::size_t(8 + 3 * i)] - v6<S>(V3S::Zero(), V3S((U - L) / (U - L).norm())))));
  }
  // a unit direction through the leg's transforms (the tree's placement at θ against the pose): 64 ε
  ctx.checkResidual("s_Li = (0, 0, 0, (x_U − x_L)/M, (y_U − y_L)/M, (z_U − z_L)/M) (line 9313, OCR-damaged; 64 ε)", es, tol<S>(64));
  const DVS E = m.tree().inverseDynamics(r.theta, r.thetaDot, r.thetaDDot);
  const DVS CtL = m.constraintMatrix(r.theta).transpose() * r.lambda;
  S act = S(0), pas = S(0);
  for (int i = 0; i < 6; ++i) {
    act = maxOf<S>(act, S(abs(S(E(8 + 3 * i) - r.forcesAlpha(i) - CtL(8 + 3 * i)))));
    pas = maxOf<S>(pas, maxOf<S>(S(abs(S(E(6 + 3 * i) - CtL(6 + 3 * i)))), S(abs(S(E(7 + 3 * i) - CtL(7 + 3 * i))))));
  }
  // leg forces of O(50) N from the 24 × 24 multiplier system (λ up to ≈ 100 N): 65536 ε (1.5e-11; 1e-10 before)
  ctx.checkResidual("actuator equations: LHS = F_i + Σ λ_i· W_i·ᵀ s_Li (six legs; 65536 ε)", act, tol<S>(65536));
  ctx.checkResidual("passive U-joint equations: LHS = Σ λ W ᵀ s_Ui1, s_Ui2 (no torque; 65536 ε)", pas, tol<S>(65536));
  ctx.checkResidual("platform equations (six root joints) = Σ λ W ᵀ s (no actuator; 65536 ε)", maxAbsS<S>(DVS(E.head(6) - CtL.head(6))),
                    tol<S>(65536));
  // erratum 7: {N q̇, q̇} read as the coadjoint with swapped arguments = −{q̇, N q̇}
  const StewartDynamics<S> sl = stewartExample<S>(true);
  const V6S qd = sv<S>(frac<S>(3, 10), frac<S>(-2, 5), frac<S>(1, 5), frac<S>(1, 10), frac<S>(1, 5), frac<S>(-1, 10)), qdd = stewartAcc<S>();
  const StewartInverseDynamics<S> rl = sl.inverseDynamics(pose, qd, qdd);
  const auto lines = sl.legLines(pose);
  V6S legs = V6S::Zero();
  for (int i = 0; i < 6; ++i) legs -= rl.forcesAlpha(i) * lines[std::size_t(i)];
  const Mat6<S> NP = sl.platformInertia().transformed(pose).matrix();
  const V6S swapped = rl.platformWrench - S(2) * coadjoint(SE3Tangent<S>(qd), V6S(NP * qd));
  // massless legs: a 6 × 6 solve for the forces of the 5 kg platform: 4096 ε
  ctx.checkResidual("massless legs: platform N q̈ + {q̇, N q̇} − G = −Σ F_i (unit leg lines; 4096 ε)", maxAbsM<S>(V6S(legs - rl.platformWrench)),
                    tol<S>(4096));
  ctx.checkPrintedFails("platform equation with {N q̇, q̇} = −{q̇, N q̇} (line 9329; bound: the corrected 4096 ε)", "7",
                        maxAbsM<S>(V6S(legs - swapped)), tol<S>(4096));
}

template <class S> void stewartAlpha(Context& ctx) {
  using DVS = DynVector<S>;
  using V3S = Vec3<S>;
  using std::abs, std::cos, std::sin;
  const StewartDynamics<S> sd = stewartExample<S>(false);
  const SE3<S> pose = stewartPose<S>();
  const ConstrainedTree<S> m = sd.model(pose);
  const DynMatrix<S> C = m.constraintMatrix(DVS::Zero(24));
  ctx.checkEqual("18 homogeneous equations in 24 unknown α's: rank 18 (kernel 6 = platform freedoms)", 18, m.constraintRank(DVS::Zero(24)));
  // massless legs: α matrix → the classical J⁻ᵀ (leg Plücker lines)
  const StewartDynamics<S> sl = stewartExample<S>(true);
  const StewartInverseDynamics<S> r = sl.inverseDynamics(pose, Vec6<S>::Zero(), Vec6<S>::Zero());
  const auto lines = sl.legLines(pose);
  Mat6<S> J;
  for (int i = 0; i < 6; ++i) J.col(i) = lines[std::size_t(i)];
  Vec6<S> Fj = -r.platformWrench;
  detail::smallSolveInPlace<S, 6>(J, Fj);  // F = −J⁻¹(gravity wrench), Gaussian elimination
  // two 6 × 6 solves (the α elimination and J) of unit leg lines, relative to the largest force: 4096 ε
  ctx.checkResidual("massless legs, static platform: F = −J⁻¹(gravity wrench), J = unit leg lines (relative; 4096 ε)",
                    S(maxAbsM<S>(Vec6<S>(r.forcesAlpha - Fj)) / maxAbsM<S>(Fj)), tol<S>(4096));
  ctx.note("Static leg forces of the 5 kg platform (massless legs): " + [&] {
    std::string s;
    for (int i = 0; i < 6; ++i) s += (i ? ", " : "") + toString(toDouble(r.forcesAlpha(i)), 4);
    return s;
  }() + " N.");
  // the differentiated constraints (line 9381, a '+' lost): C θ̈ + γ = 0 at the computed accelerations
  const StewartInverseDynamics<S> rr = sd.inverseDynamics(pose, stewartTwist<S>(), stewartAcc<S>());
  const DVS acc = C * rr.thetaDDot + m.accelerationBias(rr.theta, rr.thetaDot);
  // θ̈ of O(1) from the 24-joint solve against unit screws: 4096 ε
  ctx.checkResidual("W ᵀq̈_P + φ̈W ᵀs_U1 + θ̈W ᵀs_U2 + l̈W ᵀs_L = −(bracket terms) for all 18 constraints (4096 ε)", maxAbsS<S>(acc), tol<S>(4096));
  S printed = S(0);
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) {
      const int row = 3 * i + k;
      const S a = rr.thetaDDot(6 + 3 * i) * C(row, 6 + 3 * i), b = rr.thetaDDot(7 + 3 * i) * C(row, 7 + 3 * i);
      printed = maxOf<S>(printed, S(abs(S(acc(row) - a - b + a * b))));
    }
  ctx.checkPrintedFails("the same with φ̈W ᵀs_U1 θ̈W ᵀs_U2 multiplied (no '+', line 9381; bound: the corrected 4096 ε)", "14", printed, tol<S>(4096));
  // a posture near a singularity: the legs' lines nearly dependent → the α matrix ill-conditioned
  std::array<V3S, 6> b6, p6;
  for (int i = 0; i < 6; ++i) {
    const S a = S(i) * pi<S>() / S(3);
    b6[std::size_t(i)] = V3S(S(cos(a)), S(sin(a)), S(0));
    p6[std::size_t(i)] = V3S(S(cos(a) / 2), S(sin(a) / 2), S(0));  // all legs in planes through the z-axis: singular
  }
  const StewartDynamics<S> sing(b6, p6, SpatialInertia<S>(S(5), V3S::Zero(), Mat3<S>::Identity()),
                                StewartLegInertia<S>{S(0), S(0), S(0), S(0), S(0), S(0)}, frac<S>(981, 100));
  std::string verdict = "solved";
  try {
    sing.inverseDynamics(SE3<S>(SE3Tangent<S>(sv<S>(S(0), S(0), S(0), S(0), S(0), S(1))).exp()), Vec6<S>::Zero(), Vec6<S>::Zero());
  } catch (const InvalidInput&) {
    verdict = "InvalidInput";
  }
  ctx.checkEqual("radial legs (rotation about z unresisted): singular α matrix reported", "InvalidInput", verdict);
}

template <class S> void stewartAlgorithm(Context& ctx) {
  using DVS = DynVector<S>;
  using V6S = Vec6<S>;
  using std::abs, std::pow, std::exp;
  const StewartDynamics<S> sd = stewartExample<S>(false);
  // (1) power balance along a trajectory: Σ F_i l̇_i = d(E_K + E_P)/dt. The platform's twist and its rate by
  // 5-point differences of the pose at h = ε^(1/6) (nested: truncation (ωh)⁴/30 and rounding ε/h² both ≈ ε^(2/3);
  // h = 1e-3 before, 2.5e-3 in double now)
  const S h6 = Tolerance<S>::precision(5);
  auto twistAt = [&](const S& t, const S& h) {  // spatial twist of pose(t) by differences
    const Mat4<S> Pd = (S(8) * Mat4<S>(stewartPose<S>(S(t + h)).matrix() - stewartPose<S>(S(t - h)).matrix()) -
                        Mat4<S>(stewartPose<S>(S(t + 2 * h)).matrix() - stewartPose<S>(S(t - 2 * h)).matrix())) /
                       S(12 * h);
    return V6S(SE3Tangent<S>::vee(Mat4<S>(Pd * stewartPose<S>(t).inverse().matrix())).coeffs());
  };
  auto state = [&](const S& t) {
    const S h = h6;
    const V6S qd = twistAt(t, h);
    const V6S qdd = (S(8) * V6S(twistAt(S(t + h), h) - twistAt(S(t - h), h)) - V6S(twistAt(S(t + 2 * h), h) - twistAt(S(t - 2 * h), h))) / S(12 * h);
    return std::make_pair(qd, qdd);
  };
  auto energy = [&](const S& t) {
    const SE3<S> P = stewartPose<S>(t);
    const auto [qd, qdd] = state(t);
    const StewartInverseDynamics<S> r = sd.inverseDynamics(P, qd, qdd);
    const ConstrainedTree<S> m = sd.model(P);
    return S(m.tree().kineticEnergy(r.theta, r.thetaDot) + m.tree().potentialEnergy(r.theta));
  };
  // Bound: dE/dt by 5-point differences at d = 1e-2 is off by d⁴|E⁽⁵⁾|/30; the trajectory (stewartPose)
  // moves at ≤ 2 rad/s, so E (quadratic in the velocities) carries frequencies ≤ ω = 4 rad/s and
  // |E⁽⁵⁾| ≲ ω⁴|Ė|: relative (ωd)⁴/30 = 8.5e-8; ×2 for the harmonics of the nonlinear maps (exp, leg
  // kinematics). The twist differences add ≲ ε^(2/3) relative, amplified by 1/d in dE: 64 ε^(2/3)/d.
  const S d = frac<S>(1, 100);
  const S kPowerBound = S(2) * S(pow(S(4 * d), 4)) / S(30) + S(64) * S(pow(Tolerance<S>::epsilon(), S(2) / S(3))) / d;
  if (std::is_same_v<S, float>)
    ctx.note("float: the power balance is not checked — the nested differences of the pose leave ε^(2/3) ≈ 2.4e-5 in the twist rates, "
             "1/d = 100 times more in dE/dt than the 1.7e-7 of the difference bound.");
  else {
    S worst = S(0), sc = S(0);
    for (int t10 : {2, 9, 17}) {
      const S t = frac<S>(t10, 10);
      const auto [qd, qdd] = state(t);
      const StewartInverseDynamics<S> r = sd.inverseDynamics(stewartPose<S>(t), qd, qdd);
      S power = S(0);
      for (int i = 0; i < 6; ++i) power += r.forcesAlpha(i) * r.thetaDot(8 + 3 * i);
      const S dE = (S(8) * S(energy(S(t + d)) - energy(S(t - d))) - S(energy(S(t + 2 * d)) - energy(S(t - 2 * d)))) / S(12 * d);
      worst = maxOf<S>(worst, S(abs(S(power - dE))));
      sc = maxOf<S>(sc, S(abs(power)));
    }
    ctx.checkResidual("power balance Σ F_i l̇_i = d(E_K + E_P)/dt along a heave-and-sway trajectory (relative, differences; "
                      "≤ 2(ωd)⁴/30 + 64 ε^(2/3)/d, ω = 4 rad/s, d = 1e-2)",
                      S(worst / sc), kPowerBound);
  }
  // (2) computed-force control of the simulated platform (24 joints, 18 constraints), 1 s
  const SE3<S> P0 = stewartPose<S>();
  const ConstrainedTree<S> m = sd.model(P0);
  const auto s0 = state(S(0));
  ConstrainedState<S> y{DVS::Zero(24), sd.inverseDynamics(P0, s0.first, s0.second).thetaDot};
  y.thetaDot *= frac<S>(9, 10);  // a 10 % velocity error to correct
  const S h = frac<S>(4, 1000), kp = S(100), kd = S(20);
  const int steps = 250;
  S track = S(0), drift = S(0), work = S(0);
  const S E0 = m.totalEnergy(y);
  for (int k = 0; k < steps; ++k) {
    const S t = S(k) * h;
    const TreeConfiguration<S> c = m.tree().configuration(y.theta);
    const SE3<S> P = c.placements[5] * P0;
    const V6S qP = m.tree().linkVelocities(c, y.thetaDot)[5];
    const auto [qdD, qddD] = state(t);
    const V6S e = (stewartPose<S>(t) * P.inverse()).log().coeffs();
    const V6S cmd = qddD + kd * V6S(qdD - qP) + kp * e;
    const Eigen::Matrix<S, 6, 1> F = sd.forcesAt(m, y.theta, y.thetaDot, cmd);
    DVS tau = DVS::Zero(24);
    for (int i = 0; i < 6; ++i) tau(8 + 3 * i) = F(i);
    const ConstrainedState<S> y1 = m.rk4Step(y, h, tau, true);
    for (int i = 0; i < 6; ++i) work += F(i) * (y1.theta(8 + 3 * i) - y.theta(8 + 3 * i));
    y = y1;
    drift = maxOf<S>(drift, maxAbsS<S>(m.positionResidual(y.theta)));
    if (t > frac<S>(1, 2)) track = maxOf<S>(track, S(e.norm()));
  }
  const S dE = m.totalEnergy(y) - E0;
  // Bound of the tracking error: with the commanded acceleration the error obeys ë + k_d ė + k_p e = 0,
  // critically damped (k_p = 100, k_d = 20: double pole −10); from e(0) = 0, ė(0) = −0.1 q̇_P(0) it is
  // e(t) = ė(0) t e^{−10t}, whose largest value for t ≥ 0.5 s is 0.5 e^{−5}|ė(0)|; ×2 for the
  // zero-order hold of the command over h = 4 ms (h·k_d = 0.08 of a pole's time constant).
  const S trackBound = S(2) * frac<S>(1, 2) * S(exp(S(-5))) * frac<S>(1, 10) * S(s0.first.norm());
  ctx.checkResidual("computed-force control: pose error after 0.5 s (10 % initial velocity error, k_p = 100, k_d = 20; "
                    "≤ 2 · 0.5e^{−5}|ė(0)|)",
                    track, trackBound);
  // the projection (Newton to Tolerance::identity) leaves the 18 ball joints within 4096 ε of the ground points
  ctx.checkResidual("constraint drift of the simulated platform (projection after each step; 4096 ε)", drift, tol<S>(4096));
  // Bound: with the forces held over each step the work is F Δl exactly; what is left is RK4's energy defect of
  // the held-force motion — 2.1e-13 relative in long double as in double (a method error, ≈ h⁴/1240; the earlier
  // double bound, 250·16 ε = 8.9e-13, took it for rounding) — bounded by h⁴/256 (1e-12), plus
  // rounding, a few ε of E per step in the energy and the work increments (16 ε per step over the 250 steps).
  ctx.checkResidual("work of the leg forces = change of E_K + E_P (relative, zero-order hold; ≤ h⁴/256 + 250 steps × 16 ε)",
                    S(abs(S(work - dE)) / abs(dE)), S(h * h * h * h / 256 + S(steps) * tol<S>(16)));
  ctx.note("Computed-force control over 1 s at h = 4 ms: final pose error " + toString(toDouble(track), 3) + ", ankle drift " +
           toString(toDouble(drift), 3) + " m, leg work " + toString(toDouble(work), 5) + " J vs ΔE " + toString(toDouble(dE), 5) +
           " J. Step 2 of the algorithm cites §14.1.2 where the recursive algorithm is §14.1.3 (erratum 15, cross-reference).");
}

// ---------------------------------------------------------------------------------------------
void figure142(Context& ctx) {
  const FourBarDynamics<double> fb = crankRocker();
  const FourBarPosture<double> p = fb.posture(1.0);
  ctx.checkResidual("drawn posture closes: |P₃ − P₄| = d₃", std::abs((p.joints[2] - p.joints[3]).norm() - 1.8), 1e-14);
  if (!ctx.makeFigures()) return;
  rd::Plot pl;
  pl.title = "Fig. 14.2: the planar 4-bar (crank–rocker d = (1, 2.2, 1.8, 2.5))";
  pl.equalAspect = true;
  pl.x.label = "x";
  pl.y.label = "y";
  for (int k = 0; k < 12; ++k) {
    const FourBarPosture<double> q = fb.posture(k * M_PI / 6);
    std::vector<double> xs, ys;
    for (int j = 0; j < 4; ++j) {
      xs.push_back(q.joints[std::size_t(j)](0));
      ys.push_back(q.joints[std::size_t(j)](1));
    }
    auto& s = pl.add(k == 0 ? "postures every 30° of θ₁" : "", xs, ys, rd::Color::hex(0xBBBBBB));
    s.width = 1.5;
  }
  std::vector<double> cx, cy;
  for (int k = 0; k <= 72; ++k) {
    const FourBarPosture<double> q = fb.posture(k * M_PI / 36);
    cx.push_back(q.joints[2](0));
    cy.push_back(q.joints[2](1));
  }
  pl.add("path of joint 3 (P₃)", cx, cy, rd::Color::hex(0x009E73)).dashed = true;
  pl.add("ground d₄", {0, 2.5}, {0, 0}, rd::Color::hex(0x555555)).width = 6;
  const char* names[3] = {"crank d₁", "coupler d₂", "rocker d₃"};
  const rd::Color cols[3] = {rd::Color::hex(0x0072B2), rd::Color::hex(0xD55E00), rd::Color::hex(0xCC79A7)};
  const int from[3] = {0, 1, 3}, to[3] = {1, 2, 2};
  for (int i = 0; i < 3; ++i) {
    auto& s = pl.add(names[i], {p.joints[std::size_t(from[i])](0), p.joints[std::size_t(to[i])](0)},
                     {p.joints[std::size_t(from[i])](1), p.joints[std::size_t(to[i])](1)}, cols[i]);
    s.width = 5;
    s.markers = true;
  }
  const char* jl[4] = {"1 (origin)", "2", "3", "4 (d₄, 0)"};
  for (int j = 0; j < 4; ++j) pl.texts.push_back({p.joints[std::size_t(j)](0), p.joints[std::size_t(j)](1), std::string("joint ") + jl[j], rd::Color::hex(0x000000), 20});
  pl.texts.push_back({0.25, 0.05, "θ₁", rd::Color::hex(0x0072B2), 20});
  pl.legend = rd::LegendCorner::BottomRight;
  const std::string file = "GF-14-fig-14.2.png";
  rd::renderPlotPngAndSvg(pl, ctx.figurePath(file));
  ctx.figure(file, "Fig. 14.2 redrawn: joint 1 at the origin, joint 4 at (d₄, 0), crank at θ₁ = 1 rad with the coupler and rocker "
                   "closing the loop; grey: postures every 30°, dashed: the path of joint 3. The torque curve is GF-14.4-torque-curve.png.");
}

void figure143(Context& ctx) {
  const PlanarBiped<double> b(bipedParameters(), bipedHome());
  const BipedRun<double> r = bipedShift<double>(b);
  ctx.checkEqual("lift-off found for the drawing", "yes", r.liftOff > 0 ? "yes" : "no");
  if (!ctx.makeFigures()) return;
  rd::Plot pl;
  pl.title = "Fig. 14.3: planar biped (torso, thighs, shanks, feet); start and lift-off postures";
  pl.equalAspect = true;
  pl.x.label = "x [m]";
  pl.y.label = "y [m]";
  auto draw = [&](double s, rd::Color c, const std::string& name, bool labels) {
    BipedPose<double> pose = bipedHome();
    pose.hip(0) = -0.36 * s;
    pose.hip(1) -= 0.13 * s;
    const auto J = b.jointCentres(b.angles(pose));
    const V2 top = J[0] + V2(0, 0.6);
    pl.add(name, {top(0), J[0](0)}, {top(1), J[0](1)}, c).width = 7;
    for (int leg = 0; leg < 2; ++leg) {
      const V2 k = J[std::size_t(1 + 2 * leg)], a = J[std::size_t(2 + 2 * leg)];
      auto& s = pl.add("", {J[0](0), k(0), a(0)}, {J[0](1), k(1), a(1)}, c);
      s.width = 5;
      s.markers = true;
      pl.add("", {a(0) - 0.05, a(0) + 0.15}, {a(1) - 0.02, a(1) - 0.02}, c).width = 5;  // foot
    }
    if (labels) {
      pl.texts.push_back({J[0](0), J[0](1), "hip (x_h, y_h)", rd::Color::hex(0x000000), 18});
      pl.texts.push_back({J[1](0), J[1](1), "R knee", rd::Color::hex(0x000000), 18});
      pl.texts.push_back({J[3](0), J[3](1), "L knee", rd::Color::hex(0x000000), 18});
      pl.texts.push_back({J[2](0), J[2](1), "R ankle (x_Ra, y_Ra)", rd::Color::hex(0x000000), 18});
      pl.texts.push_back({J[4](0), J[4](1), "L ankle", rd::Color::hex(0x000000), 18});
    }
  };
  draw(0.0, rd::Color::hex(0x0072B2), "start: hip midway", true);
  const double s = 0.5 - 0.5 * std::cos(M_PI * r.liftOff / 2.0);
  draw(s, rd::Color::hex(0xD55E00), "at lift-off (t = " + toString(r.liftOff, 3) + " s)", false);
  pl.add("ground", {-0.6, 0.6}, {-0.04, -0.04}, rd::Color::hex(0x555555)).width = 3;
  pl.legend = rd::LegendCorner::TopRight;
  const std::string file = "GF-14-fig-14.3.png";
  rd::renderPlotPngAndSvg(pl, ctx.figurePath(file));
  ctx.figure(file, "Fig. 14.3 redrawn: the seven-link planar biped with both feet on the ground (ankles pinned), at the start of the "
                   "weight shift and where the right foot's vertical force reaches zero (GF-14.5-foot-force.png).");
}

void figure144(Context& ctx) {
  const StewartDynamics<double> sd = stewartExample(false);
  const SE3<double> pose = stewartPose();
  ctx.checkEqual("six legs drawn", 6, (long long)sd.legLines(pose).size());
  if (!ctx.makeFigures()) return;
  // oblique projection (x, y, z) → (x + 0.45 y, z + 0.3 y)
  auto pr = [](const V3& v) { return V2(v.x() - 0.45 * v.y(), v.z() + 0.25 * v.y()); };
  rd::Plot pl;
  pl.title = "Fig. 14.4: Stewart platform, leg 1 = U1 (upper) + L1 (lower)";
  pl.equalAspect = true;
  pl.grid = false;
  std::vector<double> bx, by, px, py;
  std::array<int, 6> order{0, 1, 2, 3, 4, 5};
  for (int i : order) {
    const V2 a = pr(sd.base()[std::size_t(i)]);
    bx.push_back(a(0));
    by.push_back(a(1));
  }
  std::array<V3, 6> U;
  for (int i = 0; i < 6; ++i) U[std::size_t(i)] = pose * sd.platformPoints()[std::size_t(i)];
  std::array<int, 6> po{2, 1, 4, 3, 0, 5};  // platform points sorted by angle
  for (int i : po) {
    const V2 a = pr(U[std::size_t(i)]);
    px.push_back(a(0));
    py.push_back(a(1));
  }
  auto& bs = pl.add("base (ground ball joints L_i)", bx, by, rd::Color::hex(0x555555));
  bs.closed = true;
  bs.width = 3;
  auto& ps = pl.add("platform P (joints U_i)", px, py, rd::Color::hex(0x0072B2));
  ps.closed = true;
  ps.width = 4;
  for (int i = 0; i < 6; ++i) {
    const V3 L = sd.base()[std::size_t(i)], u = U[std::size_t(i)];
    const V3 mid = L + 0.45 * (u - L);
    const rd::Color cl = i == 0 ? rd::Color::hex(0xD55E00) : rd::Color::hex(0x999999), cu = i == 0 ? rd::Color::hex(0xE69F00) : rd::Color::hex(0xBBBBBB);
    auto& lo = pl.add(i == 0 ? "leg 1, lower part L1" : "", {pr(L)(0), pr(mid)(0)}, {pr(L)(1), pr(mid)(1)}, cl);
    lo.width = 8;
    const V3 mid2 = L + 0.35 * (u - L);
    auto& up = pl.add(i == 0 ? "leg 1, upper part U1 (slides on L1)" : "", {pr(mid2)(0), pr(u)(0)}, {pr(mid2)(1), pr(u)(1)}, cu);
    up.width = 4;
  }
  const V3 L1 = sd.base()[0], U1 = U[0];
  rd::PlotText tl{pr(L1)(0), pr(L1)(1), "L1 (x_L1, y_L1, z_L1)", rd::Color::hex(0xD55E00), 20};
  tl.dx = -230;
  tl.dy = 24;
  pl.texts.push_back(tl);
  rd::PlotText tu{pr(U1)(0), pr(U1)(1), "U1 (x_U1, y_U1, z_U1)", rd::Color::hex(0xE69F00), 20};
  tu.dx = 60;  // right of leg 1, clear of the platform edge
  tu.dy = 30;
  pl.texts.push_back(tu);
  pl.legend = rd::LegendCorner::TopLeft;
  pl.y.max = 1.5;  // room above the platform for the legend
  const std::string file = "GF-14-fig-14.4.png";
  rd::renderPlotPngAndSvg(pl, ctx.figurePath(file));
  ctx.figure(file, "Fig. 14.4 redrawn (oblique projection): the platform (blue) on six legs; leg 1 highlighted with its lower part L1 "
                   "(ball joint on the ground at L1) and its upper part U1 (2-dof joint on the platform at U1), sliding on each other.");
}

}  // namespace

SOMA_STUDY_SCALAR("GF-14.4-planar-inertia", "Planar inertia = the (ω_z, v_x, v_y) block of N", "GF §14.4", planarInertiaStudy);
SOMA_STUDY_SCALAR("GF-14.4-four-bar-null-vector", "4-bar null vector α (erratum 8)", "GF §14.4", nullVector);
SOMA_STUDY_SCALAR("GF-14.4-four-bar-eom", "4-bar equation of motion = multipliers = virtual work; torque curve; free motion", "GF §14.4", fourBarEom);
SOMA_STUDY_SCALAR("GF-14.4-four-bar-shaking-moment", "4-bar shaking moment = momentum rate (erratum 9)", "GF §14.4", shakingMoment);
SOMA_STUDY_SCALAR("GF-14.5-biped-equations", "Biped joint equations, root equation (erratum 11), passive fall", "GF §14.5", bipedEquations);
SOMA_STUDY_SCALAR("GF-14.5-biped-vertical-foot-force", "Biped vertical foot force by α (erratum 10), lift-off", "GF §14.5", bipedFootForce);
SOMA_STUDY_SCALAR("GF-14.6-stewart-constraint-wrenches", "Stewart ground-joint constraint wrenches", "GF §14.6", stewartWrenches);
SOMA_STUDY_SCALAR("GF-14.6-stewart-leg-equations", "Stewart leg and platform equations (errata 7, 13)", "GF §14.6", stewartLegs);
SOMA_STUDY_SCALAR("GF-14.6-stewart-alpha-system", "Stewart 18 × 24 α system, J⁻ᵀ limit, singularity (erratum 14)", "GF §14.6", stewartAlpha);
SOMA_STUDY({.id = "GF-14.6-stewart-inverse-dynamics-algorithm",
            .title = "Stewart 5-step inverse dynamics: power balance, computed-force control (erratum 15)",
            .source = "GF §14.6",
            .chapter = kChapter,
            .scalarGeneric = false,
            .run = stewartAlgorithm<double>,
            .whyDouble = "a 1 s computed-force simulation of the 24-joint platform (250 RK4 steps with projection, 23 s in "
                         "double; over 10× that in __float128 and mpfr); its body is scalar-generic and passes in float and "
                         "long double, the library's scalars are tested in tests/geometry/dynamics/constrained_mechanisms.cpp"});
SOMA_STUDY_DOUBLE("GF-14-fig-14.2", "Fig. 14.2: the planar 4-bar", "GF §14.4 Fig. 14.2", figure142);
SOMA_STUDY_DOUBLE("GF-14-fig-14.3", "Fig. 14.3: the planar biped", "GF §14.5 Fig. 14.3", figure143);
SOMA_STUDY_DOUBLE("GF-14-fig-14.4", "Fig. 14.4: platform and one leg of a Stewart platform", "GF §14.6 Fig. 14.4", figure144);

}  // namespace soma::studies::gf14::SOMA_UNITY_ID
