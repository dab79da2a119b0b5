// Studies of GF chapter 4, §4.5.3–4.5.4: closed-form dexp and its inverse for SO(3) (angular
// velocity) and SE(3) (velocity screw), by the book's idempotent calculus.
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.5.3, GF-4.5.3-so3-dexp-and-inverse --------------------------------------------------
template <class S> void so3DexpInverse(Context& c) {
  auto g = rng(60);
  using CM = CMat<Mat3<S>>;
  const S tol = Tolerance<S>::identity(64);
  const Vec3<S> w = randomUnit<S>(g) * (S(13) / S(10));
  const SO3Tangent<S> r(w);
  const Mat3<S> W = skew(w), W2 = W * W, I = Mat3<S>::Identity();
  const S th2 = w.squaredNorm(), th = sqrt(th2);
  // GF §4.5.3: Σ Ω^k/(k+1)! = I + (1 − cos θ)/θ² Ω + (θ − sin θ)/θ³ Ω²
  const Mat3<S> book = I + (S(1) - cos(th)) / th2 * W + (th - sin(th)) / (th2 * th) * W2;
  c.checkResidual("Σ Ω^k/(k+1)! (120 terms) = I + (1 − cos θ)/θ² Ω + (θ − sin θ)/θ³ Ω² (θ = 1.3)",
                  maxAbs(Mat3<S>(dexpSeries(r, 120) - book)), tol);
  c.checkResidual("= SO3Tangent::ljac()", maxAbs(Mat3<S>(r.ljac() - book)), tol);
  const CM Pp{Mat3<S>(-W2 / (S(2) * th2)), Mat3<S>(W / (S(2) * th))};
  const CM Pm{Mat3<S>(-W2 / (S(2) * th2)), Mat3<S>(-W / (S(2) * th))};
  const CM P0 = CM::real(Mat3<S>(W2 / th2 + I));
  using C = Cx<S>;
  const C ith(S(0), th), mith(S(0), -th), one(S(1));
  const C fm = (C::expi(th) - one) / ith, fp = (C::expi(-th) - one) / mith;  // (e^{±iθ} − 1)/(±iθ)
  c.checkResidual("= P₀ + (e^{iθ} − 1)/(iθ) P₋ − (e^{−iθ} − 1)/(iθ) P₊", (P0 + (fm * Pm) + (fp * Pp) - CM::real(book)).maxAbs(), tol);
  // Inverse: both printed forms, by inverting the idempotent coefficients.
  const Mat3<S> inv1 = I - W / S(2) + (S(1) / th2 + sin(th) / (S(2) * th * (cos(th) - S(1)))) * W2;
  const Mat3<S> inv2 = I - W / S(2) + (S(1) / th2 - S(1) / (S(2) * th * tan(th / S(2)))) * W2;
  c.checkResidual("inverse I − ½Ω + (1/θ² + sin θ/(2θ(cos θ − 1)))Ω² times dexp = I", maxAbs(Mat3<S>(inv1 * book - I)), tol);
  c.checkResidual("half-angle form I − ½Ω + (1/θ² − cot(θ/2)/(2θ))Ω² times dexp = I", maxAbs(Mat3<S>(inv2 * book - I)), tol);
  c.checkResidual("= SO3Tangent::ljacinv()", maxAbs(Mat3<S>(r.ljacinv() - inv2)), tol);
  const CM invP = P0 + ((one / fm) * Pm) + ((one / fp) * Pp);
  c.checkResidual("= P₀ + iθ/(e^{iθ} − 1) P₋ − iθ/(e^{−iθ} − 1) P₊", (invP - CM::real(inv2)).maxAbs(), tol);
  // θ → 0: 1/θ² − cot(θ/2)/(2θ) → 1/12 with cancellation ~ eps/θ².
  const S small = S(1) / S(10000);
  const S direct = S(1) / (small * small) - S(1) / (S(2) * small * tan(small / S(2)));
  S exact;  // the same expression in mpfr at ≥ 2·digits(S) + 64 bits, rounded to S
  {
    const int old = mpfrBits();
    setMpfrBits(std::max(320, 2 * digits<S>() + 64));
    const mpreal t = scalarCast<mpreal>(small);
    exact = scalarCast<S>(mpreal(1 / (t * t) - 1 / (2 * t * tan(t / 2))));
    setMpfrBits(old);
  }
  c.checkNear("θ = 1e-4: 1/θ² − cot(θ/2)/(2θ) → 1/12 (cancellation: error ≤ 64 eps/θ² vs mpfr)", exact, direct,
              tol / (small * small));
  const SO3Tangent<S> rs(Vec3<S>(randomUnit<S>(g) * small));
  c.checkResidual("θ = 1e-4: soma ljacinv · ljac = I (Taylor branch)", maxAbs(Mat3<S>(rs.ljacinv() * rs.ljac() - I)), tol);
  // θ → 2π: det dexp = 2(1 − cos θ)/θ² → 0, dexp not invertible at 2π.
  const S near2pi = S(2) * pi<S>() - S(1) / S(1000);
  const SO3Tangent<S> rb(Vec3<S>(randomUnit<S>(g) * near2pi));
  c.checkNear("θ = 2π − 1e-3: det dexp = 2(1 − cos θ)/θ² (→ 0 at 2π)", S(2) * (S(1) - cos(near2pi)) / (near2pi * near2pi),
              rb.ljac().determinant(), tol);
  c.checkResidual("θ = 2π − 1e-3: ljacinv · ljac = I (error ≤ 64 eps/(2π − θ))", maxAbs(Mat3<S>(rb.ljacinv() * rb.ljac() - I)),
                  tol * S(1000));
}
SOMA_STUDY_SCALAR("GF-4.5.3-so3-dexp-and-inverse", "Angular velocity: closed-form SO(3) dexp and its inverse (idempotents)",
           "GF §4.5.3", so3DexpInverse);

// ---- GF §4.5.4, GF-4.5.4-se3-dexp-and-inverse --------------------------------------------------
/// The book's closed forms of Σ Z^k/(k+1)! and its inverse. GF §4.5.4, GF-4.5.4-se3-dexp-and-inverse
template <class S> Mat6<S> se3DexpBook(const Mat6<S>& Z, const S& th) {
  const Mat6<S> Z2 = Z * Z, Z3 = Z2 * Z, Z4 = Z3 * Z;
  const S s = sin(th), co = cos(th), t2 = th * th;
  return Mat6<S>::Identity() + (S(4) - th * s - S(4) * co) / (S(2) * t2) * Z + (S(4) * th - S(5) * s + th * co) / (S(2) * t2 * th) * Z2 +
         (S(2) - th * s - S(2) * co) / (S(2) * t2 * t2) * Z3 + (S(2) * th - S(3) * s + th * co) / (S(2) * t2 * t2 * th) * Z4;
}
template <class S> Mat6<S> se3DexpInverseBook(const Mat6<S>& Z, const S& th) {
  const Mat6<S> Z2 = Z * Z, Z4 = Z2 * Z2;
  const S s = sin(th), co = cos(th), t2 = th * th;
  return Mat6<S>::Identity() - Z / S(2) + (S(2) / t2 + (th + S(3) * s) / (S(4) * th * (co - S(1)))) * Z2 +
         (S(1) / (t2 * t2) + (th + s) / (S(4) * t2 * th * (co - S(1)))) * Z4;
}
template <class S> void se3DexpInverse(Context& c) {
  auto g = rng(61);
  using CM = CMat<Mat6<S>>;
  const S tol = Tolerance<S>::identity(64);
  const S th = S(13) / S(10);
  const SE3Tangent<S> s = randomTwistWithAngle<S>(g, th);
  const Mat6<S> Z = s.ad(), I = Mat6<S>::Identity();
  const Mat6<S> book = se3DexpBook(Z, th);
  c.checkResidual("Σ Z^k/(k+1)! (150 terms) = book's quartic in Z (θ = 1.3)", maxAbs(Mat6<S>(dexpSeries(s, 150) - book)), tol * S(4));
  c.checkResidual("= SE3Tangent::ljac()", maxAbs(Mat6<S>(s.ljac() - book)), tol * S(4));
  // Spectral form with the book's P, N and the summed coefficients.
  const AdjointSpectral<S> P = adjointSpectral(Z, th);
  using C = Cx<S>;
  const C one(S(1)), ith(S(0), th), mith(S(0), -th);
  const C ap = (C::expi(-th) - one) / mith, am = (C::expi(th) - one) / ith;
  const C bp = ((mith - one) * C::expi(-th) + one) / mith, bm = ((ith - one) * C::expi(th) + one) / ith;
  const CM spec = P.P0 + (ap * P.Pp) + (bp * P.Np) + (am * P.Pm) + (bm * P.Nm);
  c.checkResidual("= P₀ + a₊P₊ + b₊N₊ + a₋P₋ + b₋N₋ (summed series coefficients)", (spec - CM::real(book)).maxAbs(), tol * S(4));
  const Mat6<S> inv = se3DexpInverseBook(Z, th);
  c.checkResidual("book's inverse (no Z³ term) times dexp = I", maxAbs(Mat6<S>(inv * book - I)), tol * S(4));
  c.checkResidual("= SE3Tangent::ljacinv()", maxAbs(Mat6<S>(s.ljacinv() - inv)), tol * S(4));
  const CM specInv = P.P0 + ((one / ap) * P.Pp) + ((C(S(-1)) * bp / (ap * ap)) * P.Np) + ((one / am) * P.Pm) +
                     ((C(S(-1)) * bm / (am * am)) * P.Nm);
  c.checkResidual("= 1/a₀P₀ + 1/a₊P₊ − b₊/a₊² N₊ + … (inverse by coefficients)", (specInv - CM::real(inv)).maxAbs(), tol * S(4));
  // θ → 0: the printed coefficients cancel; θ → 2π: singular.
  for (const S& small : {S(1) / S(10), S(1) / S(100)}) {
    const SE3Tangent<S> x = randomTwistWithAngle<S>(g, small);
    const S err = maxAbs(Mat6<S>(se3DexpBook(x.ad(), small) - x.ljac()));
    c.checkResidual("θ = " + str(small) + ": book's dexp vs ljac (cancellation: error ≤ 64 eps/θ³)", err,
                    tol * maxOf(S(1), S(1) / (small * small * small)));
    const S errInv = maxAbs(Mat6<S>(se3DexpInverseBook(x.ad(), small) - x.ljacinv()));
    c.checkResidual("θ = " + str(small) + ": book's inverse vs ljacinv (error ≤ 64 eps/θ⁴)", errInv,
                    tol * maxOf(S(1), S(1) / ipow(small, 4)));
  }
  const S near2pi = S(2) * pi<S>() - S(1) / S(1000);
  const SE3Tangent<S> xb = randomTwistWithAngle<S>(g, near2pi);
  // Near 2π the inverse blows up like 1/δ² (δ = 2π − θ: the nilpotent parts square the 1/δ of
  // SO(3)); dexp⁻¹·dexp = I then holds to eps/δ².
  c.checkResidual("θ = 2π − 1e-3: ljacinv · ljac = I (error ≤ 64 eps/δ², δ = 2π − θ)",
                  maxAbs(Mat6<S>(xb.ljacinv() * xb.ljac() - I)), tol * S(1000000));
  c.note("θ = 2π − 1e-3: det dexp = " + str(xb.ljac().determinant()) + " (the square of the SO(3) value 2(1 − cos θ)/θ² = " +
         str(S(2) * (S(1) - cos(near2pi)) / (near2pi * near2pi)) + "): dexp is not invertible at 2π.");
}
SOMA_STUDY_SCALAR("GF-4.5.4-se3-dexp-and-inverse", "Velocity screw: closed-form SE(3) dexp (quartic in Z) and its inverse",
           "GF §4.5.4", se3DexpInverse);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
