// Studies of GF §13.6 (in the asked scalar; reference derivatives in __float128 below it, in S for
// __float128 and mpfr; the two figures drawn in double from the S results): decoupled 2R designs and the quadratic
// line complex with its Kummer surface, ignorable coordinates of 2R and 3R arms, flat coordinates
// and the Gaussian curvature of a 2R inertia metric (errata 11, 12, 18–20, 23).
#include "gf13/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

#include <Eigen/Eigenvalues>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

template <class S>
SerialDynamics<S> twoR(const Vec6<S>& s1, const Vec6<S>& s2, const SpatialInertia<S>& l1, const SpatialInertia<S>& l2,
                       const S& grav = S(0)) {
  return SerialDynamics<S>({SE3Tangent<S>(s1), SE3Tangent<S>(s2)}, {l1, l2}, grav);
}
/// (x, y, z)/d in S: the exact inputs of these studies as S rounds them.
template <class S> Vec3<S> fv3(long x, long y, long z, long d = 1) { return Vec3<S>(frac<S>(x, d), frac<S>(y, d), frac<S>(z, d)); }
/// The line through r along the unit w (pitch 0), in S.
template <class S> Vec6<S> line(const Vec3<S>& w, const Vec3<S>& r) { return lineScrew<S>(w, r, S(0)); }
/// A unit vector drawn as unit3 (double, the same draws) and made unit in S.
template <class S> Vec3<S> unit3S(std::mt19937_64& g) {
  using std::sqrt;  // std's by name: __float128 has no argument-dependent lookup
  V3 v;
  do v = rv3(g);
  while (v.squaredNorm() < 1e-2 || v.squaredNorm() > 1);
  const Vec3<S> w = castMatrix<S>(v);
  return w / sqrt(w.squaredNorm());
}
/// Largest change of A over a grid of the given joint (others at 0), relative to max |A|.
template <class S> S aVariation(const SerialDynamics<S>& r, int joint) {
  DynVector<S> th = DynVector<S>::Zero(r.dof());
  const DynMatrix<S> A0 = r.massMatrix(th);
  S worst = 0;
  for (int k = 1; k <= 24; ++k) {
    th(joint) = frac<S>(-12 + k, 4);  // −3 + k/4
    worst = maxOf(worst, maxAbsOf(DynMatrix<S>(r.massMatrix(th) - A0)));
  }
  return worst / maxAbsOf(A0);
}

// Thresholds of §13.6.1–13.6.2 (1e-15 / 1e-14 / 1e-13 in the double studies): quantities that vanish
// by the exact structure of the inputs (products of axis-aligned screws with N₂) 4 ε; a 6×6 congruence
// N ↦ G⁻ᵀNG⁻¹ by a rotation and the sums of a 2R's or 3R's A, relative, 32 ε (a handful of roundings
// per entry, each ≤ ε of the largest term); the controls must miss by 1000× these.

template <class S> void decoupling(Context& ctx) {
  using std::abs;
  using std::sqrt;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  auto g = std::mt19937_64(1360);
  // s₁ along x, s₂ along z, both through the origin (s₁ ⟂ s₂); link 2 symmetric about s₂, c.o.m. on it
  const Vec6<S> s1 = line<S>(fv3<S>(1, 0, 0), Vec3<S>::Zero()), s2 = line<S>(fv3<S>(0, 0, 1), Vec3<S>::Zero());
  const SpatialInertia<S> l1 = castBody<S>(randomBody(g));
  const Mat3<S> I2 = fv3<S>(20, 20, 5, 100).asDiagonal();
  const SpatialInertia<S> l2(frac<S>(17, 10), fv3<S>(0, 0, 4, 10), I2);
  const SerialDynamics<S> r = twoR(s1, s2, l1, l2);
  const Mat6<S> N2 = l2.matrix(), Q0 = q0<S>();
  const S c1 = s2.dot(N2 * s1), c2 = s2.dot(N2 * br(s2, s1)), c3 = s2.dot(N2 * br(s2, br(s2, s1)));
  const S exact = tol<S>(4), rel = tol<S>(32);
  ctx.checkResidual("conditions s₂ᵀN₂s₁ = s₂ᵀN₂[s₂, s₁] = s₂ᵀN₂[s₂, [s₂, s₁]] = 0 (4 ε)", maxOf(S(abs(c1)), maxOf(S(abs(c2)), S(abs(c3)))), exact);
  ctx.checkResidual("revolute s₁ needs s₂ᵀN₂Q₀N₂s₂ = 0 (quadratic line complex; 4 ε)", S(abs(S(s2.dot(N2 * Q0 * N2 * s2)))), exact);
  ctx.checkResidual("and s₁ᵀN₂[s₂, s₁] = 0 (constant A; 4 ε)", S(abs(S(s1.dot(N2 * br(s2, s1))))), exact);
  ctx.checkResidual("A(θ₂) constant over θ₂ ∈ [−3, 3] (relative; 32 ε)", aVariation(r, 1), rel);
  S bmax = 0;
  const DVS th = DVS::Constant(2, frac<S>(7, 10)), thd = DVS::Constant(2, S(3)), thdd = rjointsS<S>(g, 2);
  const auto B = r.coriolisTensor(th);
  for (const DMS& b : B) bmax = maxOf(bmax, maxAbsOf(b));
  const DMS A = r.massMatrix(th);
  ctx.checkResidual("B = 0: with g = 0 the torques are linear in θ̈, τ = Aθ̈ (relative to |A|; 32 ε)", S(bmax / maxAbsOf(A)), rel);
  // RNEA's velocity terms (|θ̇|² = 9 times |N|) cancel exactly; their rounding: 64 ε |A| (|θ̇|² + |θ̈|)
  const S rneaTol = tol<S>(64) * maxAbsOf(A) * S(S(9) + maxAbsOf(thdd));
  ctx.checkResidual("RNEA at θ̇ = (3, 3) rad/s equals Aθ̈ (N·m; 64 ε |A| (|θ̇|² + |θ̈|))", maxAbsOf(DVS(r.inverseDynamics(th, thd, thdd) - A * thdd)),
                    rneaTol);
  // control: c.o.m. off the axis, or axes not perpendicular: A varies
  const SerialDynamics<S> off = twoR(s1, s2, l1, SpatialInertia<S>(frac<S>(17, 10), fv3<S>(1, 0, 4, 10), I2));
  const SerialDynamics<S> tilt = twoR(line<S>(Vec3<S>(fv3<S>(1, 0, 1) / sqrt(S(2))), Vec3<S>::Zero()), s2, l1, l2);
  ctx.checkPrintedFails("control: c.o.m. 0.1 m off s₂ — A constant", "— (control)", aVariation(off, 1), rel);
  const DVS zero = DVS::Zero(2);
  ctx.note("With s₁ tilted 45° from s₂ (same symmetric link 2) A is still independent of θ₂ (variation " +
           toString(aVariation(tilt, 1), 3) + ") but no longer diagonal: A₁₂ = s₁ᵀN₂s₂ = " +
           toString(S(tilt.massMatrix(zero)(0, 1)), 3) + " against " + toString(S(r.massMatrix(zero)(0, 1)), 3) +
           " for s₁ ⟂ s₂ — decoupling needs the perpendicularity.");
  ctx.checkEqual("tilted s₁: A diagonal?", "no", abs(S(tilt.massMatrix(zero)(0, 1))) > frac<S>(1, 1000) ? "no" : "yes");
  // three joints: a diagonal A for all θ is impossible — a random 3R is far from it, and even the decoupled 2R plus
  // a third symmetric link on s₁ ⟂ s₂ ⟂ s₃ loses diagonality as θ₂ turns s₃
  const Vec6<S> s3 = line<S>(fv3<S>(1, 0, 0), fv3<S>(0, 0, 8, 10));
  const SerialDynamics<S> r3({SE3Tangent<S>(s1), SE3Tangent<S>(s2), SE3Tangent<S>(s3)},
                             {l1, l2, SpatialInertia<S>(frac<S>(8, 10), fv3<S>(3, 0, 8, 10), Mat3<S>(fv3<S>(2, 10, 10, 100).asDiagonal()))},
                             S(0));
  S offd = 0;
  for (int k = 0; k < 12; ++k) {
    const DMS A3 = r3.massMatrix(DVS::Constant(3, frac<S>(k, 2)));
    offd = maxOf(offd, maxOf(S(abs(A3(0, 1))), maxOf(S(abs(A3(0, 2))), S(abs(A3(1, 2))))));
  }
  ctx.checkEqual("3R extension (s₁ ⟂ s₂ ⟂ s₃, symmetric links): A off-diagonal somewhere", "yes", offd > frac<S>(1, 1000) ? "yes" : "no");
}

template <class S> void kummer(Context& ctx) {
  using std::abs;
  auto g = std::mt19937_64(1361);
  S eq = 0, edet = 0, printedRatio = 0;
  int rankDrop = 0;
  for (int t = 0; t < 100; ++t) {
    const Vec3<S> d = rv3<S>(g, 0.1, 1);
    const S m = uni<S>(g, 0.5, 3);
    Mat6<S> N = Mat6<S>::Zero();
    N.template topLeftCorner<3, 3>() = d.asDiagonal();
    N.template bottomRightCorner<3, 3>() = m * Mat3<S>::Identity();
    const Vec3<S> r = rv3<S>(g), w = unit3S<S>(g);
    const Vec6<S> s = line<S>(w, r);
    const S x = r(0), y = r(1), z = r(2);
    const S complex = (d(0) - d(2)) * y * w(2) * w(0) + (d(1) - d(0)) * z * w(0) * w(1) + (d(2) - d(1)) * x * w(1) * w(2);
    eq = maxOf(eq, S(abs(S(s.dot(N * q0<S>() * N * s) - S(2) * m * complex))));
    Mat3<S> C;
    C << S(0), (d(1) - d(0)) * z, (d(0) - d(2)) * y, (d(1) - d(0)) * z, S(0), (d(2) - d(1)) * x, (d(0) - d(2)) * y, (d(2) - d(1)) * x, S(0);
    const S printed = (d(1) - d(0)) * (d(0) - d(2)) * (d(2) - d(1)) * x * y * z;
    const S det = C.determinant();
    edet = maxOf(edet, S(abs(S(det - S(2) * printed)) / abs(det)));  // det ≠ 0: x, y, z, d_i − d_j ≠ 0 for these draws
    printedRatio = maxOf(printedRatio, S(abs(S(det / printed))));
    // on a principal plane (z = 0) the conic degenerates
    Mat3<S> C0 = C;
    C0(0, 1) = C0(1, 0) = S(0);
    rankDrop += C0.determinant() == S(0);  // the cofactor expansion of a zero-pattern: exactly 0
  }
  // six products of ≤ 5 factors of size ≤ 3, summed: 64 ε (1.4e-14 in double; 1e-14 before)
  ctx.checkResidual("s₂ᵀNQ₀Ns₂ = 2m[(d₁−d₃)yω_zω_x + (d₂−d₁)zω_xω_y + (d₃−d₂)xω_yω_z] (100 random; 64 ε)", eq, tol<S>(64));
  // two products of three differences each, against one of six factors: 16 ε relative (1e-13 before)
  ctx.checkResidual("det of the conic = 2(d₂−d₁)(d₁−d₃)(d₃−d₂)xyz (relative; 16 ε)", edet, tol<S>(16));
  ctx.checkNear("printed Kummer determinant (d₂−d₁)(d₁−d₃)(d₃−d₂)xyz: off by the factor (erratum 23, harmless; 2 · 16 ε)", S(2),
                printedRatio, tol<S>(32));
  ctx.checkEqual("conic degenerate on the principal plane z = 0 (Kummer surface = the three planes)", 100, rankDrop);
}

/// Skew-line 2R of §13.6.2: s₂ = (i, 0), s₁ = (cosφ i − sinφ j, l sinφ i + l cosφ j).
template <class S> Vec6<S> skewS1(const S& phi, const S& l) {
  using std::cos;
  using std::sin;
  Vec6<S> s;
  s << cos(phi), -sin(phi), S(0), l * sin(phi), l * cos(phi), S(0);
  return s;
}
template <class S> SpatialInertia<S> symmetricAboutX(const S& m, const S& cx, const S& i11, const S& i22) {
  return SpatialInertia<S>(m, Vec3<S>(cx, S(0), S(0)), Mat3<S>(Vec3<S>(i11, i22, i22).asDiagonal()));
}
template <class S> S dAdTheta2(const SerialDynamics<S>& r) {
  using std::abs;
  // max over a grid of |∂A/∂θ₂| via the closed form ∂A₁₁ = −2s₁ᵀN₂[s₂, s₁], ∂A₁₂ = −s₂ᵀN₂[s₂, s₁] (2R)
  S worst = 0;
  for (int k = 0; k < 24; ++k) {
    DynVector<S> th(2);
    th << frac<S>(3, 10), frac<S>(-12 + k, 4);
    const auto c = r.configuration(th);
    const Vec6<S>&s1 = c.screws[0], &s2 = c.screws[1];
    const Mat6<S>& N2 = c.inertias[1];
    worst = maxOf(worst, maxOf(S(abs(S(S(2) * s1.dot(N2 * br(s2, s1))))), S(abs(S(s2.dot(N2 * br(s2, s1)))))));
  }
  return worst;
}

template <class S> void ignorable2R(Context& ctx) {
  using std::abs;
  using R = Ref<S>;
  auto g = std::mt19937_64(1362);
  const S phi = frac<S>(7, 10), l = frac<S>(1, 2);
  const Vec6<S> s1 = skewS1(phi, l), s2 = line<S>(fv3<S>(1, 0, 0), Vec3<S>::Zero());
  const SpatialInertia<S> l1 = castBody<S>(randomBody(g)), l2 = symmetricAboutX(frac<S>(13, 10), frac<S>(4, 10), frac<S>(5, 100), frac<S>(2, 10));
  const SerialDynamics<S> r = twoR(s1, s2, l1, l2);
  const Mat6<S> N2 = l2.matrix();
  const S exact = tol<S>(4), rel = tol<S>(32);
  ctx.checkResidual("solution N₂ (rotationally symmetric about s₂): ad(s₂)ᵀN₂ + N₂ad(s₂) = 0 (4 ε)",
                    maxAbsOf(Mat6<S>(adm(s2).transpose() * N2 + N2 * adm(s2))), exact);
  ctx.checkResidual("A independent of θ₂ over a grid (relative; 32 ε)", aVariation(r, 1), rel);
  ctx.checkResidual("∂A₁₁/∂θ₂ = −2s₁ᵀN₂[s₂, s₁] = 0 and ∂A₁₂/∂θ₂ = −s₂ᵀN₂[s₂, s₁] = 0 on the grid (32 ε)", dAdTheta2(r), rel);
  // the closed forms of ∂A/∂θ₂ against differences, on a generic N₂ where they do not vanish
  const SerialDynamics<S> gen = twoR(s1, s2, l1, castBody<S>(randomBody(g)));
  const SerialDynamics<R> genR = castRobotUnit<R>(gen);
  DynVector<S> th(2);
  th << frac<S>(3, 10), frac<S>(9, 10);
  const auto c = gen.configuration(th);
  const S fd11 = refDiff<S>([&](const R& u) {
    DynVector<R> a = castV<R>(th);
    a(1) += u;
    return R(genR.massMatrix(a)(0, 0));
  });
  // a 2R's bracket and congruence: 64 ε (1.4e-14 in double; 1e-12 before), plus the difference bound
  ctx.checkNear(std::string("generic N₂: ∂A₁₁/∂θ₂ = −2s₁ᵀN₂[s₂, s₁] (vs ") + refHow<S>() + "; 64 ε + difference bound)", fd11,
                S(S(-2) * c.screws[0].dot(c.inertias[1] * br(c.screws[1], c.screws[0]))), S(tol<S>(64) + refTol<S>()));
  ctx.checkPrintedFails("generic N₂: θ₂ ignorable", "— (control)", dAdTheta2(gen), rel);
  // the six coefficient equations: their solution family is exactly 'symmetric about s₂, c on s₂'
  const S m13 = frac<S>(13, 10);
  const SpatialInertia<S> breakI(m13, fv3<S>(4, 0, 0, 10), Mat3<S>(fv3<S>(5, 20, 25, 100).asDiagonal()));  // I₂₂ ≠ I₃₃
  const SpatialInertia<S> breakC(m13, fv3<S>(4, 1, 0, 10), Mat3<S>(fv3<S>(5, 20, 20, 100).asDiagonal()));  // c_y ≠ 0
  ctx.checkPrintedFails("I₂₂ ≠ I₃₃ (violates (I₃₃ − I₂₂)sin²φ = 0): θ₂ ignorable", "— (control)", dAdTheta2(twoR(s1, s2, l1, breakI)), rel);
  ctx.checkPrintedFails("c_y ≠ 0 (violates −I₁₃cosφ sinφ + mlc_y = 0): θ₂ ignorable", "— (control)", dAdTheta2(twoR(s1, s2, l1, breakC)), rel);
  // the printed general N₂ (line 8488): last row (mc_x, −mc_x, 0, …) is not symmetric with column 6
  const S m = m13, cx = frac<S>(4, 10), cy = frac<S>(-2, 10);
  const S printedRow6[3] = {S(m * cx), S(-m * cx), S(0)}, column6[3] = {S(m * cy), S(-m * cx), S(0)};
  ctx.checkPrintedFails("general N₂ as printed is symmetric (N₆₁ = N₁₆)", "18", S(abs(S(printedRow6[0] - column6[0]))), exact);
  ctx.note("θ₁ is always ignorable (nothing depends on it). Line 8463 writes N_s for N₂ (erratum 19).");
}

template <class S> void ignorableIIAIIB(Context& ctx) {
  using std::abs;
  auto g = std::mt19937_64(1363);
  const SpatialInertia<S> l1 = castBody<S>(randomBody(g));
  // IIA (l = 0, intersecting axes): I off-diagonal zero, I₂₂ = I₃₃ about the c.o.m. frame at the ORIGIN; c free
  // The condition is on the inertia about the intersection point: I_origin = I_c − mC² must be diag(I₁₁, I₂₂, I₂₂).
  const S phi = frac<S>(9, 10);
  const Vec6<S> s1 = skewS1(phi, S(0)), s2 = line<S>(fv3<S>(1, 0, 0), Vec3<S>::Zero());
  const Vec3<S> c = fv3<S>(20, -30, 25, 100);
  const S m = frac<S>(11, 10);
  const Mat3<S> C = skew(c);
  const Mat3<S> Iorigin = fv3<S>(5, 8, 8, 10).asDiagonal();  // I_c = I_origin + mC² must stay positive definite
  const SpatialInertia<S> lA(m, c, Mat3<S>(Iorigin + m * C * C));  // I_c = I_origin + mC²
  const S exact = tol<S>(4), rel = tol<S>(32);
  ctx.checkResidual("IIA (l = 0): I₁₂ = I₁₃ = I₂₃ = 0, I₂₂ = I₃₃ about the origin, c.o.m. off s₂: θ₂ ignorable (32 ε)",
                    dAdTheta2(twoR(s1, s2, l1, lA)), rel);
  S so3 = 0;
  const Mat6<S> N = lA.matrix(), Qm = adm(s2).transpose() * N + N * adm(s2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Vec6<S> a = Vec6<S>::Zero(), b = Vec6<S>::Zero();
      a(i) = 1;
      b(j) = 1;
      so3 = maxOf(so3, S(abs(S(a.dot(Qm * b)))));
    }
  // N's upper block I_c − mC² = I_origin recovers the diagonal to the rounding of mC²: 32 ε
  ctx.checkResidual("equivalently s_iᵀQs_j = 0 for all s_i, s_j ∈ so(3) (Q = ad(s₂)ᵀN₂ + N₂ad(s₂); 32 ε)", so3, rel);
  // IIB (φ = 0, parallel axes): c.o.m. on s₂, 3×3 inertia unrestricted
  const Vec6<S> p1 = skewS1(S(0), frac<S>(6, 10));
  const SpatialInertia<S> any = castBody<S>(randomBody(g));
  const SpatialInertia<S> lB(any.mass(), fv3<S>(35, 0, 0, 100), any.inertiaAboutCentre());
  ctx.checkResidual("IIB (φ = 0): c.o.m. on s₂, arbitrary 3×3 inertia: θ₂ ignorable (32 ε)", dAdTheta2(twoR(p1, s2, l1, lB)), rel);
  S se2 = 0;
  const Mat6<S> NB = lB.matrix(), QB = adm(s2).transpose() * NB + NB * adm(s2);
  // se(2) of the plane ⟂ s₂ (x): rotations about x, translations along y, z
  std::vector<Vec6<S>> basis(3, Vec6<S>::Zero());
  basis[0](0) = 1;
  basis[1](4) = 1;
  basis[2](5) = 1;
  for (const Vec6<S>& a : basis)
    for (const Vec6<S>& b : basis) se2 = maxOf(se2, S(abs(S(a.dot(QB * b)))));
  ctx.checkResidual("equivalently s_iᵀQs_j = 0 over se(2) (4 ε)", se2, exact);
  const SpatialInertia<S> lB2(any.mass(), fv3<S>(35, 10, 0, 100), any.inertiaAboutCentre());
  ctx.checkPrintedFails("IIB with c.o.m. 0.1 m off s₂: θ₂ ignorable", "— (control)", dAdTheta2(twoR(p1, s2, l1, lB2)), rel);
  ctx.note("Lines 8518, 8530 write s_i, s_i ∈ so(3) and s_iᵀ(…)s_i for s_i, s_j (erratum 19).");
}

template <class S> void ignorable3R(Context& ctx) {
  using std::abs;
  using std::cos;
  using std::sin;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  auto g = std::mt19937_64(1364);
  // s₁ ∥ s₂ (z axes through (0,0,0) and (1,0,0)); s₃ along x through (1, 0, 0.3) on the joint-2 axis
  const Vec6<S> s1 = line<S>(fv3<S>(0, 0, 1), Vec3<S>::Zero()), s2 = line<S>(fv3<S>(0, 0, 1), fv3<S>(1, 0, 0));
  const Vec6<S> s3 = line<S>(fv3<S>(1, 0, 0), fv3<S>(10, 0, 3, 10));
  const S m2 = 2, m3 = frac<S>(8, 10), e = frac<S>(1, 2);
  const SpatialInertia<S> l3(m3, Vec3<S>(S(1) + e, S(0), frac<S>(3, 10)), Mat3<S>(fv3<S>(1, 8, 8, 100).asDiagonal()));  // symmetric about s₃
  const SpatialInertia<double> l2b = randomBody(g);
  const SpatialInertia<S> l2(m2, Vec3<S>(S(1) - m3 * e / m2, S(0), frac<S>(1, 10)), castMatrix<S>(l2b.inertiaAboutCentre()));  // composite c.o.m. on s₂
  const SerialDynamics<S> r({SE3Tangent<S>(s1), SE3Tangent<S>(s2), SE3Tangent<S>(s3)}, {castBody<S>(randomBody(g)), l2, l3}, S(0));
  const Vec3<S> comp = (m2 * l2.centreOfMass() + m3 * l3.centreOfMass()) / (m2 + m3);
  const S exact = tol<S>(4), rel = tol<S>(32);
  ctx.checkResidual("composite c.o.m. of links 2 + 3 on the joint-2 axis (distance; 4 ε)", S(Vec3<S>(comp - Vec3<S>(S(1), S(0), comp(2))).norm()), exact);
  ctx.checkResidual("θ₃ ignorable: A independent of θ₃ (relative; 32 ε)", aVariation(r, 2), rel);
  ctx.checkResidual("θ₂ ignorable: A independent of θ₂ (relative; 32 ε)", aVariation(r, 1), rel);
  S both = 0;
  const DMS A0 = r.massMatrix(DVS::Zero(3));
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      DVS th(3);
      th << S(0), frac<S>(-30 + 8 * a, 10), frac<S>(-30 + 8 * b, 10);
      both = maxOf(both, maxAbsOf(DMS(r.massMatrix(th) - A0)));
    }
  ctx.checkResidual("A constant over an 8 × 8 (θ₂, θ₃) grid (relative; 32 ε)", S(both / maxAbsOf(A0)), rel);
  const SpatialInertia<S> l2off(m2, Vec3<S>(S(1) - m3 * e / m2 + frac<S>(1, 10), S(0), frac<S>(1, 10)), castMatrix<S>(l2b.inertiaAboutCentre()));
  const SerialDynamics<S> bad({SE3Tangent<S>(s1), SE3Tangent<S>(s2), SE3Tangent<S>(s3)}, {castBody<S>(randomBody(g)), l2off, l3}, S(0));
  ctx.checkPrintedFails("control: composite c.o.m. 0.1 m off the joint-2 axis: θ₂ ignorable", "— (control)", aVariation(bad, 1), rel);
  // the brackets of the skew case: [s₂, s] = (0, I₁₁ sinφ k), [s₂, [s₂, s]] = (0, −I₁₁ sinφ (sinφ i + cosφ j))
  const S phi = frac<S>(8, 10), l = frac<S>(4, 10), I11 = frac<S>(7, 100);
  const Vec6<S> t2 = skewS1(phi, l);
  const Mat6<S> N3 = symmetricAboutX(S(1), frac<S>(3, 10), I11, frac<S>(2, 10)).matrix();
  const Vec6<S> s = q0<S>() * N3 * line<S>(fv3<S>(1, 0, 0), Vec3<S>::Zero());
  Vec6<S> w1, w2;
  w1 << S(0), S(0), S(0), S(0), S(0), I11 * sin(phi);
  w2 << S(0), S(0), S(0), -I11 * sin(phi) * sin(phi), -I11 * sin(phi) * cos(phi), S(0);
  // one or two products with sinφ, cosφ of entries ≤ I₁₁: 4 ε I₁₁ (6.2e-17 in double; 1e-16 before)
  ctx.checkResidual("[s₂, s] = (0, I₁₁ sinφ k), s = Q₀N₃s₃ (4 ε I₁₁)", S((br(t2, s) - w1).norm()), S(exact * I11));
  ctx.checkResidual("[s₂, [s₂, s]] = (0, −I₁₁ sinφ (sinφ i + cosφ j)) (4 ε I₁₁)", S((br(t2, br(t2, s)) - w2).norm()), S(exact * I11));
}

// Nested reference differences (a second derivative, or a derivative of differenced K): the outer
// 8th-order difference of the inner one. Below __float128 both in __float128 at d = 2⁻⁸ (truncation
// d⁸|f⁽¹⁰⁾|/630 ≈ 1e-22 |f⁽¹⁰⁾|, the inner rounding 1e-31 over d: below long double's ε); in __float128
// and mpfr the inner at ε^(1/9) (error ≈ ε^(8/9)) and the outer at ε^(8/81), where its truncation
// d⁸ and the inner error over d are both ε^(64/81): bound 4096 ε^(64/81).
template <class S> Ref<S> nestedStep() {
  if constexpr (kWideRef<S>) {
    return Q(1) / Q(256);
  } else {
    using std::pow;
    return pow(Tolerance<S>::epsilon(), S(8) / S(81));
  }
}
template <class S> S nestedTol() {
  if constexpr (kWideRef<S>) {
    return S(0);
  } else {
    using std::pow;
    return S(4096) * pow(Tolerance<S>::epsilon(), S(64) / S(81));
  }
}
/// f''(0) for f: Ref<S> → Ref<S>, as S (nested diff8).
template <class S, class F> S refDiff2(F&& f) {
  using R = Ref<S>;
  return scalarCast<S>(diff8<R>([&](const R& u) { return diff8<R>([&](const R& v) { return R(f(R(u + v))); }, refStep<S>()); }, nestedStep<S>()));
}

template <class S> void flat(Context& ctx) {
  using std::abs;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  using R = Ref<S>;
  auto g = std::mt19937_64(1365);
  // decoupled 2R of GF-13.6.1: A constant, φ = A^{1/2}θ, K = A^{1/2}, φ̈ = K⁻ᵀτ
  const Vec6<S> s1 = line<S>(fv3<S>(1, 0, 0), Vec3<S>::Zero()), s2 = line<S>(fv3<S>(0, 0, 1), Vec3<S>::Zero());
  const SerialDynamics<S> r =
      twoR(s1, s2, castBody<S>(randomBody(g)), SpatialInertia<S>(frac<S>(17, 10), fv3<S>(0, 0, 4, 10), Mat3<S>(fv3<S>(20, 20, 5, 100).asDiagonal())));
  const DMS A = r.massMatrix(DVS::Zero(2));
  const Eigen::SelfAdjointEigenSolver<DMS> es(A);
  const DMS K = es.operatorSqrt();
  S worst = 0;
  for (int t = 0; t < 20; ++t) {
    const DVS th = rjointsS<S>(g, 2, -3, 3), thd = rjointsS<S>(g, 2, -3, 3), tau = rjointsS<S>(g, 2, -2, 2);
    const DVS phidd = K * r.forwardDynamics(th, thd, tau);
    worst = maxOf(worst, maxAbsOf(DVS(phidd - K.transpose().partialPivLu().solve(tau))));
  }
  // forward dynamics solves Aθ̈ = τ − h, h's velocity terms (|θ̇|² ≤ 9 times |A|) cancelling to rounding:
  // θ̈ errs by 64 ε (|τ| + 9 λ_max)/λ_min, φ̈ = Kθ̈ by √λ_max times that (1e-13 before)
  using std::sqrt;
  const S lmin = es.eigenvalues()(0), lmax = es.eigenvalues()(1);
  const S flatTol = tol<S>(64) * (S(2) + S(9) * lmax) * sqrt(lmax) / lmin;
  ctx.checkResidual("decoupled 2R, φ = A^{1/2}θ: φ̈ = (Kᵀ)⁻¹τ at any θ, θ̇ (20 random states; 64 ε (|τ| + |θ̇|²λ_max)√λ_max/λ_min)",
                    worst, flatTol);
  // B_ijk = K_li ∂_kK_lj for A = KᵀK, K = ∂φ/∂θ, φ nonlinear (3 dof), nested reference differences
  auto phi = [](const DynVector<R>& t) {
    using std::cos;
    using std::sin;
    DynVector<R> f(3);
    f(0) = t(0) + R(3) / R(10) * sin(t(1));
    f(1) = t(1) + R(2) / R(10) * t(0) * t(2);
    f(2) = t(2) + R(1) / R(4) * cos(t(0));
    return f;
  };
  const DynVector<R> t0 = castV<R>(rjoints(g, 3));
  auto Kat = [&](const DynVector<R>& t) {
    DynMatrix<R> Km(3, 3);
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l)
        Km(l, j) = diff8<R>([&](const R& u) {
          DynVector<R> a = t;
          a(j) += u;
          return R(phi(a)(l));
        }, refStep<S>());
    return Km;
  };
  auto Aat = [&](const DynVector<R>& t) {
    const DynMatrix<R> Km = Kat(t);
    return DynMatrix<R>(Km.transpose() * Km);
  };
  std::vector<DMS> dA, dK;
  for (int k = 0; k < 3; ++k) {
    DMS a(3, 3), kk(3, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        a(i, j) = scalarCast<S>(diff8<R>([&](const R& u) {
          DynVector<R> x = t0;
          x(k) += u;
          return R(Aat(x)(i, j));
        }, nestedStep<S>()));
        kk(i, j) = scalarCast<S>(diff8<R>([&](const R& u) {
          DynVector<R> x = t0;
          x(k) += u;
          return R(Kat(x)(i, j));
        }, nestedStep<S>()));
      }
    dA.push_back(a);
    dK.push_back(kk);
  }
  const DMS K0 = castMatrix<S>(DynMatrix<R>(Kat(t0)));
  S e = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const S chr = (dA[std::size_t(k)](i, j) + dA[std::size_t(j)](i, k) - dA[std::size_t(i)](j, k)) / S(2);
        S rhs = 0;
        for (int l = 0; l < 3; ++l) rhs += K0(l, i) * dK[std::size_t(k)](l, j);
        e = maxOf(e, S(abs(S(chr - rhs))));
      }
  // sums of three O(1) products in S: 16 ε (3.6e-15 in double; 1e-12 before), plus the nested bound
  ctx.checkResidual(std::string("½(∂_kA_ij + ∂_jA_ik − ∂_iA_jk) = K_li ∂_kK_lj for A = KᵀK, K = ∂φ/∂θ (nested differences, ") +
                        (kWideRef<S> ? "in __float128" : "in S") + "; 16 ε + nested bound)",
                    e, S(tol<S>(16) + nestedTol<S>()));
  ctx.note("Lines 8590, 8610, 8626 print K_ij = ∂φ_i/∂θ_i, π_i = K_jiφ̇_i, B_iikθ̇_iθ̇_k = K̇_iiσ_i (erratum 20); the "
           "identities checked use ∂φ_i/∂θ_j and B_jikθ̇_jθ̇_k = K̇_jiσ_j.");
}

/// Brioschi curvature of a metric (E, F, G) depending on v = θ₂ only (u = θ₁ derivatives zero).
template <class S> S brioschi(const S& E, const S& F, const S& G, const S& Ev, const S& Fv, const S& Gv, const S& Evv) {
  Mat3<S> M1, M2;
  const S half = frac<S>(1, 2);
  M1 << -half * Evv, S(0), -half * Ev, Fv, E, F, half * Gv, F, G;
  M2 << S(0), half * Ev, S(0), half * Ev, E, F, S(0), F, G;
  const S den = E * G - F * F;
  return (M1.determinant() - M2.determinant()) / (den * den);
}

/// The 2R inertia metric E = A₁₁, F = A₁₂, G = A₂₂ at θ₂ and its θ₂-derivatives (A does not
/// depend on θ₁), Δ = EG − F² with Δ', Δ'': reference differences (refDiff, refDiff2) on the robot in R.
template <class S> struct MetricJet {
  S e, f, g, ev, fv, gv, evv, d, dp, dpp;
};
template <class S> MetricJet<S> metricJet(const SerialDynamics<Ref<S>>& rq, const S& th2, bool withDelta = true) {
  using R = Ref<S>;
  auto Aq = [&](const R& u) {
    DynVector<R> a(2);
    a << R(0), R(scalarCast<R>(th2) + u);
    return DynMatrix<R>(rq.massMatrix(a));
  };
  auto E = [&](const R& u) { return R(Aq(u)(0, 0)); };
  auto Det = [&](const R& u) {
    const DynMatrix<R> A = Aq(u);
    return R(A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1));
  };
  const DynMatrix<R> A0 = Aq(R(0));
  MetricJet<S> j{};
  j.e = scalarCast<S>(A0(0, 0));
  j.f = scalarCast<S>(A0(0, 1));
  j.g = scalarCast<S>(A0(1, 1));
  j.ev = refDiff<S>(E);
  j.fv = refDiff<S>([&](const R& u) { return R(Aq(u)(0, 1)); });
  j.gv = refDiff<S>([&](const R& u) { return R(Aq(u)(1, 1)); });
  j.evv = refDiff2<S>(E);
  j.d = j.e * j.g - j.f * j.f;
  if (withDelta) {  // Δ', Δ'' (not needed for the curvature alone)
    j.dp = refDiff<S>(Det);
    j.dpp = refDiff2<S>(Det);
  }
  return j;
}
template <class S> S brioschi(const MetricJet<S>& j) { return brioschi(j.e, j.f, j.g, j.ev, j.fv, j.gv, j.evv); }

/// The random 2R of GF-13.6.3 (no gravity): drawn in double, its axes made unit in S.
template <class S> SerialDynamics<S> curvature2R() {
  auto g = std::mt19937_64(1366);
  const Vec3<S> u1 = unit3S<S>(g), p1 = rv3<S>(g), u2 = unit3S<S>(g), p2 = rv3<S>(g);  // named: a fixed draw order
  const Vec6<S> s1 = line<S>(u1, p1);
  const Vec6<S> s2 = line<S>(u2, p2);
  const SpatialInertia<S> l1 = castBody<S>(randomBody(g));
  const SpatialInertia<S> l2 = castBody<S>(randomBody(g));
  return twoR(s1, s2, l1, l2);
}

template <class S> void gaussian(Context& ctx) {
  using std::abs;
  using R = Ref<S>;
  using V6S = Vec6<S>;
  const SerialDynamics<S> r = curvature2R<S>();
  const SerialDynamics<R> rq = curvature2R<R>();
  const S t2 = frac<S>(6, 10);
  const MetricJet<S> j = metricJet<S>(rq, t2);
  const S gg = j.g, Ev = j.ev, Evv = j.evv, D = j.d, Dp = j.dp, Dpp = j.dpp;
  const S Kb = brioschi(j);
  const S one = 1;
  // single reference derivatives of a 2R's A (entries O(1)): 64 ε + the difference bound (1e-14 before)
  ctx.checkResidual(std::string("A₂₂ = s₂ᵀN₂s₂ independent of θ₂ (") + refHow<S>() + "; 64 ε + difference bound)", S(abs(j.gv)),
                    S(tol<S>(64) + refTol<S>()));
  // Δ', Δ'' from the book's screw formulas at the current configuration
  DynVector<S> th(2);
  th << S(0), t2;
  const auto c = r.configuration(th);
  const V6S &s1 = c.screws[0], &s2 = c.screws[1];
  const Mat6<S>& N2 = c.inertias[1];
  const S a22 = s2.dot(N2 * s2), a12 = s1.dot(N2 * s2);
  const S DpBook = S(2) * s1.dot(N2 * br(s1, s2)) * a22 - S(2) * s2.dot(N2 * br(s1, s2)) * a12;
  auto DppBook = [&](const S& k) {
    const S b = s2.dot(N2 * br(s1, s2));
    return S(k * s1.dot(N2 * br(s2, br(s2, s1))) * a22 + k * br(s2, s1).dot(N2 * br(s2, s1)) * a22 -
             S(2) * s2.dot(N2 * br(s2, br(s2, s1))) * a12 - S(2) * b * b);
  };
  // products of a 2R's brackets and A entries: 512 ε (1.1e-13 in double; 1e-12 before) resp. 4096 ε for Δ''
  // (1e-11), relative to max(1, |Δ'|), plus the difference bounds
  const S tolDp = (tol<S>(512) + refTol<S>()) * maxOf(one, S(abs(Dp))), tolDpp = (tol<S>(4096) + nestedTol<S>()) * maxOf(one, S(abs(Dpp)));
  ctx.checkNear("Δ' = 2(s₁ᵀN₂[s₁,s₂])(s₂ᵀN₂s₂) − 2(s₂ᵀN₂[s₁,s₂])(s₁ᵀN₂s₂) vs differences (512 ε + difference bound)", Dp, DpBook, tolDp);
  ctx.checkNear("Δ'' with coefficients 2, 2 (corrected, erratum 12) vs differences (4096 ε + nested bound)", Dpp, DppBook(S(2)), tolDpp);
  ctx.checkPrintedFails("Δ'' with coefficients 4, 4 (line 8691)", "12", S(abs(S(DppBook(S(4)) - Dpp)) / maxOf(one, S(abs(Dpp)))),
                        S(tolDpp / maxOf(one, S(abs(Dpp)))));
  const S Kc = (Ev * Dp - S(2) * D * Evv) / (S(4) * D * D);
  const S Kp = gg / S(4) * (S(2) * D * Dpp - S(3) * Dp * Dp) / (D * D);
  // K from 3×3 determinants of the jet over Δ²: relative 4096 ε plus the nested bound (1e-10 before)
  const S tolK = (tol<S>(4096) + nestedTol<S>()) * maxOf(one, S(abs(Kb)));
  ctx.checkNear("K(A) = (A₁₁'Δ' − 2ΔA₁₁'')/(4Δ²) (corrected) = Brioschi curvature of A (4096 ε + nested bound)", Kb, Kc, tolK);
  ctx.checkPrintedFails("K = (A₂₂/4)(2ΔΔ'' − 3Δ'²)/Δ² (line 8677) vs Brioschi K(A)", "11", S(abs(S(Kp - Kb)) / abs(Kb)),
                        S(tolK / maxOf(one, S(abs(Kb)))));
  // the printed K is the curvature of A⁻¹. Its jet from A's: (A⁻¹)' = −A⁻¹A'A⁻¹, (A⁻¹)'' = 2A⁻¹A'A⁻¹A'A⁻¹ −
  // A⁻¹A''A⁻¹ (A and its reference derivatives are trigonometric polynomials of degree 2 in θ₂; A⁻¹ is
  // rational, and its own differences carried the truncation of 1/Δ's complex poles: 1.5e-14 in double,
  // 1.6e-14 in long double, 3.4e-22 in __float128 against 4096 ε)
  auto Aentry = [&](int a, int b) {
    return [&rq, &t2, a, b](const R& u) {
      DynVector<R> x(2);
      x << R(0), R(scalarCast<R>(t2) + u);
      return R(rq.massMatrix(x)(a, b));
    };
  };
  Mat2<S> A0, A1, A2;
  A0 << j.e, j.f, j.f, j.g;
  A1 << j.ev, j.fv, j.fv, j.gv;
  const S fvv = refDiff2<S>(Aentry(0, 1)), gvv = refDiff2<S>(Aentry(1, 1));
  A2 << j.evv, fvv, fvv, gvv;
  const Mat2<S> B0 = A0.inverse(), B1 = -B0 * A1 * B0, B2 = S(2) * B0 * A1 * B0 * A1 * B0 - B0 * A2 * B0;
  const S Kinv = brioschi(B0(0, 0), B0(0, 1), B0(1, 1), B1(0, 0), B1(0, 1), B1(1, 1), B2(0, 0));
  // the same determinants for A⁻¹, whose entries are A's over Δ: 4096 ε relative (1e-9 before)
  ctx.checkNear("the printed K equals the Brioschi curvature of A⁻¹ (μ₁, μ₂ orthonormal for A⁻¹; its jet from A's; 4096 ε + "
                "nested bound)", Kinv, Kp, S((tol<S>(4096) + nestedTol<S>()) * maxOf(one, S(abs(Kinv)))));
  if (ctx.makeFigures()) {
    // K(θ₂) over a turn, computed in S and drawn in double: Brioschi K(A), the corrected closed form,
    // the printed formula (= K(A⁻¹))
    std::vector<double> ts, kb, kc, kp;
    for (int k = 0; k <= 72; ++k) {
      const S th2 = -pi<S>() + S(2) * pi<S>() * S(k) / S(72);
      const MetricJet<S> m = metricJet<S>(rq, th2);
      ts.push_back(toDouble(th2));
      kb.push_back(toDouble(brioschi(m)));
      kc.push_back(toDouble(S((m.ev * m.dp - S(2) * m.d * m.evv) / (S(4) * m.d * m.d))));
      kp.push_back(toDouble(S(m.g / S(4) * (S(2) * m.d * m.dpp - S(3) * m.dp * m.dp) / (m.d * m.d))));
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
           "printed formula " + toString(Kp, 6) + "; Δ'' = " + toString(Dpp, 6) + " (differences), printed " + toString(DppBook(S(4)), 6) + ".");
}


/// ∂A/∂θ_l (l = 0, 1) by the five-point stencil at h = ε^(1/5): truncation h⁴|A⁽⁵⁾|/30, rounding
/// ≈ 1.5 ε|A|/h, both ≈ ε^(4/5) (|A⁽⁵⁾| ≤ 32|A|: A's entries have frequencies ≤ 2 in θ₂) —
/// independent of the recursive dynamics that rk4Step uses. (h = 1e-3 in the double study, 7.4e-4 now.)
template <class S> std::array<DynMatrix<S>, 2> massMatrixGradient(const SerialDynamics<S>& r, const DynVector<S>& th) {
  const S h = Tolerance<S>::precision(4);
  std::array<DynMatrix<S>, 2> dA;
  for (int l = 0; l < 2; ++l) {
    auto at = [&](const S& t) {
      DynVector<S> a = th;
      a(l) += t;
      return r.massMatrix(a);
    };
    dA[std::size_t(l)] = (S(8) * (at(h) - at(S(-h))) - (at(S(2) * h) - at(S(-2) * h))) / (S(12) * h);
  }
  return dA;
}
/// θ̈^i = −Γ^i_jk θ̇^jθ̇^k with Γ^i_jk = ½A^{il}(∂_jA_lk + ∂_kA_lj − ∂_lA_jk): the geodesic equation
/// of the kinetic-energy metric written from A alone. GF §13.4.2 (B = Christoffel symbols of A)
template <class S> DynVector<S> christoffelAcceleration(const SerialDynamics<S>& r, const DynVector<S>& th, const DynVector<S>& v) {
  const std::array<DynMatrix<S>, 2> dA = massMatrixGradient(r, th);
  DynVector<S> lower = DynVector<S>::Zero(2);  // Γ_ljk θ̇^jθ̇^k
  for (int l = 0; l < 2; ++l)
    for (int jj = 0; jj < 2; ++jj)
      for (int k = 0; k < 2; ++k)
        lower(l) += (dA[std::size_t(jj)](l, k) + dA[std::size_t(k)](l, jj) - dA[std::size_t(l)](jj, k)) * v(jj) * v(k) / S(2);
  return -r.massMatrix(th).ldlt().solve(lower);
}
template <class S> struct Geodesic {
  std::vector<DynVector<S>> theta, thetaDot;
};
/// n RK4 steps of length h on the Christoffel form (theta, thetaDot sampled at every step).
template <class S> Geodesic<S> christoffelGeodesic(const SerialDynamics<S>& r, DynVector<S> th, DynVector<S> v, const S& h, int n) {
  using DVS = DynVector<S>;
  Geodesic<S> out{{th}, {v}};
  const S half = h / S(2);
  for (int k = 0; k < n; ++k) {
    const DVS a1 = christoffelAcceleration(r, th, v);
    const DVS a2 = christoffelAcceleration(r, DVS(th + half * v), DVS(v + half * a1));
    const DVS a3 = christoffelAcceleration(r, DVS(th + half * DVS(v + half * a1)), DVS(v + half * a2));
    const DVS a4 = christoffelAcceleration(r, DVS(th + h * DVS(v + half * a2)), DVS(v + h * a3));
    th += h * v + h * h / S(6) * (a1 + a2 + a3);
    v += h / S(6) * (a1 + S(2) * a2 + S(2) * a3 + a4);
    out.theta.push_back(th);
    out.thetaDot.push_back(v);
  }
  return out;
}
/// Free motion without gravity (τ = 0) by the library's RK4 on the recursive dynamics.
template <class S> Geodesic<S> freeMotion(const SerialDynamics<S>& r, const DynVector<S>& th, const DynVector<S>& v, const S& h, int n) {
  JointState<S> y{th, v};
  Geodesic<S> out{{th}, {v}};
  for (int k = 0; k < n; ++k) {
    y = rk4Step<S>(r, y, h, DynVector<S>::Zero(2));
    out.theta.push_back(y.theta);
    out.thetaDot.push_back(y.thetaDot);
  }
  return out;
}

// Derived figure (GF §13.4.2, §13.6.3): free motion of the 2R of GF-13.6.3 without gravity runs on
// the geodesics of the kinetic-energy metric A; they bend where K ≠ 0 and spread by the Jacobi
// equation J'' + KJ = 0. Computed in S, the figure drawn in double from the S geodesics.
template <class S> void geodesics2R(Context& ctx) {
  using std::abs;
  using std::cos;
  using std::log2;
  using std::sin;
  using std::sqrt;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  const SerialDynamics<S> r = curvature2R<S>();
  const SerialDynamics<Ref<S>> rq = curvature2R<Ref<S>>();
  DVS th0(2);
  th0 << S(0), frac<S>(6, 10);
  const Eigen::LLT<DMS> chol(r.massMatrix(th0));
  const DMS Lt = chol.matrixU();  // A = UᵀU: θ̇ = U⁻¹u has θ̇ᵀAθ̇ = |u|²
  auto direction = [&](const S& phi) {
    const DVS u = Vec2<S>(cos(phi), sin(phi));
    return DVS(Lt.template triangularView<Eigen::Upper>().solve(u));
  };
  const S T = frac<S>(3, 2);
  constexpr int n = 300;
  const S h = T / S(n);
  // 1. two formulations of the same motion agree: recursive dynamics vs Christoffel symbols of A. In
  // __float128 and mpfr without figures over 4 of the 16 directions (every fourth: the bound below is
  // per geodesic, the same for any number of them), to keep the run under a minute
  const int fan = kWideRef<S> || ctx.makeFigures() ? 16 : 4;
  std::vector<Geodesic<S>> free, chr;
  S agree = 0, drift = 0;
  for (int k = 0; k < fan; ++k) {
    const DVS v0 = direction(S(2) * pi<S>() * S(k) / S(fan));  // k/fan of a turn: the same 16 (or every fourth)
    free.push_back(freeMotion(r, th0, v0, h, n));
    chr.push_back(christoffelGeodesic(r, th0, v0, h, n));
    for (int s = 0; s <= n; ++s) {
      agree = maxOf(agree, maxAbsOf(DVS(free.back().theta[std::size_t(s)] - chr.back().theta[std::size_t(s)])));
      const DVS& th = free.back().theta[std::size_t(s)];
      const DVS& v = free.back().thetaDot[std::size_t(s)];
      drift = maxOf(drift, S(abs(S(v.dot(r.massMatrix(th) * v) - S(1)))));
    }
  }
  // the two RK4 runs are the same scheme on the same field (RK4's θ update h v + h²/6 (a₁ + a₂ + a₃) is
  // RK4's): they differ by the five-point ∂A's ≈ 2.6 ε^(4/5)|A| and each run's rounding, n ε per
  // step count, both carried through the motion (|A⁻¹| |θ̇|² T²/2 ≈ O(1)): 64 (ε^(4/5) + n ε)
  // (3.1e-11 in double; 1e-10 before)
  using std::pow;
  const S agreeTol = S(64) * (S(pow(Tolerance<S>::epsilon(), S(4) / S(5))) + S(n) * Tolerance<S>::epsilon());
  ctx.checkResidual("free motion (RNE, rk4Step) = geodesic of A (Γ from ∂A, own RK4): max |Δθ| over " + std::to_string(fan) +
                        " directions, 1.5 s (64 (ε^(4/5) + n ε), n = 300)", agree, agreeTol);
  // RK4's truncation at h = 5 ms, the same in every scalar (not an ε of S): float's rounding over 300
  // steps (n ε ≈ 4e-5) is far above it
  const bool isFloat = std::is_same_v<S, float>;
  if (isFloat)
    ctx.note("Skipped in float: the speed drift and RK4's order from it (truncation 2e-12 at h = 5 ms, below float's "
             "rounding n ε ≈ 4e-5; float measures " + toString(drift, 2) + "), and the Jacobi separation (δ = 1e-5 "
             "apart is resolved by float only to ε/δ ≈ 1e-2 relative, the check asks δ).");
  else
    ctx.checkResidual("speed θ̇ᵀAθ̇ = 1 conserved along the geodesics (RK4, h = 5 ms; its truncation, not an ε of S)", drift,
                      frac<S>(1, 10000000000L));
  // RK4 is fourth order: the speed drift falls by ~16 when h halves
  S drift2 = 0;
  {
    const S phi = frac<S>(3, 10);
    const Geodesic<S> fine = freeMotion(r, th0, direction(phi), S(h / S(2)), 2 * n), coarse = freeMotion(r, th0, direction(phi), h, n);
    auto worst = [&](const Geodesic<S>& gd) {
      S w = 0;
      for (std::size_t s = 0; s < gd.theta.size(); ++s)
        w = maxOf(w, S(abs(S(gd.thetaDot[s].dot(r.massMatrix(gd.theta[s]) * gd.thetaDot[s]) - S(1)))));
      return w;
    };
    drift = worst(coarse);
    drift2 = worst(fine);
  }
  if (!isFloat) ctx.checkNear("RK4 order of the speed drift: log₂(drift(h)/drift(h/2)) = 4 (± 0.5)", S(4), S(log2(S(drift / drift2))), frac<S>(1, 2));
  // 2. Jacobi: geodesics leaving at angle δ separate as δJ(t), J'' = −K(θ₂(t))J, J(0) = 0, J'(0) = 1
  const S delta = frac<S>(1, 100000), phi0 = frac<S>(3, 10);
  constexpr int nj = 60;
  const S hj = T / S(nj);
  const Geodesic<S> base = freeMotion(r, th0, direction(phi0), hj, nj), side = freeMotion(r, th0, direction(S(phi0 + delta)), hj, nj);
  // J along the base geodesic by RK4 with K at the step's ends and midpoint (θ₂ of the base at
  // t + h/2 from a half step of the same integrator)
  S J = 0, Jd = 1, worstJ = 0, worstFlat = 0;
  const S half = frac<S>(1, 2);
  for (int k = 0; k < nj; ++k) {
    const std::size_t kk = std::size_t(k);
    const S Ka = brioschi(metricJet<S>(rq, S(base.theta[kk](1)), false));
    const JointState<S> halfStep = rk4Step<S>(r, {base.theta[kk], base.thetaDot[kk]}, S(hj / S(2)), DVS::Zero(2));
    const S Km = brioschi(metricJet<S>(rq, S(halfStep.theta(1)), false));
    const S Kb = brioschi(metricJet<S>(rq, S(base.theta[kk + 1](1)), false));
    const S k1 = Jd, l1 = -Ka * J;
    const S k2 = Jd + half * hj * l1, l2 = -Km * (J + half * hj * k1);
    const S k3 = Jd + half * hj * l2, l3 = -Km * (J + half * hj * k2);
    const S k4 = Jd + hj * l3, l4 = -Kb * (J + hj * k3);
    J += hj / S(6) * (k1 + S(2) * k2 + S(2) * k3 + k4);
    Jd += hj / S(6) * (l1 + S(2) * l2 + S(2) * l3 + l4);
    const DVS d = side.theta[kk + 1] - base.theta[kk + 1];
    const DVS mid = half * (side.theta[kk + 1] + base.theta[kk + 1]);
    const S sep = sqrt(S(d.dot(r.massMatrix(mid) * d))) / delta;
    worstJ = maxOf(worstJ, S(abs(S(sep - J)) / J));
    worstFlat = maxOf(worstFlat, S(abs(S(sep - hj * S(k + 1))) / (hj * S(k + 1))));
  }
  // relative tolerance δ: the separation is δJ + O(δ²) (not an ε of S)
  if (!isFloat) ctx.checkResidual("separation of geodesics δ = 1e-5 apart = δJ(t), J'' + K J = 0 (relative, 1.5 s; O(δ))", worstJ, delta);
  ctx.recordIn<S>("control: the flat prediction J = t (K = 0) misses the separation by more than 1 %", "> 0.01", toString(worstFlat, 3),
                  worstFlat, frac<S>(1, 100), worstFlat > frac<S>(1, 100));
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
  const double T0 = toDouble(T), a0 = toDouble(th0(0)), b0 = toDouble(th0(1));
  for (int k = 0; k < fan; ++k) {
    std::vector<double> x, y, lx, ly;
    for (const DVS& t : free[std::size_t(k)].theta) {
      x.push_back(toDouble(t(0)));
      y.push_back(toDouble(t(1)));
    }
    const DVS v0 = free[std::size_t(k)].thetaDot.front();
    for (int s = 0; s <= 10; ++s) {
      lx.push_back(a0 + T0 * s / 10 * toDouble(v0(0)));
      ly.push_back(b0 + T0 * s / 10 * toDouble(v0(1)));
    }
    pl.add(k == 0 ? "straight lines θ₀ + tθ̇₀ (flat metric)" : "", lx, ly, rd::Color::hex(0xAAAAAA)).dashed = true;
    pl.add(k == 0 ? "geodesics of A, unit speed, 1.5 s" : "", x, y, rd::Color::hex(0x0072B2));
  }
  auto& st = pl.add("start θ₀ = (0, 0.6)", {a0}, {b0}, rd::Color::hex(0xD55E00));
  st.line = false;
  st.markers = true;
  const std::string file = "GF-13.6.3-geodesics-2R.png";
  rd::renderPlotPngAndSvg(pl, ctx.figurePath(file));
  ctx.figure(file, "Free motions of the random 2R of GF-13.6.3 without gravity, from one posture in 16 directions at unit "
                   "kinetic speed: geodesics of the inertia metric A (blue), which bend away from the straight lines of "
                   "the joint coordinates (dashed); their spreading follows the Jacobi equation with the Gaussian curvature K(θ₂).");
}
}  // namespace

SOMA_STUDY_SCALAR("GF-13.6.1-decoupling-2R", "A decoupled 2R: constant diagonal A, B = 0; impossible for three joints", "GF §13.6.1", decoupling);
SOMA_STUDY_SCALAR("GF-13.6.1-quadratic-complex-kummer", "The quadratic line complex of revolute s₁ and its Kummer surface (erratum 23)", "GF §13.6.1", kummer);
SOMA_STUDY_SCALAR("GF-13.6.2-ignorable-2R-IA", "θ₂ ignorable for skew axes: link 2 symmetric about s₂ (erratum 18)", "GF §13.6.2", ignorable2R);
SOMA_STUDY_SCALAR("GF-13.6.2-ignorable-IIA-IIB", "θ₂ ignorable for intersecting (IIA) and parallel (IIB) axes", "GF §13.6.2", ignorableIIAIIB);
SOMA_STUDY_SCALAR("GF-13.6.2-ignorable-3R", "θ₂ and θ₃ ignorable in a 3R: s₁ ∥ s₂, composite c.o.m. on s₂", "GF §13.6.2", ignorable3R);
SOMA_STUDY_SCALAR("GF-13.6.3-flat-coordinates", "Flat coordinates φ(θ): φ̈ = K⁻ᵀτ; B = K_li∂_kK_lj (erratum 20)", "GF §13.6.3", flat);
SOMA_STUDY_SCALAR("GF-13.6.3-gaussian-curvature-2R", "Gaussian curvature of a 2R inertia metric (errata 11, 12)", "GF §13.6.3", gaussian);
SOMA_STUDY_SCALAR("GF-13.6.3-geodesics-2R", "Derived figure: free motion = geodesics of A; Jacobi spreading by K", "GF §13.4.2, §13.6.3", geodesics2R);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
