// Studies of GF §13.2–13.3 (double): time derivatives in the fixed frame, the single-body equation
// of motion, the serial-link equations, the gravity wrench, link accelerations, the closed form
// A, B, C (errata 1, 2, 15), the payload increments and the recursive Newton–Euler algorithm.
#include "gf13/common.hpp"

#include "soma/algebra/screw_bracket.hpp"
#include "soma/geometry/dynamics/free_body.hpp"

#include <Eigen/Eigenvalues>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

void timeDerivatives(Context& ctx) {
  auto g = std::mt19937_64(1320);
  double es = 0, em = 0, en = 0;
  for (int t = 0; t < 50; ++t) {
    const V6 z = rv6(g), s0 = rv6(g), P0 = rv6(g);
    const M6 N0 = randomBody(g).matrix();
    auto G = [&](double u) { return SE3Tangent<double>(V6(u * z)).exp(); };
    const V6 ds = dmat([&](double u) { return V6(G(u).adjoint() * s0); }, 1e-3);
    const V6 dP = dmat([&](double u) { return coadjointAct(G(u), P0); }, 1e-3);
    const M6 dN = dmat([&](double u) { return coadjointTransform(G(u), N0); }, 1e-3);
    es = std::max(es, (ds - br(z, s0)).norm() / s0.norm());
    em = std::max(em, (dP - coad(z, P0)).norm() / P0.norm());
    en = std::max(en, maxAbs(DM(dN - (-adm(z).transpose() * N0 - N0 * adm(z)))) / maxAbs(DM(N0)));
  }
  // 4th-order differences with d = 1e-3: truncation ~ d⁴ = 1e-12 times the 5th derivative (|z| ≤ √6)
  ctx.checkResidual("d/dt s = [z, s] along e^{t ad z} (50 random, 4th-order differences)", es, 1e-9);
  ctx.checkResidual("d/dt 𝓜 = {z, 𝓜}", em, 1e-9);
  ctx.checkResidual("Ṅ = −ad(z)ᵀN − N ad(z) (line 7810)", en, 1e-9);
}

void singleBody(Context& ctx) {
  auto g = std::mt19937_64(1321);
  const SpatialInertia<double> body = randomBody(g);
  RigidBodyState<double> y{SE3<double>(), SE3Tangent<double>(rv6(g))};
  const M6 N0 = body.matrix();
  auto accel = [&](const SE3<double>& x, const SE3Tangent<double>& s) {
    return rigidBodyAcceleration<double>(coadjointTransform(x, N0), s, V6::Zero());
  };
  const V6 mom0 = N0 * y.velocity.coeffs();
  const double e0 = y.velocity.coeffs().dot(mom0) / 2;
  double dm = 0, de = 0;
  for (int k = 0; k < 1000; ++k) {
    y = rkmk4Step(y, 1e-3, accel);
    const M6 N = coadjointTransform(y.pose, N0);
    dm = std::max(dm, (N * y.velocity.coeffs() - mom0).norm() / mom0.norm());
    de = std::max(de, abs(y.velocity.coeffs().dot(N * y.velocity.coeffs()) / 2 - e0) / e0);
  }
  ctx.checkResidual("free body 1 s (RKMK4, h = 1 ms): spatial momentum N q̇ constant (relative)", dm, 1e-10);
  ctx.checkResidual("and E_K constant (relative)", de, 1e-10);
  // the body-frame Euler equations: I_c ω̇_b + ω_b × I_c ω_b = 0 for a body with c at the origin
  const SpatialInertia<double> b0(body.mass(), V3::Zero(), body.inertiaAboutCentre());
  const V3 w = rv3(g);
  SE3Tangent<double> s(w, V3::Zero());
  const V6 a = rigidBodyAcceleration<double>(b0.matrix(), s, V6::Zero()).coeffs();
  const M3 I = body.inertiaAboutCentre();
  const V3 euler = I.ldlt().solve(V3(-w.cross(I * w)));
  ctx.checkResidual("at the c.o.m.: N q̈ + {q̇, N q̇} = 0 gives Euler's ω̇ = −I⁻¹(ω × Iω)", V3(a.head<3>() - euler).norm(), 1e-14);
}

/// τ_i from the link equations (line 7843) with explicit gravity wrenches 𝒢_j = (−m g c × k, −m g k).
DV linkEquationTorque(const SerialDynamics<double>& r, const DV& th, const DV& thd, const DV& thdd) {
  const auto c = r.configuration(th);
  const auto qd = r.linkVelocities(c, thd);
  const auto qdd = r.linkAccelerations(c, thd, thdd);
  const int n = r.dof();
  DV tau = DV::Zero(n);
  const V3 k(0, 0, 1);
  for (int i = 0; i < n; ++i) {
    const V6& si = c.screws[std::size_t(i)];
    for (int j = i; j < n; ++j) {
      const M6& N = c.inertias[std::size_t(j)];
      const double m = r.homeLinks()[std::size_t(j)].mass();
      const V3 cj = c.placements[std::size_t(j)].act(r.homeLinks()[std::size_t(j)].centreOfMass());
      V6 G;
      G << -m * r.gravity() * cj.cross(k), -m * r.gravity() * k;
      tau(i) += qdd[std::size_t(j)].dot(N * si) + qd[std::size_t(j)].dot(N * br(si, qd[std::size_t(j)])) - G.dot(si);
    }
  }
  return tau;
}

void linkEquations(Context& ctx) {
  auto g = std::mt19937_64(1322);
  double worst = 0;
  for (int t = 0; t < 20; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 6);
    const DV th = rjoints(g, 6, -3, 3), thd = rjoints(g, 6), thdd = rjoints(g, 6);
    const DV a = linkEquationTorque(r, th, thd, thdd), b = r.inverseDynamics(th, thd, thdd);
    worst = std::max(worst, maxAbs(DV(a - b)) / maxAbs(b));
  }
  ctx.checkResidual("τ_i = Σ_{j≥i}(q̈_jᵀN_js_i + q̇_jᵀN_j[s_i, q̇_j] − 𝒢_jᵀs_i) = RNEA (20 random 6R, relative)", worst, 1e-13);
}

void gravityWrench(Context& ctx) {
  auto g = std::mt19937_64(1323);
  double eg = 0, es = 0;
  for (int t = 0; t < 50; ++t) {
    const SpatialInertia<double> b = randomBody(g, 2);
    const double grav = 9.81;
    V6 gs = V6::Zero();
    gs(5) = -grav;
    V6 G;
    G << -b.mass() * grav * b.centreOfMass().cross(V3(0, 0, 1)), -b.mass() * grav * V3(0, 0, 1);
    eg = std::max(eg, (b.matrix() * gs - G).norm() / G.norm());
  }
  for (int t = 0; t < 20; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 6);
    const DV th = rjoints(g, 6, -3, 3), thd = rjoints(g, 6), thdd = rjoints(g, 6);
    const DV a = r.inverseDynamicsSpatial(th, thd, thdd), b = r.inverseDynamics(th, thd, thdd);
    es = std::max(es, maxAbs(DV(a - b)) / maxAbs(b));
  }
  ctx.checkResidual("𝒢 = (−mg c × k, −mg k) = N g with g = (0, −g k) (50 random bodies)", eg, 1e-15);
  ctx.checkResidual("spatial formula τ_i = Σ_{j≥i}((q̈_j − g)ᵀN_js_i + q̇_jᵀN_j[s_i, q̇_j]) = RNEA (line 7861)", es, 1e-13);
}

void linkAccelerations(Context& ctx) {
  auto g = std::mt19937_64(1324);
  double worst = 0;
  for (int t = 0; t < 20; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 6);
    const DV th = rjoints(g, 6), thd = rjoints(g, 6), thdd = rjoints(g, 6);
    const auto acc = r.linkAccelerations(r.configuration(th), thd, thdd);
    const SerialDynamics<Q> rq = castRobot<Q>(r);
    for (int i = 0; i < 6; ++i) {
      V6 fd;
      for (int k = 0; k < 6; ++k)
        fd(k) = dq([&](const Q& u) {
          const DynVector<Q> a = castV<Q>(th) + u * castV<Q>(thd) + (u * u / 2) * castV<Q>(thdd);
          return rq.linkVelocities(rq.configuration(a), DynVector<Q>(castV<Q>(thd) + u * castV<Q>(thdd)))[std::size_t(i)](k);
        });
      worst = std::max(worst, (fd - acc[std::size_t(i)]).norm() / std::max(1.0, fd.norm()));
      if (t > 2) break;  // the __float128 differences are slow: full check on 3 robots, link 1 on the rest
    }
  }
  ctx.checkResidual("q̈_i = Σθ̈_js_j + Σ_{k<l≤i}θ̇_kθ̇_l[s_k, s_l] = d/dt q̇_i (8th-order differences in __float128)", worst, 1e-12);
  ctx.note("Line 7873 prints Σ_{i=1}^{i} θ̈_i s_j (erratum 15, index typo): as printed it is not a formula; read as "
           "Σ_{j=1}^{i} θ̈_j s_j it is the one checked.");
}

void generalisedInertia(Context& ctx) {
  auto g = std::mt19937_64(1325);
  double ek = 0, sym = 0;
  int pd = 0;
  for (int t = 0; t < 50; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 2 + t % 6, t % 3 == 0 ? 1 : -1);
    const DV th = rjoints(g, r.dof(), -3, 3), thd = rjoints(g, r.dof());
    const DM A = r.massMatrix(th);
    ek = std::max(ek, abs(thd.dot(A * thd) / 2 - r.kineticEnergy(th, thd)) / r.kineticEnergy(th, thd));
    sym = std::max(sym, maxAbs(DM(A - A.transpose())));
    pd += Eigen::LLT<DM>(A).info() == Eigen::Success;
  }
  ctx.checkResidual("½θ̇ᵀAθ̇ = ½Σq̇_iᵀN_iq̇_i (50 random robots, 2–7 joints, some prismatic)", ek, 1e-14);
  ctx.checkResidual("A symmetric", sym, 0.0);
  ctx.checkEqual("A positive definite", 50, pd);
  // PUMA 560 with published inertias: singular posture θ₅ = 0 (wrist), A stays PD
  const SerialDynamics<double> p = puma();
  DV th(6);
  th << 0.3, -0.5, 0.7, 0.2, 0.0, -0.4;
  const Eigen::SelfAdjointEigenSolver<DM> es(p.massMatrix(th));
  ctx.checkEqual("PUMA 560 at the wrist singularity θ₅ = 0: A positive definite", "yes", es.eigenvalues().minCoeff() > 0 ? "yes" : "no");
  ctx.note("PUMA 560 (Armstrong et al. 1986 inertias) at θ = (0.3, −0.5, 0.7, 0.2, 0, −0.4): eigenvalues of A from " +
           toString(es.eigenvalues().minCoeff(), 4) + " to " + toString(es.eigenvalues().maxCoeff(), 4) + " kg·m².");
  // link 1's mass and transverse moments are torque-neutral (the robot file's stand-in values)
  auto links = pumaLinks();
  links[0] = SpatialInertia<double>(25.0, V3::Zero(), M3(V3(2.0, 0.35, 3.0).asDiagonal()));
  const SerialDynamics<double> p2 = serialDynamicsOf(puma560Robot<double>(), links, 9.81);
  double diff = 0;
  for (int t = 0; t < 20; ++t) {
    const DV a = rjoints(g, 6, -3, 3), b = rjoints(g, 6), c = rjoints(g, 6);
    diff = std::max(diff, maxAbs(DV(p.inverseDynamics(a, b, c) - p2.inverseDynamics(a, b, c))));
  }
  ctx.checkResidual("PUMA link 1: m₁ = 1 → 25 kg, I_xx, I_zz changed: every joint torque unchanged (N·m)", diff, 1e-12);
}

/// B_ijk with the third brackets as printed, [s_k, s_i] (j ≤ k) and [s_i, s_k] (k < j), x = max(i, j, k).
// GF §13.2.2 lines 7889–7895 as printed (erratum 2)
std::vector<DM> coriolisAsPrinted(const ChainConfiguration<double>& c) {
  const int n = int(c.screws.size());
  std::vector<DM> B(std::size_t(n), DM(n, n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const M6& Nb = c.tails[std::size_t(std::max(i, std::max(j, k)))];
        const V6 &si = c.screws[std::size_t(i)], &sj = c.screws[std::size_t(j)], &sk = c.screws[std::size_t(k)];
        const double t1 = sj.dot(Nb * screwBracket(si, sk)), t2 = sk.dot(Nb * screwBracket(si, sj));
        const V6 third = j <= k ? screwBracket(sk, si) : screwBracket(si, sk);
        B[std::size_t(i)](j, k) = (t1 + t2 - si.dot(Nb * third)) / 2;
      }
  return B;
}

/// C_i = +s_iᵀ(N_i + … + N_n)g.
// GF §13.2.2 line 7899 as printed (erratum 1)
DV gravityAsPrinted(const SerialDynamics<double>& r, const ChainConfiguration<double>& c) {
  DV C(r.dof());
  for (int i = 0; i < r.dof(); ++i) C(i) = c.screws[std::size_t(i)].dot(c.tails[std::size_t(i)] * r.gravityScrew());
  return C;
}

void coriolisB(Context& ctx) {
  auto g = std::mt19937_64(1326);
  double chr = 0, rn = 0, printed = 1e300;
  for (int t = 0; t < 10; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 5);
    const SerialDynamics<Q> rq = castRobot<Q>(r);
    const DV th = rjoints(g, 5, -3, 3), thd = rjoints(g, 5), z = DV::Zero(5);
    const auto B = r.coriolisTensor(th), Bp = coriolisAsPrinted(r.configuration(th));
    std::vector<DM> dA(5, DM(5, 5));
    for (int k = 0; k < 5; ++k)
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
          dA[std::size_t(k)](i, j) = dq([&](const Q& u) {
            DynVector<Q> a = castV<Q>(th);
            a(k) += u;
            return rq.massMatrix(a)(i, j);
          });
    double sc = 0;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        for (int k = 0; k < 5; ++k) {
          const double c = (dA[std::size_t(k)](i, j) + dA[std::size_t(j)](i, k) - dA[std::size_t(i)](j, k)) / 2;
          chr = std::max(chr, abs(c - B[std::size_t(i)](j, k)));
          sc = std::max(sc, abs(c));
        }
    chr /= sc;
    const DV cor = r.inverseDynamics(th, thd, z) - r.inverseDynamics(th, z, z);
    DV bc(5), bp(5);
    for (int i = 0; i < 5; ++i) {
      bc(i) = thd.dot(B[std::size_t(i)] * thd);
      bp(i) = thd.dot(Bp[std::size_t(i)] * thd);
    }
    rn = std::max(rn, maxAbs(DV(cor - bc)) / maxAbs(cor));
    printed = std::min(printed, maxAbs(DV(cor - bp)) / maxAbs(cor));
  }
  ctx.checkResidual("B_ijk (corrected) = ½(∂_kA_ij + ∂_jA_ik − ∂_iA_jk), derivatives in __float128 (10 random 5R, relative)", chr, 1e-13);
  ctx.checkResidual("B_ijk θ̇_jθ̇_k = RNEA(θ, θ̇, 0) − C (relative)", rn, 1e-13);
  ctx.checkPrintedFails("B with third terms [s_k, s_i] (j ≤ k), [s_i, s_k] (k < j) (lines 7889, 7893): B θ̇θ̇ vs RNEA", "2", printed, 1e-6);
}

void gravityC(Context& ctx) {
  auto g = std::mt19937_64(1327);
  double rn = 0, fd = 0, printed = 1e300;
  for (int t = 0; t < 20; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 6);
    const SerialDynamics<Q> rq = castRobot<Q>(r);
    const DV th = rjoints(g, 6, -3, 3), z = DV::Zero(6);
    const DV C = r.gravityTorque(th), Cp = gravityAsPrinted(r, r.configuration(th)), tau = r.inverseDynamics(th, z, z);
    rn = std::max(rn, maxAbs(DV(C - tau)) / maxAbs(tau));
    printed = std::min(printed, maxAbs(DV(Cp - tau)) / maxAbs(tau));
    for (int i = 0; i < 6; ++i)
      fd = std::max(fd, abs(dq([&](const Q& u) {
                              DynVector<Q> a = castV<Q>(th);
                              a(i) += u;
                              return rq.potentialEnergy(a);
                            }) - C(i)) / maxAbs(C));
  }
  ctx.checkResidual("C_i = −s_iᵀ(N_i + … + N_n)g = RNEA(θ, 0, 0) (20 random 6R, relative)", rn, 1e-13);
  ctx.checkResidual("C_i = ∂E_P/∂θ_i, E_P = Σm_i g z_i (differences in __float128)", fd, 1e-13);
  ctx.checkPrintedFails("C_i = +s_iᵀ(N_i + … + N_n)g (line 7899) vs RNEA", "1", printed, 1e-6);
  // g = 0 hides the error
  const SerialDynamics<double> r0 = randomRobot(g, 6, -1, 0.0);
  const DV th = rjoints(g, 6);
  ctx.checkResidual("with g = 0 the printed and corrected C agree (both 0): the sign error is invisible", maxAbs(gravityAsPrinted(r0, r0.configuration(th))), 0.0);
}

void payload(Context& ctx) {
  auto g = std::mt19937_64(1328);
  double ea = 0, eb = 0, ec = 0, printed = 1e300;
  for (int t = 0; t < 20; ++t) {
    const SerialDynamics<double> r = randomRobot(g, 6);
    const SpatialInertia<double> p = randomBody(g);
    const SerialDynamics<double> rp = r.withPayload(p);
    const DV th = rjoints(g, 6, -3, 3);
    const auto terms = r.payloadTerms(th, p);
    const DM dA = rp.massMatrix(th) - r.massMatrix(th);
    ea = std::max(ea, maxAbs(DM(dA - terms.A)) / maxAbs(dA));
    const DV dC = rp.gravityTorque(th) - r.gravityTorque(th);
    ec = std::max(ec, maxAbs(DV(dC - terms.C)) / maxAbs(dC));
    printed = std::min(printed, maxAbs(DV(dC + terms.C)) / maxAbs(dC));  // printed C^p = +s_iᵀN_p g = −(corrected)
    const auto B1 = rp.coriolisTensor(th), B0 = r.coriolisTensor(th);
    double sc = 0, e = 0;
    for (int i = 0; i < 6; ++i) {
      e = std::max(e, maxAbs(DM(B1[std::size_t(i)] - B0[std::size_t(i)] - terms.B[std::size_t(i)])));
      sc = std::max(sc, maxAbs(terms.B[std::size_t(i)]));
    }
    eb = std::max(eb, e / sc);
  }
  ctx.checkResidual("A' − A = A^p, A^p_ij = s_iᵀN_ps_j (20 random 6R + payload, relative)", ea, 1e-13);
  ctx.checkResidual("B' − B = B^p (B with N̄_x → N_p, lines 7911–7917)", eb, 1e-13);
  ctx.checkResidual("C' − C = C^p = −s_iᵀN_p g (corrected)", ec, 1e-13);
  ctx.checkPrintedFails("C^p_i = s_iᵀN_p g (line 7921)", "1", printed, 1e-6);
  ctx.note("The payload B^p (lines 7913/7917) prints the third brackets correctly; the general B (lines 7889/7893) "
           "does not (erratum 2). Line 7917 has OCR damage (`rac`, erratum 21).");
}

void rnea(Context& ctx) {
  auto g = std::mt19937_64(1329);
  double ec = 0, es = 0, egr = 0, ein = 0, epr = 0, ebig = 0, efast = 0;
  for (int t = 0; t < 30; ++t) {
    const int n = 3 + t % 5;
    const SerialDynamics<double> r = randomRobot(g, n, t % 4 == 1 ? 1 : -1);
    const DV th = rjoints(g, n, -3, 3), thd = rjoints(g, n), thdd = rjoints(g, n), z = DV::Zero(n);
    const DV tau = r.inverseDynamics(th, thd, thdd);
    ec = std::max(ec, maxAbs(DV(tau - r.inverseDynamicsClosedForm(th, thd, thdd))) / maxAbs(tau));
    es = std::max(es, maxAbs(DV(tau - r.inverseDynamicsSpatial(th, thd, thdd))) / maxAbs(tau));
    egr = std::max(egr, maxAbs(DV(r.inverseDynamics(th, z, z) - r.gravityTorque(th))) / maxAbs(r.gravityTorque(th)));
    const SerialDynamics<double> r0 = r.withGravity(0.0);
    const DV at = r.massMatrix(th) * thdd;
    ein = std::max(ein, maxAbs(DV(r0.inverseDynamics(th, z, thdd) - at)) / maxAbs(at));
    // large |θ|: θ + 2π·100 on the revolute joints gives the same τ up to the rounding of θ
    DV big = th;
    for (int i = 0; i < n; ++i)
      if (!(t % 4 == 1 && i == 1)) big(i) += 200 * pi<double>();
    ebig = std::max(ebig, maxAbs(DV(r.inverseDynamics(big, thd, thdd) - tau)) / maxAbs(tau));
    // high rates: Coriolis dominance (θ̇ × 100)
    const DV fast = 100 * thd;
    const DV tf = r.inverseDynamics(th, fast, thdd);
    efast = std::max(efast, maxAbs(DV(tf - r.inverseDynamicsClosedForm(th, fast, thdd))) / maxAbs(tf));
    (void)epr;
  }
  ctx.checkResidual("RNEA (home coordinates, box 8041–8065) = A θ̈ + Bθ̇θ̇ + C (30 random robots, 3–7 joints, prismatic)", ec, 1e-13);
  ctx.checkResidual("RNEA = spatial formula (line 7861)", es, 1e-13);
  ctx.checkResidual("θ̇ = θ̈ = 0: RNEA gives the gravity torques C", egr, 1e-13);
  ctx.checkResidual("g = 0, θ̇ = 0: RNEA gives A θ̈", ein, 1e-13);
  ctx.checkResidual("θ + 200π on revolute joints: same τ (relative; rounding of θ ≈ 630 · 1.1e-16)", ebig, 1e-12);
  ctx.checkResidual("θ̇ × 100 (Coriolis dominance): RNEA = closed form", efast, 1e-13);
  ctx.note("soma's RNEA follows the book's box literally: one exponential H_i = exp(θ_i s_i⁰) per joint, twists "
           "moved by H_i⁻¹ and co-screws by H_{i+1}⁻ᵀ in 3×3 blocks and cross products (as the book recommends), "
           "N_i⁰ applied as (I ω + mc × v, m v − mc × ω). Timing against KDL: papers/benchmarks/dynamics.md.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-13.2.1-time-derivatives", "ṡ = [z, s], 𝓜̇ = {z, 𝓜}, Ṅ = −ad(z)ᵀN − N ad(z) in the fixed frame", "GF §13.2.1", timeDerivatives);
SOMA_STUDY_DOUBLE("GF-13.2.1-single-body-eom", "N q̈ + {q̇, N q̇} = 𝒲: a free body keeps N q̇ and E_K", "GF §13.2.1", singleBody);
SOMA_STUDY_DOUBLE("GF-13.2.2-serial-link-equations", "Link equations summed and paired with s_i give τ_i (line 7843)", "GF §13.2.2", linkEquations);
SOMA_STUDY_DOUBLE("GF-13.2.2-gravity-wrench", "𝒢_i = N_i g and the spatial formula (line 7861)", "GF §13.2.2", gravityWrench);
SOMA_STUDY_DOUBLE("GF-13.2.2-link-accelerations", "q̈_i = Σθ̈_js_j + Σθ̇_kθ̇_l[s_k, s_l] (erratum 15)", "GF §13.2.2", linkAccelerations);
SOMA_STUDY_DOUBLE("GF-13.2.2-generalised-inertia-A", "A_ij = s_iᵀN̄_max(i,j)s_j: E_K, SPD, PUMA 560 at a singularity", "GF §13.2.2", generalisedInertia);
SOMA_STUDY_DOUBLE("GF-13.2.2-coriolis-B", "B_ijk = Christoffel symbols of A (erratum 2)", "GF §13.2.2", coriolisB);
SOMA_STUDY_DOUBLE("GF-13.2.2-gravity-C", "C_i = −s_iᵀN̄_i g = ∂E_P/∂θ_i (erratum 1)", "GF §13.2.2", gravityC);
SOMA_STUDY_DOUBLE("GF-13.2.3-payload", "Payload increments A^p, B^p, C^p (erratum 1)", "GF §13.2.3", payload);
SOMA_STUDY_DOUBLE("GF-13.3-recursive-newton-euler", "The recursive Newton–Euler algorithm in home coordinates", "GF §13.3", rnea);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
