// Studies of GF chapter 4, §4.4.3: exp and log of SE(3) in the 6×6 adjoint representation
// (quintic, P/N calculus, Hermite interpolation; erratum E4.8).
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)

namespace {

std::string angleText(double theta) {
  const double pi = 3.14159265358979323846;
  if (theta > 3) return "π − " + toString(pi - theta, 3);
  return toString(theta, 6);
}

// ---- GF §4.4.3, GF-4.4.3-adjoint-exp (erratum E4.7) ---------------------------------------------
/// The book's closed form of e^Z. GF §4.4.3, GF-4.4.3-adjoint-exp
template <class S> Mat6<S> adjointExpBook(const Mat6<S>& Z, const S& th) {
  const Mat6<S> Z2 = Z * Z, Z3 = Z2 * Z, Z4 = Z3 * Z;
  const S s = sin(th), co = cos(th), t2 = th * th;
  return Mat6<S>::Identity() + (S(3) * s - th * co) / (S(2) * th) * Z + (S(4) - S(4) * co - th * s) / (S(2) * t2) * Z2 +
         (s - th * co) / (S(2) * t2 * th) * Z3 + (S(2) - S(2) * co - th * s) / (S(2) * t2 * t2) * Z4;
}
template <class S> void adjointExp(Context& c) {
  auto g = rng(55);
  using CM = CMat<Mat6<S>>;
  const S th = S(6) / S(5);
  const SE3Tangent<S> s = randomTwistWithAngle<S>(g, th);
  const Mat6<S> Z = s.ad(), I = Mat6<S>::Identity();
  const S t2 = th * th;
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("Z⁵ + 2θ²Z³ + θ⁴Z = 0 (θ = 1.2)", maxAbs(Mat6<S>(Z * Z * Z * Z * Z + S(2) * t2 * Z * Z * Z + t2 * t2 * Z)), tol * S(4));
  const Mat3<S> W = skew(s.ang()), V = skew(s.lin()), W2 = W * W;
  c.checkPrintedFails("Ω²VΩ² + θ²(ΩV + VΩ) = −θ⁴V", "E4.7", maxAbs(Mat3<S>(W2 * V * W2 + t2 * (W * V + V * W) + t2 * t2 * V)), tol * S(4));
  S corr(0);
  for (int n = 0; n < 20; ++n) {
    const Vec3<S> w = randomVec<S, 3>(g);
    const Mat3<S> Wn = skew(w), Vn = skew(Vec3<S>(randomVec<S, 3>(g))), Wn2 = Wn * Wn;
    const S tn2 = w.squaredNorm();
    corr = maxOf(corr, maxAbs(Mat3<S>(Wn2 * Vn * Wn2 + tn2 * (Wn2 * Vn + Vn * Wn2) + tn2 * tn2 * Vn)));
  }
  c.checkResidual("corrected Ω²VΩ² + θ²(Ω²V + VΩ²) = −θ⁴V (20 random pairs)", corr, tol * S(4));
  const AdjointSpectral<S> P = adjointSpectral(Z, th);
  // Factored = expanded: P₊ = −Z(Z − iθ)²(2Z + 3iθ)/(4θ⁴), N₋ = Z(Z + iθ)²(Z − iθ)/(4θ⁴).
  const CM Zc = CM::real(Z), Ic = CM::real(I);
  const Cx<S> ith(S(0), th), i3th(S(0), S(3) * th), quarter(S(1) / (S(4) * t2 * t2));
  const CM ZmI = Zc - (ith * Ic), ZpI = Zc + (ith * Ic);
  const CM PpF = (Cx<S>(-S(1)) * quarter) * (Zc * ZmI * ZmI * (Cx<S>(S(2)) * Zc + (i3th * Ic)));
  const CM NmF = quarter * (Zc * ZpI * ZpI * ZmI);
  c.checkResidual("P₊ factored = expanded; N₋ factored = expanded (with iθ³Z for the OCR'd I₆θ³Z)",
                  maxOf((PpF - P.Pp).maxAbs(), (NmF - P.Nm).maxAbs()), tol * S(4));
  S rel = maxOf((P.P0 * P.P0 - P.P0).maxAbs(), maxOf((P.Pp * P.Pp - P.Pp).maxAbs(), (P.Pm * P.Pm - P.Pm).maxAbs()));
  rel = maxOf(rel, maxOf((P.P0 * P.Pp).maxAbs(), maxOf((P.Pp * P.Pm).maxAbs(), (P.P0 * P.Pm).maxAbs())));
  rel = maxOf(rel, maxOf((P.Np * P.Np).maxAbs(), (P.Nm * P.Nm).maxAbs()));
  rel = maxOf(rel, maxOf((P.Pp * P.Np - P.Np).maxAbs(), (P.Pm * P.Nm - P.Nm).maxAbs()));
  rel = maxOf(rel, maxOf((P.Np * P.Pm).maxAbs(), (P.Nm * P.Pp).maxAbs()));
  c.checkResidual("P² = P, PP' = 0, N² = 0, P±N± = N±, N₊P₋ = N₋P₊ = 0", rel, tol * S(4));
  c.checkResidual("P₀ + P₊ + P₋ = I₆", (P.P0 + P.Pp + P.Pm - Ic).maxAbs(), tol);
  const Cx<S> mith(S(0), -th);
  c.checkResidual("Z = −iθP₊ − iθN₊ + iθP₋ + iθN₋",
                  ((mith * P.Pp) + (mith * P.Np) + (ith * P.Pm) + (ith * P.Nm) - Zc).maxAbs(), tol * S(4));
  const Mat6<S> series = expSeries(Z);
  const Cx<S> em = Cx<S>::expi(-th), ep = Cx<S>::expi(th);
  const CM spectral = P.P0 + (em * P.Pp) + ((mith * em) * P.Np) + (ep * P.Pm) + ((ith * ep) * P.Nm);
  c.checkResidual("e^Z = P₀ + e^{−iθ}P₊ − iθe^{−iθ}N₊ + e^{iθ}P₋ + iθe^{iθ}N₋ (vs power series)",
                  (spectral - CM::real(series)).maxAbs(), tol * S(4));
  c.checkResidual("book's closed form of e^Z = power series", maxAbs(Mat6<S>(adjointExpBook(Z, th) - series)), tol * S(4));
  c.checkResidual("e^{ad s} = Ad(e^s) (SE3::adjoint of SE3Tangent::exp)", maxAbs(Mat6<S>(adjointExpBook(Z, th) - s.exp().adjoint())),
                  tol * S(4));
  c.checkNear("Tr H = 2 + 4 cos θ", S(2) + S(4) * cos(th), series.trace(), tol);
  // θ → 0: the printed coefficients cancel (numerators vanish like θ⁴…θ⁶).
  for (const S& small : {S(1) / S(10), S(1) / S(100)}) {
    const SE3Tangent<S> x = randomTwistWithAngle<S>(g, small);
    const S err = maxAbs(Mat6<S>(adjointExpBook(x.ad(), small) - x.exp().adjoint()));
    // Each numerator (e.g. 2 − 2cos θ − θ sin θ ~ θ⁴/12) carries an absolute error ~eps, i.e. a
    // coefficient error ~eps/θ⁴, against |Z⁴| ~ θ³|v|: the sum errs by ~eps/θ.
    const S bound = tol * maxOf(S(1), S(1) / small);
    c.checkResidual("θ = " + str(small) + ": book's e^Z vs Ad(e^s) (cancellation: error ≤ 64 eps/θ)", err, bound);
  }
  const SE3Tangent<S> tr(Vec3<S>::Zero(), randomVec<S, 3>(g));
  c.checkResidual("pure translation: Z² = 0 and e^Z = I + Z = Ad(e^s)",
                  maxOf(maxAbs(Mat6<S>(tr.ad() * tr.ad())), maxAbs(Mat6<S>(I + tr.ad() - tr.exp().adjoint()))), S(0));
}
SOMA_STUDY_SCALAR("GF-4.4.3-adjoint-exp",
           "SE(3) exp in the 6×6 adjoint representation: quintic, P/N calculus, closed form; E4.7",
           "GF §4.4.3", adjointExp);

// ---- GF §4.4.3, GF-4.4.3-adjoint-log (erratum E4.8) ---------------------------------------------
/// The book's log(H) = αI + βH + γH² + δH³ + εH⁴ (ζ = 0) with prefactor 1/(k sin³θ): k = 8 as
/// printed, k = 4 corrected (erratum E4.8). GF §4.4.3, GF-4.4.3-adjoint-log
template <class S> std::array<S, 5> adjointLogCoefficients(const S& th, int k) {
  const S p = S(1) / (S(k) * ipow(sin(th), 3));
  auto c = [&](int n) { return cos(S(n) * th); };
  auto s = [&](int n) { return sin(S(n) * th); };
  return {-p * (S(2) * th + S(4) * th * c(1) - th * c(3) - s(2) - s(3)),
          p * (S(8) * th + S(8) * th * c(1) + S(2) * th * c(2) - S(2) * s(1) - S(3) * s(2) - S(2) * s(3) - s(4)),
          -p * (S(8) * th + S(11) * th * c(1) + S(4) * th * c(2) + th * c(3) - S(3) * s(1) - S(4) * s(2) - S(3) * s(3) - s(4)),
          p * (S(4) * th + S(8) * th * c(1) + S(2) * th * c(2) - S(2) * s(1) - S(3) * s(2) - S(2) * s(3)),
          -p * (S(2) * th + th * c(1) - s(1) - s(2))};
}
template <class S> Mat6<S> adjointLogBook(const Mat6<S>& H, int k) {
  const S th = angleOf<S>(H.template topLeftCorner<3, 3>());
  const auto a = adjointLogCoefficients(th, k);
  Mat6<S> power = Mat6<S>::Identity(), sum = Mat6<S>::Zero();
  for (int n = 0; n < 5; ++n) {
    sum += a[n] * power;
    power = power * H;
  }
  return sum;
}
template <class S> void adjointLog(Context& c) {
  auto g = rng(56);
  const S tol = Tolerance<S>::identity(64);
  for (int trial = 0; trial < 2; ++trial) {
    const S th = trial == 0 ? S(6) / S(5) : S(23) / S(10);
    const SE3Tangent<S> s = randomTwistWithAngle<S>(g, th);
    const Mat6<S> H = s.exp().adjoint(), Z = s.ad();
    const std::string at = " (random twist, θ = " + str(th) + ")";
    c.checkNear("Tr H = 2 + 4 cos θ" + at, S(2) + S(4) * cos(th), H.trace(), tol);
    c.checkPrintedFails("log H with prefactor 1/(8 sin³θ): log H = Z" + at, "E4.8", maxAbs(Mat6<S>(adjointLogBook(H, 8) - Z)), tol * S(16));
    c.checkResidual("corrected prefactor 1/(4 sin³θ): log H = Z" + at, maxAbs(Mat6<S>(adjointLogBook(H, 4) - Z)), tol * S(16));
    c.checkNear("printed log H = ½ Z exactly (ratio of max entries)" + at, S(1) / S(2),
                maxAbs(adjointLogBook(H, 8)) / maxAbs(Z), tol * S(16));
    // Independent Hermite solve: p(1) = 0, p(e^{∓iθ}) = ∓iθ, x p'(x) = 1 at x = e^{∓iθ}, ζ = 0.
    using C = Cx<S>;
    std::vector<std::vector<C>> A;
    std::vector<C> b;
    A.push_back({C(S(1)), C(S(1)), C(S(1)), C(S(1)), C(S(1))});
    b.push_back(C(S(0)));
    for (const S& sgn : {S(-1), S(1)}) {
      const C x = C::expi(sgn * th);
      std::vector<C> row, drow;
      C xp(S(1));
      for (int n = 0; n < 5; ++n) {
        row.push_back(xp);
        drow.push_back(C(S(n)) * xp);
        xp = xp * x;
      }
      A.push_back(row);
      b.push_back(C(S(0), sgn * th));
      A.push_back(drow);
      b.push_back(C(S(1)));
    }
    const auto herm = solveComplex<S>(A, b);
    const auto corrected = adjointLogCoefficients(th, 4);
    S coeff(0);
    for (int n = 0; n < 5; ++n) coeff = maxOf(coeff, maxOf(abs(herm[n].re - corrected[n]), abs(herm[n].im)));
    c.checkResidual("Hermite solve reproduces the doubled α, β, γ, δ, ε" + at, coeff, tol * S(16));
  }
  // Accuracy of the corrected polynomial log over θ.
  const Vec3<S> a = randomUnit<S>(g), v = randomVec<S, 3>(g);
  for (const S& theta : {S(1) / S(10), S(1), S(3), pi<S>() - S(1) / S(1000)}) {
    const SE3Tangent<S> x(Vec3<S>(a * theta), v);
    const S err = maxAbs(Mat6<S>(adjointLogBook(x.exp().adjoint(), 4) - x.ad()));
    const S d = pi<S>() - theta;
    const S bound = tol * maxOf(S(1), maxOf(S(1) / ipow(theta, 4), S(1) / (d * d * d)));
    c.checkResidual("corrected polynomial log, θ = " + angleText(toDouble(theta)) +
                        " (error ≤ 64 eps · max(1, 1/θ⁴, 1/(π − θ)³))",
                    err, bound);
  }
}
SOMA_STUDY_SCALAR("GF-4.4.3-adjoint-log",
           "SE(3) log in the adjoint representation by Hermite interpolation; prefactor halved (E4.8)",
           "GF §4.4.3", adjointLog);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
