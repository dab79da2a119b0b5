// Studies of Selig & Bayro-Corrochano (2010) §6–§7: the coadjoint action, dN/dt, the equations of
// motion (and SB's E-form) against the 6×6 screw formulation, a free tumbling body integrated in
// both formulations (drift table per formulation and scalar, and a figure), and the §7 claims.
// Every study runs in the scalar asked for (--scalar); the free-body drift table of
// SB-6-equation-of-motion integrates on every rung of the ladder whatever that scalar.
#include "sb/common.hpp"

#include "soma/algebra/clifford/multivector.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace soma::studies::sb::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {
using namespace soma::clifford_dynamics;

template <class S> void coadjointAction(Context& c) {
  auto g = rng(601);
  S eFormula = 0, eFd = 0, eOther = 0;
  for (int k = 0; k < 30; ++k) {
    const T6<S> s(rv6<S>(g));
    const V6<S> P = rv6<S>(g);
    const Biv<S> se = screwElement(s), Pe = coScrewElement(P);
    eFormula = maxOf(eFormula, mxm(V6<S>(coScrewOf(coadjoint(se, Pe)) - soma::coadjoint(s, P))));
    const Biv<S> sb = bar(se);
    const auto full = (sb * Pe - Pe * sb) / S(2);
    eOther = maxOf(eOther, S(mx(full.template grade<0>()) + mx(full.template grade<4>())));
    // d/dt e^{t s̄/2} P e^{−t s̄/2} at t = 0 (5-point difference)
    auto Pt = [&](const S& t) {
      const Ev<S> u = clifford::exp(Biv<S>(sb * (t / 2)));
      return Biv<S>(((u * Pe) * u.conjugate()).template grade<2>());
    };
    const Biv<S> fd = cdiff<S>(Pt, fdStep<S>());
    eFd = maxOf(eFd, mx(Biv<S>(fd - coadjoint(se, Pe))));
  }
  // two-term cross products: 4 ε (8.9e-16; 1e-15 before)
  c.checkResidual("½(s̄P − P s̄) = (ω×l + v×p, ω×p) (30 draws, 4 ε)", eFormula, tol<S>(4));
  c.checkResidual("… and it has no grade 0 or 4 part (4 ε)", eOther, tol<S>(4));
  c.checkResidual("= d/dt e^{t s̄/2} P e^{−t s̄/2} at t = 0 (differences at h = ε^(1/5), 2048 ε^(4/5))", eFd, fdTol<S>());
}

template <class S> void inertiaDerivativeStudy(Context& c) {
  auto g = rng(602);
  S eFd = 0, eWedge = 0;
  for (int k = 0; k < 10; ++k) {
    const SpatialInertia<S> b = randBody<S>(g);
    const Quad<S> N0 = inertiaElement(b.matrix());
    const Ev<S> g0 = motorElement(randMotion<S>(g));
    const Biv<S> s = screwElement(T6<S>(rv6<S>(g)));
    auto Nt = [&](const S& t) { return actInertia(Ev<S>(clifford::exp(Biv<S>(s * (t / 2))) * g0), N0); };
    const Quad<S> fd = cdiff<S>(Nt, fdStep<S>());
    const Quad<S> N = Nt(S(0));
    eFd = maxOf(eFd, S(mx(Quad<S>(fd - inertiaDerivative(N, s))) / mx(N)));
    eWedge = maxOf(eWedge, mx(clifford::outer(s * N - N * s, s)));
  }
  c.checkResidual("dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄) along g(t) = e^{ts/2} g₀ (differences at h = ε^(1/5), relative, "
                  "2048 ε^(4/5))",
                  eFd, fdTol<S>());
  // products with N (entries up to m|t|² ≈ 30 at |t| ≤ 2√3), unscaled: 256 ε (5.7e-14; 1e-13 before)
  c.checkResidual("(sN − Ns) ∧ s = 0 (256 ε)", eWedge, tol<S>(256));
}

// ---------------------------------------------------------------- the free tumbling body
struct Flight {
  std::vector<double> t, dE, dP;  // relative errors of energy and spatial momentum
  double maxE = 0, maxP = 0, seconds = 0;
  Vec6<double> finalVelocity = Vec6<double>::Zero();
  double finalDiff(const Flight& o) const { return (finalVelocity - o.finalVelocity).cwiseAbs().maxCoeff(); }
};
template <class S> Flight fly(bool useClifford, int n, double T, bool keepSeries) {
  const SpatialInertia<S> body(S(2), Vec3<S>(S(3) / S(10), S(-2) / S(10), S(1) / S(10)),
                               Mat3<S>(Vec3<S>(S(1), S(2), S(3)).asDiagonal()));
  const SE3Tangent<S> s0(Vec3<S>(S(1) / S(10), S(2), S(1) / S(10)), Vec3<S>(S(1) / S(2), S(0), S(-1) / S(4)));
  const clifford_dynamics::Quadvector<S> N0 = useClifford ? inertiaElement(body.matrix()) : clifford_dynamics::Quadvector<S>();
  auto acc6 = [&](const SE3<S>& x, const SE3Tangent<S>& s) {
    return rigidBodyAcceleration(coadjointTransform(x, body.matrix()), s, Vec6<S>(Vec6<S>::Zero()));
  };
  auto accC = [&](const SE3<S>& x, const SE3Tangent<S>& s) {
    const auto N = actInertia(motorElement(x), N0);
    return screwOf(clifford_dynamics::rigidBodyAcceleration(N, screwElement(s), clifford_dynamics::Bivector<S>()).sdot);
  };
  // energy and momentum measured in the formulation that is integrated
  auto measure = [&](const RigidBodyState<S>& y, S& E, Vec6<S>& P) {
    if (useClifford) {
      const auto N = actInertia(motorElement(y.pose), N0);
      const auto se = screwElement(y.velocity);
      E = kineticEnergy(N, se);
      P = coScrewOf(momentum(N, se));
    } else {
      const Mat6<S> N = coadjointTransform(y.pose, body.matrix());
      P = N * y.velocity.coeffs();
      E = y.velocity.coeffs().dot(P) / S(2);
    }
  };
  RigidBodyState<S> y{SE3<S>::Identity(), s0};
  S E0;
  Vec6<S> P0;
  measure(y, E0, P0);
  const S h = scalarCast<S>(T) / S(n);
  Flight f;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 1; i <= n; ++i) {
    y = useClifford ? rkmk4Step(y, h, accC) : rkmk4Step(y, h, acc6);
    S E;
    Vec6<S> P;
    measure(y, E, P);
    using std::abs;
    const double de = toDouble(S(abs(E - E0) / E0)), dp = toDouble(S((P - P0).norm() / P0.norm()));
    f.maxE = std::max(f.maxE, de);
    f.maxP = std::max(f.maxP, dp);
    if (keepSeries) f.t.push_back(T * i / n), f.dE.push_back(de), f.dP.push_back(dp);
  }
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (int i = 0; i < 6; ++i) f.finalVelocity(i) = toDouble(y.velocity.coeffs()(i));
  return f;
}

// Part 1 runs in the scalar asked for; part 2, the drift table, integrates the free body on every rung
// of the ladder whatever the scalar asked for (its checks are per rung).
template <class S> void equationOfMotion(Context& c) {
  // 1. SB's derivative of P = A ∨ (N ∧ s) against the 6×6 equation, general inertias
  auto g = rng(603);
  S eLhs = 0, eCor = 0;
  const Quad<S> A = elementA<S>();
  for (int k = 0; k < 30; ++k) {
    const S mass = uni<S>(g, 0.5, 3);
    const Vec3<S> dd = rv3<S>(g, 0.3, 2);
    const SpatialInertia<S> b = SpatialInertia<S>::diagonal(mass, dd);
    const SE3<S> x = randMotion<S>(g);
    const Quad<S> N = actInertia(motorElement(x), inertiaElement(b.matrix()));
    const M6<S> N6 = b.transformed(x).matrix();
    const T6<S> s(rv6<S>(g)), sd(rv6<S>(g));
    const Biv<S> se = screwElement(s), sde = screwElement(sd), sb = bar(se);
    const Biv<S> lhs = (shuffle(A, clifford::outer(N, sde)) + shuffle(A, clifford::outer(sb * N - N * sb, se)) / S(2)).template grade<2>();
    eLhs = maxOf(eLhs, S(mxm(V6<S>(coScrewOf(lhs) - (N6 * sd.coeffs() + soma::coadjoint(s, V6<S>(N6 * s.coeffs()))))) / mxm(N6)));
    const Biv<S> P = momentum(N, se);
    const Biv<S> cor = (shuffle(A, clifford::outer(sb * N - N * sb, se)) / S(2)).template grade<2>();
    eCor = maxOf(eCor, S(mx(Biv<S>(cor - coadjoint(se, P))) / mxm(N6)));
  }
  // relative to ‖N‖, a few products of unit-scale screws: 32 ε (7.1e-15; 1e-14 before)
  c.checkResidual("A ∨ (N ∧ ṡ) + ½ A ∨ ((s̄N − Ns̄) ∧ s) = N ṡ + {s, N s} (30 general inertias, relative, 32 ε)", eLhs, tol<S>(32));
  c.checkResidual("½ A ∨ ((s̄N − Ns̄) ∧ s) = ½(s̄P − P s̄) = {s, P} (32 ε)", eCor, tol<S>(32));

  // 2. a free tumbling body, both formulations, every scalar the formulation is cheap in
  const double T = 20;
  const int n = 400;
  struct Row {
    std::string form, scalar;
    Flight a, b;  // step h and h/2
  };
  std::vector<Row> rows;
  rows.push_back({"6x6", "float", fly<float>(false, n, T, false), fly<float>(false, 2 * n, T, false)});
  rows.push_back({"6x6", "double", fly<double>(false, n, T, true), fly<double>(false, 2 * n, T, true)});
  rows.push_back({"6x6", "long double", fly<long double>(false, n, T, false), fly<long double>(false, 2 * n, T, false)});
  rows.push_back({"6x6", "float128", fly<__float128>(false, n, T, false), fly<__float128>(false, 2 * n, T, false)});
  rows.push_back({"6x6", "mpfr", fly<mpfr::mpreal>(false, n, T, false), fly<mpfr::mpreal>(false, 2 * n, T, false)});
  rows.push_back({"Cl(0,6,2)", "float", fly<float>(true, n, T, false), fly<float>(true, 2 * n, T, false)});
  rows.push_back({"Cl(0,6,2)", "double", fly<double>(true, n, T, true), fly<double>(true, 2 * n, T, true)});
  rows.push_back({"Cl(0,6,2)", "long double", fly<long double>(true, n, T, false), fly<long double>(true, 2 * n, T, false)});
  std::string table = "Free body (m = 2, c = (0.3, −0.2, 0.1), I_c = diag(1, 2, 3), ω₀ = (0.1, 2, 0.1), v₀ = (0.5, 0, −0.25)), "
                      "RKMK4, T = 20, h = 0.05 (400 steps) and h/2. Max relative drift over the flight:\n"
                      "| formulation | scalar | energy, h | energy, h/2 | momentum, h | momentum, h/2 | order (energy) | seconds (h) |\n"
                      "|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "| %s | %s | %.3g | %.3g | %.3g | %.3g | %.2f | %.2f |\n", r.form.c_str(), r.scalar.c_str(),
                  r.a.maxE, r.b.maxE, r.a.maxP, r.b.maxP, std::log2(r.a.maxE / r.b.maxE), r.a.seconds);
    table += buf;
  }
  c.note(table);
  // the bound: an order-4 method divides the truncation drift by 16 when h halves; allow 2^3.5 plus
  // a rounding floor of (steps)·64 ε of the scalar. A priori: drift(h) ≤ (hΩ)⁴ Ω T, Ω = |ω₀| + |v₀|.
  const double Om = std::sqrt(0.01 + 4 + 0.01) + std::sqrt(0.25 + 0.0625), h = T / n;
  const double apriori = std::pow(h * Om, 4) * Om * T;
  auto epsOf = [](const std::string& s) {
    return s == "float" ? 1.19e-7 : s == "double" ? 2.22e-16 : s == "long double" ? 1.08e-19 : s == "float128" ? 1.93e-34 : toDouble(Tolerance<mpfr::mpreal>::epsilon());
  };
  for (const Row& r : rows) {
    const double floor2 = 2 * n * 64 * epsOf(r.scalar);
    const double bound = r.a.maxE / std::pow(2.0, 3.5) + floor2;
    c.checkResidual(r.form + " " + r.scalar + ": energy drift at h/2 (bound drift(h)/2^3.5 + 2n·64ε)", r.b.maxE, bound);
    c.checkResidual(r.form + " " + r.scalar + ": momentum drift at h/2 (same bound)", r.b.maxP, r.a.maxP / std::pow(2.0, 3.5) + floor2);
    c.checkResidual(r.form + " " + r.scalar + ": energy drift at h ≤ (hΩ)⁴ΩT + n·64ε", r.a.maxE, apriori + n * 64 * epsOf(r.scalar));
  }
  // the two formulations integrate the same ODE: identical drift to rounding in double
  // (the flow tumbles near the intermediate axis, so rounding differences between the two formulations grow
  // along the flight; the drift they report agrees to 6 significant digits)
  c.checkNear("double: Clifford energy drift = 6×6 energy drift (relative, 1e-6)", 1.0, rows[6].a.maxE / rows[1].a.maxE, 1e-6);
  c.checkNear("double: Clifford momentum drift = 6×6 momentum drift (relative, 1e-6)", 1.0, rows[6].a.maxP / rows[1].a.maxP, 1e-6);
  c.checkNear("double: final velocity, Clifford vs 6×6 (max |Δs|, same ODE and method)", 0.0, rows[6].a.finalDiff(rows[1].a), 1e-9);
  c.note("float128 and mpfr run only the 6×6 formulation: a Cl(0,6,2) step costs ~12 dense products, software "
         "floating point makes that minutes per flight. A Lagrangian derivation (SB's closing remark in §6) is "
         "not attempted.");

  if (c.makeFigures()) {
    render::Plot p;
    p.title = "Free tumbling body, RKMK4: relative drift vs time";
    p.x.label = "time t";
    p.y.label = "relative error";
    p.y.scale = render::AxisScale::Log10;
    p.y.min = 1e-13;
    p.y.max = 1e-1;  // room above the curves for the legend
    auto clip = [](std::vector<double> v) {
      for (double& x : v) x = std::max(x, 1e-17);
      return v;
    };
    const Row& r6 = rows[1];
    const Row& rc = rows[6];
    p.add("energy, 6×6, h = 0.05", r6.a.t, clip(r6.a.dE), render::palette::blue);
    p.add("energy, Cl(0,6,2), h = 0.05", rc.a.t, clip(rc.a.dE), render::palette::orange).dashed = true;
    p.add("momentum, 6×6, h = 0.05", r6.a.t, clip(r6.a.dP), render::palette::vermillion);
    p.add("momentum, Cl(0,6,2), h = 0.05", rc.a.t, clip(rc.a.dP), render::palette::bluishGreen).dashed = true;
    p.add("energy, 6×6, h = 0.025", r6.b.t, clip(r6.b.dE), render::palette::grey);
    const auto file = "SB-6-equation-of-motion-drift.png";
    render::renderPlotPngAndSvg(p, c.figurePath(file), 1200, 800);
    c.figure(file, "Relative energy and spatial-momentum error of a free tumbling body integrated with RKMK4 in the "
                   "6×6 screw formulation (solid) and SB's Cl(0,6,2) E-form (dashed), double; the two coincide. "
                   "Halving h lowers the energy error by ~2⁴ (grey).");
  }
}

template <class S> void eForm(Context& c) {
  auto g = rng(604);
  S eAE = 0, eForm = 0, eGrades = 0, eSolve = 0, eRes = 0;
  const D<S> AE = D<S>(elementA<S>() * elementE<S>());
  for (int k = 0; k < 30; ++k) {
    const V6<S> Pv = rv6<S>(g);
    eAE = maxOf(eAE, mx(D<S>(shuffle(AE, D<S>(coScrewElement(Pv))) - D<S>(coScrewElement(Pv)))));
    const SpatialInertia<S> b = randBody<S>(g);
    const SE3<S> x = randMotion<S>(g);
    const Quad<S> N = actInertia(motorElement(x), inertiaElement(b.matrix()));
    const M6<S> N6 = b.transformed(x).matrix();
    const T6<S> s(rv6<S>(g)), sd(rv6<S>(g));
    const V6<S> W = N6 * sd.coeffs() + soma::coadjoint(s, V6<S>(N6 * s.coeffs()));
    const auto lhs = eFormLeft(N, screwElement(s), screwElement(sd));
    eForm = maxOf(eForm, S(mx(lhs.template grade<6>() - eFormRight(coScrewElement(W))) / mxm(N6)));
    eGrades = maxOf(eGrades, S((mx(lhs.template grade<4>()) + mx(lhs.template grade<8>())) / mxm(N6)));
    const auto acc = clifford_dynamics::rigidBodyAcceleration(N, screwElement(s), coScrewElement(W));
    eSolve = maxOf(eSolve, mxm(V6<S>(screwOf(acc.sdot).coeffs() - sd.coeffs())));
    eRes = maxOf(eRes, S(acc.residual / mxm(N6)));
  }
  // (AE) ∨ c is a signed copy: 4 ε (1e-15 before); the E-form relative to ‖N‖: 32 ε (7.1e-15; 1e-14
  // before); the 28×6 least-squares solve loses a factor of the conditioning of N: 4096 ε (9.1e-13; 1e-12 before)
  c.checkResidual("(AE) ∨ c = c for random co-screws c (4 ε)", eAE, tol<S>(4));
  c.checkResidual("N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E with W = N ṡ + {s, N s} (30 general inertias, relative, 32 ε)", eForm,
                  tol<S>(32));
  c.checkResidual("… its grade-4 and grade-8 parts vanish (32 ε)", eGrades, tol<S>(32));
  c.checkResidual("solving the E-form for ṡ (28×6 least squares) recovers ṡ (4096 ε)", eSolve, tol<S>(4096));
  c.checkResidual("… with a consistent system (residual after the solve, relative, 32 ε)", eRes, tol<S>(32));
}

template <class S> void claims(Context& c) {
  // dimension counts: span{b̄_i b_j} (36) ⊃ symmetric forms (21) ⊃ inertias (10); numerical rank by
  // soma's one-sided Jacobi SVD (singular values above Tolerance::rank = 1024 ε of the largest)
  auto rankOf = [](const std::vector<Quad<S>>& v) {
    detail::SmallMat<S> M(Quad<S>::size, Eigen::Index(v.size()));
    for (std::size_t j = 0; j < v.size(); ++j)
      for (int i = 0; i < Quad<S>::size; ++i) M(i, Eigen::Index(j)) = v[j][i];
    return detail::smallNumericalRank<S>(M);
  };
  std::vector<Quad<S>> all, sym, inert;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const Biv<S> bi = screwElement(T6<S>(V6<S>(V6<S>::Unit(i)))), bj = screwElement(T6<S>(V6<S>(V6<S>::Unit(j))));
      all.push_back((bar(bi) * bj).template grade<4>());
      if (j >= i) {
        M6<S> E = M6<S>::Zero();
        E(i, j) = E(j, i) = 1;
        sym.push_back(formElement(E));
      }
    }
  auto g = rng(701);
  for (int k = 0; k < 30; ++k) inert.push_back(inertiaElement(randBody<S>(g).matrix()));
  c.checkEqual("rank of {b̄_i b_j} (all 6×6 forms)", 36, rankOf(all));
  c.checkEqual("rank of the symmetric forms (Sym² of the adjoint)", 21, rankOf(sym));
  c.checkEqual("rank spanned by 30 random inertias (m, mc, I: 1 + 3 + 6)", 10, rankOf(inert));
  std::vector<Quad<S>> both = all;
  both.insert(both.end(), sym.begin(), sym.end());
  c.checkEqual("symmetric forms lie in span{b̄_i b_j}", 36, rankOf(both));
  // a stiffness matrix K transforms like an inertia: W = A ∨ (K ∧ δs), K → (gḡ)K(gḡ)*
  S eK = 0, eW = 0;
  for (int k = 0; k < 10; ++k) {
    M6<S> Lm;
    for (int i = 0; i < 6; ++i) Lm.col(i) = rv6<S>(g);
    const M6<S> K = Lm * Lm.transpose();
    const SE3<S> x = randMotion<S>(g);
    const M6<S> Hi = x.inverse().adjoint();
    // relative to (1 + |t|)² ‖K‖: the translation enters H^{-1} and H^{-T} once each
    const S t1 = S(1) + x.translation().norm();
    eK = maxOf(eK, S(mxm(M6<S>(formMatrix(actInertia(motorElement(x), formElement(K))) - Hi.transpose() * K * Hi)) /
                     (t1 * t1 * mxm(K))));
    const T6<S> ds(rv6<S>(g));
    eW = maxOf(eW, S(mxm(V6<S>(coScrewOf(momentum(formElement(K), screwElement(ds))) - K * ds.coeffs())) / mxm(K)));
  }
  // six-term products relative to the scale: 32 ε (7.1e-15; 1e-14 before)
  c.checkResidual("stiffness K: A ∨ (K ∧ δs) = K δs (relative to ‖K‖, 32 ε)", eW, tol<S>(32));
  c.checkResidual("stiffness K: (gḡ)K(gḡ)* has matrix H^{-T} K H^{-1} (relative to (1+|t|)² ‖K‖, 32 ε)", eK, tol<S>(32));
  // even-graded: Cl⁺(0,6,2) ≅ Cl(0,5,2) via f_i = g₀ g_i (i = 1…7)
  int bad = 0;
  for (int i = 1; i < 8; ++i) {
    const D<S> fi = D<S>(D<S>::generator(0) * D<S>::generator(i));
    const D<S> sq = D<S>(fi * fi);
    const S want = i < 6 ? S(-1) : S(0);
    if (mx(D<S>(sq - want)) != S(0)) ++bad;
    for (int j = i + 1; j < 8; ++j) {
      const D<S> fj = D<S>(D<S>::generator(0) * D<S>::generator(j));
      if (mx(D<S>(fi * fj + fj * fi)) != S(0)) ++bad;
    }
  }
  c.checkEqual("f_i = a₁ g_i generate Cl⁺(0,6,2) as Cl(0,5,2): relations violated (5 square −1, 2 square 0, anticommute)",
               0, bad);
  c.note("SB §7's open question (the smallest Clifford algebra containing Sym²(ad se(3))) is not addressed by the "
         "paper and not here. Serial robots in this formalism (SB ref. [13]) are GF ch. 13, a later issue.");
}

}  // namespace

SOMA_STUDY_SCALAR("SB-6-coadjoint-action", "{s, P} = ½(s̄P − P s̄)", "SB §6", coadjointAction);
SOMA_STUDY_SCALAR("SB-6-inertia-derivative", "dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄)", "SB §6", inertiaDerivativeStudy);
SOMA_STUDY_SCALAR("SB-6-equation-of-motion", "dP/dt = W in Cl(0,6,2) = 6×6 equation; free body drift in both formulations",
         "SB §6", equationOfMotion);
SOMA_STUDY_SCALAR("SB-6-E-form", "N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E", "SB §6", eForm);
SOMA_STUDY_SCALAR("SB-7-claims", "Sym² of the adjoint inside Cl(0,6,2); stiffness; even subalgebra", "SB §7", claims);

}  // namespace soma::studies::sb::SOMA_UNITY_ID
