// Studies of GF §15.4 (double): hybrid force/position control — the Lipkin–Duffy frame dependence of a
// selection matrix, the dual-basis projectors AB and XY (and their dependence on the complement: a
// finding, E15.15), the peg in a hole (errata E15.7, E15.8), the second fundamental form of a pinned
// body, the N₆-orthonormal projectors, the multipliers (erratum E15.9), the hybrid law's invariance
// (errata E15.9, E15.10), and the block diagrams of Figs. 15.1 and 15.2.
#include "gf15/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

namespace soma::studies::gf15::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

DM pegFreedoms() {
  DM Z = DM::Zero(6, 2);
  Z(2, 0) = Z(5, 1) = 1;  // z₁ = (k, 0), z₂ = (0, k)
  return Z;
}
DM pegComplement() {
  DM S = DM::Zero(6, 4);
  S(0, 0) = S(1, 1) = S(3, 2) = S(4, 3) = 1;  // (i,0), (j,0), (0,i), (0,j)
  return S;
}
M6 shiftX(double r) { return SE3<double>(SO3<double>::Identity(), V3(r, 0, 0)).adjoint(); }

void natural(Context& ctx) {
  // Raibert–Craig: one selection matrix S = diag(0,0,1,0,0,1) used for twists AND (via I − S) wrenches.
  M6 Ssel = M6::Zero();
  Ssel(2, 2) = Ssel(5, 5) = 1;
  const M6 H = shiftX(0.4);  // the same peg described from an origin moved 0.4 along x
  const M6 Hi = H.inverse();
  const V6 err(0.01, -0.02, 0.03, 0.002, 0.001, -0.004);  // a twist error in frame 1
  // the action of S in frame 2, mapped back to frame 1, vs the action in frame 1
  const V6 act1 = Ssel * err, act2back = H * (Ssel * (Hi * err));
  ctx.checkPrintedFails("selection matrix S used in two frames (origin shifted 0.4 along x): |S e − H S H⁻¹e|", "— Lipkin & Duffy", (act1 - act2back).cwiseAbs().maxCoeff(), 1e-9);
  // the invariant operator AB: built in frame 2 from the transformed screws, it is H⁻¹(AB)H
  const HybridProjectors<double> p1 = dualBasisProjectors<double>(pegFreedoms(), pegComplement());
  const HybridProjectors<double> p2 = dualBasisProjectors<double>(DM(Hi * pegFreedoms()), DM(Hi * pegComplement()));
  ctx.checkResidual("AB built in frame 2 acts like AB in frame 1: |AB e − H (AB)₂ H⁻¹ e|", (p1.motionProjector() * err - H * (p2.motionProjector() * (Hi * err))).cwiseAbs().maxCoeff(), 1e-15);
  // constraint wrenches do no work on freedoms, in any frame
  ctx.checkResidual("|Xᵀ A| in frame 2 (reciprocity of constraint wrenches and freedoms)", maxAbs(DM(p2.X.transpose() * p2.A)), 1e-15);
  ctx.note("Natural constraints (the hole's walls) supply the wrenches X; artificial ones are imposed by the controller. The control "
           "actions through AB and XY do not interfere because XᵀA = 0.");
}

void dualBases(Context& ctx) {
  auto g = std::mt19937_64(1543);
  double idem = 0, dual = 0, comp = 0;
  for (int t = 0; t < 20; ++t) {
    const int n = 1 + t % 5;
    DM Z(6, n), S(6, 6 - n);
    for (int i = 0; i < n; ++i) Z.col(i) = rv6(g);
    for (int i = 0; i < 6 - n; ++i) S.col(i) = rv6(g);
    const HybridProjectors<double> p = dualBasisProjectors<double>(Z, S);
    const M6 AB = p.motionProjector(), XY = p.wrenchProjector();
    // relative to the size of the operators (random bases can be ill-conditioned: ‖AB‖ up to ~1e2)
    const double sc = 1 + maxAbs(DM(AB)) + maxAbs(DM(XY));
    idem = std::max({idem, maxAbs(DM(AB * AB - AB)) / (sc * sc), maxAbs(DM(XY * XY - XY)) / (sc * sc)});
    dual = std::max({dual, maxAbs(DM(p.B * p.A - DM::Identity(n, n))) / sc, maxAbs(DM(p.Y * p.X - DM::Identity(6 - n, 6 - n))) / sc,
                     maxAbs(DM(p.X.transpose() * p.A)) / sc});
    comp = std::max(comp, maxAbs(DM(AB + XY.transpose() - M6::Identity())) / sc);
  }
  ctx.checkResidual("AB, XY idempotent (20 random freedom systems, n = 1…5; relative to (1 + ‖AB‖ + ‖XY‖)²)", idem, 1e-13);
  ctx.checkResidual("BA = I_n, YX = I_{6−n}, XᵀA = 0 (relative)", dual, 1e-13);
  ctx.checkResidual("AB + (XY)ᵀ = I (complementary under the pairing, relative)", comp, 1e-13);
  // finding E15.15: the projection DOES depend on the complement S' (the book says it does not)
  DM Z(6, 2), S1(6, 4);
  for (int i = 0; i < 2; ++i) Z.col(i) = rv6(g);
  for (int i = 0; i < 4; ++i) S1.col(i) = rv6(g);
  DM S2 = S1;
  S2.col(0) += 0.5 * Z.col(0);  // "add elements of S to the basis elements of S'"
  const HybridProjectors<double> pa = dualBasisProjectors<double>(Z, S1), pb = dualBasisProjectors<double>(Z, S2);
  ctx.checkPrintedFails("\"the lack of uniqueness will not affect the projection\": |AB(S'₁) − AB(S'₂)| with S'₂ = S'₁ + element of S", "E15.15 (finding)",
              maxAbs(DM(pa.motionProjector() - pb.motionProjector())), 1e-9);
  ctx.checkResidual("both are projectors onto the same S (image unchanged): |AB₂·AB₁ − AB₁|", maxAbs(DM(pb.motionProjector() * pa.motionProjector() - pa.motionProjector())), 1e-11);
  ctx.note("AB projects onto S along S' (its kernel); a different complement gives a different projector with the same image. "
           "A canonical complement needs extra structure — exactly the N₆ metric of §15.4.4 (GF-15.4.4-N6-orthonormal-projections).");
}

void peg(Context& ctx) {
  const HybridProjectors<double> p = dualBasisProjectors<double>(pegFreedoms(), pegComplement());
  DM B(2, 6);
  B << 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1;
  ctx.checkResidual("B (rows W₁ᵀ, W₂ᵀ) as printed at line 9918", maxAbs(DM(p.B - B)), 0.0);
  ctx.checkResidual("A = Bᵀ", maxAbs(DM(p.A - B.transpose())), 0.0);
  DM Y = DM::Zero(4, 6);
  Y(0, 0) = Y(1, 1) = Y(2, 3) = Y(3, 4) = 1;
  ctx.checkResidual("Y (rows e₁, e₂, e₄, e₅) and X = Yᵀ as printed", maxAbs(DM(p.Y - Y)) + maxAbs(DM(p.X - Y.transpose())), 0.0);
  M6 AB = M6::Zero(), XY = M6::Zero();
  AB(2, 2) = AB(5, 5) = 1;
  XY(0, 0) = XY(1, 1) = XY(3, 3) = XY(4, 4) = 1;
  ctx.checkResidual("AB = diag(0,0,1,0,0,1) (the display dropped at line 9932, E15.7)", maxAbs(DM(p.motionProjector() - AB)), 0.0);
  ctx.checkResidual("XY = diag(1,1,0,1,1,0) (dropped at line 9942, E15.7): the Raibert–Craig I − S", maxAbs(DM(p.wrenchProjector() - XY)), 0.0);
  ctx.note("E15.7 is an OCR loss (the displays are missing from the seed, not wrong in the book): the reconstructed matrices "
           "are the ones computed here; there is no printed matrix to fail.");
}

void transformation(Context& ctx) {
  const double r = 0.7;
  const M6 H = shiftX(r);
  M6 Hbook = M6::Identity();
  Hbook(4, 2) = -r;
  Hbook(5, 1) = r;
  ctx.checkResidual("H = Ad(origin moved r along x) is the book's H (H₅₃ = −r, H₆₂ = r)", maxAbs(DM(H - Hbook)), 0.0);
  const HybridProjectors<double> p = dualBasisProjectors<double>(pegFreedoms(), pegComplement());
  const HybridProjectors<double> t = transformedProjectors<double>(p, H);
  M6 XYc = M6::Zero();
  XYc(0, 0) = XYc(1, 1) = XYc(3, 3) = XYc(4, 4) = 1;
  XYc(1, 5) = -r;
  XYc(2, 4) = -r;
  ctx.checkResidual("X̃Ỹ = HᵀXYH⁻ᵀ = rows (1,0,0,0,0,0), (0,1,0,0,0,−r), (0,0,0,0,−r,0), (0,0,0,1,0,0), (0,0,0,0,1,0), 0", maxAbs(DM(t.wrenchProjector() - XYc)), 1e-15);
  M6 printed = M6::Zero();  // the printed five rows (+r, row (0,0,0,0,1,0) missing), padded with a zero row
  printed(0, 0) = 1;
  printed(1, 1) = 1;
  printed(1, 5) = r;
  printed(2, 4) = r;
  printed(3, 3) = 1;
  ctx.checkPrintedFails("the printed X̃Ỹ (+r at (2,6), (3,5), five rows)", "E15.8", maxAbs(DM(t.wrenchProjector() - printed)), 1e-9);
  M6 ABc = M6::Zero();
  ABc(2, 2) = ABc(5, 5) = 1;
  ABc(4, 2) = r;
  ABc(5, 1) = r;
  ctx.checkResidual("ÃB̃ = H⁻¹(AB)H: nonzero (3,3) = 1, (5,3) = r, (6,2) = r, (6,6) = 1 (display dropped, E15.7)", maxAbs(DM(t.motionProjector() - ABc)), 1e-15);
  V6 z1(0, 0, 1, 0, r, 0), W6(0, 0, -r, 0, 1, 0);
  ctx.checkResidual("z̃₁ = (k, r j)", (V6(t.A.col(0)) - z1).cwiseAbs().maxCoeff(), 1e-15);
  ctx.checkResidual("W̃₆ = (−r k, j)", (V6(t.X.col(3)) - W6).cwiseAbs().maxCoeff(), 1e-15);
  const V6 rotY(0, 1, 0, 0, 0, 0);
  const V6 proj = t.motionProjector() * rotY;
  ctx.checkResidual("a rotation about the new y-axis projects onto the z-translation (0, 0, 0, 0, 0, r)", (proj - V6(0, 0, 0, 0, 0, r)).cwiseAbs().maxCoeff(), 1e-15);
}

void secondFundamental(Context& ctx) {
  auto g = std::mt19937_64(1545);
  const double m = 2.0;
  const V3 c(0.3, -0.2, 0.25);
  const V3 d(0.2, 0.3, 0.4);
  const M3 R = SO3<double>::Random(g).matrix();
  const SpatialInertia<double> body(m, c, M3(R * V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose()));
  const M6 N = body.matrix();
  DM Z = DM::Zero(6, 3);
  Z(0, 0) = Z(1, 1) = Z(2, 2) = 1;  // pinned at the origin: SO(3) about 0
  const HybridProjectors<double> p = n6Projectors<double>(Z, N);
  const V3 w(0.8, -0.5, 1.1);
  const M3 Io = body.inertiaAboutOrigin();
  const V3 wd = Io.ldlt().solve(V3(-w.cross(Io * w)));  // free rotation about the pin
  V6 V, Vd;
  V << w, V3::Zero();
  Vd << wd, V3::Zero();
  const V6 total = rigidBodyWrench<double>(N, V, Vd), II = secondFundamentalWrench<double>(p, N, V, Vd);
  const V3 F = m * (wd.cross(c) + w.cross(w.cross(c)));
  ctx.checkResidual("free motion on the constraint: N₆∇_VV is a pure force through the pin (moment part)", total.head<3>().norm(), 1e-14);
  ctx.checkResidual("its force = m(ω̇ × c + ω × (ω × c)), the pin reaction", (total.tail<3>() - F).norm(), 1e-14);
  ctx.checkResidual("N₆II(V, V) = XXᵀN₆⁻¹(N₆∇_VV) equals it (the tangential part Ñ∇_VV vanishes)", (II - total).norm(), 1e-13);
  ctx.checkEqual("the reaction is nonzero although SO(3) is a subgroup (N₆ is only left-invariant)", 1, F.norm() > 0.1 ? 1 : 0);
  ctx.note("Reaction force " + toString(F.norm(), 4) + " N for |ω| = " + toString(w.norm(), 3) + " rad/s, c = (0.3, −0.2, 0.25) m, m = 2 kg.");
  // E15.10: "H(V,V)" is II(V, V); nothing numeric to fail (OCR)
}

void n6Orthonormal(Context& ctx) {
  auto g = std::mt19937_64(1546);
  double e1 = 0, e2 = 0, e3 = 0, e4 = 0;
  for (int t = 0; t < 20; ++t) {
    const int n = 1 + t % 5;
    DM L(6, 6);
    for (int i = 0; i < 36; ++i) L(i) = uni(g);
    const M6 N = L * L.transpose() + 0.5 * M6::Identity();
    DM Z(6, n);
    for (int i = 0; i < n; ++i) Z.col(i) = rv6(g);
    const HybridProjectors<double> p = n6Projectors<double>(Z, N);
    DM full(6, 6);
    full << p.A, p.Y.transpose();
    e1 = std::max(e1, maxAbs(DM(full.transpose() * N * full - DM::Identity(6, 6))));
    e2 = std::max(e2, maxAbs(DM(p.X * p.X.transpose() * N.inverse() - N * p.Y.transpose() * p.Y)));
    const M6 AB = p.A * p.A.transpose() * N, XY = N * p.Y.transpose() * p.Y;
    e3 = std::max({e3, maxAbs(DM(AB * AB - AB)), maxAbs(DM(XY * XY - XY))});
    e4 = std::max(e4, maxAbs(DM(AB + XY.transpose() - M6::Identity())));
  }
  ctx.checkResidual("z_iᵀN₆z_j = δ_ij (N₆-Gram–Schmidt, 20 random SPD N₆ and subspaces)", e1, 1e-11);
  ctx.checkResidual("XXᵀN₆⁻¹ = N₆YᵀY", e2, 1e-10);
  ctx.checkResidual("AAᵀN₆ and N₆YᵀY idempotent", e3, 1e-10);
  ctx.checkResidual("complementary: AAᵀN₆ + (N₆YᵀY)ᵀ = I", e4, 1e-10);
}

/// λ_j = z_iᵀN₆V̇ + VᵀN₆[z_j, V] with i = n+1 (the first constraint index) for every j.
// GF §15.4.4 line 10034 as printed (erratum E15.9)
DV constraintMultipliersAsPrinted(const HybridProjectors<double>& p, const M6& N6, const V6& V, const V6& Vdot) {
  DV lam(p.Y.rows());
  for (Eigen::Index j = 0; j < p.Y.rows(); ++j)
    lam(j) = V6(p.Y.row(0).transpose()).dot(N6 * Vdot) + V.dot(N6 * br(p.Y.row(j).transpose(), V));
  return lam;
}

void multipliers(Context& ctx) {
  auto g = std::mt19937_64(1547);
  const SpatialInertia<double> body(1.5, V3(0.2, 0.1, -0.3), M3(V3(0.3, 0.4, 0.5).asDiagonal()));
  const M6 N = body.matrix();
  // a body sliding on a plane z = 0 (freedoms: rotation about z through 0, translations x, y)
  DM Z = DM::Zero(6, 3);
  Z(2, 0) = Z(3, 1) = Z(4, 2) = 1;
  const HybridProjectors<double> p = n6Projectors<double>(Z, N);
  // a state tangent to the constraint and the free constrained acceleration: project N∇ onto the freedoms
  const V6 V = p.A * rvec(g, 3);
  // V̇ = A a with a from the constrained equations Aᵀ(N V̇ + {V, N V}) = 0
  const DM AtNA = p.A.transpose() * N * p.A;
  const DV a = AtNA.ldlt().solve(DV(-(p.A.transpose() * coadjointBrace<double>(V, V6(N * V)))));
  const V6 Vd = p.A * a;
  const V6 total = rigidBodyWrench<double>(N, V, Vd);
  const DV lam = constraintMultipliers<double>(p, N, V, Vd);
  ctx.checkResidual("free constrained motion: Σλ_jW_j = N₆V̇ + {V, N₆V} with λ_j = z_jᵀN₆V̇ + VᵀN₆[z_j, V] (E15.9)", (V6(p.X * lam) - total).norm(), 1e-14);
  // any V̇ (a wrench also applied along the freedoms): the λ_j are the W_j-coefficients of N₆∇_VV,
  // i.e. Σλ_jW_j = XXᵀN₆⁻¹(N₆∇_VV) = N₆II(V, V)
  const V6 Vg = rv6(g);
  const DV lamG = constraintMultipliers<double>(p, N, V, Vg);
  ctx.checkResidual("general V̇: Σλ_jW_j = XXᵀN₆⁻¹(N₆V̇ + {V, N₆V})", (V6(p.X * lamG) - secondFundamentalWrench<double>(p, N, V, Vg)).norm(), 1e-14);
  const DV lamP = constraintMultipliersAsPrinted(p, N, V, Vg);
  ctx.checkPrintedFails("λ_j with z_i (i = n+1 fixed, line 10034), general V̇: |Σλ_jW_j − N₆II(V,V)|", "E15.9",
              (V6(p.X * lamP) - secondFundamentalWrench<double>(p, N, V, Vg)).norm(), 1e-9);
  ctx.note("For a free constrained motion on a subgroup (here SE(2) of the plane) V̇ is tangent, W_jᵀV̇ = 0 and the first term "
           "vanishes for every j — the index slip only shows when V̇ has a normal component.");
  // no-reaction condition: λ_j = 0 ⟺ W_jᵀq̈₆ = q̇₆ᵀN₆[q̇₆, z_j]
  double cond = 0;
  for (int j = 0; j < 3; ++j) {
    const V6 zj = p.Y.row(j).transpose(), Wj = p.X.col(j);
    cond = std::max(cond, abs(lamG(j) - (Wj.dot(Vg) - V.dot(N * br(V, zj)))));
  }
  ctx.checkResidual("λ_j = W_jᵀV̇ − VᵀN₆[V, z_j]: so λ_j = 0 iff W_jᵀq̈₆ = q̇₆ᵀN₆[q̇₆, z_j] (with W_j, E15.9)", cond, 1e-14);
}

void hybridLaw(Context& ctx) {
  auto g = std::mt19937_64(1548);
  const SpatialInertia<double> body(1.5, V3(0.2, 0.1, -0.3), M3(V3(0.3, 0.4, 0.5).asDiagonal()));
  const M6 N = body.matrix();
  DM Z = DM::Zero(6, 2);
  Z(2, 0) = Z(5, 1) = 1;  // the peg
  const HybridProjectors<double> p = n6Projectors<double>(Z, N);
  const SM J = [&] {
    const JointSpaceGeometry<double> geo(randomScrews(g, 6));
    return SM(geo.screws(rvec(g, 6)));
  }();
  const V6 Wd = rv6(g), qd = rv6(g), q6 = rv6(g), qdd = rv6(g), q6dd = rv6(g);
  const DV tauF = forceControlTorque<double>(p, Wd, DM(J));
  const V6 qe = hybridVelocityError<double>(p, N, qd, q6);
  const V6 qee = hybridAccelerationError<double>(p, N, qdd, q6dd, qe);
  // the same computed in a second frame (random rigid change H): torques identical, screws transform
  const M6 H = SE3<double>::Random(g).adjoint(), Hi = H.inverse();
  const M6 N2 = H.transpose() * N * H;
  const HybridProjectors<double> p2 = n6Projectors<double>(DM(Hi * Z), N2);
  const DV tauF2 = forceControlTorque<double>(p2, V6(H.transpose() * Wd), DM(Hi * J));
  const V6 qe2 = hybridVelocityError<double>(p2, N2, V6(Hi * qd), V6(Hi * q6));
  const V6 qee2 = hybridAccelerationError<double>(p2, N2, V6(Hi * qdd), V6(Hi * q6dd), qe2);
  ctx.checkResidual("τ^f_i = Σ_{j=n+1}^{6}(W_dᵀz_j)(W_jᵀs_i): the same joint torques in two frames", maxAbs(DV(tauF - tauF2)), 1e-12);
  ctx.checkResidual("q̇_e = AAᵀN₆(q̇_d − q̇₆) transforms as a screw (q̇_e₂ = H⁻¹q̇_e)", (qe2 - Hi * qe).cwiseAbs().maxCoeff(), 1e-12);
  ctx.checkResidual("q̈_e = AAᵀN₆(q̈_d − q̈₆) + AAᵀ{q̇_e, N₆q̇_e} (braces restored, E15.10) transforms as a screw", (qee2 - Hi * qee).cwiseAbs().maxCoeff(), 1e-12);
  // the force torques do no work on the freedoms: τ^f = Jᵀ(XYW_d) and (XYW_d)ᵀz_i = 0 for i ≤ n
  const V6 Wp = p.X * (p.Y * Wd);
  ctx.checkResidual("the projected wrench does no work on the freedoms", maxAbs(DV(p.A.transpose() * Wp)), 1e-14);
  // E15.9: the printed Σ_{j=k+1}: with k = 0 (k is unbound) the sum includes the freedoms, W_d is not projected
  DM full(6, 6);
  full << p.A, p.Y.transpose();
  DM Wall(6, 6);
  Wall << DM(N * p.A), p.X;  // W_j = N₆z_j for all j
  V6 Wk0 = V6::Zero();
  for (int j = 0; j < 6; ++j) Wk0 += Wd.dot(V6(full.col(j))) * V6(Wall.col(j));
  ctx.checkPrintedFails("τ^f with Σ_{j=k+1}, k read as 0: work of the commanded wrench on the freedoms", "E15.9", maxAbs(DV(p.A.transpose() * Wk0)), 1e-9);
  (void)qee;
}

// A block-diagram helper on a 2-D plot with hidden axes.
struct Diagram {
  rd::Plot plot;
  void box(double x, double y, double w, double h, const std::string& text, rd::Color c = rd::palette::blue) {
    plot.add("", {x - w / 2, x + w / 2, x + w / 2, x - w / 2}, {y - h / 2, y - h / 2, y + h / 2, y + h / 2}, c).closed = true;
    rd::PlotText t;
    t.x = x;
    t.y = y;
    t.text = text;
    t.hAlign = rd::HAlign::Center;
    t.vAlign = rd::VAlign::Middle;
    t.dx = 0;
    t.dy = 0;
    t.pixelHeight = 20;
    plot.texts.push_back(t);
  }
  void sum(double x, double y) {
    std::vector<double> xs, ys;
    for (int k = 0; k < 32; ++k) {
      xs.push_back(x + 0.18 * std::cos(2 * pi<double>() * k / 32));
      ys.push_back(y + 0.18 * std::sin(2 * pi<double>() * k / 32));
    }
    plot.add("", xs, ys, rd::palette::black).closed = true;
    text(x, y, "Σ", rd::HAlign::Center);
  }
  void arrow(std::vector<double> xs, std::vector<double> ys, const std::string& label = "", rd::Color c = rd::palette::black) {
    plot.add("", xs, ys, c).width = 2.5;
    const std::size_t n = xs.size();
    const double dx = xs[n - 1] - xs[n - 2], dy = ys[n - 1] - ys[n - 2], l = std::hypot(dx, dy);
    const double ux = dx / l, uy = dy / l, s = 0.13;
    plot.add("", {xs[n - 1] - s * ux + 0.5 * s * uy, xs[n - 1], xs[n - 1] - s * ux - 0.5 * s * uy},
             {ys[n - 1] - s * uy - 0.5 * s * ux, ys[n - 1], ys[n - 1] - s * uy + 0.5 * s * ux}, c)
        .width = 2.5;
    if (!label.empty()) text((xs[0] + xs[1]) / 2, (ys[0] + ys[1]) / 2 + 0.12, label, rd::HAlign::Center, 18);
  }
  void text(double x, double y, const std::string& s, rd::HAlign h = rd::HAlign::Left, double px = 20) {
    rd::PlotText t;
    t.x = x;
    t.y = y;
    t.text = s;
    t.hAlign = h;
    t.vAlign = rd::VAlign::Middle;
    t.dx = 0;
    t.dy = 0;
    t.pixelHeight = px;
    plot.texts.push_back(t);
  }
  void finish(Context& ctx, const std::string& file, const std::string& caption) {
    plot.grid = false;
    plot.x.min = 0;
    plot.x.max = 14;
    plot.y.min = 0;
    plot.y.max = 7;
    plot.x.ticks = {-100};
    plot.y.ticks = {-100};
    plot.equalAspect = true;
    rd::renderPlotPngAndSvg(plot, ctx.figurePath(file), 1500, 800);
    ctx.figure(file, caption);
  }
};

void fig151(Context& ctx) {
  // the check behind the figure: in the peg frame the Raibert–Craig S and I − S are AB and XY
  const HybridProjectors<double> p = dualBasisProjectors<double>(pegFreedoms(), pegComplement());
  ctx.checkResidual("S + (I − S) = I with S = AB, I − S = XY in the peg frame", maxAbs(DM(p.motionProjector() + p.wrenchProjector() - M6::Identity())), 0.0);
  if (!ctx.makeFigures()) return;
  Diagram d;
  d.plot.title = "Fig. 15.1: hybrid control architecture (Raibert–Craig, after Spong & Vidyasagar)";
  d.text(0.2, 5.2, "x_d");
  d.arrow({0.7, 1.6}, {5.2, 5.2});
  d.sum(1.8, 5.2);
  d.arrow({2.0, 3.0}, {5.2, 5.2}, "e_x");
  d.box(3.9, 5.2, 1.8, 0.8, "S");
  d.arrow({4.8, 5.8}, {5.2, 5.2});
  d.box(6.9, 5.2, 2.2, 0.8, "position law");
  d.arrow({8.0, 9.0, 9.0}, {5.2, 5.2, 4.15});
  d.text(0.2, 2.2, "f_d");
  d.arrow({0.7, 1.6}, {2.2, 2.2});
  d.sum(1.8, 2.2);
  d.arrow({2.0, 3.0}, {2.2, 2.2}, "e_f");
  d.box(3.9, 2.2, 1.8, 0.8, "I − S");
  d.arrow({4.8, 5.8}, {2.2, 2.2});
  d.box(6.9, 2.2, 2.2, 0.8, "force law");
  d.arrow({8.0, 9.0, 9.0}, {2.2, 2.2, 3.25});
  d.sum(9.0, 3.7);
  d.arrow({9.2, 10.2}, {3.7, 3.7}, "τ");
  d.box(11.4, 3.7, 2.4, 1.0, "robot + environment");
  d.arrow({12.5, 13.3, 13.3, 1.8, 1.8}, {3.9, 3.9, 6.4, 6.4, 5.4});
  d.text(6.5, 6.6, "measured position x (kinematics)", rd::HAlign::Center, 18);
  d.arrow({12.5, 13.0, 13.0, 1.8, 1.8}, {3.5, 3.5, 0.9, 0.9, 2.0});
  d.text(6.5, 0.6, "measured force f (wrist sensor)", rd::HAlign::Center, 18);
  d.text(1.45, 5.65, "+", rd::HAlign::Center, 18);
  d.text(1.45, 2.65, "+", rd::HAlign::Center, 18);
  d.text(2.05, 5.75, "−", rd::HAlign::Center, 18);
  d.text(2.05, 1.7, "−", rd::HAlign::Center, 18);
  d.finish(ctx, "gf15_fig15_1.png", "Fig. 15.1 redrawn: the Raibert–Craig hybrid controller. The selection matrix S passes the position "
                                    "error and I − S the force error; in the peg frame S = AB = diag(0,0,1,0,0,1) and I − S = XY (GF-15.4.3-peg-in-hole).");
}

void fig152(Context& ctx) {
  const auto body = SpatialInertia<double>(1.5, V3(0.2, 0.1, -0.3), M3(V3(0.3, 0.4, 0.5).asDiagonal()));
  const HybridProjectors<double> p = n6Projectors<double>(pegFreedoms(), body.matrix());
  ctx.checkResidual("the figure's operators: AAᵀN₆ and N₆YᵀY are complementary projectors",
                    maxAbs(DM(p.motionProjector() + p.wrenchProjector().transpose() - M6::Identity())), 1e-13);
  if (!ctx.makeFigures()) return;
  Diagram d;
  d.plot.title = "Fig. 15.2: hybrid control with compensation for constraint-space curvature";
  d.text(0.1, 5.2, "q̇_d, q̈_d");
  d.arrow({1.0, 1.6}, {5.2, 5.2});
  d.sum(1.8, 5.2);
  d.arrow({2.0, 2.8}, {5.2, 5.2});
  d.box(4.2, 5.2, 2.6, 1.0, "AAᵀN₆ (·)");
  d.arrow({5.5, 6.2}, {5.2, 5.2}, "q̇_e");
  d.box(7.6, 5.2, 2.6, 1.0, "+ AAᵀ{q̇_e, N₆q̇_e}");
  d.arrow({8.9, 9.6, 9.6}, {5.2, 5.2, 4.15}, "q̈_e");
  d.text(0.1, 2.2, "W_d");
  d.arrow({0.7, 2.8}, {2.2, 2.2});
  d.box(4.2, 2.2, 2.6, 1.0, "XXᵀN₆⁻¹ = N₆YᵀY");
  d.arrow({5.5, 6.2}, {2.2, 2.2});
  d.box(7.6, 2.2, 2.6, 1.0, "τ^f = Σ W_dᵀz_j W_jᵀs_i");
  d.arrow({8.9, 9.6, 9.6}, {2.2, 2.2, 3.25}, "τ^f");
  d.sum(9.6, 3.7);
  d.arrow({9.8, 10.6}, {3.7, 3.7}, "τ");
  d.box(12.0, 3.7, 2.4, 1.0, "robot + constraint");
  d.arrow({13.2, 13.7, 13.7, 1.8, 1.8}, {3.9, 3.9, 6.4, 6.4, 5.4});
  d.text(7.0, 6.6, "measured q̇₆, q̈₆ (motion feedback: τ^m from q̈_e by computed torque)", rd::HAlign::Center, 18);
  d.text(1.45, 5.65, "+", rd::HAlign::Center, 18);
  d.text(2.05, 5.75, "−", rd::HAlign::Center, 18);
  d.text(7.0, 0.8, "the curvature term keeps the commanded motion on the constraint manifold (no reaction wrench)", rd::HAlign::Center, 18);
  d.finish(ctx, "gf15_fig15_2.png", "Fig. 15.2 redrawn: the coordinate-free hybrid controller. Motion errors pass the N₆-orthogonal "
                                    "projector AAᵀN₆ with the second-fundamental-form correction AAᵀ{q̇_e, N₆q̇_e}; the desired wrench "
                                    "passes N₆YᵀY and becomes joint torques τ^f (braces and τ restored, errata E15.9, E15.10).");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-15.4.2-constraints-natural-artificial", "Selection matrices depend on the frame (Lipkin–Duffy); AB does not", "GF §15.4.1–15.4.2", natural);
SOMA_STUDY_DOUBLE("GF-15.4.3-dual-bases-projection", "Dual bases: AB and XY idempotent and complementary (finding E15.15)", "GF §15.4.3", dualBases);
SOMA_STUDY_DOUBLE("GF-15.4.3-peg-in-hole", "Peg in hole: AB = diag(0,0,1,0,0,1), XY = diag(1,1,0,1,1,0) (erratum E15.7)", "GF §15.4.3", peg);
SOMA_STUDY_DOUBLE("GF-15.4.3-projection-transformation", "ÃB̃ = H⁻¹(AB)H, X̃Ỹ = Hᵀ(XY)H⁻ᵀ, shifted origin (errata E15.7, E15.8)", "GF §15.4.3", transformation);
SOMA_STUDY_DOUBLE("GF-15.4.4-second-fundamental-form", "N₆II(V,V): the reaction of a pinned body (erratum E15.10)", "GF §15.4.4", secondFundamental);
SOMA_STUDY_DOUBLE("GF-15.4.4-N6-orthonormal-projections", "AAᵀN₆ and XXᵀN₆⁻¹ = N₆YᵀY", "GF §15.4.4", n6Orthonormal);
SOMA_STUDY_DOUBLE("GF-15.4.4-constraint-multipliers", "λ_j = z_jᵀN₆V̇ + VᵀN₆[z_j, V] (erratum E15.9)", "GF §15.4.4", multipliers);
SOMA_STUDY_DOUBLE("GF-15.4.4-hybrid-control-law", "The hybrid law is frame-invariant (errata E15.9, E15.10)", "GF §15.4.4", hybridLaw);
SOMA_STUDY_DOUBLE("GF-15-fig-15.1", "Fig. 15.1: hybrid control architecture", "GF §15.4.1", fig151);
SOMA_STUDY_DOUBLE("GF-15-fig-15.2", "Fig. 15.2: hybrid control with curvature compensation", "GF §15.4.4", fig152);

}  // namespace soma::studies::gf15::SOMA_UNITY_ID
