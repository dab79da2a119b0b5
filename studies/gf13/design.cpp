// Studies of GF §13.6 (double, derivatives in __float128): decoupled 2R designs and the quadratic
// line complex with its Kummer surface, ignorable coordinates of 2R and 3R arms, flat coordinates
// and the Gaussian curvature of a 2R inertia metric (errata 11, 12, 18–20, 23).
#include "gf13/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

#include <Eigen/Eigenvalues>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

SerialDynamics<double> twoR(const V6& s1, const V6& s2, const SpatialInertia<double>& l1, const SpatialInertia<double>& l2,
                            double grav = 0) {
  return SerialDynamics<double>({SE3Tangent<double>(s1), SE3Tangent<double>(s2)}, {l1, l2}, grav);
}
/// Largest change of A over a grid of the given joint (others at 0), relative to max |A|.
double aVariation(const SerialDynamics<double>& r, int joint) {
  DV th = DV::Zero(r.dof());
  const DM A0 = r.massMatrix(th);
  double worst = 0;
  for (int k = 1; k <= 24; ++k) {
    th(joint) = -3 + k * 0.25;
    worst = std::max(worst, maxAbs(DM(r.massMatrix(th) - A0)));
  }
  return worst / maxAbs(A0);
}

void decoupling(Context& ctx) {
  auto g = std::mt19937_64(1360);
  // s₁ along x, s₂ along z, both through the origin (s₁ ⟂ s₂); link 2 symmetric about s₂, c.o.m. on it
  const V6 s1 = lineScrew(V3(1, 0, 0), V3::Zero()), s2 = lineScrew(V3(0, 0, 1), V3::Zero());
  const SpatialInertia<double> l1 = randomBody(g);
  const SpatialInertia<double> l2(1.7, V3(0, 0, 0.4), M3(V3(0.2, 0.2, 0.05).asDiagonal()));
  const SerialDynamics<double> r = twoR(s1, s2, l1, l2);
  const M6 N2 = l2.matrix(), Q0 = q0();
  const double c1 = s2.dot(N2 * s1), c2 = s2.dot(N2 * br(s2, s1)), c3 = s2.dot(N2 * br(s2, br(s2, s1)));
  ctx.checkResidual("conditions s₂ᵀN₂s₁ = s₂ᵀN₂[s₂, s₁] = s₂ᵀN₂[s₂, [s₂, s₁]] = 0", std::max({abs(c1), abs(c2), abs(c3)}), 1e-15);
  ctx.checkResidual("revolute s₁ needs s₂ᵀN₂Q₀N₂s₂ = 0 (quadratic line complex)", abs(s2.dot(N2 * Q0 * N2 * s2)), 1e-15);
  ctx.checkResidual("and s₁ᵀN₂[s₂, s₁] = 0 (constant A)", abs(s1.dot(N2 * br(s2, s1))), 1e-15);
  ctx.checkResidual("A(θ₂) constant over θ₂ ∈ [−3, 3] (relative)", aVariation(r, 1), 1e-15);
  double bmax = 0;
  const auto B = r.coriolisTensor(DV::Constant(2, 0.7));
  for (const DM& b : B) bmax = std::max(bmax, maxAbs(b));
  ctx.checkResidual("B = 0: with g = 0 the torques are linear in θ̈, τ = Aθ̈", bmax, 1e-15);
  const DV th = DV::Constant(2, 0.7), thd(DV::Constant(2, 3.0)), thdd = rjoints(g, 2);
  ctx.checkResidual("RNEA at θ̇ = (3, 3) rad/s equals Aθ̈ (N·m)", maxAbs(DV(r.inverseDynamics(th, thd, thdd) - r.massMatrix(th) * thdd)), 1e-13);
  // control: c.o.m. off the axis, or axes not perpendicular: A varies
  const SerialDynamics<double> off = twoR(s1, s2, l1, SpatialInertia<double>(1.7, V3(0.1, 0, 0.4), M3(V3(0.2, 0.2, 0.05).asDiagonal())));
  const SerialDynamics<double> tilt = twoR(lineScrew(V3(1, 0, 1).normalized(), V3::Zero()), s2, l1, l2);
  ctx.checkPrintedFails("control: c.o.m. 0.1 m off s₂ — A constant", "— (control)", aVariation(off, 1), 1e-6);
  ctx.note("With s₁ tilted 45° from s₂ (same symmetric link 2) A is still independent of θ₂ (variation " +
           toString(aVariation(tilt, 1), 3) + ") but no longer diagonal: A₁₂ = s₁ᵀN₂s₂ = " +
           toString(tilt.massMatrix(DV::Zero(2))(0, 1), 3) + " against " + toString(r.massMatrix(DV::Zero(2))(0, 1), 3) +
           " for s₁ ⟂ s₂ — decoupling needs the perpendicularity.");
  ctx.checkEqual("tilted s₁: A diagonal?", "no", abs(tilt.massMatrix(DV::Zero(2))(0, 1)) > 1e-3 ? "no" : "yes");
  // three joints: a diagonal A for all θ is impossible — a random 3R is far from it, and even the decoupled 2R plus
  // a third symmetric link on s₁ ⟂ s₂ ⟂ s₃ loses diagonality as θ₂ turns s₃
  const V6 s3 = lineScrew(V3(1, 0, 0), V3(0, 0, 0.8));
  const SerialDynamics<double> r3({SE3Tangent<double>(s1), SE3Tangent<double>(s2), SE3Tangent<double>(s3)},
                                  {l1, l2, SpatialInertia<double>(0.8, V3(0.3, 0, 0.8), M3(V3(0.02, 0.1, 0.1).asDiagonal()))}, 0);
  double offd = 0;
  for (int k = 0; k < 12; ++k) {
    const DV t = DV::Constant(3, 0.5 * k);
    const DM A = r3.massMatrix(t);
    offd = std::max({offd, abs(A(0, 1)), abs(A(0, 2)), abs(A(1, 2))});
  }
  ctx.checkEqual("3R extension (s₁ ⟂ s₂ ⟂ s₃, symmetric links): A off-diagonal somewhere", "yes", offd > 1e-3 ? "yes" : "no");
}

void kummer(Context& ctx) {
  auto g = std::mt19937_64(1361);
  double eq = 0, edet = 0, printedRatio = 0;
  int rankDrop = 0;
  for (int t = 0; t < 100; ++t) {
    const V3 d = rv3(g, 0.1, 1);
    const double m = uni(g, 0.5, 3);
    M6 N = M6::Zero();
    N.topLeftCorner<3, 3>() = d.asDiagonal();
    N.bottomRightCorner<3, 3>() = m * M3::Identity();
    const V3 r = rv3(g), w = unit3(g);
    const V6 s = lineScrew(w, r);
    const double x = r(0), y = r(1), z = r(2);
    const double complex = (d(0) - d(2)) * y * w(2) * w(0) + (d(1) - d(0)) * z * w(0) * w(1) + (d(2) - d(1)) * x * w(1) * w(2);
    eq = std::max(eq, abs(s.dot(N * q0() * N * s) - 2 * m * complex));
    M3 C;
    C << 0, (d(1) - d(0)) * z, (d(0) - d(2)) * y, (d(1) - d(0)) * z, 0, (d(2) - d(1)) * x, (d(0) - d(2)) * y, (d(2) - d(1)) * x, 0;
    const double printed = (d(1) - d(0)) * (d(0) - d(2)) * (d(2) - d(1)) * x * y * z;
    edet = std::max(edet, abs(C.determinant() - 2 * printed) / std::max(1e-300, abs(C.determinant())));
    printedRatio = std::max(printedRatio, abs(C.determinant() / printed));
    // on a principal plane (z = 0) the conic degenerates
    M3 C0 = C;
    C0(0, 1) = C0(1, 0) = 0;
    rankDrop += abs(C0.determinant()) < 1e-15;
  }
  ctx.checkResidual("s₂ᵀNQ₀Ns₂ = 2m[(d₁−d₃)yω_zω_x + (d₂−d₁)zω_xω_y + (d₃−d₂)xω_yω_z] (100 random)", eq, 1e-14);
  ctx.checkResidual("det of the conic = 2(d₂−d₁)(d₁−d₃)(d₃−d₂)xyz (relative)", edet, 1e-13);
  ctx.checkNear("printed Kummer determinant (d₂−d₁)(d₁−d₃)(d₃−d₂)xyz: off by the factor (erratum 23, harmless)", 2.0, printedRatio, 1e-12);
  ctx.checkEqual("conic degenerate on the principal plane z = 0 (Kummer surface = the three planes)", 100, rankDrop);
}

/// Skew-line 2R of §13.6.2: s₂ = (i, 0), s₁ = (cosφ i − sinφ j, l sinφ i + l cosφ j).
V6 skewS1(double phi, double l) {
  V6 s;
  s << std::cos(phi), -std::sin(phi), 0, l * std::sin(phi), l * std::cos(phi), 0;
  return s;
}
SpatialInertia<double> symmetricAboutX(double m, double cx, double i11, double i22) {
  return SpatialInertia<double>(m, V3(cx, 0, 0), M3(V3(i11, i22, i22).asDiagonal()));
}
double dAdTheta2(const SerialDynamics<double>& r) {
  // max over a grid of |∂A/∂θ₂| via the closed form ∂A₁₁ = −2s₁ᵀN₂[s₂, s₁], ∂A₁₂ = −s₂ᵀN₂[s₂, s₁] (2R)
  double worst = 0;
  for (int k = 0; k < 24; ++k) {
    DV th(2);
    th << 0.3, -3 + 0.25 * k;
    const auto c = r.configuration(th);
    const V6 &s1 = c.screws[0], &s2 = c.screws[1];
    const M6& N2 = c.inertias[1];
    worst = std::max({worst, abs(2 * s1.dot(N2 * br(s2, s1))), abs(s2.dot(N2 * br(s2, s1)))});
  }
  return worst;
}

void ignorable2R(Context& ctx) {
  auto g = std::mt19937_64(1362);
  const double phi = 0.7, l = 0.5;
  const V6 s1 = skewS1(phi, l), s2 = lineScrew(V3(1, 0, 0), V3::Zero());
  const SpatialInertia<double> l1 = randomBody(g), l2 = symmetricAboutX(1.3, 0.4, 0.05, 0.2);
  const SerialDynamics<double> r = twoR(s1, s2, l1, l2);
  const M6 N2 = l2.matrix();
  ctx.checkResidual("solution N₂ (rotationally symmetric about s₂): ad(s₂)ᵀN₂ + N₂ad(s₂) = 0",
                    maxAbs(DM(adm(s2).transpose() * N2 + N2 * adm(s2))), 1e-15);
  ctx.checkResidual("A independent of θ₂ over a grid (relative)", aVariation(r, 1), 1e-14);
  ctx.checkResidual("∂A₁₁/∂θ₂ = −2s₁ᵀN₂[s₂, s₁] = 0 and ∂A₁₂/∂θ₂ = −s₂ᵀN₂[s₂, s₁] = 0 on the grid", dAdTheta2(r), 1e-14);
  // the closed forms of ∂A/∂θ₂ against differences, on a generic N₂ where they do not vanish
  const SerialDynamics<double> gen = twoR(s1, s2, l1, randomBody(g));
  DV th(2);
  th << 0.3, 0.9;
  const auto c = gen.configuration(th);
  const double fd11 = dq([&](const Q& u) {
    DynVector<Q> a = castV<Q>(th);
    a(1) += u;
    return castRobot<Q>(gen).massMatrix(a)(0, 0);
  });
  ctx.checkNear("generic N₂: ∂A₁₁/∂θ₂ = −2s₁ᵀN₂[s₂, s₁] (vs differences)", fd11,
                -2 * c.screws[0].dot(c.inertias[1] * br(c.screws[1], c.screws[0])), 1e-12);
  ctx.checkPrintedFails("generic N₂: θ₂ ignorable", "— (control)", dAdTheta2(gen), 1e-6);
  // the six coefficient equations: their solution family is exactly 'symmetric about s₂, c on s₂'
  const SpatialInertia<double> breakI(1.3, V3(0.4, 0, 0), M3(V3(0.05, 0.2, 0.25).asDiagonal()));  // I₂₂ ≠ I₃₃
  const SpatialInertia<double> breakC(1.3, V3(0.4, 0.1, 0), M3(V3(0.05, 0.2, 0.2).asDiagonal()));  // c_y ≠ 0
  ctx.checkPrintedFails("I₂₂ ≠ I₃₃ (violates (I₃₃ − I₂₂)sin²φ = 0): θ₂ ignorable", "— (control)", dAdTheta2(twoR(s1, s2, l1, breakI)), 1e-6);
  ctx.checkPrintedFails("c_y ≠ 0 (violates −I₁₃cosφ sinφ + mlc_y = 0): θ₂ ignorable", "— (control)", dAdTheta2(twoR(s1, s2, l1, breakC)), 1e-6);
  // the printed general N₂ (line 8488): last row (mc_x, −mc_x, 0, …) is not symmetric with column 6
  const double m = 1.3, cx = 0.4, cy = -0.2;
  const double printedRow6[3] = {m * cx, -m * cx, 0}, column6[3] = {m * cy, -m * cx, 0};
  ctx.checkPrintedFails("general N₂ as printed is symmetric (N₆₁ = N₁₆)", "18", abs(printedRow6[0] - column6[0]), 1e-12);
  ctx.note("θ₁ is always ignorable (nothing depends on it). Line 8463 writes N_s for N₂ (erratum 19).");
}

void ignorableIIAIIB(Context& ctx) {
  auto g = std::mt19937_64(1363);
  const SpatialInertia<double> l1 = randomBody(g);
  // IIA (l = 0, intersecting axes): I off-diagonal zero, I₂₂ = I₃₃ about the c.o.m. frame at the ORIGIN; c free
  // The condition is on the inertia about the intersection point: I_origin = I_c − mC² must be diag(I₁₁, I₂₂, I₂₂).
  const double phi = 0.9;
  const V6 s1 = skewS1(phi, 0), s2 = lineScrew(V3(1, 0, 0), V3::Zero());
  const V3 c(0.2, -0.3, 0.25);
  const double m = 1.1;
  const M3 C = hat(c);
  const M3 Iorigin = V3(0.5, 0.8, 0.8).asDiagonal();  // I_c = I_origin + mC² must stay positive definite
  const SpatialInertia<double> lA(m, c, M3(Iorigin + m * C * C));  // I_c = I_origin + mC²
  ctx.checkResidual("IIA (l = 0): I₁₂ = I₁₃ = I₂₃ = 0, I₂₂ = I₃₃ about the origin, c.o.m. off s₂: θ₂ ignorable",
                    dAdTheta2(twoR(s1, s2, l1, lA)), 1e-14);
  double so3 = 0;
  const M6 N = lA.matrix(), Qm = adm(s2).transpose() * N + N * adm(s2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      V6 a = V6::Zero(), b = V6::Zero();
      a(i) = 1;
      b(j) = 1;
      so3 = std::max(so3, abs(a.dot(Qm * b)));
    }
  ctx.checkResidual("equivalently s_iᵀQs_j = 0 for all s_i, s_j ∈ so(3) (Q = ad(s₂)ᵀN₂ + N₂ad(s₂))", so3, 1e-15);
  // IIB (φ = 0, parallel axes): c.o.m. on s₂, 3×3 inertia unrestricted
  const V6 p1 = skewS1(0, 0.6);
  const SpatialInertia<double> any = randomBody(g);
  const SpatialInertia<double> lB(any.mass(), V3(0.35, 0, 0), any.inertiaAboutCentre());
  ctx.checkResidual("IIB (φ = 0): c.o.m. on s₂, arbitrary 3×3 inertia: θ₂ ignorable", dAdTheta2(twoR(p1, s2, l1, lB)), 1e-14);
  double se2 = 0;
  const M6 NB = lB.matrix(), QB = adm(s2).transpose() * NB + NB * adm(s2);
  // se(2) of the plane ⟂ s₂ (x): rotations about x, translations along y, z
  std::vector<V6> basis(3, V6::Zero());
  basis[0](0) = 1;
  basis[1](4) = 1;
  basis[2](5) = 1;
  for (const V6& a : basis)
    for (const V6& b : basis) se2 = std::max(se2, abs(a.dot(QB * b)));
  ctx.checkResidual("equivalently s_iᵀQs_j = 0 over se(2)", se2, 1e-15);
  const SpatialInertia<double> lB2(any.mass(), V3(0.35, 0.1, 0), any.inertiaAboutCentre());
  ctx.checkPrintedFails("IIB with c.o.m. 0.1 m off s₂: θ₂ ignorable", "— (control)", dAdTheta2(twoR(p1, s2, l1, lB2)), 1e-6);
  ctx.note("Lines 8518, 8530 write s_i, s_i ∈ so(3) and s_iᵀ(…)s_i for s_i, s_j (erratum 19).");
}

void ignorable3R(Context& ctx) {
  auto g = std::mt19937_64(1364);
  // s₁ ∥ s₂ (z axes through (0,0,0) and (1,0,0)); s₃ along x through (1, 0, 0.3) on the joint-2 axis
  const V6 s1 = lineScrew(V3(0, 0, 1), V3::Zero()), s2 = lineScrew(V3(0, 0, 1), V3(1, 0, 0));
  const V6 s3 = lineScrew(V3(1, 0, 0), V3(1, 0, 0.3));
  const double m2 = 2.0, m3 = 0.8, e = 0.5;
  const SpatialInertia<double> l3(m3, V3(1 + e, 0, 0.3), M3(V3(0.01, 0.08, 0.08).asDiagonal()));  // symmetric about s₃
  const SpatialInertia<double> l2b = randomBody(g);
  const SpatialInertia<double> l2(m2, V3(1 - m3 * e / m2, 0, 0.1), l2b.inertiaAboutCentre());  // composite c.o.m. on s₂
  const SerialDynamics<double> r({SE3Tangent<double>(s1), SE3Tangent<double>(s2), SE3Tangent<double>(s3)},
                                 {randomBody(g), l2, l3}, 0);
  const V3 comp = (m2 * l2.centreOfMass() + m3 * l3.centreOfMass()) / (m2 + m3);
  ctx.checkResidual("composite c.o.m. of links 2 + 3 on the joint-2 axis (distance)", V3(comp - V3(1, 0, comp(2))).norm(), 1e-15);
  ctx.checkResidual("θ₃ ignorable: A independent of θ₃ (relative)", aVariation(r, 2), 1e-14);
  ctx.checkResidual("θ₂ ignorable: A independent of θ₂ (relative)", aVariation(r, 1), 1e-14);
  double both = 0;
  const DM A0 = r.massMatrix(DV::Zero(3));
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      DV th(3);
      th << 0, -3 + 0.8 * a, -3 + 0.8 * b;
      both = std::max(both, maxAbs(DM(r.massMatrix(th) - A0)));
    }
  ctx.checkResidual("A constant over an 8 × 8 (θ₂, θ₃) grid (relative)", both / maxAbs(A0), 1e-14);
  const SpatialInertia<double> l2off(m2, V3(1 - m3 * e / m2 + 0.1, 0, 0.1), l2b.inertiaAboutCentre());
  const SerialDynamics<double> bad({SE3Tangent<double>(s1), SE3Tangent<double>(s2), SE3Tangent<double>(s3)},
                                   {randomBody(g), l2off, l3}, 0);
  ctx.checkPrintedFails("control: composite c.o.m. 0.1 m off the joint-2 axis: θ₂ ignorable", "— (control)", aVariation(bad, 1), 1e-6);
  // the brackets of the skew case: [s₂, s] = (0, I₁₁ sinφ k), [s₂, [s₂, s]] = (0, −I₁₁ sinφ (sinφ i + cosφ j))
  const double phi = 0.8, l = 0.4, I11 = 0.07;
  const V6 t2 = skewS1(phi, l);
  const M6 N3 = symmetricAboutX(1.0, 0.3, I11, 0.2).matrix();
  const V6 s = q0() * N3 * lineScrew(V3(1, 0, 0), V3::Zero());
  V6 w1, w2;
  w1 << 0, 0, 0, 0, 0, I11 * std::sin(phi);
  w2 << 0, 0, 0, -I11 * std::sin(phi) * std::sin(phi), -I11 * std::sin(phi) * std::cos(phi), 0;
  ctx.checkResidual("[s₂, s] = (0, I₁₁ sinφ k), s = Q₀N₃s₃", (br(t2, s) - w1).norm(), 1e-16);
  ctx.checkResidual("[s₂, [s₂, s]] = (0, −I₁₁ sinφ (sinφ i + cosφ j))", (br(t2, br(t2, s)) - w2).norm(), 1e-16);
}

void flat(Context& ctx) {
  auto g = std::mt19937_64(1365);
  // decoupled 2R of GF-13.6.1: A constant, φ = A^{1/2}θ, K = A^{1/2}, φ̈ = K⁻ᵀτ
  const V6 s1 = lineScrew(V3(1, 0, 0), V3::Zero()), s2 = lineScrew(V3(0, 0, 1), V3::Zero());
  const SerialDynamics<double> r = twoR(s1, s2, randomBody(g), SpatialInertia<double>(1.7, V3(0, 0, 0.4), M3(V3(0.2, 0.2, 0.05).asDiagonal())));
  const DM A = r.massMatrix(DV::Zero(2));
  const Eigen::SelfAdjointEigenSolver<DM> es(A);
  const DM K = es.operatorSqrt();
  double worst = 0;
  for (int t = 0; t < 20; ++t) {
    const DV th = rjoints(g, 2, -3, 3), thd = rjoints(g, 2, -3, 3), tau = rjoints(g, 2, -2, 2);
    const DV phidd = K * r.forwardDynamics(th, thd, tau);
    worst = std::max(worst, maxAbs(DV(phidd - K.transpose().partialPivLu().solve(tau))));
  }
  ctx.checkResidual("decoupled 2R, φ = A^{1/2}θ: φ̈ = (Kᵀ)⁻¹τ at any θ, θ̇ (20 random states)", worst, 1e-13);
  // B_ijk = K_li ∂_kK_lj for A = KᵀK, K = ∂φ/∂θ, φ nonlinear (3 dof), derivatives in __float128
  auto phi = [](const DynVector<Q>& t) {
    DynVector<Q> f(3);
    f(0) = t(0) + Q(0.3) * sinq(t(1));
    f(1) = t(1) + Q(0.2) * t(0) * t(2);
    f(2) = t(2) + Q(0.25) * cosq(t(0));
    return f;
  };
  const DynVector<Q> t0 = castV<Q>(rjoints(g, 3));
  auto Kat = [&](const DynVector<Q>& t) {
    DynMatrix<Q> Km(3, 3);
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l)
        Km(l, j) = diff8<Q>([&](const Q& u) {
          DynVector<Q> a = t;
          a(j) += u;
          return phi(a)(l);
        }, Q(1) / Q(256));
    return Km;
  };
  auto Aat = [&](const DynVector<Q>& t) {
    const DynMatrix<Q> Km = Kat(t);
    return DynMatrix<Q>(Km.transpose() * Km);
  };
  std::vector<DynMatrix<Q>> dA, dK;
  for (int k = 0; k < 3; ++k) {
    DynMatrix<Q> a(3, 3), kk(3, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        a(i, j) = diff8<Q>([&](const Q& u) {
          DynVector<Q> x = t0;
          x(k) += u;
          return Aat(x)(i, j);
        }, Q(1) / Q(64));
        kk(i, j) = diff8<Q>([&](const Q& u) {
          DynVector<Q> x = t0;
          x(k) += u;
          return Kat(x)(i, j);
        }, Q(1) / Q(64));
      }
    dA.push_back(a);
    dK.push_back(kk);
  }
  const DynMatrix<Q> K0 = Kat(t0);
  double e = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Q chr = (dA[std::size_t(k)](i, j) + dA[std::size_t(j)](i, k) - dA[std::size_t(i)](j, k)) / 2;
        Q rhs = 0;
        for (int l = 0; l < 3; ++l) rhs += K0(l, i) * dK[std::size_t(k)](l, j);
        e = std::max(e, double(fabsq(chr - rhs)));
      }
  ctx.checkResidual("½(∂_kA_ij + ∂_jA_ik − ∂_iA_jk) = K_li ∂_kK_lj for A = KᵀK, K = ∂φ/∂θ (nested differences in __float128)", e, 1e-12);
  ctx.note("Lines 8590, 8610, 8626 print K_ij = ∂φ_i/∂θ_i, π_i = K_jiφ̇_i, B_iikθ̇_iθ̇_k = K̇_iiσ_i (erratum 20); the "
           "identities checked use ∂φ_i/∂θ_j and B_jikθ̇_jθ̇_k = K̇_jiσ_j.");
}

/// Brioschi curvature of a metric (E, F, G) depending on v = θ₂ only (u = θ₁ derivatives zero).
double brioschi(double E, double F, double G, double Ev, double Fv, double Gv, double Evv) {
  M3 M1, M2;
  M1 << -0.5 * Evv, 0, -0.5 * Ev, Fv, E, F, 0.5 * Gv, F, G;
  M2 << 0, 0.5 * Ev, 0, 0.5 * Ev, E, F, 0, F, G;
  const double den = E * G - F * F;
  return (M1.determinant() - M2.determinant()) / (den * den);
}

/// The 2R inertia metric E = A₁₁, F = A₁₂, G = A₂₂ at θ₂ and its θ₂-derivatives (A does not
/// depend on θ₁), Δ = EG − F² with Δ', Δ'': 8th-order differences in __float128.
struct MetricJet {
  double e, f, g, ev, fv, gv, evv, d, dp, dpp;
};
MetricJet metricJet(const SerialDynamics<Q>& rq, double th2) {
  auto Aq = [&](const Q& u) {
    DynVector<Q> a(2);
    a << Q(0), Q(th2) + u;
    return rq.massMatrix(a);
  };
  auto d2 = [&](auto f) {
    return double(diff8<Q>([&](const Q& u) { return diff8<Q>([&](const Q& v) { return f(u + v); }, Q(1) / Q(256)); }, Q(1) / Q(256)));
  };
  auto E = [&](const Q& u) { return Aq(u)(0, 0); };
  auto Det = [&](const Q& u) {
    const DynMatrix<Q> A = Aq(u);
    return A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1);
  };
  const DynMatrix<Q> A0 = Aq(Q(0));
  MetricJet j{};
  j.e = double(A0(0, 0));
  j.f = double(A0(0, 1));
  j.g = double(A0(1, 1));
  j.ev = dq(E);
  j.fv = dq([&](const Q& u) { return Aq(u)(0, 1); });
  j.gv = dq([&](const Q& u) { return Aq(u)(1, 1); });
  j.evv = d2(E);
  j.d = j.e * j.g - j.f * j.f;
  j.dp = dq(Det);
  j.dpp = d2(Det);
  return j;
}
double brioschi(const MetricJet& j) { return brioschi(j.e, j.f, j.g, j.ev, j.fv, j.gv, j.evv); }

/// The random 2R of GF-13.6.3 (no gravity).
SerialDynamics<double> curvature2R() {
  auto g = std::mt19937_64(1366);
  const V3 u1 = unit3(g), p1 = rv3(g), u2 = unit3(g), p2 = rv3(g);  // named: a fixed draw order
  const V6 s1 = lineScrew(u1, p1);
  const V6 s2 = lineScrew(u2, p2);
  const SpatialInertia<double> l1 = randomBody(g);
  const SpatialInertia<double> l2 = randomBody(g);
  return twoR(s1, s2, l1, l2);
}

void gaussian(Context& ctx) {
  const SerialDynamics<double> r = curvature2R();
  const SerialDynamics<Q> rq = castRobot<Q>(r);
  const double t2 = 0.6;
  const MetricJet j = metricJet(rq, t2);
  const double gg = j.g, Ev = j.ev, Evv = j.evv, D = j.d, Dp = j.dp, Dpp = j.dpp;
  const double Kb = brioschi(j);
  ctx.checkResidual("A₂₂ = s₂ᵀN₂s₂ independent of θ₂", abs(j.gv), 1e-14);
  // Δ', Δ'' from the book's screw formulas at the current configuration
  DV th(2);
  th << 0, t2;
  const auto c = r.configuration(th);
  const V6 &s1 = c.screws[0], &s2 = c.screws[1];
  const M6& N2 = c.inertias[1];
  const double a22 = s2.dot(N2 * s2), a12 = s1.dot(N2 * s2);
  const double DpBook = 2 * s1.dot(N2 * br(s1, s2)) * a22 - 2 * s2.dot(N2 * br(s1, s2)) * a12;
  auto DppBook = [&](double k) {
    return k * s1.dot(N2 * br(s2, br(s2, s1))) * a22 + k * br(s2, s1).dot(N2 * br(s2, s1)) * a22 -
           2 * s2.dot(N2 * br(s2, br(s2, s1))) * a12 - 2 * std::pow(s2.dot(N2 * br(s1, s2)), 2);
  };
  ctx.checkNear("Δ' = 2(s₁ᵀN₂[s₁,s₂])(s₂ᵀN₂s₂) − 2(s₂ᵀN₂[s₁,s₂])(s₁ᵀN₂s₂) vs differences", Dp, DpBook, 1e-12 * std::max(1.0, abs(Dp)));
  ctx.checkNear("Δ'' with coefficients 2, 2 (corrected, erratum 12) vs differences", Dpp, DppBook(2), 1e-11 * std::max(1.0, abs(Dpp)));
  ctx.checkPrintedFails("Δ'' with coefficients 4, 4 (line 8691)", "12", abs(DppBook(4) - Dpp) / std::max(1.0, abs(Dpp)), 1e-6);
  const double Kc = (Ev * Dp - 2 * D * Evv) / (4 * D * D);
  const double Kp = gg / 4 * (2 * D * Dpp - 3 * Dp * Dp) / (D * D);
  ctx.checkNear("K(A) = (A₁₁'Δ' − 2ΔA₁₁'')/(4Δ²) (corrected) = Brioschi curvature of A", Kb, Kc, 1e-10 * std::max(1.0, abs(Kb)));
  ctx.checkPrintedFails("K = (A₂₂/4)(2ΔΔ'' − 3Δ'²)/Δ² (line 8677) vs Brioschi K(A)", "11", abs(Kp - Kb) / std::max(1e-12, abs(Kb)), 1e-6);
  // the printed K is the curvature of A⁻¹
  auto Ai = [&](const Q& u) {
    DynVector<Q> a(2);
    a << Q(0), Q(t2) + u;
    return DynMatrix<Q>(rq.massMatrix(a).inverse());
  };
  auto d1 = [&](auto fn) { return dq(fn); };
  auto d2 = [&](auto fn) {
    return double(diff8<Q>([&](const Q& u) { return diff8<Q>([&](const Q& v) { return fn(u + v); }, Q(1) / Q(256)); }, Q(1) / Q(256)));
  };
  const DynMatrix<Q> B0 = Ai(Q(0));
  const double Kinv = brioschi(double(B0(0, 0)), double(B0(0, 1)), double(B0(1, 1)), d1([&](const Q& u) { return Ai(u)(0, 0); }),
                               d1([&](const Q& u) { return Ai(u)(0, 1); }), d1([&](const Q& u) { return Ai(u)(1, 1); }),
                               d2([&](const Q& u) { return Ai(u)(0, 0); }));
  ctx.checkNear("the printed K equals the Brioschi curvature of A⁻¹ (μ₁, μ₂ orthonormal for A⁻¹)", Kinv, Kp, 1e-9 * std::max(1.0, abs(Kinv)));
  if (ctx.makeFigures()) {
    // K(θ₂) over a turn: Brioschi K(A), the corrected closed form, the printed formula (= K(A⁻¹))
    std::vector<double> ts, kb, kc, kp;
    for (int k = 0; k <= 72; ++k) {
      const double th2 = -pi<double>() + 2 * pi<double>() * k / 72;
      const MetricJet m = metricJet(rq, th2);
      ts.push_back(th2);
      kb.push_back(brioschi(m));
      kc.push_back((m.ev * m.dp - 2 * m.d * m.evv) / (4 * m.d * m.d));
      kp.push_back(m.g / 4 * (2 * m.d * m.dpp - 3 * m.dp * m.dp) / (m.d * m.d));
    }
    namespace rd = soma::render;
    rd::Plot pl;
    pl.title = "Gaussian curvature of a random 2R inertia metric";
    pl.x.label = "θ₂ [rad]";
    pl.y.label = "K";
    pl.legend = rd::LegendCorner::TopLeft;
    pl.add("Brioschi K(A) (from differences of A)", ts, kb, rd::Color::hex(0x0072B2));
    auto& corr = pl.add("corrected (A₁₁'Δ' − 2ΔA₁₁'')/(4Δ²)", ts, kc, rd::Color::hex(0x009E73));
    corr.line = false;
    corr.markers = true;
    pl.add("printed (A₂₂/4)(2ΔΔ'' − 3Δ'²)/Δ² (erratum 11)", ts, kp, rd::Color::hex(0xD55E00)).dashed = true;
    const std::string file = "GF-13.6.3-gaussian-curvature.png";
    rd::renderPlotPngAndSvg(pl, ctx.figurePath(file));
    ctx.figure(file, "Gaussian curvature K(θ₂) of the inertia metric of a random 2R (independent of θ₁): the "
                     "Brioschi formula on A and the corrected closed form coincide; the printed formula is the "
                     "curvature of A⁻¹ (erratum 11).");
  }
  ctx.note("Random 2R at θ₂ = 0.6: K(A) = " + toString(Kb, 6) + " (Brioschi) = " + toString(Kc, 6) + " (corrected formula); "
           "printed formula " + toString(Kp, 6) + "; Δ'' = " + toString(Dpp, 6) + " (differences), printed " + toString(DppBook(4), 6) + ".");
}


/// ∂A/∂θ_l (l = 0, 1) by the five-point stencil, h = 1e-3: truncation h⁴|A⁽⁵⁾|/30 ~ 1e-14,
/// rounding ~ ε|A|/h ~ 1e-13 — independent of the recursive dynamics that rk4Step uses.
std::array<DM, 2> massMatrixGradient(const SerialDynamics<double>& r, const DV& th) {
  constexpr double h = 1e-3;
  std::array<DM, 2> dA;
  for (int l = 0; l < 2; ++l) {
    auto at = [&](double t) {
      DV a = th;
      a(l) += t;
      return r.massMatrix(a);
    };
    dA[std::size_t(l)] = (8 * (at(h) - at(-h)) - (at(2 * h) - at(-2 * h))) / (12 * h);
  }
  return dA;
}
/// θ̈^i = −Γ^i_jk θ̇^jθ̇^k with Γ^i_jk = ½A^{il}(∂_jA_lk + ∂_kA_lj − ∂_lA_jk): the geodesic equation
/// of the kinetic-energy metric written from A alone. GF §13.4.2 (B = Christoffel symbols of A)
DV christoffelAcceleration(const SerialDynamics<double>& r, const DV& th, const DV& v) {
  const std::array<DM, 2> dA = massMatrixGradient(r, th);
  DV lower = DV::Zero(2);  // Γ_ljk θ̇^jθ̇^k
  for (int l = 0; l < 2; ++l)
    for (int jj = 0; jj < 2; ++jj)
      for (int k = 0; k < 2; ++k)
        lower(l) += 0.5 * (dA[std::size_t(jj)](l, k) + dA[std::size_t(k)](l, jj) - dA[std::size_t(l)](jj, k)) * v(jj) * v(k);
  return -r.massMatrix(th).ldlt().solve(lower);
}
struct Geodesic {
  std::vector<DV> theta, thetaDot;
};
/// n RK4 steps of length h on the Christoffel form (theta, thetaDot sampled at every step).
Geodesic christoffelGeodesic(const SerialDynamics<double>& r, DV th, DV v, double h, int n) {
  Geodesic out{{th}, {v}};
  for (int k = 0; k < n; ++k) {
    const DV a1 = christoffelAcceleration(r, th, v);
    const DV a2 = christoffelAcceleration(r, th + 0.5 * h * v, v + 0.5 * h * a1);
    const DV a3 = christoffelAcceleration(r, th + 0.5 * h * (v + 0.5 * h * a1), v + 0.5 * h * a2);
    const DV a4 = christoffelAcceleration(r, th + h * (v + 0.5 * h * a2), v + h * a3);
    th += h * v + h * h / 6 * (a1 + a2 + a3);
    v += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    out.theta.push_back(th);
    out.thetaDot.push_back(v);
  }
  return out;
}
/// Free motion without gravity (τ = 0) by the library's RK4 on the recursive dynamics.
Geodesic freeMotion(const SerialDynamics<double>& r, const DV& th, const DV& v, double h, int n) {
  JointState<double> y{th, v};
  Geodesic out{{th}, {v}};
  for (int k = 0; k < n; ++k) {
    y = rk4Step<double>(r, y, h, DV::Zero(2));
    out.theta.push_back(y.theta);
    out.thetaDot.push_back(y.thetaDot);
  }
  return out;
}

// Derived figure (GF §13.4.2, §13.6.3): free motion of the 2R of GF-13.6.3 without gravity runs on
// the geodesics of the kinetic-energy metric A; they bend where K ≠ 0 and spread by the Jacobi
// equation J'' + KJ = 0.
void geodesics2R(Context& ctx) {
  const SerialDynamics<double> r = curvature2R();
  const SerialDynamics<Q> rq = castRobot<Q>(r);
  DV th0(2);
  th0 << 0, 0.6;
  const Eigen::LLT<DM> chol(r.massMatrix(th0));
  const DM Lt = chol.matrixU();  // A = UᵀU: θ̇ = U⁻¹u has θ̇ᵀAθ̇ = |u|²
  auto direction = [&](double phi) { return DV(Lt.triangularView<Eigen::Upper>().solve(Eigen::Vector2d(std::cos(phi), std::sin(phi)))); };
  constexpr double T = 1.5;
  constexpr int n = 300;
  constexpr double h = T / n;
  // 1. two formulations of the same motion agree: recursive dynamics vs Christoffel symbols of A
  constexpr int fan = 16;
  std::vector<Geodesic> free, chr;
  double agree = 0, drift = 0;
  for (int k = 0; k < fan; ++k) {
    const DV v0 = direction(2 * pi<double>() * k / fan);
    free.push_back(freeMotion(r, th0, v0, h, n));
    chr.push_back(christoffelGeodesic(r, th0, v0, h, n));
    for (int s = 0; s <= n; ++s) {
      agree = std::max(agree, maxAbs(DV(free.back().theta[std::size_t(s)] - chr.back().theta[std::size_t(s)])));
      const DV& th = free.back().theta[std::size_t(s)];
      const DV& v = free.back().thetaDot[std::size_t(s)];
      drift = std::max(drift, abs(v.dot(r.massMatrix(th) * v) - 1));
    }
  }
  ctx.checkResidual("free motion (RNE, rk4Step) = geodesic of A (Γ from ∂A, own RK4): max |Δθ| over 16 directions, 1.5 s", agree, 1e-10);
  ctx.checkResidual("speed θ̇ᵀAθ̇ = 1 conserved along the geodesics (RK4, h = 5 ms)", drift, 1e-10);
  // RK4 is fourth order: the speed drift falls by ~16 when h halves
  double drift2 = 0;
  {
    const Geodesic fine = freeMotion(r, th0, direction(0.3), h / 2, 2 * n), coarse = freeMotion(r, th0, direction(0.3), h, n);
    auto worst = [&](const Geodesic& gd) {
      double w = 0;
      for (std::size_t s = 0; s < gd.theta.size(); ++s)
        w = std::max(w, abs(gd.thetaDot[s].dot(r.massMatrix(gd.theta[s]) * gd.thetaDot[s]) - 1));
      return w;
    };
    drift = worst(coarse);
    drift2 = worst(fine);
  }
  ctx.checkNear("RK4 order of the speed drift: log₂(drift(h)/drift(h/2)) = 4", 4.0, std::log2(drift / drift2), 0.5);
  // 2. Jacobi: geodesics leaving at angle δ separate as δJ(t), J'' = −K(θ₂(t))J, J(0) = 0, J'(0) = 1
  constexpr double delta = 1e-5, phi0 = 0.3;
  constexpr int nj = 60;
  constexpr double hj = T / nj;
  const Geodesic base = freeMotion(r, th0, direction(phi0), hj, nj), side = freeMotion(r, th0, direction(phi0 + delta), hj, nj);
  // J along the base geodesic by RK4 with K at the step's ends and midpoint (θ₂ of the base at
  // t + h/2 from a half step of the same integrator)
  double J = 0, Jd = 1, worstJ = 0, worstFlat = 0;
  for (int k = 0; k < nj; ++k) {
    const double Ka = brioschi(metricJet(rq, base.theta[std::size_t(k)](1)));
    const JointState<double> half = rk4Step<double>(r, {base.theta[std::size_t(k)], base.thetaDot[std::size_t(k)]}, hj / 2, DV::Zero(2));
    const double Km = brioschi(metricJet(rq, half.theta(1)));
    const double Kb = brioschi(metricJet(rq, base.theta[std::size_t(k) + 1](1)));
    const double k1 = Jd, l1 = -Ka * J;
    const double k2 = Jd + 0.5 * hj * l1, l2 = -Km * (J + 0.5 * hj * k1);
    const double k3 = Jd + 0.5 * hj * l2, l3 = -Km * (J + 0.5 * hj * k2);
    const double k4 = Jd + hj * l3, l4 = -Kb * (J + hj * k3);
    J += hj / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    Jd += hj / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
    const DV d = side.theta[std::size_t(k) + 1] - base.theta[std::size_t(k) + 1];
    const DV mid = 0.5 * (side.theta[std::size_t(k) + 1] + base.theta[std::size_t(k) + 1]);
    const double sep = std::sqrt(d.dot(r.massMatrix(mid) * d)) / delta;
    worstJ = std::max(worstJ, abs(sep - J) / J);
    worstFlat = std::max(worstFlat, abs(sep - hj * (k + 1)) / (hj * (k + 1)));
  }
  // relative tolerance δ: the separation is δJ + O(δ²)
  ctx.checkResidual("separation of geodesics δ = 1e-5 apart = δJ(t), J'' + K J = 0 (relative, 1.5 s)", worstJ, delta);
  ctx.record("control: the flat prediction J = t (K = 0) misses the separation by more than 1 %", "> 0.01", toString(worstFlat, 3),
             worstFlat, 1e-2, worstFlat > 1e-2);
  ctx.note("2R of GF-13.6.3 from θ = (0, 0.6) at unit speed θ̇ᵀAθ̇ = 1: RNE vs Christoffel " + toString(agree, 2) + " rad; speed drift " +
           toString(drift, 2) + " (h = 5 ms), " + toString(drift2, 2) + " (h/2); Jacobi field vs separation " + toString(worstJ, 2) +
           " relative, the flat J = t is off by " + toString(worstFlat, 2) + ".");
  if (!ctx.makeFigures()) return;
  namespace rd = soma::render;
  rd::Plot pl;
  pl.title = "Geodesics of a 2R's kinetic-energy metric (free motion, no gravity)";
  pl.x.label = "θ₁ [rad]";
  pl.y.label = "θ₂ [rad]";
  pl.equalAspect = true;
  pl.y.max = 2.1;  // room for the legend above the fan
  for (int k = 0; k < fan; ++k) {
    std::vector<double> x, y, lx, ly;
    for (const DV& t : free[std::size_t(k)].theta) {
      x.push_back(t(0));
      y.push_back(t(1));
    }
    const DV v0 = free[std::size_t(k)].thetaDot.front();
    for (int s = 0; s <= 10; ++s) {
      lx.push_back(th0(0) + T * s / 10 * v0(0));
      ly.push_back(th0(1) + T * s / 10 * v0(1));
    }
    pl.add(k == 0 ? "straight lines θ₀ + tθ̇₀ (flat metric)" : "", lx, ly, rd::Color::hex(0xAAAAAA)).dashed = true;
    pl.add(k == 0 ? "geodesics of A, unit speed, 1.5 s" : "", x, y, rd::Color::hex(0x0072B2));
  }
  auto& st = pl.add("start θ₀ = (0, 0.6)", {th0(0)}, {th0(1)}, rd::Color::hex(0xD55E00));
  st.line = false;
  st.markers = true;
  const std::string file = "GF-13.6.3-geodesics-2R.png";
  rd::renderPlotPngAndSvg(pl, ctx.figurePath(file));
  ctx.figure(file, "Free motions of the random 2R of GF-13.6.3 without gravity, from one posture in 16 directions at unit "
                   "kinetic speed: geodesics of the inertia metric A (blue), which bend away from the straight lines of "
                   "the joint coordinates (dashed); their spreading follows the Jacobi equation with the Gaussian curvature K(θ₂).");
}
}  // namespace

SOMA_STUDY_DOUBLE("GF-13.6.1-decoupling-2R", "A decoupled 2R: constant diagonal A, B = 0; impossible for three joints", "GF §13.6.1", decoupling);
SOMA_STUDY_DOUBLE("GF-13.6.1-quadratic-complex-kummer", "The quadratic line complex of revolute s₁ and its Kummer surface (erratum 23)", "GF §13.6.1", kummer);
SOMA_STUDY_DOUBLE("GF-13.6.2-ignorable-2R-IA", "θ₂ ignorable for skew axes: link 2 symmetric about s₂ (erratum 18)", "GF §13.6.2", ignorable2R);
SOMA_STUDY_DOUBLE("GF-13.6.2-ignorable-IIA-IIB", "θ₂ ignorable for intersecting (IIA) and parallel (IIB) axes", "GF §13.6.2", ignorableIIAIIB);
SOMA_STUDY_DOUBLE("GF-13.6.2-ignorable-3R", "θ₂ and θ₃ ignorable in a 3R: s₁ ∥ s₂, composite c.o.m. on s₂", "GF §13.6.2", ignorable3R);
SOMA_STUDY_DOUBLE("GF-13.6.3-flat-coordinates", "Flat coordinates φ(θ): φ̈ = K⁻ᵀτ; B = K_li∂_kK_lj (erratum 20)", "GF §13.6.3", flat);
SOMA_STUDY_DOUBLE("GF-13.6.3-gaussian-curvature-2R", "Gaussian curvature of a 2R inertia metric (errata 11, 12)", "GF §13.6.3", gaussian);
SOMA_STUDY_DOUBLE("GF-13.6.3-geodesics-2R", "Derived figure: free motion = geodesics of A; Jacobi spreading by K", "GF §13.4.2, §13.6.3", geodesics2R);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
