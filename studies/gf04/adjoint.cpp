// Studies of GF chapter 4, §4.2: the adjoint representations of SO(3) and SE(3).
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.2, GF-4.2-adjoint-SO3 ----------------------------------------------------------
template <class S> void adjointSO3(Context& c) {
  auto g = rng(44);
  S worst(0), worstBook(0), worstRows(0), worstHom(0);
  for (int n = 0; n < 50; ++n) {
    const SO3<S> r = SO3<S>::Random(g), r2 = SO3<S>::Random(g);
    const Mat3<S> R = r.matrix();
    const Vec3<S> w = randomVec<S, 3>(g);
    const Mat3<S> conj = R * skew(w) * R.transpose();
    worst = maxOf(worst, maxAbs(Mat3<S>(conj - skew(Vec3<S>(R * w)))));
    const Vec3<S> r1 = R.row(0).transpose(), rr2 = R.row(1).transpose(), r3 = R.row(2).transpose();
    Mat3<S> book;
    book << S(0), -r3.dot(w), rr2.dot(w), r3.dot(w), S(0), -r1.dot(w), -rr2.dot(w), r1.dot(w), S(0);
    worstBook = maxOf(worstBook, maxAbs(Mat3<S>(book - conj)));
    worstRows = maxOf(worstRows, maxOf(maxAbs(Vec3<S>(r1.cross(rr2) - r3)),
                                       maxOf(maxAbs(Vec3<S>(rr2.cross(r3) - r1)), maxAbs(Vec3<S>(r3.cross(r1) - rr2)))));
    worstHom = maxOf(worstHom, maxAbs(Mat3<S>((r * r2).adjoint() - r.adjoint() * r2.adjoint())));
  }
  c.checkResidual("R Ω Rᵀ = hat(R ω) (50 random R, ω)", worst, Tolerance<S>::identity(64));
  c.checkResidual("book's row form [[0, −r₃·ω, r₂·ω], …] = R Ω Rᵀ", worstBook, Tolerance<S>::identity(64));
  c.checkResidual("rows: r₁ × r₂ = r₃, r₂ × r₃ = r₁, r₃ × r₁ = r₂", worstRows, Tolerance<S>::identity(64));
  c.checkResidual("Ad(R₁R₂) = Ad(R₁) Ad(R₂)", worstHom, Tolerance<S>::identity(64));
  // Extreme: rotation a hair short of π.
  const Vec3<S> a = randomUnit<S>(g), w = randomVec<S, 3>(g);
  const Mat3<S> Rpi = SO3<S>::fromAxisAngle(a, pi<S>() - S(1) / S(1000000000)).matrix();
  c.checkResidual("R Ω Rᵀ = hat(Rω) at θ = π − 1e-9",
                  maxAbs(Mat3<S>(Rpi * skew(w) * Rpi.transpose() - skew(Vec3<S>(Rpi * w)))),
                  Tolerance<S>::identity(64));
  // Extreme: a non-orthogonal matrix: conjugation no longer matches R ω, and soma rejects it.
  const Mat3<S> bad = Rpi * (S(11) / S(10));
  const S defect = maxAbs(Mat3<S>(bad * skew(w) * bad.transpose() - skew(Vec3<S>(bad * w))));
  c.checkNear("R' = 1.1 R: |R'ΩR'ᵀ − hat(R'ω)| = 0.11 |hat(Rω)| (Ad is not conjugation off SO(3))",
              S(11) / S(100) * maxAbs(skew(Vec3<S>(Rpi * w))), defect, Tolerance<S>::identity(64));
  bool threw = false;
  try {
    (void)SO3<S>::fromMatrix(bad);
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("SO3::fromMatrix(1.1 R) throws InvalidInput", "throws", threw ? "throws" : "accepted");
}
SOMA_STUDY_SCALAR("GF-4.2-adjoint-SO3", "Adjoint representation of SO(3): R Ω Rᵀ = hat(R ω)", "GF §4.2",
           adjointSO3);

// ---- GF §4.2, GF-4.2-adjoint-SE3 ----------------------------------------------------------
template <class S> Mat6<S> bookAd(const Mat3<S>& R, const Vec3<S>& t) {
  Mat6<S> m;  // GF §4.2, GF-4.2-adjoint-SE3: [[R, 0], [T R, R]]
  m << R, Mat3<S>::Zero(), skew(t) * R, R;
  return m;
}
template <class S> void adjointSE3(Context& c) {
  auto g = rng(45);
  S wConj(0), wLib(0), wProd(0), wInv(0), wInvForm(0), wHom(0);
  for (int n = 0; n < 50; ++n) {
    const SE3<S> x = SE3<S>::Random(g), y = SE3<S>::Random(g);
    const SE3Tangent<S> s(randomVec<S, 6>(g));
    const Mat3<S> R = x.rotation(), R2 = y.rotation();
    const Vec3<S> t = x.translation(), t2 = y.translation();
    const Mat6<S> A = bookAd(R, t), B = bookAd(R2, t2);
    const Mat4<S> conj = x.matrix() * s.hat() * x.inverse().matrix();
    wConj = maxOf(wConj, maxAbs(Vec6<S>(A * s.coeffs() - SE3Tangent<S>::vee(conj).coeffs())));
    wLib = maxOf(wLib, maxAbs(Mat6<S>(A - x.adjoint())));
    const Mat3<S> T = skew(t), T2 = skew(t2);
    const Mat3<S> block = (T + R * T2 * R.transpose()) * R * R2;
    wProd = maxOf(wProd, maxAbs(Mat3<S>((A * B).template bottomLeftCorner<3, 3>() - block)));
    Mat6<S> inv;
    inv << R.transpose(), Mat3<S>::Zero(), -R.transpose() * T, R.transpose();
    wInv = maxOf(wInv, maxAbs(Mat6<S>(inv * A - Mat6<S>::Identity())));
    wInvForm = maxOf(wInvForm, maxAbs(Mat3<S>(-R.transpose() * T + (R.transpose() * T * R) * R.transpose())));
    wHom = maxOf(wHom, maxAbs(Mat6<S>((x * y).adjoint() - x.adjoint() * y.adjoint())));
  }
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("[[R,0],[TR,R]] s = vee(g ŝ g⁻¹) (50 random g, s)", wConj, tol);
  c.checkResidual("book's 6×6 matrix = SE3::adjoint()", wLib, tol);
  c.checkResidual("product: bottom-left block (T₁ + R₁T₂R₁ᵀ)R₁R₂", wProd, tol);
  c.checkResidual("inverse [[Rᵀ,0],[−RᵀT,Rᵀ]] · Ad = I", wInv, tol);
  c.checkResidual("−RᵀT = −(RᵀTR)Rᵀ", wInvForm, tol);
  c.checkResidual("Ad(g₁g₂) = Ad(g₁)Ad(g₂)", wHom, tol);
  // Extreme: |t| = 1e6 — the TR block dominates; error relative to |t|.
  const S big(1000000);
  const SE3<S> far(SO3<S>::fromAxisAngle(randomUnit<S>(g), pi<S>() - S(1) / S(1000)),
                   Vec3<S>(randomUnit<S>(g) * big));
  const SE3Tangent<S> s(randomVec<S, 6>(g));
  const Mat4<S> conj = far.matrix() * s.hat() * far.inverse().matrix();
  c.checkResidual("|t| = 1e6, θ = π − 1e-3: Ad s vs conjugation (error ≤ 64 eps |t|)",
                  maxAbs(Vec6<S>(far.adjoint() * s.coeffs() - SE3Tangent<S>::vee(conj).coeffs())),
                  tol * big);
}
SOMA_STUDY_SCALAR("GF-4.2-adjoint-SE3", "Adjoint representation of SE(3): [[R, 0], [TR, R]], product, inverse",
           "GF §4.2", adjointSE3);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
