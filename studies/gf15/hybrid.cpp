// Studies of GF §15.4 (in the asked scalar; the block diagrams in double): hybrid force/position control — the Lipkin–Duffy frame dependence of a
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

constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";

/// SO3<double>::Random's draw in S: its quaternion renormalised in S (a rotation to S's rounding).
template <class S> SO3<S> rotationS(std::mt19937_64& g) {
  Quat<S> q(castMatrix<S>(Vec4<double>(SO3<double>::Random(g).quaternion().coeffs())));
  q.normalize();
  return SO3<S>::fromQuaternionUnchecked(q);
}
template <class S> DgMatrix<S> pegFreedoms() {
  using DM = DgMatrix<S>;
  DM Z = DM::Zero(6, 2);
  Z(2, 0) = Z(5, 1) = 1;  // z₁ = (k, 0), z₂ = (0, k)
  return Z;
}
template <class S> DgMatrix<S> pegComplement() {
  using DM = DgMatrix<S>;
  DM Sc = DM::Zero(6, 4);
  Sc(0, 0) = Sc(1, 1) = Sc(3, 2) = Sc(4, 3) = 1;  // (i,0), (j,0), (0,i), (0,j)
  return Sc;
}
template <class S> Mat6<S> shiftX(const S& r) { return SE3<S>(SO3<S>::Identity(), Vec3<S>(r, S(0), S(0))).adjoint(); }

template <class S> void natural(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  // Raibert–Craig: one selection matrix S = diag(0,0,1,0,0,1) used for twists AND (via I − S) wrenches.
  M6 Ssel = M6::Zero();
  Ssel(2, 2) = Ssel(5, 5) = 1;
  const M6 H = shiftX<S>(frac<S>(2, 5));  // the same peg described from an origin moved 0.4 along x
  const M6 Hi = shiftX<S>(frac<S>(-2, 5));  // the exact inverse of a translation's adjoint
  const V6 err = (V6() << frac<S>(1, 100), frac<S>(-1, 50), frac<S>(3, 100), frac<S>(1, 500), frac<S>(1, 1000), frac<S>(-1, 250)).finished();  // a twist error in frame 1
  // the action of S in frame 2, mapped back to frame 1, vs the action in frame 1
  const V6 act1 = Ssel * err, act2back = H * (Ssel * (Hi * err));
  ctx.checkPrintedFails("selection matrix S used in two frames (origin shifted 0.4 along x): |S e − H S H⁻¹e|", "— Lipkin & Duffy", mx<S>(V6(act1 - act2back)), tol<S>(4));
  // the invariant operator AB: built in frame 2 from the transformed screws, it is H⁻¹(AB)H
  const HybridProjectors<S> p1 = dualBasisProjectors<S>(pegFreedoms<S>(), pegComplement<S>());
  const HybridProjectors<S> p2 = dualBasisProjectors<S>(DM(Hi * pegFreedoms<S>()), DM(Hi * pegComplement<S>()));
  ctx.checkResidual("AB built in frame 2 acts like AB in frame 1: |AB e − H (AB)₂ H⁻¹ e|", mx<S>(V6(p1.motionProjector() * err - H * (p2.motionProjector() * (Hi * err)))), tol<S>(4));
  // constraint wrenches do no work on freedoms, in any frame
  ctx.checkResidual("|Xᵀ A| in frame 2 (reciprocity of constraint wrenches and freedoms)", mx<S>(DM(p2.X.transpose() * p2.A)), tol<S>(4));
  ctx.note("Natural constraints (the hole's walls) supply the wrenches X; artificial ones are imposed by the controller. The control "
           "actions through AB and XY do not interfere because XᵀA = 0.");
}

template <class S> void dualBases(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  auto g = std::mt19937_64(1543);
  S idem = 0, dual = 0, comp = 0;
  int rejected = 0;
  for (int t = 0; t < 20; ++t) {
    const int n = 1 + t % 5;
    DM Z(6, n), Sc(6, 6 - n);
    for (int i = 0; i < n; ++i) Z.col(i) = V6(castMatrix<S>(rv6(g)));
    for (int i = 0; i < 6 - n; ++i) Sc.col(i) = V6(castMatrix<S>(rv6(g)));
    HybridProjectors<S> p;
    try {
      p = dualBasisProjectors<S>(Z, Sc);
    } catch (const InvalidInput&) {  // σ_min/σ_max of [Z S'] below 65536 ε (cond above 128 in float)
      ++rejected;
      continue;
    }
    const M6 AB = p.motionProjector(), XY = p.wrenchProjector();
    // relative to the size of the operators (random bases can be ill-conditioned: ‖AB‖ up to ~1e2)
    const S sc = 1 + mx<S>(DM(AB)) + mx<S>(DM(XY));
    idem = std::max({idem, mx<S>(DM(AB * AB - AB)) / (sc * sc), mx<S>(DM(XY * XY - XY)) / (sc * sc)});
    dual = std::max({dual, mx<S>(DM(p.B * p.A - DM::Identity(n, n))) / sc, mx<S>(DM(p.Y * p.X - DM::Identity(6 - n, 6 - n))) / sc,
                     mx<S>(DM(p.X.transpose() * p.A)) / sc});
    comp = std::max(comp, mx<S>(DM(AB + XY.transpose() - M6::Identity())) / sc);
  }
  ctx.checkResidual("AB, XY idempotent (20 random freedom systems, n = 1…5; relative to (1 + ‖AB‖ + ‖XY‖)²; 512 ε)", idem, tol<S>(512));
  ctx.checkResidual("BA = I_n, YX = I_{6−n}, XᵀA = 0 (relative, 512 ε)", dual, tol<S>(512));
  ctx.checkResidual("AB + (XY)ᵀ = I (complementary under the pairing, relative, 512 ε)", comp, tol<S>(512));
  if (rejected)
    ctx.note(std::to_string(rejected) + " of the 20 random bases [Z S'] left out: dualBasisProjectors calls them singular in this scalar "
             "(σ_min/σ_max below its threshold 65536 ε).");
  // finding E15.15: the projection DOES depend on the complement S' (the book says it does not)
  DM Z(6, 2), S1(6, 4);
  for (int i = 0; i < 2; ++i) Z.col(i) = V6(castMatrix<S>(rv6(g)));
  for (int i = 0; i < 4; ++i) S1.col(i) = V6(castMatrix<S>(rv6(g)));
  DM S2 = S1;
  S2.col(0) += frac<S>(1, 2) * Z.col(0);  // "add elements of S to the basis elements of S'"
  const HybridProjectors<S> pa = dualBasisProjectors<S>(Z, S1), pb = dualBasisProjectors<S>(Z, S2);
  // first-order bound of a product of the two projectors: 6-term sums of entries ≤ ‖AB₁‖‖AB₂‖, each projector
  // good to a few ε of its own size
  const S tolImage = tol<S>(64) * (1 + mx<S>(DM(pa.motionProjector()))) * (1 + mx<S>(DM(pb.motionProjector())));
  ctx.checkPrintedFails("\"the lack of uniqueness will not affect the projection\": |AB(S'₁) − AB(S'₂)| with S'₂ = S'₁ + element of S", "E15.15 (finding)",
              mx<S>(DM(pa.motionProjector() - pb.motionProjector())), tolImage);
  ctx.checkResidual("both are projectors onto the same S (image unchanged): |AB₂·AB₁ − AB₁| (64 ε·(1 + ‖AB₁‖)(1 + ‖AB₂‖))",
                    mx<S>(DM(pb.motionProjector() * pa.motionProjector() - pa.motionProjector())), tolImage);
  ctx.note("AB projects onto S along S' (its kernel); a different complement gives a different projector with the same image. "
           "A canonical complement needs extra structure — exactly the N₆ metric of §15.4.4 (GF-15.4.4-N6-orthonormal-projections).");
}

template <class S> void peg(Context& ctx) {
  using M6 = Mat6<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  const HybridProjectors<S> p = dualBasisProjectors<S>(pegFreedoms<S>(), pegComplement<S>());
  DM B(2, 6);
  B << 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1;
  ctx.checkResidual("B (rows W₁ᵀ, W₂ᵀ) as printed at line 9918", mx<S>(DM(p.B - B)), S(0));
  ctx.checkResidual("A = Bᵀ", mx<S>(DM(p.A - B.transpose())), S(0));
  DM Y = DM::Zero(4, 6);
  Y(0, 0) = Y(1, 1) = Y(2, 3) = Y(3, 4) = 1;
  ctx.checkResidual("Y (rows e₁, e₂, e₄, e₅) and X = Yᵀ as printed", mx<S>(DM(p.Y - Y)) + mx<S>(DM(p.X - Y.transpose())), S(0));
  M6 AB = M6::Zero(), XY = M6::Zero();
  AB(2, 2) = AB(5, 5) = 1;
  XY(0, 0) = XY(1, 1) = XY(3, 3) = XY(4, 4) = 1;
  ctx.checkResidual("AB = diag(0,0,1,0,0,1) (the display dropped at line 9932, E15.7)", mx<S>(DM(p.motionProjector() - AB)), S(0));
  ctx.checkResidual("XY = diag(1,1,0,1,1,0) (dropped at line 9942, E15.7): the Raibert–Craig I − S", mx<S>(DM(p.wrenchProjector() - XY)), S(0));
  ctx.note("E15.7 is an OCR loss (the displays are missing from the seed, not wrong in the book): the reconstructed matrices "
           "are the ones computed here; there is no printed matrix to fail.");
}

template <class S> void transformation(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  const S r = frac<S>(7, 10);
  const M6 H = shiftX<S>(r);
  M6 Hbook = M6::Identity();
  Hbook(4, 2) = -r;
  Hbook(5, 1) = r;
  ctx.checkResidual("H = Ad(origin moved r along x) is the book's H (H₅₃ = −r, H₆₂ = r)", mx<S>(DM(H - Hbook)), S(0));
  const HybridProjectors<S> p = dualBasisProjectors<S>(pegFreedoms<S>(), pegComplement<S>());
  const HybridProjectors<S> t = transformedProjectors<S>(p, H);
  M6 XYc = M6::Zero();
  XYc(0, 0) = XYc(1, 1) = XYc(3, 3) = XYc(4, 4) = 1;
  XYc(1, 5) = -r;
  XYc(2, 4) = -r;
  ctx.checkResidual("X̃Ỹ = HᵀXYH⁻ᵀ = rows (1,0,0,0,0,0), (0,1,0,0,0,−r), (0,0,0,0,−r,0), (0,0,0,1,0,0), (0,0,0,0,1,0), 0", mx<S>(DM(t.wrenchProjector() - XYc)), tol<S>(4));
  M6 printed = M6::Zero();  // the printed five rows (+r, row (0,0,0,0,1,0) missing), padded with a zero row
  printed(0, 0) = 1;
  printed(1, 1) = 1;
  printed(1, 5) = r;
  printed(2, 4) = r;
  printed(3, 3) = 1;
  ctx.checkPrintedFails("the printed X̃Ỹ (+r at (2,6), (3,5), five rows)", "E15.8", mx<S>(DM(t.wrenchProjector() - printed)), tol<S>(4));
  M6 ABc = M6::Zero();
  ABc(2, 2) = ABc(5, 5) = 1;
  ABc(4, 2) = r;
  ABc(5, 1) = r;
  ctx.checkResidual("ÃB̃ = H⁻¹(AB)H: nonzero (3,3) = 1, (5,3) = r, (6,2) = r, (6,6) = 1 (display dropped, E15.7)", mx<S>(DM(t.motionProjector() - ABc)), tol<S>(4));
  const V6 z1 = (V6() << 0, 0, 1, 0, r, 0).finished(), W6 = (V6() << 0, 0, -r, 0, 1, 0).finished();
  ctx.checkResidual("z̃₁ = (k, r j)", mx<S>(V6(V6(t.A.col(0)) - z1)), tol<S>(4));
  ctx.checkResidual("W̃₆ = (−r k, j)", mx<S>(V6(V6(t.X.col(3)) - W6)), tol<S>(4));
  const V6 rotY = (V6() << 0, 1, 0, 0, 0, 0).finished();
  const V6 proj = t.motionProjector() * rotY;
  ctx.checkResidual("a rotation about the new y-axis projects onto the z-translation (0, 0, 0, 0, 0, r)", mx<S>(V6(proj - (V6() << 0, 0, 0, 0, 0, r).finished())), tol<S>(4));
}

template <class S> void secondFundamental(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using V3 = Vec3<S>;
  using M3 = Mat3<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  auto g = std::mt19937_64(1545);
  const S m = S(2);
  const V3 c(frac<S>(3, 10), frac<S>(-1, 5), frac<S>(1, 4));
  const V3 d(frac<S>(1, 5), frac<S>(3, 10), frac<S>(2, 5));
  const M3 R = rotationS<S>(g).matrix();
  const SpatialInertia<S> body(m, c, M3(R * V3(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose()));
  const M6 N = body.matrix();
  DM Z = DM::Zero(6, 3);
  Z(0, 0) = Z(1, 1) = Z(2, 2) = 1;  // pinned at the origin: SO(3) about 0
  const HybridProjectors<S> p = n6Projectors<S>(Z, N);
  const V3 w(frac<S>(4, 5), frac<S>(-1, 2), frac<S>(11, 10));
  const M3 Io = body.inertiaAboutOrigin();
  V3 wd = -w.cross(Io * w);  // free rotation about the pin: I_o ω̇ = −ω × I_o ω
  detail::smallSolveInPlace<S, 3>(Io, wd);
  V6 V, Vd;
  V << w, V3::Zero();
  Vd << wd, V3::Zero();
  const V6 total = rigidBodyWrench<S>(N, V, Vd), II = secondFundamentalWrench<S>(p, N, V, Vd);
  const V3 F = m * (wd.cross(c) + w.cross(w.cross(c)));
  ctx.checkResidual("free motion on the constraint: N₆∇_VV is a pure force through the pin (moment part; 64 ε)", S(total.template head<3>().norm()), tol<S>(64));
  ctx.checkResidual("its force = m(ω̇ × c + ω × (ω × c)), the pin reaction (64 ε)", S(V3(total.template tail<3>() - F).norm()), tol<S>(64));
  ctx.checkResidual("N₆II(V, V) = XXᵀN₆⁻¹(N₆∇_VV) equals it (the tangential part Ñ∇_VV vanishes; 512 ε)", S(V6(II - total).norm()), tol<S>(512));
  ctx.checkEqual("the reaction is nonzero although SO(3) is a subgroup (N₆ is only left-invariant)", 1, F.norm() > frac<S>(1, 10) ? 1 : 0);
  ctx.note("Reaction force " + toString(toDouble(S(F.norm())), 4) + " N for |ω| = " + toString(toDouble(S(w.norm())), 3) + " rad/s, c = (0.3, −0.2, 0.25) m, m = 2 kg.");
  // E15.10: "H(V,V)" is II(V, V); nothing numeric to fail (OCR)
}

template <class S> void n6Orthonormal(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  auto g = std::mt19937_64(1546);
  S e1 = 0, e2 = 0, e3 = 0, e4 = 0;
  for (int t = 0; t < 20; ++t) {
    const int n = 1 + t % 5;
    DM L(6, 6);
    for (int i = 0; i < 36; ++i) L(i) = S(uni(g));
    const M6 N = L * L.transpose() + frac<S>(1, 2) * M6::Identity();
    DM Z(6, n);
    for (int i = 0; i < n; ++i) Z.col(i) = V6(castMatrix<S>(rv6(g)));
    const HybridProjectors<S> p = n6Projectors<S>(Z, N);
    const M6 Ninv = inverse6<S>(N);  // soma's Gaussian elimination, not Eigen's LU (compile cost)
    DM full(6, 6);
    full << p.A, p.Y.transpose();
    e1 = std::max(e1, mx<S>(DM(full.transpose() * N * full - DM::Identity(6, 6))));
    e2 = std::max(e2, mx<S>(DM(p.X * p.X.transpose() * Ninv - N * p.Y.transpose() * p.Y)));
    const M6 AB = p.A * p.A.transpose() * N, XY = N * p.Y.transpose() * p.Y;
    e3 = std::max({e3, mx<S>(DM(AB * AB - AB)), mx<S>(DM(XY * XY - XY))});
    e4 = std::max(e4, mx<S>(DM(AB + XY.transpose() - M6::Identity())));
  }
  ctx.checkResidual("z_iᵀN₆z_j = δ_ij (N₆-Gram–Schmidt, 20 random SPD N₆ and subspaces; 32768 ε = 7.3e-12 in double, the double study's 1e-11 as a multiple of ε)", e1, tol<S>(32768));
  ctx.checkResidual("XXᵀN₆⁻¹ = N₆YᵀY (2¹⁹ ε = 1.2e-10 in double, the double study's 1e-10 as a multiple of ε)", e2, tol<S>(1 << 19));
  ctx.checkResidual("AAᵀN₆ and N₆YᵀY idempotent (2¹⁹ ε)", e3, tol<S>(1 << 19));
  ctx.checkResidual("complementary: AAᵀN₆ + (N₆YᵀY)ᵀ = I (2¹⁹ ε)", e4, tol<S>(1 << 19));
}

/// λ_j = z_iᵀN₆V̇ + VᵀN₆[z_j, V] with i = n+1 (the first constraint index) for every j.
// GF §15.4.4 line 10034 as printed (erratum E15.9)
template <class S>
DgVector<S> constraintMultipliersAsPrinted(const HybridProjectors<S>& p, const Mat6<S>& N6, const Vec6<S>& V, const Vec6<S>& Vdot) {
  using V6 = Vec6<S>;
  using DV = DgVector<S>;
  DV lam(p.Y.rows());
  for (Eigen::Index j = 0; j < p.Y.rows(); ++j)
    lam(j) = V6(p.Y.row(0).transpose()).dot(N6 * Vdot) + V.dot(N6 * brS<S>(p.Y.row(j).transpose(), V));
  return lam;
}

template <class S> void multipliers(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using V3 = Vec3<S>;
  using M3 = Mat3<S>;
  using DV = DgVector<S>;
  using DM = DgMatrix<S>;
  using std::abs;
  auto g = std::mt19937_64(1547);
  const SpatialInertia<S> body(frac<S>(3, 2), V3(frac<S>(1, 5), frac<S>(1, 10), frac<S>(-3, 10)), M3(V3(frac<S>(3, 10), frac<S>(2, 5), frac<S>(1, 2)).asDiagonal()));
  const M6 N = body.matrix();
  // a body sliding on a plane z = 0 (freedoms: rotation about z through 0, translations x, y)
  DM Z = DM::Zero(6, 3);
  Z(2, 0) = Z(3, 1) = Z(4, 2) = 1;
  const HybridProjectors<S> p = n6Projectors<S>(Z, N);
  // a state tangent to the constraint and the free constrained acceleration: project N∇ onto the freedoms
  const V6 V = p.A * rvecS<S>(g, 3);
  // V̇ = A a with a from the constrained equations Aᵀ(N V̇ + {V, N V}) = 0
  const DM AtNA = p.A.transpose() * N * p.A;
  V3 a3 = -(p.A.transpose() * coadjointBrace<S>(V, V6(N * V)));
  detail::smallSolveInPlace<S, 3>(M3(AtNA), a3);
  const DV a = a3;
  const V6 Vd = p.A * a;
  const V6 total = rigidBodyWrench<S>(N, V, Vd);
  const DV lam = constraintMultipliers<S>(p, N, V, Vd);
  ctx.checkResidual("free constrained motion: Σλ_jW_j = N₆V̇ + {V, N₆V} with λ_j = z_jᵀN₆V̇ + VᵀN₆[z_j, V] (E15.9; 64 ε)", S(V6(V6(p.X * lam) - total).norm()), tol<S>(64));
  // any V̇ (a wrench also applied along the freedoms): the λ_j are the W_j-coefficients of N₆∇_VV,
  // i.e. Σλ_jW_j = XXᵀN₆⁻¹(N₆∇_VV) = N₆II(V, V)
  const V6 Vg = V6(castMatrix<S>(rv6(g)));
  const DV lamG = constraintMultipliers<S>(p, N, V, Vg);
  ctx.checkResidual("general V̇: Σλ_jW_j = XXᵀN₆⁻¹(N₆V̇ + {V, N₆V})", S(V6(V6(p.X * lamG) - secondFundamentalWrench<S>(p, N, V, Vg)).norm()), tol<S>(64));
  const DV lamP = constraintMultipliersAsPrinted<S>(p, N, V, Vg);
  ctx.checkPrintedFails("λ_j with z_i (i = n+1 fixed, line 10034), general V̇: |Σλ_jW_j − N₆II(V,V)|", "E15.9",
              S(V6(V6(p.X * lamP) - secondFundamentalWrench<S>(p, N, V, Vg)).norm()), tol<S>(64));
  ctx.note("For a free constrained motion on a subgroup (here SE(2) of the plane) V̇ is tangent, W_jᵀV̇ = 0 and the first term "
           "vanishes for every j — the index slip only shows when V̇ has a normal component.");
  // no-reaction condition: λ_j = 0 ⟺ W_jᵀq̈₆ = q̇₆ᵀN₆[q̇₆, z_j]
  S cond = 0;
  for (int j = 0; j < 3; ++j) {
    const V6 zj = p.Y.row(j).transpose(), Wj = p.X.col(j);
    cond = std::max(cond, abs(lamG(j) - (Wj.dot(Vg) - V.dot(N * brS<S>(V, zj)))));
  }
  ctx.checkResidual("λ_j = W_jᵀV̇ − VᵀN₆[V, z_j]: so λ_j = 0 iff W_jᵀq̈₆ = q̇₆ᵀN₆[q̇₆, z_j] (with W_j, E15.9; 64 ε)", cond, tol<S>(64));
}

template <class S> void hybridLaw(Context& ctx) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
  using V3 = Vec3<S>;
  using M3 = Mat3<S>;
  using DV = DgVector<S>;
  using DM = DgMatrix<S>;
  using SM = ScrewMatrix<S>;
  using std::abs;
  auto g = std::mt19937_64(1548);
  const SpatialInertia<S> body(frac<S>(3, 2), V3(frac<S>(1, 5), frac<S>(1, 10), frac<S>(-3, 10)), M3(V3(frac<S>(3, 10), frac<S>(2, 5), frac<S>(1, 2)).asDiagonal()));
  const M6 N = body.matrix();
  DM Z = DM::Zero(6, 2);
  Z(2, 0) = Z(5, 1) = 1;  // the peg
  const HybridProjectors<S> p = n6Projectors<S>(Z, N);
  const SM J = [&] {
    const JointSpaceGeometry<S> geo(randomScrewsS<S>(g, 6));
    return SM(geo.screws(rvecS<S>(g, 6)));
  }();
  const V6 Wd = V6(castMatrix<S>(rv6(g))), qd = V6(castMatrix<S>(rv6(g))), q6 = V6(castMatrix<S>(rv6(g))), qdd = V6(castMatrix<S>(rv6(g))), q6dd = V6(castMatrix<S>(rv6(g)));
  const DV tauF = forceControlTorque<S>(p, Wd, DM(J));
  const V6 qe = hybridVelocityError<S>(p, N, qd, q6);
  const V6 qee = hybridAccelerationError<S>(p, N, qdd, q6dd, qe);
  // the same computed in a second frame (random rigid change H): torques identical, screws transform
  const SE3<S> Hs(rotationS<S>(g), V3(castMatrix<S>(rv3(g))));
  const M6 H = Hs.adjoint(), Hi = Hs.inverse().adjoint();
  const M6 N2 = H.transpose() * N * H;
  const HybridProjectors<S> p2 = n6Projectors<S>(DM(Hi * Z), N2);
  const DV tauF2 = forceControlTorque<S>(p2, V6(H.transpose() * Wd), DM(Hi * J));
  const V6 qe2 = hybridVelocityError<S>(p2, N2, V6(Hi * qd), V6(Hi * q6));
  const V6 qee2 = hybridAccelerationError<S>(p2, N2, V6(Hi * qdd), V6(Hi * q6dd), qe2);
  ctx.checkResidual("τ^f_i = Σ_{j=n+1}^{6}(W_dᵀz_j)(W_jᵀs_i): the same joint torques in two frames (4096 ε)", mx<S>(DV(tauF - tauF2)), tol<S>(4096));
  ctx.checkResidual("q̇_e = AAᵀN₆(q̇_d − q̇₆) transforms as a screw (q̇_e₂ = H⁻¹q̇_e; 4096 ε)", mx<S>(V6(qe2 - Hi * qe)), tol<S>(4096));
  ctx.checkResidual("q̈_e = AAᵀN₆(q̈_d − q̈₆) + AAᵀ{q̇_e, N₆q̇_e} (braces restored, E15.10) transforms as a screw (4096 ε)", mx<S>(V6(qee2 - Hi * qee)), tol<S>(4096));
  // the force torques do no work on the freedoms: τ^f = Jᵀ(XYW_d) and (XYW_d)ᵀz_i = 0 for i ≤ n
  const V6 Wp = p.X * (p.Y * Wd);
  ctx.checkResidual("the projected wrench does no work on the freedoms (64 ε)", mx<S>(DV(p.A.transpose() * Wp)), tol<S>(64));
  // E15.9: the printed Σ_{j=k+1}: with k = 0 (k is unbound) the sum includes the freedoms, W_d is not projected
  DM full(6, 6);
  full << p.A, p.Y.transpose();
  DM Wall(6, 6);
  Wall << DM(N * p.A), p.X;  // W_j = N₆z_j for all j
  V6 Wk0 = V6::Zero();
  for (int j = 0; j < 6; ++j) Wk0 += Wd.dot(V6(full.col(j))) * V6(Wall.col(j));
  ctx.checkPrintedFails("τ^f with Σ_{j=k+1}, k read as 0: work of the commanded wrench on the freedoms", "E15.9", mx<S>(DV(p.A.transpose() * Wk0)), tol<S>(64));
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
  const HybridProjectors<double> p = dualBasisProjectors<double>(pegFreedoms<double>(), pegComplement<double>());
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
  const HybridProjectors<double> p = n6Projectors<double>(pegFreedoms<double>(), body.matrix());
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

SOMA_STUDY_SCALAR("GF-15.4.2-constraints-natural-artificial", "Selection matrices depend on the frame (Lipkin–Duffy); AB does not", "GF §15.4.1–15.4.2", natural);
SOMA_STUDY_SCALAR("GF-15.4.3-dual-bases-projection", "Dual bases: AB and XY idempotent and complementary (finding E15.15)", "GF §15.4.3", dualBases);
SOMA_STUDY_SCALAR("GF-15.4.3-peg-in-hole", "Peg in hole: AB = diag(0,0,1,0,0,1), XY = diag(1,1,0,1,1,0) (erratum E15.7)", "GF §15.4.3", peg);
SOMA_STUDY_SCALAR("GF-15.4.3-projection-transformation", "ÃB̃ = H⁻¹(AB)H, X̃Ỹ = Hᵀ(XY)H⁻ᵀ, shifted origin (errata E15.7, E15.8)", "GF §15.4.3", transformation);
SOMA_STUDY_SCALAR("GF-15.4.4-second-fundamental-form", "N₆II(V,V): the reaction of a pinned body (erratum E15.10)", "GF §15.4.4", secondFundamental);
SOMA_STUDY_SCALAR("GF-15.4.4-N6-orthonormal-projections", "AAᵀN₆ and XXᵀN₆⁻¹ = N₆YᵀY", "GF §15.4.4", n6Orthonormal);
SOMA_STUDY_SCALAR("GF-15.4.4-constraint-multipliers", "λ_j = z_jᵀN₆V̇ + VᵀN₆[z_j, V] (erratum E15.9)", "GF §15.4.4", multipliers);
SOMA_STUDY_SCALAR("GF-15.4.4-hybrid-control-law", "The hybrid law is frame-invariant (errata E15.9, E15.10)", "GF §15.4.4", hybridLaw);
SOMA_STUDY_DOUBLE("GF-15-fig-15.1", "Fig. 15.1: hybrid control architecture", "GF §15.4.1", fig151);
SOMA_STUDY_DOUBLE("GF-15-fig-15.2", "Fig. 15.2: hybrid control with curvature compensation", "GF §15.4.4", fig152);

}  // namespace soma::studies::gf15::SOMA_UNITY_ID
