// Studies of GF §15.1 (double): invariant metrics on se(3), the bi-invariant connection, geodesics
// as one-parameter subgroups, the joint-space pull-back metric, its Christoffel symbols (errata
// E15.1, E15.2, E15.3, E15.12) and the Maurer–Cartan form (erratum E15.14).
#include "gf15/common.hpp"

namespace soma::studies::gf15::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

void invariantMetricIdentity(Context& ctx) {
  ctx.checkResidual("Q0: max |C^l_ij Q_lk + C^l_ik Q_lj| over all basis triples", invarianceDefect<double>(reciprocalProductMatrix<double>()), 1e-15);
  ctx.checkResidual("Q_inf = diag(I, 0): the same", invarianceDefect<double>(killingMatrixQinf<double>()), 1e-15);
  ctx.checkResidual("Q_p = Q0 + 0.3 Q_inf", invarianceDefect<double>(InvariantMetric<double>{1, 0.3}.matrix()), 1e-15);
  // structure constants are anti-symmetric: C^k_ij = −C^k_ji
  double anti = 0;
  for (const auto& c : structureConstants<double>()) anti = std::max(anti, maxAbs(DM(c + c.transpose())));
  ctx.checkResidual("C^k_ij + C^k_ji", anti, 0.0);
  ctx.checkPrintedFails("the Euclidean 6×6 metric I₆ is invariant (control, not an erratum)", "— control",
              invarianceDefect<double>(M6::Identity()), 1e-12);
}

void biinvariantConnection(Context& ctx) {
  auto g = std::mt19937_64(1511);
  const InvariantMetric<double> Q{1, 0.3};
  double tors = 0, metric = 0, anti = 0;
  for (int t = 0; t < 20; ++t) {
    const V6 X = rv6(g), Y = rv6(g), Z = rv6(g);
    tors = std::max(tors, (biinvariantCovariant<double>(X, Y) - biinvariantCovariant<double>(Y, X) - br(X, Y)).cwiseAbs().maxCoeff());
    metric = std::max(metric, abs(Q(biinvariantCovariant<double>(X, Y), Z) + Q(Y, biinvariantCovariant<double>(X, Z))));
  }
  for (const auto& G : biinvariantChristoffel<double>()) anti = std::max(anti, maxAbs(DM(G + G.transpose())));
  ctx.checkResidual("torsion-free: ∇_XY − ∇_YX = [X, Y] (20 random pairs)", tors, 1e-15);
  ctx.checkResidual("metric: Q_p(∇_XY, Z) + Q_p(Y, ∇_XZ) = 0 (α = 1, β = 0.3)", metric, 1e-14);
  ctx.checkResidual("Γ^k_ij = −½C^k_ij is anti-symmetric in i, j (\"a symmetric connection has an anti-symmetric symbol\")", anti, 0.0);
  // extreme: Q_inf alone is degenerate (rank 3), so "multiply by the inverse metric" is impossible
  ctx.checkEqual("rank of Q_inf (degenerate: the derivation needs α ≠ 0)", 3,
                 detail::smallNumericalRank<double>(DM(killingMatrixQinf<double>())));
  bool threw = false;
  try {
    (void)InvariantMetric<double>{0, 1}.nullPitch();
  } catch (const InvalidInput&) {
    threw = true;
  }
  ctx.checkEqual("Q_p with α = 0 is rejected (InvalidInput)", 1, threw ? 1 : 0);
}

void geodesicsSubgroups(Context& ctx) {
  auto g = std::mt19937_64(1512);
  const JointSpaceGeometry<double> geo(randomScrews(g, 6));
  DV th = rvec(g, 6, -0.5, 0.5), v = rvec(g, 6, -0.3, 0.3);
  const SE3<double> g0 = geo.forward(th);
  const V6 X = geo.screws(th) * v;
  double drift = 0;
  for (int k = 0; k < 100; ++k) {
    geo.geodesicStep(th, v, 0.01);
    drift = std::max(drift, (V6(geo.screws(th) * v) - X).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("RK4 on θ̈ = −Γθ̇θ̇ (100 steps of 0.01): max |q̇₆(t) − q̇₆(0)|", drift, 1e-9);
  const SE3<double> expect = SE3Tangent<double>(X).exp().compose(g0);
  ctx.checkResidual("ρ(θ(1)) = e^{X} ρ(θ(0)) (a translate of a one-parameter subgroup)",
                    (geo.forward(th).matrix() - expect.matrix()).cwiseAbs().maxCoeff(), 1e-9);
  // erratum E15.12: ∫Q(γ̇, γ̇)dt is the energy, not length². γ(t) = e^{φ(t)X}, X a unit rotation, metric Q_inf
  // φ = t: ∫Q = 1 = length²; φ = t²: length = ∫|φ̇| = 1 but ∫Q = ∫4t² = 4/3.
  auto integrate = [](auto phidot) {
    double e = 0, l = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) / n, p = phidot(t);
      e += p * p / n;
      l += std::abs(p) / n;
    }
    return std::pair<double, double>(e, l);
  };
  const auto [e1, l1] = integrate([](double) { return 1.0; });
  const auto [e2, l2] = integrate([](double t) { return 2 * t; });
  ctx.checkNear("constant speed φ = t: ∫Q(γ̇,γ̇)dt = length² = 1", l1 * l1, e1, 1e-12);
  ctx.checkNear("reparametrised φ = t²: the length is unchanged (1)", 1.0, l2, 1e-8);
  ctx.checkPrintedFails("length²(γ) = ∫Q(γ̇, γ̇)dt for φ = t² (the energy is 4/3, the length² 1)", "E15.12", abs(e2 - l2 * l2), 1e-6);
  ctx.note("The energy ∫Q(γ̇,γ̇)dt has the same critical curves as the length only among constant-speed curves; "
           "the geodesics it yields are the constant-speed ones (E15.12, harmless).");
}

void qpNullGeodesics(Context& ctx) {
  auto g = std::mt19937_64(1513);
  double worst = 0, other = 0;
  for (int t = 0; t < 20; ++t) {
    const double p = uni(g, -2, 2);
    const InvariantMetric<double> Q = InvariantMetric<double>::withNullPitch(p);
    const V6 s = lineScrew(unit3(g), rv3(g), p);
    worst = std::max(worst, abs(Q(s, s)));
    const V6 s2 = lineScrew(unit3(g), rv3(g), p + 1);
    other = std::max(other, abs(Q(s2, s2) - 2));  // Q_p(s, s) = 2α(p' − p)|ω|² = 2
    ctx.checkNear(t == 0 ? "p = −β/2α recovered from Q_p" : "", p, Q.nullPitch(), 1e-15);
  }
  ctx.checkResidual("Q_p(s, s) = 0 for pitch-p screws (20 random metrics and axes)", worst, 1e-14);
  ctx.checkResidual("Q_p(s, s) = 2α(p' − p)|ω|² for a pitch-p' screw", other, 1e-14);
  // same geodesics for every metric, different lengths: the geodesic acceleration is metric-independent
  const JointSpaceGeometry<double> geo(randomScrews(g, 6));
  const DV th = rvec(g, 6), v = rvec(g, 6);
  double diff = 0;
  for (double beta : {-3.0, -0.5, 0.0, 0.4, 2.0}) {
    const JointSpaceGeometry<double> gq(geo.homeScrews(), InvariantMetric<double>{1, beta});
    const auto lc = gq.christoffelLeviCivita(th);
    DV a(6);
    for (int i = 0; i < 6; ++i) a(i) = -v.dot(lc[std::size_t(i)] * v);
    diff = std::max(diff, maxAbs(DV(a - geo.geodesicAcceleration(th, v))) / maxAbs(a));
  }
  ctx.checkResidual("Levi-Civita geodesic acceleration of JᵀQ_pJ for β ∈ {−3, −½, 0, 0.4, 2} (relative)", diff, 1e-10);
}

void pullbackMetric(Context& ctx) {
  auto g = std::mt19937_64(1514);
  const JointSpaceGeometry<double> geo(randomScrews(g, 6), InvariantMetric<double>{1, 0.3});
  const DV th = rvec(g, 6);
  const SM J = geo.screws(th);
  const auto D = geo.screwDerivatives(J);
  double err = 0, fk = 0;
  for (int i = 0; i < 6; ++i) {
    const SM fd = cdiff([&](double u) {
      DV a = th;
      a(i) += u;
      return SM(geo.screws(a));
    });
    err = std::max(err, maxAbs(DM(fd - D[std::size_t(i)])));
    // s_i(θ) is the spatial Jacobian: ∂ρ/∂θ_i ρ⁻¹ = ŝ_i
    const Mat4<double> dr = cdiff([&](double u) {
      DV a = th;
      a(i) += u;
      return Mat4<double>(geo.forward(a).matrix());
    });
    const Mat4<double> sh = dr * geo.forward(th).inverse().matrix();
    fk = std::max(fk, (SE3Tangent<double>::vee(sh).coeffs() - V6(J.col(i))).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("∂s_j/∂θ_i = [s_i, s_j] (i < j), 0 otherwise: finite differences", err, 1e-9);
  ctx.checkResidual("s_i(θ) = e^{θ₁ad s₁}···e^{θ_{i−1}ad s_{i−1}} s_i(0) equals (∂ρ/∂θ_i)ρ⁻¹ (corrected form, E15.3)", fk, 1e-9);
  ctx.checkResidual("Q_p* = JᵀQ_pJ is symmetric", maxAbs(DM(geo.pullbackMetric(th) - geo.pullbackMetric(th).transpose())), 1e-15);
  // E15.3: the printed e^{θad}···s_i(0)···e^{−θad} is type-correct only with s_i(0) read as the 6×6 matrix
  // ad(s_i(0)); then it equals ad(s_i(θ)) (conjugation), consistent with the corrected vector form.
  SE3<double> G = SE3<double>::Identity();
  for (int k = 0; k < 3; ++k) G = G.compose(SE3Tangent<double>(V6(th(k) * geo.homeScrews()[std::size_t(k)])).exp());
  const M6 conj = G.adjoint() * SE3Tangent<double>(geo.homeScrews()[3]).ad() * G.adjoint().inverse();
  ctx.checkResidual("printed form in the ad representation: Ad·ad(s₄(0))·Ad⁻¹ = ad(s₄(θ))",
                    (conj - SE3Tangent<double>(V6(J.col(3))).ad()).cwiseAbs().maxCoeff(), 1e-14);
  // read with s_i(0) a vector and the trailing factors applied to it as well, Ad·Ad⁻¹·s = s(0) is wrong
  ctx.checkPrintedFails("s_i(θ) read as e^{θad}···e^{−θad} s_i(0) (the factors cancel: s_i(0))", "E15.3",
              (geo.homeScrews()[3] - V6(J.col(3))).cwiseAbs().maxCoeff(), 1e-6);
}

void covariantDerivative(Context& ctx) {
  auto g = std::mt19937_64(1515);
  const InvariantMetric<double> Q{1, -0.4};
  const JointSpaceGeometry<double> geo(randomScrews(g, 6), Q);
  const DV th = rvec(g, 6), td = rvec(g, 6), a = rvec(g, 6), b = rvec(g, 6), z = DV::Zero(6);
  const double dq = cdiff([&](double t) {
    const SM J = geo.screws(DV(th + t * td));
    return DV::Constant(1, Q(V6(J * a), V6(J * b)));
  })(0);
  const SM J = geo.screws(th);
  const double rhs = Q(geo.covariantDerivative(th, td, a, z), V6(J * b)) + Q(V6(J * a), geo.covariantDerivative(th, td, b, z));
  ctx.checkNear("d/dt Q_p(V, W) = Q_p(∇_UV, W) + Q_p(V, ∇_UW) along θ + tθ̇ (finite differences)", dq, rhs, 1e-9);
  // parallel transport along a curve preserves Q_p(V, V): solve ∇_U V = 0 for φ̇ along θ(t) = θ + tθ̇
  DV p = a;
  auto pdot = [&](double t, const DV& ph) {  // ∇_U V = J φ̈ + (bracket terms) = 0 → φ̈ = −J⁻¹(bracket terms)
    const DV tt = th + t * td;
    const V6 rest = geo.covariantDerivative(tt, td, ph, z);
    return DV(-(geo.coScrews(geo.screws(tt)) * rest));
  };
  const double q0 = Q(V6(J * p), V6(J * p));
  // 0.25 s of the line θ + tθ̇: this random robot nears a singularity at t ≈ 0.45 (cond J ≈ 500, |φ̇| ~ 1e3),
  // where the W_i blow up and fixed-step RK4 loses the invariant; the segment before it is regular
  const double h = 0.0025;
  for (int k = 0; k < 100; ++k) {
    const double t = k * h;
    const DV k1 = pdot(t, p), k2 = pdot(t + h / 2, DV(p + h / 2 * k1)), k3 = pdot(t + h / 2, DV(p + h / 2 * k2)), k4 = pdot(t + h, DV(p + h * k3));
    p += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const SM J1 = geo.screws(DV(th + 0.25 * td));
  ctx.checkNear("parallel transport ∇_UV = 0 (RK4, 100 steps over 0.25 s) preserves Q_p(V, V)", q0, Q(V6(J1 * p), V6(J1 * p)), 1e-10 * std::max(1.0, abs(q0)));
  const DV tdd = rvec(g, 6);
  ctx.checkResidual("∇_U U = q̈₆ (the spatial end-effector acceleration)",
                    (geo.covariantDerivative(th, td, td, tdd) - geo.endEffectorAcceleration(th, td, tdd)).cwiseAbs().maxCoeff(), 1e-14);
}

void geodesicEquation(Context& ctx) {
  auto g = std::mt19937_64(1516);
  const JointSpaceGeometry<double> geo(randomScrews(g, 6));
  DV th = rvec(g, 6, -0.5, 0.5), v = rvec(g, 6, -0.3, 0.3);
  const DV th0 = th, v0 = v;
  const V6 X = geo.screws(th) * v;
  auto drift = [&](int N) {
    DV a = th0, b = v0;
    for (int k = 0; k < N; ++k) geo.geodesicStep(a, b, 1.0 / N);
    return (V6(geo.screws(a) * b) - X).cwiseAbs().maxCoeff();
  };
  const double d200 = drift(200), d400 = drift(400);
  ctx.checkResidual("θ̈_i + Σ_{j<k} W_i([s_j, s_k])θ̇_jθ̇_k = 0, RK4 400 × 1/400 s: end-effector twist drift", d400, 1e-9);
  ctx.checkNear("halving h divides the drift by 2⁴ (RK4 truncation, not a model error): ratio", 16.0, d200 / d400, 4.0);
  th = th0;
  v = v0;
  // E15.2: the printed Σ_{i<j} θ̇_iθ̇_k[s_i, s_j] with the unbound k read as j's partner i (θ̇_i²)
  auto printedAcc = [&](const DV& t, const DV& w) {
    const SM J = geo.screws(t);
    V6 a = V6::Zero();
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j) a += w(i) * w(i) * br(V6(J.col(i)), V6(J.col(j)));
    return DV(-(geo.coScrews(J) * a));
  };
  th = th0;
  v = v0;
  for (int k = 0; k < 100; ++k) {
    const double h = 0.01;
    const DV a1 = printedAcc(th, v), v2 = v + h / 2 * a1, a2 = printedAcc(DV(th + h / 2 * v), v2), v3 = v + h / 2 * a2,
             a3 = printedAcc(DV(th + h / 2 * v2), v3), v4 = v + h * a3, a4 = printedAcc(DV(th + h * v3), v4);
    th += h / 6 * (v + 2 * v2 + 2 * v3 + v4);
    v += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
  }
  ctx.checkPrintedFails("Σ_{i<j} θ̇_iθ̇_k[s_i, s_j] with k read as i: twist drift", "E15.2", (V6(geo.screws(th) * v) - X).cwiseAbs().maxCoeff(), 1e-6);
  // near a singularity the W_i blow up: the library reports it instead of returning NaN
  auto s = geo.homeScrews();
  s[4] = s[3];
  bool threw = false;
  try {
    (void)JointSpaceGeometry<double>(s).geodesicAcceleration(DV::Zero(6), DV::Ones(6));
  } catch (const InvalidInput&) {
    threw = true;
  }
  ctx.checkEqual("two coincident joint axes (singular J): InvalidInput, not NaN", 1, threw ? 1 : 0);
}

/// The "anti-symmetric" reading Γ^i_jk = ½W_i([s_j, s_k]) for all j ≠ k (0 for j = k), W_i the rows of J⁻¹.
// GF §15.1 line 9581 as printed (erratum E15.1)
std::vector<DM> christoffelAsPrinted(const JointSpaceGeometry<double>& geo, const DV& th) {
  const ScrewMatrix<double> J = geo.screws(th);
  const DM W = geo.coScrews(J);
  std::vector<DM> G(6, DM::Zero(6, 6));
  for (int j = 0; j < 6; ++j)
    for (int k = 0; k < 6; ++k) {
      if (j == k) continue;
      const DV w = W * br(J.col(j), J.col(k)) / 2.0;
      for (int i = 0; i < 6; ++i) G[std::size_t(i)](j, k) = w(i);
    }
  return G;
}

void christoffel(Context& ctx) {
  auto g = std::mt19937_64(1517);
  const JointSpaceGeometry<double> geo(randomScrews(g, 6), InvariantMetric<double>{1, 0.3});
  const DV th = rvec(g, 6);
  std::vector<DM> dG;
  for (int i = 0; i < 6; ++i)
    dG.push_back(cdiff([&](double u) {
      DV a = th;
      a(i) += u;
      return geo.pullbackMetric(a);
    }, 1e-4));
  const DM Gi = geo.pullbackMetric(th).inverse();
  const auto book = geo.christoffelBook(th), printed = christoffelAsPrinted(geo, th);
  double err = 0, errP = 0, sym = 0, scale = 0;
  for (int j = 0; j < 6; ++j)
    for (int k = 0; k < 6; ++k) {
      DV lower(6);
      for (int l = 0; l < 6; ++l) lower(l) = (dG[std::size_t(j)](l, k) + dG[std::size_t(k)](l, j) - dG[std::size_t(l)](j, k)) / 2;
      const DV up = Gi * lower;
      for (int i = 0; i < 6; ++i) {
        err = std::max(err, abs(up(i) - book[std::size_t(i)](j, k)));
        errP = std::max(errP, abs(up(i) - printed[std::size_t(i)](j, k)));
        sym = std::max(sym, abs(book[std::size_t(i)](j, k) - book[std::size_t(i)](k, j)));
        scale = std::max(scale, abs(up(i)));
      }
    }
  ctx.checkResidual("Γ^i_jk = ±½W_i([s_j, s_k]) equals the finite-difference Levi-Civita symbols of JᵀQ_pJ (α = 1, β = 0.3)", err, 1e-8);
  ctx.checkResidual("the case formula is SYMMETRIC in j, k", sym, 1e-14);
  ctx.checkResidual("and equals the analytic Levi-Civita symbols",
                    [&] {
                      const auto lc = geo.christoffelLeviCivita(th);
                      double m = 0;
                      for (int i = 0; i < 6; ++i) m = std::max(m, maxAbs(DM(lc[std::size_t(i)] - book[std::size_t(i)])));
                      return m;
                    }(),
                    1e-12);
  ctx.checkPrintedFails("\"the Christoffel symbol must be anti-symmetric\": Γ^i_jk = ½W_i([s_j, s_k]) for all j, k", "E15.1", errP / scale, 1e-12);
  ctx.note("Max |Γ| = " + toString(scale, 4) + ". Anti-symmetry holds only in the Lie-algebra (non-holonomic) frame; "
           "in joint coordinates a torsion-free connection has symmetric symbols, and the anti-symmetric part contracts to zero "
           "in Γ^i_jkθ̇_jθ̇_k.");
}

void maurerCartan(Context& ctx) {
  auto g = std::mt19937_64(1518);
  const JointSpaceGeometry<double> geo(randomScrews(g, 6));
  const DV th = rvec(g, 6);
  const auto d = geo.maurerCartanDifferential(th);
  const SE3<double> r = geo.forward(th);
  double err = 0, left = 0, leftPrinted = 0;
  auto col = [&](int which, int dir, double u, bool body) {
    DV x = th;
    x(dir) += u;
    const V6 s = geo.screws(x).col(which);
    return body ? V6(geo.forward(x).inverse().adjoint() * s) : s;
  };
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const V6 dsj = cdiff([&](double u) { return col(j, i, u, false); }), dsi = cdiff([&](double u) { return col(i, j, u, false); });
      err = std::max(err, (dsj - dsi - d[std::size_t(i)][std::size_t(j)]).cwiseAbs().maxCoeff());
      // the left-invariant form g⁻¹dg: body screws b_i = Ad(ρ⁻¹)s_i satisfy ∂_ib_j − ∂_jb_i = −[b_i, b_j]
      const V6 bj = cdiff([&](double u) { return col(j, i, u, true); }), bi = cdiff([&](double u) { return col(i, j, u, true); });
      const M6 Ai = r.inverse().adjoint();
      const V6 bb = br(V6(Ai * geo.screws(th).col(i)), V6(Ai * geo.screws(th).col(j)));
      left = std::max(left, (bj - bi + bb).cwiseAbs().maxCoeff());
      leftPrinted = std::max(leftPrinted, (bj - bi - bb).cwiseAbs().maxCoeff());
    }
  ctx.checkResidual("ρ*Ω = Σ s_i ⊗ dθ_i: d(ρ*Ω)(∂_i, ∂_j) = ∂_is_j − ∂_js_i = [s_i, s_j] (finite differences)", err, 1e-9);
  ctx.checkResidual("left-invariant g⁻¹dg (body screws): ∂_ib_j − ∂_jb_i = −[b_i, b_j], i.e. dω = −½[ω, ω]", left, 1e-9);
  ctx.checkPrintedFails("\"left-invariant\" form with dΩ = +½[Ω, Ω] on body screws", "E15.14", leftPrinted, 1e-6);
  ctx.note("With spatial screws s_i the pulled-back form is the right-invariant dg g⁻¹, for which the book's '+' is right "
           "(its final formula, line 9619, holds); the text calls it left-invariant.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-15.1-invariant-metric-identity", "Bi-invariance C^l_ijQ_lk + C^l_ikQ_lj = 0 for Q0, Q_inf, Q_p", "GF §15.1", invariantMetricIdentity);
SOMA_STUDY_DOUBLE("GF-15.1-biinvariant-connection", "The metric connection ∇_iX_j = ½[X_i, X_j], Γ = −½C", "GF §15.1", biinvariantConnection);
SOMA_STUDY_DOUBLE("GF-15.1-geodesics-subgroups", "Geodesics are the one-parameter subgroups and their translates (erratum E15.12)", "GF §15.1", geodesicsSubgroups);
SOMA_STUDY_DOUBLE("GF-15.1-Qp-null-geodesics", "Q_p = αQ0 + βQ_inf: pitch −β/2α screws are null; all Q_p share geodesics", "GF §15.1", qpNullGeodesics);
SOMA_STUDY_DOUBLE("GF-15.1-joint-space-pullback-metric", "Q_p* = JᵀQ_pJ and the screw transport s_i(θ) (erratum E15.3)", "GF §15.1", pullbackMetric);
SOMA_STUDY_DOUBLE("GF-15.1-joint-space-covariant-derivative", "∇_UV in joint space: metric compatibility, parallel transport", "GF §15.1", covariantDerivative);
SOMA_STUDY_DOUBLE("GF-15.1-joint-space-geodesic-equation", "θ̈_i + Σ_{j<k}W_i([s_j,s_k])θ̇_jθ̇_k = 0 keeps the twist (erratum E15.2)", "GF §15.1", geodesicEquation);
SOMA_STUDY_DOUBLE("GF-15.1-joint-space-christoffel", "Γ^i_jk = ±½W_i([s_j,s_k]) is the Levi-Civita symbol, symmetric (erratum E15.1)", "GF §15.1", christoffel);
SOMA_STUDY_DOUBLE("GF-15.1-maurer-cartan-pullback", "ρ*Ω = Σs_i⊗dθ_i and d(ρ*Ω) = Σ_{i<j}[s_i,s_j]⊗dθ_i∧dθ_j (erratum E15.14)", "GF §15.1", maurerCartan);

}  // namespace soma::studies::gf15::SOMA_UNITY_ID
