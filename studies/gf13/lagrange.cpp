// Studies of GF §13.4 (in the asked scalar; reference differences in __float128 below it, in S for
// __float128 and mpfr; the energy figure drawn in double from the S results): the Lagrangian energies and the
// energy of free motion per integrator (figure), partial derivatives, Euler–Lagrange = Newton–Euler,
// Christoffel symbols, ∂A in three cases, small oscillations and harmonic screws (errata 3–9, 16,
// 17). §13.5 is in gf13/hamilton.cpp.
#include "gf13/common.hpp"

#include "soma/algebra/screw_bracket.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <array>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

template <class S> DynVector<S> pumaStart() {
  DynVector<S> th(6);
  th << frac<S>(2, 10), frac<S>(-6, 10), frac<S>(8, 10), frac<S>(3, 10), frac<S>(9, 10), frac<S>(-4, 10);
  return th;
}

/// E_P = Σ g̃ᵀc̃_i with c̃_i = (m_i c_i, m_i) (c_i the c.o.m. at θ) and g̃ = (−g k, 0), = −Σ m_i g z_i.
// GF §13.4 lines 8081–8085 as printed (erratum 3)
template <class S> S potentialEnergyAsPrinted(const SerialDynamics<S>& r, const DynVector<S>& th) {
  const ChainConfiguration<S> c = r.configuration(th);
  const Vec4<S> gt(S(0), S(0), S(-r.gravity()), S(0));
  S e = 0;
  for (int i = 0; i < r.dof(); ++i) {
    const SpatialInertia<S>& link = r.homeLinks()[std::size_t(i)];
    Vec4<S> ct;
    ct << link.mass() * c.placements[std::size_t(i)].act(link.centreOfMass()), link.mass();
    e += gt.dot(ct);
  }
  return e;
}

/// Q_ij = s_aᵀN̄_a[g, s_b], a = max(i, j), b = min(i, j): the bracket in the printed order.
// GF §13.4.3 lines 8206–8210 as printed (erratum 8)
template <class S> DynMatrix<S> potentialHessianAsPrinted(const SerialDynamics<S>& r, const DynVector<S>& th) {
  const ChainConfiguration<S> c = r.configuration(th);
  const int n = r.dof();
  DynMatrix<S> Qm(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b <= a; ++b)
      Qm(a, b) = Qm(b, a) = c.screws[std::size_t(a)].dot(c.tails[std::size_t(a)] * screwBracket(r.gravityScrew(), c.screws[std::size_t(b)]));
  return Qm;
}

/// max |E(t) − E(0)| over `steps` RK4 steps (resp. implicit-midpoint steps) of length h from (θ, θ̇).
template <class S> S rk4Drift(const SerialDynamics<S>& r, const DynVector<S>& th, const DynVector<S>& thd, const S& h, int steps) {
  using std::abs;
  JointState<S> y{th, thd};
  const DynVector<S> z = DynVector<S>::Zero(r.dof());
  const S e0 = totalEnergy(r, y);
  S worst = 0;
  for (int k = 0; k < steps; ++k) {
    y = rk4Step(r, y, h, z);
    worst = maxOf(worst, S(abs(S(totalEnergy(r, y) - e0))));
  }
  return worst;
}
template <class S> S midDrift(const SerialDynamics<S>& r, const DynVector<S>& th, const DynVector<S>& thd, const S& h, int steps) {
  using std::abs;
  CanonicalState<S> y{th, r.momentum(th, thd)};
  const DynVector<S> z = DynVector<S>::Zero(r.dof());
  const S e0 = r.hamiltonian(y.theta, y.momentum);
  S worst = 0;
  for (int k = 0; k < steps; ++k) {
    y = implicitMidpointStep(r, y, h, z);
    worst = maxOf(worst, S(abs(S(r.hamiltonian(y.theta, y.momentum) - e0))));
  }
  return worst;
}
/// The same for the double PUMA cast to T (the per-scalar table of the note), in double.
template <class T> double rk4DriftIn(const SerialDynamics<double>& r0, const DV& th, const DV& thd, double h, int steps) {
  return toDouble(rk4Drift<T>(castRobot<T>(r0), castV<T>(th), castV<T>(thd), scalarCast<T>(h), steps));
}
template <class T> double midDriftIn(const SerialDynamics<double>& r0, const DV& th, const DV& thd, double h, int steps) {
  return toDouble(midDrift<T>(castRobot<T>(r0), castV<T>(th), castV<T>(thd), scalarCast<T>(h), steps));
}

template <class S> void energies(Context& ctx) {
  using std::abs;
  using std::log2;
  using DVS = DynVector<S>;
  const SerialDynamics<S> r = pumaIn<S>();
  const DVS th0 = pumaStart<S>(), thd0 = DVS::Constant(6, frac<S>(1, 2)), z = DVS::Zero(6);
  const S h = frac<S>(2, 1000);
  const int steps = 5000, perSecond = 500;  // 10 s at h = 2 ms
  JointState<S> y{th0, thd0};
  CanonicalState<S> c{th0, r.momentum(th0, thd0)};
  const S e0 = totalEnergy(r, y);
  const S ep0 = r.kineticEnergy(th0, thd0) + potentialEnergyAsPrinted(r, th0);
  std::vector<double> ts, er, em, ep;  // the figure's curves, in double
  S wr = 0, wm = 0, wp = 0, wr1 = 0, wm1 = 0;
  for (int k = 1; k <= steps; ++k) {
    y = rk4Step(r, y, h, z);
    c = implicitMidpointStep(r, c, h, z);
    const S a = abs(S(totalEnergy(r, y) - e0)), b = abs(S(r.hamiltonian(c.theta, c.momentum) - e0));
    const S p = abs(S(r.kineticEnergy(y.theta, y.thetaDot) + potentialEnergyAsPrinted(r, y.theta) - ep0));
    wr = maxOf(wr, a);
    wm = maxOf(wm, b);
    wp = maxOf(wp, p);
    if (k <= perSecond) {
      wr1 = wr;
      wm1 = wm;
    }
    if (k % 10 == 0) {
      ts.push_back(toDouble(S(S(k) * h)));
      er.push_back(std::max(toDouble(a), 1e-16));
      em.push_back(std::max(toDouble(b), 1e-16));
      ep.push_back(std::max(toDouble(p), 1e-16));
    }
  }
  ctx.note("PUMA 560 (Armstrong et al. inertias, puma560_dynamics.json), τ = 0, g = 9.81, θ₀ = (0.2, −0.6, 0.8, 0.3, "
           "0.9, −0.4), θ̇₀ = 0.5 rad/s each, E₀ = " + toString(e0, 6) + " J, 10 s at h = 2 ms.");
  // The orders, fitted: over a fixed time the energy error scales like h⁴ (RK4) and h² (midpoint).
  // Fitted over h, h/2, h/4 (the least-squares slope of log|ΔE| against log h on three equally spaced
  // points is log₂(e(h)/e(h/4))/2); the pairwise orders are in the note. The fitted order differs
  // from the asymptotic one by the O(h) next term of the error expansion: the pairwise orders (RK4
  // 3.973 for h, h/2 and 3.987 for h/2, h/4: the gap halves with h) put it at 0.02 here, so the
  // margin is 0.05 (2.5×). These are the integrators' truncation errors, the same in every scalar:
  // the margin does not scale with ε. Rounding (N ε E₀, N steps) must lie far below the smallest
  // error fitted: 2000 · 1.1e-16 · 11 J = 2.4e-12 J in double against 4.6e-10 J (RK4 at h/4), but
  // 2000 · 6e-8 · 11 J = 1.3e-3 J in float, above every error fitted — float skips the two fits.
  // The run at h over the first second is the main loop's (wr1, wm1). __float128 and mpfr fit the
  // order from h and h/2 only, log₂(e(h)/e(h/2)): 3.973 and 2.000 in double, the same truncation in every
  // scalar, so the margin 0.05 is 1.85× the RK4 deviation 0.027 — and their midpoint rule, iterated to
  // 64 ε by Newton, costs ~30 field evaluations a step: the h/4 runs (4000 steps) would take minutes in mpfr.
  const bool quarter = kWideRef<S>;
  auto order = [](const S& eH, const S& eQuarter) { return S(log2(S(eH / eQuarter)) / S(2)); };
  std::array<S, 3> rk = {wr1, rk4Drift<S>(r, th0, thd0, S(h / S(2)), 1000), S(0)};
  std::array<S, 3> md = {wm1, midDrift<S>(r, th0, thd0, S(h / S(2)), 1000), S(0)};
  if (quarter) {
    rk[2] = rk4Drift<S>(r, th0, thd0, S(h / S(4)), 2000);
    md[2] = midDrift<S>(r, th0, thd0, S(h / S(4)), 2000);
  }
  const S pRk = quarter ? order(rk[0], rk[2]) : S(log2(S(rk[0] / rk[1]))), pMid = quarter ? order(md[0], md[2]) : S(log2(S(md[0] / md[1])));
  const std::string hs = quarter ? "h = 2, 1, 0.5 ms" : "h = 2, 1 ms (pairwise)";
  const S kOrderMargin = frac<S>(5, 100);
  const S roundingFloor = S(2000) * Tolerance<S>::epsilon() * abs(e0);
  if constexpr (!std::is_same_v<S, float>) {
    ctx.checkNear("RK4: fitted order of the energy error over 1 s, " + hs + " (order 4 ± 0.05)", S(4), pRk, kOrderMargin);
    ctx.checkNear("implicit midpoint: fitted order of the energy error, " + hs + " (order 2 ± 0.05)", S(2), pMid, kOrderMargin);
  } else {
    ctx.note("Skipped in float: the two fitted orders (the rounding floor N ε E₀ = " + toString(roundingFloor, 2) +
             " J over 2000 steps exceeds the RK4 error at h/4, " + toString(rk[2], 2) + " J: the error measured is rounding, "
             "not truncation).");
  }
  if (quarter)
    ctx.note("Energy errors over 1 s at h = 2, 1, 0.5 ms: RK4 " + toString(rk[0], 3) + ", " + toString(rk[1], 3) + ", " +
             toString(rk[2], 3) + " J (pairwise orders " + toString(S(log2(S(rk[0] / rk[1]))), 4) + ", " +
             toString(S(log2(S(rk[1] / rk[2]))), 4) + "); midpoint " + toString(md[0], 3) + ", " + toString(md[1], 3) + ", " +
             toString(md[2], 3) + " J (pairwise orders " + toString(S(log2(S(md[0] / md[1]))), 4) + ", " +
             toString(S(log2(S(md[1] / md[2]))), 4) + ").");
  else
    ctx.note("Energy errors over 1 s at h = 2, 1 ms: RK4 " + toString(rk[0], 3) + ", " + toString(rk[1], 3) + " J; midpoint " +
             toString(md[0], 3) + ", " + toString(md[1], 3) + " J (h/4 not run in " + std::string(scalarName<S>()) + ": see the fit).");
  // RK4's secular drift (1.6e-6 J over 10 s) lies below float's rounding floor (4e-5 J over the first second)
  if constexpr (std::is_same_v<S, float>)
    ctx.note("Skipped in float: RK4's secular drift (its error over 10 s, 1.6e-6 J in double, is below float's rounding "
             "floor; float measures " + toString(wr1, 3) + " J over the first second and " + toString(wr, 3) + " J over 10 s).");
  else
    ctx.checkEqual("RK4: error over 10 s > 5 × error over the first second (secular drift)", "drifts", wr > S(5) * wr1 ? "drifts" : "bounded");
  ctx.checkEqual("midpoint: error over 10 s ≤ 3 × error over the first second (no secular drift)", "bounded",
                 wm <= S(3) * wm1 ? "bounded" : "drifts");
  ctx.note("RK4 over the first second " + toString(wr1, 3) + " J, over 10 s " + toString(wr, 3) + " J; midpoint over the "
           "first second " + toString(wm1, 3) + " J, over 10 s " + toString(wm, 3) + " J.");
  // the noise of this computation is the integrator's: the corrected energy drifts by wr (RK4, 10 s)
  ctx.checkPrintedFails("E_K + printed E_P = E_K + Σ g̃ᵀc̃_i = E_K − Σ m g z conserved (lines 8081–8085; bound: the corrected "
                        "energy's RK4 drift over the same 10 s)", "3", wp, wr);
  // drift per scalar (RK4 and midpoint, 1 s at h = 2 ms): the double PUMA cast to each scalar, whatever S is
  const SerialDynamics<double> r0 = puma();
  const DV th0d = castV<double>(pumaStart<double>()), thd0d = DV::Constant(6, 0.5);
  const double hd = 2e-3;
  std::string table;
  const int n1 = 500;
  table += "float: RK4 " + toString(rk4DriftIn<float>(r0, th0d, thd0d, hd, n1), 3) + " J, midpoint " + toString(midDriftIn<float>(r0, th0d, thd0d, hd, n1), 3) + " J; ";
  table += "double: RK4 " + toString(rk4DriftIn<double>(r0, th0d, thd0d, hd, n1), 3) + " J, midpoint " + toString(midDriftIn<double>(r0, th0d, thd0d, hd, n1), 3) + " J; ";
  table += "long double: RK4 " + toString(rk4DriftIn<long double>(r0, th0d, thd0d, hd, n1), 3) + " J, midpoint " + toString(midDriftIn<long double>(r0, th0d, thd0d, hd, n1), 3) + " J; ";
  table += "__float128: RK4 " + toString(rk4DriftIn<Q>(r0, th0d, thd0d, hd, 100), 3) + " J (0.2 s)";
  ctx.note("Energy error per scalar, 1 s at h = 2 ms (the double PUMA cast to each; truncation dominates except in float): " + table + ".");
  if (ctx.makeFigures()) {
    rd::Plot p;
    p.title = "PUMA 560 free motion: energy error |E(t) − E(0)| per integrator";
    p.x.label = "t [s]";
    p.y.label = "|ΔE| [J]";
    p.y.scale = rd::AxisScale::Log10;
    p.legend = rd::LegendCorner::BottomRight;
    p.add("RK4, h = 2 ms", ts, er, rd::Color::hex(0x0072B2));
    p.add("implicit midpoint (symplectic), h = 2 ms", ts, em, rd::Color::hex(0xD55E00));
    p.add("RK4 with the printed E_P (erratum 3)", ts, ep, rd::Color::hex(0x009E73)).dashed = true;
    const std::string file = "GF-13.4-energy-per-integrator.png";
    rd::renderPlotPngAndSvg(p, ctx.figurePath(file));
    ctx.figure(file, "Energy error of the free PUMA 560 (τ = 0, gravity) over 10 s: RK4 (order 4) drifts slowly, the "
                     "symplectic implicit midpoint rule (order 2) oscillates without drift, and E_K plus the printed "
                     "potential energy (erratum 3) is not conserved at all.");
  }
}

template <class S> void partials(Context& ctx) {
  using R = Ref<S>;
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using DVS = DynVector<S>;
  auto g = std::mt19937_64(1341);
  const SerialDynamics<double> rd = randomRobot(g, 6);
  const SerialDynamics<S> r = castRobotUnit<S>(rd);
  const SerialDynamics<R> rq = castRobotUnit<R>(rd);
  const DVS th = rjointsS<S>(g, 6), thd = rjointsS<S>(g, 6);
  const DynVector<R> thr = castV<R>(th), thdr = castV<R>(thd);
  const auto c = r.configuration(th);
  const auto qd = r.linkVelocities(c, thd);
  S eN = 0, eNp = 0, eq = 0, eqp = 0, eK = 0, eP = 0, ePp = 0, es = 0;
  bool firstN = true, firstP = true;
  for (int i = 0; i < 6; ++i) {
    auto shifted = [&](const R& u) {
      DynVector<R> a = thr;
      a(i) += u;
      return a;
    };
    for (int j = 0; j < 6; ++j) {
      const M6 dN = refDiffM<S>([&](const R& u) { return Mat6<R>(rq.configuration(shifted(u)).inertias[std::size_t(j)]); });
      const V6 dqd = refDiffM<S>([&](const R& u) {
        const auto cc = rq.configuration(shifted(u));
        return Vec6<R>(rq.linkVelocities(cc, thdr)[std::size_t(j)]);
      });
      const V6 ds = refDiffM<S>([&](const R& u) { return Vec6<R>(rq.configuration(shifted(u)).screws[std::size_t(j)]); });
      const M6& Nj = c.inertias[std::size_t(j)];
      const M6 adi = adm(c.screws[std::size_t(i)]);
      const M6 want = i <= j ? M6(-adi.transpose() * Nj - Nj * adi) : M6(M6::Zero());
      const M6 printed = j <= i ? M6(-adi.transpose() * Nj + Nj * adi) : M6(M6::Zero());
      eN = maxOf(eN, maxAbsOf(M6(dN - want)));
      if (i == j) {
        const S e = maxAbsOf(M6(dN - printed));
        eNp = firstN || e < eNp ? e : eNp;
        firstN = false;
      }
      const V6 wq = i <= j ? br(c.screws[std::size_t(i)], V6(qd[std::size_t(j)] - qd[std::size_t(i)])) : V6(V6::Zero());
      eq = maxOf(eq, S((dqd - wq).norm()));
      if (i < j) eqp = maxOf(eqp, S(dqd.norm()));  // printed: zero unless j ≤ i
      const V6 wsd = i <= j ? br(c.screws[std::size_t(i)], c.screws[std::size_t(j)]) : V6(V6::Zero());
      es = maxOf(es, S((ds - wsd).norm()));
    }
    const DVS gk = r.kineticEnergyGradient(th, thd);
    eK = maxOf(eK, S(abs(S(refDiff<S>([&](const R& u) { return R(rq.kineticEnergy(shifted(u), thdr)); }) - gk(i)))));
    const S dEP = refDiff<S>([&](const R& u) { return R(rq.potentialEnergy(shifted(u))); });
    // printed first form: Σ_{j≥i} −m_j g k·(ω_i × c_j + v_i)
    S printedEP = 0;
    for (int j = i; j < 6; ++j) {
      const Vec3<S> cj = c.placements[std::size_t(j)].act(r.homeLinks()[std::size_t(j)].centreOfMass());
      const V6& si = c.screws[std::size_t(i)];
      printedEP += -r.homeLinks()[std::size_t(j)].mass() * r.gravity() * Vec3<S>(si.template head<3>().cross(cj) + si.template tail<3>())(2);
    }
    eP = maxOf(eP, S(abs(S(dEP - r.gravityTorque(th)(i)))));
    const S e = abs(S(dEP - printedEP)) / std::max<S>(S(1), abs(dEP));
    ePp = firstP || e < ePp ? e : ePp;
    firstP = false;
  }
  // brackets and 6×6 products of a 6R's screws and inertias (entries ≲ 10): 4096 ε (9.1e-13 in double;
  // 1e-9 before, the bound of the 4th-order differences at d = 1e-3 the study used; 1e-12 for E_K, E_P),
  // plus the reference derivative's bound
  const S bound = tol<S>(4096) + refTol<S>();
  const std::string how = std::string(" (") + refHow<S>() + "; 4096 ε + difference bound)";
  ctx.checkResidual("∂s_j/∂θ_i = [s_i, s_j] (i ≤ j), 0 otherwise" + how, es, bound);
  ctx.checkResidual("∂q̇_j/∂θ_i = [s_i, q̇_j − q̇_i] for i ≤ j, 0 for j < i (corrected, erratum 4)", eq, bound);
  ctx.checkPrintedFails("∂q̇_j/∂θ_i nonzero only 'if j ≤ i' (line 8127): |∂q̇_j/∂θ_i| for i < j", "4", eqp, bound);
  ctx.checkResidual("∂N_j/∂θ_i = −ad(s_i)ᵀN_j − N_j ad(s_i) for i ≤ j (corrected, erratum 5)", eN, bound);
  ctx.checkPrintedFails("∂N_j/∂θ_i = −ad(s_i)ᵀN_j + N_j ad(s_i) (line 8131), i = j", "5", eNp, bound);
  ctx.checkResidual("∂E_K/∂θ_i = −Σ_{j≥i} q̇_jᵀN_j[s_i, q̇_i]" + how, eK, bound);
  ctx.checkResidual("∂E_P/∂θ_i = −Σ_{j≥i} s_iᵀN_j g = C_i", eP, bound);
  ctx.checkPrintedFails("∂E_P/∂θ_i = Σ_{j≥i} −m_j g k·(ω_i × c_j + v_i) (line 8139)", "3", ePp, bound);
  ctx.note("Line 8115 writes e^{θ_j ad(s_j)} s_i⁰ for s_j⁰ (erratum 6, typo).");
}

/// τ_i = d/dt ∂L/∂θ̇_i − ∂L/∂θ_i with L = E_K − E_P differentiated numerically in R (the reference scalar).
template <class S>
DynVector<S> lagrangeTorque(const SerialDynamics<Ref<S>>& r, const DynVector<S>& th, const DynVector<S>& thd, const DynVector<S>& thdd) {
  using R = Ref<S>;
  const int n = r.dof();
  const DynVector<R> a = castV<R>(th), b = castV<R>(thd), c = castV<R>(thdd);
  auto L = [&](const DynVector<R>& x, const DynVector<R>& v) { return R(r.kineticEnergy(x, v) - r.potentialEnergy(x)); };
  DynVector<S> tau(n);
  for (int i = 0; i < n; ++i) {
    auto dLdv = [&](const DynVector<R>& x, const DynVector<R>& v) {
      DynVector<R> p = v, m = v;
      p(i) += 1;
      m(i) -= 1;
      return R((L(x, p) - L(x, m)) / R(2));  // exact: L is quadratic in θ̇
    };
    const S ddt = refDiff<S>([&](const R& t) { return dLdv(DynVector<R>(a + t * b + (t * t / R(2)) * c), DynVector<R>(b + t * c)); });
    const S dth = refDiff<S>([&](const R& t) {
      DynVector<R> x = a;
      x(i) += t;
      return L(x, b);
    });
    tau(i) = ddt - dth;
  }
  return tau;
}

template <class S> void eulerLagrange(Context& ctx) {
  using DVS = DynVector<S>;
  auto g = std::mt19937_64(1342);
  S worst = 0;
  for (int t = 0; t < 6; ++t) {
    const SerialDynamics<double> rd = t == 0 ? puma() : randomRobot(g, 3 + t % 4, t % 3 == 2 ? 1 : -1);
    const SerialDynamics<S> r = castRobotUnit<S>(rd);
    const DVS th = rjointsS<S>(g, r.dof(), -3, 3), thd = rjointsS<S>(g, r.dof()), thdd = rjointsS<S>(g, r.dof());
    const DVS a = lagrangeTorque<S>(castRobotUnit<Ref<S>>(rd), th, thd, thdd), b = r.inverseDynamics(th, thd, thdd);
    worst = maxOf(worst, S(maxAbsOf(DVS(a - b)) / maxAbsOf(b)));
  }
  // RNEA relative 256 ε (GF-13.3), the Lagrangian side a sum of ≤ 7 links' energies: 4096 ε (9.1e-13 in
  // double; 1e-12 before), plus the reference derivative's bound
  ctx.checkResidual(std::string("τ from d/dt ∂L/∂θ̇ − ∂L/∂θ (L = E_K − E_P differentiated numerically, 8th order, ") + refHow<S>() +
                        ") = RNEA (PUMA 560 + 5 random robots, relative; 4096 ε + difference bound)",
                    worst, S(tol<S>(4096) + refTol<S>()));
  ctx.note("The Lagrangian is built from E_K = ½Σq̇ᵀNq̇ (link velocities) and E_P = Σmgz, not from A: the agreement "
           "checks the whole chain of §13.4.1. Differences below __float128: step 2⁻⁸, truncation ≈ 1e-22·|f⁽⁹⁾|, rounding ≈ 1e-31; "
           "in __float128 and mpfr: step ε^(1/9).");
}

/// ∂A/∂θ_k by reference differences (R = Ref<S>) of the same double robot made unit in R.
template <class S> std::vector<DynMatrix<S>> dAnumeric(const SerialDynamics<double>& rd, const DynVector<S>& th) {
  using R = Ref<S>;
  const SerialDynamics<R> rq = castRobotUnit<R>(rd);
  const int n = rd.dof();
  std::vector<DynMatrix<S>> dA(std::size_t(n), DynMatrix<S>(n, n));
  for (int k = 0; k < n; ++k)
    dA[std::size_t(k)] = refDiffM<S>([&](const R& u) {
      DynVector<R> a = castV<R>(th);
      a(k) += u;
      const DynMatrix<R> A = rq.massMatrix(a);
      return DynMatrix<R>((A + A.transpose()) / R(2));
    });
  return dA;
}

template <class S> void christoffel(Context& ctx) {
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  auto g = std::mt19937_64(1343);
  const SerialDynamics<double> rd = randomRobot(g, 5);
  const SerialDynamics<S> r = castRobotUnit<S>(rd);
  const DVS th = rjointsS<S>(g, 5), thd = rjointsS<S>(g, 5);
  const auto dA = dAnumeric<S>(rd, th);
  const auto B = r.coriolisTensor(th);
  S eb = 0, ep = 0, sc = 0;
  DMS Adot = DMS::Zero(5, 5), Cm = DMS::Zero(5, 5);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) {
        const S c = (dA[std::size_t(k)](i, j) + dA[std::size_t(j)](i, k) - dA[std::size_t(i)](j, k)) / S(2);
        const S printed = (dA[std::size_t(k)](i, j) + dA[std::size_t(i)](i, k) - dA[std::size_t(i)](j, k)) / S(2);
        eb = maxOf(eb, S(abs(S(c - B[std::size_t(i)](j, k)))));
        ep = maxOf(ep, S(abs(S(printed - B[std::size_t(i)](j, k)))));
        sc = maxOf(sc, S(abs(c)));
        Adot(i, j) += dA[std::size_t(k)](i, j) * thd(k);
        Cm(i, j) += B[std::size_t(i)](j, k) * thd(k);
      }
  // B θ̇θ̇ = (dA/dt)θ̇ − ½ θ̇ᵀ ∂_iA θ̇ (line 8153)
  DVS lhs(5), rhs(5);
  for (int i = 0; i < 5; ++i) {
    lhs(i) = thd.dot(B[std::size_t(i)] * thd);
    rhs(i) = (Adot * thd)(i) - thd.dot(dA[std::size_t(i)] * thd) / S(2);
  }
  // B from 5 tail sums of 6×6 products, relative: 512 ε (1.1e-13 in double; 1e-13 before), plus the
  // difference bound of ∂A (× 16 for the sums of 5 terms of |θ̇| ≤ 1 in Ȧ and the relative scale)
  const S bound = tol<S>(512) + S(16) * refTol<S>();
  const std::string how = std::string(" (∂A by ") + refHow<S>() + "; relative, 512 ε + 16 × difference bound)";
  ctx.checkResidual("B_ijkθ̇_jθ̇_k = Ȧ_ijθ̇_j − ½∂_iA_jkθ̇_jθ̇_k (line 8153)" + how, S(maxAbsOf(DVS(lhs - rhs)) / maxAbsOf(lhs)), bound);
  ctx.checkResidual("B_ijk = ½(∂_kA_ij + ∂_jA_ik − ∂_iA_jk)" + how, S(eb / sc), bound);
  ctx.checkPrintedFails("B_ijk = ½(∂_kA_ij + ∂_iA_ik − ∂_iA_jk) (line 8165)", "7", S(ep / sc), bound);
  const DMS M = Adot - S(2) * Cm;
  ctx.checkResidual("Ȧ − 2B(θ̇) is skew-symmetric (passivity)" + how, S(maxAbsOf(DMS(M + M.transpose())) / maxAbsOf(M)), bound);
}

template <class S> void dAcases(Context& ctx) {
  using DMS = DynMatrix<S>;
  auto g = std::mt19937_64(1344);
  const SerialDynamics<double> rd = randomRobot(g, 6);
  const SerialDynamics<S> r = castRobotUnit<S>(rd);
  const DynVector<S> th = rjointsS<S>(g, 6);
  const auto c = r.configuration(th);
  const auto dA = dAnumeric<S>(rd, th);
  const DMS A = r.massMatrix(c);
  auto s = [&](int i) { return c.screws[std::size_t(i)]; };
  auto Nb = [&](int i) { return c.tails[std::size_t(i)]; };
  S worst = 0, sc = 0, typo = 0;
  int triples = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = j; k < 6; ++k) {
        S f = 0;
        if (i <= j) f = 0;
        else if (i <= k) f = s(k).dot(Nb(k) * br(s(j), s(i)));
        else f = s(k).dot(Nb(i) * br(s(j), s(i))) + s(j).dot(Nb(i) * br(s(k), s(i)));
        worst = maxOf(worst, S(abs(S(f - dA[std::size_t(i)](j, k)))));
        sc = maxOf(sc, S(abs(dA[std::size_t(i)](j, k))));
        ++triples;
        if (j < k) typo = maxOf(typo, S(abs(S(s(k).dot(Nb(j) * s(j)) - A(j, k)))));
      }
  ctx.checkEqual("index triples (i, j ≤ k) on a 6R", 126, triples);
  // tail sums of 6×6 products, relative to max |∂A|: 512 ε (1.1e-13 in double; 1e-13 before), plus the
  // difference bound (× 16: relative to max |∂A| ≈ 0.1–1)
  const S bound = tol<S>(512) + S(16) * refTol<S>();
  ctx.checkResidual(std::string("∂A_jk/∂θ_i in the three cases i ≤ j, j < i ≤ k, k < i (relative to max |∂A|; ") + refHow<S>() +
                        ", 512 ε + 16 × difference bound)", S(worst / sc), bound);
  ctx.checkPrintedFails("A_jk = s_kᵀ(N_j + … + N_n)s_j for j < k (line 8183)", "9", S(typo / maxAbsOf(A)), bound);
}

/// A stable equilibrium (minimum of E_P) by Levenberg–Marquardt on ∇E_P = C with Hessian Q, from several
/// starts (drawn in double, the same in every scalar). C is in N·m: its scale is g Σ m_i (N·m per m of
/// lever); the iteration stops at |C|∞ ≤ 4 ε g Σm (9e-14 N·m in double for Σm ≈ 10; 1e-13 before) or
/// after 12 rejected steps in a row (C at its rounding floor), and accepts at 512 ε g Σm (1.1e-11;
/// 1e-11 before) with Q positive definite (λ_min > 1e-6 N·m/rad). A step is taken when E_P falls, or
/// when |C| falls and E_P does not rise beyond its rounding (64 ε|E_P|): near the minimum E_P changes
/// by |C|²/Q, below its rounding once |C| < √(ε|E_P|Q) (1e-38 in mpfr-256, where the energy test alone
/// stalled every start far above 512 ε g Σm).
template <class S> bool equilibrium(const SerialDynamics<S>& r, std::mt19937_64& g, DynVector<S>& th) {
  using std::abs;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  const int n = r.dof();
  S massSum = 0;
  for (const auto& l : r.homeLinks()) massSum += l.mass();
  const S cScale = r.gravity() * massSum;
  for (int start = 0; start < 10; ++start) {
    th = rjointsS<S>(g, n, -3, 3);
    S mu = 1, e = r.potentialEnergy(th);
    int rejected = 0;
    for (int it = 0; it < 400 && rejected < 12; ++it) {
      const DVS C = r.gravityTorque(th);
      if (maxAbsOf(C) < tol<S>(4) * cScale) break;
      const DMS Qm = r.potentialHessian(th);
      const S shift = maxOf(S(0), S(-Eigen::SelfAdjointEigenSolver<DMS>(Qm).eigenvalues().minCoeff()));
      const DVS trial = th - DMS(Qm + (mu + frac<S>(11, 10) * shift) * DMS::Identity(n, n)).ldlt().solve(C);
      const bool finite = allFinite(trial);
      const S et = finite ? r.potentialEnergy(trial) : e;
      if (et < e || (finite && et <= e + tol<S>(64) * abs(e) && maxAbsOf(r.gravityTorque(trial)) < maxAbsOf(C))) {
        th = trial;
        e = et;
        mu = maxOf(S(mu / S(10)), frac<S>(1, 1000000000000L));
        rejected = 0;
      } else {
        mu *= S(10);
        ++rejected;
      }
    }
    const Eigen::SelfAdjointEigenSolver<DMS> es(r.potentialHessian(th));
    if (maxAbsOf(r.gravityTorque(th)) < tol<S>(512) * cScale && es.eigenvalues().minCoeff() > frac<S>(1, 1000000)) return true;
  }
  return false;
}

template <class S> void smallOscillations(Context& ctx) {
  using std::abs;
  using std::sqrt;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  using R = Ref<S>;
  // pendulum: revolute about x through the origin, a small body at (0, 0, −L)
  const S m = 2, L = frac<S>(7, 10), grav = frac<S>(981, 100);
  const SerialDynamics<S> pend({SE3Tangent<S>(lineScrew<S>(Vec3<S>(1, 0, 0), Vec3<S>::Zero(), S(0)))},
                               {SpatialInertia<S>(m, Vec3<S>(0, 0, -L), Mat3<S>(Mat3<S>::Identity() * frac<S>(1, 1000000)))}, grav);
  const DVS z = DVS::Zero(1);
  // one bracket and two products of O(1) screws with N (entries ≤ mL): 64 ε of mgL (1.9e-13 in double; 1e-12 before)
  const S mgl = m * grav * L, pendTol = tol<S>(64) * mgl;
  ctx.checkNear("hanging pendulum: Q = ∂²E_P/∂θ² = +mgL (stable; 64 ε mgL)", mgl, S(pend.potentialHessian(z)(0, 0)), pendTol);
  ctx.checkNear("printed Q = s_iᵀN̄_i[g, s_j] (lines 8206–8210) gives −mgL: 'unstable' [as printed, erratum 8]", S(-mgl),
                S(potentialHessianAsPrinted(pend, z)(0, 0)), pendTol);
  auto g = std::mt19937_64(1345);
  // Hessian against differences of C on a random 6R
  const SerialDynamics<double> r6d = randomRobot(g, 6);
  const SerialDynamics<S> r6 = castRobotUnit<S>(r6d);
  const SerialDynamics<R> rq = castRobotUnit<R>(r6d);
  const DVS th = rjointsS<S>(g, 6);
  const DMS H = r6.potentialHessian(th);
  S eh = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      eh = maxOf(eh, S(abs(S(refDiff<S>([&](const R& u) {
                                DynVector<R> a = castV<R>(th);
                                a(j) += u;
                                return R(rq.gravityTorque(a)(i));
                              }) - H(i, j)))));
  // Q from tail sums of a 6R's brackets and inertias, relative: 512 ε (1.1e-13 in double; 1e-13 before),
  // plus the difference bound (× 16, as GF-13.4.2-dA-three-cases)
  ctx.checkResidual(std::string("Q_ij = s_aᵀN̄_a[s_b, g] (a = max, b = min) = ∂C_i/∂θ_j (random 6R, relative; ") + refHow<S>() +
                        ", 512 ε + 16 × difference bound)",
                    S(eh / maxAbsOf(H)), S(tol<S>(512) + S(16) * refTol<S>()));
  // normal modes of a 3R about a stable equilibrium, checked against the nonlinear motion
  const SerialDynamics<S> r = castRobotUnit<S>(randomRobot(g, 3));
  DVS eq;
  const bool found = equilibrium(r, g, eq);
  ctx.checkEqual("stable equilibrium found (C = 0, Q positive definite)", "yes", found ? "yes" : "no");
  if (!found) return;
  const DMS A = r.massMatrix(eq), Qm = r.potentialHessian(eq);
  const Eigen::GeneralizedSelfAdjointEigenSolver<DMS> ges(Qm, A);
  const S lam2 = ges.eigenvalues()(0);
  const DVS mode = ges.eigenvectors().col(0);
  // det(Q − λ²A) of a 3×3 relative to det Q = Πλ_i² det A: the eigenvalue's error ε‖A⁻¹Q‖ times the two
  // other gaps over Πλ², and the determinant's own rounding ε‖Q‖³/det Q: 64 ε (λ²_max/λ²_min)³
  // (7e-14 in double; 1e-12 before)
  const S spread = ges.eigenvalues()(2) / lam2;
  ctx.checkResidual("det(Q − λ²A) = 0 at the lowest λ² (relative; 64 ε (λ²_max/λ²_min)³)",
                    S(abs(S((Qm - lam2 * A).determinant())) / abs(S(Qm.determinant()))), S(tol<S>(64) * spread * spread * spread));
  ctx.checkEqual("all λ² > 0 at a minimum of E_P (stable)", "yes", ges.eigenvalues().minCoeff() > S(0) ? "yes" : "no");
  // nonlinear motion from θ* + εa with θ̇ = 0 returns after one period 2π/λ to within O(ε²)
  const S lam = sqrt(lam2), period = S(2) * pi<S>() / lam, eps = frac<S>(1, 100000);
  const int steps = 2000;
  JointState<S> y{DVS(eq + eps * mode / maxAbsOf(mode)), DVS::Zero(3)};
  for (int k = 0; k < steps; ++k) y = rk4Step<S>(r, y, S(period / S(steps)), DVS::Zero(3));
  const S back = maxAbsOf(DVS(y.theta - eq - eps * mode / maxAbsOf(mode))) / eps;
  // the O(ε) nonlinearity (ε = 1e-5) and RK4's h⁴ truncation at 2000 steps per period: 1e-3, the same in
  // every scalar (not an ε of S). Float cannot resolve it: ε = 1e-5 is 84 ulps of θ ≈ 1, so the
  // rounding of θ alone is 1e-2 of ε.
  if constexpr (std::is_same_v<S, float>)
    ctx.note("Skipped in float: the return of the small oscillation (ε = 1e-5 is 84 float ulps of θ; rounding alone is "
             "1e-2 of ε, above the 1e-3 asked). Float measures " + toString(back, 3) + ".");
  else
    ctx.checkResidual("small oscillation along the lowest mode returns after 2π/λ (error / ε, ε = 1e-5; O(ε) + RK4 h⁴, "
                      "not an ε of S)", back, frac<S>(1, 1000));
  ctx.note("3R equilibrium: λ² = " + toString(ges.eigenvalues()(0), 5) + ", " + toString(ges.eigenvalues()(1), 5) + ", " +
           toString(ges.eigenvalues()(2), 5) + " s⁻²; period of the lowest mode " + toString(period, 5) +
           " s. Line 8195 prints θ̇_i = θ̇_i = 0 for θ̇_i = θ̈_i = 0 (erratum 17, OCR).");
}

template <class S> void harmonicScrews(Context& ctx) {
  using std::abs;
  using DMS = DynMatrix<S>;
  auto g = std::mt19937_64(1346);
  const SerialDynamics<S> r = castRobotUnit<S>(randomRobot(g, 6));
  DynVector<S> eq;
  const bool found = equilibrium(r, g, eq);
  ctx.checkEqual("stable equilibrium of a random 6R found", "yes", found ? "yes" : "no");
  if (!found) return;
  const DMS A = r.massMatrix(eq), Qm = r.potentialHessian(eq);
  const Eigen::GeneralizedSelfAdjointEigenSolver<DMS> ges(Qm, A);
  const DMS P = ges.eigenvectors();  // A-orthonormal columns
  const auto c = r.configuration(eq);
  DMS J(6, 6);
  for (int i = 0; i < 6; ++i) J.col(i) = c.screws[std::size_t(i)];
  const DMS H = J * P;  // harmonic screws h = Σ a_i s_i
  const DMS Ji = J.inverse();
  const DMS GA = H.transpose() * Ji.transpose() * A * Ji * H, GQ = H.transpose() * Ji.transpose() * Qm * Ji * H;
  DMS offA = GA, offQ = GQ;
  offA.diagonal().setZero();
  offQ.diagonal().setZero();
  // J⁻¹(JP) = P to ε cond(J), and the eigensolver's PᵀAP = I to ε cond(L) = ε √cond(A) (it reduces by
  // the Cholesky factor A = LLᵀ, P = L⁻ᵀV): the off-diagonals of PᵀAP and PᵀQP/|Q| are
  // 64 ε (cond J + √cond A) (1e-10 before)
  using std::sqrt;
  const Eigen::JacobiSVD<DMS> sj(J), sa(A);
  const S condJ = sj.singularValues()(0) / sj.singularValues()(5), condA = sa.singularValues()(0) / sa.singularValues()(5);
  const S bound = tol<S>(64) * (condJ + sqrt(condA));
  const std::string how = " (64 ε (cond J + √cond A), cond J = " + toString(condJ, 3) + ", cond A = " + toString(condA, 3) + ")";
  ctx.checkResidual("h_aᵀ(Jᵀ)⁻¹AJ⁻¹h_b = 0 for a ≠ b (six harmonic screws)" + how, maxAbsOf(offA), bound);
  ctx.checkResidual("h_aᵀ(Jᵀ)⁻¹QJ⁻¹h_b = 0 for a ≠ b (relative to |Q|)" + how, S(maxAbsOf(offQ) / maxAbsOf(Qm)), bound);
  S typo = 0;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < a; ++b) {
      S s = 0;
      for (int i = 0; i < 6; ++i) s += A(i, i) * P(i, a) * P(i, b);
      typo = maxOf(typo, S(abs(s)));
    }
  ctx.checkPrintedFails("A_ijφ_iψ_i = 0 (line 8246)", "16", typo, bound);
  std::string pitches;
  for (int a = 0; a < 6; ++a) {
    const Vec6<S> h = H.col(a);
    pitches += (a ? ", " : "") + toString(S(h.template head<3>().dot(h.template tail<3>()) / h.template head<3>().squaredNorm()), 3);
  }
  ctx.note("Pitches of the six harmonic screws (m): " + pitches + "; λ² from " + toString(ges.eigenvalues()(0), 4) + " to " +
           toString(ges.eigenvalues()(5), 4) + " s⁻².");
}

}  // namespace

SOMA_STUDY_SCALAR("GF-13.4-lagrangian-energies", "E_K + Σmgz conserved in free motion, per integrator and scalar (erratum 3)", "GF §13.4", energies);
SOMA_STUDY_SCALAR("GF-13.4.1-partial-derivatives", "∂s_j, ∂q̇_j, ∂N_j, ∂E_K, ∂E_P with respect to θ_i (errata 3–6)", "GF §13.4.1", partials);
SOMA_STUDY_SCALAR("GF-13.4.1-euler-lagrange-agreement", "Euler–Lagrange by differentiation = Newton–Euler", "GF §13.4.1", eulerLagrange);
SOMA_STUDY_SCALAR("GF-13.4.2-christoffel-B", "B = Christoffel symbols of A; Ȧ − 2B(θ̇) skew (erratum 7)", "GF §13.4.2", christoffel);
SOMA_STUDY_SCALAR("GF-13.4.2-dA-three-cases", "∂A_jk/∂θ_i in three index cases (erratum 9)", "GF §13.4.2", dAcases);
SOMA_STUDY_SCALAR("GF-13.4.3-small-oscillations", "Small oscillations: Q = Hessian of E_P, normal modes (errata 8, 17)", "GF §13.4.3", smallOscillations);
SOMA_STUDY_SCALAR("GF-13.4.3-harmonic-screws", "Harmonic screws are A- and Q-orthogonal (erratum 16)", "GF §13.4.3", harmonicScrews);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
