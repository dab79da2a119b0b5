// Studies of GF chapter 4, §4.4 and §4.4.1: the exponential map, su(2) exp/log, the so(3)
// idempotents.
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.4, GF-4.4-exp-basics (erratum E4.4) ---------------------------------------------
template <class S> void expBasics(Context& c) {
  auto g = rng(48);
  // det e^X = e^{Tr X} on random 4×4 matrices (power-series exponential).
  S worstDet(0);
  for (int n = 0; n < 10; ++n) {
    Mat4<S> x;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) x(i, j) = uniform<S>(g);
    const S lhs = expSeries(x).determinant(), rhs = exp(x.trace());
    worstDet = maxOf(worstDet, abs(lhs - rhs) / rhs);
  }
  c.checkResidual("det e^X = e^{Tr X} (10 random 4×4, relative)", worstDet, Tolerance<S>::identity(256));
  // γ(t) = e^{tX} is the integral curve of the left-invariant field: γ' = γ X.
  const SE3Tangent<S> s(randomVec<S, 6>(g));
  const Mat4<S> X = s.hat();
  const S t0 = S(7) / S(10);
  const Mat4<S> fd = derivative<S>([&](const S& d) { return expSeries(Mat4<S>((t0 + d) * X)); });
  c.checkResidual("d/dt e^{tX} = e^{tX} X at t = 0.7 (finite differences)",
                  maxAbs(Mat4<S>(fd - expSeries(Mat4<S>(t0 * X)) * X)), fdTolerance<S>(S(8)));
  // One-parameter subgroup e^{t₁X} e^{t₂X} = e^{(t₁+t₂)X} (soma's closed-form exp).
  const S t1 = S(13) / S(10), t2 = -S(4) / S(10);
  c.checkResidual("e^{t₁X} e^{t₂X} = e^{(t₁+t₂)X} (SE3 exp, t₁ = 1.3, t₂ = −0.4)",
                  maxAbs(Mat4<S>(((s * t1).exp() * (s * t2).exp()).matrix() - (s * (t1 + t2)).exp().matrix())),
                  Tolerance<S>::identity(64));
  // "if": commuting twists (same axis, different pitch) add.
  const Vec3<S> a = randomUnit<S>(g), q = randomVec<S, 3>(g);
  const SE3Tangent<S> c1(a, Vec3<S>(q.cross(a) + S(2) / S(10) * a)), c2(Vec3<S>(a * S(2)), Vec3<S>(S(2) * q.cross(a) - S(1) / S(2) * a));
  c.checkResidual("commuting twists: |[X, Y]| = 0", maxAbs(bracket(c1, c2).coeffs()), Tolerance<S>::identity(16));
  c.checkResidual("… and e^X e^Y = e^{X+Y}", maxAbs(Mat4<S>((c1.exp() * c2.exp()).matrix() - (c1 + c2).exp().matrix())),
                  Tolerance<S>::identity(64));
  // "only if" fails (E4.4): 2π-rotations about unit axes 120° apart.
  const Vec3<S> ax(S(1), S(0), S(0));
  const Vec3<S> bx(-S(1) / S(2), sqrt(S(3)) / S(2), S(0));
  const Mat3<S> Xr = skew(Vec3<S>(S(2) * pi<S>() * ax)), Yr = skew(Vec3<S>(S(2) * pi<S>() * bx));
  const Mat3<S> lhs = expSeries(Xr) * expSeries(Yr), rhs = expSeries(Mat3<S>(Xr + Yr));
  c.checkResidual("2π-rotations about axes 120° apart: e^X e^Y = e^{X+Y} (= I; power series)",
                  maxOf(maxAbs(Mat3<S>(lhs - rhs)), maxAbs(Mat3<S>(rhs - Mat3<S>::Identity()))),
                  Tolerance<S>::identity(256));
  const S comm = sqrt((Xr * Yr - Yr * Xr).squaredNorm());
  c.checkNear("… while |[X, Y]|_F = 4π² sin 120° · √2", S(4) * pi<S>() * pi<S>() * sqrt(S(3)) / S(2) * sqrt(S(2)),
              comm, Tolerance<S>::identity(256) * S(64));
  c.checkPrintedFails("\"e^X e^Y = e^{X+Y} only if [X, Y] = 0\": |[X, Y]| should be 0", "E4.4", comm,
              Tolerance<S>::identity());
  // Mercator series log g = Σ (−1)^{k+1}(g − I)^k/k near I; diverges beyond 60°.
  auto mercator = [&](const Mat3<S>& gm, int maxTerms, S* lastTerm, S* term20, S* term40) {
    const Mat3<S> d = gm - Mat3<S>::Identity();
    Mat3<S> power = d, sum = Mat3<S>::Zero();
    for (int k = 1; k <= maxTerms; ++k) {
      const Mat3<S> term = power / S(k);
      sum += (k % 2 == 1) ? term : Mat3<S>(-term);
      const S tn = maxAbs(term);
      if (k == 20 && term20) *term20 = tn;
      if (k == 40 && term40) *term40 = tn;
      if (lastTerm) *lastTerm = tn;
      if (!term20 && tn <= Tolerance<S>::epsilon() * Tolerance<S>::epsilon()) break;
      power = power * d;
    }
    return sum;
  };
  const Vec3<S> w = randomUnit<S>(g) * (S(1) / S(2));
  const SO3<S> near = SO3Tangent<S>(w).exp();
  const Mat3<S> logSeries = mercator(near.matrix(), 4000, nullptr, nullptr, nullptr);
  c.checkResidual("Mercator series at θ = 0.5 (|g − I| = 0.49) = soma's log",
                  maxAbs(Mat3<S>(logSeries - near.log().hat())), Tolerance<S>::identity(64));
  S t20(0), t40(0);
  const SO3<S> far = SO3Tangent<S>(Vec3<S>(randomUnit<S>(g) * (S(100) * pi<S>() / S(180)))).exp();
  (void)mercator(far.matrix(), 40, nullptr, &t20, &t40);
  c.checkEqual("Mercator series at θ = 100° (spectral radius 2 sin 50° = 1.53)", "diverges",
               t40 > t20 ? "diverges" : "converges");
  c.note("Mercator terms at 100°: |term₂₀| = " + str(t20) + ", |term₄₀| = " + str(t40) + ".");
}
SOMA_STUDY_SCALAR("GF-4.4-exp-basics",
           "Matrix exponential: det e^X = e^{Tr X}, one-parameter subgroups, Mercator log, E4.4",
           "GF §4.4", expBasics);

// ---- GF §4.4, GF-4.4-su2-exp-log ------------------------------------------------------------
/// The book's su(2) logarithm log U = t csc t U − t cot t I with t = atan2(sin t, cos t) read off
/// U = cos t I + (sin t / t) M (cos t = Re U₀₀ = Tr U / 2).
// GF §4.4, GF-4.4-su2-exp-log
template <class S> CMat<Mat2<S>> su2Log(const CMat<Mat2<S>>& u, S* tOut = nullptr) {
  const S ct = u.re(0, 0);
  const S st = sqrt(u.im(0, 0) * u.im(0, 0) + u.re(0, 1) * u.re(0, 1) + u.im(0, 1) * u.im(0, 1));
  const S t = atan2(st, ct);
  if (tOut) *tOut = t;
  const S k = t / st;  // t csc t
  return {Mat2<S>(k * (u.re - ct * Mat2<S>::Identity())), Mat2<S>(k * u.im)};
}
template <class S> void su2ExpLog(Context& c) {
  const S a = S(3) / S(10), b = -S(9) / S(10), cc = S(12) / S(10);
  const CMat<Mat2<S>> M = su2Element(a, b, cc);
  const S t = sqrt(a * a + b * b + cc * cc);
  const CMat<Mat2<S>> M2 = M * M;
  c.checkResidual("M² = −(a² + b² + c²) I₂, (a,b,c) = (0.3, −0.9, 1.2)",
                  maxOf(maxAbs(Mat2<S>(M2.re + t * t * Mat2<S>::Identity())), maxAbs(M2.im)), Tolerance<S>::identity(16));
  c.checkNear("t² = det M", t * t, M.re(0, 0) * M.re(1, 1) - M.im(0, 0) * M.im(1, 1) -
                                       (M.re(0, 1) * M.re(1, 0) - M.im(0, 1) * M.im(1, 0)),
              Tolerance<S>::identity(16));
  const CMat<Mat2<S>> U = fromRealForm<S>(expSeries(realForm(M)));
  const CMat<Mat2<S>> closed{Mat2<S>(cos(t) * Mat2<S>::Identity() + sin(t) / t * M.re), Mat2<S>(sin(t) / t * M.im)};
  c.checkResidual("e^M = cos t I₂ + (sin t / t) M (vs power series)", (U - closed).maxAbs(), Tolerance<S>::identity(64));
  S tt(0);
  c.checkResidual("log U = t csc t U − t cot t I₂ recovers M", (su2Log(U, &tt) - M).maxAbs(), Tolerance<S>::identity(64));
  c.checkNear("Tr U = 2 cos t", S(2) * cos(t), U.re.trace(), Tolerance<S>::identity(16));
  // Extremes: t = 1e-8 and t → π (U → −I: log loses accuracy like eps / sin t, fails at π).
  for (const S& tiny : {S(1) / S(100000000), pi<S>() - S(1) / S(1000000)}) {
    const Vec3<S> dir = Vec3<S>(a, b, cc) / t;
    const CMat<Mat2<S>> m = su2Element<S>(dir(0) * tiny, dir(1) * tiny, dir(2) * tiny);
    const CMat<Mat2<S>> u = fromRealForm<S>(expSeries(realForm(m)));
    const S bound = Tolerance<S>::identity(64) * maxOf(S(1), tiny / sin(tiny));
    c.checkResidual("t = " + str(tiny, 17) + ": log(e^M) = M (error ≤ 64 eps · t / sin t)", (su2Log(u) - m).maxAbs(), bound);
  }
  const CMat<Mat2<S>> minusI{Mat2<S>(-Mat2<S>::Identity()), Mat2<S>::Zero()};
  const CMat<Mat2<S>> l = su2Log(minusI);
  const bool fails = !isFinite(l.maxAbs()) ||
                     (fromRealForm<S>(expSeries(realForm(l))) - minusI).maxAbs() > Tolerance<S>::identity(64);
  c.checkEqual("U = −I (t = π): t csc t U − t cot t I (the book: \"fails when t = ±π\")", "fails",
               fails ? "fails" : "recovers U");
}
SOMA_STUDY_SCALAR("GF-4.4-su2-exp-log", "su(2): M² = −t² I, e^M = cos t I + sin t/t M, log U", "GF §4.4",
           su2ExpLog);

// ---- GF §4.4.1, GF-4.4.1-so3-idempotents ----------------------------------------------------
template <class S> void so3Idempotents(Context& c) {
  auto g = rng(49);
  using CM = CMat<Mat3<S>>;
  for (const S& theta : {S(13) / S(10), S(1) / S(100000000)}) {
    const Vec3<S> w = randomUnit<S>(g) * theta;
    const Mat3<S> W = skew(w), W2 = W * W, I = Mat3<S>::Identity();
    const S th2 = w.squaredNorm(), th = sqrt(th2);
    const std::string at = " (θ = " + str(theta) + ")";
    c.checkResidual("Ω³ + θ²Ω = 0" + at, maxAbs(Mat3<S>(W2 * W + th2 * W)) / (th2 * th), Tolerance<S>::identity(16));
    // GF §4.4.1: P₀ = Ω²/θ² + I, P± = −Ω²/(2θ²) ± iΩ/(2θ)
    const CM P0 = CM::real(Mat3<S>(W2 / th2 + I));
    const CM Pp{Mat3<S>(-W2 / (S(2) * th2)), Mat3<S>(W / (S(2) * th))};
    const CM Pm{Mat3<S>(-W2 / (S(2) * th2)), Mat3<S>(-W / (S(2) * th))};
    S annihilate = maxOf((P0 * Pp).maxAbs(), maxOf((P0 * Pm).maxAbs(), (Pp * Pm).maxAbs()));
    annihilate = maxOf(annihilate, maxOf((Pp * P0).maxAbs(), (Pm * Pp).maxAbs()));
    c.checkResidual("P₀P₊ = P₀P₋ = P₊P₋ = 0 (mutually annihilating)" + at, annihilate, Tolerance<S>::identity(16));
    const S idem = maxOf((P0 * P0 - P0).maxAbs(), maxOf((Pp * Pp - Pp).maxAbs(), (Pm * Pm - Pm).maxAbs()));
    c.checkResidual("P² = P for P₀, P₊, P₋" + at, idem, Tolerance<S>::identity(16));
    c.checkResidual("P₀ + P₊ + P₋ = I₃" + at, (P0 + Pp + Pm - CM::real(I)).maxAbs(), Tolerance<S>::identity(16));
    const Cx<S> ith(S(0), th);
    c.checkResidual("Ω = iθP₋ − iθP₊" + at, ((ith * Pm) - (ith * Pp) - CM::real(W)).maxAbs() / th, Tolerance<S>::identity(16));
    // Ωⁿ = (−iθ)ⁿP₊ + (iθ)ⁿP₋ divided by θⁿ: (Ω/θ)ⁿ = (−i)ⁿP₊ + iⁿP₋ (no underflow of θⁿ).
    S powers(0);
    const Mat3<S> Wu = W / th;
    Mat3<S> Wn = Wu;
    const Cx<S> mi(S(0), S(-1)), pi1(S(0), S(1));
    Cx<S> lp = mi, lm = pi1;
    for (int n = 1; n <= 6; ++n) {
      powers = maxOf(powers, ((lp * Pp) + (lm * Pm) - CM::real(Wn)).maxAbs());
      Wn = Wn * Wu;
      lp = lp * mi;
      lm = lm * pi1;
    }
    c.checkResidual("Ωⁿ = (−iθ)ⁿP₊ + (iθ)ⁿP₋, n = 1..6 (relative to θⁿ)" + at, powers, Tolerance<S>::identity(64));
    const CM expP = P0 + (Cx<S>::expi(-th) * Pp) + (Cx<S>::expi(th) * Pm);
    c.checkResidual("e^Ω = P₀ + e^{−iθ}P₊ + e^{iθ}P₋ (vs power series)" + at,
                    (expP - CM::real(expSeries(W))).maxAbs(), Tolerance<S>::identity(64));
    // Spectral calculus for another analytic f: sin Ω = sin(0)P₀ + sin(−iθ)P₊ + sin(iθ)P₋,
    // sin(±iθ) = ±i sinh θ; compared with the power series Σ (−1)^k Ω^{2k+1}/(2k+1)!.
    Mat3<S> sinSeries = Mat3<S>::Zero(), term = W;
    for (int k = 0; k < 200; ++k) {
      sinSeries += term;
      term = Mat3<S>(-(term * W2) / S((2 * k + 2) * (2 * k + 3)));
      if (maxAbs(term) <= Tolerance<S>::epsilon() * Tolerance<S>::epsilon()) break;
    }
    const Cx<S> sh(S(0), sinh(th));
    const CM sinP = ((S(-1) * sh) * Pp) + (sh * Pm);
    c.checkResidual("spectral calculus f(Ω) = f(0)P₀ + f(−iθ)P₊ + f(iθ)P₋ for f = sin" + at,
                    (sinP - CM::real(sinSeries)).maxAbs() / th, Tolerance<S>::identity(64));
  }
}
SOMA_STUDY_SCALAR("GF-4.4.1-so3-idempotents",
           "so(3) idempotents P₀, P±: annihilating, idempotent, Ωⁿ and e^Ω by spectral calculus",
           "GF §4.4.1", so3Idempotents);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
