// Studies of GF chapter 4, §4.4.2: exp and log of SE(3) in the 4×4 representation by the book's
// idempotent/nilpotent calculus and Hermite interpolation, against power series and soma.
#include "gf04/common.hpp"

namespace soma::studies::gf04 {
void helixFigure(Context& c);          // gf04/figures.cpp
void interpolationFigure(Context& c);  // gf04/figures.cpp
}  // namespace soma::studies::gf04

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)

namespace {

std::string angleText(double theta) {
  const double pi = 3.14159265358979323846;
  if (theta > 3) return "π − " + toString(pi - theta, 3);
  return toString(theta, 6);
}

// ---- GF §4.4.2, GF-4.4.2-se3-exp-4x4 ---------------------------------------------------------
/// The book's closed form e^S = I + S + (1 − cos θ)/θ² S² + (θ − sin θ)/θ³ S³.
// GF §4.4.2, GF-4.4.2-se3-exp-4x4
template <class S> Mat4<S> se3ExpBook(const Mat4<S>& Sm, const S& th) {
  const Mat4<S> S2 = Sm * Sm;
  return Mat4<S>::Identity() + Sm + (S(1) - cos(th)) / (th * th) * S2 + (th - sin(th)) / (th * th * th) * S2 * Sm;
}
template <class S> void se3Exp4x4(Context& c) {
  auto g = rng(53);
  using CM = CMat<Mat4<S>>;
  const SE3Tangent<S> s = randomTwistWithAngle<S>(g, S(6) / S(5));
  const Mat4<S> Sm = s.hat(), I = Mat4<S>::Identity(), S2 = Sm * Sm, S3 = S2 * Sm;
  const S th2 = s.ang().squaredNorm(), th = sqrt(th2);
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("S⁴ + θ²S² = 0 (θ = 1.2)", maxAbs(Mat4<S>(S3 * Sm + th2 * S2)), tol);
  // GF §4.4.2: P₀ = (S² + θ²I)/θ², N₀ = S(S² + θ²I)/θ², P± = ±S²(S ∓ iθI)/(2iθ³)
  const CM P0 = CM::real(Mat4<S>((S2 + th2 * I) / th2));
  const CM N0 = CM::real(Mat4<S>(Sm * (S2 + th2 * I) / th2));
  const CM Pp{Mat4<S>(-S2 / (S(2) * th2)), Mat4<S>(-S3 / (S(2) * th2 * th))};
  const CM Pm{Mat4<S>(-S2 / (S(2) * th2)), Mat4<S>(S3 / (S(2) * th2 * th))};
  S rel = maxOf((N0 * N0).maxAbs(), maxOf((N0 * Pp).maxAbs(), (N0 * Pm).maxAbs()));
  rel = maxOf(rel, (N0 * P0 - N0).maxAbs());
  c.checkResidual("N₀² = 0, N₀P± = 0, N₀P₀ = N₀", rel, tol);
  S proj = maxOf((P0 * Pp).maxAbs(), maxOf((P0 * Pm).maxAbs(), (Pp * Pm).maxAbs()));
  proj = maxOf(proj, maxOf((P0 * P0 - P0).maxAbs(), maxOf((Pp * Pp - Pp).maxAbs(), (Pm * Pm - Pm).maxAbs())));
  c.checkResidual("P₀, P± idempotent and mutually annihilating", proj, tol);
  c.checkResidual("P₀ + P₊ + P₋ = I₄", (P0 + Pp + Pm - CM::real(I)).maxAbs(), tol);
  const Cx<S> ith(S(0), th);
  c.checkResidual("S = N₀ − iθP₊ + iθP₋", (N0 - (ith * Pp) + (ith * Pm) - CM::real(Sm)).maxAbs(), tol);
  const Mat4<S> series = expSeries(Sm);
  const CM spectral = P0 + N0 + (Cx<S>::expi(-th) * Pp) + (Cx<S>::expi(th) * Pm);
  c.checkResidual("e^S = P₀ + N₀ + e^{−iθ}P₊ + e^{iθ}P₋ (vs power series)", (spectral - CM::real(series)).maxAbs(), tol);
  const Mat4<S> book = se3ExpBook(Sm, th);
  c.checkResidual("e^S = I + S + (1 − cos θ)/θ² S² + (θ − sin θ)/θ³ S³ (vs power series)", maxAbs(Mat4<S>(book - series)), tol);
  c.checkResidual("= SE3Tangent::exp ((e^Ω, V u) form)", maxAbs(Mat4<S>(book - s.exp().matrix())), tol);
  // Pitch zero: S³ = −θ²S and e^S = I + sin θ/θ S + (1 − cos θ)/θ² S².
  const Vec3<S> a = randomUnit<S>(g), q = randomVec<S, 3>(g);
  const SE3Tangent<S> r(Vec3<S>(a * th), Vec3<S>(q.cross(Vec3<S>(a * th))));
  const Mat4<S> R = r.hat(), R2 = R * R;
  c.checkResidual("pitch 0: S³ = −θ²S", maxAbs(Mat4<S>(R2 * R + th2 * R)), tol);
  c.checkResidual("pitch 0: e^S = I + sin θ/θ S + (1 − cos θ)/θ² S²",
                  maxAbs(Mat4<S>(I + sin(th) / th * R + (S(1) - cos(th)) / th2 * R2 - expSeries(R))), tol);
  // Pure translation: S² = 0, e^S = I + S.
  const SE3Tangent<S> t(Vec3<S>::Zero(), randomVec<S, 3>(g));
  c.checkResidual("pure translation: S² = 0", maxAbs(Mat4<S>(t.hat() * t.hat())), S(0));
  c.checkResidual("pure translation: e^S = I + S = SE3Tangent::exp", maxAbs(Mat4<S>(I + t.hat() - t.exp().matrix())), S(0));
  // Extremes: θ = 1e-6 with |u| = 1e3; θ = π; θ = 20 (many turns: log is the principal branch).
  const SE3Tangent<S> small(Vec3<S>(a * (S(1) / S(1000000))), Vec3<S>(randomUnit<S>(g) * S(1000)));
  c.checkResidual("θ = 1e-6, |u| = 1e3: SE3Tangent::exp = power series in mpfr (error ≤ 64 eps |u|)",
                  maxAbs(Mat4<S>(small.exp().matrix() - expReference<4>(small.hat()))), tol * S(1000));
  const SE3Tangent<S> half(Vec3<S>(a * pi<S>()), randomVec<S, 3>(g));
  c.checkResidual("θ = π: book closed form = power series", maxAbs(Mat4<S>(se3ExpBook(half.hat(), pi<S>()) - expSeries(half.hat()))),
                  tol * S(4));
  const SE3Tangent<S> turns(Vec3<S>(a * S(20)), randomVec<S, 3>(g));
  const SE3<S> G = turns.exp();
  const SE3Tangent<S> principal = G.log();
  c.checkResidual("θ = 20 (3 turns): exp(log(e^S)) = e^S", maxAbs(Mat4<S>(principal.exp().matrix() - G.matrix())), tol * S(20));
  c.checkResidual("… and log returns the principal branch, |ω| ≤ π",
                  maxOf(S(0), sqrt(principal.ang().squaredNorm()) - pi<S>()), tol);
  if constexpr (std::is_same_v<S, double>) {
    if (c.makeFigures()) helixFigure(c);
  }
}
SOMA_STUDY_SCALAR("GF-4.4.2-se3-exp-4x4",
           "SE(3) exp in the 4×4 representation: S⁴ + θ²S² = 0, idempotents, nilpotent, closed form",
           "GF §4.4.2", se3Exp4x4);

// ---- GF §4.4.2, GF-4.4.2-se3-log-4x4 (erratum E4.6) ---------------------------------------------
/// The book's Hermite coefficients a, b, c, d (log G = aI + bG + cG² + dG³).
// GF §4.4.2, GF-4.4.2-se3-log-4x4
template <class S> std::array<S, 4> se3LogCoefficients(const S& th) {
  const S sh = sin(th / S(2)), ch = cos(th / S(2));
  const S k = S(1) / (S(8) * sh * sh * sh * ch);  // ⅛ csc³(θ/2) sec(θ/2)
  const S c1 = cos(th), c2 = cos(S(2) * th), s1 = sin(th), s2 = sin(S(2) * th);
  return {k * (th * c2 - s1), -k * (th * c1 + S(2) * th * c2 - s1 - s2), k * (S(2) * th * c1 + th * c2 - s1 - s2),
          -k * (th * c1 - s1)};
}
template <class S> Mat4<S> se3LogBook(const Mat4<S>& G) {
  const S th = angleOf<S>(G.template topLeftCorner<3, 3>());
  const auto k = se3LogCoefficients(th);
  const Mat4<S> G2 = G * G;
  return k[0] * Mat4<S>::Identity() + k[1] * G + k[2] * G2 + k[3] * G2 * G;
}
template <class S> void se3Log4x4(Context& c) {
  auto g = rng(54);
  const S th = S(6) / S(5);
  const SE3Tangent<S> s = randomTwistWithAngle<S>(g, th);
  const Mat4<S> G = s.exp().matrix();
  c.checkNear("Tr G = 2(1 + cos θ)", S(2) * (S(1) + cos(th)), G.trace(), Tolerance<S>::identity(16));
  // Independent Hermite solve: p(1) = 0, p'(1) = 1, p(e^{∓iθ}) = ∓iθ, p cubic.
  using C = Cx<S>;
  const C one(S(1)), x2 = C::expi(-th), x3 = C::expi(th);
  const auto herm = solveComplex<S>({{one, one, one, one},
                                     {C(S(0)), one, C(S(2)), C(S(3))},
                                     {one, x2, x2 * x2, x2 * x2 * x2},
                                     {one, x3, x3 * x3, x3 * x3 * x3}},
                                    {C(S(0)), one, C(S(0), -th), C(S(0), th)});
  const auto book = se3LogCoefficients(th);
  const char* names[4] = {"a", "b", "c", "d"};
  for (int k = 0; k < 4; ++k)
    c.checkNear(std::string("book's ") + names[k] + " = Hermite interpolation coefficient (θ = 1.2)", herm[k].re, book[k],
                Tolerance<S>::identity(256));
  const Mat4<S> L = se3LogBook(G);
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("log G = aI + bG + cG² + dG³ = S (θ = 1.2)", maxAbs(Mat4<S>(L - s.hat())), tol * S(4));
  c.checkResidual("= soma SE3::log (log R and V⁻¹t)", maxAbs(Vec6<S>(SE3Tangent<S>::vee(L).coeffs() - s.exp().log().coeffs())),
                  tol * S(4));
  // E4.6: the assembled display reads "− (θcos θ + 2θcos 2θ − sin θ)G − sin 2θ)G": taken
  // literally the sin 2θ term of b changes sign.
  const S sh = sin(th / S(2)), ch = cos(th / S(2));
  const S k = S(1) / (S(8) * sh * sh * sh * ch);
  const Mat4<S> G2 = G * G;
  const Mat4<S> garbled =
      k * ((th * cos(S(2) * th) - sin(th)) * Mat4<S>::Identity() - (th * cos(th) + S(2) * th * cos(S(2) * th) - sin(th)) * G -
           sin(S(2) * th) * G + (S(2) * th * cos(th) + th * cos(S(2) * th) - sin(th) - sin(S(2) * th)) * G2 -
           (th * cos(th) - sin(th)) * G2 * G);
  c.checkPrintedFails("assembled log(G) display read literally (OCR-garbled)", "E4.6", maxAbs(Mat4<S>(garbled - s.hat())), tol * S(4));
  // Accuracy of the polynomial form over θ: cancellation ~ eps/θ² near 0, eps/(π − θ) near π.
  const Vec3<S> a = randomUnit<S>(g), v = randomVec<S, 3>(g);
  for (const S& theta : {S(1) / S(100000), S(1) / S(1000), S(1) / S(10), S(1), S(3), pi<S>() - S(1) / S(1000)}) {
    const SE3Tangent<S> x(Vec3<S>(a * theta), v);
    const S err = maxAbs(Mat4<S>(se3LogBook(x.exp().matrix()) - x.hat()));
    const S bound = tol * maxOf(S(1), maxOf(S(1) / (theta * theta), S(1) / (pi<S>() - theta)));
    c.checkResidual("book's polynomial log, θ = " + angleText(toDouble(theta)) +
                        " (error ≤ 64 eps · max(1, 1/θ², 1/(π − θ)))",
                    err, bound);
  }
  // θ = 0 (pure translation): log G = G − I; the polynomial's csc³(θ/2) is 0/0 there.
  const SE3Tangent<S> tr(Vec3<S>::Zero(), randomVec<S, 3>(g));
  const Mat4<S> Gt = tr.exp().matrix();
  c.checkResidual("θ = 0 (pure translation): soma SE3::log = vee(G − I)",
                  maxAbs(Vec6<S>(tr.exp().log().coeffs() - SE3Tangent<S>::vee(Mat4<S>(Gt - Mat4<S>::Identity())).coeffs())), S(0));
  c.checkEqual("θ = 0: the book's polynomial log (csc³(θ/2) = 1/0)", "non-finite",
               allFinite(se3LogBook(Gt)) ? "finite" : "non-finite");
  if constexpr (std::is_same_v<S, double>) {
    if (c.makeFigures()) interpolationFigure(c);
  }
}
SOMA_STUDY_SCALAR("GF-4.4.2-se3-log-4x4",
           "SE(3) log in the 4×4 representation by Hermite interpolation; assembled display garbled (E4.6)",
           "GF §4.4.2", se3Log4x4);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
