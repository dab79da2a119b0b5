// Studies of GF chapter 4, §4.1–4.2: tangent algebras, twist velocity, the hat map, the
// adjoint representations of SO(3) and SE(3).
#include "gf04_common.hpp"

#include <Eigen/LU>

namespace soma::studies::gf04 {
namespace {

// ---- GF §4.1, GF-4.1-tangent-algebras (erratum E4.1) --------------------------------------

/// Nullity of the real-linear constraint map L (dimension of its solution space) by full-pivot
/// LU with the Tolerance rank threshold.
template <class S> int nullity(const MatX<S>& l) {
  Eigen::FullPivLU<MatX<S>> lu(l);
  lu.setThreshold(Tolerance<S>::rank());
  return int(l.cols()) - int(lu.rank());
}

template <class S> void tangentAlgebras(Context& c) {
  // so(n): kernel of X ↦ Xᵀ + X on n×n real matrices (the linearised MᵀM = I).
  for (int n = 2; n <= 5; ++n) {
    MatX<S> l = MatX<S>::Zero(n * n, n * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        l(i * n + j, i * n + j) += S(1);  // X_ij
        l(i * n + j, j * n + i) += S(1);  // (Xᵀ)_ij = X_ji
      }
    c.checkEqual("dim so(" + std::to_string(n) + ") = n(n−1)/2 (nullity of Ẋᵀ + Ẋ = 0)",
                 n * (n - 1) / 2, nullity(l));
  }
  // u(n), su(n): X = A + iB, X† + X = (A + Aᵀ) + i(B − Bᵀ); su(n) adds Im Tr X = Tr B = 0.
  for (int n = 2; n <= 4; ++n) {
    const int m = n * n;
    MatX<S> l = MatX<S>::Zero(2 * m + 1, 2 * m);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        l(i * n + j, i * n + j) += S(1);
        l(i * n + j, j * n + i) += S(1);
        l(m + i * n + j, m + i * n + j) += S(1);
        l(m + i * n + j, m + j * n + i) -= S(1);
      }
    const MatX<S> lu = l.topRows(2 * m);
    c.checkEqual("dim u(" + std::to_string(n) + ") = n² (nullity of U̇† + U̇ = 0)", m, nullity(lu));
    for (int i = 0; i < n; ++i) l(2 * m, m + i * n + i) = S(1);
    c.checkEqual("dim su(" + std::to_string(n) + ") = n² − 1 (adds Tr U̇ = 0)", m - 1, nullity(l));
  }
  // The book's su(2) element [[ai, b+ci], [−b+ci, −ai]] is anti-Hermitian, not Hermitian (E4.1).
  auto g = rng(41);
  const S a = uniform<S>(g), b = uniform<S>(g), cc = uniform<S>(g);
  Mat2<S> re, im;
  re << S(0), b, -b, S(0);
  im << a, cc, cc, -a;
  const S antiHerm = maxOf(maxAbs(Mat2<S>(re.transpose() + re)), maxAbs(Mat2<S>(im - im.transpose())));
  c.checkResidual("book's su(2) element: M† + M = 0 (anti-Hermitian)", antiHerm, S(0));
  c.checkResidual("book's su(2) element: Tr M = 0", abs(im.trace()) + abs(re.trace()), S(0));
  const S herm = maxOf(maxAbs(Mat2<S>(re.transpose() - re)), maxAbs(Mat2<S>(im.transpose() + im)));
  recordFails(c, "\"the Lie algebra of the unitary groups consists of Hermitian matrices\": M† − M = 0",
              "E4.1", herm, Tolerance<S>::identity());
  // exp(M) (power series of the real 4×4 form [[Re, −Im], [Im, Re]]) lies in SU(2).
  Mat4<S> big;
  big << re, -im, im, re;
  const Mat4<S> u = expSeries(big);
  const Mat2<S> ur = u.template topLeftCorner<2, 2>(), ui = u.template bottomLeftCorner<2, 2>();
  const Mat2<S> uhuRe = ur.transpose() * ur + ui.transpose() * ui;
  const Mat2<S> uhuIm = ur.transpose() * ui - ui.transpose() * ur;
  c.checkResidual("exp(M) (power series) is unitary: |U†U − I|",
                  maxOf(maxAbs(Mat2<S>(uhuRe - Mat2<S>::Identity())), maxAbs(uhuIm)),
                  Tolerance<S>::identity(64));
  const S detRe = ur(0, 0) * ur(1, 1) - ui(0, 0) * ui(1, 1) - (ur(0, 1) * ur(1, 0) - ui(0, 1) * ui(1, 0));
  const S detIm = ur(0, 0) * ui(1, 1) + ui(0, 0) * ur(1, 1) - (ur(0, 1) * ui(1, 0) + ui(0, 1) * ur(1, 0));
  c.checkResidual("exp(M) has det 1 (det e^X = e^{Tr X}, Tr M = 0)",
                  maxOf(abs(detRe - S(1)), abs(detIm)), Tolerance<S>::identity(64));
  // Extremes: projection of a noisy matrix onto so(4) and su(3).
  MatX<S> noisy(4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) noisy(i, j) = uniform<S>(g);
  const MatX<S> proj = (noisy - noisy.transpose()) / S(2);
  c.checkResidual("projection ½(A − Aᵀ) onto so(4) is antisymmetric", maxAbs(MatX<S>(proj + proj.transpose())), S(0));
  const S orth = ((noisy - proj).cwiseProduct(proj)).sum();
  c.checkResidual("A − ½(A − Aᵀ) is Frobenius-orthogonal to so(4) (nearest point)", abs(orth),
                  Tolerance<S>::identity(64) * S(16));
  MatX<S> xr(3, 3), xi(3, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) xr(i, j) = uniform<S>(g), xi(i, j) = uniform<S>(g);
  MatX<S> hr = (xr - xr.transpose()) / S(2), hi = (xi + xi.transpose()) / S(2);  // ½(X − X†)
  const S tr = hi.trace() / S(3);
  for (int i = 0; i < 3; ++i) hi(i, i) -= tr;
  c.checkResidual("su(3) projection ½(X − X†) − Tr/3: anti-Hermitian and traceless",
                  maxOf(maxOf(maxAbs(MatX<S>(hr + hr.transpose())), maxAbs(MatX<S>(hi - hi.transpose()))),
                        abs(hi.trace())),
                  Tolerance<S>::identity(16));
}
GF04_STUDY("GF-4.1-tangent-algebras",
           "so(n), u(n), su(n) as tangent spaces: dimensions, su(2) is anti-Hermitian (E4.1)",
           "GF §4.1", tangentAlgebras);

// ---- GF §4.1, GF-4.1-se3-twist-velocity ---------------------------------------------------
template <class S> void se3TwistVelocity(Context& c) {
  auto g = rng(42);
  const Vec3<S> axis = randomUnit<S>(g), u = randomVec<S, 3>(g), p0 = randomVec<S, 3>(g);
  const S h = S(3) / S(10);  // pitch per radian (the book's p/2π)
  for (const S& theta0 : {S(0), S(7) / S(10)}) {
    auto path = [&](const S& d) { return screwMotion<S>(axis, u, h, theta0 + d).act(p0); };
    const Vec3<S> fd = derivative<S>(path);
    const Vec3<S> p = path(S(0));
    // GF §4.1: ṗ = Ω(p − u) + θ̇ h â, and with v = u × ω + θ̇ h â: ṗ = ω × p + v.
    const Vec3<S> book1 = axis.cross(p - u) + h * axis;
    const Vec3<S> v = u.cross(axis) + h * axis;
    const Vec3<S> book2 = axis.cross(p) + v;
    const std::string at = " at θ = " + str(theta0);
    c.checkResidual("finite-difference velocity of screwMotion = Ω(p − u) + θ̇ p/2π v̂" + at,
                    maxAbs(Vec3<S>(fd - book1)), fdTolerance<S>(S(4)));
    c.checkResidual("ω × p + v with v = u × ω + θ̇ p/2π v̂ equals Ω(p − u) + …" + at,
                    maxAbs(Vec3<S>(book2 - book1)), Tolerance<S>::identity(16));
  }
  // Moment convention v = u × ω (= −ω × u): exp(θ s) reproduces the screw motion.
  const SE3Tangent<S> s(axis, Vec3<S>(u.cross(axis) + h * axis));
  const S th = S(13) / S(10);
  c.checkResidual("exp(θ(ω; u × ω + hω)) = screw motion about the line through u",
                  maxAbs(Mat4<S>((s * th).exp().matrix() - screwMotion<S>(axis, u, h, th).matrix())),
                  Tolerance<S>::identity(64));
  // Extreme: ω = 0, a pure translation: ṗ = v.
  const Vec3<S> vt = randomVec<S, 3>(g);
  auto trans = [&](const S& d) { return (SE3Tangent<S>(Vec3<S>::Zero(), vt) * d).exp().act(p0); };
  c.checkResidual("ω = 0 (pure translation): ṗ = v", maxAbs(Vec3<S>(derivative<S>(trans) - vt)),
                  fdTolerance<S>());
  // Extreme: |u| = 1e6: v = u × ω is 1e6 but ṗ is O(1) for p near the axis (cancellation).
  const S big(1000000);
  const Vec3<S> uBig = u * (big / sqrt(u.squaredNorm())), pNear = uBig + randomVec<S, 3>(g);
  const Vec3<S> direct = axis.cross(pNear) + (uBig.cross(axis) + h * axis);
  const Vec3<S> stable = axis.cross(pNear - uBig) + h * axis;
  c.checkResidual("|u| = 1e6: ω × p + v vs Ω(p − u) + hω (error ≤ 64 eps |u|: cancellation)",
                  maxAbs(Vec3<S>(direct - stable)), Tolerance<S>::identity(64) * big);
}
GF04_STUDY("GF-4.1-se3-twist-velocity",
           "Point velocity under a screw motion: ṗ = ω × p + v with moment v = u × ω + h ω",
           "GF §4.1", se3TwistVelocity);

// ---- GF §4.1, GF-4.1-hat-map (erratum E4.2) -------------------------------------------------
template <class S> int levi(int i, int j, int k) {
  if (i == j || j == k || i == k) return 0;
  return ((j - i + 3) % 3 == 1) ? 1 : -1;  // even permutations of (0,1,2) are cyclic shifts
}
template <class S> void hatMap(Context& c) {
  Mat3<S> X, Y, Z;
  X << 0, 0, 0, 0, 0, -1, 0, 1, 0;
  Y << 0, 0, 1, 0, 0, 0, -1, 0, 0;
  Z << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  c.checkResidual("hat(e_x) = X", maxAbs(Mat3<S>(skew<S>(Vec3<S>::UnitX()) - X)), S(0));
  c.checkResidual("hat(e_y) = Y", maxAbs(Mat3<S>(skew<S>(Vec3<S>::UnitY()) - Y)), S(0));
  c.checkResidual("hat(e_z) = Z", maxAbs(Mat3<S>(skew<S>(Vec3<S>::UnitZ()) - Z)), S(0));
  auto g = rng(43);
  S worst(0), worstEps(0), worstFixed(0), worstVee(0);
  for (int n = 0; n < 100; ++n) {
    const Vec3<S> w = randomVec<S, 3>(g), x = randomVec<S, 3>(g);
    const Mat3<S> W = SO3Tangent<S>(w).hat();
    worst = maxOf(worst, maxAbs(Vec3<S>(W * x - w.cross(x))));
    Mat3<S> printed = Mat3<S>::Zero(), fixed = Mat3<S>::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          printed(i, j) += S(levi<S>(i, j, k)) * w(k);
          fixed(i, j) -= S(levi<S>(i, j, k)) * w(k);
        }
    worstEps = maxOf(worstEps, maxAbs(Mat3<S>(printed - W)));
    worstFixed = maxOf(worstFixed, maxAbs(Mat3<S>(fixed - W)));
    worstVee = maxOf(worstVee, maxAbs(Vec3<S>(SO3Tangent<S>::vee(W).coeffs() - w)));
  }
  c.checkResidual("Ω x = ω × x (100 random pairs)", worst, Tolerance<S>::identity(8));
  recordFails(c, "(Ω)_ij = E_ijk ω_k", "E4.2", worstEps, Tolerance<S>::identity(8));
  c.checkResidual("corrected (Ω)_ij = −E_ijk ω_k (100 random ω)", worstFixed, S(0));
  c.checkResidual("vee(hat(ω)) = ω", worstVee, S(0));
  const Vec3<S> w = randomVec<S, 3>(g);
  c.checkResidual("Ω = ad(ω) (so(3) adjoint)", maxAbs(Mat3<S>(SO3Tangent<S>(w).ad() - skew(w))), S(0));
}
GF04_STUDY("GF-4.1-hat-map", "The hat map ω ↦ Ω, Ωx = ω × x; the ε-tensor formula's sign (E4.2)",
           "GF §4.1", hatMap);

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
GF04_STUDY("GF-4.2-adjoint-SO3", "Adjoint representation of SO(3): R Ω Rᵀ = hat(R ω)", "GF §4.2",
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
GF04_STUDY("GF-4.2-adjoint-SE3", "Adjoint representation of SE(3): [[R, 0], [TR, R]], product, inverse",
           "GF §4.2", adjointSE3);

}  // namespace
}  // namespace soma::studies::gf04
