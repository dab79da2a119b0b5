// Studies of GF chapter 4, §4.4.1: Rodrigues and the two so(3) logarithms (trace formula,
// Lagrange polynomial).
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.4.1, GF-4.4.1-rodrigues ---------------------------------------------------------
/// The book's Rodrigues formula, evaluated as printed. GF §4.4.1, GF-4.4.1-rodrigues
template <class S> Mat3<S> rodriguesBook(const Vec3<S>& w) {
  const S th = sqrt(w.squaredNorm());
  const Mat3<S> W = skew(w);
  return Mat3<S>::Identity() + sin(th) / th * W + (S(1) - cos(th)) / (th * th) * W * W;
}
template <class S> void rodrigues(Context& c) {
  auto g = rng(50);
  const Vec3<S> a = randomUnit<S>(g), u = randomVec<S, 3>(g);
  for (const S& theta : {S(1) / S(100000000), S(3) / S(10), S(1), pi<S>() / S(2), pi<S>(), S(2) * pi<S>(), S(1000)}) {
    const Vec3<S> w = a * theta;
    const Mat3<S> R = rodriguesBook(w);
    const std::string at = " (θ = " + str(theta, 6) + ")";
    const S tol = Tolerance<S>::identity(64) * maxOf(S(1), theta);  // series squarings: error ∝ θ
    c.checkResidual("I + sin θ/θ Ω + (1 − cos θ)/θ² Ω² = Σ Ωⁿ/n!" + at, maxAbs(Mat3<S>(R - expSeries(skew(w)))), tol);
    c.checkResidual("= SO3Tangent::exp (quaternion route)" + at, maxAbs(Mat3<S>(R - SO3Tangent<S>(w).exp().matrix())), tol);
    const Vec3<S> vec = u + sin(theta) * a.cross(u) + (S(1) - cos(theta)) * a.cross(a.cross(u));
    c.checkResidual("vector form u + sin θ v×u + (1 − cos θ) v×(v×u) = R u" + at, maxAbs(Vec3<S>(vec - R * u)), tol);
    c.checkResidual("RᵀR = I, det R = 1" + at,
                    maxOf(maxAbs(Mat3<S>(R.transpose() * R - Mat3<S>::Identity())), abs(R.determinant() - S(1))),
                    Tolerance<S>::identity(64));
  }
  c.checkResidual("θ = 2π: e^Ω = I", maxAbs(Mat3<S>(rodriguesBook(Vec3<S>(a * (S(2) * pi<S>()))) - Mat3<S>::Identity())),
                  Tolerance<S>::identity(64) * S(8));
  // θ < 1e-8: (1 − cos θ)/θ² loses every digit in double; 2 sin²(θ/2)/θ² keeps them.
  const S tiny = S(1) / S(100000000);
  S taylor(0), term = S(1) / S(2);  // 2(1 − cos θ)/θ² = Σ (−1)^k 2θ^{2k}/(2k+2)!, summed to eps
  for (int k = 1; k < 100 && abs(term) > Tolerance<S>::epsilon() * Tolerance<S>::epsilon(); ++k) {
    taylor += term;
    term = -term * tiny * tiny / S((2 * k + 1) * (2 * k + 2));
  }
  const S half = S(2) * sin(tiny / S(2)) * sin(tiny / S(2)) / (tiny * tiny);
  const S direct = (S(1) - cos(tiny)) / (tiny * tiny);
  c.checkNear("θ = 1e-8: 2 sin²(θ/2)/θ² = its Taylor series ½ − θ²/24 + … (relative)", S(1), half / taylor, Tolerance<S>::identity(8));
  c.note("(1 − cos θ)/θ² evaluated directly at θ = 1e-8 has relative error " + str(abs(direct / taylor - S(1))) +
         " (the Ω² term is O(θ²), so R is still accurate to eps; the coefficient is not).");
}
SOMA_STUDY_SCALAR("GF-4.4.1-rodrigues", "Rodrigues formula e^Ω = I + sin θ/θ Ω + (1 − cos θ)/θ² Ω²",
           "GF §4.4.1", rodrigues);

// ---- GF §4.4.1, GF-4.4.1-so3-log-trace -----------------------------------------------------
/// θ from the trace (cos θ = (Tr R − 1)/2) and R − Rᵀ (sin θ = |vee(R − Rᵀ)|/2) by atan2, and the
/// book's log R = θ/(2 sin θ)(R − Rᵀ). GF §4.4.1, GF-4.4.1-so3-log-trace
template <class S> Mat3<S> so3LogTrace(const Mat3<S>& R, S* thetaOut = nullptr) {
  const Mat3<S> A = R - R.transpose();
  const S st = sqrt(SO3Tangent<S>::vee(A).coeffs().squaredNorm()) / S(2);
  const S ct = (R.trace() - S(1)) / S(2);
  const S th = atan2(st, ct);
  if (thetaOut) *thetaOut = th;
  return th / (S(2) * st) * A;
}
template <class S> void so3LogTrace(Context& c) {
  auto g = rng(51);
  const Vec3<S> a = randomUnit<S>(g);
  for (const S& theta : {S(1) / S(100000), S(1) / S(10), S(1), S(3), pi<S>() - S(1) / S(1000), pi<S>() - S(1) / S(1000000)}) {
    const Vec3<S> w = a * theta;
    const Mat3<S> R = SO3Tangent<S>(w).exp().matrix();
    const std::string at = " (θ = " + (theta > S(3) ? "π − " + str(pi<S>() - theta, 3) : str(theta, 6)) + ")";
    c.checkNear("Tr R = 1 + 2 cos θ" + at, S(1) + S(2) * cos(theta), R.trace(), Tolerance<S>::identity(16));
    S th(0);
    const Mat3<S> L = so3LogTrace(R, &th);
    const S bound = Tolerance<S>::identity(64) * maxOf(S(1), theta / sin(theta));  // divides by sin θ
    c.checkResidual("book: θ/(2 sin θ)(R − Rᵀ) = Ω (error ≤ 64 eps θ/sin θ)" + at, maxAbs(Mat3<S>(L - skew(w))), bound);
    c.checkResidual("soma SO3::log (quaternion) = Ω" + at, maxAbs(Vec3<S>(SO3<S>::fromMatrix(R).log().coeffs() - w)),
                    Tolerance<S>::identity(64));
  }
  // θ = 0: 0/0 in the printed formula; its limit ½ gives log I = 0.
  const Mat3<S> I = Mat3<S>::Identity();
  const Mat3<S> atZero = so3LogTrace(I);
  c.checkEqual("R = I: θ/(2 sin θ) is 0/0 (the formula needs its limit ½)", "non-finite",
               allFinite(atZero) ? "finite" : "non-finite");
  // Tr R slightly above 3 by round-off: acos((Tr R − 1)/2) is NaN, the atan2 route gives θ = 0.
  const Mat3<S> above = I * (S(1) + S(4) * Tolerance<S>::epsilon());
  using std::acos;
  const S viaAcos = acos((above.trace() - S(1)) / S(2));
  S viaAtan(1);
  (void)so3LogTrace(above, &viaAtan);
  c.checkEqual("Tr R = 3 + 12 eps: acos((Tr R − 1)/2)", "NaN", isFinite(viaAcos) ? "finite" : "NaN");
  c.checkResidual("Tr R = 3 + 12 eps: atan2 route gives θ = 0", abs(viaAtan), S(0));
  // θ = π: the book's formula fails (sin θ = 0); soma's log returns ±π â.
  const Mat3<S> Rpi = SO3Tangent<S>(Vec3<S>(a * pi<S>())).exp().matrix();
  const Vec3<S> lp = SO3<S>::fromMatrix(Rpi).log().coeffs();
  c.checkResidual("θ = π: soma SO3::log = ±π â",
                  minOfPair(maxAbs(Vec3<S>(lp - a * pi<S>())), maxAbs(Vec3<S>(lp + a * pi<S>()))),
                  Tolerance<S>::identity(64));
  const S bookErr = maxAbs(Mat3<S>(so3LogTrace(Rpi) - skew(Vec3<S>(a * pi<S>()))));
  c.note("At θ = π the printed formula's error is " + str(bookErr) +
         " (R − Rᵀ and sin θ are both round-off; the book: \"the method fails when θ = ±π\").");
}
SOMA_STUDY_SCALAR("GF-4.4.1-so3-log-trace", "so(3) log from the trace: Tr R = 1 + 2cos θ, log R = θ/(2 sin θ)(R − Rᵀ)",
           "GF §4.4.1", so3LogTrace);

// ---- GF §4.4.1, GF-4.4.1-so3-log-polynomial (erratum E4.5) ---------------------------------
/// The book's Lagrange-polynomial log: Ω = aI + bR + cR² with the closed-form coefficients.
// GF §4.4.1, GF-4.4.1-so3-log-polynomial
template <class S> Mat3<S> so3LogPolynomial(const Mat3<S>& R) {
  const S st = sqrt(SO3Tangent<S>::vee(Mat3<S>(R - R.transpose())).coeffs().squaredNorm()) / S(2);
  const S th = atan2(st, (R.trace() - S(1)) / S(2));
  const S k = -th / (S(2) * st);
  return k * ((S(1) + S(2) * cos(th)) * Mat3<S>::Identity() - S(2) * (S(1) + cos(th)) * R + R * R);
}
template <class S> void so3LogPolynomial(Context& c) {
  auto g = rng(52);
  S cubic(0);
  for (int n = 0; n < 20; ++n) {
    const Mat3<S> R = SO3<S>::Random(g).matrix();
    const S tr = R.trace();
    cubic = maxOf(cubic, maxAbs(Mat3<S>(R * R * R - tr * R * R + tr * R - Mat3<S>::Identity())));
  }
  c.checkResidual("R³ − Tr(R)R² + Tr(R)R − I = 0 (20 random R)", cubic, Tolerance<S>::identity(64));
  // Lagrange interpolation through (1, 0), (e^{−iθ}, −iθ), (e^{iθ}, iθ).
  const S th = S(11) / S(10);
  using C = Cx<S>;
  const C x1(S(1)), x2 = C::expi(-th), x3 = C::expi(th), y1(S(0)), y2(S(0), -th), y3(S(0), th);
  auto p = [&](const C& x, bool printed) {
    const C d3 = printed ? (x3 - x1) * (x3 - x1) : (x3 - x1) * (x3 - x2);
    return (x - x2) * (x - x3) / ((x1 - x2) * (x1 - x3)) * y1 + (x - x3) * (x - x1) / ((x2 - x3) * (x2 - x1)) * y2 +
           (x - x1) * (x - x2) / d3 * y3;
  };
  const S corr = maxOf((p(x1, false) - y1).abs(), maxOf((p(x2, false) - y2).abs(), (p(x3, false) - y3).abs()));
  c.checkResidual("corrected Lagrange p(x_k) = y_k (θ = 1.1)", corr, Tolerance<S>::identity(16));
  c.checkPrintedFails("Lagrange third denominator (x₃ − x₁)(x₃ − x₁): p(x₃) = y₃", "E4.5", (p(x3, true) - y3).abs(),
              Tolerance<S>::identity(16));
  // Monomial coefficients: by solving the Vandermonde system, vs the book's closed forms.
  const auto abc = solveComplex<S>({{C(S(1)), x1, x1 * x1}, {C(S(1)), x2, x2 * x2}, {C(S(1)), x3, x3 * x3}}, {y1, y2, y3});
  const S a = -th / (S(2) * sin(th)) * (S(1) + S(2) * cos(th)), b = th / sin(th) * (S(1) + cos(th)), cc = -th / (S(2) * sin(th));
  c.checkNear("a = −θ/(2 sin θ)(1 + 2 cos θ) (vs Vandermonde solve)", a, abc[0].re, Tolerance<S>::identity(64));
  c.checkNear("b = θ/sin θ (1 + cos θ)", b, abc[1].re, Tolerance<S>::identity(64));
  c.checkNear("c = −θ/(2 sin θ)", cc, abc[2].re, Tolerance<S>::identity(64));
  c.checkResidual("a, b, c are real (imaginary parts)", maxOf(abs(abc[0].im), maxOf(abs(abc[1].im), abs(abc[2].im))),
                  Tolerance<S>::identity(64));
  // The polynomial log vs the exact Ω, and the float64 accuracy profile.
  const Vec3<S> ax = randomUnit<S>(g);
  for (const S& theta : {S(1) / S(100000), S(1) / S(10), S(1), S(3), pi<S>() - S(1) / S(1000), pi<S>() - S(1) / S(1000000)}) {
    const Vec3<S> w = ax * theta;
    const Mat3<S> R = SO3Tangent<S>(w).exp().matrix();
    const std::string at = " (θ = " + (theta > S(3) ? "π − " + str(pi<S>() - theta, 3) : str(theta, 6)) + ")";
    const S bound = Tolerance<S>::identity(64) * maxOf(S(1), theta / sin(theta));
    c.checkResidual("log R = −θ/(2 sin θ)((1 + 2cos θ)I − 2(1 + cos θ)R + R²) (error ≤ 64 eps θ/sin θ)" + at,
                    maxAbs(Mat3<S>(so3LogPolynomial(R) - skew(w))), bound);
  }
}
SOMA_STUDY_SCALAR("GF-4.4.1-so3-log-polynomial", "so(3) log as a Lagrange polynomial in R; Lagrange typo (E4.5)",
           "GF §4.4.1", so3LogPolynomial);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
