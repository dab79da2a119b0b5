// Studies of GF chapter 4, §4.7–4.8: the Killing forms of so(3) and se(3), the
// Campbell–Baker–Hausdorff series and the closed-form so(3) composition.
#include "gf04/common.hpp"

#include <Eigen/LU>

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.7, GF-4.7-killing-so3 (erratum E4.11) ------------------------------------------------
template <class S> void killingSo3(Context& c) {
  auto g = rng(65);
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("Killing matrix of so(3) = −2 I₃ (exact)",
                  maxAbs(Mat3<S>(killingForm<SO3Tangent<S>>() + S(2) * Mat3<S>::Identity())), S(0));
  S form(0), inv(0);
  for (int n = 0; n < 50; ++n) {
    const SO3Tangent<S> x(randomVec<S, 3>(g)), y(randomVec<S, 3>(g)), z(randomVec<S, 3>(g));
    form = maxOf(form, abs((x.ad() * y.ad()).trace() + S(2) * x.coeffs().dot(y.coeffs())));
    const S lhs = (bracket(z, x).ad() * y.ad()).trace() + (x.ad() * bracket(z, y).ad()).trace();
    inv = maxOf(inv, abs(lhs));
  }
  c.checkResidual("Tr(ad x ad y) = −2 x·y (50 random pairs)", form, tol);
  c.checkResidual("invariance ⟨[z, x], y⟩ + ⟨x, [z, y]⟩ = 0", inv, tol);
  // E4.11: "Tr((A + BC)) = Tr(AC + BC)" — the bilinearity step should read Tr((A + B)C).
  Mat3<S> A, B, C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = uniform<S>(g), B(i, j) = uniform<S>(g), C(i, j) = uniform<S>(g);
  c.checkPrintedFails("Tr(A + BC) = Tr(AC + BC)", "E4.11", abs(Mat3<S>(A + B * C).trace() - Mat3<S>(A * C + B * C).trace()), tol);
  c.checkResidual("corrected Tr((A + B)C) = Tr(AC) + Tr(BC)", abs(Mat3<S>((A + B) * C).trace() - (A * C).trace() - (B * C).trace()), tol);
}
SOMA_STUDY_SCALAR("GF-4.7-killing-so3", "Killing form of so(3): ⟨x, y⟩ = Tr(ad x ad y) = −2 x·y", "GF §4.7", killingSo3);

// ---- GF §4.7, GF-4.7-killing-se3 (erratum E4.10) -------------------------------------------------
template <class S> void killingSe3(Context& c) {
  auto g = rng(66);
  const S tol = Tolerance<S>::identity(64);
  const Mat6<S> K = killingForm<SE3Tangent<S>>();
  Mat6<S> correct = Mat6<S>::Zero(), printed = Mat6<S>::Zero();
  correct.template topLeftCorner<3, 3>() = -S(4) * Mat3<S>::Identity();
  printed.template topLeftCorner<3, 3>() = -S(2) * Mat3<S>::Identity();
  c.checkPrintedFails("Killing matrix of se(3) = diag(−2I₃, 0)", "E4.10", maxAbs(Mat6<S>(K - printed)), S(0));
  c.checkResidual("corrected: Killing matrix of se(3) = diag(−4I₃, 0) (exact)", maxAbs(Mat6<S>(K - correct)), S(0));
  S form(0), invariance(0), transl(0);
  for (int n = 0; n < 50; ++n) {
    const SE3Tangent<S> s1(randomVec<S, 6>(g)), s2(randomVec<S, 6>(g));
    form = maxOf(form, abs((s1.ad() * s2.ad()).trace() + S(4) * s1.ang().dot(s2.ang())));
    const Mat6<S> Ad = SE3<S>::Random(g).adjoint();
    const SE3Tangent<S> a1(Vec6<S>(Ad * s1.coeffs())), a2(Vec6<S>(Ad * s2.coeffs()));
    invariance = maxOf(invariance, abs((a1.ad() * a2.ad()).trace() - (s1.ad() * s2.ad()).trace()));
    const SE3Tangent<S> t(Vec3<S>::Zero(), randomVec<S, 3>(g));
    transl = maxOf(transl, abs((t.ad() * s1.ad()).trace()));
  }
  c.checkResidual("Tr(ad s₁ ad s₂) = −4 ω₁·ω₂ (50 random pairs)", form, tol);
  c.checkResidual("Ad-invariance ⟨Ad s₁, Ad s₂⟩ = ⟨s₁, s₂⟩", invariance, tol * S(4));
  c.checkResidual("degenerate: ⟨(0; v), s⟩ = 0 for every s", transl, tol);
  Eigen::FullPivLU<MatX<S>> lu{MatX<S>(K)};
  lu.setThreshold(Tolerance<S>::rank());
  c.checkEqual("rank of the se(3) Killing form", 3, int(lu.rank()));
}
SOMA_STUDY_SCALAR("GF-4.7-killing-se3", "Killing form of se(3): −4 ω₁·ω₂, degenerate (printed −2, E4.10)", "GF §4.7",
           killingSe3);

// ---- GF §4.8, GF-4.8-cbh-series ---------------------------------------------------------------------
template <class T, class G> typename T::Scalar bchError(const T& x, const T& y, int order, const G&) {
  const T exact = (x.exp() * y.exp()).log();
  return maxAbs((bch(x, y, order) - exact).coeffs());
}
template <class S> void cbhSeries(Context& c) {
  auto g = rng(67);
  // |X|, |Y| ≈ r: r = 0.05 (the catalogue's test), raised for float so the O(r⁴) remainder stays
  // above round-off (r = eps^(1/8)).
  const S r = maxOf(S(1) / S(20), pow(Tolerance<S>::epsilon(), S(1) / S(8)));
  const SO3Tangent<S> x(Vec3<S>(randomUnit<S>(g) * r)), y(Vec3<S>(randomUnit<S>(g) * r));
  const SE3Tangent<S> p(Vec6<S>(randomVec<S, 6>(g) * r)), q(Vec6<S>(randomVec<S, 6>(g) * r));
  const S e3 = bchError(x, y, 3, 0), e3h = bchError(x * (S(1) / S(2)), y * (S(1) / S(2)), 3, 0);
  const S e2 = bchError(x, y, 2, 0);
  const S e4 = bchError(x, y, 4, 0), e4h = bchError(x * (S(1) / S(2)), y * (S(1) / S(2)), 4, 0);
  c.note("so(3), |X| = |Y| = " + str(r) + ": |log(e^X e^Y) − f_k| = " + str(e2) + " (k = 2), " + str(e3) + " (k = 3), " +
         str(e4) + " (k = 4).");
  c.checkResidual("so(3): X + Y + ½[X,Y] + (1/12)([X,[X,Y]] + [Y,[Y,X]]) = log(e^X e^Y) to O(r⁴) (≤ r⁴)", e3, ipow(r, 4));
  c.checkNear("so(3): halving X, Y divides the 3rd-order error by 16 (fourth-order remainder)", S(16), e3 / e3h, S(3));
  if (e4h > S(64) * Tolerance<S>::epsilon())  // the O(r⁵) remainder must stand above round-off
    c.checkNear("so(3): with the 4th-order term −(1/24)[Y,[X,[X,Y]]] the ratio is 32", S(32), e4 / e4h, S(6));
  else
    c.note("4th-order ratio not measurable in this type: remainder " + str(e4h) + " below 64 eps.");
  const S s3 = bchError(p, q, 3, 0), s3h = bchError(p * (S(1) / S(2)), q * (S(1) / S(2)), 3, 0);
  c.checkResidual("se(3): 3rd-order CBH = log(e^X e^Y) to O(r⁴)", s3, S(8) * ipow(r, 4));
  c.checkNear("se(3): halving divides the 3rd-order error by 16", S(16), s3 / s3h, S(3));
  // Near the convergence radius ‖X‖ + ‖Y‖ ≈ log 2: the truncations are no longer small.
  const S big = log(S(2)) / S(2);
  const SO3Tangent<S> xb(Vec3<S>(randomUnit<S>(g) * big)), yb(Vec3<S>(randomUnit<S>(g) * big));
  c.note("so(3), |X| = |Y| = log(2)/2: 3rd-order error " + str(bchError(xb, yb, 3, 0)) + ", 4th-order error " +
         str(bchError(xb, yb, 4, 0)) + ".");
}
SOMA_STUDY_SCALAR("GF-4.8-cbh-series", "Campbell–Baker–Hausdorff series log(e^X e^Y) to third order; error order",
           "GF §4.8", cbhSeries);

// ---- GF §4.8, GF-4.8-so3-closed-form-bch ------------------------------------------------------------
/// The book's closed-form composition: φ, a, b, c with e^{θ₁ ad x₁} e^{θ₂ ad x₂} =
/// e^{φ(a ad x₁ + b ad x₂ + c [ad x₁, ad x₂])} (unit x₁, x₂), φ/2 by atan2.
// GF §4.8, GF-4.8-so3-closed-form-bch
template <class S> std::array<S, 4> closedFormBch(const Vec3<S>& x1, const Vec3<S>& x2, const S& t1, const S& t2) {
  const S s1 = sin(t1 / S(2)), c1 = cos(t1 / S(2)), s2 = sin(t2 / S(2)), c2 = cos(t2 / S(2));
  const S cphi = c1 * c2 - s1 * s2 * x1.dot(x2);
  const Vec3<S> vec = s1 * c2 * x1 + c1 * s2 * x2 + s1 * s2 * x1.cross(x2);
  const S sphi = sqrt(vec.squaredNorm());
  return {S(2) * atan2(sphi, cphi), s1 * c2 / sphi, c1 * s2 / sphi, s1 * s2 / sphi};
}
template <class S> void so3ClosedFormBch(Context& c) {
  auto g = rng(68);
  const S tol = Tolerance<S>::identity(64);
  S rr(0), comm(0);
  for (int n = 0; n < 50; ++n) {
    const Vec3<S> u = randomVec<S, 3>(g), v = randomVec<S, 3>(g);
    const CMat<Mat2<S>> Ru = su2Element(u(0), u(1), u(2)), Rv = su2Element(v(0), v(1), v(2));
    const Vec3<S> w = u.cross(v);
    const CMat<Mat2<S>> lhs = Ru * Rv, rhs = CMat<Mat2<S>>{Mat2<S>(-u.dot(v) * Mat2<S>::Identity()), Mat2<S>::Zero()} +
                                               su2Element(w(0), w(1), w(2));
    rr = maxOf(rr, (lhs - rhs).maxAbs());
    const CMat<Mat2<S>> twice = su2Element(S(2) * w(0), S(2) * w(1), S(2) * w(2));
    comm = maxOf(comm, (Ru * Rv - Rv * Ru - twice).maxAbs());
  }
  c.checkResidual("R(x₁)R(x₂) = −(x₁·x₂)I₂ + R(x₁ × x₂) (50 random pairs)", rr, tol);
  c.checkResidual("[R(x₁), R(x₂)] = 2R(x₁ × x₂)", comm, tol);
  const Vec3<S> x1 = randomUnit<S>(g), x2 = randomUnit<S>(g);
  auto composite = [&](const Vec3<S>& a1, const Vec3<S>& a2, const S& t1, const S& t2, const std::string& what, const S& tl) {
    const auto k = closedFormBch(a1, a2, t1, t2);
    const Mat3<S> A1 = skew(a1), A2 = skew(a2);
    const Mat3<S> gen = k[0] * (k[1] * A1 + k[2] * A2 + k[3] * (A1 * A2 - A2 * A1));
    const Mat3<S> lhs = (SO3Tangent<S>(Vec3<S>(a1 * t1)).exp() * SO3Tangent<S>(Vec3<S>(a2 * t2)).exp()).matrix();
    c.checkResidual(what + ": e^{θ₁ ad x₁} e^{θ₂ ad x₂} = e^{φ(a ad x₁ + b ad x₂ + c [ad x₁, ad x₂])}",
                    maxAbs(Mat3<S>(expSeries(gen) - lhs)), tl);
    return k;
  };
  const S t1 = S(11) / S(10), t2 = -S(8) / S(10);
  const auto k = composite(x1, x2, t1, t2, "θ₁ = 1.1, θ₂ = −0.8, random unit axes", tol);
  // su(2) form: the commutator carries c/2.
  const CMat<Mat2<S>> X1 = su2Element(x1(0), x1(1), x1(2)), X2 = su2Element(x2(0), x2(1), x2(2));
  const CMat<Mat2<S>> gen2 = Cx<S>(k[0] / S(2)) * (Cx<S>(k[1]) * X1 + Cx<S>(k[2]) * X2 + Cx<S>(k[3] / S(2)) * (X1 * X2 - X2 * X1));
  const Mat4<S> lhs2 = expSeries(realForm(CMat<Mat2<S>>(Cx<S>(t1 / S(2)) * X1))) * expSeries(realForm(CMat<Mat2<S>>(Cx<S>(t2 / S(2)) * X2)));
  c.checkResidual("su(2): e^{θ₁/2 X₁} e^{θ₂/2 X₂} = e^{φ/2 (a X₁ + b X₂ + (c/2)[X₁, X₂])}",
                  maxAbs(Mat4<S>(expSeries(realForm(gen2)) - lhs2)), tol);
  const Quat<S> qa = SO3Tangent<S>(Vec3<S>(x1 * t1)).exp().quaternion(), qb = SO3Tangent<S>(Vec3<S>(x2 * t2)).exp().quaternion();
  const Quat<S> prod = quaternionProduct(qa, qb);
  const Vec3<S> axisVec = k[1] * x1 + k[2] * x2 + k[3] * x1.cross(x2);
  c.checkResidual("= quaternion product (cos φ/2, sin φ/2 (a x₁ + b x₂ + c x₁ × x₂))",
                  maxOf(abs(prod.w() - cos(k[0] / S(2))), maxAbs(Vec3<S>(prod.vec() - sin(k[0] / S(2)) * axisVec))), tol);
  // Extremes: parallel axes (c-term vanishes, φ = θ₁ + θ₂); composite identity (sin φ/2 = 0);
  // φ beyond π (atan2 keeps the branch).
  const auto kp = composite(x1, x1, t1, S(3) / S(10), "parallel axes", tol);
  c.checkNear("parallel axes: φ = θ₁ + θ₂", t1 + S(3) / S(10), kp[0], tol);
  const auto kb = composite(x1, x1, S(3), S(3), "parallel axes, θ₁ = θ₂ = 3 (φ = 6 > π)", tol * S(4));
  c.checkNear("φ = 6 (atan2 branch, not acos)", S(6), kb[0], tol * S(4));
  const auto ki = closedFormBch(x1, x1, t1, -t1);
  c.checkEqual("composite identity (θ₂ = −θ₁, same axis): sin φ/2 = 0, a, b, c undefined", "non-finite",
               isFinite(ki[1]) ? "finite" : "non-finite");
}
SOMA_STUDY_SCALAR("GF-4.8-so3-closed-form-bch",
           "Closed-form so(3) composition e^{θ₁x₁}e^{θ₂x₂} = e^{φ(a x₁ + b x₂ + c x₁ × x₂)} via su(2)",
           "GF §4.8", so3ClosedFormBch);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
